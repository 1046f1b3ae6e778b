/*
 * rp3d.c - ReactPhysics3D's getOneUnitOrthogonalVector and friction
 * vectors: k = the axis of the smallest |n_i| (ties to the later axis),
 * b1 = unit(e_k x n), b2 = n x b1.
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* k: ax < ay ? (ax < az ? 0 : 2) : (ay < az ? 1 : 2) */
int FAMILY_BRANCH(rp3d)(const onb_method *m, int prec, const double n[3])
{
	double ax, ay, az;
	(void)m;
	if (prec == PREC_FLOAT) {
		ax = fabsf((float)n[0]); ay = fabsf((float)n[1]); az = fabsf((float)n[2]);
	} else {
		ax = fabs(n[0]); ay = fabs(n[1]); az = fabs(n[2]);
	}
	return ax < ay ? (ax < az ? 0 : 2) : (ay < az ? 1 : 2);
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(rp3d)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	xperp_cross(br == 0 ? 0 : br == 1 ? 1 : 2, br == 1 ? -1 : +1, n, r1, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b == 0 ? "|x| smallest: b1 = (0, -z, y) / len"
	     : b == 1 ? "|y| smallest: b1 = (-z, 0, x) / len" : "|z| smallest: b1 = (-y, x, 0) / len";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	/* (0, -z, y), (-z, 0, x) or (-y, x, 0) */
	kit_perp_cross(c, br == 0 ? 0 : br == 1 ? 1 : 2, br == 1 ? -1 : +1, n, r1, r2);
}

/* getMinAxis's compares as branch points 0 (|x| < |y|), 1 (|x| < |z|),
   2 (|y| < |z|), evaluated as its ?: does; three divisions by the length */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	int k;
	cv p[3], l;
	(void)m;
	if (cm_branch_abs(c, 0, CM_LT, n[0], n[1]))
		k = cm_branch_abs(c, 1, CM_LT, n[0], n[2]) ? 0 : 2;
	else
		k = cm_branch_abs(c, 2, CM_LT, n[1], n[2]) ? 1 : 2;
	if (k == 0) {
		l = cm_sqrt(c, P, ADDM(MUL(n[1], n[1]), n[2], n[2]));
		p[0] = K(0.0); p[1] = cm_neg(c, n[2]); p[2] = n[1];
	} else if (k == 1) {
		l = cm_sqrt(c, P, ADDM(MUL(n[0], n[0]), n[2], n[2]));
		p[0] = cm_neg(c, n[2]); p[1] = K(0.0); p[2] = n[0];
	} else {
		l = cm_sqrt(c, P, MADD(n[0], n[0], MUL(n[1], n[1])));
		p[0] = cm_neg(c, n[1]); p[1] = n[0]; p[2] = K(0.0);
	}
	for (k = 0; k < 3; k++)
		out[k] = DIV(p[k], l);
	mk_cross_out(c, P, n, out, 1, 1, "fff");  /* contracted as GCC fuses them */
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

FAMILY_DECLARE(rp3d);
const study_family family_rp3d = {
	"rp3d", FAMILY_PASSES(rp3d), names, mpfr, FAMILY_PAIRS(rp3d), family_no_variant,
	family_no_exact_zero, model, 3, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
