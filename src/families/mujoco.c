/*
 * mujoco.c - MuJoCo's mju_makeFrame for a contact (its y-axis undefined):
 * m = n/|n|; e = the y-axis when |m.y| < 1/2, else the z-axis;
 * b1 = unit(e - m (m.e)), b2 = m x b1 (Gram-Schmidt of an axis).
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when -1/2 < m.y < 1/2 for m = n normalized as mju_normalize3 does
   (the rule on the rounded m.y, so the FMA copy's rule is compiled with
   contraction too) */
int FAMILY_BRANCH(mujoco)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT) {
		const float x = (float)n[0], y = (float)n[1], z = (float)n[2];
		const float s = sqrtf(x * x + y * y + z * z);
		const float my = s < 1e-15f ? 0.0f : y * (1.0f / s);
		return my < 0.5f && my > -0.5f;
	} else if (prec == PREC_HALF) {   /* 1e-15 is 0 in binary16 */
		const double x = n[0], y = n[1], z = n[2];
		const double s = prec_half_round(sqrt(prec_half_round(prec_half_round(prec_half_round(x * x) +
		                 prec_half_round(y * y)) + prec_half_round(z * z))));
		const double my = s < prec_half_round(1e-15) ? 0.0 : prec_half_round(y * prec_half_round(1.0 / s));
		return my < 0.5 && my > -0.5;
	} else {
		const double x = n[0], y = n[1], z = n[2];
		const double s = sqrt(x * x + y * y + z * z);
		const double my = s < 1e-15 ? 0.0 : y * (1.0 / s);
		return my < 0.5 && my > -0.5;
	}
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(mujoco)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	xv w[3], e[3], d;
	int i;
	(void)m; (void)loc;
	for (i = 0; i < 3; i++)
		w[i] = n[i];
	xnormalize(w, bad);
	xset3(e, 0.0, br ? 1.0 : 0.0, br ? 0.0 : 1.0);
	d = br ? w[1] : w[2];
	for (i = 0; i < 3; i++)
		r1[i] = xsub(e[i], xmul(w[i], d, bad), bad);
	xnormalize(r1, bad);
	xcross(r2, w, r1, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "|m.y| < 1/2: b1 = unit(y - m m.y)" : "|m.y| >= 1/2: b1 = unit(z - m m.z)";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	int i;
	(void)m; (void)loc;
	kit_copy3(c->w, n);
	kit_normalize(c, c->w);
	kit_set3(c->u, 0.0, br ? 1.0 : 0.0, br ? 0.0 : 1.0);
	mpfr_set(c->t[0], c->w[br ? 1 : 2], R);
	for (i = 0; i < 3; i++) {
		mpfr_mul(c->t[1], c->w[i], c->t[0], R);
		mpfr_sub(r1[i], c->u[i], c->t[1], R);
	}
	kit_normalize(c, r1);
	kit_cross(c, r2, c->w, r1);
}

/* mju_normalize3: sqrt of the squares left to right, 1/s, three products
   (s >= 1e-15 on the unit sphere) */
static void normalize(cm *c, int P, cv v[3])
{
	const cv inv = DIV(K(1.0), cm_sqrt(c, P, mk_dot3_xf(c, P, v, v)));
	int i;
	for (i = 0; i < 3; i++)
		v[i] = MUL(v[i], inv);
}

static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	cv w[3], e[3], d;
	int i;
	(void)m;
	for (i = 0; i < 3; i++)
		w[i] = n[i];
	normalize(c, P, w);
	if (cm_branch_abs(c, 0, CM_LT, w[1], K(0.5))) {
		e[0] = K(0.0); e[1] = K(1.0); e[2] = K(0.0);
	} else {
		e[0] = K(0.0); e[1] = K(0.0); e[2] = K(1.0);
	}
	d = mk_dot3(c, P, w, e);
	for (i = 0; i < 3; i++)
		e[i] = SUBM(e[i], w[i], d);
	normalize(c, P, e);
	for (i = 0; i < 3; i++)
		out[i] = e[i];
	mk_cross_fused(c, P, w, e, out + 3, "fnn");  /* as GCC fuses it */
}

/* b2 = w x (u - w (w.u)) = w x u has no u component, for any n */
static int exact_zero(const onb_method *m, int br) { (void)m; return br ? 4 : 5; }

/* measured against n but built from n/|n|: all five */
static unsigned zero_any_n(const onb_method *m) { (void)m; return CQ_ALL; }

FAMILY_DECLARE(mujoco);
const study_family family_mujoco = {
	"mujoco", FAMILY_PASSES(mujoco), names, mpfr, FAMILY_PAIRS(mujoco), family_no_variant,
	exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
