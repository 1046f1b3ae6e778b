/*
 * willems.c - Sascha Willems' Vulkan samples (pbribl prefilterenvmap.frag
 * importanceSample_GGX): up = (0,0,1) when |n.z| < 0.999, else (1,0,0);
 * b1 = unit(up x n), b2 = unit(n x b1).  Both normalized; never singular
 * on the sphere (|up x n|^2 >= 1 - 0.999^2).
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 0: up = z; 1: up = x (|n.z| >= 0.999, or NaN) */
int FAMILY_BRANCH(willems)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT)
		return !(fabsf((float)n[2]) < 0.999f);
	return !(fabs(n[2]) < 0.999);
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(willems)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	xv u[3];
	(void)m; (void)loc;
	xset3(u, br == 1, 0.0, br == 0);
	xcross(r1, u, n, bad);
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
	return b ? "|n.z| >= 0.999: up = (1,0,0)" : "|n.z| < 0.999: up = (0,0,1)";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_set3(c->u, br == 1, 0.0, br == 0);
	kit_cross(c, r1, c->u, n);
	kit_normalize(c, r1);
	kit_cross(c, r2, n, r1);
	kit_normalize(c, r2);
}

/* The kernel: |n.z| < 0.999 (one branch point), t = up x n (products by
   0 and 1), b1 = t / sqrt(t.t), q = n x b1, b2 = q / sqrt(q.q). */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const int sel = cm_branch_abs(c, 0, CM_LT, n[2], K(0.999));
	cv up[3], t[3], q[3], l;
	int i;
	(void)m;
	up[0] = K(sel ? 0.0 : 1.0); up[1] = K(0.0); up[2] = K(sel ? 1.0 : 0.0);
	mk_cross(c, P, up, n, t);
	l = cm_sqrt(c, P, mk_dot3(c, P, t, t));
	for (i = 0; i < 3; i++)
		out[i] = DIV(t[i], l);
	mk_cross_fused(c, P, n, out, q, "nnn");
	mk_note_cross(c, 1, q);
	l = cm_sqrt(c, P, mk_dot3(c, P, q, q));
	for (i = 0; i < 3; i++)
		out[3 + i] = DIV(q[i], l);
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1 | (1u << CQ_N2); }

FAMILY_DECLARE(willems);
const study_family family_willems = {
	"willems", FAMILY_PASSES(willems), names, mpfr, FAMILY_PAIRS(willems), family_no_variant,
	family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,  /* no --fma model: the kernel is studied as compiled, -ffp-contract=off */
};
#endif
