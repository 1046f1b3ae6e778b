/*
 * cycles_cross111.c - Blender Cycles' make_orthonormals
 * (src/util/math_float3.h): b1 = normalize((1,1,1) x n) = normalize((n.z -
 * n.y, n.x - n.z, n.y - n.x)), or (-1,1,1) x n = (n.z - n.y, n.x + n.z,
 * -n.y - n.x) on the diagonal n.x = n.y = n.z; b2 = n x b1.  Its methods
 * differ in the cross product's rounding (onb_method.norm): the SSE4.2
 * kernel's products and difference, or the AVX2 kernel's fmsub
 * (ONB__EVAL_FMSUB: fma(p, q, -(r s))).
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when n.x = n.y = n.z (as the kernel compares them) */
int FAMILY_BRANCH(cycles_cross111)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT) {
		const float x = (float)n[0], y = (float)n[1], z = (float)n[2];
		return x <= y && x >= y && x <= z && x >= z;
	}
	return n[0] <= n[1] && n[0] >= n[1] && n[0] <= n[2] && n[0] >= n[2];
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(cycles_cross111)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2,
                                  int *bad)
{
	(void)m; (void)loc;
	r1[0] = xsub(n[2], n[1], bad);
	if (br) {
		r1[1] = xadd(n[0], n[2], bad);
		r1[2] = xneg(xadd(n[1], n[0], bad));
	} else {
		r1[1] = xsub(n[0], n[2], bad);
		r1[2] = xsub(n[1], n[0], bad);
	}
	xnormalize(r1, bad);
	xcross(r2, n, r1, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "n.x = n.y = n.z: b1 = normalize((-1,1,1) x n)" : "b1 = normalize((1,1,1) x n)";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	mpfr_sub(r1[0], n[2], n[1], R);
	if (br) {
		mpfr_add(r1[1], n[0], n[2], R);
		mpfr_add(r1[2], n[1], n[0], R);
		mpfr_neg(r1[2], r1[2], R);
	} else {
		mpfr_sub(r1[1], n[0], n[2], R);
		mpfr_sub(r1[2], n[1], n[0], R);
	}
	kit_normalize(c, r1);
	kit_cross(c, r2, n, r1);
}

/* The kernel's four comparisons (n.x <= n.y && n.x >= n.y && n.x <= n.z
   && n.x >= n.z), each a branch point, all evaluated. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const int lt_y = cm_branch(c, 0, CM_LT, n[0], n[1]), gt_y = cm_branch(c, 1, CM_GT, n[0], n[1]);
	const int lt_z = cm_branch(c, 2, CM_LT, n[0], n[2]), gt_z = cm_branch(c, 3, CM_GT, n[0], n[2]);
	cv a[3], l;
	/* b1 = a/|a| with a orthogonal to n, b2 = n x b1: |b2| = |n| */
	cm_formula_exact_n(c, 0, 1u << CQ_N2);
	a[0] = SUB(n[2], n[1]);
	if (lt_y || gt_y || lt_z || gt_z) {
		a[1] = SUB(n[0], n[2]); a[2] = SUB(n[1], n[0]);
	} else {
		a[1] = ADD(n[0], n[2]); a[2] = SUB(cm_neg(c, n[1]), n[0]);
	}
	l = cm_sqrt(c, P, mk_dot3_xf(c, P, a, a));
	out[0] = DIV(a[0], l); out[1] = DIV(a[1], l); out[2] = DIV(a[2], l);
	cm_formula_zero_after(c, (1u << CQ_D2N) | (1u << CQ_D12));   /* b2 = n x b1 */
	if (m->norm != ONB__EVAL_FMSUB) {
		mk_cross_out(c, P, n, out, 1, 1, "fff");  /* as GCC fuses it */
		return;
	}
	out[3] = cm_fma(c, P, n[1], out[2], cm_neg(c, MUL(n[2], out[1])));
	out[4] = cm_fma(c, P, n[2], out[0], cm_neg(c, MUL(n[0], out[2])));
	out[5] = cm_fma(c, P, n[0], out[1], cm_neg(c, MUL(n[1], out[0])));
	mk_note_cross(c, 1, out + 3);   /* b2 = cross(n, b1), fused: the cross rule holds */
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

FAMILY_DECLARE(cycles_cross111);
const study_family family_cycles_cross111 = {
	"cycles_cross111", FAMILY_PASSES(cycles_cross111), names, mpfr, FAMILY_PAIRS(cycles_cross111),
	family_no_variant, family_no_exact_zero, model, 4, zero_any_n, family_no_singular, family_meets_none,
	family_fma_model,
};
#endif
