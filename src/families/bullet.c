/*
 * bullet.c - Bullet's btPlaneSpace1 (and ODE's dPlaneSpace, its alias):
 * when |z| > 1/sqrt(2) (rounded to the format), b1 = (0, -z, y)/|.|,
 * else (-y, x, 0)/|.|; b2 = n x b1, written out with its long component
 * simplified to a k = |.|.
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when |z| > SIMDSQRT12 in the format */
int FAMILY_BRANCH(bullet)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT)
		return fabsf((float)n[2]) > 0x1.6a09e6p-1f;
	if (prec == PREC_HALF)   /* SIMDSQRT12 in binary16 */
		return fabs(n[2]) > prec_half_round(0x1.6a09e667f3bcdp-1);
	return fabs(n[2]) > 0x1.6a09e667f3bcdp-1;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(bullet)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	xperp_cross(br ? 0 : 2, +1, n, r1, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "|z| > 1/sqrt2: b1 = (0, -z, y) / len" : "|z| <= 1/sqrt2: b1 = (-y, x, 0) / len";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_perp_cross(c, br ? 0 : 2, +1, n, r1, r2);   /* (0, -z, y) or (-y, x, 0) */
}

static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	cv a, k;
	(void)m;
	if (cm_branch_abs(c, 0, CM_GT, n[2], K(0x1.6a09e667f3bcdp-1))) {
		a = ADDM(MUL(n[1], n[1]), n[2], n[2]);   /* contracted: fma(z, z, y*y) */
		k = DIV(K(1.0), cm_sqrt(c, P, a));
		out[0] = K(0.0); out[1] = MUL(cm_neg(c, n[2]), k); out[2] = MUL(n[1], k);
		out[3] = MUL(a, k); out[4] = MUL(cm_neg(c, n[0]), out[2]); out[5] = MUL(n[0], out[1]);
	} else {
		a = MADD(n[0], n[0], MUL(n[1], n[1]));   /* contracted: fma(x, x, y*y) */
		k = DIV(K(1.0), cm_sqrt(c, P, a));
		out[0] = MUL(cm_neg(c, n[1]), k); out[1] = MUL(n[0], k); out[2] = K(0.0);
		out[3] = MUL(cm_neg(c, n[2]), out[1]); out[4] = MUL(n[2], out[0]); out[5] = MUL(a, k);
	}
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

FAMILY_DECLARE(bullet);
const study_family family_bullet = {
	"bullet", FAMILY_PASSES(bullet), names, mpfr, FAMILY_PAIRS(bullet), family_no_variant,
	family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
