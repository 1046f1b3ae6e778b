/*
 * enumerate.c - every float input of the default domain in a small box,
 * and each method's largest defect over them (enumerate.h).  Which side
 * of the domain an input lies on, and the runs of its members along an
 * axis, are domain32.c's.
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
