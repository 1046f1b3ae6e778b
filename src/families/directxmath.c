/*
 * directxmath.c - DirectXMath's XMVector3Orthogonal completed by
 * XMVector3Normalize and XMVector3Cross: p = (y + z, -x, -x) where z < 0
 * and y < 0 agree, else (y - z, -x, x); b1 = p/|p|, b2 = n x b1.
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when (z < 0) == (y < 0) (p = (y + z, -x, -x)), 0 else */
int FAMILY_BRANCH(directxmath)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT)
		return ((float)n[2] < 0.0f) == ((float)n[1] < 0.0f);
	return (n[2] < 0.0) == (n[1] < 0.0);
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(directxmath)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	if (br) {
		r1[0] = xadd(n[1], n[2], bad); r1[1] = xneg(n[0]); r1[2] = xneg(n[0]);
	} else {
		r1[0] = xsub(n[1], n[2], bad); r1[1] = xneg(n[0]); r1[2] = n[0];
	}
	xnormalize(r1, bad);
	xcross(r2, n, r1, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "(z < 0) == (y < 0): p = (y + z, -x, -x)" : "(z < 0) != (y < 0): p = (y - z, -x, x)";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	if (br) {
		mpfr_add(r1[0], n[1], n[2], R); mpfr_neg(r1[1], n[0], R); mpfr_neg(r1[2], n[0], R);
	} else {
		mpfr_sub(r1[0], n[1], n[2], R); mpfr_neg(r1[1], n[0], R); mpfr_set(r1[2], n[0], R);
	}
	kit_normalize(c, r1);
	kit_cross(c, r2, n, r1);
}

/* Two branch points, z < 0 and y < 0 (their agreement picks p); the
   guards of XMVector3Normalize (+0 for a zero length, NaN for an infinite
   one) are not branches here: |p|^2 >= |n|^2 on any n. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const int zneg = cm_branch(c, 0, CM_LT, n[2], K(0.0));
	const int yneg = cm_branch(c, 1, CM_LT, n[1], K(0.0));
	cv len, lsq;
	int i;
	(void)m;
	out[1] = SUB(K(0.0), n[0]);
	if (zneg == yneg) {
		out[0] = ADD(n[1], n[2]); out[2] = SUB(K(0.0), n[0]);
	} else {
		out[0] = SUB(n[1], n[2]); out[2] = n[0];
	}
	lsq = mk_dot3_xf(c, P, out, out);
	len = cm_sqrt(c, P, lsq);
	/* XMVector3Normalize's guards (only off the unit sphere): an infinite
	   length squared gives NaN, a zero length gives 0 */
	if (!cm_branch(c, 2, CM_LT, lsq, K(INFINITY))) {
		cm_formula_nonzero(c, CQ_ALL);
		for (i = 0; i < 3; i++)
			out[i] = K(NAN);
	} else if (!cm_branch(c, 3, CM_GT, len, K(0.0))) {
		cm_formula_nonzero(c, CQ_ALL);
		for (i = 0; i < 3; i++)
			out[i] = K(0.0);
	} else {
		for (i = 0; i < 3; i++)
			out[i] = DIV(out[i], len);
	}
	mk_cross_out(c, P, n, out, 1, 1, "ssf");
}

/* b1 = p/|p| with p.n = 0 for any n, b2 = n x b1 */
static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

FAMILY_DECLARE(directxmath);
const study_family family_directxmath = {
	"directxmath", FAMILY_PASSES(directxmath), names, mpfr, FAMILY_PAIRS(directxmath), family_no_variant,
	family_no_exact_zero, model, 4, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,
};
#endif
