/*
 * gltf_viewer.c - the Khronos glTF-Sample-Viewer's generateTBN
 * (ibl_filtering.frag): up = (0,1,0), or (0,0,+-1) when 1 - |n.y| <= 1e-7
 * (the sign of n.y); b1 = unit(up x n), b2 = n x b1.
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 0: up = y; 1: up = +z; 2: up = -z.  NdotUp = (x*0 + y*1) + z*0 is n.y
   (its sign of zero and NaN aside, which the guard does not see). */
int FAMILY_BRANCH(gltf_viewer)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT) {
		const float d = (float)n[1];
		return 1.0f - fabsf(d) <= 0.0000001f ? (d > 0.0f ? 1 : 2) : 0;
	}
	return 1.0 - fabs(n[1]) <= 0.0000001 ? (n[1] > 0.0 ? 1 : 2) : 0;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(gltf_viewer)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2,
                              int *bad)
{
	xv u[3];
	(void)m; (void)loc;
	xset3(u, 0.0, br == 0, br == 1 ? 1.0 : br == 2 ? -1.0 : 0.0);
	xcross(r1, u, n, bad);
	xnormalize(r1, bad);
	xcross(r2, n, r1, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b == 0 ? "up = (0,1,0)" : b == 1 ? "1 - |n.y| <= 1e-7, n.y > 0: up = (0,0,1)" :
	       "1 - |n.y| <= 1e-7, n.y <= 0: up = (0,0,-1)";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_set3(c->u, 0.0, br == 0, br == 1 ? 1.0 : br == 2 ? -1.0 : 0.0);
	kit_cross(c, r1, c->u, n);
	kit_normalize(c, r1);
	kit_cross(c, r2, n, r1);
}

/* Branch points as the kernel evaluates them: fabs(d) (the sign of d),
   1 - |d| <= 1e-7 (read as not 1 - |d| > 1e-7), d > 0; then t = up x n,
   b1 = t / sqrt(t.t), b2 = n x b1. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const cv d = ADD(ADD(MUL(n[0], K(0.0)), MUL(n[1], K(1.0))), MUL(n[2], K(0.0)));
	const cv ad = cm_branch_sign(c, 0, d) ? cm_neg(c, d) : d;
	cv up[3], t[3], l;
	int i;
	(void)m;
	up[0] = K(0.0); up[1] = K(1.0); up[2] = K(0.0);
	if (!cm_branch(c, 1, CM_GT, SUB(K(1.0), ad), K(0.0000001))) {
		up[1] = K(0.0);
		up[2] = K(cm_branch(c, 2, CM_GT, d, K(0.0)) ? 1.0 : -1.0);
	}
	mk_cross(c, P, up, n, t);
	l = cm_sqrt(c, P, mk_dot3(c, P, t, t));
	for (i = 0; i < 3; i++)
		out[i] = DIV(t[i], l);
	mk_cross_out(c, P, n, out, 1, 1, "nnn");
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

FAMILY_DECLARE(gltf_viewer);
const study_family family_gltf_viewer = {
	"gltf_viewer", FAMILY_PASSES(gltf_viewer), names, mpfr, FAMILY_PAIRS(gltf_viewer), family_no_variant,
	family_no_exact_zero, model, 3, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,  /* no --fma model: the kernel is studied as compiled, -ffp-contract=off */
};
#endif
