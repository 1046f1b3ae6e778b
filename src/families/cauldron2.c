/*
 * cauldron2.c - FidelityFX Cauldron2 CreateTangentVectors (threshold
 * 0.99999f) and three.js PMREM ggxConvolution (0.999f): willems' rule,
 * up = (0,0,1) when |n.z| < t, else (1,0,0); b1 = unit(up x n), b2 = n x b1
 * not normalized.  Its own file, not willems.c: a family's certify key is a
 * checksum of its file's objects (scripts/code-keys.sh), so willems'
 * committed keys stay current.
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 0: up = z; 1: up = x (|n.z| >= t, or NaN), t a float constant
   (cauldron2 0.99999f, threejs 0.999f), rounded to binary16 in half
   (0.99999f becomes 1) */
static int up_rule(int prec, const double n[3], float t)
{
	if (prec == PREC_FLOAT)
		return !(fabsf((float)n[2]) < t);
	if (prec == PREC_HALF)
		return !(fabs(prec_half_round(n[2])) < prec_half_round((double)t));
	return !(fabs(n[2]) < (double)t);
}
int FAMILY_BRANCH(cauldron2)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	return up_rule(prec, n, 0.99999f);
}
int FAMILY_BRANCH(threejs)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	return up_rule(prec, n, 0.999f);
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(cauldron2)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	xv u[3];
	(void)m; (void)loc;
	xset3(u, br == 1, 0.0, br == 0);
	xcross(r1, u, n, bad);
	xnormalize(r1, bad);
	xcross(r2, n, r1, bad);
}
void FAMILY_PAIR(threejs)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	FAMILY_PAIR(cauldron2)(m, br, loc, n, r1, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

/* ---- cauldron2 ---- */
static const char *names_cauldron2(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "|n.z| >= 0.99999f: up = (1,0,0)" : "|n.z| < 0.99999f: up = (0,0,1)";
}
static const char *names_threejs(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "|n.z| >= 0.999f: up = (1,0,0)" : "|n.z| < 0.999f: up = (0,0,1)";
}

static void mpfr_cauldron2(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_set3(c->u, br == 1, 0.0, br == 0);
	kit_cross(c, r1, c->u, n);
	kit_normalize(c, r1);
	kit_cross(c, r2, n, r1);
}

/* The kernel: |n.z| < t (one branch point), up = z or x, v = up x n
   (products by 0 and 1), b1 = v / sqrt(v.v), b2 = n x b1. */
static void model_up(cm *c, int P, const cv n[3], cv out[6], float t)
{
	const int sel = cm_branch_abs(c, 0, CM_LT, n[2], K((double)t));
	cv up[3], v[3], l;
	int i;
	up[0] = K(sel ? 0.0 : 1.0); up[1] = K(0.0); up[2] = K(sel ? 1.0 : 0.0);
	mk_cross(c, P, up, n, v);
	l = cm_sqrt(c, P, mk_dot3(c, P, v, v));
	for (i = 0; i < 3; i++)
		out[i] = DIV(v[i], l);
	mk_cross_out(c, P, n, out, 1, 1, "nnn");
}
static void model_cauldron2(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	(void)m;
	model_up(c, P, n, out, 0.99999f);
}
static void model_threejs(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	(void)m;
	model_up(c, P, n, out, 0.999f);
}

static unsigned zero_any_n_cauldron2(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

FAMILY_DECLARE(cauldron2);
const study_family family_cauldron2 = {
	"cauldron2", FAMILY_PASSES(cauldron2), names_cauldron2, mpfr_cauldron2, FAMILY_PAIRS(cauldron2),
	family_no_variant, family_no_exact_zero, model_cauldron2, 1, zero_any_n_cauldron2, family_no_singular,
	family_meets_none,
	family_no_fma_model,  /* a shader: studied under IEEE as compiled (-ffp-contract=off); issue 42's profiles */
};

FAMILY_DECLARE(threejs);
const study_family family_threejs = {
	"threejs", FAMILY_PASSES(threejs), names_threejs, mpfr_cauldron2, FAMILY_PAIRS(threejs),
	family_no_variant, family_no_exact_zero, model_threejs, 1, zero_any_n_cauldron2, family_no_singular,
	family_meets_none,
	family_no_fma_model,  /* a shader: studied under IEEE as compiled (-ffp-contract=off); issue 42's profiles */
};
#endif
