/*
 * ospray.c - OSPRay's ISPC frame(N) (rkcommon LinearSpace.ih): pbrt_v3's
 * vectors with the tie rule reversed (dx0 = (0, z, -y) only when
 * |x| < |y|), normalized by 1/sqrt of the three-term dot, b2 = N x b1 in
 * the format.  Its own file, beside pbrt_v3.c (whose MPFR formula and
 * pair it uses): a family's certify key is a checksum of its file's
 * objects (scripts/code-keys.sh), so pbrt_v3's committed keys stay current.
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 1 when not |n.x| < |n.y| (the tie and NaN: dx1 = (-z, 0, x)), pbrt_v3's
   branch ids */
int FAMILY_BRANCH(ospray)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT)
		return !(fabsf((float)n[0]) < fabsf((float)n[1]));
	return !(fabs(n[0]) < fabs(n[1]));
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(pbrt_v3)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad);
void FAMILY_PAIR(ospray)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	FAMILY_PAIR(pbrt_v3)(m, br, loc, n, r1, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

extern const study_family family_pbrt_v3;

static void mpfr_ospray(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	family_pbrt_v3.mpfr(c, m, br, loc, n, r1, r2);
}
static unsigned zero_any_n_ospray(const onb_method *m) { return family_pbrt_v3.zero_any_n(m); }

/* ---- ospray ---- */
static const char *names_ospray(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "not |n.x| < |n.y|: b1 = (-n.z, 0, n.x) / len" : "|n.x| < |n.y|: b1 = (0, n.z, -n.y) / len";
}

/* u = (0, z, -y) or (-z, 0, x), the 0 a literal; s = 1/sqrt(u.u) with
   u.u = (u.x*u.x + u.y*u.y) + u.z*u.z; b1 = u * s (three products);
   b2 = cross(N, b1) in the format.  Contracted (the --fma copy: GCC 12
   -O3 -mfma -ffp-contract=fast, read with -fdump-tree-widening_mul):
   u.u = fma(u.z, u.z, u.x*u.x + u.y*u.y); b2.x and b2.y (vectorized) as
   p - fused q, b2.z as fused p - q.  That is one fused build of these
   lines, the study's model of ISPC's FMA targets; LLVM under ISPC's
   fast-math (contract, reassoc) may fuse or reorder otherwise. */
static void model_ospray(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	cv s, u[3];
	int i;
	(void)m;
	if (cm_branch_abs(c, 0, CM_LT, n[0], n[1])) {
		u[0] = K(0.0); u[1] = n[2]; u[2] = cm_neg(c, n[1]);
	} else {
		u[0] = cm_neg(c, n[2]); u[1] = K(0.0); u[2] = n[0];
	}
	s = DIV(K(1.0), cm_sqrt(c, P, mk_dot3_zf(c, P, u, u)));
	for (i = 0; i < 3; i++)
		out[i] = MUL(u[i], s);
	mk_cross_out(c, P, n, out, 1, 1, "ssf");
}

FAMILY_DECLARE(ospray);
const study_family family_ospray = {
	"ospray", FAMILY_PASSES(ospray), names_ospray, mpfr_ospray, FAMILY_PAIRS(ospray), family_no_variant,
	family_no_exact_zero, model_ospray, 1, zero_any_n_ospray, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
