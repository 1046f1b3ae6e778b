/*
 * duff.c - Duff et al. 2017, Listing 2 (revisedONB): Frisvad's formula
 * for n.z >= 0, its mirror a = 1/(1 - n.z) below.
 * unity: Unity's GetLocalFrame, Reynolds' form of the same basis turned by
 * 180 degrees, (-b1, -b2), with its own products (x*(y*a), y*(y*a)).
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
/* unity: FastSign(z) = z >= 0 ? 1 : -1, so 1 when n.z < 0 (-0 the upper) */
int FAMILY_BRANCH(unity)(const onb_method *m, int prec, const double n[3])
{
	return FAMILY_BRANCH(duff)(m, prec, n);
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
void FAMILY_PAIR(unity)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	int i;
	FAMILY_PAIR(duff)(m, br, loc, n, r1, r2, bad);
	for (i = 0; i < 3; i++) {
		r1[i] = xneg(r1[i]);
		r2[i] = xneg(r2[i]);
	}
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

static void mpfr_unity(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1,
                       mpfr_t *r2)
{
	int i;
	mpfr(c, m, br, loc, n, r1, r2);
	for (i = 0; i < 3; i++) {
		mpfr_neg(r1[i], r1[i], MPFR_RNDN);
		mpfr_neg(r2[i], r2[i], MPFR_RNDN);
	}
}

/* sz = +-1 (exact products), a = 1/(sz + z), ya = y a, b = x ya, c = x sz;
   b1 = ((c x) a - 1, sz b, c), b2 = (b, y ya - sz, y) */
static void model_unity(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const cv sz = K(cm_branch(c, 0, CM_LT, n[2], K(0.0)) ? -1.0 : 1.0);
	const cv a = DIV(K(1.0), ADD(sz, n[2]));
	const cv ya = MUL(n[1], a), b = MUL(n[0], ya), cc = MUL(n[0], sz);
	(void)m;
	out[0] = SUB(MUL(MUL(cc, n[0]), a), K(1.0)); out[1] = MUL(sz, b); out[2] = cc;
	out[3] = b; out[4] = SUB(MUL(n[1], ya), sz); out[5] = n[1];
}

FAMILY_DECLARE(duff);
const study_family family_duff = {
	"duff", FAMILY_PASSES(duff), names, mpfr, FAMILY_PAIRS(duff), family_no_variant,
	family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};

FAMILY_DECLARE(unity);
const study_family family_unity = {
	"unity", FAMILY_PASSES(unity), names, mpfr_unity, FAMILY_PAIRS(unity), family_no_variant,
	family_no_exact_zero, model_unity, 1, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,  /* its --fma copy's fusions are not modelled yet */
};
#endif
