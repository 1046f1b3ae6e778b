/*
 * physx.c - PhysX's PxComputeBasisVectors: when |y| <= 0.9999f,
 * b1 = (z, 0, -x)/|.| and b2 = n x b1 (not normalized); otherwise
 * b1 = (1, 0, 0) whatever n is and b2 = (0, z, -y)/|.|.  physx_fixed
 * (variant ONB__WILD_FIXED, this project's fix) takes b1 = b2 x n there.
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN
#define PHYSX_T 0x1.fff2e4p-1 /* 0.9999f */

#if FAMILY_RULE_PASS
/* 1 when |y| > 0.9999f: the fallback b1 = (1, 0, 0) */
int FAMILY_BRANCH(physx)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT)
		return !(fabsf((float)n[1]) <= 0.9999f);
	if (prec == PREC_HALF)   /* 0.9999f is 1 in binary16 */
		return !(fabs(n[1]) <= prec_half_round((double)0.9999f));
	return !(fabs(n[1]) <= PHYSX_T);
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(physx)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)loc;
	if (br) {
		r2[0] = xc(0.0); r2[1] = n[2]; r2[2] = xneg(n[1]);
		xnormalize(r2, bad);
		if (m->norm == ONB__WILD_FIXED)
			xcross(r1, r2, n, bad);
		else
			xset3(r1, 1.0, 0.0, 0.0);
	} else {
		r1[0] = n[2]; r1[1] = xc(0.0); r1[2] = xneg(n[0]);
		xnormalize(r1, bad);
		xcross(r2, n, r1, bad);
	}
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)buf; (void)n;
	if (b)
		return m->norm == ONB__WILD_FIXED ? "|y| > 0.9999f: b2 = unit(0, z, -y), b1 = b2 x n"
		                                  : "|y| > 0.9999f: b1 = (1, 0, 0), b2 = unit(0, z, -y)";
	return "|y| <= 0.9999f: b1 = unit(z, 0, -x), b2 = n x b1";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)loc;
	if (br) {
		mpfr_set_zero(r2[0], 1); mpfr_set(r2[1], n[2], R); mpfr_neg(r2[2], n[1], R);
		kit_normalize(c, r2);
		if (m->norm == ONB__WILD_FIXED)
			kit_cross(c, r1, r2, n);
		else
			kit_set3(r1, 1.0, 0.0, 0.0);
	} else {
		mpfr_set(r1[0], n[2], R); mpfr_set_zero(r1[1], 1); mpfr_neg(r1[2], n[0], R);
		kit_normalize(c, r1);
		kit_cross(c, r2, n, r1);
	}
}

/* PxVec3::normalize: m = sqrt(x*x + y*y + z*z), f = 1/m, three products
   (m > 0 on the unit sphere) */
static void normalize(cm *c, int P, cv v[3])
{
	const cv s = cm_sqrt(c, P, mk_dot3_zf(c, P, v, v));
	cv f;
	int i;
	/* the kernel's `if (m > 0)`: always taken on the unit sphere in float
	   and double; in half the squares underflow near +-y (where 0.9999f
	   is 1 and the fallback never comes), m = 0 and v stays unscaled.
	   Branch point 1, in half only (the float and double models keep
	   their one branch point). */
	if (P == PREC_HALF && !cm_branch(c, 1, CM_GT, s, K(0.0)))
		return;
	f = DIV(K(1.0), s);
	for (i = 0; i < 3; i++)
		v[i] = MUL(v[i], f);
}

static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	if (cm_branch_abs(c, 0, CM_GT, n[1], K(PHYSX_T))) {
		out[3] = K(0.0); out[4] = n[2]; out[5] = cm_neg(c, n[1]);
		normalize(c, P, out + 3);
		if (m->norm == ONB__WILD_FIXED) {
			mk_cross_out(c, P, n, out, 0, 0, "ssf");  /* as GCC fuses it */
		} else {   /* b1 = (1, 0, 0): b1.n = n.x, not 0 on the unit sphere */
			cm_formula_nonzero(c, 1u << CQ_D1N);
			out[0] = K(1.0); out[1] = K(0.0); out[2] = K(0.0);
		}
	} else {
		out[0] = n[2]; out[1] = K(0.0); out[2] = cm_neg(c, n[0]);
		normalize(c, P, out);
		out[3] = MUL(n[1], out[2]);
		out[4] = SUBM(MUL(n[2], out[0]), n[0], out[2]);
		out[5] = MUL(cm_neg(c, n[1]), out[0]);
	}
}

/* |b1| = 1, b2.n = 0 and b1.b2 = 0 on both branches for any n; b1.n = x
   on physx's fallback, |b2| = |n| on the main branch and |b1| = |n| on
   physx_fixed's fallback */
static unsigned zero_any_n(const onb_method *m)
{
	return m->norm == ONB__WILD_FIXED ? ((1u << CQ_D1N) | (1u << CQ_D2N) | (1u << CQ_D12))
	                                  : ((1u << CQ_N1) | (1u << CQ_D2N) | (1u << CQ_D12));
}
static int variant(const onb_method *m) { return m->norm == ONB__WILD_FIXED; }

FAMILY_DECLARE(physx);
const study_family family_physx = {
	"physx", FAMILY_PASSES(physx), names, mpfr, FAMILY_PAIRS(physx), variant,
	family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
