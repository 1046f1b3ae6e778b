/*
 * model_kit.h - the operations the families' rounding models are written
 * with (src/families/): a kernel's operations in the model context
 * (model.h), in the same order and format as include/libonb/onb.h performs them.
 * C evaluates a*b*c as (a*b)*c and -a*b as (-a)*b; the models spell that
 * out.  The macros need `c` (the context) and `P` (PREC_FLOAT, PREC_DOUBLE or PREC_HALF) in
 * scope.  The kit imports the model context alone.
 */
#ifndef ONB_CERTIFY_MODEL_KIT_H
#define ONB_CERTIFY_MODEL_KIT_H

#include "libonb/onb.h"
#include "model.h"
#include "model_int.h"

#define ADD(a, b) cm_add(c, P, a, b)
#define SUB(a, b) cm_sub(c, P, a, b)
#define MUL(a, b) cm_mul(c, P, a, b)
#define DIV(a, b) cm_div(c, P, a, b)
#define K(v)      cm_cst(c, cm_round(c, P, (v)))   /* the constant rounded to the format */
/* a*b + d (MADD), d + a*b (ADDM), a*b - d (MSUB) and d - a*b (SUBM) as
   the kernel writes them: two
   roundings, or, in a contracted model (c->contract: the kernel compiled
   with -mfma -ffp-contract=fast), the one rounding of the fused a*b + d,
   where GCC fuses it (tests/test_certify.c checks each contracted model
   against the --fma copy of its kernel, bit for bit). */
#define MADD(a, b, d) (c->contract ? cm_fma(c, P, a, b, d) : ADD(MUL(a, b), d))
#define ADDM(d, a, b) (c->contract ? cm_fma(c, P, a, b, d) : ADD(d, MUL(a, b)))
#define MSUB(a, b, d) (c->contract ? cm_fma(c, P, a, b, cm_neg(c, d)) : SUB(MUL(a, b), d))
#define SUBM(d, a, b) (c->contract ? cm_fma(c, P, cm_neg(c, a), b, d) : SUB(d, MUL(a, b)))

/* b = cross(p, q) as onb.h writes it: b.x = p.y*q.z - p.z*q.y, ... */
static inline void mk_cross(cm *c, int P, const cv p[3], const cv q[3], cv b[3])
{
	b[0] = SUB(MUL(p[1], q[2]), MUL(p[2], q[1]));
	b[1] = SUB(MUL(p[2], q[0]), MUL(p[0], q[2]));
	b[2] = SUB(MUL(p[0], q[1]), MUL(p[1], q[0]));
}

/* x*x + y*y + z*z, left to right */
static inline cv mk_dot3(cm *c, int P, const cv p[3], const cv q[3])
{
	return ADD(ADD(MUL(p[0], q[0]), MUL(p[1], q[1])), MUL(p[2], q[2]));
}

/* The contracted forms GCC gives (x*x + y*y) + z*z and a cross product
   under -mfma -ffp-contract=fast, which differ from kernel to kernel (its
   widening_mul pass fuses what the vectorizer left it; read with
   -fdump-tree-widening_mul).  Plain (two roundings each) in a model
   without contraction.  mk_dot3_xf: fma(z, z, fma(x, x, y*y)). */
static inline cv mk_dot3_xf(cm *c, int P, const cv p[3], const cv q[3])
{
	if (!c->contract)
		return mk_dot3(c, P, p, q);
	return cm_fma(c, P, p[2], q[2], cm_fma(c, P, p[0], q[0], MUL(p[1], q[1])));
}

/* mk_dot3_zf: fma(z, z, x*x + y*y) */
static inline cv mk_dot3_zf(cm *c, int P, const cv p[3], const cv q[3])
{
	if (!c->contract)
		return mk_dot3(c, P, p, q);
	return cm_fma(c, P, p[2], q[2], ADD(MUL(p[0], q[0]), MUL(p[1], q[1])));
}

/* cross(p, q) with, per component, the product GCC fuses: 'f' the first
   (a*b - c*d as fma(a, b, -(c*d))), 's' the second (fma(-c, d, a*b)),
   'n' none; plain in a model without contraction. */
static inline void mk_cross_fused(cm *c, int P, const cv p[3], const cv q[3], cv b[3], const char *how)
{
	static const int i1[3] = { 1, 2, 0 }, i2[3] = { 2, 0, 1 };
	int k;
	for (k = 0; k < 3; k++) {
		const cv a = p[i1[k]], bb = q[i2[k]], cc = p[i2[k]], d = q[i1[k]];
		if (c->contract && how[k] == 'f')
			b[k] = MSUB(a, bb, MUL(cc, d));
		else if (c->contract && how[k] == 's')
			b[k] = SUBM(MUL(a, bb), cc, d);
		else
			b[k] = SUB(MUL(a, bb), MUL(cc, d));
	}
}

/* Notes that q = cross(n, the other output), or cross(the other, n), as
   mk_cross_fused computes it, is output `to` (b1: 0, b2: 1) or is
   normalized into it (bound.c checks which; the factors must be the
   input n and the other output exactly). */
static inline void mk_note_cross(cm *c, int to, const cv q[3])
{
	c->cross_to = to + 1;
	c->cross_q[0] = q[0]; c->cross_q[1] = q[1]; c->cross_q[2] = q[2];
}

/* The output out[to] (b1: to = 0, b2: to = 1) = cross(n, the other
   output) (n_first) or cross(the other, n), fused as `how`; recorded for
   bound.c's cross rule (cm.cross_to), which bounds |out[to]|, its dot
   with n and with the other from their own bounds and |n|. */
static inline void mk_cross_out(cm *c, int P, const cv n[3], cv out[6], int to, int n_first, const char *how)
{
	const cv *src = out + (to ? 0 : 3);
	cv *dst = out + (to ? 3 : 0);
	if (n_first)
		mk_cross_fused(c, P, n, src, dst, how);
	else
		mk_cross_fused(c, P, src, n, dst, how);
	mk_note_cross(c, to, dst);
}

/* Newton's step y * (1.5 - (0.5*x*y)*y); contracted, GCC fuses the
   last product into the subtraction (fma(-y, 0.5*x*y, 1.5)). */
static inline cv mk_newton(cm *c, int P, cv x, cv y)
{
	return c->contract ? cm_newton_fused(c, P, x, y) : cm_newton(c, P, x, y);
}

/* onb__rsq / onb__rsqf: the normalization variants (onb_method.norm).
   Newton's step y * (1.5 - 0.5*x*y*y) is Listing 3's (and InvSqrt's, with
   xhalf = 0.5*x computed first: the same products in the same order). */
static inline cv mk_rsq(cm *c, int P, cv x, int norm)
{
	switch (norm) {
	case ONB__NORM_INVSQRT:
		if (P == PREC_HALF)   /* the float bit trick's seed of x widened, rounded to half (src/lib/half.c) */
			return mk_newton(c, P, x, cm_cvt(c, P, cm_seed(c, SEED_INVSQRT_F, cm_cvt(c, PREC_FLOAT, x))));
		return mk_newton(c, P, x, cm_seed(c, P == PREC_FLOAT ? SEED_INVSQRT_F : SEED_INVSQRT_D, x));
	case ONB__NORM_RSQRT:
	case ONB__NORM_RSQRT_NR: {
		cv xf = P == PREC_FLOAT ? x : cm_cvt(c, PREC_FLOAT, x), y;
#if ONB_HAVE_HW_RSQRT
		y = cm_seed(c, SEED_RSQRTSS, xf);
#else
		y = cm_div(c, PREC_FLOAT, cm_cst(c, 1.0), cm_sqrt(c, PREC_FLOAT, xf));
#endif
		y = cm_cvt(c, P, y);
		return norm == ONB__NORM_RSQRT ? y : mk_newton(c, P, x, y);
	}
	case ONB__NORM_NONE:
		cm_formula_nonzero(c, CQ_LENGTHS);
		return K(1.0);
	default: /* (float)(1.0/sqrt((double)x)) in float, 1.0/sqrt(x) in double */
		return cm_cvt(c, P, cm_div(c, PREC_DOUBLE, cm_cst(c, 1.0), cm_sqrt(c, PREC_DOUBLE, cm_cvt(c, PREC_DOUBLE, x))));
	}
}

/* onb__naive_post: u *= s, b1 = u, b2 = cross(n, u). */
static inline void mk_post_n_cross_u(cm *c, int P, const cv n[3], const cv u[3], cv s, cv out[6])
{
	int i;
	for (i = 0; i < 3; i++)
		out[i] = MUL(u[i], s);
	mk_cross_out(c, P, n, out, 1, 1, "nnn");
}

/* Frisvad's formula with a = 1/(1 + n.z) (sg = +1) and Duff's mirror with
   a = 1/(1 - n.z) (sg = -1), as onb_frisvad_threshold and onb_duff. */
static inline void mk_frisvad(cm *c, int P, int sg, const cv n[3], cv out[6])
{
	cv one = K(1.0), a, b;
	a = DIV(one, sg > 0 ? ADD(one, n[2]) : SUB(one, n[2]));
	if (sg > 0) {
		b = MUL(MUL(cm_neg(c, n[0]), n[1]), a);
		out[0] = SUBM(one, MUL(n[0], n[0]), a); out[1] = b; out[2] = cm_neg(c, n[0]);
		out[3] = b; out[4] = SUBM(one, MUL(n[1], n[1]), a); out[5] = cm_neg(c, n[1]);
	} else {
		b = MUL(MUL(n[0], n[1]), a);
		out[0] = SUBM(one, MUL(n[0], n[0]), a); out[1] = cm_neg(c, b); out[2] = n[0];
		out[3] = b; out[4] = MSUB(MUL(n[1], n[1]), a, one); out[5] = cm_neg(c, n[1]);
	}
}

/* Listing 2: below the threshold t the fallback (0, -1, 0), (-1, 0, 0),
   else Frisvad's formula (frisvad, frisvad_max, and frisvad_rotate's
   basis with t just above -1). */
static inline void mk_frisvad_listing2(cm *c, int P, double t, const cv n[3], cv out[6])
{
	if (cm_branch(c, 0, CM_LT, n[2], cm_cst(c, t))) {
		cm_formula_nonzero(c, CQ_ALL);
		out[0] = K(0.0); out[1] = K(-1.0); out[2] = K(0.0);
		out[3] = K(-1.0); out[4] = K(0.0); out[5] = K(0.0);
		return;
	}
	mk_frisvad(c, P, 1, n, out);
}

/* The defect quantities (CQ_ bits) that stay 0 in exact arithmetic for
   every n, unit or not: b1 normalized and b2 = n x b1 (naive); b2 = v s
   with v.n = 0 and b1 = v x n (hughes_moeller); b1 = p/|p| with p = n x e
   and b2 = n x b1 (stark, pbrt_v3; tangent_cross_z with b1 and b2
   swapped).  Frisvad's and Duff's formulas need a unit n for every one. */
#define ZN_CROSS     ((1u << CQ_D2N) | (1u << CQ_D12))
#define ZN_NAIVE     (ZN_CROSS | (1u << CQ_N1))
#define ZN_HM_NONORM ((1u << CQ_D1N) | (1u << CQ_D2N) | (1u << CQ_D12))
#define ZN_HM        (ZN_HM_NONORM | (1u << CQ_N2))
#define ZN_UNIT_B1   ((1u << CQ_N1) | (1u << CQ_D1N) | (1u << CQ_D2N) | (1u << CQ_D12))
#define ZN_UNIT_B2   ((1u << CQ_N2) | (1u << CQ_D1N) | (1u << CQ_D2N) | (1u << CQ_D12))

#endif
