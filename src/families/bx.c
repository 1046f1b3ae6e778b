/*
 * bx.c - bgfx's bx::calcTangentFrame: T = (-z, 0, x)/|(x, z)| when |x| >
 * |z|, else (0, z, -y)/|(y, z)| (pbrt-v3's vectors), through bx's sqrt
 * (0 below FLT_MIN) and rcpSafe; B = n x T.  Variant ONB__WILD_FIXED
 * (bx_fixed, this project's fix): pbrt-v3's branch |x| > |y|.
 */
#include <float.h>
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 1 when |x| > |z| (fixed: |x| > |y|): T = (-z, 0, x)/len */
int FAMILY_BRANCH(bx)(const onb_method *m, int prec, const double n[3])
{
	const int k = m->norm == ONB__WILD_FIXED ? 1 : 2;
	if (prec == PREC_FLOAT)
		return fabsf((float)n[0]) > fabsf((float)n[k]);
	return fabs(n[0]) > fabs(n[k]);
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(bx)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	xperp_cross(br ? 1 : 0, -1, n, r1, r2, bad);   /* (-z, 0, x) or (0, z, -y) */
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)buf; (void)n;
	if (m->norm == ONB__WILD_FIXED)
		return b ? "|x| > |y|: T = (-z, 0, x) / len" : "|x| <= |y|: T = (0, z, -y) / len";
	return b ? "|x| > |z|: T = (-z, 0, x) / len" : "|x| <= |z|: T = (0, z, -y) / len";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_perp_cross(c, br ? 1 : 0, -1, n, r1, r2);
}

/* Branch points: the formula's, then the square below FLT_MIN (bx::sqrt
   returns 0 and rcpSafe 1/FLT_MIN = 2^126); above it max(FLT_MIN, len) is
   len (len >= sqrt(FLT_MIN)). */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const int first = cm_branch_abs(c, 0, CM_GT, n[0], n[m->norm == ONB__WILD_FIXED ? 1 : 2]);
	const cv a = first ? n[0] : n[1];
	const cv s2 = MADD(a, a, MUL(n[2], n[2]));
	cv inv;
	if (cm_branch(c, 1, CM_LT, s2, K((double)FLT_MIN))) {
		cm_formula_nonzero(c, CQ_ALL);
		inv = K(0x1p126);
	} else {
		cm_formula_exact_n(c, ZN_UNIT_B1, 1u << CQ_N2);
		inv = DIV(K(1.0), cm_sqrt(c, P, s2));
	}
	if (first) {
		out[0] = MUL(cm_neg(c, n[2]), inv); out[1] = K(0.0); out[2] = MUL(n[0], inv);
	} else {
		out[0] = K(0.0); out[1] = MUL(n[2], inv); out[2] = MUL(cm_neg(c, n[1]), inv);
	}
	mk_cross_out(c, P, n, out, 1, 1, "ssf");
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return 0; }
static int variant(const onb_method *m) { return m->norm == ONB__WILD_FIXED; }

FAMILY_DECLARE(bx);
const study_family family_bx = {
	"bx", FAMILY_PASSES(bx), names, mpfr, FAMILY_PAIRS(bx), variant,
	family_no_exact_zero, model, 2, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
