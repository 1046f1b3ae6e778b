/*
 * enumerate.c - every float input of the default domain in a small box,
 * and each method's largest defect over them (enumerate.h).
 *
 * The domain side.  A float v is the rounding of the reals whose magnitude
 * lies between |v| - down/2 and |v| + up/2 (down, up: the gaps to the next
 * floats towards and away from 0; down = 0 for a zero).  cert_in_domain
 * takes n as a member when the box of those reals holds a point of
 * |u| = 1 inside: sum of the squared low ends < 1 < sum of the squared high
 * ends.  Both sums grow with |n[axis]|, so along a ray of one component the
 * side goes -1, 0, +1, and the members are one run of consecutive floats.
 * In double the ends (at most 26 significant bits, above 2^-151) and their
 * squares are exact, and each sum of three squares below 4.1 is within
 * 2^-48 of exact; cert_f32_side decides from those sums unless one is
 * within 2^-46 of 1, and then asks cert_in_domain.  Near 1 the two sums
 * are at least 2^-26 apart (some component is above 0.57, its gaps above
 * 2^-25), so at most one of them is that close to 1 and a non-member's
 * side is the side of that one.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "enumerate.h"
#include "region.h"
#include "model/model.h"
#include "common/options.h"
#include "inputs/inputs.h"

/* Two fixed ranges of 21 floats about a centre (7 for -x itself). */
static const cert_box boxes[] = {
	{ "south_frisvad", "n.z = -0x1.fffffcp-1 = frisvad's float threshold (-0.9999999f), taken by the general "
	  "formula; its centre is frisvad's worst float input in results/reference/worst.csv",
	  2, { 0x1.908aaap-12, -0x1.967164p-12, 0.0 }, 10, -1.0, 0.0 },
	{ "south_frisvad_below", "n.z = -0x1.fffffep-1, the float below frisvad's threshold: its special branch",
	  2, { 0x1.6a09e6p-13, -0x1.3988ep-12, 0.0 }, 10, -1.0, 0.0 },
	{ "frisvad_max_t", "n.z = -0x1.fffe6cp-1 = frisvad_max's float threshold (-0.99998796f), general formula",
	  2, { -0x1.ecb654p-9, -0x1.9d6f44p-9, 0.0 }, 10, -1.0, 0.0 },
	{ "south_band", "1 + n.z ~ 2^-21, inside the band where frisvad's error is large",
	  2, { 0x1.8p-11, -0x1.52a9p-11, 0.0 }, 10, -1.0, 0.0 },
	{ "north", "1 - n.z ~ 3 * 2^-24, near +z", 2, { 0x1.3p-11, -0x1.1p-12, 0.0 }, 10, 0.0, 1.0 },
	{ "hm_x_eq_z", "|n.x| = |n.z| -+ 10 floats (hughes_moeller's branch), n.y ~ 0.3",
	  1, { 0x1.595ce6p-1, 0.0, 0x1.595ce6p-1 }, 10, 0.0, 1.0 },
	{ "seam_z0", "n.z within 10 subnormal steps of 0, both zeros (duff's copysign seam), n.x ~ 0.6",
	  1, { 0x1.333334p-1, 0.0, 0.0 }, 10, 0.0, 1.0 },
	{ "minus_x", "n.x ~ -1 approached (naive's singular direction), n.y ~ 2^-12, n.z ~ -2^-13",
	  0, { 0.0, 0x1.1p-12, -0x1.3p-13 }, 10, -1.0, 0.0 },
	{ "minus_x_axis", "n = -x itself and its neighbours: n.y, n.z within 3 subnormal steps of 0, both zeros",
	  0, { 0.0, 0.0, 0.0 }, 3, -1.0, 0.0 },
};

const cert_box *cert_boxes(int *count)
{
	*count = (int)(sizeof boxes / sizeof boxes[0]);
	return boxes;
}

#define SIDE_TOL 0x1p-46

int cert_f32_side(const double n[3])
{
	double lo = 0.0, hi = 0.0;
	int i;
	for (i = 0; i < 3; i++) {
		const double a = fabs(n[i]);
		float f;
		double up, down;
		if (!isfinite(n[i]) || fmt_round(n[i], PREC_FLOAT) != n[i])
			return 2;
		if (!(a < 2.0))
			return 1;   /* every low end is above 1.99 */
		f = (float)a;
		up = (double)nextafterf(f, INFINITY) - a;
		down = a > 0.0 ? a - (double)nextafterf(f, 0.0f) : 0.0;
		lo += (a - down / 2) * (a - down / 2);
		hi += (a + up / 2) * (a + up / 2);
	}
	if (lo - 1.0 > SIDE_TOL)
		return 1;
	if (hi - 1.0 < -SIDE_TOL)
		return -1;
	if (lo - 1.0 < -SIDE_TOL && hi - 1.0 > SIDE_TOL)
		return 0;
	if (cert_in_domain(n, PREC_FLOAT, -1.0))
		return 0;
	if (fabs(lo - 1.0) <= SIDE_TOL && fabs(hi - 1.0) <= SIDE_TOL)
		return 2;
	return fabs(lo - 1.0) <= SIDE_TOL ? 1 : -1;
}

/* The float of ordinal k >= 0 (its bits), with the sign of sign. */
static double fval(int64_t k, int sign)
{
	const uint32_t b = (uint32_t)k;
	float f;
	memcpy(&f, &b, 4);
	return sign < 0 ? -(double)f : (double)f;
}

/* 1 when n with n[axis] = fval(k, sign) is on side >= want; -1: no side. */
static int at_least(const double n[3], int axis, int sign, int64_t k, int want)
{
	double v[3];
	int s;
	memcpy(v, n, sizeof v);
	v[axis] = fval(k, sign);
	s = cert_f32_side(v);
	return s == 2 ? -1 : s >= want;
}

#define KMAX ((int64_t)0x7f7fffff) /* the ordinal of FLT_MAX */

/* The first k in [0, KMAX] with at_least (KMAX + 1 if none), -1 when a
   side could not be told: galloping from k0, then bisection.  Invariant:
   at_least fails at a (or a = -1), holds at b (or b = KMAX + 1). */
static int64_t first_at_least(const double n[3], int axis, int sign, int64_t k0, int want)
{
	int64_t a, b, step = 1;
	int t = at_least(n, axis, sign, k0, want);
	if (t < 0)
		return -1;
	if (t) {
		for (b = k0;; b = a, step *= 2) {
			if (step > b) {
				a = -1;
				break;
			}
			a = b - step;
			if ((t = at_least(n, axis, sign, a, want)) < 0)
				return -1;
			if (!t)
				break;
		}
	} else {
		for (a = k0;; a = b, step *= 2) {
			if (step > KMAX - a) {
				b = KMAX + 1;
				break;
			}
			b = a + step;
			if ((t = at_least(n, axis, sign, b, want)) < 0)
				return -1;
			if (t)
				break;
		}
	}
	while (b - a > 1) {
		const int64_t mid = a + (b - a) / 2;
		if ((t = at_least(n, axis, sign, mid, want)) < 0)
			return -1;
		if (t)
			b = mid;
		else
			a = mid;
	}
	return b;
}

long long cert_f32_run(const double n[3], int axis, int sign, double *lo, double *hi)
{
	double q = 1.0, v[3];
	float g;
	uint32_t bits;
	int64_t l, h;
	int i;
	for (i = 0; i < 3; i++)
		if (i != axis)
			q -= n[i] * n[i];
	g = (float)sqrt(fmax(0.0, q));   /* a start near the run */
	memcpy(&bits, &g, 4);
	if ((l = first_at_least(n, axis, sign, (int64_t)bits, 0)) < 0)
		goto fail;
	memcpy(v, n, sizeof v);
	v[axis] = fval(l, sign);
	if (l > KMAX || cert_f32_side(v) != 0)
		return 0;
	if ((h = first_at_least(n, axis, sign, l, 1)) < 0)
		goto fail;
	*lo = fval(l, sign);
	*hi = fval(h - 1, sign);
	return (long long)(h - l);
fail:
	study_error("enumerate: the domain side of (%a, %a, %a) along axis %d could not be told", n[0], n[1], n[2],
	            axis);
	return -1;
}

typedef struct {
	double *v;
	long long n, cap;
} in_list;

static int push(in_list *l, const double n[3])
{
	if (l->n >= CERT_ENUM_MAX) {
		study_error("enumerate: more than %lld inputs in a box", CERT_ENUM_MAX);
		return -1;
	}
	if (l->n == l->cap) {
		const long long cap = l->cap ? 2 * l->cap : 4096;
		double *v = realloc(l->v, (size_t)cap * 3 * sizeof *v);
		if (!v) {
			study_error("enumerate: out of memory");
			return -1;
		}
		l->v = v;
		l->cap = cap;
	}
	memcpy(&l->v[3 * l->n++], n, 3 * sizeof *n);
	return 0;
}

/* 1 when n with n[ax] = x is a member (cert_in_domain, the exact test). */
static int member(const double n[3], int ax, double x)
{
	double v[3];
	memcpy(v, n, sizeof v);
	v[ax] = x;
	return cert_in_domain(v, PREC_FLOAT, -1.0);
}

/* n with its two fixed components set: every domain value of the third,
   each confirmed by cert_in_domain, and so is the non-member either side
   of each run (beyond the zero a run of that sign ends anyway). */
static int complete(const cert_box *bx, double n[3], in_list *l)
{
	const int ax = bx->axis;
	int sign;
	for (sign = -1; sign <= 1; sign += 2) {
		double lo, hi, x;
		long long len = cert_f32_run(n, ax, sign, &lo, &hi), k;
		if (len < 0)
			return -1;
		if (len == 0)
			continue;
		if ((lo != 0.0 && member(n, ax, nextafterf((float)lo, 0.0f))) ||
		    member(n, ax, nextafterf((float)hi, (float)(sign * INFINITY)))) {
			study_error("enumerate: a run of axis %d at (%a, %a, %a) does not end where cert_in_domain does",
			            ax, n[0], n[1], n[2]);
			return -1;
		}
		for (k = 0, x = lo; k < len; k++, x = nextafterf((float)x, (float)(sign * INFINITY))) {
			if (!member(n, ax, x)) {
				study_error("enumerate: cert_in_domain rejects %a on axis %d of a run", x, ax);
				return -1;
			}
			n[ax] = x;
			if (x >= bx->lo && x <= bx->hi && push(l, n))
				return -1;
		}
	}
	return 0;
}

/* The float o floats from c (c a float); at the zero, -0 when z. */
static double from(double c, int o, int z)
{
	const double v = fmt_step(c, o, PREC_FLOAT);
	return v == 0.0 && z ? -0.0 : v;
}

long long cert_box_inputs(const cert_box *b, double **out)
{
	const int a = (b->axis + 1) % 3, c = (b->axis + 2) % 3;
	in_list l = { NULL, 0, 0 };
	int i, j, za, zc;
	double n[3];
	*out = NULL;
	for (i = -b->half; i <= b->half; i++)
		for (za = 0; za <= (from(b->c[a], i, 0) == 0.0); za++)
			for (j = -b->half; j <= b->half; j++)
				for (zc = 0; zc <= (from(b->c[c], j, 0) == 0.0); zc++) {
					n[a] = from(b->c[a], i, za);
					n[c] = from(b->c[c], j, zc);
					n[b->axis] = 0.0;
					if (complete(b, n, &l)) {
						free(l.v);
						return -1;
					}
				}
	*out = l.v;
	return l.n;
}

int cert_inputs_region(const double *in, long long count, cert_region *r)
{
	long long i;
	r->nz_lo = r->phi_lo = INFINITY;
	r->nz_hi = r->phi_hi = -INFINITY;
	for (i = 0; i < count; i++) {
		const double *n = &in[3 * i], p = cert_phi_deg(n[0], n[1]);
		r->nz_lo = fmin(r->nz_lo, n[2]);
		r->nz_hi = fmax(r->nz_hi, n[2]);
		r->phi_lo = fmin(r->phi_lo, p);
		r->phi_hi = fmax(r->phi_hi, p);
	}
	if (count <= 0 || (r->phi_lo < 90.0 && r->phi_hi > 270.0))
		return -1;
	r->phi_hi = fmin(360.0, nextafter(r->phi_hi, INFINITY));
	return 0;
}

int cert_enumerate(cert_ctx *x, const study_kernel *k, const double *in, long long count, double *d,
                   cert_enum *out)
{
	long long i;
	memset(out, 0, sizeof *out);
	out->max = -1.0;
	if (!kernel_runs(k, PREC_FLOAT)) {
		study_error("enumerate: %s has no float code", k->name);
		return -1;
	}
	for (i = 0; i < count; i++) {
		const double *n = &in[3 * i];
		int nf = 0;
		const double e = cert_probe(x, k, PREC_FLOAT, n, &nf);
		out->inputs++;
		if (d)
			d[i] = nf ? INFINITY : e;
		if (nf)
			out->nonfinite++;
		else if (e > out->max) {
			out->max = e;
			memcpy(out->n, n, sizeof out->n);
		}
	}
	return 0;
}
