/*
 * found_dir.c - the found side for frisvad_rotate, whose direction error
 * max(| |w| - 1 |, |w.n - z|) depends on the local direction
 * loc = (x, y, z) as well as on n.
 *
 * For each n tried, the locs where that error can be largest follow from
 * the basis the kernel forms on the way (onb_frisvad_threshold with no
 * threshold performs the same operations): w = M loc + e with M = [b1 b2 n],
 * so |w|^2 - 1 is about loc^T (G - I) loc (G = M^T M), largest along an
 * eigenvector of G - I, and w.n - z about loc . (b1.n, b2.n, |n|^2 - 1),
 * largest along that vector.  Those, with both signs, and a few fixed and
 * random directions are each made a rounding of a unit vector (the two
 * smaller components rounded, the largest completed: probe.c), run
 * through the real kernel and screened in double-double; the best is
 * measured as `onbstudy eval --local` measures it.  At the end, ulp walks
 * in loc from the best input move the roundings of the dot products.
 */
#include <math.h>
#include <string.h>
#include "found_dir.h"
#include "inputs/inputs.h"
#include "inputs/rng.h"


/* The kernel's basis on n (its special case n.z = -1: w = (-y, -x, -z),
   the basis (0, -1, 0), (-1, 0, 0)). */
static void rotate_basis(int prec, const double n[3], double b[6])
{
	if (n[2] == -1.0) {
		b[0] = 0.0; b[1] = -1.0; b[2] = 0.0;
		b[3] = -1.0; b[4] = 0.0; b[5] = 0.0;
	} else if (prec == PREC_FLOAT) {
		const onb_vec3f nf = { (float)n[0], (float)n[1], (float)n[2] };
		onb_vec3f b1, b2;
		onb_frisvad_thresholdf(nf, -INFINITY, &b1, &b2);
		b[0] = b1.x; b[1] = b1.y; b[2] = b1.z; b[3] = b2.x; b[4] = b2.y; b[5] = b2.z;
	} else {
		const onb_vec3 nd = { n[0], n[1], n[2] };
		onb_vec3 b1, b2;
		onb_frisvad_threshold(nd, -INFINITY, &b1, &b2);
		b[0] = b1.x; b[1] = b1.y; b[2] = b1.z; b[3] = b2.x; b[4] = b2.y; b[5] = b2.z;
	}
}

/* Eigenvectors of the symmetric 3x3 a (destroyed) into the columns of v,
   by Jacobi rotations: only candidates, so a few sweeps are plenty. */
static void eig3(double a[3][3], double v[3][3])
{
	int sweep, p, q, i;
	for (p = 0; p < 3; p++)
		for (q = 0; q < 3; q++)
			v[p][q] = p == q;
	for (sweep = 0; sweep < 8; sweep++)
		for (p = 0; p < 2; p++)
			for (q = p + 1; q < 3; q++) {
				double th, t, c, s;
				if (fabs(a[p][q]) <= 1e-300)
					continue;
				th = (a[q][q] - a[p][p]) / (2 * a[p][q]);
				t = (th >= 0 ? 1.0 : -1.0) / (fabs(th) + sqrt(th * th + 1));
				c = 1 / sqrt(t * t + 1);
				s = t * c;
				for (i = 0; i < 3; i++) {   /* a = a J, then J^T a */
					const double x = a[i][p], y = a[i][q];
					a[i][p] = c * x - s * y;
					a[i][q] = s * x + c * y;
				}
				for (i = 0; i < 3; i++) {
					const double x = a[p][i], y = a[q][i];
					a[p][i] = c * x - s * y;
					a[q][i] = s * x + c * y;
				}
				for (i = 0; i < 3; i++) {
					const double x = v[i][p], y = v[i][q];
					v[i][p] = c * x - s * y;
					v[i][q] = s * x + c * y;
				}
			}
}

/* The direction v made a loc of the domain: scaled to unit length, its
   two smaller components rounded, the largest completed (probe.c).
   Returns 0 when no such loc could be made. */
static int make_loc(probe_env *e, const double v[3], double loc[3])
{
	const double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
	int i, b, sure;
	double c;
	if (!(len > 0.0) || !isfinite(len))
		return 0;
	for (i = 0; i < 3; i++)
		loc[i] = v[i] / len;
	b = cert_biggest(loc);
	for (i = 0; i < 3; i++)
		if (i != b)
			loc[i] = fmt_round(loc[i], e->prec);
	c = cert_complete(e->x, e->prec, loc[(b + 1) % 3], loc[(b + 2) % 3], &sure);
	if (isnan(c))
		return 0;
	loc[b] = copysign(c, loc[b]);
	return sure || cert_in_domain(loc, e->prec, -1.0);
}

/* The screened direction error of the kernel on (n, loc); -1 and
   res->nonfinite set when its output is not finite. */
static double screen(probe_env *e, const double n[3], const double loc[3])
{
	double w[3], s2;
	e->res->probes++;
	if (e->prec == PREC_FLOAT) {
		const onb_vec3f nf = { (float)n[0], (float)n[1], (float)n[2] };
		const onb_vec3f r = e->k->rotf(nf, (float)loc[0], (float)loc[1], (float)loc[2]);
		w[0] = r.x; w[1] = r.y; w[2] = r.z;
	} else {
		const onb_vec3 nd = { n[0], n[1], n[2] };
		const onb_vec3 r = e->k->rot(nd, loc[0], loc[1], loc[2]);
		w[0] = r.x; w[1] = r.y; w[2] = r.z;
	}
	if (!isfinite(w[0]) || !isfinite(w[1]) || !isfinite(w[2])) {
		e->res->nonfinite = 1;
		return -1.0;
	}
	s2 = found_dot_dd(w, w, 1.0);
	return fmax(fabs(s2 / (1.0 + sqrt(1.0 + s2))), fabs(found_dot_dd(w, n, loc[2])));
}

/* (n, loc) measured exactly when its screened error d reaches found. */
static void measure(probe_env *e, const double n[3], const double loc[3], double d)
{
	sample_metrics m;
	double v;
	if (!found_worth_measuring(e, d))
		return;
	ref_eval(e->x->rc, e->k, e->prec, n, loc, 0, &m);
	if (m.nonfinite) {
		e->res->nonfinite = 1;
		return;
	}
	v = fmax(m.dir_norm, m.dir_cos);
	if (v > e->res->found) {
		e->res->found = v;
		memcpy(e->res->found_n, n, sizeof e->res->found_n);
		memcpy(e->res->found_loc, loc, sizeof e->res->found_loc);
	}
}

int found_dir_candidates(int prec, const double n[3], uint64_t *rng, double c[FOUND_DIR_CAND][3])
{
	double b[6], g[3][3], v[3][3];
	const double *col[3];
	int i, j, k = 0;
	rotate_basis(prec, n, b);
	col[0] = b; col[1] = b + 3; col[2] = n;
	for (i = 0; i < 3; i++)
		for (j = 0; j < 3; j++)
			g[i][j] = found_dot_dd(col[i], col[j], i == j ? 1.0 : 0.0);
	c[k][0] = g[0][2]; c[k][1] = g[1][2]; c[k][2] = g[2][2]; k++;   /* w.n - z */
	eig3(g, v);
	for (j = 0; j < 3; j++, k++)
		for (i = 0; i < 3; i++)
			c[k][i] = v[i][j];
	for (j = 0; j < 4; j++, k++)   /* the other sign */
		for (i = 0; i < 3; i++)
			c[k][i] = -c[k - 4][i];
	c[k][0] = 0.6; c[k][1] = 0.0; c[k][2] = 0.8; k++;   /* the sweep's loc */
	c[k][0] = 0.0; c[k][1] = 0.0; c[k][2] = 1.0; k++;
	for (j = 0; j < 2; j++, k++)
		for (i = 0; i < 3; i++)
			c[k][i] = (double)(rng_mix64((*rng)++) >> 11) * 0x1p-53 - 0.5;
	return k;
}

double found_dir_try(probe_env *e, const double n[3])
{
	double c[FOUND_DIR_CAND][3], loc[3], best_loc[3], d, best = -1.0;
	int i, j, nc = found_dir_candidates(e->prec, n, &e->rng, c);
	/* each candidate screened as three rounded components (cheap), the
	   best made a domain member (the completion, in MPFR) and screened
	   again: that one is what is kept and measured */
	for (i = 0; i < nc; i++) {
		const double len = sqrt(c[i][0] * c[i][0] + c[i][1] * c[i][1] + c[i][2] * c[i][2]);
		if (!(len > 0.0) || !isfinite(len))
			continue;
		for (j = 0; j < 3; j++)
			loc[j] = fmt_round(c[i][j] / len, e->prec);
		if ((d = screen(e, n, loc)) < 0.0)
			return -1.0;
		if (d > best) {
			best = d;
			memcpy(best_loc, c[i], sizeof best_loc);
		}
	}
	if (best < 0.0 || !make_loc(e, best_loc, loc) || (best = screen(e, n, loc)) < 0.0)
		return -1.0;
	measure(e, n, loc, best);
	return best;
}

/* An earlier run's worst (n, loc) (--starts): measured as it is, when n
   lies in the region and both in the domain. */
void found_dir_start(probe_env *e, const double n[3], const double loc[3])
{
	double d;
	if (!cert_in_region(e->r, n) || !cert_in_domain(n, e->prec, e->o->tolerance) ||
	    !cert_in_domain(loc, e->prec, -1.0) || (e->prec == PREC_FLOAT && (fmt_round(loc[0], PREC_FLOAT) != loc[0] ||
	    fmt_round(loc[1], PREC_FLOAT) != loc[1] || fmt_round(loc[2], PREC_FLOAT) != loc[2])))
		return;
	if ((d = screen(e, n, loc)) >= 0.0)
		measure(e, n, loc, d);
}

/* Ulp walks in loc from the found input: the two smaller components of
   loc moved by a few ulps at a random scale, the largest completed; a
   step that pays is kept.  This moves the roundings of w's dot products,
   which the candidate directions do not aim at. */
void found_dir_walk(probe_env *e, long steps)
{
	static const int scale[4] = { 1, 2, 8, 64 };
	double n[3], loc[3], d;
	long s;
	if (!(e->res->found > 0.0))
		return;
	memcpy(n, e->res->found_n, sizeof n);
	memcpy(loc, e->res->found_loc, sizeof loc);
	d = screen(e, n, loc);
	for (s = 0; s < steps && d >= 0.0; s++) {
		const int b = cert_biggest(loc), k = scale[rng_mix64(e->rng++) & 3];
		const uint64_t h = rng_mix64(e->rng++);
		double m[3], v;
		int sure;
		memcpy(m, loc, sizeof m);
		m[(b + 1) % 3] = fmt_step(m[(b + 1) % 3], (int64_t)(h % (uint64_t)(2 * k + 1)) - k, e->prec);
		m[(b + 2) % 3] = fmt_step(m[(b + 2) % 3], (int64_t)((h >> 20) % (uint64_t)(2 * k + 1)) - k, e->prec);
		v = cert_complete(e->x, e->prec, m[(b + 1) % 3], m[(b + 2) % 3], &sure);
		if (isnan(v))
			continue;
		m[b] = copysign(v, m[b]);
		if (!sure && !cert_in_domain(m, e->prec, -1.0))
			continue;
		if ((v = screen(e, n, m)) > d) {
			d = v;
			memcpy(loc, m, sizeof loc);
			measure(e, n, loc, d);
		}
	}
}
