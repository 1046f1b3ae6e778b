/*
 * raylib.c - raylib's Vector3Perpendicular completed by Vector3Normalize
 * and Vector3CrossProduct: p = n x e with e the cardinal axis of the
 * smallest |component| (ties to the earlier axis), b1 = p/|p|, b2 = n x b1.
 * Stark's fixed formula (stark.c) with raylib's tie rule.
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 0 x, 1 y, 2 z: min = |x|; y if |y| < min (min = |y|); z if |z| < min */
int FAMILY_BRANCH(raylib)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT) {
		const float ax = fabsf((float)n[0]), ay = fabsf((float)n[1]), az = fabsf((float)n[2]);
		const int y = ay < ax;
		return az < (y ? ay : ax) ? 2 : y;
	} else {
		const double ax = fabs(n[0]), ay = fabs(n[1]), az = fabs(n[2]);
		const int y = ay < ax;
		return az < (y ? ay : ax) ? 2 : y;
	}
}
#endif

#if FAMILY_PAIR_PASS
/* p = n x e_br = -(e_br x n), b1 = p/|p|, b2 = n x b1 */
void FAMILY_PAIR(raylib)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
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
	return b == 0 ? "|x| smallest: p = n x (x-axis)" : b == 1 ? "|y| smallest: p = n x (y-axis)" : "|z| smallest: p = n x (z-axis)";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_perp_cross(c, br, -1, n, r1, r2);
}

/* Three branch points: |y| < |x|, then |z| < the smaller, then the
   guard length > 0 (never false on the unit sphere: |p|^2 >= 2/3 |n|^2
   (1 - O(u)); off it, in binary16, a tiny n's |p|^2 underflows). */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const int y = cm_branch_abs(c, 0, CM_LT, n[1], n[0]);
	const int z = cm_branch_abs(c, 1, CM_LT, n[2], y ? n[1] : n[0]);
	const int k = z ? 2 : y;
	cv e[3], p[3];
	(void)m;
	e[0] = K(k == 0 ? 1.0 : 0.0); e[1] = K(k == 1 ? 1.0 : 0.0); e[2] = K(k == 2 ? 1.0 : 0.0);
	mk_cross(c, P, n, e, p);   /* products by 0 and 1: exact, fused or not */
	if (c->contract) {   /* the --fma copy: GCC 12's fusions */
		cv s = DIV(K(1.0), cm_sqrt(c, P, MADD(p[2], p[2], MADD(p[0], p[0], MUL(p[1], p[1])))));
		int i;
		for (i = 0; i < 3; i++)
			out[i] = MUL(p[i], s);
		out[3] = SUBM(MUL(n[1], out[2]), n[2], out[1]);
		out[4] = SUBM(MUL(n[2], out[0]), n[0], out[2]);
		out[5] = MSUB(n[0], out[1], MUL(n[1], out[0]));
		return;
	}
	{
		/* Vector3Normalize's guard: skipped when the length is 0 (only
		   off the unit sphere: a tiny n whose |p|^2 underflows) */
		const cv len = cm_sqrt(c, P, mk_dot3(c, P, p, p));
		if (cm_branch(c, 2, CM_GT, len, K(0.0))) {
			mk_post_n_cross_u(c, P, n, p, DIV(K(1.0), len), out);
		} else {
			cm_formula_nonzero(c, CQ_ALL);
			mk_post_n_cross_u(c, P, n, p, K(1.0), out); /* b1 = p, unnormalized */
		}
	}
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

FAMILY_DECLARE(raylib);
const study_family family_raylib = {
	"raylib", FAMILY_PASSES(raylib), names, mpfr, FAMILY_PAIRS(raylib), family_no_variant,
	family_no_exact_zero, model, 3, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,
};
#endif
