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

static int push(gpu_inputs *in, size_t *cap, float x, float y, float z)
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
	in->n[3 * in->count] = x;
	in->n[3 * in->count + 1] = y;
	in->n[3 * in->count + 2] = z;
	in->unit[in->count] = (unsigned char)is_unit(in->n + 3 * in->count);
	in->count++;
	return 0;
}

static int add_dist(gpu_inputs *in, size_t *cap, int dist, uint64_t seed, uint64_t per)
{
	dist_spec d;
	uint64_t i;
	int rc = 0;
	memset(&d, 0, sizeof d);
	d.dist = dist;
	d.prec = PREC_FLOAT;
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
		rc = push(in, cap, (float)n[0], (float)n[1], (float)n[2]);
	}
	dist_free(&d);
	return rc;
}

int gpu_inputs_make(gpu_inputs *in, uint64_t seed, uint64_t per)
{
	static const float ext[] = { 0.0f, -0.0f, 0x1p-149f, -0x1p-149f, 0x1.fffffcp-127f, 0x1p-126f,
		1.0f, -1.0f, 0x1.fffffep-1f, -0x1.fffffep-1f, 0x1.000002p+0f, 0.5f,
		INFINITY, -INFINITY, NAN };
	const size_t ne = sizeof ext / sizeof ext[0];
	size_t cap = 0, a, b, c;
	int dist, rc = 0;
	memset(in, 0, sizeof *in);
	for (dist = 0; dist < NDIST && rc == 0; dist++)
		rc = add_dist(in, &cap, dist, seed, per);
	for (a = 0; a < ne && rc == 0; a++)
		for (b = 0; b < ne && rc == 0; b++)
			for (c = 0; c < ne && rc == 0; c++)
				rc = push(in, &cap, ext[a], ext[b], ext[c]);
	if (rc != 0) {
		fprintf(stderr, "onbstudy-gpu: out of memory building the inputs\n");
		gpu_inputs_free(in);
	}
	return rc;
}

void gpu_inputs_free(gpu_inputs *in)
{
	free(in->n);
	free(in->unit);
	memset(in, 0, sizeof *in);
}
