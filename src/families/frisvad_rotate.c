/*
 * frisvad_rotate.c - Frisvad 2012, Equation 3: a direction (x, y, z) of
 * the local frame of n, rotated without forming the basis.  Not a
 * registry method (m = NULL everywhere here): the study measures its
 * direction error; certify has no model of it (docs/certify.md).
 */
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
int FAMILY_BRANCH(frisvad_rotate)(const onb_method *m, int prec, const double n[3])
{
	(void)m; (void)prec; (void)n;
	return 0;
}
#endif

#if FAMILY_PAIR_PASS
/* b2 is scratch; at n.z = -1 exactly, (-y, -x, -z) */
void FAMILY_PAIR(frisvad_rotate)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2,
                                 int *bad)
{
	xv u[3];
	int i;
	const xv t3 = xadd(n[2], xc(1.0), bad);
	(void)m; (void)br;
	if (is_zero(t3)) {
		xset3(r1, -loc[1], -loc[0], -loc[2]);
		return;
	}
	xfrisvad(n, u, r2, bad);
	if (*bad)
		return;
	for (i = 0; i < 3; i++) {
		r1[i] = xadd(xmul(xc(loc[0]), u[i], bad), xmul(xc(loc[1]), r2[i], bad), bad);
		r1[i] = xadd(r1[i], xmul(xc(loc[2]), n[i], bad), bad);
	}
}
#endif

#if FAMILY_MAIN_PASS
static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)b; (void)buf; (void)n;
	return "no branch";
}

/* the direction loc of the local frame of n, into r1 (r2 is scratch) */
static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	mpfr_t *u = c->u, *t = c->t;
	int i;
	(void)m; (void)br;
	mpfr_add_ui(t[3], n[2], 1, R);
	if (mpfr_zero_p(t[3])) {
		mpfr_set_d(r1[0], -loc[1], R);
		mpfr_set_d(r1[1], -loc[0], R);
		mpfr_set_d(r1[2], -loc[2], R);
		return;
	}
	kit_frisvad(c, 1, n, u, r2);           /* u = b1, r2 = b2 */
	mpfr_set_d(t[3], loc[0], R);
	mpfr_set_d(t[4], loc[1], R);
	mpfr_set_d(t[5], loc[2], R);
	for (i = 0; i < 3; i++) {
		mpfr_mul(c->p0, t[3], u[i], R);
		mpfr_mul(c->p1, t[4], r2[i], R);
		mpfr_add(r1[i], c->p0, c->p1, R);
		mpfr_mul(c->p0, t[5], n[i], R);
		mpfr_add(r1[i], r1[i], c->p0, R);
	}
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return 0; }

FAMILY_DECLARE(frisvad_rotate);
const study_family family_frisvad_rotate = {
	"frisvad_rotate", FAMILY_PASSES(frisvad_rotate), names, mpfr, FAMILY_PAIRS(frisvad_rotate),
	family_no_variant, family_no_exact_zero, NULL, 0, zero_any_n, family_no_singular, family_meets_none,
};
#endif
