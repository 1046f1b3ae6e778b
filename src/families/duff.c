/*
 * duff.c - Duff et al. 2017, Listing 2 (revisedONB): Frisvad's formula
 * for n.z >= 0, its mirror a = 1/(1 - n.z) below.
 */
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 1 when n.z < 0: the lower branch (-0 takes the upper) */
int FAMILY_BRANCH(duff)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT)
		return (float)n[2] < 0.0f;
	return n[2] < 0.0;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(duff)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	if (br)
		xduff(n, -1, 0, r1, r2, bad);
	else
		xfrisvad(n, r1, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "n.z < 0: the lower branch" : "n.z >= 0 (-0 too): the upper branch";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_frisvad(c, br ? -1 : 1, n, r1, r2);
}

static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	(void)m;
	mk_frisvad(c, P, cm_branch(c, 0, CM_LT, n[2], K(0.0)) ? -1 : 1, n, out);
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return 0; }

FAMILY_DECLARE(duff);
const study_family family_duff = {
	"duff", FAMILY_PASSES(duff), names, mpfr, FAMILY_PAIRS(duff), family_no_variant,
	family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
};
#endif
