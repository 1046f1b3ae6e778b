/*
 * gpu_compare.c - every method of onb.glsl and onb.hlsl (methods.inc) on
 * the driver, against libonb's C float kernel bit for bit, and the
 * envelope check: the defect of each driver output on a rounded unit
 * input against the proven bound of the arithmetic the driver performs.
 *
 * Which C kernel a shader kernel must match: itself, unless it calls
 * fma() and the driver's fma rounds twice (the operations probe says so;
 * Vulkan allows it), when it must match its unfused twin (methods.inc).
 * The bound: the whole-sphere float row of that kernel in a certify CSV
 * (default results/certify/certify.csv, the IEEE model: valid for the
 * driver's outputs because they are the C kernel's bits, which the
 * comparison checks; --bounds takes a `certify --arith` CSV instead).
 * The defect D = max(| |b1|-1 |, | |b2|-1 |, |b1.n|, |b2.n|, |b1.b2|) is
 * computed in long double from the float outputs (products of floats are
 * exact there; the sums err by < 2^-60 relative), +inf when an output is
 * not finite.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "libonb/onb.h"
#include "gpu/gpu.h"
#include "gpu/compare.h"

static const gpu_method methods[] = {
#define ONB_GPU_METHOD(id, m, twin) { id, #m, #twin, 0 },
#define ONB_GPU_METHOD64(id, m, twin) { id, #m, #twin, 1 },
#define ONB_GPU_METHOD64S(id, m, twin) { id, #m, #twin, 2 },
#include "gpu/methods.inc"
#undef ONB_GPU_METHOD
#undef ONB_GPU_METHOD64
#undef ONB_GPU_METHOD64S
	{ 99, "broken_duff_sign", "duff_branchless", 0 },
};

const gpu_method *gpu_methods(size_t *count)
{
	*count = sizeof methods / sizeof methods[0];
	return methods;
}

double gpu_defect(const float n[3], const float b[6])
{
	long double s[5], d = 0.0L;
	const float *u = b, *v = b + 3;
	int k;
	for (k = 0; k < 6; k++)
		if (!isfinite(b[k]))
			return INFINITY;
	s[0] = sqrtl((long double)u[0] * u[0] + (long double)u[1] * u[1] + (long double)u[2] * u[2]) - 1.0L;
	s[1] = sqrtl((long double)v[0] * v[0] + (long double)v[1] * v[1] + (long double)v[2] * v[2]) - 1.0L;
	s[2] = (long double)u[0] * n[0] + (long double)u[1] * n[1] + (long double)u[2] * n[2];
	s[3] = (long double)v[0] * n[0] + (long double)v[1] * n[1] + (long double)v[2] * n[2];
	s[4] = (long double)u[0] * v[0] + (long double)u[1] * v[1] + (long double)u[2] * v[2];
	for (k = 0; k < 5; k++)
		if (fabsl(s[k]) > d)
			d = fabsl(s[k]);
	return (double)d;
}

/* The C kernel's outputs on every input (b: 6 floats per input). */
int gpu_c_outputs(const char *name, const gpu_inputs *in, float *b)
{
	const onb_method *m = onb_find(name);
	size_t i;
	if (!m || !m->basisf) {
		fprintf(stderr, "onbstudy-gpu: no float method \"%s\" in libonb's registry\n", name);
		return -1;
	}
	for (i = 0; i < in->count; i++) {
		onb_vec3f n, b1, b2;
		n.x = in->n[3 * i]; n.y = in->n[3 * i + 1]; n.z = in->n[3 * i + 2];
		m->basisf(n, &b1, &b2);
		b[6 * i] = b1.x; b[6 * i + 1] = b1.y; b[6 * i + 2] = b1.z;
		b[6 * i + 3] = b2.x; b[6 * i + 4] = b2.y; b[6 * i + 5] = b2.z;
	}
	return 0;
}

/* How the six outputs a (C) and b (driver) differ, the worst component
   deciding: GPU_SAME bits, GPU_NAN (both NaN, other payloads), GPU_ZERO
   (both zero, other signs), GPU_NONFINITE (one is NaN or infinite),
   GPU_VALUE (two different finite values). */
int gpu_class(const float *a, const float *b)
{
	int k, r = GPU_SAME;
	for (k = 0; k < 6; k++) {
		int c = GPU_SAME;
		if (gpu_bits(a[k]) == gpu_bits(b[k]))
			continue;
		if (isnan(a[k]) && isnan(b[k]))
			c = GPU_NAN;
		else if (a[k] == 0.0f && b[k] == 0.0f)
			c = GPU_ZERO;
		else if (!isfinite(a[k]) || !isfinite(b[k]))
			c = GPU_NONFINITE;
		else
			c = GPU_VALUE;
		if (c > r)
			r = c;
	}
	return r;
}

/* The float whole-sphere bound of `name` in a certify CSV: the row with
   nz -1..1 and phi 0..360.  +inf for "singular"; -1 when absent. */
double gpu_bound(const char *csv, const char *name)
{
	FILE *f = fopen(csv, "r");
	char line[1024];
	double b = -1.0;
	const size_t len = strlen(name);
	if (!f) {
		fprintf(stderr, "onbstudy-gpu: cannot open %s\n", csv);
		return -1.0;
	}
	while (b < 0.0 && fgets(line, sizeof line, f)) {
		char *p = line + len;
		if (strncmp(line, name, len) != 0 || strncmp(p, ",float,-1,1,0,360,", 18) != 0)
			continue;
		p += 18;
		b = strncmp(p, "inf", 3) == 0 ? INFINITY : strtod(p, NULL);
	}
	fclose(f);
	return b;
}

/* The profile a certify CSV was made under ("# arith: NAME ..."), into
   name[len]; "ieee" when the CSV has no such line (a plain certify run). */
void gpu_bounds_profile(const char *csv, char *name, size_t len)
{
	FILE *f = fopen(csv, "r");
	char line[1024];
	snprintf(name, len, "ieee");
	if (!f)
		return;
	while (fgets(line, sizeof line, f) && line[0] == '#')
		if (strncmp(line, "# arith: ", 9) == 0) {
			const int n = (int)strcspn(line + 9, " \n");
			snprintf(name, len, "%.*s", n, line + 9);
			break;
		}
	fclose(f);
}
