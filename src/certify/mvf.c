/*
 * mvf.c - the mean-value-form back end of the models (CM_MVF).
 *
 * Every value is an outward-rounded MPFI interval that encloses it for all
 * points of the box: real unit vectors u in a box of (n.z, azimuth) and
 * every error term e_k in [-r_k, r_k].  Beside it, the value carries its
 * gradient in the e's, also as intervals over the whole box (forward
 * differentiation).  A rounding of an exact result v to format f is
 *     fl(v) = v (1 + e) + eta,   |e| <= u,   |eta| <= eta_f,
 * with eta only where |v| can fall below the smallest normal number
 * (u = 2^-24, eta_f = 2^-150 in float; 2^-53 and 2^-1074 in double).
 * An operation the box proves exact adds no term: a product by 0 or 1, by
 * a power of two that cannot underflow, of two floats in double, a
 * conversion that widens, and x - y with y/2 <= x <= 2y (Sterbenz).
 *
 * Mean value theorem: for any quantity Q of the outputs,
 *     Q(u, e) = Q(u, 0) + sum_k e_k dQ/de_k(u, xi),  xi between 0 and e,
 * so |Q| <= |Q(U, 0)| + sum_k r_k max|dQ/de_k(U, E)| over the box, which
 * is what mvf_quantity bounds.  Where Q(u, 0) = 0 identically (the method
 * is exact on the unit sphere), the first term is 0.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <mpfi.h>
#include "model_int.h"
#include "mvf.h"

#define MV_PREC   80
#define MV_MAXVAR 192

typedef struct {
	mpfi_t v;        /* the value over the box                         */
	mpfi_t *g;       /* d v / d e_k, meaningful where nz[k]             */
	unsigned char *nz;
	int ng;          /* entries 0..ng-1 may be nonzero                  */
	int fmt;         /* CM_F32 or CM_F64: the format the value lies in  */
	int is_cst;      /* an exact constant cval                          */
	double cval;
} mval;

struct mvf {
	mval val[CM_MAXV];
	int n;
	double r[MV_MAXVAR];   /* the range of each error term */
	int nvar;
	int failed;
	int zero_e;            /* every e is 0: values only, no gradients */
	mpfi_t t1, t2, t3;     /* scratch of round_to, grad_lin, sterbenz */
	mpfi_t s1, s2;         /* scratch of the operations: scale factors */
	mpfi_t one, mone;
	mpfr_t f1, f2;
};

mvf *mvf_new(void)
{
	mvf *m = calloc(1, sizeof *m);
	int i, k;
	if (!m)
		return NULL;
	for (i = 0; i < CM_MAXV; i++) {
		mval *x = &m->val[i];
		mpfi_init2(x->v, MV_PREC);
		x->g = malloc(MV_MAXVAR * sizeof *x->g);
		x->nz = calloc(MV_MAXVAR, 1);
		if (!x->g || !x->nz)
			abort(); /* a few MB at start-up: nothing sensible to do */
		for (k = 0; k < MV_MAXVAR; k++)
			mpfi_init2(x->g[k], MV_PREC);
	}
	mpfi_init2(m->t1, MV_PREC);
	mpfi_init2(m->t2, MV_PREC);
	mpfi_init2(m->t3, MV_PREC);
	mpfi_init2(m->s1, MV_PREC);
	mpfi_init2(m->s2, MV_PREC);
	mpfi_init2(m->one, MV_PREC);
	mpfi_init2(m->mone, MV_PREC);
	mpfi_set_d(m->one, 1.0);
	mpfi_set_d(m->mone, -1.0);
	mpfr_init2(m->f1, MV_PREC);
	mpfr_init2(m->f2, MV_PREC);
	return m;
}

void mvf_free(mvf *m)
{
	int i, k;
	if (!m)
		return;
	for (i = 0; i < CM_MAXV; i++) {
		for (k = 0; k < MV_MAXVAR; k++)
			mpfi_clear(m->val[i].g[k]);
		free(m->val[i].g);
		free(m->val[i].nz);
		mpfi_clear(m->val[i].v);
	}
	mpfi_clear(m->t1);
	mpfi_clear(m->t2);
	mpfi_clear(m->t3);
	mpfi_clear(m->s1);
	mpfi_clear(m->s2);
	mpfi_clear(m->one);
	mpfi_clear(m->mone);
	mpfr_clear(m->f1);
	mpfr_clear(m->f2);
	free(m);
}

int mvf_failed(const mvf *m) { return m->failed; }

static double unit_round(int f) { return f == CM_F32 ? 0x1p-24 : 0x1p-53; }
/* Half the smallest subnormal; in double 2^-1075 is not a double, so
   its double neighbour 2^-1074 (a sound, looser term). */
static double eta_of(int f) { return f == CM_F32 ? 0x1p-150 : 0x1p-1074; }
static double normal_min(int f) { return f == CM_F32 ? 0x1p-126 : 0x1p-1022; }

/* A fresh value slot with an empty gradient. */
static cv fresh(mvf *m, int fmt)
{
	mval *x;
	if (m->n >= CM_MAXV) {
		m->failed = 1;
		return CM_MAXV - 1;
	}
	x = &m->val[m->n];
	memset(x->nz, 0, (size_t)(x->ng > 0 ? x->ng : 0));
	x->ng = 0;
	x->fmt = fmt;
	x->is_cst = 0;
	return m->n++;
}

static int new_var(mvf *m, double range)
{
	if (m->nvar >= MV_MAXVAR) {
		m->failed = 1;
		return MV_MAXVAR - 1;
	}
	m->r[m->nvar] = range;
	return m->nvar++;
}

static void set_grad(mval *x, int k, mpfi_srcptr g)
{
	mpfi_set(x->g[k], g);
	x->nz[k] = 1;
	if (x->ng <= k)
		x->ng = k + 1;
}

/* r->g = sa * a->g + sb * b->g (sa, sb intervals; b may be NULL). */
static void grad_lin(mvf *m, mval *r, const mval *a, mpfi_srcptr sa, const mval *b, mpfi_srcptr sb)
{
	int k, ng = a->ng;
	if (m->zero_e)
		return;
	if (b && b->ng > ng)
		ng = b->ng;
	for (k = 0; k < ng; k++) {
		int ia = k < a->ng && a->nz[k], ib = b && k < b->ng && b->nz[k];
		if (!ia && !ib)
			continue;
		if (ia)
			mpfi_mul(m->t3, a->g[k], sa);
		else
			mpfi_set_d(m->t3, 0.0);
		if (ib) {
			mpfi_mul(m->t2, b->g[k], sb);
			mpfi_add(m->t3, m->t3, m->t2);
		}
		set_grad(r, k, m->t3);
	}
}

cv mvf_cst(mvf *m, double v)
{
	cv i = fresh(m, (double)(float)v == v ? CM_F32 : CM_F64);
	mpfi_set_d(m->val[i].v, v);
	m->val[i].is_cst = 1;
	m->val[i].cval = v;
	return i;
}

/* Round slot r (an exact result) to format f, unless it is exact there. */
static void round_to(mvf *m, cv r, int f)
{
	mval *x = &m->val[r];
	double u = unit_round(f);
	int k;
	x->fmt = f;
	if (mpfi_nan_p(x->v) || !mpfi_bounded_p(x->v)) {
		m->failed = 1;
		return;
	}
	if (m->zero_e)
		return;
	mpfi_interv_d(m->t1, 1.0 - u, 1.0 + u);
	for (k = 0; k < x->ng; k++)
		if (x->nz[k])
			mpfi_mul(x->g[k], x->g[k], m->t1);
	set_grad(x, new_var(m, u), x->v);
	mpfi_mig(m->f1, x->v);
	mpfi_mul(x->v, x->v, m->t1);
	if (mpfr_cmp_d(m->f1, normal_min(f)) < 0) {
		double eta = eta_of(f);
		mpfi_set_d(m->t1, 1.0);
		set_grad(x, new_var(m, eta), m->t1);
		mpfi_interv_d(m->t1, -eta, eta);
		mpfi_add(x->v, x->v, m->t1);
	}
}

static int is_cst(const mval *x, double v) { return x->is_cst && x->cval == v; }

static int is_pow2(const mval *x)
{
	int e;
	return x->is_cst && x->cval != 0.0 && fabs(frexp(x->cval, &e)) == 0.5;
}

/* Sterbenz: x - y is exact when y/2 <= x <= 2y (x, y of one sign and in
   the format).  neg_b: the operation is x + b, i.e. y = -b. */
static int sterbenz(mvf *m, const mval *a, const mval *b, int neg_b, int f)
{
	mpfi_srcptr y = b->v;
	if (a->fmt > f || b->fmt > f)
		return 0;
	if (neg_b) {
		mpfi_neg(m->t1, b->v);
		y = m->t1;
	}
	if (mpfi_is_strictly_neg(a->v) && mpfi_is_strictly_neg(y)) {
		mpfi_neg(m->t2, a->v);
		mpfi_neg(m->t1, y);
		return mvf_ratio_within_2(m, m->t2, m->t1);
	}
	if (mpfi_is_strictly_pos(a->v) && mpfi_is_strictly_pos(y))
		return mvf_ratio_within_2(m, a->v, y);
	return 0;
}

/* For positive intervals x, y: y/2 <= x <= 2y at every point. */
int mvf_ratio_within_2(mvf *m, mpfi_srcptr x, mpfi_srcptr y)
{
	mpfi_get_left(m->f1, x);
	mpfi_get_right(m->f2, y);
	mpfr_div_2ui(m->f2, m->f2, 1, MPFR_RNDU);
	if (mpfr_cmp(m->f1, m->f2) < 0)
		return 0;
	mpfi_get_right(m->f1, x);
	mpfi_get_left(m->f2, y);
	mpfr_mul_2ui(m->f2, m->f2, 1, MPFR_RNDD);
	return mpfr_cmp(m->f1, m->f2) <= 0;
}

/* 1 when the box proves the operation exact in format f. */
static int exact_op(mvf *m, int op, int f, const mval *a, const mval *b, const mval *r)
{
	switch (op) {
	case MVF_NEG:
		return 1;
	case MVF_CVT:
		return f == CM_F64 || a->fmt == CM_F32;
	case MVF_MUL:
		if (is_cst(a, 0.0) || is_cst(b, 0.0) || is_cst(a, 1.0) || is_cst(b, 1.0) ||
		    is_cst(a, -1.0) || is_cst(b, -1.0))
			return 1;
		if (f == CM_F64 && a->fmt == CM_F32 && b->fmt == CM_F32)
			return 1; /* 24 + 24 bits fit in 53 */
		if (is_pow2(a) || is_pow2(b)) {
			mpfi_mig(m->f1, r->v);
			return mpfr_cmp_d(m->f1, normal_min(f)) >= 0;
		}
		return 0;
	case MVF_ADD:
	case MVF_SUB:
		if (is_cst(a, 0.0) || is_cst(b, 0.0))
			return 1;
		return sterbenz(m, a, b, op == MVF_ADD, f);
	default:
		return 0;
	}
}

static void copy_grad(mvf *m, mval *r, const mval *a)
{
	int k;
	if (m->zero_e)
		return;
	for (k = 0; k < a->ng; k++)
		if (a->nz[k])
			set_grad(r, k, a->g[k]);
}

/* r->g += d->g */
static void grad_add(mvf *m, mval *r, const mval *d)
{
	int k;
	if (m->zero_e)
		return;
	for (k = 0; k < d->ng; k++) {
		if (!d->nz[k])
			continue;
		if (k < r->ng && r->nz[k])
			mpfi_add(r->g[k], r->g[k], d->g[k]);
		else
			set_grad(r, k, d->g[k]);
	}
}

/* The exact operation into r (value and gradient); 0 when it cannot be
   enclosed (a division by an interval holding 0, a square root whose
   derivative is unbounded). */
static int exact_eval(mvf *m, int op, mval *r, const mval *a, const mval *b, const mval *d)
{
	switch (op) {
	case MVF_ADD:
		mpfi_add(r->v, a->v, b->v);
		grad_lin(m, r, a, m->one, b, m->one);
		return 1;
	case MVF_SUB:
		mpfi_sub(r->v, a->v, b->v);
		grad_lin(m, r, a, m->one, b, m->mone);
		return 1;
	case MVF_MUL:
	case MVF_FMA:
		mpfi_mul(r->v, a->v, b->v);
		grad_lin(m, r, a, b->v, b, a->v);
		if (op == MVF_FMA) {
			mpfi_add(r->v, r->v, d->v);
			grad_add(m, r, d);
		}
		return 1;
	case MVF_DIV:
		if (mpfi_has_zero(b->v))
			return 0;
		mpfi_div(r->v, a->v, b->v);
		mpfi_inv(m->s1, b->v);          /* d(a/b) = da/b - db a/b^2 */
		mpfi_div(m->s2, r->v, b->v);
		mpfi_neg(m->s2, m->s2);
		grad_lin(m, r, a, m->s1, b, m->s2);
		return 1;
	case MVF_SQRT:
		if (!mpfi_is_nonneg(a->v))
			return 0;
		mpfi_sqrt(r->v, a->v);
		if (m->zero_e)
			return 1;
		if (!mpfi_is_strictly_pos(a->v))
			return 0;
		mpfi_mul_2ui(m->s1, r->v, 1);   /* d sqrt(a) = da / (2 sqrt(a)) */
		mpfi_inv(m->s1, m->s1);
		grad_lin(m, r, a, m->s1, NULL, NULL);
		return 1;
	case MVF_NEG:
		mpfi_neg(r->v, a->v);
		grad_lin(m, r, a, m->mone, NULL, NULL);
		return 1;
	default: /* MVF_CVT */
		mpfi_set(r->v, a->v);
		copy_grad(m, r, a);
		return 1;
	}
}

cv mvf_op(mvf *m, int op, int f, cv ia, cv ib, cv id)
{
	cv ir = fresh(m, f);
	mval *r = &m->val[ir];
	const mval *a = &m->val[ia], *b = ib >= 0 ? &m->val[ib] : NULL, *d = id >= 0 ? &m->val[id] : NULL;
	if (m->failed)
		return ir;
	if (!exact_eval(m, op, r, a, b, d) || mpfi_nan_p(r->v) || !mpfi_bounded_p(r->v)) {
		m->failed = 1;
		return ir;
	}
	if (op == MVF_NEG)
		r->fmt = a->fmt;
	else if (!exact_op(m, op, f, a, b, r))
		round_to(m, ir, f);
	return ir;
}

cv mvf_seed(mvf *m, seed_kind k, cv ia)
{
	int f = k == SEED_INVSQRT_D ? CM_F64 : CM_F32;
	cv ir = fresh(m, f);
	mval *r = &m->val[ir];
	const mval *a = &m->val[ia];
	seed_bound sb;
	if (m->failed)
		return ir;
	mpfi_get_left(m->f1, a->v);
	mpfi_get_right(m->f2, a->v);
	if (seed_bound_get(k, &sb) != 0 || mpfr_cmp_d(m->f1, sb.x_lo) < 0 || mpfr_cmp_d(m->f2, sb.x_hi) > 0) {
		m->failed = 1; /* outside the inputs whose seed error was bounded */
		return ir;
	}
	mpfi_sqrt(m->s1, a->v);                          /* 1/sqrt(a)               */
	mpfi_inv(m->s1, m->s1);
	mpfi_interv_d(m->t1, 1.0 - sb.bound, 1.0 + sb.bound);
	mpfi_mul(r->v, m->s1, m->t1);                    /* (1 + e)/sqrt(a)         */
	if (m->zero_e) {
		mpfi_set(r->v, m->s1);
		return ir;
	}
	mpfi_div(m->s2, r->v, a->v);                     /* d/da = -(1 + e)/(2 a^1.5) */
	mpfi_div_2ui(m->s2, m->s2, 1);
	mpfi_neg(m->s2, m->s2);
	grad_lin(m, r, a, m->s2, NULL, NULL);
	set_grad(r, new_var(m, sb.bound), m->s1);        /* d/de = 1/sqrt(a)        */
	return ir;
}

void mvf_compare(mvf *m, int op, int absolute, cv ia, cv ib, int *can_true, int *can_false)
{
	mpfi_srcptr a = m->val[ia].v, b = m->val[ib].v;
	if (absolute) {
		mpfi_abs(m->s1, a);
		mpfi_abs(m->s2, b);
		a = m->s1;
		b = m->s2;
	}
	if (op == CM_GT) { /* a > b */
		mpfi_srcptr t = a;
		a = b;
		b = t;
	}
	/* a < b possible when min a < max b; false possible when max a >= min b */
	mpfi_get_left(m->f1, a);
	mpfi_get_right(m->f2, b);
	*can_true = mpfr_cmp(m->f1, m->f2) < 0;
	mpfi_get_right(m->f1, a);
	mpfi_get_left(m->f2, b);
	*can_false = mpfr_cmp(m->f1, m->f2) >= 0;
}

void mvf_sign_possible(mvf *m, cv ia, int *can_set, int *can_clear)
{
	mpfi_get_left(m->f1, m->val[ia].v);
	mpfi_get_right(m->f2, m->val[ia].v);
	*can_set = mpfr_sgn(m->f1) <= 0;   /* -0 possible wherever 0 is */
	*can_clear = mpfr_sgn(m->f2) >= 0;
}

/* Start a run over box b: the inputs n_i = u_i (1 + d_i) + eta_i, or
   u_i (1 + t) with |t| <= tolerance when tolerance >= 0. */
void mvf_begin(mvf *m, const mvf_box *b, int zero_e, cv in[3])
{
	double u = unit_round(b->prec);
	int i, t_var = -1;
	m->n = 0;
	m->nvar = 0;
	m->failed = 0;
	m->zero_e = zero_e;
	for (i = 0; i < 3; i++)
		in[i] = fresh(m, b->prec);
	mpfi_interv_d(m->t1, b->z_lo, b->z_hi);                 /* z             */
	mpfi_d_sub(m->s1, 1.0, m->t1);
	mpfi_add_d(m->s2, m->t1, 1.0);
	mpfi_mul(m->s1, m->s1, m->s2);
	if (!mpfi_is_nonneg(m->s1))
		mpfi_interv_d(m->s1, 0.0, 1.0);
	mpfi_sqrt(m->s1, m->s1);                                /* r = sqrt(1 - z^2) */
	mpfi_set(m->val[in[2]].v, m->t1);
	mpfi_interv_d(m->t2, b->phi_lo, b->phi_hi);             /* phi, radians  */
	mpfi_cos(m->s2, m->t2);
	mpfi_mul(m->val[in[0]].v, m->s1, m->s2);
	mpfi_sin(m->s2, m->t2);
	mpfi_mul(m->val[in[1]].v, m->s1, m->s2);
	if (zero_e)
		return;
	if (b->tolerance >= 0)
		t_var = new_var(m, b->tolerance);
	for (i = 0; i < 3; i++) {
		mval *x = &m->val[in[i]];
		mpfi_set(m->s2, x->v);                              /* u_i           */
		if (t_var >= 0) {
			set_grad(x, t_var, m->s2);
			mpfi_interv_d(m->t1, 1.0 - b->tolerance, 1.0 + b->tolerance);
			mpfi_mul(x->v, x->v, m->t1);
			continue;
		}
		set_grad(x, new_var(m, u), m->s2);
		mpfi_interv_d(m->t1, 1.0 - u, 1.0 + u);
		mpfi_mul(x->v, x->v, m->t1);
		mpfi_mig(m->f1, m->s2);
		if (mpfr_cmp_d(m->f1, normal_min(b->prec)) < 0) {
			double eta = eta_of(b->prec);
			set_grad(x, new_var(m, eta), m->one);
			mpfi_interv_d(m->t1, -eta, eta);
			mpfi_add(x->v, x->v, m->t1);
		}
	}
}

/* Exact operations on model values, for the defect quantities. */
static cv ex(mvf *m, int op, cv a, cv b)
{
	cv ir = fresh(m, CM_F64);
	mval *r = &m->val[ir];
	if (!m->failed && (!exact_eval(m, op, r, &m->val[a], b >= 0 ? &m->val[b] : NULL, NULL) ||
	                   mpfi_nan_p(r->v) || !mpfi_bounded_p(r->v)))
		m->failed = 1;
	return ir;
}

static cv ex_dot(mvf *m, const cv *p, const cv *q)
{
	cv s = ex(m, MVF_MUL, p[0], q[0]);
	s = ex(m, MVF_ADD, s, ex(m, MVF_MUL, p[1], q[1]));
	return ex(m, MVF_ADD, s, ex(m, MVF_MUL, p[2], q[2]));
}

void mvf_quantities(mvf *m, const cv n[3], const cv out[6], cv q[5])
{
	cv one = mvf_cst(m, 1.0);
	q[CQ_N1] = ex(m, MVF_SUB, ex(m, MVF_SQRT, ex_dot(m, out, out), -1), one);
	q[CQ_N2] = ex(m, MVF_SUB, ex(m, MVF_SQRT, ex_dot(m, out + 3, out + 3), -1), one);
	q[CQ_D1N] = ex_dot(m, out, n);
	q[CQ_D2N] = ex_dot(m, out + 3, n);
	q[CQ_D12] = ex_dot(m, out, out + 3);
}

/* |Q| over the box directly, and sum_k r_k max|dQ/de_k|, rounded up. */
void mvf_bounds(mvf *m, cv iq, double *direct, double *lin)
{
	const mval *q = &m->val[iq];
	int k;
	if (m->failed) {
		*direct = *lin = INFINITY;
		return;
	}
	mpfi_mag(m->f1, q->v);
	*direct = mpfr_get_d(m->f1, MPFR_RNDU);
	mpfr_set_zero(m->f2, 1);
	for (k = 0; k < q->ng; k++) {
		if (!q->nz[k])
			continue;
		mpfi_mag(m->f1, q->g[k]);
		mpfr_mul_d(m->f1, m->f1, m->r[k], MPFR_RNDU);
		mpfr_add(m->f2, m->f2, m->f1, MPFR_RNDU);
	}
	*lin = mpfr_get_d(m->f2, MPFR_RNDU);
}
