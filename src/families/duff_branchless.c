/*
 * duff_branchless.c - Duff et al. 2017, Listing 3 (branchlessONB): the
 * sign s = copysign(1, n.z), a = -1/(s + n.z).  Beside the listing in
 * float and double, the family holds this project's float-only
 * evaluations of the same formula (onb_method.norm): ONB__EVAL_WIDE
 * (duff_wide: in double, rounded once) and ONB__EVAL_COMP (duff_comp:
 * fma-compensated); they share the exact formula, not the rounding model,
 * and so does Mitsuba 3's coordinate_system (ONB__EVAL_MITSUBA3: another
 * product order in b2.y).
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when signbit(n.z): sign = -1 (-0 takes the lower branch) */
int FAMILY_BRANCH(duff_branchless)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT)
		return signbit((float)n[2]) != 0;
	return signbit(n[2]) != 0;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(duff_branchless)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2,
                                  int *bad)
{
	(void)m; (void)loc;
	xduff(n, br ? -1 : 1, 1, r1, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "signbit(n.z) set: sign = -1" : "signbit(n.z) clear: sign = +1";
}

/* s = +-1, a = -1/(s + z), b = x y a, b1 = (1 + s x^2 a, s b, -s x), b2 = (b, s + y^2 a, -y) */
static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	mpfr_t *t = c->t;
	const int s = br ? -1 : 1;
	(void)m; (void)loc;
	mpfr_add_si(t[0], n[2], s, R);
	mpfr_si_div(t[0], -1, t[0], R);
	mpfr_mul(t[1], n[0], n[1], R);
	mpfr_mul(t[1], t[1], t[0], R);
	mpfr_sqr(t[2], n[0], R);
	mpfr_mul(t[2], t[2], t[0], R);
	mpfr_mul_si(t[2], t[2], s, R);
	mpfr_add_ui(r1[0], t[2], 1, R);
	mpfr_mul_si(r1[1], t[1], s, R);
	mpfr_mul_si(r1[2], n[0], -s, R);
	mpfr_set(r2[0], t[1], R);
	mpfr_sqr(t[2], n[1], R);
	mpfr_mul(t[2], t[2], t[0], R);
	mpfr_add_si(r2[1], t[2], s, R);
	mpfr_neg(r2[2], n[1], R);
}

/* Listing 3 as written, in precision P. */
static void model_listing(cm *c, int P, const cv n[3], cv out[6])
{
	const double sg = cm_branch_sign(c, 0, n[2]) ? -1.0 : 1.0;
	cv s = K(sg), ms = K(-sg), a, b;
	a = DIV(K(-1.0), ADD(s, n[2]));
	b = MUL(MUL(n[0], n[1]), a);
	out[0] = ADDM(K(1.0), MUL(MUL(s, n[0]), n[0]), a); out[1] = MUL(s, b); out[2] = MUL(ms, n[0]);
	out[3] = b; out[4] = ADDM(s, MUL(n[1], n[1]), a); out[5] = cm_neg(c, n[1]);
}

/* duff_wide: the float input widened, Listing 3 in double, each output
   rounded once to float. */
static void model_wide(cm *c, int P, const cv nf[3], cv out[6])
{
	cv n[3], d[6];
	int i;
	for (i = 0; i < 3; i++)
		n[i] = cm_cvt(c, PREC_DOUBLE, nf[i]);
	model_listing(c, PREC_DOUBLE, n, d);
	for (i = 0; i < 6; i++)
		out[i] = cm_cvt(c, P, d[i]);
}

/* duff_comp: onb_duff_compf, operation by operation. */
static void model_comp(cm *c, int P, const cv n[3], cv out[6])
{
	const double sg = cm_branch_sign(c, 0, n[2]) ? -1.0 : 1.0;
	cv x = n[0], y = n[1], z = n[2], s = K(sg), one = K(1.0);
	cv h, hl, a, e, al, xx, xxl, xy, xyl, yy, yyl, p, pl, b, bl, q, ql, sp, t1, t1l, t2, t2l, bb;
	h = ADD(s, z); hl = ADD(SUB(s, h), z);
	a = DIV(K(-1.0), h);
	e = cm_fma(c, P, a, h, one);
	al = MUL(a, ADD(e, MUL(a, hl)));
	xx = MUL(x, x); xxl = cm_fma(c, P, x, x, cm_neg(c, xx));
	xy = MUL(x, y); xyl = cm_fma(c, P, x, y, cm_neg(c, xy));
	yy = MUL(y, y); yyl = cm_fma(c, P, y, y, cm_neg(c, yy));
	p = MUL(xx, a); pl = ADD(cm_fma(c, P, xx, a, cm_neg(c, p)), ADD(MUL(xx, al), MUL(xxl, a)));
	b = MUL(xy, a); bl = ADD(cm_fma(c, P, xy, a, cm_neg(c, b)), ADD(MUL(xy, al), MUL(xyl, a)));
	q = MUL(yy, a); ql = ADD(cm_fma(c, P, yy, a, cm_neg(c, q)), ADD(MUL(yy, al), MUL(yyl, a)));
	sp = MUL(s, p);
	t1 = ADD(one, sp); t1l = ADD(SUB(one, t1), sp);
	t2 = ADD(s, q); t2l = ADD(SUB(s, t2), q);
	bb = ADD(b, bl);
	out[0] = ADD(t1, ADD(t1l, MUL(s, pl))); out[1] = MUL(s, bb); out[2] = MUL(cm_neg(c, s), x);
	out[3] = bb; out[4] = ADD(t2, ADD(t2l, ql)); out[5] = cm_neg(c, y);
}

/* mitsuba3: Mitsuba 3's coordinate_system through Dr.Jit without FMA:
   a = -(1/(s + z)), b1.x = s (x^2 a) + 1, b2.y = y (y a) + s. */
static void model_mitsuba3(cm *c, int P, const cv n[3], cv out[6])
{
	const double sg = cm_branch_sign(c, 0, n[2]) ? -1.0 : 1.0;
	cv s = K(sg), ms = K(-sg), a, b;
	a = cm_neg(c, DIV(K(1.0), ADD(s, n[2])));
	b = MUL(MUL(n[0], n[1]), a);
	out[0] = MADD(s, MUL(MUL(n[0], n[0]), a), K(1.0)); out[1] = MUL(s, b); out[2] = MUL(ms, n[0]);
	out[3] = b; out[4] = MADD(n[1], MUL(n[1], a), s); out[5] = cm_neg(c, n[1]);
}

static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	switch (m->norm) {
	case ONB__EVAL_MITSUBA3: model_mitsuba3(c, P, n, out); break;
	case ONB__EVAL_WIDE: model_wide(c, P, n, out); break;
	case ONB__EVAL_COMP: model_comp(c, P, n, out); break;
	default:             model_listing(c, P, n, out); break;
	}
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return 0; }

FAMILY_DECLARE(duff_branchless);
const study_family family_duff_branchless = {
	"duff_branchless", FAMILY_PASSES(duff_branchless), names, mpfr, FAMILY_PAIRS(duff_branchless),
	family_no_variant, family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
