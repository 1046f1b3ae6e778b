/*
 * osl_ortho.c - OpenShadingLanguage testrender's ortho (raytracer.h):
 * b1 = (z, 0, -x) when |x| > .01f, else (0, -z, y), normalized by Imath's
 * Vec3::normalize (each component divided by the length); b2 = n x b1.
 * osl_gabornoise (liboslnoise/gabornoise.h make_orthonormals): v = n
 * Imath-normalized first; b1 = (0, v.z, -v.y) when |v.x| < 0.9f, else
 * (-v.z, 0, v.x), Imath-normalized; b2 = v x b1.
 */
#include <float.h>
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when |n.x| > .01f (the float literal, rounded to binary16 in half) */
int FAMILY_BRANCH(osl_ortho)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT)
		return fabsf((float)n[0]) > .01f;
	if (prec == PREC_HALF)
		return fabs(prec_half_round(n[0])) > prec_half_round((double).01f);
	return fabs(n[0]) > (double).01f;
}
/* 1 when not |v.x| < 0.9f, v = n / |n| as Imath's normalize computes it
   in the format (a unit n never reaches lengthTiny or a zero length) */
int FAMILY_BRANCH(osl_gabornoise)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT) {
		const float x = (float)n[0], y = (float)n[1], z = (float)n[2];
		return !(fabsf(x / sqrtf(x * x + y * y + z * z)) < .9f);
	} else if (prec == PREC_HALF) {
		const double x = n[0], y = n[1], z = n[2];
		const double d = prec_half_round(prec_half_round(prec_half_round(x * x) + prec_half_round(y * y)) +
		                                 prec_half_round(z * z));
		return !(fabs(prec_half_round(x / prec_half_round(sqrt(d)))) < prec_half_round((double).9f));
	} else {
		const double x = n[0], y = n[1], z = n[2];
		return !(fabs(x / sqrt(x * x + y * y + z * z)) < (double).9f);
	}
}
#endif

#if FAMILY_PAIR_PASS
/* (z, 0, -x) = +(e_y x n), (0, -z, y) = +(e_x x n) */
void FAMILY_PAIR(osl_ortho)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	xperp_cross(br ? 1 : 0, +1, n, r1, r2, bad);
}
/* v = n/|n|; (0, v.z, -v.y) = -(e_x x v), (-v.z, 0, v.x) = -(e_y x v) */
void FAMILY_PAIR(osl_gabornoise)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	xv v[3];
	int i;
	(void)m; (void)loc;
	for (i = 0; i < 3; i++)
		v[i] = n[i];
	xnormalize(v, bad);
	xperp_cross(br ? 1 : 0, -1, v, r1, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "|n.x| > .01f: b1 = (n.z, 0, -n.x) / len" : "|n.x| <= .01f: b1 = (0, -n.z, n.y) / len";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_perp_cross(c, br ? 1 : 0, +1, n, r1, r2);
}

/* Imath's lengthTiny on p, whose component z0 is the literal +0 (its
   |.| = +0 needs no comparison; m < +0 is never true): the largest |p_i|
   m, each |p_i| / m, m * sqrt of their squares' sum; 0 when m = 0.
   v >= 0 ? v : -v is read as v < 0 ? -v : v, m == 0 as !(m > 0) (the
   same for every non-NaN value).  Branch points from id on (the
   comparisons), zid the test m = 0; z0 = -1: no literal zero. */
static cv length_tiny(cm *c, int P, const cv p[3], int z0, int id, int zid, int *zero)
{
	cv a[3], m;
	int i;
	*zero = 0;
	for (i = 0; i < 3; i++)
		a[i] = i == z0 ? p[i] : (cm_branch(c, id++, CM_LT, p[i], K(0.0)) ? cm_neg(c, p[i]) : p[i]);
	m = a[0];
	for (i = 1; i < 3; i++)
		if (i != z0 && cm_branch(c, id++, CM_LT, m, a[i]))
			m = a[i];
	if (!cm_branch(c, zid, CM_GT, m, K(0.0))) {
		*zero = 1;
		return K(0.0);
	}
	for (i = 0; i < 3; i++)
		a[i] = DIV(a[i], m);
	return MUL(m, cm_sqrt(c, P, mk_dot3(c, P, a, a)));
}

/* Imath's normalize on p, in place: l = length(p), sqrt(p.p) or
   lengthTiny() when p.p is below `tiny` (2 * the format's smallest
   normal), then p / l, three divisions, unless l = 0.  Branch points 1
   the tiny test, 2-6 lengthTiny's (*zero its m = 0), 7 l != 0.  A macro, not a function:
   the compiled models stay byte-identical, and with them every certify
   key of osl_ortho and osl_gabornoise (scripts/code-keys.sh). */
#define IMATH_NORMALIZE(p, z0, tiny, zero)                                      \
	do {                                                                       \
		cv l_, l2_ = mk_dot3(c, P, p, p);                                      \
		int i_;                                                                \
		l_ = cm_branch(c, 1, CM_LT, l2_, K(tiny)) ? length_tiny(c, P, p, z0, 2, 6, &(zero)) : cm_sqrt(c, P, l2_); \
		if (cm_branch(c, 7, CM_GT, l_, K(0.0)))                                \
			for (i_ = 0; i_ < 3; i_++)                                         \
				p[i_] = DIV(p[i_], l_);                                        \
	} while (0)

/* p = (z, 0, -x) or (0, -z, y) (the 0 a literal); l = Imath's length():
   sqrt(p.x*p.x + p.y*p.y + p.z*p.z), or lengthTiny() when that sum is
   below 2 * the format's smallest normal (never for a unit n: |p|^2 >=
   1e-4); b1 = p / l, three divisions, unless l = 0; b2 = n x b1 (Imath's
   cross, n first).  Branch points: 0 the threshold, 1 the tiny test, 2-6
   lengthTiny's, 7 l != 0. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const double tiny = P == PREC_FLOAT ? 0x1p-125 : P == PREC_HALF ? 0x1p-13 : 0x1p-1021;
	cv p[3];
	int i, z0, zero;
	(void)m;
	if (cm_branch_abs(c, 0, CM_GT, n[0], K((double).01f))) {
		p[0] = n[2]; p[1] = K(0.0); p[2] = cm_neg(c, n[0]); z0 = 1;
	} else {
		p[0] = K(0.0); p[1] = cm_neg(c, n[2]); p[2] = n[1]; z0 = 0;
	}
	IMATH_NORMALIZE(p, z0, tiny, zero);
	for (i = 0; i < 3; i++)
		out[i] = p[i];
	mk_cross_out(c, P, n, out, 1, 1, "nnn");
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

FAMILY_DECLARE(osl_ortho);
const study_family family_osl_ortho = {
	"osl_ortho", FAMILY_PASSES(osl_ortho), names, mpfr, FAMILY_PAIRS(osl_ortho), family_no_variant,
	family_no_exact_zero, model, 8, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,
};
/* ---- osl_gabornoise ---- */
static const char *names_gabor(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "|v.x| >= 0.9f: b1 = (-v.z, 0, v.x) / len" : "|v.x| < 0.9f: b1 = (0, v.z, -v.y) / len";
}

static void mpfr_gabor(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_copy3(c->w, n);
	kit_normalize(c, c->w);
	kit_perp_cross(c, br ? 1 : 0, -1, c->w, r1, r2);
}

/* v = n / length(n), three divisions unless the length is 0 (Imath's
   length: lengthTiny below 2 * the smallest normal, as a tiny non-unit n
   takes it, never a unit one); a = (0, v.z, -v.y) or (-v.z, 0, v.x) (the
   0 a literal); l = Imath's length(a) (|a|^2 >= 0.19 on the sphere);
   b1 = a / l unless l = 0; b2 = v x b1.  Branch points (at most 8, bound.c):
   0 the threshold, 1 a's tiny test, 2-4 and 6 a's lengthTiny, 7 a's
   l != 0; 5 n's tiny test, infeasible on a unit n, so the lengthTiny of n
   behind it reuses ids 0-4 and 6 (only CM_EXEC, which compares values,
   runs it: tests/test_half's tiny inputs). */
static void model_gabor(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const double tiny = P == PREC_FLOAT ? 0x1p-125 : P == PREC_HALF ? 0x1p-13 : 0x1p-1021;
	cv v[3], a[3], l, l2;
	int i, z0, zero;
	(void)m;
	l2 = mk_dot3(c, P, n, n);
	if (cm_branch(c, 5, CM_LT, l2, K(tiny))) {   /* never on a unit n: ids 0-4, 6 reused */
		l = length_tiny(c, P, n, -1, 0, 6, &zero);
		for (i = 0; i < 3; i++)
			v[i] = zero ? n[i] : DIV(n[i], l);
	} else {
		l = cm_sqrt(c, P, l2);   /* >= sqrt(2 * the smallest normal) > 0 */
		for (i = 0; i < 3; i++)
			v[i] = DIV(n[i], l);
	}
	if (cm_branch_abs(c, 0, CM_LT, v[0], K((double).9f))) {
		a[0] = K(0.0); a[1] = v[2]; a[2] = cm_neg(c, v[1]); z0 = 0;
	} else {
		a[0] = cm_neg(c, v[2]); a[1] = K(0.0); a[2] = v[0]; z0 = 1;
	}
	IMATH_NORMALIZE(a, z0, tiny, zero);
	for (i = 0; i < 3; i++)
		out[i] = a[i];
	mk_cross(c, P, v, a, out + 3);
}

/* measured against n but built from n/|n|: all five */
static unsigned zero_any_n_gabor(const onb_method *m) { (void)m; return CQ_ALL; }

FAMILY_DECLARE(osl_gabornoise);
const study_family family_osl_gabornoise = {
	"osl_gabornoise", FAMILY_PASSES(osl_gabornoise), names_gabor, mpfr_gabor, FAMILY_PAIRS(osl_gabornoise),
	family_no_variant, family_no_exact_zero, model_gabor, 8, zero_any_n_gabor, family_no_singular,
	family_meets_none, family_no_fma_model,
};
#endif
