/*
 * capsaicin.c - AMD Capsaicin's GetOrthoVectors (sampling.hlsl): b1 =
 * unit(e_x x n) = (0, -z, y)/len when the branch holds, else unit(n x e_z)
 * = (y, -x, 0)/len; b2 = n x b1.  The branch is |z| > 0 (capsaicin) or
 * |z| > |x| (capsaicin_fixed, variant ONB__WILD_FIXED: this project's fix).
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 1 when |z| > 0 (capsaicin) or |z| > |x| (capsaicin_fixed) */
int FAMILY_BRANCH(capsaicin)(const onb_method *m, int prec, const double n[3])
{
	const int fixed = m->norm == ONB__WILD_FIXED;
	if (prec == PREC_FLOAT)
		return fabsf((float)n[2]) > (fixed ? fabsf((float)n[0]) : 0.0f);
	return fabs(n[2]) > (fixed ? fabs(n[0]) : 0.0);
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(capsaicin)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	xperp_cross(br ? 0 : 2, br ? +1 : -1, n, r1, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)buf; (void)n;
	if (m->norm == ONB__WILD_FIXED)
		return b ? "|z| > |x|: b1 = (0, -z, y) / len" : "|z| <= |x|: b1 = (y, -x, 0) / len";
	return b ? "|z| > 0: b1 = (0, -z, y) / len" : "z = +-0: b1 = (y, -x, 0) / len";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_perp_cross(c, br ? 0 : 2, br ? +1 : -1, n, r1, r2);   /* (0, -z, y) or (y, -x, 0) */
}

/* One branch point; k = 1/sqrt(p2.z^2 + y^2), b1 = its products by k,
   b2 = cross(n, b1) */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const int fixed = m->norm == ONB__WILD_FIXED;
	cv k;
	cm_formula_exact_n(c, 0, 1u << CQ_N2);   /* b1 unit and orthogonal to n, b2 = n x b1 */
	if (cm_branch_abs(c, 0, CM_GT, n[2], fixed ? n[0] : K(0.0))) {
		k = DIV(K(1.0), cm_sqrt(c, P, ADD(MUL(n[2], n[2]), MUL(n[1], n[1]))));
		out[0] = K(0.0); out[1] = MUL(cm_neg(c, n[2]), k); out[2] = MUL(n[1], k);
	} else {
		k = DIV(K(1.0), cm_sqrt(c, P, ADD(MUL(n[0], n[0]), MUL(n[1], n[1]))));
		out[0] = MUL(n[1], k); out[1] = MUL(cm_neg(c, n[0]), k); out[2] = K(0.0);
	}
	cm_formula_zero_after(c, (1u << CQ_D2N) | (1u << CQ_D12));   /* b2 = n x b1 */
	mk_cross_out(c, P, n, out, 1, 1, "nnn");
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }
static int variant(const onb_method *m) { return m->norm == ONB__WILD_FIXED; }

/* capsaicin: exactly none, but z*z + y*y underflows to 0 at +-x with n.z != 0 (NaN) */
static const char *singular(const onb_method *m)
{
	return m->norm == ONB__WILD_FIXED ? "none" : "none exactly; in rounding, z*z + y*y below the smallest subnormal near n = +-x";
}

static int meets_singular(const onb_method *m, double nz_lo, double nz_hi, double phi_lo, double phi_hi)
{
	return m->norm != ONB__WILD_FIXED && nz_lo <= 0.0 && nz_hi >= 0.0 &&
	       (phi_lo <= 0.0 || phi_hi >= 360.0 || (phi_lo <= 180.0 && phi_hi >= 180.0));
}

FAMILY_DECLARE(capsaicin);
const study_family family_capsaicin = {
	"capsaicin", FAMILY_PASSES(capsaicin), names, mpfr, FAMILY_PAIRS(capsaicin), variant,
	family_no_exact_zero, model, 1, zero_any_n, singular, meets_singular,
	family_no_fma_model,
};
#endif
