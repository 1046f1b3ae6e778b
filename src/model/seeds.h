/*
 * seeds.h - relative error bounds of the approximate reciprocal square
 * roots' seeds, as the certify model uses them: a kernel's seed
 * s(x) is s(x) = (1 + e)/sqrt(x) with |e| <= bound, for every x in
 * [x_lo, x_hi].  The later operations (the Newton step of InvSqrt and
 * SSE_rsqrt_1N, the (float) conversion of the double rsqrt variant) are
 * not part of the seed: the model rounds them op by op.
 *
 *   SEED_RSQRTSS    _mm_rsqrt_ss(x) on THIS CPU (vendors' tables differ):
 *                   measured over every positive normal float.
 *   SEED_INVSQRT_F  0x5f3759df - (i >> 1) (Listing 3 InvSqrt), before its
 *                   Newton step: measured over every positive normal float.
 *   SEED_INVSQRT_D  0x5fe6eb50c7b537a9 - (i >> 1) (Lomont), before Newton:
 *                   proven with outward-rounded intervals (MPFI) over the
 *                   mantissa pieces (seeds_d.c).
 *
 * +0, subnormals and inf are outside [x_lo, x_hi]: the model treats them
 * as singular (what each seed does there: seed_edge_report()).
 *
 * src/certify/ holds the proven extremes; these seed bounds
 * (seeds.c: the float scans and the literature values, seeds_d.c: the
 * double proof, seeds_get.c: the cache, the CPU, the edges) are its first
 * part.  They import only libonb (the kernels' own rsqrt), MPFR and MPFI;
 * the Gappa cross-check is scripts/gappa.sh.
 */
#ifndef ONB_SEEDS_H
#define ONB_SEEDS_H
#include <math.h>
#include <stdint.h>
#include <stdio.h>

typedef enum { SEED_RSQRTSS, SEED_INVSQRT_F, SEED_INVSQRT_D, NSEED } seed_kind;

typedef struct {
	double bound;        /* |s(x) sqrt(x) - 1| <= bound on [x_lo, x_hi], rounded up */
	double worst_x;      /* an input where the largest error was found ...         */
	double worst;        /* ... and that error |s sqrt(x) - 1| (MPFR, nearest)      */
	double x_lo, x_hi;   /* the inputs covered: the positive normal numbers        */
	const char *how;     /* how the bound was obtained                              */
} seed_bound;

/* The bound of seed k, computed on the first call (thread-safe: once per
   process and kind), then cached.  The float kinds enumerate 2^31 - 2^23
   inputs with OpenMP (seconds on 2 cores); the double kind runs the
   interval proof (well under a second).  Call it before a parallel
   region: inside one, the scan's own OpenMP region runs on one thread.
   Returns 0, or -1 for a bad k or a failed computation (message on
   stderr). */
int seed_bound_get(seed_kind k, seed_bound *out);

const char *seed_name(seed_kind k);

/* The seeds exactly as the kernels of include/libonb/onb.h compute them
   (tests/test_seeds.c checks them against onb.h bit for bit). */
float  seed_rsqrtss(float x);
float  seed_invsqrt_f(float x);
double seed_invsqrt_d(double x);

/* D = s^2 x - 1 for float s, x > 0.  sx = s*x is exact (24 + 24 bits);
   hi = (float)sx and lo = sx - hi are exact, each of 24 bits; s*hi and
   s*lo are exact (48 bits); s*hi is in [0.5, 2] so s*hi - 1 is exact
   (Sterbenz): D = (s*hi - 1) + s*lo rounds once, d = D (1 + r) with
   |r| <= 2^-53.  NAN outside the premise. */
static inline double seed_dev_f(float x, float s)
{
	const double sd = s, sx = sd * (double)x;
	const double hi = (double)(float)sx, lo = sx - hi;
	const double a = sd * hi;
	if (!(a >= 0.5 && a <= 2.0) || !isfinite(sx))
		return NAN;
	return (a - 1.0) + sd * lo;
}

/* |s sqrt(x) - 1| for float s, x > 0 normal with s*s*x in [0.5, 2],
   computed from exact partial products: relative error below 2^-50
   (seeds.c explains why). */
double seed_err_f(float x, float s);
/* |s sqrt(x) - 1| for double s, x > 0 in MPFR at 256 bits, rounded up. */
double seed_err_d(double x, double s);

/* The float scan behind seed_bound_get, over the biased exponents
   [eb_lo, eb_hi] (1..254 is every normal float).  bound is |e| at the
   extremes of d = s^2 x - 1 (computed with one rounding), widened by
   2^-52 relative and rounded up (seeds.c).  Also counts the inputs
   whose seed is not s(x * 4^-k) * 2^-k for the base binade pair
   (eb 1, 2): *nonperiodic (NULL to skip that check). */
int seed_scan_float(seed_kind k, int eb_lo, int eb_hi, seed_bound *out,
		    uint64_t *nonperiodic);

/* The double seed's interval proof (seeds_d.c); rtol: the branch and
   bound stops when every box's upper bound is within (1 + rtol) of the
   largest error found at a real input. */
int seed_prove_double(double rtol, seed_bound *out, long *nboxes);

/* This CPU: vendor, brand string, family/model/stepping (CPUID). */
const char *seed_cpu(void);

/* What each seed returns at +0, the smallest and largest subnormal, +inf. */
void seed_edge_report(FILE *f);

#endif
