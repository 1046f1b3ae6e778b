/*
 * filament.c - Filament's frisvadKernel (libs/geometry/src/TangentSpaceMesh.cpp):
 * Frisvad's Listing 2 rotated to y-up.  With p = (n.z, n.x, n.y), Frisvad's
 * formula on p gives (u, v); Filament's tangent and bitangent are u and v
 * relabelled back, b1 = (u.y, u.z, u.x), b2 = (v.y, v.z, v.x).  Below the
 * threshold t (onb_method.threshold, -1 + FLT_EPSILON) on n.y the fixed
 * basis (-1, 0, 0), (0, 0, -1).  filament_fixed (variant ONB__WILD_FIXED,
 * this project's fix) branches on the sign of n.y instead: below 0, Duff
 * et al.'s lower formula on p, its pair turned (u, v) -> (v, -u), which
 * keeps the fallback's frame at n = -y.
 */
#include <stdio.h>
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when n.y < t: the fallback */
int FAMILY_BRANCH(filament)(const onb_method *m, int prec, const double n[3])
{
	if (m->norm == ONB__WILD_FIXED) /* 1 when n.y < 0 (-0 takes the formula) */
		return prec == PREC_FLOAT ? (float)n[1] < 0.0f : n[1] < 0.0;
	if (prec == PREC_FLOAT)
		return (float)n[1] < (float)m->threshold;
	if (prec == PREC_HALF)   /* the float constant rounded to binary16 */
		return n[1] < prec_half_round((double)(float)m->threshold);
	return n[1] < m->threshold;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(filament)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	xv p[3], u[3], v[3], w[3];
	int i;
	(void)loc;
	p[0] = n[2]; p[1] = n[0]; p[2] = n[1];
	if (br && m->norm == ONB__WILD_FIXED) {
		xduff(p, -1, 0, w, u, bad);       /* (u, v) = (v', -u') */
		for (i = 0; i < 3; i++)
			v[i] = xneg(w[i]);
	} else if (br) {
		xset3(r1, -1.0, 0.0, 0.0);
		xset3(r2, 0.0, 0.0, -1.0);
		return;
	} else
		xfrisvad(p, u, v, bad);
	r1[0] = u[1]; r1[1] = u[2]; r1[2] = u[0];
	r2[0] = v[1]; r2[1] = v[2]; r2[2] = v[0];
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	if (m && m->norm == ONB__WILD_FIXED)
		return b ? "n.y < 0: Duff's lower formula (y-up), turned" : "n.y >= 0 (-0 too): the formula (y-up)";
	snprintf(buf, n, b ? "fallback: n.y < t = %.9g" : "formula (y-up): n.y >= t = %.9g", m ? m->threshold : NAN);
	return buf;
}

/* The relabelling is exact: mpfr_swap moves the components in place. */
static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	int i;
	(void)loc;
	if (br && m->norm != ONB__WILD_FIXED) {
		kit_set3(r1, -1.0, 0.0, 0.0);
		kit_set3(r2, 0.0, 0.0, -1.0);
		return;
	}
	mpfr_swap(n[0], n[2]); mpfr_swap(n[1], n[2]);     /* n = (z, x, y) */
	kit_frisvad(c, br ? -1 : 1, n, r1, r2);
	mpfr_swap(n[1], n[2]); mpfr_swap(n[0], n[2]);     /* n back */
	if (br)                                            /* (u, v) -> (v, -u) */
		for (i = 0; i < 3; i++) {
			mpfr_swap(r1[i], r2[i]);
			mpfr_neg(r2[i], r2[i], R);
		}
	mpfr_swap(r1[0], r1[1]); mpfr_swap(r1[1], r1[2]); /* (a, b, c) -> (b, c, a) */
	mpfr_swap(r2[0], r2[1]); mpfr_swap(r2[1], r2[2]);
}

/* filament_fixed: the formula for n.y >= 0; below, Duff's lower formula
   on p = (z, x, y), its pair (u, v) turned to (v, -u) (exact), then
   relabelled back as the formula's. */
static void model_fixed(cm *c, int P, const cv n[3], cv out[6])
{
	cv p[3], o[6];
	int lower = cm_branch(c, 0, CM_LT, n[1], K(0.0));
	p[0] = n[2]; p[1] = n[0]; p[2] = n[1];
	mk_frisvad(c, P, lower ? -1 : 1, p, o);
	if (lower) {
		out[0] = o[4]; out[1] = o[5]; out[2] = o[3];
		out[3] = cm_neg(c, o[1]); out[4] = cm_neg(c, o[2]); out[5] = cm_neg(c, o[0]);
		/* contracted, -(1 - z*z*a) is fma(z*z, a, -1): the same value,
		   but +0 where the negation gives -0 (a = 1 at z = +-1) */
		if (c->contract)
			out[5] = MSUB(MUL(p[0], p[0]), DIV(K(1.0), SUB(K(1.0), p[2])), K(1.0));
		return;
	}
	out[0] = o[1]; out[1] = o[2]; out[2] = o[0];
	out[3] = o[4]; out[4] = o[5]; out[5] = o[3];
}

/* The threshold is the registry's, rounded to the format as the float
   kernel's constant is. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const double t = P == PREC_DOUBLE ? m->threshold : cm_round(c, P, (double)(float)m->threshold);
	cv p[3], o[6];
	if (m->norm == ONB__WILD_FIXED) {
		model_fixed(c, P, n, out);
		return;
	}
	if (cm_branch(c, 0, CM_LT, n[1], cm_cst(c, t))) {
		cm_formula_nonzero(c, CQ_ALL);
		out[0] = K(-1.0); out[1] = K(0.0); out[2] = K(0.0);
		out[3] = K(0.0); out[4] = K(0.0); out[5] = K(-1.0);
		return;
	}
	p[0] = n[2]; p[1] = n[0]; p[2] = n[1];
	mk_frisvad(c, P, 1, p, o);
	out[0] = o[1]; out[1] = o[2]; out[2] = o[0];
	out[3] = o[4]; out[4] = o[5]; out[5] = o[3];
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return 0; }
static int variant(const onb_method *m) { return m->norm == ONB__WILD_FIXED; }

FAMILY_DECLARE(filament);
const study_family family_filament = {
	"filament", FAMILY_PASSES(filament), names, mpfr, FAMILY_PAIRS(filament), variant,
	family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
