/*
 * frisvad_rotate.c - Frisvad 2012, Equation 3: a direction (x, y, z) of
 * the local frame of n, rotated without forming the basis.  Not a
 * registry method (m = NULL everywhere here): the study measures its
 * direction error.  Its certify model is the basis the kernel forms on
 * the way (Frisvad's formula without a threshold): certify bounds the
 * direction error from that basis's defects (bound.c, docs/certify.md).
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

#include "model/model_kit.h"

/* The basis the kernel forms on the way, op for op: Frisvad's formula
   (a = 1/(1 + n.z), b = (-n.x n.y) a, 1 - (n.x n.x) a, ...) with no
   threshold, so that w = x b1 + y b2 + z n, each component the kernel's
   ((x b1_i + y b2_i) + z n_i) (tests/test_certify.c checks those bits).
   The kernel's one special case, 1 + n.z == 0, is n.z == -1 on every
   input whose n.z >= -1 (1 + n.z is exact there, Sterbenz), which is
   n.z < t for t the format value just above -1: its output (-y, -x, -z)
   is x (0, -1, 0) + y (-1, 0, 0) + z (0, 0, -1), and the model returns
   that basis (0, -1, 0), (-1, 0, 0) there.  Inputs with n.z < -1 (the
   tolerance domain) would take the formula in the kernel: certify does
   not bound frisvad_rotate in that domain. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const double t = P == PREC_FLOAT ? -1.0 + 0x1p-24 : -1.0 + 0x1p-53;
	(void)m;
	mk_frisvad_listing2(c, P, t, n, out);
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return 0; }

FAMILY_DECLARE(frisvad_rotate);
const study_family family_frisvad_rotate = {
	"frisvad_rotate", FAMILY_PASSES(frisvad_rotate), names, mpfr, FAMILY_PAIRS(frisvad_rotate),
	family_no_variant, family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,  /* a direction, not a basis: its --fma copy has no rows */
};
#endif
