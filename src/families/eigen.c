/*
 * eigen.c - Eigen's unitOrthogonal (size 3) completed by Eigen's cross:
 * b1 = (-y, x, 0)/|.| unless |x| and |y| are both <= p|z| (p = Eigen's
 * dummy_precision: 1e-5 float, 1e-12 double), then (0, -z, y)/|.|;
 * b2 = n x b1.
 * filament_hm: the same formula (Filament's hughesMollerMethod) with the
 * branch |x| > |z| + FLT_EPSILON, the sum rounded in the format.
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 unless |x| <= |z| p and |y| <= |z| p (|z| p rounded in the format) */
int FAMILY_BRANCH(eigen)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT) {
		const float zp = fabsf((float)n[2]) * 1e-5f;
		return !(fabsf((float)n[0]) <= zp) || !(fabsf((float)n[1]) <= zp);
	} else if (prec == PREC_HALF) {   /* NumTraits<Eigen::half>::dummy_precision() = half(1e-2f) */
		const double zp = prec_half_round(fabs(n[2]) * prec_half_round((double)1e-2f));
		return !(fabs(n[0]) <= zp) || !(fabs(n[1]) <= zp);
	} else {
		const double zp = fabs(n[2]) * 1e-12;
		return !(fabs(n[0]) <= zp) || !(fabs(n[1]) <= zp);
	}
}
/* 1 when |x| > |z| + 2^-23 (FLT_EPSILON, the sum rounded in the format) */
int FAMILY_BRANCH(filament_hm)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT)
		return fabsf((float)n[0]) > fabsf((float)n[2]) + 0x1p-23f;
	if (prec == PREC_HALF)   /* 2^-23 is a binary16 subnormal, exact; the sum rounded to binary16 */
		return fabs(n[0]) > prec_half_round(fabs(n[2]) + 0x1p-23);
	return fabs(n[0]) > fabs(n[2]) + 0x1p-23;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(eigen)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	xperp_cross(br ? 2 : 0, +1, n, r1, r2, bad);
}
void FAMILY_PAIR(filament_hm)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2,
                              int *bad)
{
	FAMILY_PAIR(eigen)(m, br, loc, n, r1, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "x or y not much smaller than z: b1 = (-y, x, 0) / len" : "x, y << z: b1 = (0, -z, y) / len";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_perp_cross(c, br ? 2 : 0, +1, n, r1, r2);   /* (-y, x, 0) or (0, -z, y) */
}

/* Two branch points as the kernel's || evaluates them: |x| > |z| p, and
   only when it fails, |y| > |z| p. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const cv zp = MUL(n[2], K(P == PREC_FLOAT ? 1e-5 : P == PREC_HALF ? (double)1e-2f : 1e-12)); /* |RN(z p)| = RN(|z| p) */
	cv r;
	(void)m;
	cm_formula_exact_n(c, 0, 1u << CQ_N2);   /* b1 unit and orthogonal to n, b2 = n x b1 */
	if (cm_branch_abs(c, 0, CM_GT, n[0], zp) || cm_branch_abs(c, 1, CM_GT, n[1], zp)) {
		r = DIV(K(1.0), cm_sqrt(c, P, MADD(n[0], n[0], MUL(n[1], n[1]))));
		out[0] = MUL(cm_neg(c, n[1]), r); out[1] = MUL(n[0], r); out[2] = K(0.0);
	} else {
		r = DIV(K(1.0), cm_sqrt(c, P, ADDM(MUL(n[1], n[1]), n[2], n[2])));
		out[0] = K(0.0); out[1] = MUL(cm_neg(c, n[2]), r); out[2] = MUL(n[1], r);
	}
	cm_formula_zero_after(c, (1u << CQ_D2N) | (1u << CQ_D12));   /* b2 = n x b1 */
	mk_cross_out(c, P, n, out, 1, 1, "ssf");  /* contracted as GCC fuses them */
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

static const char *names_hm(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "|x| > |z| + FLT_EPSILON: b1 = (-y, x, 0) / len" : "|x| <= |z| + FLT_EPSILON: b1 = (0, -z, y) / len";
}

/* Branch point 1: the sign of z (|z| as a value); 0: |x| > RN(|z| + 2^-23).
   Then t * (1/sqrt(t.t)) with the zero term added last, b2 = n x t. */
static void model_hm(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const cv az = cm_branch_sign(c, 1, n[2]) ? cm_neg(c, n[2]) : n[2];
	cv r;
	(void)m;
	cm_formula_exact_n(c, 0, 1u << CQ_N2);   /* b1 unit and orthogonal to n, b2 = n x b1 */
	if (cm_branch_abs(c, 0, CM_GT, n[0], ADD(az, K(0x1p-23)))) {
		r = DIV(K(1.0), cm_sqrt(c, P, MADD(n[0], n[0], MUL(n[1], n[1]))));   /* t.y^2 fused, t = (-y, x, 0) */
		out[0] = MUL(cm_neg(c, n[1]), r); out[1] = MUL(n[0], r); out[2] = MUL(K(0.0), r);   /* 0 * inf = NaN */
	} else {
		r = DIV(K(1.0), cm_sqrt(c, P, MADD(n[1], n[1], MUL(n[2], n[2]))));   /* t.z^2 fused, t = (0, -z, y) */
		out[0] = MUL(K(0.0), r); out[1] = MUL(cm_neg(c, n[2]), r); out[2] = MUL(n[1], r);
	}
	cm_formula_zero_after(c, (1u << CQ_D2N) | (1u << CQ_D12));   /* b2 = n x b1 */
	mk_cross_out(c, P, n, out, 1, 1, "ssf");  /* contracted as GCC fuses them */
}

FAMILY_DECLARE(eigen);
const study_family family_eigen = {
	"eigen", FAMILY_PASSES(eigen), names, mpfr, FAMILY_PAIRS(eigen), family_no_variant,
	family_no_exact_zero, model, 2, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};

FAMILY_DECLARE(filament_hm);
const study_family family_filament_hm = {
	"filament_hm", FAMILY_PASSES(filament_hm), names_hm, mpfr, FAMILY_PAIRS(filament_hm), family_no_variant,
	family_no_exact_zero, model_hm, 2, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,
};
#endif
