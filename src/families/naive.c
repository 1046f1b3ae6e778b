/*
 * naive.c - the naive family (Frisvad 2012, Listing 1 "naive"): project
 * an axis off n and normalize, b2 = n x b1.  Its methods differ in the
 * normalization (onb_method.norm: libm, InvSqrt, rsqrtss, rsqrtss with a
 * Newton step, none).
 */
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when n.x > 0.9: b1 from the y-axis */
int FAMILY_BRANCH(naive)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT)
		return (float)n[0] > 0.9f;
	if (prec == PREC_HALF)
		return n[0] > prec_half_round(0.9);
	return n[0] > 0.9;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(naive)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	const xv d = br ? n[1] : n[0];
	int i;
	(void)loc;
	for (i = 0; i < 3; i++)
		r1[i] = xmul(n[i], d, bad);
	r1[br ? 1 : 0] = xsub(xc(1.0), r1[br ? 1 : 0], bad);
	r1[br ? 0 : 1] = xneg(r1[br ? 0 : 1]);
	r1[2] = xneg(r1[2]);
	if (m->norm != ONB__NORM_NONE)
		xnormalize(r1, bad);
	xcross(r2, n, r1, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "n.x > 0.9: b1 from the y-axis" : "n.x <= 0.9: b1 from the x-axis";
}

/* u = e_y if br else e_x; d = u.n; b1 = u - n d; normalize; b2 = n x b1 */
static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	mpfr_t *t = c->t;
	(void)loc;
	mpfr_set(t[0], br ? n[1] : n[0], R);   /* d, exactly */
	mpfr_mul(r1[0], n[0], t[0], R);
	mpfr_mul(r1[1], n[1], t[0], R);
	mpfr_mul(r1[2], n[2], t[0], R);
	mpfr_ui_sub(r1[br ? 1 : 0], 1, r1[br ? 1 : 0], R);
	mpfr_neg(r1[br ? 0 : 1], r1[br ? 0 : 1], R);
	mpfr_neg(r1[2], r1[2], R);
	if (m->norm != ONB__NORM_NONE)
		kit_normalize(c, r1);
	kit_cross(c, r2, n, r1);
}

/* the unnormalized formula is another formula */
static int variant(const onb_method *m) { return m->norm != ONB__NORM_NONE; }

/* b2 = n x (e - n (n.e)) = n x e has no e component, for any n */
static int exact_zero(const onb_method *m, int br) { (void)m; return 3 + br; }

static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	cv b[3], d, u[3], s;
	int i;
	if (cm_branch(c, 0, CM_GT, n[0], K(0.9))) {
		b[0] = K(0.0); b[1] = K(1.0); b[2] = K(0.0);
	} else {
		b[0] = K(1.0); b[1] = K(0.0); b[2] = K(0.0);
	}
	d = mk_dot3(c, P, b, n);      /* contracted or not: its products are exact */
	for (i = 0; i < 3; i++)
		u[i] = SUBM(b[i], n[i], d);
	if (m->norm == ONB__NORM_NONE) {  /* GCC vectorizes this one otherwise */
		(void)mk_rsq(c, P, K(1.0), m->norm);  /* 1, and the formula's nonzero lengths */
		for (i = 0; i < 3; i++)
			out[i] = u[i];
		mk_cross_out(c, P, n, out, 1, 1, "ssf");   /* out = u */
		return;
	}
	s = mk_rsq(c, P, mk_dot3_xf(c, P, u, u), m->norm);
	for (i = 0; i < 3; i++)
		out[i] = MUL(u[i], s);
	mk_cross_out(c, P, n, out, 1, 1, "fff");
}

static unsigned zero_any_n(const onb_method *m) { return m->norm == ONB__NORM_NONE ? ZN_CROSS : ZN_NAIVE; }

/* Normalized: b1 = u/|u| with u -> 0 at n = -x.  Unnormalized, b1 = u
   is finite everywhere. */
static const char *singular(const onb_method *m)
{
	return m->norm == ONB__NORM_NONE ? "none" : "n = -x (and near it, n.y, n.z subnormal: |b1|^2 underflows)";
}

static int meets_singular(const onb_method *m, double nz_lo, double nz_hi, double phi_lo, double phi_hi)
{
	return m->norm != ONB__NORM_NONE && nz_lo <= 0.0 && nz_hi >= 0.0 && phi_lo <= 180.0 && phi_hi >= 180.0;
}

FAMILY_DECLARE(naive);
const study_family family_naive = {
	"naive", FAMILY_PASSES(naive), names, mpfr, FAMILY_PAIRS(naive), variant, exact_zero,
	model, 1, zero_any_n, singular, meets_singular,
	family_fma_model,
};
#endif
