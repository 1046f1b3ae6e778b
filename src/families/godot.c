/*
 * godot.c - Godot's Vector3::get_any_perpendicular completed by Godot's
 * cross (docs/wild-specs/README.md): p = n x e, e = RIGHT (1,0,0) when |x|
 * <= |y| and |x| <= |z|, else UP (0,1,0); b1 = p / sqrt(p.p) (Godot's
 * normalize divides; (0,0,0) when p.p is 0), b2 = n x b1.  Variant
 * ONB__WILD_FIXED (godot_fixed, this project's fix): BACK (0,0,1) instead
 * of UP when |y| > |z|, so |p|^2 >= 2/3.
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 0 RIGHT, 1 UP, 2 BACK (fixed only) */
int FAMILY_BRANCH(godot)(const onb_method *m, int prec, const double n[3])
{
	const int fixed = m->norm == ONB__WILD_FIXED;
	if (prec == PREC_FLOAT) {
		const float ax = fabsf((float)n[0]), ay = fabsf((float)n[1]), az = fabsf((float)n[2]);
		return ax <= ay && ax <= az ? 0 : !fixed || ay <= az ? 1 : 2;
	} else {
		const double ax = fabs(n[0]), ay = fabs(n[1]), az = fabs(n[2]);
		return ax <= ay && ax <= az ? 0 : !fixed || ay <= az ? 1 : 2;
	}
}
#endif

#if FAMILY_PAIR_PASS
/* p = n x e_br = -(e_br x n), b1 = p/|p|, b2 = n x b1 */
void FAMILY_PAIR(godot)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	xperp_cross(br, -1, n, r1, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b == 0 ? "|x| <= |y|, |z|: p = n x RIGHT" : b == 1 ? "else: p = n x UP" : "fixed, |z| < |y|: p = n x BACK";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_perp_cross(c, br, -1, n, r1, r2);
}

/* Branch points as the kernel's && evaluates them: |x| > |y|, only when
   not, |x| > |z|; (fixed) |y| > |z|; then p.p > 0 (its squares underflow
   to 0 in float where p = (-z, 0, x) is tiny: b1 = 0).  Godot's
   is_zero_approx guard (every |n_i| < 1e-5) is not a branch here: it is
   never taken on the unit sphere. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const int fixed = m->norm == ONB__WILD_FIXED;
	int k = 1, i;
	cv e[3], p[3], lsq;
	if (!cm_branch_abs(c, 0, CM_GT, n[0], n[1]) && !cm_branch_abs(c, 1, CM_GT, n[0], n[2]))
		k = 0;
	else if (fixed && cm_branch_abs(c, 2, CM_GT, n[1], n[2]))
		k = 2;
	e[0] = K(k == 0 ? 1.0 : 0.0); e[1] = K(k == 1 ? 1.0 : 0.0); e[2] = K(k == 2 ? 1.0 : 0.0);
	mk_cross(c, P, n, e, p);   /* products by 0 and 1: exact, fused or not */
	lsq = c->contract ? MADD(p[2], p[2], MADD(p[0], p[0], MUL(p[1], p[1]))) : mk_dot3(c, P, p, p);
	if (cm_branch(c, 3, CM_GT, lsq, K(0.0))) {
		const cv len = cm_sqrt(c, P, lsq);
		for (i = 0; i < 3; i++)
			out[i] = DIV(p[i], len);
	} else {
		cm_formula_nonzero(c, CQ_ALL);
		out[0] = K(0.0); out[1] = K(0.0); out[2] = K(0.0);
	}
	mk_cross_out(c, P, n, out, 1, 1, "ssf");
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return 0; }
static int variant(const onb_method *m) { return m->norm == ONB__WILD_FIXED; }

FAMILY_DECLARE(godot);
const study_family family_godot = {
	"godot", FAMILY_PASSES(godot), names, mpfr, FAMILY_PAIRS(godot), variant,
	family_no_exact_zero, model, 4, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,
};
#endif
