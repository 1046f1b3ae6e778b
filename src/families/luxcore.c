/*
 * luxcore.c - LuxCoreRender's CoordinateSystem (include/luxrays/core/
 * geometry/vector.h), as Frame::SetFromZ uses it: b2 = (-n.y, n.x, 0) /
 * sqrt(n.x^2 + n.y^2), b1 = n x b2; within 1e-5 of the z axis
 * (sqrt(n.x^2 + n.y^2) < 1e-5, a double literal) b2 = (1, 0, 0), which is
 * not orthogonal to n: the fallback's defect is the formula's own.
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when sqrt(n.x^2 + n.y^2) < 1e-5 as the kernel computes it */
int FAMILY_BRANCH(luxcore)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT) {
		const float x = (float)n[0], y = (float)n[1];
		return (double)sqrtf(x * x + y * y) < 1e-5;
	}
	if (prec == PREC_HALF)
		return prec_half_round(sqrt(prec_half_round(prec_half_round(n[0] * n[0]) + prec_half_round(n[1] * n[1])))) <
		       1e-5;
	return sqrt(n[0] * n[0] + n[1] * n[1]) < 1e-5;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(luxcore)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	if (br) {
		xset3(r2, 1.0, 0.0, 0.0);
	} else {
		xaxis_cross(r2, 2, +1, n);
		xnormalize(r2, bad);
	}
	xcross(r1, n, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "sqrt(n.x^2 + n.y^2) < 1e-5: b2 = (1, 0, 0)" : "b2 = (-n.y, n.x, 0) / sqrt(n.x^2 + n.y^2)";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	if (br) {
		kit_set3(r2, 1.0, 0.0, 0.0);
	} else {
		kit_axis_cross(r2, 2, +1, n);   /* (-y, x, 0) */
		kit_normalize(c, r2);
	}
	kit_cross(c, r1, n, r2);
}

/* The comparison is with the double 1e-5, in either format. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const cv len = cm_sqrt(c, P, MADD(n[0], n[0], MUL(n[1], n[1])));   /* contracted: fma(x, x, y*y) */
	cv v[3];
	(void)m;
	if (cm_branch(c, 0, CM_LT, len, cm_cst(c, 1e-5))) {
		cm_formula_nonzero(c, CQ_ALL);
		v[0] = K(1.0); v[1] = K(0.0); v[2] = K(0.0);
	} else {   /* b2 = (-y, x, 0)/|.|, b1 = n x b2: only |b1| depends on |n| */
		cm_formula_exact_n(c, ZN_UNIT_B2, 1u << CQ_N1);
		v[0] = DIV(cm_neg(c, n[1]), len); v[1] = DIV(n[0], len); v[2] = K(0.0);
	}
	out[3] = MUL(v[0], K(1.0)); out[4] = MUL(v[1], K(1.0)); out[5] = MUL(v[2], K(1.0));
	cm_formula_zero_after(c, (1u << CQ_D1N) | (1u << CQ_D12));   /* b1 = n x b2 */
	mk_cross_out(c, P, n, out, 0, 1, "fsf");  /* contracted as GCC fuses them */
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return 0; }

FAMILY_DECLARE(luxcore);
const study_family family_luxcore = {
	"luxcore", FAMILY_PASSES(luxcore), names, mpfr, FAMILY_PAIRS(luxcore), family_no_variant,
	family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
};
#endif
