/*
 * bound.c - the certified bound of one box: every feasible branch path of
 * the model, run once over the box with its error terms (gradients) and,
 * where the formula is not exact on the unit sphere along that path, once
 * more with every error term 0 (the centre Q(U, 0)).  Each quantity takes
 * the smaller of two sound bounds: the interval of Q itself, and the mean
 * value form |Q(U, 0)| + sum_k r_k max|dQ/de_k|, its centre |Q(U, 0)| itself
 * the smaller of its interval and its own mean value form in u.
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

/* | |b| - 1 | from a bound B on | |b|^2 - 1 |: it is | |b|^2 - 1 | / (|b| + 1)
   and |b| >= sqrt(1 - B), so at most B / (1 + sqrt(1 - B)) (B when B >= 1),
   each step rounded the safe way. */
static double norm_from_square(double B)
{
	double d;
	if (!(B < 1.0))
		return B;
	d = 1.0 + nextafter(sqrt(1.0 - nextafter(B, INFINITY)), 0.0);
	return nextafter(B / nextafter(d, 0.0), INFINITY);
}

/* The bound on quantity k from one on what mvf_quantities computes. */
static double quantity_bound(int k, double v)
{
	return k == CQ_N1 || k == CQ_N2 ? norm_from_square(v) : v;
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
	int k;
	if (run_path(c, m, x, path, MVF_VALUES, q) <= 0)
		return INFINITY;
	for (k = 0; k < NCQ; k++) {
		mvf_bounds(c->m, q[k], &d, &unused);
		d = quantity_bound(k, d);
		if (!(d <= best))
			best = d;
	}
	return isnan(best) ? INFINITY : best;
}

/* The centre |Q(U, 0)| of each quantity in `want` along `path`: the
   smaller of the direct interval and the centred form |Q(c, 0)| +
   sum_i r_i max|dQ/du_i| (c the box's midpoint), which the dependency of
   the formula on u (terms of size |u| that cancel) cannot widen as much.
   Returns 0 when the direct run fails. */
static int centre_bounds(cm *c, const cm_method *m, const mvf_box *x, unsigned path, unsigned want,
                         double centre[NCQ])
{
	cv q[NCQ];
	double at_mid[NCQ], d, unused;
	int k, mid_ok;
	if (run_path(c, m, x, path, MVF_AT_ZERO, q) <= 0)
		return 0;
	for (k = 0; k < NCQ; k++)
		mvf_bounds(c->m, q[k], &centre[k], &unused);
	if (!(mid_ok = run_path(c, m, x, path, MVF_AT_MID, q) > 0))
		return 1;
	for (k = 0; k < NCQ; k++)
		mvf_bounds(c->m, q[k], &at_mid[k], &unused);
	if (run_path(c, m, x, path, MVF_CENTRED, q) <= 0)
		return 1;
	for (k = 0; k < NCQ; k++)
		if (want & (1u << k)) {
			double lin;
			mvf_bounds(c->m, q[k], &unused, &lin);
			d = nextafter(at_mid[k] + lin, INFINITY);   /* the sum rounded up */
			if (d < centre[k])
				centre[k] = d;
		}
	return 1;
}

/* The bound along one feasible path (or -1 when infeasible). */
static double path_bound(cm *c, const cm_method *m, const mvf_box *x, unsigned path)
{
	cv q[NCQ];
	double direct[NCQ], lin[NCQ], centre[NCQ], best = 0.0;
	unsigned nonzero;
	int k, r = run_path(c, m, x, path, MVF_FULL, q);
	if (r == 0)
		return -1.0;
	if (r < 0)
		return values_bound(c, m, x, path);
	for (k = 0; k < NCQ; k++)
		mvf_bounds(c->m, q[k], &direct[k], &lin[k]);
	nonzero = c->nonzero;   /* n.z given: n is not unit at e = 0 */
	if (x->has_zpoint)
		nonzero |= CQ_ALL & ~m->zero_any_n;
	if (nonzero && centre_bounds(c, m, x, path, nonzero, centre)) {
		for (k = 0; k < NCQ; k++)
			if (nonzero & (1u << k))
				lin[k] = nextafter(centre[k] + lin[k], INFINITY); /* the sum rounded up */
	} else if (nonzero) {
		for (k = 0; k < NCQ; k++)
			if (nonzero & (1u << k))
				lin[k] = INFINITY;
	}
	for (k = 0; k < NCQ; k++) {
		double v = quantity_bound(k, direct[k] < lin[k] ? direct[k] : lin[k]);
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
