/*
 * search.c - branch and bound over one region, with a search for the
 * largest defect beside it.
 *
 * The found side (found.c): inputs sampled in the region and ulp walks
 * from random inputs and from the best ones, before the branch and bound
 * (a good found value lets it stop early); then the centre of every box
 * it splits, inputs drawn in the 32 leaves with the largest bounds when
 * the bracket is still wide, and walks from the best inputs again.  The
 * bound side: the region's box of real
 * unit vectors, bounded by bound_box; the box with the largest bound is
 * split in two (in log(1 -+ z) near the poles, else in z or in the
 * azimuth, whichever is wider) until the largest bound is within target x
 * found, the budget of boxes runs out, or splitting stalls (STALL_BOXES).
 * The region's bound is the largest over the leaves: every real unit
 * vector of the box lies in some leaf.
 */
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <mpfr.h>
#include "search.h"
#include "emulate.h"
#include "inputs/inputs.h"
#include "model/model_int.h"
#include "found.h"
#include "inputs/rng.h"
#include "common/progress.h"

/* How wide a box is, in a measure that splits where the error varies:
   near the poles log2 of the ratio of 1 -+ z across it (a quarter per
   octave), elsewhere its width in z; and its arc length r dphi. */
static double z_measure(const mvf_box *b, double *mid)
{
	double a, c;
	if (b->z_hi <= -0.9 || b->z_lo >= 0.9) {
		const int south = b->z_hi <= -0.9;
		a = south ? 1.0 + b->z_lo : 1.0 - b->z_hi;
		c = south ? 1.0 + b->z_hi : 1.0 - b->z_lo;
		if (!(c > 0.0)) {
			*mid = NAN;
			return 0.0;
		}
		if (a <= 0.0) {   /* the box holds the pole: cut off all but c/16 */
			*mid = south ? -1.0 + c / 16 : 1.0 - c / 16;
			return 1.0;
		}
		*mid = south ? -1.0 + sqrt(a * c) : 1.0 - sqrt(a * c);
		return 0.25 * log2(c / a);
	}
	*mid = 0.5 * (b->z_lo + b->z_hi);
	return b->z_hi - b->z_lo;
}

/* The format values n.z can take over box b (the default domain): at
   most max of them into zs, or 0 when there are more (or none). */
static int zvalues(const mvf_box *b, double *zs, int max)
{
	const double u = b->prec == PREC_FLOAT ? 0x1p-24 : 0x1p-53;
	double lo = fmax(b->nz_lo, b->z_lo - u * fabs(b->z_lo) * 1.01);
	double hi = fmin(b->nz_hi, b->z_hi + u * fabs(b->z_hi) * 1.01), z;
	int n = 0;
	if (b->tolerance >= 0 || b->has_zpoint || !(lo <= hi))
		return 0;
	z = b->prec == PREC_FLOAT ? (double)nextafterf((float)lo, -INFINITY) : nextafter(lo, -INFINITY);
	for (; n <= max; z = b->prec == PREC_FLOAT ? (double)nextafterf((float)z, INFINITY) : nextafter(z, INFINITY)) {
		if (z < lo)
			continue;
		if (z > hi)
			break;
		if (n == max)
			return 0;
		zs[n++] = z;
	}
	return n;
}

/* The reals that round to the format value z (near a pole): z + [dlo, dhi]
   with dlo = -(gap below)/2, dhi = (gap above)/2, both exact doubles (the
   gaps are powers of two), cut to [-1, 1].  z + dlo itself is no double
   in double precision (a midpoint between two doubles): rounded to
   nearest it would tie to even, to z (an empty cell) or to the next double
   (a cell twice as wide), so the offsets are kept apart from z. */
static void rounding_cell(double z, int prec, double *dlo, double *dhi)
{
	double up = prec == PREC_FLOAT ? (double)nextafterf((float)z, INFINITY) : nextafter(z, INFINITY);
	double dn = prec == PREC_FLOAT ? (double)nextafterf((float)z, -INFINITY) : nextafter(z, -INFINITY);
	*dlo = fmax(-(z - dn) / 2, -1.0 - z);   /* -1 - z exact near -1 (Sterbenz) */
	*dhi = fmin((up - z) / 2, 1.0 - z);
}

/* Split a box with n.z given: in its offsets dz from n.z (exact), or in
   the azimuth, whichever is wider in units of the rounding cell of n.z and
   of 0.1 rad.  c[0] and c[1] hold copies of b on entry. */
static int split_cell(const mvf_box *b, mvf_box *c, double u)
{
	const double zw = (b->dz_hi - b->dz_lo) / (u * fmax(fabs(b->zpoint), 0x1p-126));
	const double pw = (b->phi_hi - b->phi_lo) / 0.1, dm = 0.5 * (b->dz_lo + b->dz_hi);
	if (zw >= pw && dm > b->dz_lo && dm < b->dz_hi) {
		c[0].dz_hi = c[1].dz_lo = dm;
		c[0].z_hi = c[1].z_lo = b->zpoint + dm;
		return 2;
	}
	if (b->phi_hi - b->phi_lo < 1e-12)
		return 0;
	c[0].phi_hi = c[1].phi_lo = 0.5 * (b->phi_lo + b->phi_hi);
	return c[0].phi_hi > b->phi_lo && c[0].phi_hi < b->phi_hi ? 2 : 0;
}

/* Split b: near the poles, once n.z can take at most 8 format values, into
   one box per value (n.z then exact, u.z the reals rounding to it); else in
   two along its wider measure.  Returns the number of children in c, 0
   when b is too small to split. */
static int split(const mvf_box *b, mvf_box *c)
{
	double zm, zs[8], zw = z_measure(b, &zm), zmin = fmin(fabs(b->z_lo), fabs(b->z_hi));
	double r = b->z_lo <= 0.0 && b->z_hi >= 0.0 ? 1.0 : sqrt(fmax(0.0, 1.0 - zmin * zmin));
	double pw = (b->phi_hi - b->phi_lo) * r;
	const double u = b->prec == PREC_FLOAT ? 0x1p-24 : 0x1p-53;
	/* only within 32 u of a pole, where n.z's own rounding is a large part
	   of 1 -+ n.z and the first-order form cannot follow it */
	int i, k = (1.0 + b->z_hi <= 32 * u || 1.0 - b->z_lo <= 32 * u) ? zvalues(b, zs, 8) : 0;
	for (i = 0; i < k; i++) {
		c[i] = *b;
		c[i].has_zpoint = 1;
		c[i].zpoint = zs[i];
		rounding_cell(zs[i], b->prec, &c[i].dz_lo, &c[i].dz_hi);
		c[i].z_lo = zs[i] + c[i].dz_lo;   /* the u.z that round to it (nearly) */
		c[i].z_hi = zs[i] + c[i].dz_hi;
	}
	if (k > 0)
		return k;
	c[0] = c[1] = *b;
	if (b->has_zpoint)   /* in units of the rounding cell of n.z, and of 0.1 rad */
		return split_cell(b, c, u);
	if (zw >= pw && !isnan(zm) && zm > b->z_lo && zm < b->z_hi) {
		c[0].z_hi = zm;
		c[1].z_lo = zm;
		return 2;
	}
	if (b->phi_hi - b->phi_lo < 1e-12)
		return 0;
	c[0].phi_hi = c[1].phi_lo = 0.5 * (b->phi_lo + b->phi_hi);
	return c[0].phi_hi > b->phi_lo && c[0].phi_hi < b->phi_hi ? 2 : 0;
}

typedef struct {
	mvf_box b;
	double bound;
	int stuck;   /* cannot be split further */
	int cause;   /* why bound is +inf (bound_box_cause), -1 */
} leaf;

/* The kernel at the box's centre, and at its two ends in u.z (where the
   input's own rounding is largest when n.z is a given value). */
static void probe_box(probe_env *e, const mvf_box *b)
{
	double zm, pm = 0.5 * (b->phi_lo + b->phi_hi);
	z_measure(b, &zm);
	if (isnan(zm))
		zm = 0.5 * (b->z_lo + b->z_hi);
	found_try_u(e, zm, pm);
	if (b->has_zpoint) {
		found_try_u(e, b->z_lo, pm);
		found_try_u(e, b->z_hi, pm);
	}
}

/* The found side guided by the bound: when the bracket is still wide,
   `per` inputs drawn in each of the `top` leaves with the largest bounds,
   where the first-order error terms say the defect can be largest. */
static void probe_worst_leaves(probe_env *e, leaf *l, int nl, int top, int per)
{
	int t, j;
	for (t = 0; t < top && t < nl; t++) {
		int i, imax = t;
		leaf tmp;
		for (i = t + 1; i < nl; i++)   /* selection: the next largest bound */
			if (l[i].bound > l[imax].bound)
				imax = i;
		tmp = l[t]; l[t] = l[imax]; l[imax] = tmp;
		for (j = 0; j < per; j++) {
			const mvf_box *b = &l[t].b;
			double z = b->z_lo + (b->z_hi - b->z_lo) * (double)(rng_mix64(e->rng++) >> 11) * 0x1p-53;
			found_try_u(e, z, b->phi_lo + (b->phi_hi - b->phi_lo) * (double)(rng_mix64(e->rng++) >> 11) * 0x1p-53);
		}
	}
}

/* The leaf with the largest bound among those that can still be split;
   *worst receives the largest bound of all. */
static int worst_leaf(const leaf *l, int nl, double *worst)
{
	int i, imax = -1;
	*worst = 0.0;
	for (i = 0; i < nl; i++) {
		if (!(l[i].bound <= *worst))
			*worst = l[i].bound;
		if (!l[i].stuck && (imax < 0 || !(l[i].bound <= l[imax].bound)))
			imax = i;
	}
	return imax;
}

/* The branch and bound stops early when the largest bound has fallen by
   less than 2% over the last STALL_BOXES boxes: the budget then goes to
   regions where splitting still pays (a bound set by the first-order
   worst case of single inputs, as at the n.z = 0 seam, does not move). */
#define STALL_BOXES 250
/* Where the bracket stays wide: inputs drawn in this many of the leaves
   with the largest bounds, samples / 16 + 8 in each. */
#define PROBE_LEAVES 32

/* cpu[0] gains the CPU time of bounding boxes, cpu[1] that of the probes. */
static void branch_and_bound(probe_env *e, const cm_method *m, const mvf_box *b0, double cpu[2])
{
	const long cap = e->o->budget + 8;
	leaf *l = malloc((size_t)cap * sizeof *l);
	int nl = 1, i;
	double worst = INFINITY, at_check = INFINITY;
	long next_check = STALL_BOXES;
	if (!l) {
		e->res->bound = INFINITY;
		return;
	}
	double t = study_thread_cpu(), t1;
	l[0].b = *b0;
	l[0].bound = bound_box(e->x->b, m, b0);
	l[0].cause = bound_box_cause(e->x->b);
	l[0].stuck = 0;
	e->res->boxes = 1;
	for (;;) {
		i = worst_leaf(l, nl, &worst);
		mvf_box c[8];
		double parent;
		int k, j, pcause;
		if (worst <= e->o->target * e->res->found || i < 0 || e->res->boxes + 8 > e->o->budget)
			break;
		if (!e->no_stall && e->res->boxes >= next_check) {   /* stalled: 250 more boxes took < 2% off */
			if (!(worst < 0.98 * at_check))
				break;
			at_check = worst;
			next_check += STALL_BOXES;
		}
		if (!(k = split(&l[i].b, c))) {
			l[i].stuck = 1;
			continue;
		}
		parent = l[i].bound;
		pcause = l[i].cause;
		for (j = 0; j < k; j++) {
			const int at = j == 0 ? i : nl++;
			const double v = bound_box(e->x->b, m, &c[j]);
			l[at].b = c[j];
			l[at].bound = v <= parent ? v : parent;   /* the parent's bound holds on its part too */
			l[at].cause = v <= parent ? bound_box_cause(e->x->b) : pcause;
			l[at].stuck = 0;
			t1 = study_thread_cpu();
			cpu[0] += t1 - t;
			probe_box(e, &c[j]);
			t = study_thread_cpu();
			cpu[1] += t - t1;
		}
		e->res->boxes += k;
	}
	e->res->bound = worst;
	if (!(worst < INFINITY) && !arith_is_ieee(e->o->arith))   /* why: the first leaf without a bound */
		for (i = 0; i < nl; i++)
			if (!(l[i].bound < INFINITY)) {
				e->res->unb_op = l[i].cause;
				break;
			}
	t1 = study_thread_cpu();
	cpu[0] += t1 - t;
	if (!(worst <= e->o->target * e->res->found))
		probe_worst_leaves(e, l, nl, PROBE_LEAVES, e->o->samples / 16 + 8);
	cpu[1] += study_thread_cpu() - t1;
	if (e->o->leaf_fn)
		for (i = 0; i < nl; i++)
			e->o->leaf_fn(e->o->leaf_arg, &l[i].b, l[i].bound);
	if (getenv("ONB_CERT_DEBUG"))
		for (nl--; nl >= 0; nl--)
			if (l[nl].bound >= worst)
				fprintf(stderr, "worst leaf: z [%.17g, %.17g] phi [%.9g, %.9g] zpoint %d %a: %g\n", l[nl].b.z_lo,
				        l[nl].b.z_hi, l[nl].b.phi_lo, l[nl].b.phi_hi, l[nl].b.has_zpoint, l[nl].b.zpoint, l[nl].bound);
	free(l);
}

/* The found side's random stream: from the seed and the region alone,
   so a region draws the same inputs in any thread and any run. */
static uint64_t region_seed(uint64_t seed, const cert_region *r)
{
	const double v[4] = { r->nz_lo, r->nz_hi, r->phi_lo, r->phi_hi };
	uint64_t h = rng_mix64(seed), b;
	int i;
	for (i = 0; i < 4; i++) {
		memcpy(&b, &v[i], sizeof b);
		h = rng_mix64(h ^ b);
	}
	return h;
}

/* --arith: the adversarial emulation (emulate.h) at the region's best
   inputs; found rises to its worst (a conforming implementation's defect
   on an input of the region). */
static void arith_found(probe_env *e, const cm_method *m)
{
	unsigned char ch[CM_EMU_MAXOP];
	emu_eval ev;
	int i;
	if (arith_is_ieee(e->o->arith) || m->direction)
		return;
	for (i = 0; i < e->res->nkeep && i < 4; i++) {
		emu_adversarial(e->x->emu, e->x->rc, m, e->prec, e->res->keep_n[i], e->o->arith, 1, ch, &ev);
		if (isfinite(ev.defect) && ev.defect > e->res->found) {
			e->res->found = ev.defect;
			memcpy(e->res->found_n, e->res->keep_n[i], sizeof e->res->found_n);
		}
	}
}

void cert_region_run(cert_ctx *x, const study_kernel *k, const cm_method *m, int prec,
                     const cert_region *r, const cert_opts *o, cert_result *res)
{
	probe_env e;
	mvf_box b;
	memset(res, 0, sizeof *res);
	memset(&e, 0, sizeof e);
	res->unb_op = -1;
	bound_set_arith(x->b, o->arith);
	e.x = x; e.k = k; e.prec = prec; e.r = r; e.o = o; e.res = res;
	double t = study_thread_cpu(), t1;
	e.rng = region_seed(o->seed, r);
	found_sample(&e);
	t1 = study_thread_cpu();
	res->cpu[CERT_T_SAMPLE] = t1 - t;
	found_walks(&e, 1);
	found_keep(&e);
	res->cpu[CERT_T_WALKS] = study_thread_cpu() - t1;
	arith_found(&e, m);
	if (region_meets_singular(k, r) || res->nonfinite) {
		res->status = CERT_SINGULAR;
		res->bound = INFINITY;
		return;
	}
	region_box(r, prec, o->tolerance, &b);
	branch_and_bound(&e, m, &b, &res->cpu[CERT_T_BOXES]);
	t = study_thread_cpu();
	found_walks(&e, 0);
	found_keep(&e);
	res->cpu[CERT_T_WALKS] += study_thread_cpu() - t;
	arith_found(&e, m);
	res->status = res->bound <= o->target * res->found ? CERT_PROVEN : CERT_BUDGET;
	if (res->nonfinite) {
		res->status = CERT_SINGULAR;
		res->bound = INFINITY;
	} else if (!(res->bound < INFINITY) && bound_unbounded_op(x->b) >= 0) {
		res->unb_op = bound_unbounded_op(x->b);
		res->status = CERT_UNBOUNDED;
	}
	/* else a bound of +inf keeps in unb_op why (--arith: branch_and_bound) */
}

void cert_region_images(cert_ctx *x, const study_kernel *k, int prec, const cert_region *r, const cert_opts *o,
                        const cert_pool_in *pool, long np, cert_result *res)
{
	probe_env e;
	const double t = study_thread_cpu();
	memset(&e, 0, sizeof e);
	e.x = x; e.k = k; e.prec = prec; e.r = r; e.o = o; e.res = res;
	e.rng = region_seed(o->seed ^ UINT64_C(0x696d61676573), r);   /* "images" */
	found_images(&e, pool, np);
	res->cpu[CERT_T_IMAGES] += study_thread_cpu() - t;
	if (res->nonfinite) {
		res->status = CERT_SINGULAR;
		res->bound = INFINITY;
	} else if (res->status != CERT_SINGULAR && res->status != CERT_UNBOUNDED) {
		res->status = res->bound <= o->target * res->found ? CERT_PROVEN : CERT_BUDGET;
	}
}

/* A second branch and bound of a region cert_region_run left at its
   budget, without the stall stop.  A region whose leaves share one bound
   stalls by the rule (splitting one leaf of a plateau takes nothing off the
   largest) though splitting them all would: rtow float over n.z in
   [0.6, 0.9] goes from 11.4u to 9.8u.  The bound kept is the smaller of
   the two runs' (both hold); found can only rise (the boxes' probes). */
void cert_region_refine(cert_ctx *x, const study_kernel *k, const cm_method *m, int prec,
                        const cert_region *r, const cert_opts *o, cert_result *res)
{
	const double old = res->bound;
	const long boxes = res->boxes;
	probe_env e;
	mvf_box b;
	double cpu[2] = { 0.0, 0.0 };
	if (res->status != CERT_BUDGET)
		return;
	bound_set_arith(x->b, o->arith);
	memset(&e, 0, sizeof e);
	e.x = x; e.k = k; e.prec = prec; e.r = r; e.o = o; e.res = res;
	e.rng = region_seed(o->seed ^ UINT64_C(0x726566696e65), r);   /* "refine": other draws */
	e.no_stall = 1;
	region_box(r, prec, o->tolerance, &b);
	branch_and_bound(&e, m, &b, cpu);
	res->cpu[CERT_T_REFINE] += cpu[0] + cpu[1];
	if (!(res->bound <= old))
		res->bound = old;
	res->boxes += boxes;
	res->status = res->bound <= o->target * res->found ? CERT_PROVEN : CERT_BUDGET;
	if (res->nonfinite) {
		res->status = CERT_SINGULAR;
		res->bound = INFINITY;
	}
}
