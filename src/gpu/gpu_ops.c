/*
 * gpu_ops.c - how the driver rounds each operation the methods use: the
 * kernels of ops.comp (one GLSL operation each) on random operands of
 * every magnitude and on the extremes, against IEEE binary32 round to
 * nearest as the C kernels compute it (libonb's flags: no contraction, no
 * FTZ), and inversesqrt also against the correctly rounded 1/sqrt(a)
 * (MPFR).  A row per operation: identical, differing, the largest
 * distance in ulps (adjacent floats), and the first differing operands.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <mpfr.h>
#include "gpu/gpu.h"
#include "inputs/rng.h"

typedef struct {
	int id;           /* ops.comp's OP */
	const char *glsl; /* the operation as written there */
	int unary_pos;    /* operands made |a| (sqrt, inversesqrt) */
	int ref;          /* the reference (ieee()): the IEEE operation, or a model */
	const char *against;
	int preserve;     /* run from ops_preserve.spv (SignedZeroInfNanPreserve) */
} op_row;

static const op_row ops[] = {
	{ 0, "a + b", 0, 0, "IEEE", 0 }, { 11, "a - b", 0, 11, "IEEE", 0 }, { 1, "a * b", 0, 1, "IEEE", 0 },
	{ 2, "a / b", 0, 2, "IEEE", 0 }, { 3, "1.0 / a", 0, 3, "IEEE", 0 }, { 4, "sqrt(a)", 1, 4, "IEEE", 0 },
	{ 5, "inversesqrt(a)", 1, 5, "correctly rounded 1/sqrt(a)", 0 },
	{ 6, "1.0 / sqrt(a)", 1, 6, "IEEE, two roundings", 0 },
	{ 7, "fma(a, b, c)", 0, 7, "fused (one rounding)", 0 },
	{ 7, "fma(a, b, c)", 0, 8, "a * b, then + c (two roundings)", 0 },
	{ 8, "precise a * b + c", 0, 8, "two roundings", 0 },
	{ 9, "a * b + c (not precise)", 0, 8, "two roundings", 0 },
	{ 10, "sign(a)", 0, 10, "GLSL: 1, 0 (either zero) or -1", 0 },
	{ 12, "abs(a)", 0, 12, "IEEE", 0 }, { 13, "-a", 0, 13, "IEEE", 0 },
	{ 14, "0.0 - a", 0, 14, "IEEE", 0 }, { 15, "a * 0.0", 0, 15, "IEEE", 0 }, { 16, "a + 0.0", 0, 16, "IEEE", 0 },
	{ 14, "0.0 - a, SignedZeroInfNanPreserve", 0, 14, "IEEE", 1 },
	{ 15, "a * 0.0, SignedZeroInfNanPreserve", 0, 15, "IEEE", 1 },
	{ 16, "a + 0.0, SignedZeroInfNanPreserve", 0, 16, "IEEE", 1 },
};
#define NOPS (sizeof ops / sizeof ops[0])

uint32_t gpu_bits(float f)
{
	uint32_t u;
	memcpy(&u, &f, sizeof u);
	return u;
}

int64_t gpu_ord(float f)
{
	const uint32_t u = gpu_bits(f);
	return (u >> 31) ? -(int64_t)(u & 0x7fffffffu) : (int64_t)u;
}

static float from_bits(uint32_t u)
{
	float f;
	memcpy(&f, &u, sizeof f);
	return f;
}

/* Operand k of triple i: random bits (every class of float), a random
   magnitude 2^[-40, 40], or one of the extremes. */
static float operand(uint64_t seed, size_t i, int k)
{
	static const uint32_t ext[] = { 0x00000000u, 0x80000000u, 0x00000001u, 0x80000001u, 0x007fffffu,
		0x00800000u, 0x3f800000u, 0xbf800000u, 0x7f7fffffu, 0x7f800000u, 0xff800000u, 0x7fc00000u,
		0x3f7fffffu, 0x3f800001u, 0x33800000u, 0x00400000u };
	const uint64_t r = rng_u64(seed, 0x6f7073u + (uint64_t)k, i);
	switch (r % 8) {
	case 0:
		return from_bits((uint32_t)(r >> 32));
	case 1:
		return from_bits(ext[(r >> 8) % (sizeof ext / sizeof ext[0])]);
	default: {
		const double m = 1.0 + (double)(r >> 40) * 0x1p-24;
		return (float)ldexp((r >> 3) & 1 ? -m : m, (int)((r >> 32) % 81) - 40);
	}
	}
}

static float rsqrt_cr(mpfr_t t, float a)
{
	mpfr_set_flt(t, a, MPFR_RNDN);
	mpfr_rec_sqrt(t, t, MPFR_RNDN);
	return mpfr_get_flt(t, MPFR_RNDN);
}

/* IEEE binary32, as libonb's C kernels compute (volatile: one rounding
   per operation, no contraction whatever the flags). */
static float ieee(int id, float a, float b, float c, mpfr_t t)
{
	volatile float p;
	switch (id) {
	case 0:  return a + b;
	case 11: return a - b;
	case 1:  return a * b;
	case 2:  return a / b;
	case 3:  return 1.0f / a;
	case 4:  return sqrtf(a);
	case 5:  return rsqrt_cr(t, a);
	case 6:  return 1.0f / sqrtf(a);
	case 7:  return fmaf(a, b, c);
	case 8: case 9: p = a * b; return p + c;
	case 10: return a > 0.0f ? 1.0f : a < 0.0f ? -1.0f : 0.0f;
	case 12: return fabsf(a);
	case 14: return 0.0f - a;
	case 15: return a * 0.0f;
	case 16: return a + 0.0f;
	default: return -a;
	}
}

static void row(FILE *f, const op_row *o, const float *in, const uint32_t *out, size_t count, mpfr_t t)
{
	size_t i, same = 0, nan = 0, diff = 0, first = count;
	int64_t worst = 0;
	for (i = 0; i < count; i++) {
		const float a = in[3 * i], b = in[3 * i + 1], c = in[3 * i + 2];
		const float want = ieee(o->ref, a, b, c, t), got = from_bits(out[i]);
		if (gpu_bits(want) == out[i]) {
			same++;
		} else if (isnan(want) && isnan(got)) {
			nan++;
		} else {
			int64_t dist = isnan(want) || isnan(got) ? INT64_MAX : llabs(gpu_ord(want) - gpu_ord(got));
			if (dist == 0)
				dist = 1;  /* +0 against -0 */
			diff++;
			if (dist > worst)
				worst = dist;
			if (first == count)
				first = i;
		}
	}
	fprintf(f, "| `%s` | %s | %zu | %zu | %zu | ", o->glsl, o->against, same, nan, diff);
	if (worst == INT64_MAX)
		fprintf(f, "NaN | ");
	else
		fprintf(f, "%lld | ", (long long)worst);
	if (first < count) {
		const float a = in[3 * first], b = in[3 * first + 1], c = in[3 * first + 2];
		fprintf(f, "(%a, %a, %a): %a, IEEE %a |\n", (double)a, (double)b, (double)c,
		        (double)from_bits(out[first]), (double)ieee(o->ref, a, b, c, t));
	} else {
		fprintf(f, "- |\n");
	}
}

int gpu_ops(gpu_dev *d, const char *spvdir, FILE *f, uint64_t seed, size_t count)
{
	float *in = malloc(3 * count * sizeof *in), *use = malloc(3 * count * sizeof *use);
	uint32_t *out = malloc(count * sizeof *out);
	char spv[4096], spvp[4096];
	size_t i, k;
	int bad = 0;
	mpfr_t t;
	if (!in || !use || !out) {
		fprintf(stderr, "onbstudy-gpu: out of memory\n");
		free(in); free(use); free(out);
		return -1;
	}
	snprintf(spv, sizeof spv, "%s/ops.spv", spvdir);
	snprintf(spvp, sizeof spvp, "%s/ops_preserve.spv", spvdir);
	mpfr_init2(t, 128);
	for (i = 0; i < count; i++)
		for (k = 0; k < 3; k++)
			in[3 * i + k] = operand(seed, i, (int)k);
	fprintf(f, "| operation | against | same bits | both NaN | differ | largest distance (ulps) | first differing (a, b, c): driver, reference |\n|---|---|---|---|---|---|---|\n");
	for (k = 0; k < NOPS && bad >= 0; k++) {
		for (i = 0; i < 3 * count; i++)
			use[i] = ops[k].unary_pos ? fabsf(in[i]) : in[i];
		if (gpu_run(d, ops[k].preserve ? spvp : spv, ops[k].id, (const uint32_t *)(const void *)use, 3 * count, out, count,
		            (uint32_t)((count + 63) / 64)) != 0) {
			bad = -1;
			break;
		}
		row(f, &ops[k], use, out, count, t);
		for (i = 0; i < count && bad >= 0; i++)
			if (gpu_bits(ieee(ops[k].ref, use[3 * i], use[3 * i + 1], use[3 * i + 2], t)) != out[i]
			    && !(isnan(from_bits(out[i])) && isnan(ieee(ops[k].ref, use[3 * i], use[3 * i + 1], use[3 * i + 2], t)))) {
				bad++;
				break;
			}
	}
	mpfr_clear(t);
	free(in); free(use); free(out);
	return bad;
}
