/*
 * gpu_half.c - onbstudy-gpu half: the binary16 kernels of src/gpu/half.comp
 * (explicit float16_t arithmetic, the device's shaderFloat16) on the
 * driver, against libonb's C half kernels (src/lib/half.c, each operation
 * rounded to binary16) bit for bit, and the envelope check: every result
 * on an input that is a rounding to binary16 of a real unit vector must
 * lie within the bound that `certify --arith vulkan --precision half`
 * proves at that input (gpu_regions.c's regions, in half: within 8 half
 * ulps), which covers every conforming Vulkan binary16 implementation.
 *
 * The inputs: the sweep's distributions in half (src/inputs with
 * PREC_HALF, each component rounded to binary16 by prec_half_round) and
 * every triple of 15 binary16 extremes (signed zeros, the smallest and
 * largest subnormals 2^-24 and 1023 2^-24, the smallest normal 2^-14,
 * +-1 and their neighbours, 65504, +-inf, NaN).  They travel as floats
 * (every binary16 value is one) and the kernel converts exactly.
 *
 * A method fails when the driver gives another finite value than C on
 * some input, or a unit input's defect lies above its bound.  Signs of
 * zeros and NaN/inf differences are counted and shown, as in compare.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "libonb/onb.h"
#include "gpu/gpu.h"
#include "gpu/compare.h"
#include "inputs/inputs.h"
#include "common/prec.h"

typedef struct { int id; const char *name, *expect; int f64; } half_method;
static const half_method hmethods[] = {
#define ONB_GPU_HALF(id, m, f64, call) { id, #m, #m, f64 },
#include "gpu/half_methods.inc"
#undef ONB_GPU_HALF
	{ 98, "broken_frisvad_f32", "frisvad", 0 },
	{ 99, "broken_duff_sign", "duff_branchless", 0 },
};
#define NHM (sizeof hmethods / sizeof hmethods[0])

/* the binary16 neighbours of a finite binary16 value h (as doubles) */
static double hnext(double h, double dir)
{
	uint16_t b = prec_half_bits(h);
	if (h == 0.0)
		return dir > 0 ? 0x1p-24 : -0x1p-24;
	b = (uint16_t)(((h > 0.0) == (dir > 0.0)) ? b + 1 : b - 1);
	return prec_half_value(b);
}

/* Is n the rounding to binary16 of a real unit vector?  As gpu_inputs.c's
   is_unit, on binary16's rounding cells (closed, with a 2^-40 margin:
   the cells' ends are exact in long double). */
static int is_unit_h(const float n[3])
{
	long double mn = 0.0L, mx = 0.0L;
	int k;
	for (k = 0; k < 3; k++) {
		long double lo, hi;
		const double h = n[k];
		if (!isfinite(h) || fabs(h) >= prec_fmt(PREC_HALF)->max)
			return 0;
		lo = ((long double)h + hnext(h, -1.0)) / 2.0L;
		hi = ((long double)h + hnext(h, 1.0)) / 2.0L;
		mx += fmaxl(lo * lo, hi * hi);
		if (lo > 0.0L || hi < 0.0L)
			mn += fminl(lo * lo, hi * hi);
	}
	return mn < 1.0L - 0x1p-40L && mx > 1.0L + 0x1p-40L;
}

static float round_half(double x)
{
	return (float)prec_half_round(x);
}

/* the study's inputs in binary16 (gpu_inputs_build) */
static int half_inputs(gpu_inputs *in, uint64_t seed, uint64_t per)
{
	static const double ext[] = { 0.0, -0.0, 0x1p-24, -0x1p-24, 0x1.ff8p-15, 0x1p-14, 1.0, -1.0,
		0x1.ffcp-1, -0x1.ffcp-1, 0x1.004p+0, 0.5, 65504.0, INFINITY, NAN };
	static const gpu_format h = { PREC_HALF, round_half, is_unit_h, ext, sizeof ext / sizeof ext[0], "binary16 " };
	return gpu_inputs_build(in, &h, seed, per);
}

/* libonb's C half kernel `name` on every input (6 floats per input) */
static int c_half(const char *name, const gpu_inputs *in, float *b)
{
	const onb_method *m = onb_find(name);
	size_t i;
	int k;
	if (!m || !m->arrayh) {
		fprintf(stderr, "onbstudy-gpu: no binary16 kernel of \"%s\" in libonb (ONB_HAVE_HALF)\n", name);
		return -1;
	}
	for (i = 0; i < in->count; i++) {
		uint16_t n[3], r[6];
		for (k = 0; k < 3; k++)
			n[k] = prec_half_bits((double)in->n[3 * i + k]);
		m->arrayh(n, r, r + 3);
		for (k = 0; k < 6; k++)
			b[6 * i + k] = (float)prec_half_value(r[k]);
	}
	return 0;
}


/* ---- The kernels that round in double, with the double -> binary16
   conversion done through float (two roundings; Vulkan lets a conversion
   land on either neighbour), their other operations as half.c's.  A
   driver value that differs from C's but equals this twin's is explained. */
static double hh(double x) { return prec_half_round(x); }   /* one binary16 operation, done in double */
static double c2(double x) { return prec_half_round((double)(float)x); }
static void hcross3(const double p[3], const double q[3], double r[3])
{
	r[0] = hh(hh(p[1] * q[2]) - hh(p[2] * q[1]));
	r[1] = hh(hh(p[2] * q[0]) - hh(p[0] * q[2]));
	r[2] = hh(hh(p[0] * q[1]) - hh(p[1] * q[0]));
}
static double hdot3(const double p[3], const double q[3])
{
	return hh(hh(hh(p[0] * q[0]) + hh(p[1] * q[1])) + hh(p[2] * q[2]));
}
/* hughes_moeller (hm), naive: v, s = c2(1/sqrt(v.v)), v s, and a cross */
static void twin_norm(const double n[3], double v[3], int hm, double b[6])
{
	const double s = c2(1.0 / sqrt(hdot3(v, v)));
	double u[3], c[3];
	int k;
	for (k = 0; k < 3; k++)
		u[k] = hh(v[k] * s);
	if (hm)
		hcross3(u, n, c);   /* b1 = v x n, b2 = v */
	else
		hcross3(n, u, c);   /* b1 = u, b2 = n x u */
	for (k = 0; k < 3; k++) {
		b[k] = hm ? c[k] : u[k];
		b[3 + k] = hm ? u[k] : c[k];
	}
}
static int half_twin(const char *name, const float nf[3], float out[6])
{
	const double n[3] = { nf[0], nf[1], nf[2] };
	double b[6], v[3];
	int k;
	if (strcmp(name, "pbrt_v3") == 0) {
		const int xb = fabs(n[0]) > fabs(n[1]);
		const double inv = hh(1.0 / hh(sqrt(hh(hh(n[xb ? 0 : 1] * n[xb ? 0 : 1]) + hh(n[2] * n[2])))));
		b[0] = xb ? hh(-n[2] * inv) : hh(0.0 * inv);
		b[1] = xb ? hh(0.0 * inv) : hh(n[2] * inv);
		b[2] = xb ? hh(n[0] * inv) : hh(-n[1] * inv);
		b[3] = c2(n[1] * b[2] - n[2] * b[1]);
		b[4] = c2(n[2] * b[0] - n[0] * b[2]);
		b[5] = c2(n[0] * b[1] - n[1] * b[0]);
	} else if (strcmp(name, "hughes_moeller") == 0) {
		v[0] = fabs(n[0]) > fabs(n[2]) ? -n[1] : 0.0;
		v[1] = fabs(n[0]) > fabs(n[2]) ? n[0] : -n[2];
		v[2] = fabs(n[0]) > fabs(n[2]) ? 0.0 : n[1];
		twin_norm(n, v, 1, b);
	} else if (strcmp(name, "naive") == 0) {
		double e[3] = { 1.0, 0.0, 0.0 }, d;
		if (n[0] > 0x1.cccp-1) { e[0] = 0.0; e[1] = 1.0; }   /* 0.9 in binary16 */
		d = hdot3(e, n);
		for (k = 0; k < 3; k++)
			v[k] = hh(e[k] - hh(n[k] * d));
		twin_norm(n, v, 0, b);
	} else {
		return 0;
	}
	for (k = 0; k < 6; k++)
		out[k] = (float)b[k];
	return 1;
}

typedef struct {
	size_t twin;   /* value differences the twin explains (counted as same) */
	size_t n[GPU_NCLASS], domain, above, above_at, first, dmax_at, tighter;
	int first_cls;
	double dmax, ratio, bound_whole;
} half_cmp;

static void half_tally(half_cmp *c, const char *name, const gpu_inputs *in, const float *ref, const float *got,
                       const gpu_regions *r)
{
	size_t i;
	for (i = 0; i < in->count; i++) {
		float tw[6];
		int k = gpu_class(ref + 6 * i, got + 6 * i);
		if (k == GPU_VALUE && half_twin(name, in->n + 3 * i, tw) && gpu_class(tw, got + 6 * i) <= GPU_ZERO) {
			c->twin++;
			k = GPU_SAME;
		}
		c->n[k]++;
		if (k >= GPU_ZERO && k > c->first_cls) {
			c->first = i;
			c->first_cls = k;
		}
		if (in->unit[i]) {
			const double d = gpu_defect(in->n + 3 * i, got + 6 * i), b = gpu_regions_bound(r, in->n + 3 * i);
			c->domain++;
			c->tighter += b < r->whole;
			if (d > c->dmax || c->domain == 1) {
				c->dmax = d;
				c->dmax_at = i;
			}
			if (b > 0.0 && d / b > c->ratio)
				c->ratio = d / b;
			if (!(d <= b) && c->above++ == 0)
				c->above_at = i;
		}
	}
}

static void half_row(FILE *f, const half_method *m, const gpu_inputs *in, const half_cmp *c, const float *ref, const float *got)
{
	static const char *const what[GPU_NCLASS] = { "", "", "+-0", "NaN/inf", "value" };
	const double u = 0x1p-11;
	int k;
	fprintf(f, "| `%s` | `%s` | %zu", m->name, m->expect, c->n[GPU_SAME] + c->n[GPU_NAN]);
	if (c->n[GPU_NAN]) fprintf(f, " (%zu NaN payloads aside)", c->n[GPU_NAN]);
	if (c->twin) fprintf(f, " (%zu of them the bits of double -> binary16 through float)", c->twin);
	if (c->n[GPU_ZERO]) fprintf(f, "; +-0: %zu", c->n[GPU_ZERO]);
	if (c->n[GPU_NONFINITE]) fprintf(f, "; NaN/inf: %zu", c->n[GPU_NONFINITE]);
	if (c->n[GPU_VALUE]) fprintf(f, "; **value: %zu**", c->n[GPU_VALUE]);
	if (c->first_cls >= GPU_ZERO) {
		const size_t i = c->first;
		fprintf(f, "; first %s at (%a, %a, %a): C", what[c->first_cls], (double)in->n[3 * i], (double)in->n[3 * i + 1], (double)in->n[3 * i + 2]);
		for (k = 0; k < 6; k++) fprintf(f, " %a", (double)ref[6 * i + k]);
		fprintf(f, ", driver");
		for (k = 0; k < 6; k++) fprintf(f, " %a", (double)got[6 * i + k]);
	}
	fprintf(f, " | %zu | %.4g u | %.4g u | %zu | %.3g | %s |\n", c->domain, c->dmax / u, c->bound_whole / u, c->tighter,
	        c->ratio, c->above ? "**outside**" : "inside");
	if (c->above) {
		const size_t i = c->above_at;
		fprintf(f, "\n  %s: %zu unit inputs above the bound at the input, the first (%a, %a, %a)\n\n", m->name, c->above,
		        (double)in->n[3 * i], (double)in->n[3 * i + 1], (double)in->n[3 * i + 2]);
	}
}

static int half_wanted(const char *list, const char *name)
{
	const size_t n = strlen(name);
	const char *p = list;
	if (!list)
		return strncmp(name, "broken_", 7) != 0;
	while ((p = strstr(p, name)) != NULL) {
		if ((p == list || p[-1] == ',') && (p[n] == ',' || p[n] == '\0'))
			return 1;
		p += n;
	}
	return 0;
}

int gpu_half_check(const char *list)
{
	size_t k, found = 0, names = 1;
	const char *p;
	if (!list)
		return 0;
	for (p = list; *p; p++)
		names += *p == ',';
	for (k = 0; k < NHM; k++)
		found += (size_t)half_wanted(list, hmethods[k].name);
	if (found == names)
		return 0;
	fprintf(stderr, "onbstudy-gpu: half --methods: unknown method in '%s'; valid:", list);
	for (k = 0; k < NHM; k++)
		fprintf(stderr, " %s", hmethods[k].name);
	fprintf(stderr, "\n");
	return -1;
}

/* One method: run, compare, check; 1 when it fails, -1 on error. */
static int half_one(gpu_dev *d, const char *spv, FILE *f, const gpu_inputs *in, const half_method *m,
                    const char *bounds, float *ref, float *got)
{
	half_cmp c;
	gpu_regions r;
	memset(&c, 0, sizeof c);
	c.first_cls = -1;
	if (gpu_regions_loadp(bounds, m->expect, "half", &r) != 0 || !r.have_whole) {
		fprintf(stderr, "onbstudy-gpu: no binary16 bound of %s in %s (certify --arith vulkan --precision half)\n", m->expect, bounds);
		gpu_regions_free(&r);
		return -1;
	}
	c.bound_whole = r.whole;
	if (c_half(m->expect, in, ref) != 0 ||
	    gpu_run(d, spv, m->id, (const uint32_t *)(const void *)in->n, 3 * in->count,
	            (uint32_t *)(void *)got, 6 * in->count, (uint32_t)((in->count + 63) / 64)) != 0) {
		gpu_regions_free(&r);
		return -1;
	}
	half_tally(&c, m->expect, in, ref, got, &r);
	gpu_regions_free(&r);
	half_row(f, m, in, &c, ref, got);
	return c.n[GPU_VALUE] != 0 || c.above != 0;
}

int gpu_half(gpu_dev *d, const char *spvdir, FILE *f, uint64_t seed, uint64_t per, const char *bounds, const char *methods)
{
	gpu_inputs in;
	char spv[4096], prof[64];
	float *ref = NULL, *got = NULL;
	size_t k, units = 0;
	int bad = 0, rc = 0;
	FILE *bf = fopen(bounds, "r");
	if (!bf) {
		fprintf(stderr, "onbstudy-gpu: cannot open the binary16 bounds %s (certify --arith vulkan --precision half)\n", bounds);
		return -1;
	}
	fclose(bf);
	if (!gpu_float16(d)) {
		fprintf(stderr, "onbstudy-gpu: device \"%s\" has no shaderFloat16: no binary16 arithmetic to test\n", gpu_name(d));
		return -1;
	}
	if (half_inputs(&in, seed, per) != 0)
		return -1;
	ref = malloc(6 * in.count * sizeof *ref);
	got = malloc(6 * in.count * sizeof *got);
	if (!ref || !got) {
		fprintf(stderr, "onbstudy-gpu: out of memory\n");
		free(ref); free(got); gpu_inputs_free(&in);
		return -1;
	}
	for (k = 0; k < in.count; k++)
		units += in.unit[k];
	snprintf(spv, sizeof spv, "%s/half.spv", spvdir);
	gpu_bounds_profile(bounds, prof, sizeof prof);
	fprintf(f, "\n### Binary16 (%zu inputs, %zu of them roundings to binary16 of real unit vectors, seed %llu; bounds of profile %s, half, from %s)\n\n",
	        in.count, units, (unsigned long long)seed, prof, bounds);
	fprintf(f, "| kernel | C half kernel | same bits as C | unit inputs | largest D there | whole-sphere bound | inputs with a region bound below it | largest D / bound at the input | envelope |\n"
	           "|---|---|---|---|---|---|---|---|---|\n");
	for (k = 0; k < NHM && rc == 0; k++) {
		if (!half_wanted(methods, hmethods[k].name))
			continue;
		if (hmethods[k].f64 && !gpu_float64(d)) {
			fprintf(f, "| `%s` | - | needs shaderFloat64, which the device lacks | | | | | | |\n", hmethods[k].name);
			continue;
		}
		rc = half_one(d, spv, f, &in, &hmethods[k], bounds, ref, got);
		bad += rc > 0;
		rc = rc < 0 ? -1 : 0;
	}
	free(ref); free(got);
	gpu_inputs_free(&in);
	return rc ? -1 : bad;
}

/* The RelaxedPrecision decorations of a SPIR-V module (OpDecorate, 71,
   with decoration 0), or -1 when it cannot be read. */
static long relaxed_count(const char *path)
{
	FILE *f = fopen(path, "rb");
	uint32_t w[4096];
	size_t n, i, skip = 5;   /* the header's five words */
	long c = 0;
	uint32_t need = 0, op = 0;
	size_t have = 0;
	uint32_t ins[3];
	if (!f)
		return -1;
	while ((n = fread(w, sizeof w[0], sizeof w / sizeof w[0], f)) > 0)
		for (i = 0; i < n; i++) {
			if (skip) { skip--; continue; }
			if (need == 0) {   /* an instruction's first word: length and opcode */
				need = w[i] >> 16;
				op = w[i] & 0xffffu;
				have = 0;
				if (need == 0) { fclose(f); return -1; }
			}
			if (have < 3)
				ins[have] = w[i];
			have++;
			if (--need == 0 && op == 71 && have >= 3 && ins[2] == 0)
				c++;
		}
	fclose(f);
	return c;
}

/* Is every output a binary16 value (what an fp16 evaluation would give)? */
static int all_half(const float *b)
{
	int k;
	for (k = 0; k < 6; k++)
		if (isfinite(b[k]) && (double)b[k] != prec_half_round((double)b[k]))
			return 0;
	return 1;
}

/* gltf_viewer with `precision mediump float` (RelaxedPrecision, as its
   source declares) on the float inputs, against C's float kernel and the
   same lines without mediump on the driver.  Vulkan grants a relaxed
   operation no precision, so nothing is checked against a bound: the
   table says what this driver does. */
int gpu_relaxed(gpu_dev *d, const char *spvdir, FILE *f, uint64_t seed, uint64_t per)
{
	gpu_inputs in;
	char spv[4096], plain[4096];
	float *ref, *got, *flt;
	size_t i, same = 0, same_plain = 0, halfs = 0, n[GPU_NCLASS] = { 0 };
	long nr;
	int rc = -1;
	snprintf(spv, sizeof spv, "%s/relaxed/gltf_viewer.spv", spvdir);
	snprintf(plain, sizeof plain, "%s/wild/gltf_viewer.spv", spvdir);
	if ((nr = relaxed_count(spv)) < 0) {
		fprintf(stderr, "onbstudy-gpu: cannot read %s (make gpu builds it)\n", spv);
		return -1;
	}
	if (gpu_inputs_make(&in, seed, per) != 0)
		return -1;
	ref = malloc(6 * in.count * sizeof *ref);
	got = malloc(6 * in.count * sizeof *got);
	flt = malloc(6 * in.count * sizeof *flt);
	if (ref && got && flt && gpu_c_outputs("gltf_viewer", &in, ref) == 0 &&
	    gpu_run(d, spv, 0, (const uint32_t *)(const void *)in.n, 3 * in.count, (uint32_t *)(void *)got, 6 * in.count,
	            (uint32_t)((in.count + 63) / 64)) == 0 &&
	    gpu_run(d, plain, 0, (const uint32_t *)(const void *)in.n, 3 * in.count, (uint32_t *)(void *)flt, 6 * in.count,
	            (uint32_t)((in.count + 63) / 64)) == 0) {
		for (i = 0; i < in.count; i++) {
			n[gpu_class(ref + 6 * i, got + 6 * i)]++;
			same_plain += gpu_class(flt + 6 * i, got + 6 * i) <= GPU_NAN;
			halfs += all_half(got + 6 * i);
		}
		same = n[GPU_SAME] + n[GPU_NAN];
		fprintf(f, "\n### RelaxedPrecision: gltf_viewer with `precision mediump float` (%zu float inputs, seed %llu)\n\n",
		        in.count, (unsigned long long)seed);
		fprintf(f, "| kernel | RelaxedPrecision decorations | same bits as C's float kernel | +-0 / NaN-inf / value | same bits as its lines without mediump on the driver | inputs whose six outputs are all binary16 values |\n"
		           "|---|---|---|---|---|---|\n");
		fprintf(f, "| `gltf_viewer`, mediump | %ld | %zu of %zu | %zu / %zu / %zu | %zu of %zu | %zu of %zu |\n", nr, same, in.count,
		        n[GPU_ZERO], n[GPU_NONFINITE], n[GPU_VALUE], same_plain, in.count, halfs, in.count);
		rc = 0;
	} else if (!ref || !got || !flt) {
		fprintf(stderr, "onbstudy-gpu: out of memory\n");
	}
	free(ref); free(got); free(flt);
	gpu_inputs_free(&in);
	return rc;
}
