/*
 * frisvad.c - Frisvad 2012, Listing 2: the formula of Equations 4-6
 * above the threshold t (onb_method.threshold: Frisvad's -0.9999999,
 * Max 2017's -0.99998796), the fixed basis (0,-1,0), (-1,0,0) below it.
 */
#include <stdio.h>
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when n.z < t: the fallback */
int FAMILY_BRANCH(frisvad)(const onb_method *m, int prec, const double n[3])
{
	if (prec == PREC_FLOAT)
		return (float)n[2] < (float)m->threshold;
	if (prec == PREC_HALF)   /* the float constant rounded to binary16 */
		return n[2] < prec_half_round((double)(float)m->threshold);
	return n[2] < m->threshold;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(frisvad)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	if (br) {
		xset3(r1, 0.0, -1.0, 0.0);
		xset3(r2, -1.0, 0.0, 0.0);
	} else {
		xfrisvad(n, r1, r2, bad);
	}
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	snprintf(buf, n, b ? "fallback: n.z < t = %.9g" : "formula: n.z >= t = %.9g", m ? m->threshold : NAN);
	return buf;
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	if (br) {
		kit_set3(r1, 0.0, -1.0, 0.0);
		kit_set3(r2, -1.0, 0.0, 0.0);
	} else {
		kit_frisvad(c, 1, n, r1, r2);
	}
}

/* The threshold is the registry's, rounded to the format as the float
   kernel's constant is. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const double t = P == PREC_DOUBLE ? m->threshold : cm_round(c, P, (double)(float)m->threshold);
	mk_frisvad_listing2(c, P, t, n, out);
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return 0; }

FAMILY_DECLARE(frisvad);
const study_family family_frisvad = {
	"frisvad", FAMILY_PASSES(frisvad), names, mpfr, FAMILY_PAIRS(frisvad), family_no_variant,
	family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
