/*
 * appleseed.c - appleseed's Basis3<T>::build(normal) (foundation/math/
 * basis.h): Hughes and Moller's perpendicular with the smallest |component|
 * zeroed, u = (0, -z, y), (-z, 0, x) or (-y, x, 0); b1 = u/|u| (foundation's
 * normalize multiplies by 1/|u|); b2 = b1 x n (the basis is (u, n, v) with
 * v = cross(u, n)): left-handed as (b1, b2).  |u|^2 >= 2/3 |n|^2.
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 0: x smallest, 1: y smallest, 2: z smallest, as the nested strict
   comparisons decide (ties go to z, and to y over x) */
int FAMILY_BRANCH(appleseed)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT) {
		const float ax = fabsf((float)n[0]), ay = fabsf((float)n[1]), az = fabsf((float)n[2]);
		return ax < ay ? (ax < az ? 0 : 2) : (ay < az ? 1 : 2);
	} else {
		const double ax = fabs(n[0]), ay = fabs(n[1]), az = fabs(n[2]);
		return ax < ay ? (ax < az ? 0 : 2) : (ay < az ? 1 : 2);
	}
}
#endif

/* u of branch br as sg (e_axis x n): (0, -z, y) = e_x x n, (-z, 0, x) =
   -(e_y x n), (-y, x, 0) = e_z x n */
#define APPLESEED_SG(br) ((br) == 1 ? -1 : +1)

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(appleseed)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	xaxis_cross(r1, br, APPLESEED_SG(br), n);
	xnormalize(r1, bad);
	xcross(r2, r1, n, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b == 0 ? "|x| smallest: u = (0, -z, y)" : b == 1 ? "|y| smallest: u = (-z, 0, x)" : "|z| smallest (ties): u = (-y, x, 0)";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_axis_cross(r1, br, APPLESEED_SG(br), n);
	kit_normalize(c, r1);
	kit_cross(c, r2, r1, n);
}

/* Three branch points: |x| < |y|, then |x| < |z| or |y| < |z|.  No guard
   (appleseed asserts |u| > 0): never 0 on the unit sphere. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	cv u[3], s;
	int i, k;
	(void)m;
	if (cm_branch_abs(c, 0, CM_LT, n[0], n[1]))
		k = cm_branch_abs(c, 1, CM_LT, n[0], n[2]) ? 0 : 2;
	else
		k = cm_branch_abs(c, 2, CM_LT, n[1], n[2]) ? 1 : 2;
	if (k == 0) { u[0] = K(0.0); u[1] = cm_neg(c, n[2]); u[2] = n[1]; }
	else if (k == 1) { u[0] = cm_neg(c, n[2]); u[1] = K(0.0); u[2] = n[0]; }
	else { u[0] = cm_neg(c, n[1]); u[1] = n[0]; u[2] = K(0.0); }
	cm_formula_exact_n(c, ZN_UNIT_B1, 1u << CQ_N2);
	s = DIV(K(1.0), cm_sqrt(c, P, mk_dot3(c, P, u, u)));
	for (i = 0; i < 3; i++)
		out[i] = MUL(u[i], s);
	mk_cross_out(c, P, n, out, 1, 0, "nnn");   /* b2 = b1 x n */
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

FAMILY_DECLARE(appleseed);
const study_family family_appleseed = {
	"appleseed", FAMILY_PASSES(appleseed), names, mpfr, FAMILY_PAIRS(appleseed), family_no_variant,
	family_no_exact_zero, model, 3, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,
};
#endif
