/*
 * models.c - each libonb method as a model (model.h): the operations of
 * its kernel in include/libonb/onb.h, in the same order and format.  C evaluates
 * a*b*c as (a*b)*c and -a*b as (-a)*b; the models spell that out.
 * Branch points are numbered per method from 0.
 */
#include <stddef.h>
#include <string.h>
#include "libonb/onb.h"
#include "models.h"
#include "model_int.h"

#define ADD(a, b) cm_add(c, P, a, b)
#define SUB(a, b) cm_sub(c, P, a, b)
#define MUL(a, b) cm_mul(c, P, a, b)
#define DIV(a, b) cm_div(c, P, a, b)
#define K(v)      cm_cst(c, P == CM_F32 ? (double)(float)(v) : (v))

/* b = cross(p, q) as onb.h writes it: b.x = p.y*q.z - p.z*q.y, ... */
static void cross(cm *c, int P, const cv p[3], const cv q[3], cv b[3])
{
	b[0] = SUB(MUL(p[1], q[2]), MUL(p[2], q[1]));
	b[1] = SUB(MUL(p[2], q[0]), MUL(p[0], q[2]));
	b[2] = SUB(MUL(p[0], q[1]), MUL(p[1], q[0]));
}

/* x*x + y*y + z*z, left to right */
static cv dot3(cm *c, int P, const cv p[3], const cv q[3])
{
	return ADD(ADD(MUL(p[0], q[0]), MUL(p[1], q[1])), MUL(p[2], q[2]));
}

/* y * (1.5 - 0.5*x*y*y): Listing 3's Newton step (and InvSqrt's, with
   xhalf = 0.5*x computed first: the same products in the same order). */
static cv newton(cm *c, int P, cv x, cv y)
{
	return cm_newton(c, P, x, y);
}

/* onb__rsq / onb__rsqf: the normalization variants. */
static cv rsq(cm *c, int P, cv x, int norm)
{
	switch (norm) {
	case ONB__NORM_INVSQRT:
		return newton(c, P, x, cm_seed(c, P == CM_F32 ? SEED_INVSQRT_F : SEED_INVSQRT_D, x));
	case ONB__NORM_RSQRT:
	case ONB__NORM_RSQRT_NR: {
		cv xf = P == CM_F32 ? x : cm_cvt(c, CM_F32, x), y;
#if ONB_HAVE_HW_RSQRT
		y = cm_seed(c, SEED_RSQRTSS, xf);
#else
		y = cm_div(c, CM_F32, cm_cst(c, 1.0), cm_sqrt(c, CM_F32, xf));
#endif
		y = cm_cvt(c, P, y);
		return norm == ONB__NORM_RSQRT ? y : newton(c, P, x, y);
	}
	case ONB__NORM_NONE:
		cm_formula_nonzero(c, CQ_LENGTHS);
		return K(1.0);
	default: /* (float)(1.0/sqrt((double)x)) in float, 1.0/sqrt(x) in double */
		return cm_cvt(c, P, cm_div(c, CM_F64, cm_cst(c, 1.0), cm_sqrt(c, CM_F64, cm_cvt(c, CM_F64, x))));
	}
}

/* onb__naive_post: u *= s, b1 = u, b2 = cross(n, u). */
static void post_n_cross_u(cm *c, int P, const cv n[3], const cv u[3], cv s, cv out[6])
{
	int i;
	for (i = 0; i < 3; i++)
		out[i] = MUL(u[i], s);
	cross(c, P, n, out, out + 3);
}

static void m_naive(cm *c, int P, int norm, const cv n[3], cv out[6])
{
	cv b[3], d, u[3];
	int i;
	if (cm_branch(c, 0, CM_GT, n[0], K(0.9))) {
		b[0] = K(0.0); b[1] = K(1.0); b[2] = K(0.0);
	} else {
		b[0] = K(1.0); b[1] = K(0.0); b[2] = K(0.0);
	}
	d = dot3(c, P, b, n);
	for (i = 0; i < 3; i++)
		u[i] = SUB(b[i], MUL(n[i], d));
	post_n_cross_u(c, P, n, u, rsq(c, P, dot3(c, P, u, u), norm), out);
}

static void m_hughes_moeller(cm *c, int P, int norm, const cv n[3], cv out[6])
{
	cv v[3], s;
	int i;
	if (cm_branch_abs(c, 0, CM_GT, n[0], n[2])) {
		v[0] = cm_neg(c, n[1]); v[1] = n[0]; v[2] = K(0.0);
	} else {
		v[0] = K(0.0); v[1] = cm_neg(c, n[2]); v[2] = n[1];
	}
	s = rsq(c, P, dot3(c, P, v, v), norm);
	for (i = 0; i < 3; i++)
		out[3 + i] = MUL(v[i], s);
	cross(c, P, out + 3, n, out);  /* b1 = cross(v, n) */
}

/* Frisvad's formula with a = 1/(1 + n.z) (sg = +1) and Duff's mirror with
   a = 1/(1 - n.z) (sg = -1), as onb_frisvad_threshold and onb_duff. */
static void frisvad_formula(cm *c, int P, int sg, const cv n[3], cv out[6])
{
	cv one = K(1.0), a, b;
	a = DIV(one, sg > 0 ? ADD(one, n[2]) : SUB(one, n[2]));
	if (sg > 0) {
		b = MUL(MUL(cm_neg(c, n[0]), n[1]), a);
		out[0] = SUB(one, MUL(MUL(n[0], n[0]), a)); out[1] = b; out[2] = cm_neg(c, n[0]);
		out[3] = b; out[4] = SUB(one, MUL(MUL(n[1], n[1]), a)); out[5] = cm_neg(c, n[1]);
	} else {
		b = MUL(MUL(n[0], n[1]), a);
		out[0] = SUB(one, MUL(MUL(n[0], n[0]), a)); out[1] = cm_neg(c, b); out[2] = n[0];
		out[3] = b; out[4] = SUB(MUL(MUL(n[1], n[1]), a), one); out[5] = cm_neg(c, n[1]);
	}
}

static void m_frisvad(cm *c, int P, int max, const cv n[3], cv out[6])
{
	double t = P == CM_F32 ? (double)(max ? ONB_FRISVAD_MAX_TF : ONB_FRISVAD_TF)
	                       : (max ? ONB_FRISVAD_MAX_T : ONB_FRISVAD_T);
	if (cm_branch(c, 0, CM_LT, n[2], cm_cst(c, t))) {
		cm_formula_nonzero(c, CQ_ALL);
		out[0] = K(0.0); out[1] = K(-1.0); out[2] = K(0.0);
		out[3] = K(-1.0); out[4] = K(0.0); out[5] = K(0.0);
		return;
	}
	frisvad_formula(c, P, 1, n, out);
}

static void m_duff(cm *c, int P, int unused, const cv n[3], cv out[6])
{
	(void)unused;
	frisvad_formula(c, P, cm_branch(c, 0, CM_LT, n[2], K(0.0)) ? -1 : 1, n, out);
}

static void m_duff_branchless(cm *c, int P, int unused, const cv n[3], cv out[6])
{
	const double sg = cm_branch_sign(c, 0, n[2]) ? -1.0 : 1.0;
	cv s = K(sg), ms = K(-sg), a, b;
	(void)unused;
	a = DIV(K(-1.0), ADD(s, n[2]));
	b = MUL(MUL(n[0], n[1]), a);
	out[0] = ADD(K(1.0), MUL(MUL(MUL(s, n[0]), n[0]), a)); out[1] = MUL(s, b); out[2] = MUL(ms, n[0]);
	out[3] = b; out[4] = ADD(s, MUL(MUL(n[1], n[1]), a)); out[5] = cm_neg(c, n[1]);
}

static void m_stark(cm *c, int P, int fixed, const cv n[3], cv out[6])
{
	const int xy = cm_branch_abs(c, 0, CM_LT, n[0], n[1]);
	const int xz = cm_branch_abs(c, 1, CM_LT, n[0], n[2]);
	const int yz = cm_branch_abs(c, 2, CM_LT, n[1], n[2]);
	const int xm = xy & xz, ym = yz & !xm, zm = fixed ? !(xm | ym) : !(xm & ym);
	cv e[3], p[3];
	e[0] = K(xm ? 1.0 : 0.0); e[1] = K(ym ? 1.0 : 0.0); e[2] = K(zm ? 1.0 : 0.0);
	cross(c, P, n, e, p);
	post_n_cross_u(c, P, n, p, DIV(K(1.0), cm_sqrt(c, P, dot3(c, P, p, p))), out);
}

static void m_pbrt_v3(cm *c, int P, int unused, const cv n[3], cv out[6])
{
	cv inv, u[3], w[3];
	int i;
	(void)unused;
	if (cm_branch_abs(c, 0, CM_GT, n[0], n[1])) {
		inv = DIV(K(1.0), cm_sqrt(c, P, ADD(MUL(n[0], n[0]), MUL(n[2], n[2]))));
		u[0] = MUL(cm_neg(c, n[2]), inv); u[1] = MUL(K(0.0), inv); u[2] = MUL(n[0], inv);
	} else {
		inv = DIV(K(1.0), cm_sqrt(c, P, ADD(MUL(n[1], n[1]), MUL(n[2], n[2]))));
		u[0] = MUL(K(0.0), inv); u[1] = MUL(n[2], inv); u[2] = MUL(cm_neg(c, n[1]), inv);
	}
	if (P == CM_F64) {
		post_n_cross_u(c, P, n, u, K(1.0), out);
		return;
	}
	for (i = 0; i < 3; i++) {  /* pbrt-v3's Cross: widened to double, then to float */
		out[i] = u[i];
		w[i] = cm_cvt(c, CM_F64, n[i]);
	}
	{
		cv uw[3], b[3];
		for (i = 0; i < 3; i++)
			uw[i] = cm_cvt(c, CM_F64, u[i]);
		cross(c, CM_F64, w, uw, b);
		for (i = 0; i < 3; i++)
			out[3 + i] = cm_cvt(c, CM_F32, b[i]);
	}
}

static void m_rtow(cm *c, int P, int unused, const cv w[3], cv out[6])
{
	cv inv, uw[3], a[3], cr[3], il;
	int i;
	(void)unused;
	inv = DIV(K(1.0), cm_sqrt(c, P, dot3(c, P, w, w)));
	for (i = 0; i < 3; i++)
		uw[i] = MUL(inv, w[i]);
	if (cm_branch_abs(c, 0, CM_GT, uw[0], K(0.9))) {
		a[0] = K(0.0); a[1] = K(1.0); a[2] = K(0.0);
	} else {
		a[0] = K(1.0); a[1] = K(0.0); a[2] = K(0.0);
	}
	cross(c, P, uw, a, cr);
	il = DIV(K(1.0), cm_sqrt(c, P, dot3(c, P, cr, cr)));
	for (i = 0; i < 3; i++)
		out[3 + i] = MUL(il, cr[i]);
	cross(c, P, uw, out + 3, out);
}

static void m_tangent_cross_z(cm *c, int P, int unused, const cv n[3], cv out[6])
{
	cv t[3], cr[3], l;
	int i;
	(void)unused;
	t[0] = n[0]; t[1] = n[1]; t[2] = ADD(n[2], K(1.0));
	cross(c, P, n, t, cr);
	l = cm_sqrt(c, P, dot3(c, P, cr, cr));
	for (i = 0; i < 3; i++)
		out[3 + i] = DIV(cr[i], l);
	cross(c, P, n, out + 3, out);
}

/* duff_wide: the float input widened, Duff's branchless formula in double,
   each output rounded once to float. */
static void m_duff_wide(cm *c, int P, int unused, const cv nf[3], cv out[6])
{
	cv n[3], d[6];
	int i;
	(void)unused;
	for (i = 0; i < 3; i++)
		n[i] = cm_cvt(c, CM_F64, nf[i]);
	m_duff_branchless(c, CM_F64, 0, n, d);
	for (i = 0; i < 6; i++)
		out[i] = cm_cvt(c, P, d[i]);
}

/* duff_comp: onb_duff_compf, operation by operation. */
static void m_duff_comp(cm *c, int P, int unused, const cv n[3], cv out[6])
{
	const double sg = cm_branch_sign(c, 0, n[2]) ? -1.0 : 1.0;
	cv x = n[0], y = n[1], z = n[2], s = K(sg), one = K(1.0);
	cv h, hl, a, e, al, xx, xxl, xy, xyl, yy, yyl, p, pl, b, bl, q, ql, sp, t1, t1l, t2, t2l, bb;
	(void)unused;
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

/* zero_any_n: b1 normalized and b2 = n x b1 (naive); b2 = v s with v.n = 0
   and b1 = v x n (hughes_moeller); b1 = p/|p| with p = n x e and b2 = n x b1
   (stark, pbrt_v3; tangent_cross_z with b1 and b2 swapped); rtow measures
   against n but builds from n/|n|, so all five.  Frisvad's and Duff's
   formulas need a unit n for every one of them. */
#define ZN_CROSS     ((1u << CQ_D2N) | (1u << CQ_D12))
#define ZN_NAIVE     (ZN_CROSS | (1u << CQ_N1))
#define ZN_HM_NONORM ((1u << CQ_D1N) | (1u << CQ_D2N) | (1u << CQ_D12))
#define ZN_HM        (ZN_HM_NONORM | (1u << CQ_N2))
#define ZN_UNIT_B1   ((1u << CQ_N1) | (1u << CQ_D1N) | (1u << CQ_D2N) | (1u << CQ_D12))
#define ZN_UNIT_B2   ((1u << CQ_N2) | (1u << CQ_D1N) | (1u << CQ_D2N) | (1u << CQ_D12))

static const cm_method methods[] = {
	{ "naive", m_naive, ONB__NORM_LIBM, 1, ZN_NAIVE },
	{ "naive_invsqrt", m_naive, ONB__NORM_INVSQRT, 1, ZN_NAIVE },
	{ "naive_rsqrt", m_naive, ONB__NORM_RSQRT, 1, ZN_NAIVE },
	{ "naive_rsqrt_nr", m_naive, ONB__NORM_RSQRT_NR, 1, ZN_NAIVE },
	{ "naive_nonorm", m_naive, ONB__NORM_NONE, 1, ZN_CROSS },
	{ "hughes_moeller", m_hughes_moeller, ONB__NORM_LIBM, 1, ZN_HM },
	{ "hughes_moeller_invsqrt", m_hughes_moeller, ONB__NORM_INVSQRT, 1, ZN_HM },
	{ "hughes_moeller_rsqrt", m_hughes_moeller, ONB__NORM_RSQRT, 1, ZN_HM },
	{ "hughes_moeller_rsqrt_nr", m_hughes_moeller, ONB__NORM_RSQRT_NR, 1, ZN_HM },
	{ "hughes_moeller_nonorm", m_hughes_moeller, ONB__NORM_NONE, 1, ZN_HM_NONORM },
	{ "frisvad", m_frisvad, 0, 1, 0 },
	{ "frisvad_max", m_frisvad, 1, 1, 0 },
	{ "duff", m_duff, 0, 1, 0 },
	{ "duff_branchless", m_duff_branchless, 0, 1, 0 },
	{ "stark", m_stark, 0, 3, ZN_UNIT_B1 },
	{ "stark_fixed", m_stark, 1, 3, ZN_UNIT_B1 },
	{ "pbrt_v3", m_pbrt_v3, 0, 1, ZN_UNIT_B1 },
	{ "rtow", m_rtow, 0, 1, CQ_ALL },
	{ "tangent_cross_z", m_tangent_cross_z, 0, 0, ZN_UNIT_B2 },
	{ "duff_wide", m_duff_wide, 0, 1, 0 },
	{ "duff_comp", m_duff_comp, 0, 1, 0 },
};

const cm_method *cm_find(const char *name)
{
	size_t i;
	for (i = 0; i < sizeof methods / sizeof methods[0]; i++)
		if (strcmp(methods[i].name, name) == 0)
			return &methods[i];
	return NULL;
}

void cm_run(cm *c, const cm_method *m, int P, const cv n[3], cv out[6])
{
	m->fn(c, P, m->param, n, out);
}
