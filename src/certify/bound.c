/*
 * bound.c - the certified bound of one box: every feasible branch path of
 * the model, run once over the box with its error terms (gradients) and,
 * where the formula is not exact on the unit sphere along that path, once
 * more with every error term 0 (the centre Q(U, 0)).  Each quantity lies
 * in the intersection of two sound enclosures, both signed: the interval of
 * Q itself, and the mean value form Q(U, 0) + [-1, 1] sum_k r_k max|dQ/de_k|,
 * its centre Q(U, 0) itself the intersection of its interval and its own
 * mean value form in u.  The sign is kept to the end: | |b| - 1 | comes
 * from |b|^2 - 1 through sqrt(1 + s) - 1, which is not symmetric in s.
 */
#include <math.h>
#include <stdlib.h>
#include "bound.h"

struct bound_ctx {
	cm *c;
};

bound_ctx *bound_new(void)
{
	bound_ctx *b = calloc(1, sizeof *b);
	if (b && !(b->c = cm_new(CM_MVF))) {
		free(b);
		return NULL;
	}
	return b;
}

void bound_free(bound_ctx *b)
{
	if (!b)
		return;
	cm_free(b->c);
	free(b);
}

/* An enclosure [lo, hi] of one quantity, rounded outward. */
typedef struct {
	double lo, hi;
} span;

/* The intersection of two enclosures of the same quantity (both sound, so
   never empty but for a NaN: then the first). */
static span meet(span a, span b)
{
	span r;
	r.lo = a.lo > b.lo ? a.lo : b.lo;
	r.hi = a.hi < b.hi ? a.hi : b.hi;
	return r.lo <= r.hi ? r : a;
}

/* c + [-r, r], rounded outward. */
static span widen(span c, double r)
{
	span w;
	w.lo = nextafter(c.lo - r, -INFINITY);
	w.hi = nextafter(c.hi + r, INFINITY);
	return w;
}

/* | |b| - 1 | from an enclosure [L, H] of |b|^2 - 1: |b| - 1 = sqrt(1 + s) - 1
   grows with s, so it lies in [sqrt(1 + L) - 1, sqrt(1 + H) - 1] (-1 at the
   lowest: |b| >= 0).  Each end is evaluated as s / (1 + sqrt(1 + s)),
   without the cancellation of sqrt(1 + s) - 1 in double, and rounded the
   safe way (denominator down, quotient up).  The sign matters: an
   |b|^2 - 1 of 3 is an | |b| - 1 | of 1, not 3. */
static double norm_end(double s)
{
	double r, d;
	if (s <= -1.0)
		return 1.0;
	if (!(s < INFINITY))
		return INFINITY;
	r = nextafter(sqrt(nextafter(1.0 + s, 0.0)), 0.0);   /* <= sqrt(1 + s) */
	d = nextafter(1.0 + r, 0.0);
	return nextafter(fabs(s) / d, INFINITY);
}

static double norm_from_square(span s)
{
	double down = 0.0, up = 0.0;
	if (isnan(s.lo) || isnan(s.hi))
		return INFINITY;
	if (s.lo < 0.0)
		down = norm_end(s.lo);
	if (s.hi > 0.0)
		up = norm_end(s.hi);
	return down > up ? down : up;
}

/* The bound on quantity k from an enclosure of what mvf_quantities
   computes: |Q|, or | |b| - 1 | from |b|^2 - 1. */
static double quantity_bound(int k, span s)
{
	double a, b;
	if (k == CQ_N1 || k == CQ_N2)
		return norm_from_square(s);
	a = fabs(s.lo);
	b = fabs(s.hi);
	if (isnan(a) || isnan(b))
		return INFINITY;
	return a > b ? a : b;
}

/* One run of the model along `path`; q[] the quantities. Returns 0 when the
   path is infeasible for the box, -1 when it failed, 1 otherwise. */
static int run_path(cm *c, const cm_method *m, const mvf_box *x, unsigned path, int mode, cv q[NCQ])
{
	cv n[3], out[6];
	c->path = path;
	c->seen = 0;
	c->infeasible = 0;
	c->nonzero = 0;
	c->zero_n = c->norm_n = c->zero_late = 0;
	c->late_var = 0;
	c->failed = 0;
	mvf_begin(c->m, x, mode, n);
	cm_run(c, m, x->prec, n, out);
	if (c->infeasible)
		return 0;
	if (mvf_failed(c->m))
		return -1;
	mvf_quantities(c->m, n, out, q);
	return mvf_failed(c->m) ? -1 : 1;
}

/* Where a gradient cannot be enclosed: the largest |Q| over the box from
   the values alone (+inf when even they fail). */
static double values_bound(cm *c, const cm_method *m, const mvf_box *x, unsigned path)
{
	cv q[NCQ];
	double best = 0.0, d, unused;
	span v;
	int k;
	if (run_path(c, m, x, path, MVF_VALUES, q) <= 0)
		return INFINITY;
	for (k = 0; k < NCQ; k++) {
		mvf_bounds(c->m, q[k], &v.lo, &v.hi, &unused);
		d = quantity_bound(k, v);
		if (!(d <= best))
			best = d;
	}
	return isnan(best) ? INFINITY : best;
}

/* The centre Q(U, 0) of each quantity in `want` along `path`: the
   intersection of its direct interval and the centred form Q(c, 0) +
   [-1, 1] sum_i r_i max|dQ/du_i| (c the box's midpoint), which the
   dependency of the formula on u (terms of size |u| that cancel) cannot
   widen as much.  Returns 0 when the direct run fails. */
static int centre_bounds(cm *c, const cm_method *m, const mvf_box *x, unsigned path, unsigned want,
                         span centre[NCQ])
{
	cv q[NCQ];
	span at_mid[NCQ];
	double unused, lin;
	int k;
	if (run_path(c, m, x, path, MVF_AT_ZERO, q) <= 0)
		return 0;
	for (k = 0; k < NCQ; k++)
		mvf_bounds(c->m, q[k], &centre[k].lo, &centre[k].hi, &unused);
	if (run_path(c, m, x, path, MVF_AT_MID, q) <= 0)
		return 1;
	for (k = 0; k < NCQ; k++)
		mvf_bounds(c->m, q[k], &at_mid[k].lo, &at_mid[k].hi, &unused);
	if (run_path(c, m, x, path, MVF_CENTRED, q) <= 0)
		return 1;
	for (k = 0; k < NCQ; k++)
		if (want & (1u << k)) {
			span sink;   /* only its gradient term is wanted here */
			mvf_bounds(c->m, q[k], &sink.lo, &sink.hi, &lin);
			centre[k] = meet(centre[k], widen(at_mid[k], lin));
		}
	return 1;
}

/* The bound along one feasible path (or -1 when infeasible): each quantity
   in the intersection of its direct interval and its mean value form
   Q(U, 0) + [-1, 1] sum_k r_k max|dQ/de_k| (Q(U, 0) = 0 where the formula
   is exact on the unit sphere along the path). */
static double path_bound(cm *c, const cm_method *m, const mvf_box *x, unsigned path)
{
	cv q[NCQ];
	span direct[NCQ], centre[NCQ], nn;
	double lin[NCQ], lin_e[NCQ], best = 0.0;
	unsigned nonzero, zero_n, norm_n;
	int k, known = 0, r = run_path(c, m, x, path, MVF_FULL, q);
	if (r == 0)
		return -1.0;
	if (r < 0)
		return values_bound(c, m, x, path);
	for (k = 0; k < NCQ; k++) {
		mvf_bounds(c->m, q[k], &direct[k].lo, &direct[k].hi, &lin[k]);
		lin_e[k] = mvf_lin_arith(c->m, q[k]);
		if (!mvf_input_grad_ok(c->m))
			lin[k] = INFINITY;
	}
	mvf_norm_n(c->m, &nn.lo, &nn.hi);
	zero_n = (m->zero_any_n | c->zero_n) & ~c->nonzero;
	norm_n = c->norm_n & ~c->nonzero & ~zero_n;
	nonzero = c->nonzero;   /* n.z given: n is not unit at e = 0 */
	if (x->has_zpoint)
		nonzero |= CQ_ALL & ~m->zero_any_n;
	if (nonzero)
		known = centre_bounds(c, m, x, path, nonzero, centre);
	for (k = 0; k < NCQ; k++) {
		span s = direct[k];
		double v;
		if (!(nonzero & (1u << k))) {
			span zero = { 0.0, 0.0 };
			s = meet(s, widen(zero, lin[k]));
		} else if (known) {
			s = meet(s, widen(centre[k], lin[k]));
		}
		/* exact in n: Q(n, e) = Q(n, 0) + sum over the arithmetic's terms,
		   with Q(n, 0) = 0 or |n|^2 - 1 */
		if (c->zero_late & ~c->nonzero & (1u << k)) {
			span zero = { 0.0, 0.0 };
			s = meet(s, widen(zero, mvf_lin_from(c->m, q[k], c->late_var)));
		}
		if (zero_n & (1u << k)) {
			span zero = { 0.0, 0.0 };
			s = meet(s, widen(zero, lin_e[k]));
		} else if (norm_n & (1u << k)) {
			s = meet(s, widen(nn, lin_e[k]));
		}
		v = quantity_bound(k, s);
		if (!(v <= best))
			best = v; /* NaN stays +inf below */
	}
	return isnan(best) ? INFINITY : best;
}

double bound_box(bound_ctx *b, const cm_method *m, const mvf_box *x)
{
	unsigned path, npath = 1u << m->nbranch;
	double best = 0.0;
	for (path = 0; path < npath; path++) {
		double v = path_bound(b->c, m, x, path);
		if (!(v <= best))
			best = v;   /* an infeasible path gives -1 */
	}
	/* No feasible path: no input of the region lies in the box (every
	   comparison has a possible side on a nonempty interval, so only an
	   empty band makes every path infeasible). */
	return best;
}
