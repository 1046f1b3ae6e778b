/*
 * stark.c - Stark 2009: b1 = p/|p| with p = n x e, e chosen branch-free
 * from the smallest components, b2 = n x b1; two families of one rule:
 * stark as published (zm = 1^(xm & ym), always 1) and stark_fixed with
 * Hill 2011's zm = 1^(xm | ym) (the axis of the smallest |component|).
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 0 xm, 1 ym, 2 else */
static int rule(int prec, const double n[3])
{
	if (prec == PREC_FLOAT) {
		const float ax = fabsf((float)n[0]), ay = fabsf((float)n[1]), az = fabsf((float)n[2]);
		const int xm = (ax - ay < 0.0f) & (ax - az < 0.0f);
		const int ym = (ay - az < 0.0f) & !xm;
		return xm ? 0 : ym ? 1 : 2;
	} else {
		const double ax = fabs(n[0]), ay = fabs(n[1]), az = fabs(n[2]);
		const int xm = (ax - ay < 0.0) & (ax - az < 0.0);
		const int ym = (ay - az < 0.0) & !xm;
		return xm ? 0 : ym ? 1 : 2;
	}
}
int FAMILY_BRANCH(stark)(const onb_method *m, int prec, const double n[3]) { (void)m; return rule(prec, n); }
int FAMILY_BRANCH(stark_fixed)(const onb_method *m, int prec, const double n[3]) { (void)m; return rule(prec, n); }
#endif

#if FAMILY_PAIR_PASS
/* as published zm = 1; fixed (Hill 2011) e_k */
static void pair(int fixed, int br, const xv *n, xv *r1, xv *r2, int *bad)
{
	xv u[3];
	xset3(u, br == 0, br == 1, fixed ? br == 2 : 1);
	xcross(r1, n, u, bad);
	xnormalize(r1, bad);
	xcross(r2, n, r1, bad);
}
void FAMILY_PAIR(stark)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	pair(0, br, n, r1, r2, bad);
}
void FAMILY_PAIR(stark_fixed)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2,
                              int *bad)
{
	(void)m; (void)loc;
	pair(1, br, n, r1, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b == 0 ? "xm: p = n x (x-axis)" : b == 1 ? "ym: p = n x (y-axis)" : "zm: p = n x (z-axis)";
}

/* p = n x (xm, ym, zm), b1 = p/|p|, b2 = n x b1 */
static void formula(mpfr_kit *c, int fixed, int br, mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	kit_set3(c->u, br == 0, br == 1, fixed ? br == 2 : 1);
	kit_cross(c, r1, n, c->u);
	kit_normalize(c, r1);
	kit_cross(c, r2, n, r1);
}
static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	formula(c, 0, br, n, r1, r2);
}
static void mpfr_fixed(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1,
                       mpfr_t *r2)
{
	(void)m; (void)loc;
	formula(c, 1, br, n, r1, r2);
}

static void model_rule(cm *c, int P, int fixed, const cv n[3], cv out[6])
{
	const int xy = cm_branch_abs(c, 0, CM_LT, n[0], n[1]);
	const int xz = cm_branch_abs(c, 1, CM_LT, n[0], n[2]);
	const int yz = cm_branch_abs(c, 2, CM_LT, n[1], n[2]);
	const int xm = xy & xz, ym = yz & !xm, zm = fixed ? !(xm | ym) : !(xm & ym);
	cv e[3], p[3];
	e[0] = K(xm ? 1.0 : 0.0); e[1] = K(ym ? 1.0 : 0.0); e[2] = K(zm ? 1.0 : 0.0);
	mk_cross(c, P, n, e, p);   /* products by 0 and 1: exact, fused or not */
	if (c->contract) {   /* the --fma copy: GCC 12's fusions */
		cv s = DIV(K(1.0), cm_sqrt(c, P, MADD(p[2], p[2], MADD(p[0], p[0], MUL(p[1], p[1])))));
		int i;
		for (i = 0; i < 3; i++)
			out[i] = MUL(p[i], s);
		out[3] = SUBM(MUL(n[1], out[2]), n[2], out[1]);
		out[4] = SUBM(MUL(n[2], out[0]), n[0], out[2]);
		out[5] = MSUB(n[0], out[1], MUL(n[1], out[0]));
		return;
	}
	mk_post_n_cross_u(c, P, n, p, DIV(K(1.0), cm_sqrt(c, P, mk_dot3(c, P, p, p))), out);
}
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6]) { (void)m; model_rule(c, P, 0, n, out); }
static void model_fixed(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	(void)m;
	model_rule(c, P, 1, n, out);
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

FAMILY_DECLARE(stark);
const study_family family_stark = {
	"stark", FAMILY_PASSES(stark), names, mpfr, FAMILY_PAIRS(stark), family_no_variant,
	family_no_exact_zero, model, 3, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
FAMILY_DECLARE(stark_fixed);
const study_family family_stark_fixed = {
	"stark_fixed", FAMILY_PASSES(stark_fixed), names, mpfr_fixed, FAMILY_PAIRS(stark_fixed), family_no_variant,
	family_no_exact_zero, model_fixed, 3, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
