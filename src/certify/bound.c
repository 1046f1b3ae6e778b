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
	int unb_op;   /* bound_unbounded_op */
	int box_cause; /* bound_box_cause */
};

bound_ctx *bound_new(void)
{
	bound_ctx *b = calloc(1, sizeof *b);
	if (b && !(b->c = cm_new(CM_MVF))) {
		free(b);
		return NULL;
	}
	if (b)
		b->unb_op = b->box_cause = -1;
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
	c->cross_to = c->cross_kind = 0;
	c->failed = 0;
	mvf_begin(c->m, x, mode, n);
	cm_run(c, m, x->prec, n, out);
	if (c->infeasible || mvf_no_point(c->m))
		return 0;
	if (mvf_failed(c->m))
		return -1;
	mvf_quantities(c->m, n, out, q);
	c->cross_kind = 0;
	if (c->cross_to && !c->ar) {   /* the cross rule is proven for round to nearest */
		const cv *o = out + 3 * (c->cross_to - 1);
		if (o[0] == c->cross_q[0] && o[1] == c->cross_q[1] && o[2] == c->cross_q[2])
			c->cross_kind = 1;
		else if (mvf_scaled_of(c->m, o, c->cross_q, &c->cross_u, &c->cross_eta))
			c->cross_kind = 2;
	}
	return mvf_failed(c->m) ? -1 : 1;
}

/* Where a gradient cannot be enclosed: each quantity's interval over the
   box from the values alone (the whole line when even they fail). */
static void values_spans(cm *c, const cm_method *m, const mvf_box *x, unsigned path, span s[NCQ])
{
	cv q[NCQ];
	double unused;
	int k, ok = run_path(c, m, x, path, MVF_VALUES, q) > 0;
	for (k = 0; k < NCQ; k++) {
		s[k].lo = -INFINITY;
		s[k].hi = INFINITY;
		if (ok)
			mvf_bounds(c->m, q[k], &s[k].lo, &s[k].hi, &unused);
	}
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

/* The cross rule (cm.cross_to): an output d = cross(n, v) of the input n
   and the other output v (or cross(v, n)), each component a - b of two
   products, rounded as a(1 + d1) - b(1 + d2) then (1 + d3), or fused
   (one of d1, d2 zero).  Its error r = d - n x v has, per component,
   |r_i| <= u (1 + u) (|a_i| + |b_i|) + u |(n x v)_i| + 4 eta, and
   sum_i a_i^2 + b_i^2 = sum_(j != k) n_j^2 v_k^2 <= |n|^2 |v|^2, so
       |r| <= R = ((1 + u) sqrt 2 + 1) u |n| |v| + 8 eta,
       |n x v|^2 - 1 = A + B + A B - (n.v)^2,
   A = |n|^2 - 1, B = |v|^2 - 1, both enclosed (nn, s[v]).  Then
   |d|^2 - 1 lies in g -+ 2 R |n x v| (+ R^2 above), d.n = r.n and
   d.v = r.v: |d.n| <= R |n|, |d.v| <= R |v|.  Where the output is the
   normalized b = q K (1 + d) + eta (cross_kind 2, as Embree and Open3D
   build b2), |b.n| and |b.v| follow from |r| and |b| the same way.
   Every value is small and each step is rounded outward with a relative
   2^-50 margin. */
static double mag(span s)
{
	const double a = fabs(s.lo), b = fabs(s.hi);
	return isnan(a) || isnan(b) ? INFINITY : a > b ? a : b;
}

static double hi_of(double v) { return v + fabs(v) * 0x1p-50 + 0x1p-1000; }
static double lo_of(double v) { return v - fabs(v) * 0x1p-50 - 0x1p-1000; }

static void cross_rule(const cm *c, int prec, span nn, span s[NCQ])
{
	const double u = prec_fmt(prec)->u, eta = fmax(prec_fmt(prec)->sub_step / 2, 0x1p-1074);
	const int to = c->cross_to - 1;
	const span A = nn, B = s[to ? CQ_N1 : CQ_N2], D = s[to ? CQ_D1N : CQ_D2N];
	const span zero = { 0.0, 0.0 };
	span *len = &s[to ? CQ_N2 : CQ_N1], *dn = &s[to ? CQ_D2N : CQ_D1N];
	double ab[4], ab_lo, ab_hi, nv2, g_lo, g_hi, n_hi, v_hi, R, c_hi;
	int i;
	if (!(isfinite(A.lo) && isfinite(A.hi) && isfinite(B.lo) && isfinite(B.hi) && isfinite(D.lo) && isfinite(D.hi)))
		return;
	if (A.lo <= -1.0 || B.lo <= -1.0)
		return;
	ab[0] = A.lo * B.lo; ab[1] = A.lo * B.hi; ab[2] = A.hi * B.lo; ab[3] = A.hi * B.hi;
	ab_lo = ab_hi = ab[0];
	for (i = 1; i < 4; i++) {
		ab_lo = fmin(ab_lo, ab[i]);
		ab_hi = fmax(ab_hi, ab[i]);
	}
	nv2 = hi_of(mag(D) * mag(D));
	g_lo = lo_of(lo_of(lo_of(A.lo + B.lo) + lo_of(ab_lo)) - nv2);
	g_hi = hi_of(hi_of(A.hi + B.hi) + hi_of(ab_hi));
	n_hi = hi_of(sqrt(hi_of(1.0 + A.hi)));
	v_hi = hi_of(sqrt(hi_of(1.0 + B.hi)));
	R = hi_of(hi_of(2.4142137 * u * n_hi) * v_hi) + 8 * eta;   /* (1 + u) sqrt 2 + 1 < 2.4142137 */
	c_hi = hi_of(sqrt(hi_of(1.0 + fmax(g_hi, -1.0))));
	if (c->cross_kind == 1) {   /* the output is q itself */
		span l;
		l.lo = lo_of(g_lo - hi_of(2.0 * R * c_hi));
		l.hi = hi_of(g_hi + hi_of(2.0 * R * c_hi) + hi_of(R * R));
		*len = meet(*len, l);
		*dn = meet(*dn, widen(zero, hi_of(R * n_hi)));
		s[CQ_D12] = meet(s[CQ_D12], widen(zero, hi_of(R * v_hi)));
	} else if (c->cross_kind == 2 && isfinite(len->hi) && g_lo > -1.0) {
		/* b = q K (1 + d) + eta: |q K| <= T = (|b| + sqrt(3) eta)/(1 - u),
		   K <= T / |q|, |q| >= sqrt(1 + g) - R; b.n = K r.n + K sum q_i
		   d_i n_i + eta.n, and b.v alike */
		const double ue = c->cross_u, et = 1.7320509 * c->cross_eta;
		const double b_hi = hi_of(sqrt(hi_of(1.0 + fmax(len->hi, -1.0))));
		const double T = hi_of(hi_of(b_hi + et) / (1.0 - ue));
		const double q_lo = lo_of(lo_of(sqrt(lo_of(1.0 + g_lo))) - R);
		double f;
		if (!(q_lo > 0.0))
			return;
		f = hi_of(hi_of(hi_of(hi_of(T / q_lo) * R) + hi_of(ue * T)) + et);
		*dn = meet(*dn, widen(zero, hi_of(f * n_hi)));
		s[CQ_D12] = meet(s[CQ_D12], widen(zero, hi_of(f * v_hi)));
	}
}

/* The orthogonality rule (mvf_orth_direct): b = q K (1 + d) + eta with
   q.n = 0 exactly gives |b.n| <= (u (|b| + sqrt(3) eta) / (1 - u) +
   sqrt(3) eta) |n|, |b| and |n| from their enclosures. */
static void orth_rule(cm *c, int which, span nn, span s[NCQ])
{
	const span zero = { 0.0, 0.0 };
	const span len = s[which ? CQ_N2 : CQ_N1];
	double u, eta, b_hi, n_hi, r;
	if (!mvf_orth_direct(c->m, which, &u, &eta) || !(isfinite(len.hi) && isfinite(nn.hi)))
		return;
	b_hi = hi_of(hi_of(sqrt(hi_of(1.0 + fmax(len.hi, -1.0)))) + 1.7320509 * eta);
	n_hi = hi_of(sqrt(hi_of(1.0 + fmax(nn.hi, -1.0))));
	r = hi_of(hi_of(hi_of(u * b_hi) / (1.0 - u)) + 1.7320509 * eta) * n_hi;
	s[which ? CQ_D2N : CQ_D1N] = meet(s[which ? CQ_D2N : CQ_D1N], widen(zero, hi_of(r)));
}

/* The signed enclosure s[k] of each quantity along one path (|b|^2 - 1
   for the lengths), and nn of |n|^2 - 1 over the box: each quantity in
   the intersection of its direct interval and its mean value form
   Q(U, 0) + [-1, 1] sum_k r_k max|dQ/de_k| (Q(U, 0) = 0 where the formula
   is exact on the unit sphere along the path).  Returns 0 when the path
   is infeasible for the box, else 1. */
static int path_spans(cm *c, const cm_method *m, const mvf_box *x, unsigned path, span s[NCQ], span *nn)
{
	cv q[NCQ];
	span direct[NCQ], centre[NCQ];
	double lin[NCQ], lin_e[NCQ];
	unsigned nonzero, zero_n, norm_n;
	int k, known = 0, r = run_path(c, m, x, path, MVF_FULL, q);
	if (r == 0)
		return 0;
	nn->lo = -INFINITY;
	nn->hi = INFINITY;
	if (r < 0) {
		values_spans(c, m, x, path, s);
		return 1;
	}
	for (k = 0; k < NCQ; k++) {
		mvf_bounds(c->m, q[k], &direct[k].lo, &direct[k].hi, &lin[k]);
		lin_e[k] = mvf_lin_arith(c->m, q[k]);
		if (!mvf_input_grad_ok(c->m))
			lin[k] = INFINITY;
	}
	mvf_norm_n(c->m, &nn->lo, &nn->hi);
	zero_n = (m->zero_any_n | c->zero_n) & ~c->nonzero;
	norm_n = c->norm_n & ~c->nonzero & ~zero_n;
	nonzero = c->nonzero;   /* n.z given: n is not unit at e = 0 */
	if (x->has_zpoint)
		nonzero |= CQ_ALL & ~m->zero_any_n;
	if (nonzero)
		known = centre_bounds(c, m, x, path, nonzero, centre);
	for (k = 0; k < NCQ; k++) {
		const span zero = { 0.0, 0.0 };
		span len;
		s[k] = direct[k];
		if ((k == CQ_N1 || k == CQ_N2) && mvf_len_direct(c->m, k - CQ_N1, &len.lo, &len.hi))
			s[k] = meet(s[k], len);
		if (!(nonzero & (1u << k)))
			s[k] = meet(s[k], widen(zero, lin[k]));
		else if (known)
			s[k] = meet(s[k], widen(centre[k], lin[k]));
		/* exact in n: Q(n, e) = Q(n, 0) + sum over the arithmetic's terms,
		   with Q(n, 0) = 0 or |n|^2 - 1 */
		if (c->zero_late & ~c->nonzero & (1u << k))
			s[k] = meet(s[k], widen(zero, mvf_lin_from(c->m, q[k], c->late_var)));
		if (zero_n & (1u << k))
			s[k] = meet(s[k], widen(zero, lin_e[k]));
		else if (norm_n & (1u << k))
			s[k] = meet(s[k], widen(*nn, lin_e[k]));
	}
	for (k = 0; k < 2; k++)
		orth_rule(c, k, *nn, s);
	if (c->cross_kind)
		cross_rule(c, x->prec, *nn, s);
	return 1;
}

/* The bound on the defect along one path (-1 when infeasible). */
static double path_bound(cm *c, const cm_method *m, const mvf_box *x, unsigned path)
{
	span s[NCQ], nn;
	double best = 0.0;
	int k;
	if (!path_spans(c, m, x, path, s, &nn))
		return -1.0;
	for (k = 0; k < NCQ; k++) {
		const double v = quantity_bound(k, s[k]);
		if (!(v <= best))
			best = v; /* NaN stays +inf below */
	}
	return isnan(best) ? INFINITY : best;
}

/* ---- frisvad_rotate: the direction error from its basis's defects ----
   The kernel forms b1, b2 (the model: Frisvad's formula without a
   threshold) and returns w_i = fl(fl(fl(x b1_i) + fl(y b2_i)) + fl(z n_i)),
   loc = (x, y, z) a rounding of a unit vector.  With M = [b1 b2 n] and
   G = M^T M, w = w* + e for w* = M loc, so
     |w*|^2 - 1 = loc^T (G - I) loc + (|loc|^2 - 1),
     w*.n - z   = x b1.n + y b2.n + z (|n|^2 - 1),
   where G - I holds the five defect quantities (|b|^2 - 1 signed) and
   |n|^2 - 1, each enclosed over the box; and, per component, with
   fl(v) = v (1 + d) + h (|d| <= u, |h| <= eta for a product, h = 0 for a
   sum), |e_i| <= (1 + u)^2 (u A_i + 3 eta) + u (1 + u) C_i + u |w*_i| with
   A_i = |x b1_i| + |y b2_i| + |z n_i| and C_i = |x b1_i + y b2_i|.  Then
   | |w| - 1 | <= | |w*| - 1 | + |e| and |w.n - z| <= |w*.n - z| + |e| |n|. */

/* v rounded up for the few roundings to nearest it took (each a relative
   2^-53 of a nonnegative partial result at most: far below 2^-45), with
   an absolute margin for underflow. */
/* 2^BOUND_MAXBRANCH paths at most */
#define BOUND_MAXBRANCH 8

static double up(double v) { return v * (1.0 + 0x1p-45) + 0x1p-1000; }

/* a + b + c with its roundings covered (signs mixed). */
static double sum3_up(double a, double b, double c)
{
	return a + b + c + 0x1p-51 * (fabs(a) + fabs(b) + fabs(c)) + 0x1p-1000;
}

/* Bounds on max over unit-ish loc of +-loc^T D loc / |loc|^2, D = G - I:
   the largest eigenvalue of D is at most both its Frobenius norm and the
   largest Gershgorin end (diagonal's upper end plus the row's other
   magnitudes); the smallest at least minus both. */
static void gram_eigs(const span *sp, span nn, double *qhi, double *qlo)
{
	const double d12 = mag(sp[CQ_D12]), d13 = mag(sp[CQ_D1N]), d23 = mag(sp[CQ_D2N]);
	const double d11 = mag(sp[CQ_N1]), d22 = mag(sp[CQ_N2]), d33 = mag(nn);
	const double f = up(sqrt(d11 * d11 + d22 * d22 + d33 * d33 + 2 * (d12 * d12 + d13 * d13 + d23 * d23)));
	double gu = sum3_up(sp[CQ_N1].hi, d12, d13), gl = sum3_up(-sp[CQ_N1].lo, d12, d13);
	gu = fmax(gu, fmax(sum3_up(sp[CQ_N2].hi, d12, d23), sum3_up(nn.hi, d13, d23)));
	gl = fmax(gl, fmax(sum3_up(-sp[CQ_N2].lo, d12, d23), sum3_up(-nn.lo, d13, d23)));
	*qhi = fmax(0.0, fmin(f, gu));
	*qlo = fmax(0.0, fmin(f, gl));
}

/* The bound on max(| |w| - 1 |, |w.n - z|) along one path of the model
   (special: the kernel's n.z = -1 case, w = (-y, -x, -z) exactly, where
   the model's b1.n = -n.y and b2.n = -n.x). */
static double dir_bound(const span *sp, span nn, int prec, int special, unsigned drop)
{
	const double u = prec_fmt(prec)->u;
	const double eta = fmax(prec_fmt(prec)->sub_step / 2, 0x1p-1074);   /* half the least subnormal, up */
	const double rho = up(u + 2 * eta);           /* | |loc| - 1 | <= rho */
	const double l1 = up(1.0 + rho), l2 = up(l1 * l1);
	double qhi, qlo, b1sq, b2sq, nsq, A, C, W, e, dn, dc;
	span w2;
	int k;
	for (k = 0; k < NCQ; k++)   /* fmax and fmin would drop a NaN */
		if (isnan(sp[k].lo) || isnan(sp[k].hi))
			return INFINITY;
	if (isnan(nn.lo) || isnan(nn.hi))
		return INFINITY;
	if (special)   /* |w| = |loc|; w.n - z = x b1.n + y b2.n */
		return fmax(rho, up(l1 * sqrt(mag(sp[CQ_D1N]) * mag(sp[CQ_D1N]) + mag(sp[CQ_D2N]) * mag(sp[CQ_D2N]))));
	gram_eigs(sp, nn, &qhi, &qlo);
	if (!(qhi < INFINITY && qlo < INFINITY && nn.hi < INFINITY))
		return INFINITY;
	w2.lo = -up(qlo * l2 + 2 * rho);
	w2.hi = up(qhi * l2 + up(2 * rho + rho * rho));
	b1sq = up(1.0 + fmax(sp[CQ_N1].hi, -1.0));
	b2sq = up(1.0 + fmax(sp[CQ_N2].hi, -1.0));
	nsq = up(1.0 + fmax(nn.hi, -1.0));
	A = up(l1 * sqrt(b1sq + b2sq + nsq));
	C = up(l1 * sqrt(fmax(b1sq, b2sq) + mag(sp[CQ_D12])));
	W = up(sqrt(1.0 + fmax(w2.hi, -1.0)));
	e = drop & BOUND_DROP_DOT ? 0.0 : up((1 + u) * (1 + u) * (u * A + 6 * eta) + u * (1 + u) * C + u * W);
	dn = up(norm_from_square(w2) + e);
	dc = up(l1 * sqrt(mag(sp[CQ_D1N]) * mag(sp[CQ_D1N]) + mag(sp[CQ_D2N]) * mag(sp[CQ_D2N]) + mag(nn) * mag(nn)) +
	        e * sqrt(nsq));
	return isnan(dn) || isnan(dc) ? INFINITY : fmax(dn, dc);
}

/* The model's control flow follows the path's bits alone (cm_branch
   returns them): a path that sets the bit of a branch point which the path
   without that bit never met takes every side that path took, and so runs
   the same operations to the same bound.  Returns that earlier path, or
   -1; seen[q]: the branch points that path q (q < path) met. */
static int same_as_earlier(unsigned path, const unsigned *seen)
{
	unsigned k;
	for (k = 0; (1u << k) <= path; k++)
		if ((path >> k & 1u) && !(seen[path ^ (1u << k)] & (1u << k)))
			return (int)(path ^ (1u << k));
	return -1;
}

double bound_box(bound_ctx *b, const cm_method *m, const mvf_box *x)
{
	return bound_box_ablate(b, m, x, 0);
}

void bound_set_arith(bound_ctx *b, const arith_profile *p)
{
	cm_set_arith(b->c, p);
	b->unb_op = -1;
}

int bound_unbounded_op(const bound_ctx *b) { return b->unb_op; }

int bound_box_cause(const bound_ctx *b) { return b->box_cause; }

/* Why the path just run has no finite bound (arith.h's causes). */
static int path_cause(cm *c)
{
	if (cm_unbounded_op(c) >= 0)
		return cm_unbounded_op(c);
	if (cm_lost_op(c) >= 0)
		return cm_lost_op(c);
	return mvf_overflowed(c->m) ? AR_NOPS | AR_OVERFLOW : AR_LOST;
}

int bound_overflow_seen(bound_ctx *b) { return mvf_overflow_seen(b->c->m); }

double bound_box_ablate(bound_ctx *b, const cm_method *m, const mvf_box *x, unsigned drop)
{
	unsigned path, npath = 1u << m->nbranch, seen[1u << BOUND_MAXBRANCH];
	double best = 0.0;
	if (m->nbranch > BOUND_MAXBRANCH)
		return INFINITY;   /* no model has so many (models.c checks) */
	b->box_cause = -1;
	if (m->direction && b->c->ar) {   /* dir_bound is proven for round to nearest */
		b->unb_op = b->box_cause = AR_NOPS;
		return INFINITY;
	}
	for (path = 0; path < npath; path++) {
		const int copy = same_as_earlier(path, seen);
		double v;
		if (copy >= 0) {
			seen[path] = seen[copy];   /* the same run */
			continue;
		}
		if (m->direction) {
			span sp[NCQ], nn;
			v = path_spans(b->c, m, x, path, sp, &nn) ? dir_bound(sp, nn, x->prec, path != 0, drop) : -1.0;
		} else {
			v = path_bound(b->c, m, x, path);
		}
		seen[path] = b->c->seen;
		if (b->unb_op < 0 && cm_unbounded_op(b->c) >= 0)
			b->unb_op = cm_unbounded_op(b->c);
		if (!(v < INFINITY) && b->box_cause < 0)
			b->box_cause = path_cause(b->c);
		if (!(v <= best))
			best = v;   /* an infeasible path gives -1 */
	}
	/* No feasible path: no input of the region lies in the box (every
	   comparison has a possible side on a nonempty interval, so only an
	   empty band makes every path infeasible). */
	return best;
}
