/*
 * luxcore.c - LuxCoreRender's CoordinateSystem (include/luxrays/core/
 * geometry/vector.h), as Frame::SetFromZ uses it: b2 = (-n.y, n.x, 0) /
 * sqrt(n.x^2 + n.y^2), b1 = n x b2; within 1e-5 of the z axis
 * (sqrt(n.x^2 + n.y^2) < 1e-5, a double literal) b2 = (1, 0, 0), which is
 * not orthogonal to n: the fallback's defect is the formula's own.
 * luxcore_fixed (variant ONB__WILD_FIXED, this project's fix) takes there
 * b2 = unit(e1 - n.x n) = (1 - x^2, -x y, -x z)/|.|, (1, 0, 0) made
 * perpendicular to n; b1 = n x b2 as before.  In exact arithmetic b1.x =
 * y (-x z) - z (-x y) = 0 for every n: exact_zero.
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when sqrt(n.x^2 + n.y^2) < 1e-5 as the kernel computes it (in the
   FMA pass as its --fma copy: luxcore's fma(x, x, y*y); luxcore_fixed's
   x*x is shared with its fallback's 1 - x*x, and GCC fuses y*y there) */
int FAMILY_BRANCH(luxcore)(const onb_method *m, int prec, const double n[3])
{
	const int fixed = m->norm == ONB__WILD_FIXED;
	if (prec == PREC_FLOAT) {
		const float x = (float)n[0], y = (float)n[1];
#if FAMILY_PASS == 1
		if (fixed)
			return (double)sqrtf(fmaf(y, y, x * x)) < 1e-5;
#endif
		return (double)sqrtf(x * x + y * y) < 1e-5;
	}
#if FAMILY_PASS == 1
	if (fixed)
		return sqrt(fma(n[1], n[1], n[0] * n[0])) < 1e-5;
#endif
	(void)fixed;
	return sqrt(n[0] * n[0] + n[1] * n[1]) < 1e-5;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(luxcore)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)loc;
	if (br && m->norm == ONB__WILD_FIXED) {
		r2[0] = xsub(xc(1.0), xmul(n[0], n[0], bad), bad);
		r2[1] = xneg(xmul(n[0], n[1], bad));
		r2[2] = xneg(xmul(n[0], n[2], bad));
		xnormalize(r2, bad);
	} else if (br) {
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
	(void)buf; (void)n;
	if (b && m && m->norm == ONB__WILD_FIXED)
		return "sqrt(n.x^2 + n.y^2) < 1e-5: b2 = unit(1 - n.x^2, -n.x n.y, -n.x n.z)";
	return b ? "sqrt(n.x^2 + n.y^2) < 1e-5: b2 = (1, 0, 0)" : "b2 = (-n.y, n.x, 0) / sqrt(n.x^2 + n.y^2)";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)loc;
	if (br && m->norm == ONB__WILD_FIXED) {   /* e1 - x n */
		mpfr_mul(r2[0], n[0], n[0], R);
		mpfr_ui_sub(r2[0], 1, r2[0], R);
		mpfr_mul(r2[1], n[0], n[1], R);
		mpfr_neg(r2[1], r2[1], R);
		mpfr_mul(r2[2], n[0], n[2], R);
		mpfr_neg(r2[2], r2[2], R);
		kit_normalize(c, r2);
	} else if (br) {
		kit_set3(r2, 1.0, 0.0, 0.0);
	} else {
		kit_axis_cross(r2, 2, +1, n);   /* (-y, x, 0) */
		kit_normalize(c, r2);
	}
	kit_cross(c, r1, n, r2);
}

/* luxcore_fixed's fallback: v = (1 - x*x, -x*y, -x*z), v *= 1/sqrt(v.v)
   (LuxCore's Normalize); for any n |b2| = 1, and b1 = n x b2 is
   orthogonal to n and b2; b2.n = x (1 - |n|^2)/|v| needs a unit n.  xx is
   the kernel's x*x, which GCC computes once for len and 1 - x*x. */
static void fixed_fallback(cm *c, int P, const cv n[3], cv xx, cv v[3])
{
	cv inv;
	int i;
	cm_formula_exact_n(c, (1u << CQ_N2) | (1u << CQ_D1N) | (1u << CQ_D12), 0);
	v[0] = SUB(K(1.0), xx);
	v[1] = MUL(cm_neg(c, n[0]), n[1]);
	v[2] = MUL(cm_neg(c, n[0]), n[2]);
	inv = DIV(K(1.0), cm_sqrt(c, P, mk_dot3_xf(c, P, v, v)));
	for (i = 0; i < 3; i++)
		v[i] = MUL(v[i], inv);
}

/* The comparison is with the double 1e-5, in either format. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const int fixed = m->norm == ONB__WILD_FIXED;
	/* contracted: fma(x, x, y*y); luxcore_fixed's x*x is shared with its
	   fallback's 1 - x*x, and GCC fuses y*y instead: fma(y, y, x*x) */
	const cv xx = MUL(n[0], n[0]);
	const cv len = cm_sqrt(c, P, c->contract && fixed ? cm_fma(c, P, n[1], n[1], xx) : MADD(n[0], n[0], MUL(n[1], n[1])));
	cv v[3];
	if (cm_branch(c, 0, CM_LT, len, cm_cst(c, 1e-5))) {
		if (fixed)
			fixed_fallback(c, P, n, xx, v);
		else {
			cm_formula_nonzero(c, CQ_ALL);
			v[0] = K(1.0); v[1] = K(0.0); v[2] = K(0.0);
		}
	} else {   /* b2 = (-y, x, 0)/|.|, b1 = n x b2: only |b1| depends on |n| */
		cm_formula_exact_n(c, ZN_UNIT_B2, 1u << CQ_N1);
		v[0] = DIV(cm_neg(c, n[1]), len); v[1] = DIV(n[0], len); v[2] = K(0.0);
	}
	out[3] = MUL(v[0], K(1.0)); out[4] = MUL(v[1], K(1.0)); out[5] = MUL(v[2], K(1.0));
	cm_formula_zero_after(c, (1u << CQ_D1N) | (1u << CQ_D12));   /* b1 = n x b2 */
	mk_cross_out(c, P, n, out, 0, 1, fixed ? "ssf" : "fsf");  /* contracted as GCC fuses them */
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return 0; }
static int variant(const onb_method *m) { return m->norm == ONB__WILD_FIXED; }
/* luxcore_fixed's fallback: b1.x = n.y b2.z - n.z b2.y is 0 for any n */
static int exact_zero(const onb_method *m, int br) { return br && m->norm == ONB__WILD_FIXED ? 0 : -1; }

FAMILY_DECLARE(luxcore);
const study_family family_luxcore = {
	"luxcore", FAMILY_PASSES(luxcore), names, mpfr, FAMILY_PAIRS(luxcore), variant,
	exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
