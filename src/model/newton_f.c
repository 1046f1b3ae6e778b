/*
 * newton_f.c - the float Newton steps on a float seed, measured over every
 * float input of a binade: the extremes of y1 sqrt(x) - 1 for
 * y1 = step(x, seed(x)), as the certify model's enclosure of a step
 * (mvf.c newton_rel) uses them where the input's interval lies in a few
 * binades.  The formula enclosure charges each of the step's roundings its
 * worst case and sign at once, and the seed its largest error in every
 * binade; the scan has the actual steps: Embree's float normalization is
 * within 6.7u of 1/sqrt(x) by the formula, and in [-3.9u, 2.3u] by the scan
 * over [0.5, 2).
 *
 * The steps are the kernels' own (include/libonb/onb.h) where onb.h has
 * them; the contracted ones and Embree's step on the bit trick's seed are
 * written out as model.c's executed cm_newton_fused and cm_newton_embree*
 * run them (tests/test_seeds.c checks them bit for bit against it).
 */
#include <math.h>
#include <mpfr.h>
#include <string.h>
#include "libonb/onb.h"
#include "newton_f.h"

/* The kernels' own functions where onb.h has the step on that seed. */
float newton_f(newton_kind k, seed_kind s, float x)
{
	const float y = s == SEED_RSQRTSS ? seed_rsqrtss(x) : seed_invsqrt_f(x);
	switch (k) {
	case NEWTON_L3:
		return s == SEED_RSQRTSS ? onb__hw_rsqrt_nrf(x) : onb__invsqrtf(x);
	case NEWTON_L3_FUSED:
		return y * fmaf(-y, (x * 0.5f) * y, 1.5f);
	case NEWTON_EMBREE:
		return s == SEED_RSQRTSS ? onb__embree_rsqrtf(x) : 1.5f * y + ((x * -0.5f) * y) * (y * y);
	default:
		return fmaf(y, 1.5f, ((x * -0.5f) * y) * (y * y));
	}
}

static float from_bits(uint32_t i) { float f; memcpy(&f, &i, sizeof f); return f; }

/* The extremes of d = y1^2 x - 1 over the binade eb (seed_dev_f: one
   rounding, |r| <= 2^-53 relative); 0 when every d was defined. */
static int scan_binade(newton_kind k, seed_kind s, int eb, double *dmin, double *dmax)
{
	uint32_t i, lo = (uint32_t)eb << 23, hi = lo + (1u << 23);
	double mn = INFINITY, mx = -INFINITY;
	for (i = lo; i < hi; i++) {
		const float x = from_bits(i);
		const double d = seed_dev_f(x, newton_f(k, s, x));
		if (!(d == d))
			return -1;
		if (d < mn)
			mn = d;
		if (d > mx)
			mx = d;
	}
	*dmin = mn;
	*dmax = mx;
	return 0;
}

/* sqrt(1 + D) - 1 for the D whose rounding is d, rounded outward
   (up: the largest, else the smallest): D within d (1 +- 2^-52). */
static double e_of(double d, int up)
{
	mpfr_t t;
	double r;
	mpfr_init2(t, 256);
	mpfr_set_d(t, d, MPFR_RNDN);
	mpfr_mul_d(t, t, (d > 0) == (up != 0) ? 1.0 + 0x1p-52 : 1.0 - 0x1p-52, MPFR_RNDN); /* exact */
	mpfr_add_ui(t, t, 1, MPFR_RNDN);
	mpfr_sqrt(t, t, up ? MPFR_RNDU : MPFR_RNDD);
	mpfr_sub_ui(t, t, 1, up ? MPFR_RNDU : MPFR_RNDD);
	r = mpfr_get_d(t, up ? MPFR_RNDU : MPFR_RNDD);
	mpfr_clear(t);
	return r;
}

static struct { int state; double lo, hi; } table[NNEWTON][2][256];

int newton_range_f(newton_kind k, seed_kind s, int eb_lo, int eb_hi, double *lo, double *hi)
{
	int eb, ok = 1;
	if ((unsigned)k >= NNEWTON || (s != SEED_RSQRTSS && s != SEED_INVSQRT_F) || eb_lo < 1 || eb_hi > 254 ||
	    eb_lo > eb_hi)
		return -1;
	*lo = INFINITY;
	*hi = -INFINITY;
	for (eb = eb_lo; eb <= eb_hi && ok; eb++) {
		int st;
#pragma omp critical(newton_table)
		{
			st = table[k][s][eb].state;
			if (st == 0) {
				double dmin, dmax;
				st = scan_binade(k, s, eb, &dmin, &dmax) == 0 ? 1 : -1;
				if (st == 1) {
					table[k][s][eb].lo = e_of(dmin, 0);
					table[k][s][eb].hi = e_of(dmax, 1);
				}
				table[k][s][eb].state = st;
			}
			if (st == 1) {
				*lo = fmin(*lo, table[k][s][eb].lo);
				*hi = fmax(*hi, table[k][s][eb].hi);
			}
		}
		ok = st == 1;
	}
	return ok ? 0 : -1;
}
