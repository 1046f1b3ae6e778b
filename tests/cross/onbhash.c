/*
 * onbhash.c - make cross-check: every method of libonb on the
 * same inputs, on any machine, reduced to one hash per method, precision
 * and path (scalar method->basis[f], batch method->batch[f]).  Equal hashes
 * on two machines mean bit-identical outputs.
 *   onbhash [N]     N inputs (default 1048576), the same on every host:
 *                   the six axes, -0 components, and vectors near +-z and
 *                   +-x first; the rest from a 32-bit LCG, converted
 *                   exactly and normalized (IEEE sqrt and division are
 *                   correctly rounded, so the inputs are identical too).
 * Output, one line per method and precision:
 *   method precision scalar_hash batch_hash nans max_defect
 * The hashes take every NaN as one pattern (hash.h: a NaN's sign and
 * payload are not specified by IEEE 754 and differ between CPUs); nans is
 * S/B, how many of the 6N scalar and 6N batch outputs were NaN, so a NaN
 * where another machine has a number still shows (in the hash as well).
 * max_defect (in double) is max(| |b1| - 1 |, | |b2| - 1 |, |b1.n|, |b2.n|,
 * |b1.b2|) over the LCG inputs with n.x > -0.5 (away from naive's singular
 * -x), for the methods with ONB_HW_RSQRT only (the rest print -), to say
 * what their normalization does here.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "libonb/onb.h"
#include "hash.h"

static double *nx, *ny, *nz, *o[6];
static float *fx, *fy, *fz, *q[6];

static void special(size_t i, double x, double y, double z)
{
	nx[i] = x; ny[i] = y; nz[i] = z;
}

/* The inputs: 30 special ones, then the LCG's unit vectors. */
static void inputs(size_t n)
{
	uint32_t s = 20250u;
	size_t i = 0, k;
	static const double ax[][3] = { {1,0,0}, {-1,0,0}, {0,1,0}, {0,-1,0}, {0,0,1}, {0,0,-1},
		{-0.0,-0.0,1}, {-0.0,-0.0,-1}, {0,0,-0.0}, {1,-0.0,0}, {-1,0,-0.0}, {0,-1,-0.0} };
	for (k = 0; k < sizeof ax / sizeof ax[0]; k++, i++)
		special(i, ax[k][0], ax[k][1], ax[k][2]);
	for (k = 1; k <= 9; k++, i++) { /* near -z and +z: n.z = -+(1 - 2^-2k) */
		double e = ldexp(1.0, -2 * (int)k), r = sqrt(e * (2.0 - e));
		special(i, r, 0.0, -(1.0 - e));
		i++;
		special(i, 0.0, r, 1.0 - e);
	}
	for (; i < n; i++) {
		double v[3], l;
		int c;
		do {
			for (c = 0; c < 3; c++) {
				s = s * 1664525u + 1013904223u;
				v[c] = (double)(int32_t)s * 0x1p-31;
			}
			l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
		} while (l < 0x1p-4);
		special(i, v[0] / l, v[1] / l, v[2] / l);
	}
	for (i = 0; i < n; i++) {
		fx[i] = (float)nx[i]; fy[i] = (float)ny[i]; fz[i] = (float)nz[i];
	}
}

/* how many of three values are NaN (in double: a float NaN stays NaN) */
static size_t nan3(double a, double b, double c)
{
	return (size_t)(a != a) + (size_t)(b != b) + (size_t)(c != c);
}

static double defect(double ax, double ay, double az, double bx, double by, double bz, double x, double y, double z)
{
	double d = fabs(sqrt(ax * ax + ay * ay + az * az) - 1.0), t;
	t = fabs(sqrt(bx * bx + by * by + bz * bz) - 1.0); d = t > d ? t : d;
	t = fabs(ax * x + ay * y + az * z); d = t > d ? t : d;
	t = fabs(bx * x + by * y + bz * z); d = t > d ? t : d;
	t = fabs(ax * bx + ay * by + az * bz); d = t > d ? t : d;
	return d;
}

static void run_d(const onb_method *m, size_t n)
{
	uint64_t hs = FNV_INIT, hb = FNV_INIT;
	double md = 0.0;
	size_t i, ns = 0, nb = 0;
	int c;
	for (i = 0; i < n; i++) {
		onb_vec3 v, b1, b2;
		double d;
		v.x = nx[i]; v.y = ny[i]; v.z = nz[i];
		m->basis(v, &b1, &b2);
		ns += nan3(b1.x, b1.y, b1.z) + nan3(b2.x, b2.y, b2.z);
		hs = fnv_d(fnv_d(fnv_d(fnv_d(fnv_d(fnv_d(hs, b1.x), b1.y), b1.z), b2.x), b2.y), b2.z);
		if ((m->flags & ONB_HW_RSQRT) && i >= 30 && v.x > -0.5 &&
		    (d = defect(b1.x, b1.y, b1.z, b2.x, b2.y, b2.z, v.x, v.y, v.z)) > md)
			md = d;
	}
	m->batch(n, nx, ny, nz, o[0], o[1], o[2], o[3], o[4], o[5]);
	for (i = 0; i < n; i++)
		for (c = 0; c < 6; c++) {
			hb = fnv_d(hb, o[c][i]);
			nb += o[c][i] != o[c][i];
		}
	printf("%-24s double %016llx %016llx %zu/%zu ", m->name, (unsigned long long)hs, (unsigned long long)hb, ns, nb);
	if (m->flags & ONB_HW_RSQRT) printf("%.3e\n", md); else printf("-\n");
}

static void run_f(const onb_method *m, size_t n)
{
	uint64_t hs = FNV_INIT, hb = FNV_INIT;
	double md = 0.0;
	size_t i, ns = 0, nb = 0;
	int c;
	for (i = 0; i < n; i++) {
		onb_vec3f v, b1, b2;
		double d;
		v.x = fx[i]; v.y = fy[i]; v.z = fz[i];
		m->basisf(v, &b1, &b2);
		ns += nan3(b1.x, b1.y, b1.z) + nan3(b2.x, b2.y, b2.z);
		hs = fnv_f(fnv_f(fnv_f(fnv_f(fnv_f(fnv_f(hs, b1.x), b1.y), b1.z), b2.x), b2.y), b2.z);
		if ((m->flags & ONB_HW_RSQRT) && i >= 30 && v.x > -0.5 &&
		    (d = defect(b1.x, b1.y, b1.z, b2.x, b2.y, b2.z, v.x, v.y, v.z)) > md)
			md = d;
	}
	m->batchf(n, fx, fy, fz, q[0], q[1], q[2], q[3], q[4], q[5]);
	for (i = 0; i < n; i++)
		for (c = 0; c < 6; c++) {
			hb = fnv_f(hb, q[c][i]);
			nb += q[c][i] != q[c][i];
		}
	printf("%-24s float  %016llx %016llx %zu/%zu ", m->name, (unsigned long long)hs, (unsigned long long)hb, ns, nb);
	if (m->flags & ONB_HW_RSQRT) printf("%.3e\n", md); else printf("-\n");
}

int main(int argc, char **argv)
{
	size_t n = argc > 1 ? (size_t)strtoul(argv[1], NULL, 10) : 1048576u, k, nm;
	const onb_method *m = onb_methods(&nm);
	int c;
	if (n < 64) {
		fprintf(stderr, "onbhash: N must be at least 64\n");
		return 2;
	}
	nx = malloc(n * sizeof *nx); ny = malloc(n * sizeof *ny); nz = malloc(n * sizeof *nz);
	fx = malloc(n * sizeof *fx); fy = malloc(n * sizeof *fy); fz = malloc(n * sizeof *fz);
	for (c = 0; c < 6; c++) { o[c] = malloc(n * sizeof *o[c]); q[c] = malloc(n * sizeof *q[c]); }
	if (!nx || !ny || !nz || !fx || !fy || !fz || !o[5] || !q[5]) {
		fprintf(stderr, "onbhash: out of memory\n");
		return 1;
	}
	inputs(n);
	printf("# onbhash %zu inputs, hw rsqrt %d, batch isa %s\n", n, ONB_HAVE_HW_RSQRT, onb_batch_isa());
	for (k = 0; k < nm; k++) {
		if (m[k].basis)
			run_d(&m[k], n);
		run_f(&m[k], n);
	}
	return 0;
}
