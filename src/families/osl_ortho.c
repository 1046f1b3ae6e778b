/*
 * osl_ortho.c - OpenShadingLanguage testrender's ortho (raytracer.h):
 * b1 = (z, 0, -x) when |x| > .01f, else (0, -z, y), normalized by Imath's
 * Vec3::normalize (each component divided by the length); b2 = n x b1.
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
#endif

#if FAMILY_PAIR_PASS
/* (z, 0, -x) = +(e_y x n), (0, -z, y) = +(e_x x n) */
void FAMILY_PAIR(osl_ortho)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	xperp_cross(br ? 1 : 0, +1, n, r1, r2, bad);
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
   same for every non-NaN value). */
static cv length_tiny(cm *c, int P, const cv p[3], int z0)
{
	cv a[3], m;
	int i, id = 2;
	for (i = 0; i < 3; i++)
		a[i] = i == z0 ? p[i] : (cm_branch(c, id++, CM_LT, p[i], K(0.0)) ? cm_neg(c, p[i]) : p[i]);
	m = a[0];
	for (i = 1; i < 3; i++)
		if (i != z0 && cm_branch(c, id++, CM_LT, m, a[i]))
			m = a[i];
	if (!cm_branch(c, 6, CM_GT, m, K(0.0)))
		return K(0.0);
	for (i = 0; i < 3; i++)
		a[i] = DIV(a[i], m);
	return MUL(m, cm_sqrt(c, P, mk_dot3(c, P, a, a)));
}

/* p = (z, 0, -x) or (0, -z, y) (the 0 a literal); l = Imath's length():
   sqrt(p.x*p.x + p.y*p.y + p.z*p.z), or lengthTiny() when that sum is
   below 2 * the format's smallest normal (never for a unit n: |p|^2 >=
   1e-4); b1 = p / l, three divisions, unless l = 0; b2 = n x b1 (Imath's
   cross, n first).  Branch points: 0 the threshold, 1 the tiny test, 2-6
   lengthTiny's, 7 l != 0. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const double tiny = P == PREC_FLOAT ? 0x1p-125 : P == PREC_HALF ? 0x1p-13 : 0x1p-1021;
	cv p[3], l, l2;
	int i, z0;
	(void)m;
	if (cm_branch_abs(c, 0, CM_GT, n[0], K((double).01f))) {
		p[0] = n[2]; p[1] = K(0.0); p[2] = cm_neg(c, n[0]); z0 = 1;
	} else {
		p[0] = K(0.0); p[1] = cm_neg(c, n[2]); p[2] = n[1]; z0 = 0;
	}
	l2 = mk_dot3(c, P, p, p);
	l = cm_branch(c, 1, CM_LT, l2, K(tiny)) ? length_tiny(c, P, p, z0) : cm_sqrt(c, P, l2);
	if (cm_branch(c, 7, CM_GT, l, K(0.0)))
		for (i = 0; i < 3; i++)
			p[i] = DIV(p[i], l);
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
#endif
