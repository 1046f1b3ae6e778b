/*
 * pbrt_v3.c - pbrt-v3's CoordinateSystem (src/core/geometry.h): b1 is n
 * with a component zeroed, normalized; b2 = n x b1, the cross product
 * widened to double in float (pbrt-v3's Cross).
 * nori (Nori's and Mitsuba 0.6's coordinateSystem): the same branch rule;
 * c = (z, 0, -x) or (0, z, -y) normalized, b1 = c x n, b2 = c, in the
 * format.
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when |n.x| > |n.y| */
int FAMILY_BRANCH(pbrt_v3)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT)
		return fabsf((float)n[0]) > fabsf((float)n[1]);
	return fabs(n[0]) > fabs(n[1]);
}
int FAMILY_BRANCH(nori)(const onb_method *m, int prec, const double n[3])
{
	return FAMILY_BRANCH(pbrt_v3)(m, prec, n);
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(pbrt_v3)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	xperp_cross(br ? 1 : 0, -1, n, r1, r2, bad);
}
/* b2 = (z, 0, -x) or (0, z, -y) normalized, b1 = b2 x n = -(n x b2) */
void FAMILY_PAIR(nori)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	xv t[3];
	int i;
	(void)m; (void)loc;
	xperp_cross(br ? 1 : 0, br ? +1 : -1, n, r2, t, bad);
	for (i = 0; i < 3; i++)
		r1[i] = xneg(t[i]);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "|n.x| > |n.y|: b1 = (-n.z, 0, n.x) / len" : "|n.x| <= |n.y|: b1 = (0, n.z, -n.y) / len";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_perp_cross(c, br ? 1 : 0, -1, n, r1, r2);   /* (-z, 0, x) or (0, z, -y) */
}

/* The --fma copy's cross product n x u in double as GCC 12 contracts it
   (x86-64, -O3): b.x and b.y, vectorized, as p - fused q; b.z as fused
   p - q. */
static void cross_fma(cm *c, int P, const cv n[3], const cv u[3], cv b[3])
{
	b[0] = SUBM(MUL(n[1], u[2]), n[2], u[1]);
	b[1] = SUBM(MUL(n[2], u[0]), n[0], u[2]);
	b[2] = MSUB(n[0], u[1], MUL(n[1], u[0]));
}

/* x*x + z*z as written, or (contracted) x*x fused with the rounded z*z */
static cv sum_sq(cm *c, int P, cv x, cv z)
{
	return c->contract ? MADD(x, x, MUL(z, z)) : ADD(MUL(x, x), MUL(z, z));
}

static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	cv inv, u[3], w[3], uw[3], b[3];
	int i;
	(void)m;
	if (cm_branch_abs(c, 0, CM_GT, n[0], n[1])) {
		inv = DIV(K(1.0), cm_sqrt(c, P, sum_sq(c, P, n[0], n[2])));
		u[0] = MUL(cm_neg(c, n[2]), inv); u[1] = MUL(K(0.0), inv); u[2] = MUL(n[0], inv);
	} else {
		inv = DIV(K(1.0), cm_sqrt(c, P, sum_sq(c, P, n[1], n[2])));
		u[0] = MUL(K(0.0), inv); u[1] = MUL(n[2], inv); u[2] = MUL(cm_neg(c, n[1]), inv);
	}
	if (P == PREC_DOUBLE) {
		if (c->contract) {
			for (i = 0; i < 3; i++)
				out[i] = MUL(u[i], K(1.0));
			cross_fma(c, P, n, out, out + 3);
		} else {
			mk_post_n_cross_u(c, P, n, u, K(1.0), out);
		}
		return;
	}
	for (i = 0; i < 3; i++) {  /* pbrt-v3's Cross: widened to double, then to float (half) */
		out[i] = u[i];
		w[i] = cm_cvt(c, PREC_DOUBLE, n[i]);
	}
	for (i = 0; i < 3; i++)
		uw[i] = cm_cvt(c, PREC_DOUBLE, u[i]);
	mk_cross(c, PREC_DOUBLE, w, uw, b);
	for (i = 0; i < 3; i++)
		out[3 + i] = cm_cvt(c, P, b[i]);
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

FAMILY_DECLARE(pbrt_v3);
const study_family family_pbrt_v3 = {
	"pbrt_v3", FAMILY_PASSES(pbrt_v3), names, mpfr, FAMILY_PAIRS(pbrt_v3), family_no_variant,
	family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
/* ---- nori ---- */
static const char *names_nori(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "|n.x| > |n.y|: b2 = (n.z, 0, -n.x) / len" : "|n.x| <= |n.y|: b2 = (0, n.z, -n.y) / len";
}

static void mpfr_nori(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	int i;
	(void)m; (void)loc;
	kit_perp_cross(c, br ? 1 : 0, br ? +1 : -1, n, r2, r1);   /* b2 = c, r1 = n x c */
	for (i = 0; i < 3; i++)
		mpfr_neg(r1[i], r1[i], R);                          /* b1 = c x n, exact */
}

/* inv = 1/sqrt(x*x + z*z); c = (z*inv, 0, (-x)*inv) (or (0, z*inv,
   (-y)*inv)), the 0 a literal; b1 = cross(c, n) as Eigen writes it. */
static void model_nori(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	cv inv;
	(void)m;
	if (cm_branch_abs(c, 0, CM_GT, n[0], n[1])) {
		inv = DIV(K(1.0), cm_sqrt(c, P, sum_sq(c, P, n[0], n[2])));
		out[3] = MUL(n[2], inv); out[4] = K(0.0); out[5] = MUL(cm_neg(c, n[0]), inv);
	} else {
		inv = DIV(K(1.0), cm_sqrt(c, P, sum_sq(c, P, n[1], n[2])));
		out[3] = K(0.0); out[4] = MUL(n[2], inv); out[5] = MUL(cm_neg(c, n[1]), inv);
	}
	mk_cross_out(c, P, n, out, 0, 0, "nnn");
}

static unsigned zero_any_n_nori(const onb_method *m) { (void)m; return ZN_UNIT_B2; }

FAMILY_DECLARE(nori);
const study_family family_nori = {
	"nori", FAMILY_PASSES(nori), names_nori, mpfr_nori, FAMILY_PAIRS(nori), family_no_variant,
	family_no_exact_zero, model_nori, 1, zero_any_n_nori, family_no_singular, family_meets_none,
	family_no_fma_model,
};
#endif
