/*
 * hughes_moeller.c - Hughes & Moller 1999 (as Frisvad 2012, Listing 1):
 * b2 is n with one component zeroed and two swapped, normalized; b1 =
 * b2 x n.  Its methods differ in the normalization (onb_method.norm).
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when |n.x| > |n.z| */
int FAMILY_BRANCH(hughes_moeller)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT)
		return fabsf((float)n[0]) > fabsf((float)n[2]);
	return fabs(n[0]) > fabs(n[2]);
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(hughes_moeller)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2,
                                 int *bad)
{
	(void)loc;
	xaxis_cross(r2, br ? 2 : 0, +1, n);
	if (m->norm != ONB__NORM_NONE)
		xnormalize(r2, bad);
	xcross(r1, r2, n, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "|n.x| > |n.z|: b2 = (-n.y, n.x, 0)" : "|n.x| <= |n.z|: b2 = (0, -n.z, n.y)";
}

/* b2 = (-y, x, 0) if br else (0, -z, y); normalize; b1 = b2 x n */
static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)loc;
	kit_axis_cross(r2, br ? 2 : 0, +1, n);   /* (-y, x, 0) or (0, -z, y) */
	if (m->norm != ONB__NORM_NONE)
		kit_normalize(c, r2);
	kit_cross(c, r1, r2, n);
}

static int variant(const onb_method *m) { return m->norm != ONB__NORM_NONE; }

static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	cv v[3], s;
	int i;
	if (cm_branch_abs(c, 0, CM_GT, n[0], n[2])) {
		v[0] = cm_neg(c, n[1]); v[1] = n[0]; v[2] = K(0.0);
	} else {
		v[0] = K(0.0); v[1] = cm_neg(c, n[2]); v[2] = n[1];
	}
	if (c->contract) {   /* the --fma copy: GCC 12 fuses by^2 into bx^2 + by^2 */
		s = mk_rsq(c, P, ADD(MADD(v[1], v[1], MUL(v[0], v[0])), MUL(v[2], v[2])), m->norm);
		for (i = 0; i < 3; i++)
			out[3 + i] = MUL(v[i], s);
		out[0] = SUBM(MUL(out[4], n[2]), out[5], n[1]);
		out[1] = SUBM(MUL(out[5], n[0]), out[3], n[2]);
		out[2] = MSUB(out[3], n[1], MUL(out[4], n[0]));
		mk_note_cross(c, 0, out);   /* b1 = cross(b2, n), fused: the cross rule holds */
		return;
	}
	s = mk_rsq(c, P, mk_dot3(c, P, v, v), m->norm);
	for (i = 0; i < 3; i++)
		out[3 + i] = MUL(v[i], s);
	mk_cross_out(c, P, n, out, 0, 0, "nnn");  /* b1 = cross(v, n) */
}

static unsigned zero_any_n(const onb_method *m) { return m->norm == ONB__NORM_NONE ? ZN_HM_NONORM : ZN_HM; }

FAMILY_DECLARE(hughes_moeller);
const study_family family_hughes_moeller = {
	"hughes_moeller", FAMILY_PASSES(hughes_moeller), names, mpfr, FAMILY_PAIRS(hughes_moeller), variant,
	family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
