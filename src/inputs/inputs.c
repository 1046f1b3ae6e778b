/*
 * inputs.c - the input distributions (see inputs.h).
 */
#include <math.h>
#include <float.h>
#include <stdlib.h>
#include <string.h>
#include "inputs/inputs.h"
#include "methods/kernels.h"
#include "inputs/rng.h"
#include "common/options.h"

static const char *const names[NDIST] = {
	"uniform", "north", "south", "threshold", "exhaustive", "nonunit", "grid"
};

const char *const *dist_names(void) { return names; }

const char *dist_name(int d) { return d >= 0 && d < NDIST ? names[d] : "?"; }

int dist_find(const char *name)
{
	int i;
	for (i = 0; i < NDIST; i++)
		if (strcmp(name, names[i]) == 0)
			return i;
	return -1;
}

/* Round to the format.  The float goes through a volatile: GCC 12.2 at -O2
   drops the (float) rounding in (double)(float)(double)(long double
   expression) when the expression comes from sinl/cosl (a miscompilation
   found by tests/test_sweep.c: uniform float inputs came out as doubles). */
double fmt_round(double x, int prec)
{
	if (prec == PREC_HALF)
		return prec_half_round(x);
	if (prec == PREC_FLOAT) {
		volatile float f = (float)x;
		return f;
	}
	return x;
}

/* Ordinal of a finite value: consecutive representable values have
   consecutive ordinals, -0 and +0 both 0. */
static int64_t ordinal(double x, int prec)
{
	if (prec == PREC_HALF) {   /* the binary16 encoding's magnitude bits, from the value */
		const double a = fabs(x);
		int64_t m;
		if (a < 0x1p-14)
			m = (int64_t)(a * 0x1p24);
		else
			m = (int64_t)(ilogb(a) + 15) * 1024 + (int64_t)(ldexp(a, 10 - ilogb(a)) - 1024.0);
		return signbit(x) ? -m : m;
	}
	if (prec == PREC_FLOAT) {
		float f = (float)x;
		uint32_t u;
		memcpy(&u, &f, 4);
		return (u >> 31) ? -(int64_t)(u & 0x7fffffffu) : (int64_t)u;
	} else {
		uint64_t u;
		memcpy(&u, &x, 8);
		return (u >> 63) ? -(int64_t)(u & 0x7fffffffffffffffu) : (int64_t)u;
	}
}

static double from_ordinal(int64_t o, int prec)
{
	if (prec == PREC_HALF) {
		const int64_t m = o < 0 ? -o : o;
		const double a = m < 1024 ? (double)m * 0x1p-24
		                          : ldexp(1024.0 + (double)(m % 1024), (int)(m / 1024) - 25);
		return m >= 0x7c00 ? (o < 0 ? -INFINITY : INFINITY) : (o < 0 ? -a : a);
	}
	if (prec == PREC_FLOAT) {
		uint32_t u = o < 0 ? (uint32_t)(-o) | 0x80000000u : (uint32_t)o;
		float f;
		memcpy(&f, &u, 4);
		return f;
	} else {
		uint64_t u = o < 0 ? (uint64_t)(-o) | 0x8000000000000000u : (uint64_t)o;
		double d;
		memcpy(&d, &u, 8);
		return d;
	}
}

double fmt_step(double x, int64_t k, int prec)
{
	return from_ordinal(ordinal(x, prec) + k, prec);
}

/* ---- threshold list ---------------------------------------------------- */

typedef struct {
	double *v;
	size_t n, cap;
	int prec;
	uint64_t seed;
} list;

static int push(list *l, double x, double y, double z)
{
	if (l->n == l->cap) {
		size_t cap = l->cap ? 2 * l->cap : 4096;
		double *v = realloc(l->v, cap * 3 * sizeof *v);
		if (!v)
			return -1;
		l->v = v;
		l->cap = cap;
	}
	l->v[3 * l->n + 0] = fmt_round(x, l->prec);
	l->v[3 * l->n + 1] = fmt_round(y, l->prec);
	l->v[3 * l->n + 2] = fmt_round(z, l->prec);
	l->n++;
	return 0;
}

/* Inputs with one fixed component c (index axis) and the other two on
   the circle of radius sqrt(1 - c^2), at na random angles. */
/* The other two are those of an exact unit vector whose fixed component
   lies within half a step of c (a pseudo-random offset), so the input is
   unit to the format's rounding, as a normalized normal is. */
static int ring(list *l, int axis, double c, int na)
{
	int a;
	const long double up = (long double)fmt_step(c, 1, l->prec) - c, down = c - (long double)fmt_step(c, -1, l->prec);
	for (a = 0; a < na; a++) {
		const long double u = rng_u01(l->seed, 3000 + (uint64_t)axis, l->n) - 0.5L;
		long double ct = (long double)c + (u > 0 ? u * up : u * down);
		long double r;
		const long double phi = 6.283185307179586476925L * rng_u01(l->seed, 1000 + (uint64_t)axis, l->n);
		if (ct > 1.0L) ct = 1.0L;
		if (ct < -1.0L) ct = -1.0L;
		if (c == 0.0) ct = 0.0L; /* keep +-0 exact: the sign of n.z is what is tested */
		r = sqrtl(fmaxl(0.0L, 1.0L - ct * ct));
		const double p = (double)(r * cosl(phi)), q = (double)(r * sinl(phi));
		int rc = axis == 0 ? push(l, c, p, q) : axis == 1 ? push(l, q, c, p) : push(l, p, q, c);
		if (rc)
			return -1;
	}
	return 0;
}

/* |n_i| = |n_j| boundaries (Hughes-Moller x/z, pbrt x/y, Stark's three):
   n_i = +-s, n_j = +-s, then n_i moved by k steps. */
static int diagonal(list *l, int i, int j, int na)
{
	int a, si, sj, k;
	const int o = 3 - i - j;
	for (a = 0; a < na; a++) {
		const double c = 2.0 * rng_u01(l->seed, 2000 + (uint64_t)(3 * i + j), (uint64_t)a) - 1.0;
		const double s = fmt_round(sqrt((1.0 - c * c) / 2.0), l->prec);
		for (si = -1; si <= 1; si += 2)
			for (sj = -1; sj <= 1; sj += 2)
				for (k = -3; k <= 3; k++) {
					double v[3];
					v[o] = c;
					v[i] = fmt_step(si * s, k, l->prec);
					v[j] = sj * s;
					if (push(l, v[0], v[1], v[2]))
						return -1;
				}
	}
	return 0;
}

/* The engines' own thresholds (the registry's wild rows): PhysX's
   |n.y| = 0.9999f, Bullet's |n.z| = 1/sqrt 2, MuJoCo's |n.y| = 1/2, each
   +-8 steps; and Open3D's singular points n = +-(0, c, c), c = 1/sqrt 2,
   exactly and with n.x tiny or n.z a few steps off. */
static int engines(list *l, const double tiny[4])
{
	const int P = l->prec, NA = 8;
	const double c = fmt_round(0.70710678118654752440, P);
	int k, s, a, rc = 0;
	for (k = -8; k <= 8; k++)
		for (s = -1; s <= 1; s += 2) {
			rc |= ring(l, 1, fmt_step(s * (double)0.9999f, k, P), NA);
			rc |= ring(l, 2, fmt_step(s * c, k, P), NA);
			rc |= ring(l, 1, fmt_step(s * 0.5, k, P), NA);
		}
	for (s = -1; s <= 1; s += 2)
		for (a = 0; a < 4; a++)
			for (k = -2; k <= 2; k++) {
				rc |= push(l, tiny[a], s * c, fmt_step(s * c, k, P));
				rc |= push(l, -tiny[a], s * c, fmt_step(s * c, k, P));
			}
	return rc;
}

static int build_threshold(dist_spec *d)
{
	list l = { NULL, 0, 0, d->prec, d->seed };
	const int P = d->prec, NA = 8;
	const prec_format *F = prec_fmt(P);   /* binary16: 2^-24, 2^-14, 2^-10 */
	const double tiny[] = { 0.0, F->sub_step, F->normal_min, 2.0 * F->u, 1e-4, 0x1.4f8b58p-17 /* 1e-5 */ };
	size_t m, nm;
	const onb_method *ms = onb_methods(&nm);
	int k, s, a, b, ax;
	int rc = 0;
	/* every Frisvad-family threshold in the registry, +-8 steps; on n.x and
	   n.y too (an engine may put its pole there: filament's is -y), where
	   only the steps that stay within [-1, 1] (unit inputs) are taken */
	for (m = 0; m < nm; m++)
		if (!isnan(ms[m].threshold))
			for (k = -8; k <= 8; k++) {
				const double c = fmt_step(fmt_round(ms[m].threshold, P), k, P);
				rc |= ring(&l, 2, c, NA);
				for (ax = 0; ax < 2 && fabs(c) <= 1.0; ax++)
					rc |= ring(&l, ax, c, NA);
			}
	/* the south and north poles: 1 -+ n.z from 0 to 32 steps */
	for (k = 0; k <= 32; k++) {
		rc |= ring(&l, 2, fmt_step(-1.0, k, P), NA);
		rc |= ring(&l, 2, fmt_step(1.0, -k, P), NA);
	}
	/* the sign of n.z: +-0, subnormal, smallest normal, eps, 1e-4, 1e-5 */
	for (k = 0; k < 6; k++)
		for (s = -1; s <= 1; s += 2)
			rc |= ring(&l, 2, s * tiny[k], NA);
	/* naive's and rtow's n.x = +-0.9, and naive's singular n = -x */
	for (k = -8; k <= 8; k++)
		for (s = -1; s <= 1; s += 2)
			rc |= ring(&l, 0, fmt_step(fmt_round(s * 0.9, P), k, P), NA);
	for (k = 0; k <= 32; k++)
		rc |= ring(&l, 0, fmt_step(-1.0, k, P), NA);
	rc |= engines(&l, tiny);
	/* |x| = |z|, |x| = |y|, |y| = |z| */
	rc |= diagonal(&l, 0, 2, NA);
	rc |= diagonal(&l, 0, 1, NA);
	rc |= diagonal(&l, 1, 2, NA);
	/* the six axes exactly, and with the other components tiny: 0 to eps
	   (unit to the format); in float also 1e-4 and 1e-5 on one side (still
	   unit to float rounding: luxcore's cut at sqrt(x^2 + y^2) = 1e-5) */
	for (ax = 0; ax < 3; ax++)
		for (s = -1; s <= 1; s += 2)
			for (a = 0; a < (P != PREC_DOUBLE ? 6 : 4); a++) /* binary16 as float */
				for (b = 0; b < 4; b++) {
					double v[3];
					v[ax] = s;
					v[(ax + 1) % 3] = tiny[a];
					v[(ax + 2) % 3] = -tiny[b];
					rc |= push(&l, v[0], v[1], v[2]);
				}
	if (rc) {
		free(l.v);
		study_error("out of memory building the threshold inputs");
		return -1;
	}
	d->list = l.v;
	d->count = l.n;
	return 0;
}

int dist_prepare(dist_spec *d)
{
	d->list = NULL;
	switch (d->dist) {
	case DIST_THRESHOLD:
		return build_threshold(d);
	case DIST_EXHAUSTIVE:
		d->count = d->ex_values * (uint64_t)d->ex_azimuths;
		return 0;
	case DIST_GRID:
		d->count = (uint64_t)d->grid_rows * (uint64_t)d->grid_cols;
		return 0;
	default:
		return 0;
	}
}

void dist_free(dist_spec *d)
{
	free(d->list);
	d->list = NULL;
}

static void on_sphere(long double z, long double phi, long double scale, int prec, double n[3])
{
	const long double r = sqrtl(fmaxl(0.0L, 1.0L - z * z));
	n[0] = fmt_round((double)(scale * r * cosl(phi)), prec);
	n[1] = fmt_round((double)(scale * r * sinl(phi)), prec);
	n[2] = fmt_round((double)(scale * z), prec);
}

#define TWO_PI 6.283185307179586476925L

static void strat_edges(int h, long double *lo, long double *hi)
{
	*lo = h ? ldexpl(1.0L, h - NSTRAT + 1) : 0.0L;
	*hi = ldexpl(1.0L, h - NSTRAT + 2);
}
int dist_stratum(const dist_spec *d, uint64_t i)
{
	return d->dist == DIST_UNIFORM ? (int)(i % NSTRAT) : 0;
}
double dist_stratum_weight(int dist, int h)
{
	long double lo, hi;
	if (dist != DIST_UNIFORM)
		return h == 0 ? 1.0 : 0.0;
	strat_edges(h, &lo, &hi);
	return (double)((hi - lo) / 2.0L);
}

void dist_sample(const dist_spec *d, uint64_t i, double n[3], double loc[3], double *aux)
{
	const uint64_t S = d->seed;
	const int P = d->prec;
	const double eps = 2.0 * prec_fmt(P)->u;   /* FLT_EPSILON, DBL_EPSILON, 2^-10 */
	*aux = 0.0;
	switch (d->dist) {
	case DIST_UNIFORM: {
		/* stratified in 1 + n.z (inputs.h): uniform within stratum i mod NSTRAT */
		long double lo, hi;
		strat_edges((int)(i % NSTRAT), &lo, &hi);
		on_sphere(lo + (hi - lo) * rng_u01(S, 1, i) - 1.0L, TWO_PI * rng_u01(S, 2, i), 1.0L, P, n);
		break;
	}
	case DIST_NORTH:
	case DIST_SOUTH: {
		const double lo = log10(eps), hi = -1.0;
		const long double h = powl(10.0L, lo + (hi - lo) * rng_u01(S, 3, i));
		const long double phi = TWO_PI * rng_u01(S, 4, i);
		const long double z = d->dist == DIST_NORTH ? 1.0L - h : h - 1.0L;
		const long double r = sqrtl(h * (2.0L - h));
		n[0] = fmt_round((double)(r * cosl(phi)), P);
		n[1] = fmt_round((double)(r * sinl(phi)), P);
		n[2] = fmt_round((double)z, P);
		break;
	}
	case DIST_THRESHOLD:
		n[0] = d->list[3 * i]; n[1] = d->list[3 * i + 1]; n[2] = d->list[3 * i + 2];
		break;
	case DIST_EXHAUSTIVE: {
		const uint64_t j = i / (uint64_t)d->ex_azimuths, a = i % (uint64_t)d->ex_azimuths;
		/* n.z is the j-th representable value; x and y are those of an exact
		   unit vector whose n.z lies within half an ulp of it (a fixed
		   pseudo-random offset), so the input is unit to the format's
		   rounding, as a normalized normal is. */
		const double z = fmt_step(d->ex_from, (int64_t)j, P);
		const long double up = (long double)fmt_step(z, 1, P) - z;
		const long double jit = rng_u01(S, 10, i) - (z == -1.0 ? 0.0L : 0.5L);
		long double zt = (long double)z + jit * up;
		if (zt > 1.0L) zt = 1.0L;
		on_sphere(zt, TWO_PI * ((long double)a + 0.5L) / d->ex_azimuths, 1.0L, P, n);
		n[2] = z;
		break;
	}
	case DIST_NONUNIT: {
		const uint64_t u = rng_u64(S, 5, i);
		const double mag = pow(10.0, -7.0 + 5.0 * (double)(u >> 11) * 0x1p-53);
		const double dd = (u & 1) ? -mag : mag;
		on_sphere(1.0L - 2.0L * rng_u01(S, 6, i), TWO_PI * rng_u01(S, 7, i), 1.0L + dd, P, n);
		*aux = dd;
		break;
	}
	case DIST_GRID: {
		const uint64_t r = i / (uint64_t)d->grid_cols, c = i % (uint64_t)d->grid_cols;
		on_sphere(-1.0L + 2.0L * ((long double)r + 0.5L) / d->grid_rows,
		          TWO_PI * ((long double)c + 0.5L) / d->grid_cols, 1.0L, P, n);
		*aux = (double)i;
		break;
	}
	default:
		n[0] = n[1] = 0.0; n[2] = 1.0;
	}
	/* a cosine-weighted local direction (Malley's method) */
	{
		const long double u1 = rng_u01(S, 8, i), phi = TWO_PI * rng_u01(S, 9, i);
		const long double r = sqrtl(u1);
		loc[0] = fmt_round((double)(r * cosl(phi)), P);
		loc[1] = fmt_round((double)(r * sinl(phi)), P);
		loc[2] = fmt_round((double)sqrtl(1.0L - u1), P);
	}
}
