/*
 * rtow.c - Shirley, Ray Tracing: The Rest of Your Life, onb::build_from_w:
 * w normalized first, a = the y-axis when |w.x| > 0.9 else the x-axis,
 * b2 = unit(w x a), b1 = w x b2 (left-handed).
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 1 when |unit(w).x| > 0.9: the rule on the rounded unit(w), so the FMA
   copy's rule is compiled with contraction too */
int FAMILY_BRANCH(rtow)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT) {
		const float x = (float)n[0], y = (float)n[1], z = (float)n[2];
		const float inv = 1.0f / sqrtf(x * x + y * y + z * z);
		return fabsf(inv * x) > 0.9f;
	} else if (prec == PREC_HALF) {
		const double x = n[0], y = n[1], z = n[2];
		const double d = prec_half_round(prec_half_round(prec_half_round(x * x) + prec_half_round(y * y)) +
		                                 prec_half_round(z * z));
		const double inv = prec_half_round(1.0 / prec_half_round(sqrt(d)));
		return fabs(prec_half_round(inv * x)) > prec_half_round(0.9);
	} else {
		const double x = n[0], y = n[1], z = n[2];
		const double inv = 1.0 / sqrt(x * x + y * y + z * z);
		return fabs(inv * x) > 0.9;
	}
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(rtow)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	xv u[3], w[3];
	int i;
	(void)m; (void)loc;
	for (i = 0; i < 3; i++)
		w[i] = n[i];
	xnormalize(w, bad);
	xset3(u, br ? 0.0 : 1.0, br ? 1.0 : 0.0, 0.0);
	xcross(r2, w, u, bad);
	xnormalize(r2, bad);
	xcross(r1, w, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "|unit(w).x| > 0.9: a = y-axis" : "|unit(w).x| <= 0.9: a = x-axis";
}

/* uw = w/|w|; a = e_y if br else e_x; v = unit(uw x a); b1 = uw x v; b2 = v */
static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_copy3(c->w, n);
	kit_normalize(c, c->w);
	kit_set3(c->u, br ? 0.0 : 1.0, br ? 1.0 : 0.0, 0.0);
	kit_cross(c, r2, c->w, c->u);
	kit_normalize(c, r2);
	kit_cross(c, r1, c->w, r2);
}

static void model(cm *c, int P, const onb_method *m, const cv w[3], cv out[6])
{
	cv inv, uw[3], a[3], cr[3], il;
	int i;
	(void)m;
	inv = DIV(K(1.0), cm_sqrt(c, P, mk_dot3_xf(c, P, w, w)));
	for (i = 0; i < 3; i++)
		uw[i] = MUL(inv, w[i]);
	if (cm_branch_abs(c, 0, CM_GT, uw[0], K(0.9))) {
		a[0] = K(0.0); a[1] = K(1.0); a[2] = K(0.0);
	} else {
		a[0] = K(1.0); a[1] = K(0.0); a[2] = K(0.0);
	}
	mk_cross(c, P, uw, a, cr);
	il = DIV(K(1.0), cm_sqrt(c, P, mk_dot3_xf(c, P, cr, cr)));
	for (i = 0; i < 3; i++)
		out[3 + i] = MUL(il, cr[i]);
	mk_cross_fused(c, P, uw, out + 3, out, "ssf");
}

/* measured against n but built from n/|n|: all five */
static unsigned zero_any_n(const onb_method *m) { (void)m; return CQ_ALL; }

FAMILY_DECLARE(rtow);
const study_family family_rtow = {
	"rtow", FAMILY_PASSES(rtow), names, mpfr, FAMILY_PAIRS(rtow), family_no_variant,
	family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
