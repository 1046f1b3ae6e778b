/*
 * ogre.c - Ogre's Vector3::perpendicular (Hocevar's vector) completed by
 * Ogre's crossProduct: b1 = unit(-y, x, 0) when |x| > |z|, else
 * unit(0, -z, y) (normalisedCopy: 1/length, multiplied), b2 = n x b1.
 * hughes_moeller's vectors taken as b1, not b2.
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 1 when |x| > |z|: (-y, x, 0) */
int FAMILY_BRANCH(ogre)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT)
		return fabsf((float)n[0]) > fabsf((float)n[2]);
	return fabs(n[0]) > fabs(n[2]);
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(ogre)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	xperp_cross(br ? 2 : 0, +1, n, r1, r2, bad);   /* (-y, x, 0) or (0, -z, y) */
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "|x| > |z|: b1 = (-y, x, 0) / len" : "|x| <= |z|: b1 = (0, -z, y) / len";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_perp_cross(c, br ? 2 : 0, +1, n, r1, r2);
}

/* One branch point, |x| > |z|.  dotProduct sums from 0 in component
   order; normalise()'s guard length > 0 is not a branch here (|p|^2 >=
   1/2 |n|^2 on the unit sphere). */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	cv sq, inv;
	int i;
	(void)m;
	if (cm_branch_abs(c, 0, CM_GT, n[0], n[2])) {
		out[0] = cm_neg(c, n[1]); out[1] = n[0]; out[2] = K(0.0);
	} else {
		out[0] = K(0.0); out[1] = cm_neg(c, n[2]); out[2] = n[1];
	}
	sq = K(0.0);
	for (i = 0; i < 3; i++)
		sq = ADDM(sq, out[i], out[i]);
	inv = cm_sqrt(c, P, sq);
	/* normalisedCopy's guard: skipped when the length is 0 (only off the
	   unit sphere, where a tiny n's squares underflow) */
	if (cm_branch(c, 1, CM_GT, inv, K(0.0))) {
		inv = DIV(K(1.0), inv);
		for (i = 0; i < 3; i++)
			out[i] = MUL(out[i], inv);
	} else {
		cm_formula_nonzero(c, CQ_ALL);
	}
	mk_cross_out(c, P, n, out, 1, 1, "ssf");
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

FAMILY_DECLARE(ogre);
const study_family family_ogre = {
	"ogre", FAMILY_PASSES(ogre), names, mpfr, FAMILY_PAIRS(ogre), family_no_variant,
	family_no_exact_zero, model, 2, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,
};
#endif
