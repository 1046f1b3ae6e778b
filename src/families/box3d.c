/*
 * box3d.c - Box3D's b3Perp (include/box3d/math_functions.h) and the
 * contact solver's tangents (src/contact_solver.c): p = (y, -x, 0) where
 * x < -0.5 or 0.5 < x, else (0, z, -y); b1 = p/|p| (b3Normalize: 0 at or
 * below |p|^2 = 1000 FLT_MIN, never on the unit sphere, where |p|^2 >=
 * 1/4); b2 = b1 x n (b1 the left operand): left-handed.
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 0: x < -0.5 or 0.5 < x, p = (y, -x, 0); 1: else (NaN too), p = (0, z, -y) */
int FAMILY_BRANCH(box3d)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT) {
		const float x = (float)n[0];
		return x < -0.5f || 0.5f < x ? 0 : 1;
	}
	return n[0] < -0.5 || 0.5 < n[0] ? 0 : 1;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(box3d)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	xaxis_cross(r1, br ? 0 : 2, -1, n);   /* (y, -x, 0) or (0, z, -y) */
	xnormalize(r1, bad);
	xcross(r2, r1, n, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b == 0 ? "|x| > 0.5: p = (y, -x, 0)" : "else: p = (0, z, -y)";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_axis_cross(r1, br ? 0 : 2, -1, n);
	kit_normalize(c, r1);
	kit_cross(c, r2, r1, n);
}

/* Three branch points as the kernel's || evaluates them: x < -0.5, only
   when not, 0.5 < x; then b3Normalize's guard |p|^2 > 1000 FLT_MIN (never
   false on the unit sphere; off it a tiny n gives b1 = 0; the constant
   rounds to 0 in binary16). */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	cv p[3], ls;
	int i;
	(void)m;
	if (cm_branch(c, 0, CM_LT, n[0], K(-0.5)) || cm_branch(c, 1, CM_GT, n[0], K(0.5))) {
		p[0] = n[1]; p[1] = cm_neg(c, n[0]); p[2] = K(0.0);
	} else {
		p[0] = K(0.0); p[1] = n[2]; p[2] = cm_neg(c, n[1]);
	}
	ls = mk_dot3(c, P, p, p);
	if (cm_branch(c, 2, CM_GT, ls, K(1000.0 * 0x1p-126))) {
		const cv s = DIV(K(1.0), cm_sqrt(c, P, ls));
		cm_formula_exact_n(c, ZN_UNIT_B1, 1u << CQ_N2);
		for (i = 0; i < 3; i++)
			out[i] = MUL(s, p[i]);
	} else {
		cm_formula_nonzero(c, CQ_ALL);
		out[0] = K(0.0); out[1] = K(0.0); out[2] = K(0.0);
	}
	mk_cross_out(c, P, n, out, 1, 0, "nnn");   /* b2 = b1 x n */
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

FAMILY_DECLARE(box3d);
const study_family family_box3d = {
	"box3d", FAMILY_PASSES(box3d), names, mpfr, FAMILY_PAIRS(box3d), family_no_variant,
	family_no_exact_zero, model, 3, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,
};
#endif
