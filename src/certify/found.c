/*
 * found.c - the found side: the largest defect of the real kernel on
 * inputs of the region.
 *
 * Every input is screened first: the kernel runs on it and its five
 * defects are summed from exact products in double-double (error-free
 * transformations), a relative error far below 1e-20.  Only an input
 * whose screened defect reaches the largest found so far is measured
 * again by cert_probe, exactly as `onbstudy eval` measures it, and only
 * that measure is ever reported.  So the search can afford tens of
 * thousands of inputs per region at a fraction of a microsecond each.
 *
 * Where it looks: samples spread over the region (log-spaced in 1 -+ n.z
 * near the poles, the sector's edges and diagonals); ulp walks from random
 * inputs of the region and from the FOUND_TOP best inputs seen, each step
 * moving the two smaller components by a few ulps (at a random scale) and
 * completing the largest so that the input is the rounding of a unit
 * vector, or moving all three, or repeating the last step that paid;
 * every input whose two smaller components lie within 5 ulps of those of
 * the best inputs, with every domain value of the largest (each end of
 * its run in float); from search.c, the centres of the boxes the branch
 * and bound splits and inputs drawn in its worst leaves; and, once every
 * region has run, the images of every region's best inputs under the
 * signed permutations (found_images.c).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <mpfr.h>
#include "found.h"
#include "domain32.h"
#include "inputs/inputs.h"
#include "model/model.h"
#include "inputs/rng.h"


static uint64_t rnd(probe_env *e) { return rng_mix64(e->rng++); }
static double rnd01(probe_env *e) { return (double)(rnd(e) >> 11) * 0x1p-53; }

/* The screened defect of kernel output b (6 values) on input n. */
static double screen_defect(const double n[3], const double b[6])
{
	double d[5], m = 0.0;
	int i;
	d[0] = found_dot_dd(b, b, 1.0);
	d[1] = found_dot_dd(b + 3, b + 3, 1.0);
	d[0] = d[0] / (1.0 + sqrt(1.0 + d[0]));   /* |b| - 1 from |b|^2 - 1 */
	d[1] = d[1] / (1.0 + sqrt(1.0 + d[1]));
	d[2] = found_dot_dd(b, n, 0.0);
	d[3] = found_dot_dd(b + 3, n, 0.0);
	d[4] = found_dot_dd(b, b + 3, 0.0);
	for (i = 0; i < 5; i++)
		if (fabs(d[i]) > m)
			m = fabs(d[i]);
	return m;
}

/* Keep n among the best inputs seen (by screened defect, distinct). */
static void keep_top(probe_env *e, const double n[3], double d)
{
	int i, low = 0;
	for (i = 0; i < e->ntop; i++) {
		if (memcmp(e->top[i].n, n, 3 * sizeof *n) == 0)
			return;
		if (e->top[i].d < e->top[low].d)
			low = i;
	}
	if (e->ntop < FOUND_TOP)
		low = e->ntop++;
	else if (!(d > e->top[low].d))
		return;
	e->top[low].d = d;
	memcpy(e->top[low].n, n, 3 * sizeof *n);
}

double found_try(probe_env *e, const double n[3], int in_domain)
{
	static const double loc[3] = { 0.0, 0.0, 1.0 };
	sample_metrics s;
	double nn[3], d;
	int i;
	if (!cert_in_region(e->r, n))
		return -1.0;
	if (!in_domain) {
		int side = e->o->tolerance >= 0 ? 2 : e->prec == PREC_FLOAT ? cert_f32_side(n) : cert_f64_side(n);
		if (side == 2 ? !cert_in_domain(n, e->prec, e->o->tolerance) : side != 0)
			return -1.0;
	}
	if (e->k->rot) {   /* frisvad_rotate: the direction error, over loc too */
		d = found_dir_try(e, n);
		if (d >= 0.0)
			keep_top(e, n, d);
		return d;
	}
	e->res->probes++;
	ref_run_kernel(e->k, e->prec, n, loc, nn, &s);
	for (i = 0; i < 6; i++)
		if (!isfinite(s.out[i])) {
			e->res->nonfinite = 1;
			return -1.0;
		}
	d = screen_defect(nn, s.out);
	keep_top(e, n, d);
	if (found_worth_measuring(e, d)) {   /* measure it exactly */
		int nf = 0;
		double exact = cert_probe(e->x, e->k, e->prec, n, &nf);
		if (nf)
			e->res->nonfinite = 1;
		else if (exact > e->res->found) {
			e->res->found = exact;
			memcpy(e->res->found_n, n, sizeof e->res->found_n);
		}
	}
	return d;
}

/* cert_complete in float without MPFR, where double decides it: a^2 and
   b^2 are exact, 1 - (a^2 + b^2) in [1/4, 1) within 2^-52, its sqrt within
   2^-50 relative of the exact |c|; when that is at least 2^-48 relative
   from every midpoint of floats, the rounding is certain (and the same as
   cert_complete's).  NaN when double does not decide. */
static double complete_f32(double a, double b)
{
	const double s = 1.0 - (a * a + b * b), c = sqrt(s);
	double x, f;
	if (!(s > 0.25))
		return NAN;
	x = c * 0x1p25;   /* c in (1/2, 1]: the float midpoints are the odd integers */
	f = floor(x);
	if (fmod(f, 2.0) == 1.0 ? x - f < 0x1p-23 : f + 1.0 - x < 0x1p-23)
		return NAN;   /* too near a midpoint */
	return fmt_round(c, PREC_FLOAT);
}

/* The same in double, from double-double: s = 1 - a^2 - b^2 in [1/4, 1)
   to within 2^-104 relative (exact products, a compensated sum), c0 its
   square root in double, c1 = (s - c0^2) / (2 c0) the correction (s_hi -
   c0^2 exact by fma); the exact |c| rounds to c0 + k ulp with k the
   nearest integer to c1 / ulp, which is certain when c1 / ulp is at least
   2^-30 from every half-integer (the errors are below 2^-45 ulp). */
static double complete_f64(double a, double b)
{
	double s = 1.0, cc = 0.0, p, sh, sl, c0, c1, u, t;
	int k;
	p = a * a;
	found_acc(&s, &cc, -p);
	found_acc(&s, &cc, -fma(a, a, -p));
	p = b * b;
	found_acc(&s, &cc, -p);
	found_acc(&s, &cc, -fma(b, b, -p));
	sh = s + cc;
	sl = cc - (sh - s);
	if (!(sh > 0.25))
		return NAN;
	c0 = sqrt(sh);
	if (!(c0 > 0.5 + 0x1p-20))
		return NAN;
	c1 = (fma(-c0, c0, sh) + sl) / (2.0 * c0);
	u = 0x1p-53;   /* the grid of [1/2, 1], 1 included: |c| <= 1 */
	t = c1 / u;
	k = (int)floor(t + 0.5);
	if (fabs(t - (k - 0.5)) < 0x1p-30 || fabs(t - (k + 0.5)) < 0x1p-30 || abs(k) > 2)
		return NAN;
	return c0 + k * u;
}

double found_complete_fast(int prec, double a, double b)
{
	return prec == PREC_FLOAT ? complete_f32(a, b) : complete_f64(a, b);
}

/* n with its largest component (index b) completed; 1 when n is then
   surely a domain member, 0 when it must be asked, -1 when none exists. */
static int complete_n(probe_env *e, double n[3], int b)
{
	int sure;
	double c;
	if (e->o->tolerance >= 0)
		return 0;
	c = found_complete_fast(e->prec, n[(b + 1) % 3], n[(b + 2) % 3]);
	if (!isnan(c)) {
		n[b] = copysign(c, n[b]);   /* cheap: the walks complete every step */
		return 1;
	}
	c = cert_complete(e->x, e->prec, n[(b + 1) % 3], n[(b + 2) % 3], &sure);
	if (isnan(c))
		return -1;
	n[b] = copysign(c, n[b]);
	return sure;
}

/* Try an input near the unit vector at (z, phi): its two smaller
   components rounded to the format, the largest one the rounding of the
   exact value that makes the vector unit.  Then n is the rounding of a
   unit vector, and the largest component carries a rounding error spread
   over its whole half-ulp range, which sets | |n| - 1 |.  (Rounding all
   three from a double vector would leave n.z exact in double, and | |n| - 1 |
   near the poles far below its largest.)  In double the largest component
   would still land within a tiny part of an ulp of the double it came
   from, so one of the others is first moved by a random relative 2^-27 at
   most: the last component then moves by many of its ulps. */
static int make_ur(probe_env *e, double rr, double z, double phi, double n[3]);

static int make_u(probe_env *e, double z, double phi, double n[3])
{
	return make_ur(e, sqrt(fmax(0.0, (1.0 - z) * (1.0 + z))), z, phi, n);
}

/* The same with the distance rr = |(u.x, u.y)| from the z axis given
   (near a pole, where z = +-sqrt(1 - rr^2) is +-1 in double). */
static int make_ur(probe_env *e, double rr, double z, double phi, double n[3])
{
	int i, big = 0;
	n[0] = rr * cos(phi);
	n[1] = rr * sin(phi);
	n[2] = z;
	if (e->o->tolerance > 0) {   /* scale within the tolerance: both ends */
		double s = 1.0 + ((rnd(e) & 1) ? 1 : -1) * e->o->tolerance * 0.999;
		for (i = 0; i < 3; i++)
			n[i] *= s;
	}
	big = cert_biggest(n);
	if (e->prec == PREC_DOUBLE)   /* see above: spread the last component's rounding */
		n[(big + 1) % 3] *= 1.0 + (rnd01(e) - 0.5) * 0x1p-26;
	for (i = 0; i < 3; i++)
		n[i] = fmt_round(n[i], e->prec);   /* not (double)(float): GCC 12.2 -O2 drops it (inputs.c) */
	return complete_n(e, n, big);
}

void found_try_u(probe_env *e, double z, double phi)
{
	double n[3];
	found_try(e, n, make_u(e, z, phi, n) > 0);
}

#define DEG (3.14159265358979323846 / 180.0)

/* z at t in [0, 1] across the band: log-spaced in 1 + z (1 - z) near the
   poles, down to 1e-3 of the band's far end when the band holds the pole. */
static double sample_z(const cert_region *r, double t)
{
	double lo = r->nz_lo, hi = r->nz_hi, a, b;
	if (hi <= -0.9) {
		b = 1.0 + hi;
		a = 1.0 + lo > 0.0 ? 1.0 + lo : b * 1e-3;
		return -1.0 + a * pow(b / a, t);
	}
	if (lo >= 0.9) {
		b = 1.0 - lo;
		a = 1.0 - hi > 0.0 ? 1.0 - hi : b * 1e-3;
		return 1.0 - a * pow(b / a, t);
	}
	return lo + (hi - lo) * t;
}

int found_start_fits(const cert_start *s, const char *name, int prec)
{
	return (s->prec < 0 || s->prec == prec) && strcmp(s->method, name) == 0 &&
	       (prec == PREC_DOUBLE || (fmt_round(s->n[0], PREC_FLOAT) == s->n[0] &&
	                                fmt_round(s->n[1], PREC_FLOAT) == s->n[1] &&
	                                fmt_round(s->n[2], PREC_FLOAT) == s->n[2]));
}

/* The --starts inputs of this kernel and precision (found_try keeps those
   of the region). */
static void try_starts(probe_env *e)
{
	long i;
	for (i = 0; i < e->o->nstarts; i++) {
		const cert_start *s = &e->o->starts[i];
		if (found_start_fits(s, e->k->name, e->prec)) {
			found_try(e, s->n, 0);
			if (e->k->rot && s->has_loc)
				found_dir_start(e, s->n, s->loc);
		}
	}
}

/* Next to a pole the band's samples reach only 1 -+ z = 1e-3 of the
   band's width, rr = |(x, y)| about 1e-5 in float; the kernels' own
   pole thresholds lie below that (LuxCore's |(x, y)| < 1e-5: 168u in
   float just under it) and so do the underflows of x^2 + y^2 in float.
   So in a band that holds a pole, rr takes 4 values per decade from
   there down to 1e-24 (float) or 1e-40 (double: below that rr^2 is
   under the 2^-316 to which complete() decides the rounding of the
   largest component, and each input would need cert_in_domain at 4400
   bits), at the sector's axes, diagonals and middle. */
static void pole_samples(probe_env *e, double plo, double phi_w)
{
	const cert_region *r = e->r;
	const int south = r->nz_lo <= -1.0, north = r->nz_hi >= 1.0;
	const double floor_r = e->prec == PREC_FLOAT ? 1e-24 : 1e-40;
	double rr, d, b, n[3];
	if (!south && !north)
		return;
	b = south ? 1.0 + r->nz_hi : 1.0 - r->nz_lo;
	for (rr = sqrt(2e-3 * b); rr > floor_r; rr *= 0.5623413251903491) {   /* 10^-1/4 */
		const double z = south ? -1.0 : 1.0;
		for (d = ceil(r->phi_lo / 45.0) * 45.0; d < r->phi_hi; d += 45.0)
			found_try(e, n, make_ur(e, rr, z, d * DEG, n) > 0);
		found_try(e, n, make_ur(e, rr, z, plo + phi_w / 2, n) > 0);
		found_try(e, n, make_ur(e, rr * pow(10.0, -0.25 * rnd01(e)), z, plo + phi_w * rnd01(e), n) > 0);
	}
}

void found_sample(probe_env *e)
{
	const cert_region *r = e->r;
	const double plo = r->phi_lo * DEG, phi_w = (r->phi_hi - r->phi_lo) * DEG;
	long i;
	int j;
	double d;
	for (d = ceil(r->phi_lo / 45.0) * 45.0; d < r->phi_hi; d += 45.0)   /* diagonals and axes */
		for (j = 0; j <= 16; j++)
			found_try_u(e, sample_z(r, j / 16.0), d * DEG);
	found_try_u(e, r->nz_lo, plo + phi_w / 2);
	found_try_u(e, r->nz_hi, plo + phi_w / 2);
	for (i = 0; i < e->o->samples; i++)
		found_try_u(e, sample_z(r, rnd01(e)), plo + phi_w * rnd01(e));
	pole_samples(e, plo, phi_w);
	try_starts(e);
}

/* One proposal of a walk from n into m; k[] receives the ulp steps of the
   two smaller components (for a repeat).  Returns the domain knowledge as
   complete_n does (0 for a move of all three components). */
static int propose(probe_env *e, const double n[3], double m[3], int k[2], int fine)
{
	static const int scale[2][4] = { { 2, 8, 64, 256 }, { 1, 1, 2, 4 } };
	const int b = cert_biggest(n), s = scale[fine][rnd(e) & 3];
	const uint64_t h = rnd(e);
	int i, r;
	memcpy(m, n, 3 * sizeof *m);
	/* moves off the completion: the domain side of the result is decided
	   in double-double (cert_f32_side, cert_f64_side), cheaply in both
	   formats.  In double such an input is a member only where the two
	   smaller components' rounding cells can make up for the largest
	   one's ulp (near the diagonals), and the largest defects of
	   hughes_moeller lie on such inputs */
	if ((h & 7) == 0) {   /* all three by -2..2 ulps */
		for (i = 0; i < 3; i++)
			m[i] = fmt_step(m[i], (int64_t)((h >> (8 + 4 * i)) % 5) - 2, e->prec);
		return 0;
	}
	k[0] = (int)((h >> 8) % (uint64_t)(2 * s + 1)) - s;
	k[1] = (int)((h >> 24) % (uint64_t)(2 * s + 1)) - s;
	m[(b + 1) % 3] = fmt_step(m[(b + 1) % 3], k[0], e->prec);
	m[(b + 2) % 3] = fmt_step(m[(b + 2) % 3], k[1], e->prec);
	r = complete_n(e, m, b);
	if (r >= 0 && (h & 0x300000000000ull) == 0) {   /* a quarter: the largest one ulp off */
		m[b] = fmt_step(m[b], (h >> 50) & 1 ? 1 : -1, e->prec);
		return 0;
	}
	return r;
}

/* A hill climb from n (screened defect d) of at most `steps` steps,
   stopping after `stall` steps without a gain; a step that paid is
   repeated.  fine: steps of 1 to 4 ulps only. */
static void climb(probe_env *e, double n[3], double d, long steps, long stall, int fine)
{
	double m[3], v;
	long s, since = 0;
	int k[2] = { 0, 0 }, last[2] = { 0, 0 }, repeat = 0, known;
	for (s = 0; s < steps && since < stall; s++) {
		if (repeat) {   /* the same step once more */
			const int b = cert_biggest(n);
			memcpy(m, n, sizeof m);
			m[(b + 1) % 3] = fmt_step(m[(b + 1) % 3], last[0], e->prec);
			m[(b + 2) % 3] = fmt_step(m[(b + 2) % 3], last[1], e->prec);
			known = complete_n(e, m, b);
			k[0] = last[0];
			k[1] = last[1];
		} else {
			k[0] = k[1] = 0;
			known = propose(e, n, m, k, fine);
		}
		v = known < 0 ? -1.0 : found_try(e, m, known > 0);
		repeat = v > d && (k[0] || k[1]);
		if (v > d) {
			d = v;
			memcpy(n, m, sizeof m);
			last[0] = k[0];
			last[1] = k[1];
			since = 0;
		} else {
			since++;
		}
	}
}

/* Every input whose two smaller components are within `w` ulps of n's,
   the largest completed; in float also every other domain value of the
   largest (the ends of its run). */
static void neighbourhood(probe_env *e, const double n[3], int w)
{
	const int b = cert_biggest(n);
	int i, j;
	for (i = -w; i <= w; i++)
		for (j = -w; j <= w; j++) {
			double m[3], lo, hi;
			int known;
			memcpy(m, n, sizeof m);
			m[(b + 1) % 3] = fmt_step(m[(b + 1) % 3], i, e->prec);
			m[(b + 2) % 3] = fmt_step(m[(b + 2) % 3], j, e->prec);
			if ((known = complete_n(e, m, b)) < 0)
				continue;
			found_try(e, m, known > 0);
			if (e->prec == PREC_DOUBLE && e->o->tolerance < 0) {   /* the largest an ulp off */
				const double c = m[b];
				m[b] = fmt_step(c, 1, e->prec);
				found_try(e, m, 0);
				m[b] = fmt_step(c, -1, e->prec);
				found_try(e, m, 0);
			}
			if (e->prec == PREC_FLOAT && e->o->tolerance < 0 &&
			    cert_f32_run(m, b, signbit(m[b]) ? -1 : 1, &lo, &hi) > 1) {
				m[b] = copysign(lo, m[b]);
				found_try(e, m, 1);
				m[b] = copysign(hi, m[b]);
				found_try(e, m, 1);
			}
		}
}

/* A line search from n (screened defect d) along three directions of
   the two smaller components (both alike: radial from the largest's
   axis; each alone), by relative steps 1 +- 2^-k for k = 2..30, each
   repeated while it pays: a defect that grows up to a threshold of the
   kernel (LuxCore's |(x, y)| < 1e-5) is followed up to it, millions of
   ulps away, where the ulp walks cannot reach. */
static void line_search(probe_env *e, double n[3], double d)
{
	const int b = cert_biggest(n);
	int dir, sg, k, known, tries = 0;
	for (dir = 0; dir < 3; dir++)
		for (sg = -1; sg <= 1; sg += 2)
			for (k = 2; k <= 30 && tries < 400; k++) {
				const double f = 1.0 + sg * ldexp(1.0, -k);
				double m[3], v;
				memcpy(m, n, sizeof m);
				if (dir != 2)
					m[(b + 1) % 3] = fmt_round(m[(b + 1) % 3] * f, e->prec);
				if (dir != 1)
					m[(b + 2) % 3] = fmt_round(m[(b + 2) % 3] * f, e->prec);
				tries++;
				if ((known = complete_n(e, m, b)) < 0 || !((v = found_try(e, m, known > 0)) > d))
					continue;
				d = v;
				memcpy(n, m, sizeof m);
				k--;   /* the same step once more */
			}
}

/* The walks: from random inputs of the region (samples / 4 of them, at
   least 16; none unless `restarts`), then from each of the best inputs
   seen, then the neighbourhoods of the four best.  Below 1000 samples
   (--quick) every climb is shortened in proportion, to a quarter at most. */
void found_walks(probe_env *e, int restarts)
{
	const cert_region *r = e->r;
	const long starts = !restarts ? 0 : e->o->samples / 4 > 16 ? e->o->samples / 4 : 16;
	const double f = e->o->samples >= 1000 ? 1.0 : e->o->samples >= 250 ? e->o->samples / 1000.0 : 0.25;
	found_cand best[FOUND_TOP];
	long i;
	int nb, j;
	for (i = 0; i < starts; i++) {
		double n[3], d;
		const int known = make_u(e, sample_z(r, rnd01(e)), (r->phi_lo + (r->phi_hi - r->phi_lo) * rnd01(e)) * DEG, n);
		if (known >= 0 && (d = found_try(e, n, known > 0)) >= 0.0)
			climb(e, n, d, (long)(500 * f), (long)(400 * f), 0);
	}
	nb = e->ntop;
	memcpy(best, e->top, (size_t)nb * sizeof *best);
	for (j = 0; j < nb && (restarts || j < 4); j++)
		climb(e, best[j].n, best[j].d, (long)(800 * f), (long)(240 * f), 0);
	for (j = 0; j < (restarts ? 4 : 2) && j < e->ntop; j++) {
		int top = j, t;
		for (t = j + 1; t < e->ntop; t++)
			if (e->top[t].d > e->top[top].d)
				top = t;
		if (top != j) {
			found_cand tmp = e->top[j];
			e->top[j] = e->top[top];
			e->top[top] = tmp;
		}
		memcpy(best[0].n, e->top[j].n, sizeof best[0].n);
		line_search(e, best[0].n, e->top[j].d);
		neighbourhood(e, best[0].n, 5);
	}
	/* last, fine climbs from the best inputs now: 1 to 4 ulps a step */
	nb = e->ntop < 8 ? e->ntop : 8;
	memcpy(best, e->top, (size_t)nb * sizeof *best);
	for (j = 0; restarts && j < nb; j++)
		climb(e, best[j].n, best[j].d, (long)(300 * f), (long)(150 * f), 1);
	if (e->k->rot)
		found_dir_walk(e, (int)((restarts ? 200 : 400) * f));
}

static int by_d(const void *a, const void *b)
{
	const double x = ((const found_cand *)a)->d, y = ((const found_cand *)b)->d;
	return x > y ? -1 : x < y;
}

/* The best inputs seen into c, largest screened defect first; their count. */
static int sorted_top(const probe_env *e, found_cand c[FOUND_TOP])
{
	memcpy(c, e->top, (size_t)e->ntop * sizeof *c);
	qsort(c, (size_t)e->ntop, sizeof *c, by_d);
	return e->ntop;
}

void found_keep(probe_env *e)
{
	found_cand c[FOUND_TOP];
	const int nt = sorted_top(e, c);
	int i;
	e->res->nkeep = nt < CERT_KEEP ? nt : CERT_KEEP;
	for (i = 0; i < e->res->nkeep; i++)
		memcpy(e->res->keep_n[i], c[i].n, sizeof c[i].n);
}

void found_polish(probe_env *e, int nbest, double frac)
{
	found_cand c[FOUND_TOP];
	const int nt = sorted_top(e, c);
	int j;
	for (j = 0; j < nbest && j < nt && c[j].d >= frac * e->res->found; j++)
		climb(e, c[j].n, c[j].d, 300, 150, 1);
}
