/*
 * embree.c - Embree's frame(N) (common/math/linearspace3.h) on Vec3fa:
 * b1 = the longer of (0, n.z, -n.y) and (-n.z, 0, n.x), normalized; b2 =
 * n x b1, normalized.  The kernel normalizes with the rsqrtss estimate and
 * Embree's own Newton step (emath.h); the exact formula normalizes
 * exactly (onb_method.flags has ONB_APPROX_NORM).
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when n.z^2 + n.y^2 > n.z^2 + n.x^2 as the kernel rounds them: b1 from
   (0, n.z, -n.y) */
int FAMILY_BRANCH(embree)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT) {
		const float x = (float)n[0], y = (float)n[1], z = (float)n[2], zz = z * z;
		return zz + y * y > zz + x * x;
	}
	if (prec == PREC_HALF) {
		const double zz = prec_half_round(n[2] * n[2]);
		return prec_half_round(zz + prec_half_round(n[1] * n[1])) > prec_half_round(zz + prec_half_round(n[0] * n[0]));
	}
	return n[2] * n[2] + n[1] * n[1] > n[2] * n[2] + n[0] * n[0];
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(embree)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	if (br) {
		r1[0] = xc(0.0); r1[1] = n[2]; r1[2] = xneg(n[1]);
	} else {
		r1[0] = xneg(n[2]); r1[1] = xc(0.0); r1[2] = n[0];
	}
	xnormalize(r1, bad);
	xcross(r2, n, r1, bad);
	xnormalize(r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "n.z^2 + n.y^2 > n.z^2 + n.x^2: b1 = (0, n.z, -n.y) / len" : "else: b1 = (-n.z, 0, n.x) / len";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	if (br) {
		mpfr_set_zero(r1[0], 1); mpfr_set(r1[1], n[2], R); mpfr_neg(r1[2], n[1], R);
	} else {
		mpfr_neg(r1[0], n[2], R); mpfr_set_zero(r1[1], 1); mpfr_set(r1[2], n[0], R);
	}
	kit_normalize(c, r1);
	kit_cross(c, r2, n, r1);
	kit_normalize(c, r2);
}

/* emath.h rsqrt: r = rsqrtss(x) (of x rounded to float in double), then
   1.5 r + ((x -0.5) r)(r r), each operation rounded in P. */
static cv embree_rsqrt(cm *c, int P, cv x)
{
	cv xf = P == PREC_FLOAT ? x : cm_cvt(c, PREC_FLOAT, x), r;
#if ONB_HAVE_HW_RSQRT
	r = cm_seed(c, SEED_RSQRTSS, xf);
#else
	r = cm_div(c, PREC_FLOAT, cm_cst(c, 1.0), cm_sqrt(c, PREC_FLOAT, xf));
#endif
	r = cm_cvt(c, P, r);
	if (c->contract)   /* GCC fuses 1.5*r into the sum */
		return cm_newton_embree_fused(c, P, x, r);
	return cm_newton_embree(c, P, x, r);   /* ADD(MUL(K(1.5), r), MUL(MUL(MUL(x, K(-0.5)), r), MUL(r, r))) */
}

static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	/* contracted, GCC fuses z*z into each sum */
	const cv zz = MUL(n[2], n[2]);
	const cv d0 = c->contract ? MADD(n[2], n[2], MUL(n[1], n[1])) : ADD(zz, MUL(n[1], n[1]));
	const cv d1 = c->contract ? MADD(n[2], n[2], MUL(n[0], n[0])) : ADD(zz, MUL(n[0], n[0]));
	cv u[3], q[3], s;
	int i;
	(void)m;
	if (cm_branch(c, 0, CM_GT, d0, d1)) {
		u[0] = K(0.0); u[1] = n[2]; u[2] = cm_neg(c, n[1]); s = embree_rsqrt(c, P, d0);
	} else {
		u[0] = cm_neg(c, n[2]); u[1] = K(0.0); u[2] = n[0]; s = embree_rsqrt(c, P, d1);
	}
	for (i = 0; i < 3; i++)
		out[i] = MUL(u[i], s);
	mk_cross_fused(c, P, n, out, q, "ssf");
	mk_note_cross(c, 1, q);
	s = embree_rsqrt(c, P, mk_dot3_xf(c, P, q, q));
	for (i = 0; i < 3; i++)
		out[3 + i] = MUL(q[i], s);
}

/* b1 . n, b2 . n and b1 . b2 vanish for any n; the lengths are the
   approximate normalization's. */
static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_HM_NONORM; }

FAMILY_DECLARE(embree);
const study_family family_embree = {
	"embree", FAMILY_PASSES(embree), names, mpfr, FAMILY_PAIRS(embree), family_no_variant,
	family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
