/*
 * blender.c - Blender BLI's ortho_basis_v3v3_v3 (source/blender/blenlib/
 * intern/math_vector.cc): f = x^2 + y^2; if f > FLT_EPSILON (2^-23),
 * b1 = (y, -x, 0)/sqrt(f) and b2 = n x b1 (written without the products
 * by b1.z = 0); else the fixed frame b1 = (z < 0 ? -1 : 1, 0, 0), b2 =
 * (0, 1, 0), off-orthogonal by |n.x| <= sqrt(FLT_EPSILON): the fallback's
 * defect is the formula's own (as luxcore's 1e-5 fallback).
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 0 the formula (f > 2^-23 as the kernel computes f), 1 the fallback with
   z >= 0 (or NaN), 2 the fallback with z < 0 */
int FAMILY_BRANCH(blender)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT) {
		const float x = (float)n[0], y = (float)n[1];
		if (x * x + y * y > 0x1p-23f)
			return 0;
		return (float)n[2] < 0.0f ? 2 : 1;
	}
	if (n[0] * n[0] + n[1] * n[1] > 0x1p-23)
		return 0;
	return n[2] < 0.0 ? 2 : 1;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(blender)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	if (br) {
		xset3(r1, br == 2 ? -1.0 : 1.0, 0.0, 0.0);
		xset3(r2, 0.0, 1.0, 0.0);
		return;
	}
	xperp_cross(2, -1, n, r1, r2, bad);   /* b1 = (y, -x, 0)/|.|, b2 = n x b1 */
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b == 0 ? "x^2 + y^2 > FLT_EPSILON: b1 = (y, -x, 0)/sqrt(x^2 + y^2), b2 = n x b1"
	     : b == 1 ? "x^2 + y^2 <= FLT_EPSILON, z >= 0: b1 = (1, 0, 0), b2 = (0, 1, 0)"
	              : "x^2 + y^2 <= FLT_EPSILON, z < 0: b1 = (-1, 0, 0), b2 = (0, 1, 0)";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	if (br) {
		kit_set3(r1, br == 2 ? -1.0 : 1.0, 0.0, 0.0);
		kit_set3(r2, 0.0, 1.0, 0.0);
		return;
	}
	kit_perp_cross(c, 2, -1, n, r1, r2);
}

/* Two branch points: f > 2^-23 (the constant exact in every format: a
   binary16 subnormal), then z < 0 in the fallback. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const cv f = ADD(MUL(n[0], n[0]), MUL(n[1], n[1]));
	(void)m;
	if (cm_branch(c, 0, CM_GT, f, K(0x1p-23))) {
		const cv d = DIV(K(1.0), cm_sqrt(c, P, f));
		cm_formula_exact_n(c, ZN_UNIT_B1, 1u << CQ_N2);
		out[0] = MUL(n[1], d); out[1] = MUL(cm_neg(c, n[0]), d); out[2] = K(0.0);
		/* n x b1 with b1.z = 0: each component one product, or a - b */
		out[3] = MUL(cm_neg(c, n[2]), out[1]);
		out[4] = MUL(n[2], out[0]);
		out[5] = SUB(MUL(n[0], out[1]), MUL(n[1], out[0]));
		mk_note_cross(c, 1, out + 3);
		return;
	}
	cm_formula_nonzero(c, CQ_ALL);
	out[0] = K(cm_branch(c, 1, CM_LT, n[2], K(0.0)) ? -1.0 : 1.0); out[1] = K(0.0); out[2] = K(0.0);
	out[3] = K(0.0); out[4] = K(1.0); out[5] = K(0.0);
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return 0; }

FAMILY_DECLARE(blender);
const study_family family_blender = {
	"blender", FAMILY_PASSES(blender), names, mpfr, FAMILY_PAIRS(blender), family_no_variant,
	family_no_exact_zero, model, 2, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,
};
#endif
