/*
 * q2rtx_fixed.c - this study's fix of q2rtx and nvpro (frisvad_max) that
 * keeps their frame at -z: Duff et al.'s operations, and below n.z = 0
 * the outputs exchanged and b2 negated, (b1, b2) -> (b2, -b1) (exact).
 * Its own file, not duff.c: a family's certify key is a checksum of its
 * file's objects (scripts/code-keys.sh), so duff's committed keys stay
 * current.
 */
#include "families/family.h"

#if FAMILY_RULE_PASS
int FAMILY_BRANCH(duff)(const onb_method *m, int prec, const double n[3]);
int FAMILY_BRANCH(q2rtx_fixed)(const onb_method *m, int prec, const double n[3])
{
	return FAMILY_BRANCH(duff)(m, prec, n);
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(duff)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad);
void FAMILY_PAIR(q2rtx_fixed)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	xv t;
	int i;
	FAMILY_PAIR(duff)(m, br, loc, n, r1, r2, bad);
	if (br)
		for (i = 0; i < 3; i++) {   /* (b1, b2) -> (b2, -b1) */
			t = r1[i];
			r1[i] = r2[i];
			r2[i] = xneg(t);
		}
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

extern const study_family family_duff;

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	return family_duff.branch_name(m, b, buf, n);
}

static void mpfr_q2rtx_fixed(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n,
                             mpfr_t *r1, mpfr_t *r2)
{
	int i;
	family_duff.mpfr(c, m, br, loc, n, r1, r2);
	if (br)
		for (i = 0; i < 3; i++) {   /* (b1, b2) -> (b2, -b1), exact */
			mpfr_swap(r1[i], r2[i]);
			mpfr_neg(r2[i], r2[i], MPFR_RNDN);
		}
}

/* Duff's operations; below, the outputs exchanged and b2 negated (exact) */
static void model_q2rtx_fixed(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const int lower = cm_branch(c, 0, CM_LT, n[2], K(0.0));
	cv t[6];
	int i;
	(void)m;
	mk_frisvad(c, P, lower ? -1 : 1, n, t);
	for (i = 0; i < 3; i++) {
		out[i] = lower ? t[3 + i] : t[i];
		out[3 + i] = lower ? cm_neg(c, t[i]) : t[3 + i];
	}
}

static unsigned zero_any_n(const onb_method *m) { return family_duff.zero_any_n(m); }

FAMILY_DECLARE(q2rtx_fixed);
const study_family family_q2rtx_fixed = {
	"q2rtx_fixed", FAMILY_PASSES(q2rtx_fixed), names, mpfr_q2rtx_fixed, FAMILY_PAIRS(q2rtx_fixed),
	family_no_variant, family_no_exact_zero, model_q2rtx_fixed, 1, zero_any_n, family_no_singular,
	family_meets_none,
	family_no_fma_model,  /* a fix, studied as compiled (-ffp-contract=off) */
};
#endif
