/*
 * gpu_inputs.c - the inputs the shader kernels are compared on: the
 * sweep's distributions in float (src/inputs: uniform, north, south, the
 * threshold list, exhaustive n.z from -1, non-unit, grid) and the
 * extremes: every triple of 15 component values (signed zeros, the
 * smallest and largest subnormals, the smallest normal, +-1 and their
 * neighbours, +-inf, NaN), which holds the axes, zero vectors and n.z
 * next to -1.  Each input is marked when it is a rounding to nearest of a
 * real unit vector, the domain of certify's bounds (is_unit).
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "gpu/gpu.h"
#include "inputs/inputs.h"
#include "common/prec.h"

/* The reals that round to f lie between the midpoints to its neighbours
   (closed: conservative here, see is_unit). */
static void cell(float f, long double *lo, long double *hi)
{
	*lo = ((long double)f + (long double)nextafterf(f, -INFINITY)) / 2.0L;
	*hi = ((long double)f + (long double)nextafterf(f, INFINITY)) / 2.0L;
}

/* Is n the rounding of some real unit vector?  Yes when the smallest
   |v|^2 over n's rounding cell is below 1 and the largest above, each by
   more than 2^-50 (long double sums of 50-bit squares err by < 2^-60):
   inputs within 2^-50 of the edge are left out, never wrongly put in. */
static int is_unit(const float n[3])
{
	long double mn = 0.0L, mx = 0.0L;
	int k;
	for (k = 0; k < 3; k++) {
		long double lo, hi;
		if (!isfinite(n[k]) || fabsf(n[k]) >= FLT_MAX)
			return 0;
		cell(n[k], &lo, &hi);
		mx += fmaxl(lo * lo, hi * hi);
		if (lo > 0.0L || hi < 0.0L)
			mn += fminl(lo * lo, hi * hi);
	}
	return mn < 1.0L - 0x1p-50L && mx > 1.0L + 0x1p-50L;
}

/* Appends (x, y, z), each rounded by fmt->round, and whether the result
   is a rounding of a real unit vector (fmt->unit). */
static int push(gpu_inputs *in, size_t *cap, const gpu_format *fmt, double x, double y, double z)
{
	if (in->count == *cap) {
		size_t c = *cap ? 2 * *cap : 4096;
		float *n = realloc(in->n, 3 * c * sizeof *n);
		unsigned char *u;
		if (!n)
			return -1;
		in->n = n;
		u = realloc(in->unit, c);
		if (!u)
			return -1;
		in->unit = u;
		*cap = c;
	}
	in->n[3 * in->count] = fmt->round(x);
	in->n[3 * in->count + 1] = fmt->round(y);
	in->n[3 * in->count + 2] = fmt->round(z);
	in->unit[in->count] = (unsigned char)fmt->unit(in->n + 3 * in->count);
	in->count++;
	return 0;
}

/* `per` inputs of distribution `dist` in fmt->prec (src/inputs). */
static int add_dist(gpu_inputs *in, size_t *cap, const gpu_format *fmt, int dist, uint64_t seed, uint64_t per)
{
	dist_spec d;
	uint64_t i;
	int rc = 0;
	memset(&d, 0, sizeof d);
	d.dist = dist;
	d.prec = fmt->prec;
	d.seed = seed;
	d.count = per;
	d.ex_from = -1.0;
	d.ex_values = per / 4 ? per / 4 : 1;
	d.ex_azimuths = 4;
	d.grid_rows = 24;
	d.grid_cols = 48;
	if (dist_prepare(&d) != 0)
		return -1;
	for (i = 0; i < d.count && rc == 0; i++) {
		double n[3], loc[3], aux;
		dist_sample(&d, i, n, loc, &aux);
		rc = push(in, cap, fmt, n[0], n[1], n[2]);
	}
	dist_free(&d);
	return rc;
}

int gpu_inputs_build(gpu_inputs *in, const gpu_format *fmt, uint64_t seed, uint64_t per)
{
	size_t cap = 0, a, b, c;
	int dist, rc = 0;
	memset(in, 0, sizeof *in);
	for (dist = 0; dist < NDIST && rc == 0; dist++)
		rc = add_dist(in, &cap, fmt, dist, seed, per);
	for (a = 0; a < fmt->next && rc == 0; a++)
		for (b = 0; b < fmt->next && rc == 0; b++)
			for (c = 0; c < fmt->next && rc == 0; c++)
				rc = push(in, &cap, fmt, fmt->ext[a], fmt->ext[b], fmt->ext[c]);
	if (rc != 0) {
		fprintf(stderr, "onbstudy-gpu: out of memory building the %sinputs\n", fmt->what);
		gpu_inputs_free(in);
	}
	return rc;
}

static float round_float(double x)
{
	return (float)x;
}

int gpu_inputs_make(gpu_inputs *in, uint64_t seed, uint64_t per)
{
	/* the float extremes (each exact in double) */
	static const double ext[] = { 0.0, -0.0, 0x1p-149, -0x1p-149, 0x1.fffffcp-127, 0x1p-126,
		1.0, -1.0, 0x1.fffffep-1, -0x1.fffffep-1, 0x1.000002p+0, 0.5,
		INFINITY, -INFINITY, NAN };
	static const gpu_format f = { PREC_FLOAT, round_float, is_unit, ext, sizeof ext / sizeof ext[0], "" };
	return gpu_inputs_build(in, &f, seed, per);
}

void gpu_inputs_free(gpu_inputs *in)
{
	free(in->n);
	free(in->unit);
	memset(in, 0, sizeof *in);
}
