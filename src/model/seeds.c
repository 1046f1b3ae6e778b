/*
 * seeds.c - the float seeds' bounds, measured over every positive normal
 * float, the cache behind seed_bound_get, and the CPU they hold for.
 *
 * Literature values, for comparison only (nothing below uses them):
 *   rsqrtss: Intel documents |relative error| <= 1.5 * 2^-12 (= 3.66e-4)
 *            (SDM vol. 2, RSQRTSS); AMD documents the same limit, but the
 *            tables differ between vendors and generations, hence the
 *            measurement on this CPU.
 *   0x5f3759df: Lomont 2003 ("Fast inverse square root") gives a largest
 *            relative error of about 1.75e-3 AFTER one Newton step; the
 *            seed alone, which is what is bounded here, is off by a few
 *            percent.
 *
 * Why one binade pair is enough for the bit trick: for a normal float with
 * biased exponent eb and fraction F, i >> 1 has exponent field
 * floor(eb / 2) and fraction (eb odd ? 2^22 : 0) + floor(F / 2), so
 * 0x5f3759df - (i >> 1) depends on eb only through its parity, apart from
 * the exponent 190 - floor(eb / 2) (minus a borrow), which stays in
 * [62, 190]: s(4x) = s(x) / 2 exactly, and s sqrt(x) - 1 is the same.  The
 * scan checks s(x) == s(x0) 2^-k bit for bit anyway, for both seeds, since
 * rsqrtss's table is the hardware's and only measurement can show it.
 */
#include <math.h>
#include <mpfr.h>
#include <stdlib.h>
#include <string.h>
#include "libonb/onb.h"
#include "seeds.h"

/* The kernels' own function: rsqrtss where onb.h has it (ONB_HAVE_HW_RSQRT),
   else its fallback 1/sqrtf. */
float seed_rsqrtss(float x) { return onb__hw_rsqrtf(x); }

float seed_invsqrt_f(float x)
{
	uint32_t i;
	memcpy(&i, &x, sizeof i);
	i = 0x5f3759dfu - (i >> 1); /* onb__invsqrtf's seed, before Newton */
	memcpy(&x, &i, sizeof x);
	return x;
}

double seed_invsqrt_d(double x)
{
	uint64_t i;
	memcpy(&i, &x, sizeof i);
	i = UINT64_C(0x5fe6eb50c7b537a9) - (i >> 1); /* onb__invsqrt's seed */
	memcpy(&x, &i, sizeof x);
	return x;
}

const char *seed_name(seed_kind k)
{
	static const char *const names[NSEED] = { "rsqrtss", "invsqrt_f", "invsqrt_d" };
	return (unsigned)k < NSEED ? names[k] : "?";
}

/* |e| = |D| / (1 + sqrt(1 + D)) from d: 1 + d, the sqrt, 1 + sqrt and the
   division add at most 3 roundings on quantities near 1 and 2 to d's one;
   the condition of D -> e is <= 1.02 for |D| <= 0.07: in all the result
   is within a factor 1 +- 4 * 2^-53 = 1 +- 2^-51 of |e|. */
double seed_err_f(float x, float s)
{
	const double d = seed_dev_f(x, s);
	return d == d ? fabs(d / (1.0 + sqrt(1.0 + d))) : -1.0;
}

/* An upper bound of |sqrt(1 + D) - 1| for every D between 0 and
   d (1 + 2^-52), which holds every D whose rounding is d. */
static double err_above(double d)
{
	mpfr_t t;
	double r;
	mpfr_init2(t, 256);
	mpfr_set_d(t, d, MPFR_RNDN);
	mpfr_mul_d(t, t, 1.0 + 0x1p-52, MPFR_RNDN);    /* exact: 106 bits */
	mpfr_add_ui(t, t, 1, MPFR_RNDN);               /* exact */
	mpfr_sqrt(t, t, MPFR_RNDN);                    /* 2^-256 relative */
	mpfr_sub_ui(t, t, 1, MPFR_RNDN);
	mpfr_abs(t, t, MPFR_RNDN);
	r = nextafter(mpfr_get_d(t, MPFR_RNDU), INFINITY); /* covers the 2^-256 */
	mpfr_clear(t);
	return r;
}

double seed_err_d(double x, double s)
{
	mpfr_t t;
	double r;
	mpfr_init2(t, 256);
	mpfr_set_d(t, s, MPFR_RNDN);           /* exact */
	mpfr_mul_d(t, t, s, MPFR_RNDN);        /* exact: 106 bits */
	mpfr_mul_d(t, t, x, MPFR_RNDN);        /* exact: 159 bits */
	mpfr_sqrt(t, t, MPFR_RNDN);            /* 2^-256 relative */
	mpfr_sub_ui(t, t, 1, MPFR_RNDN);
	mpfr_abs(t, t, MPFR_RNDN);
	r = mpfr_get_d(t, MPFR_RNDU);
	mpfr_clear(t);
	return r;
}

static float seed_f(seed_kind k, float x)
{
	return k == SEED_RSQRTSS ? seed_rsqrtss(x) : seed_invsqrt_f(x);
}

static float from_bits(uint32_t i) { float f; memcpy(&f, &i, sizeof f); return f; }
static uint32_t to_bits(float f) { uint32_t i; memcpy(&i, &f, sizeof i); return i; }

/* Is s(x) == s(x0) 2^-k, x = x0 4^k with x0 in the binades eb 1 and 2? */
static int periodic(seed_kind k, uint32_t i, float s)
{
	const int eb = (int)(i >> 23), eb0 = 2 - (eb & 1), kk = (eb - eb0) / 2;
	const float x0 = from_bits((i & 0x807fffffu) | ((uint32_t)eb0 << 23));
	return to_bits(ldexpf(seed_f(k, x0), -kk)) == to_bits(s);
}

/* The scan keeps the extremes of d = s^2 x - 1, not of |e|: |e| =
   |sqrt(1 + D) - 1| grows with D above 0 and falls with it below, so the
   largest |e| is at the largest or the smallest D, and the hot loop needs
   no square root. */
typedef struct { double dmax, dmin; uint32_t amax, amin; uint64_t nonper, bad; } scan_acc;

static void scan_merge(scan_acc *into, const scan_acc *a)
{
	if (a->dmax > into->dmax || (a->dmax == into->dmax && a->amax < into->amax))
		into->dmax = a->dmax, into->amax = a->amax;
	if (a->dmin < into->dmin || (a->dmin == into->dmin && a->amin < into->amin))
		into->dmin = a->dmin, into->amin = a->amin;
	into->nonper += a->nonper;
	into->bad += a->bad;
}

static void scan_range(seed_kind k, int64_t lo, int64_t hi, int check, scan_acc *acc)
{
	int64_t i;
#pragma omp parallel
	{
		scan_acc my = { -INFINITY, INFINITY, 0, 0, 0, 0 };
#pragma omp for schedule(static, 1 << 16) nowait
		for (i = lo; i < hi; i++) {
			const float x = from_bits((uint32_t)i), s = seed_f(k, x);
			const double d = seed_dev_f(x, s);
			if (d != d)
				my.bad++;
			if (d > my.dmax)
				my.dmax = d, my.amax = (uint32_t)i;
			if (d < my.dmin)
				my.dmin = d, my.amin = (uint32_t)i;
			if (check && !periodic(k, (uint32_t)i, s))
				my.nonper++;
		}
#pragma omp critical(seed_scan)
		scan_merge(acc, &my);
	}
}

/* bound, worst_x and worst from the extremes of d. */
static void scan_result(seed_kind k, const scan_acc *acc, seed_bound *out)
{
	const float xa = from_bits(acc->amax), xb = from_bits(acc->amin);
	const double ea = seed_err_d(xa, seed_f(k, xa)), eb = seed_err_d(xb, seed_f(k, xb));
	const double ba = err_above(acc->dmax), bb = err_above(acc->dmin);
	out->bound = ba > bb ? ba : bb;
	out->worst_x = ea >= eb ? xa : xb;
	out->worst = ea >= eb ? ea : eb;
}

int seed_scan_float(seed_kind k, int eb_lo, int eb_hi, seed_bound *out,
		    uint64_t *nonperiodic)
{
	scan_acc acc = { -INFINITY, INFINITY, 0, 0, 0, 0 };
	if ((k != SEED_RSQRTSS && k != SEED_INVSQRT_F) || eb_lo < 1 || eb_hi > 254 || eb_lo > eb_hi) {
		fprintf(stderr, "seed_scan_float: bad kind %d or exponents %d..%d\n", (int)k, eb_lo, eb_hi);
		return -1;
	}
	scan_range(k, (int64_t)eb_lo << 23, (int64_t)(eb_hi + 1) << 23, nonperiodic != NULL, &acc);
	if (acc.bad) {
		fprintf(stderr, "seed_scan_float: %s: %llu inputs outside s^2 x in [0.5, 2]\n",
			seed_name(k), (unsigned long long)acc.bad);
		return -1;
	}
	if (nonperiodic)
		*nonperiodic = acc.nonper;
	scan_result(k, &acc, out);
	out->x_lo = from_bits((uint32_t)eb_lo << 23);
	out->x_hi = from_bits(((uint32_t)(eb_hi + 1) << 23) - 1);
	out->how = k == SEED_RSQRTSS
		? "rsqrtss on this CPU (seed_cpu()), every positive normal float, extremes of s^2 x - 1 from exact partial products"
		: "0x5f3759df - (i >> 1), every positive normal float, extremes of s^2 x - 1 from exact partial products";
	return 0;
}
