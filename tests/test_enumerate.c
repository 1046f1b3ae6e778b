/*
 * test_enumerate.c - no certified bound below a defect measured on every
 * float input of a small box.
 *
 * For each box of cert_boxes (src/certify/enumerate.c: near -z on
 * frisvad's float threshold, the float below it, frisvad_max's threshold
 * and inside the band where frisvad fails, near +z,
 * on hughes_moeller's |x| = |z|, at the n.z = 0 seam, near -x and at -x):
 *   - every float input of the default domain in the box, each confirmed
 *     by cert_in_domain (and each run's first non-member either side);
 *   - the region the box spans (its n.z range and azimuth range);
 *   - per method with a model whose singular set that region does not
 *     meet: the largest defect over the box's inputs (cert_probe, as
 *     `onbstudy eval` measures it), and certify's bracket for the region
 *     (cert_region_run: 120 boxes, 100 samples, target 1.25).  FAIL when the bound is below the
 *     box's maximum (a plain comparison of doubles: no slack), when the
 *     box gives a non-finite output and certify does not call the region
 *     singular, or when certify's found value is not what the box measured
 *     on the same input (found inputs outside the box, in the corners of
 *     the region, are measured again instead).
 * Also: cert_f32_side and cert_f64_side agree with cert_in_domain on
 * rounded unit vectors and their neighbours.  Prints per box and method: inputs, box maximum,
 * bound, bound / maximum, found.  The rsqrt and invsqrt variants need the
 * seed bounds (an exhaustive scan of ~20 s, seeds.h): only with --seeds.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "methods/kernels.h"
#include "inputs/inputs.h"
#include "certify/enumerate.h"
#include "certify/search.h"
#include "certify/models.h"
#include "model/model.h"
#include "certify/regions.h"
#include "inputs/rng.h"

#define MAXK 256

static double unif(uint64_t i, int k) { return (double)(rng_mix64(i * 4 + (uint64_t)k) >> 11) * 0x1p-53; }

/* The fast side test against the exact one: float roundings of unit
   vectors (uniform, and within 1e-6 of either pole), each component then
   moved by -1, 0 or +1 float; and inputs on which it falls back. */
static void side_crosscheck(long count)
{
	long i, in = 0, bad = 0;
	for (i = 0; i < count; i++) {
		double z = 2.0 * unif((uint64_t)i, 0) - 1.0, phi = 6.283185307179586 * unif((uint64_t)i, 1), n[3], r;
		int j, s;
		if (i % 3 == 1)
			z = -1.0 + 1e-6 * unif((uint64_t)i, 2);
		else if (i % 3 == 2)
			z = 1.0 - 1e-6 * unif((uint64_t)i, 2);
		r = sqrt((1.0 - z) * (1.0 + z));
		n[0] = r * cos(phi);
		n[1] = r * sin(phi);
		n[2] = z;
		for (j = 0; j < 3; j++)
			n[j] = fmt_step(fmt_round(n[j], PREC_FLOAT), (int64_t)(rng_mix64((uint64_t)i * 3 + (uint64_t)j) % 3) - 1,
			                PREC_FLOAT);
		s = cert_f32_side(n);
		in += s == 0;
		if ((s == 0) != cert_in_domain(n, PREC_FLOAT, -1.0) || s == 2)
			bad++;
	}
	/* n = (1, y, 0), y within 64 floats of 2^-12, and its rotations: the
	   sum of the squared low ends is within 2^-46 of 1 at y = 2^-12, where
	   cert_f32_side asks cert_in_domain */
	for (i = -64; i <= 64; i++) {
		int a;
		for (a = 0; a < 3; a++) {
			double n[3] = { 0.0, 0.0, 0.0 };
			int s;
			n[a] = a == 1 ? -1.0 : 1.0;
			n[(a + 1) % 3] = fmt_step(0x1p-12, i, PREC_FLOAT);
			s = cert_f32_side(n);
			in += s == 0;
			bad += (s == 0) != cert_in_domain(n, PREC_FLOAT, -1.0) || s == 2;
		}
	}
	count += 129 * 3;
	CHECK(bad == 0, "cert_f32_side disagrees with cert_in_domain on %ld of %ld inputs", bad, count);
	CHECK(in > count / 10 && in < count, "side cross-check: %ld members of %ld (want both kinds)", in, count);
	printf("cert_f32_side = cert_in_domain on %ld inputs (%ld members)\n", count, in);
}

/* The double side test against the exact one: double roundings of unit
   vectors, half of them near the diagonals |x| = |y| (where a largest
   component an ulp off its completion can still be a member), each
   component then moved by -1, 0 or +1 ulp; and (1, y, 0) with y within
   16 doubles of 2^-26.5, where the low-end sum is nearest 1. */
static void side64_crosscheck(long count)
{
	long i, in = 0, bad = 0;
	for (i = 0; i < count; i++) {
		double z = 2.0 * unif((uint64_t)i, 5) - 1.0, phi = 6.283185307179586 * unif((uint64_t)i, 6), n[3], r;
		int j, s;
		if (i % 2)
			phi = (45.0 + 90.0 * (double)(i % 4 / 2) + 1e-3 * (unif((uint64_t)i, 7) - 0.5)) * 0.017453292519943295;
		r = sqrt((1.0 - z) * (1.0 + z));
		n[0] = r * cos(phi);
		n[1] = r * sin(phi);
		n[2] = z;
		for (j = 0; j < 3; j++)
			n[j] = fmt_step(n[j], (int64_t)(rng_mix64((uint64_t)i * 3 + (uint64_t)j + 7) % 3) - 1, PREC_DOUBLE);
		s = cert_f64_side(n);
		in += s == 0;
		bad += (s == 0) != cert_in_domain(n, PREC_DOUBLE, -1.0) || s == 2;
	}
	for (i = -16; i <= 16; i++) {
		double n[3] = { 1.0, 0.0, 0.0 };
		int s;
		n[1] = fmt_step(0x1.6a09e667f3bcdp-27, i, PREC_DOUBLE);
		s = cert_f64_side(n);
		in += s == 0;
		bad += (s == 0) != cert_in_domain(n, PREC_DOUBLE, -1.0) || s == 2;
	}
	count += 33;
	CHECK(bad == 0, "cert_f64_side disagrees with cert_in_domain on %ld of %ld inputs", bad, count);
	CHECK(in > count / 10 && in < count, "double side cross-check: %ld members of %ld (want both kinds)", in, count);
	printf("cert_f64_side = cert_in_domain on %ld inputs (%ld members)\n", count, in);
}

/* The index of input n among the count of in, or -1 (bit comparison). */
static long long find_input(const double *in, long long count, const double n[3])
{
	long long i;
	for (i = 0; i < count; i++)
		if (memcmp(&in[3 * i], n, 3 * sizeof *n) == 0)
			return i;
	return -1;
}

/* One method on one box, measured (in parallel, one context each). */
typedef struct {
	int run;             /* 0: skipped; 1: measured; -1: cert_enumerate failed */
	int meets_singular;
	cert_result res;
	cert_enum e;
	long long at;        /* the found input's index in the box, or -1 */
	double at_d;         /* the box's defect there */
	double again;        /* the found input outside the box, measured again */
} one_out;

static void measure(cert_ctx *x, const study_kernel *k, const cm_method *m, const double *in, long long count,
                    double *d, const cert_region *r, one_out *o)
{
	const cert_opts opt = { 120, 100, 1.25, -1.0, 22, NULL, NULL, NULL, 0, NULL };
	int nf = 0;
	if (cert_enumerate(x, k, in, count, d, &o->e)) {
		o->run = -1;
		return;
	}
	cert_region_run(x, k, m, PREC_FLOAT, r, &opt, &o->res);
	o->at = find_input(in, count, o->res.found_n);
	o->at_d = o->at >= 0 ? d[o->at] : 0.0;
	if (o->at < 0 && o->res.found > 0.0)   /* an input of the region outside the box */
		o->again = cert_probe(x, k, PREC_FLOAT, o->res.found_n, &nf);
	o->run = 1;
}

/* The box's maximum against certify's bracket, in the methods' order. */
static void report(const study_kernel *k, const cert_box *b, const one_out *o)
{
	const cert_result *res = &o->res;
	const cert_enum *e = &o->e;
	if (o->run < 0) {
		CHECK(0, "%s: cert_enumerate failed on %s", b->name, k->name);
		return;
	}
	CHECK(e->nonfinite == 0 || res->status == CERT_SINGULAR,
	      "%s %s: %lld non-finite outputs in the box, certify's status is not singular", b->name, k->name,
	      e->nonfinite);
	CHECK(res->bound >= e->max, "%s %s: bound %a below the box's maximum %a at (%a, %a, %a)", b->name, k->name,
	      res->bound, e->max, e->n[0], e->n[1], e->n[2]);
	if (o->at >= 0)
		CHECK(memcmp(&o->at_d, &res->found, sizeof res->found) == 0 && res->found <= e->max,
		      "%s %s: found %a at (%a, %a, %a), the box measured %a there (max %a)", b->name, k->name,
		      res->found, res->found_n[0], res->found_n[1], res->found_n[2], o->at_d, e->max);
	else if (res->found > 0.0)
		CHECK(memcmp(&o->again, &res->found, sizeof o->again) == 0, "%s %s: found %a, measured again %a", b->name,
		      k->name, res->found, o->again);
	printf("  %-23s %5lld  max %-22a %9.4g u  bound %-22a %9.4g u  ratio %8.6g  found %8.4g u%s%s\n",
	       k->name, e->inputs, e->max, e->max / 0x1p-24, res->bound, res->bound / 0x1p-24,
	       e->max > 0 ? res->bound / e->max : NAN,
	       res->found / 0x1p-24, o->at >= 0 ? " (in box)" : " (outside box)",
	       res->status == CERT_SINGULAR ? " singular" : "");
}

/* The methods with an approximate reciprocal square root: their model
   needs the seed bounds, an exhaustive scan of the floats that takes
   ~20 s once per process (seeds.h). */
static int uses_seed(const char *name) { return strstr(name, "rsqrt") || strstr(name, "invsqrt"); }

/* The methods of one box, measured two or more at a time (each thread its
   own context and defect buffer), then checked and printed in order. */
static void measure_all(const study_kernel *ks, int nk, int seeds, const double *in, long long count,
                        const cert_region *r, one_out *out)
{
	int k, fail = 0;
#pragma omp parallel
	{
		cert_ctx *x = cert_ctx_new();
		double *d = malloc((size_t)count * sizeof *d);
#pragma omp for schedule(dynamic, 1)
		for (k = 0; k < nk; k++) {
			const cm_method *m = ks[k].m ? cm_find(ks[k].m->name) : NULL;
			if (!m || !kernel_runs(&ks[k], PREC_FLOAT) || (!seeds && uses_seed(ks[k].name)))
				continue;
			if (region_meets_singular(&ks[k], r)) {
				out[k].meets_singular = 1;
				continue;
			}
			if (!x || !d) {
#pragma omp atomic write
				fail = 1;
				continue;
			}
			measure(x, &ks[k], m, in, count, d, r, &out[k]);
		}
		free(d);
		cert_ctx_free(x);
	}
	CHECK(!fail, "out of memory");
}

static void one_box(const cert_box *b, const study_kernel *ks, int nk, int seeds)
{
	double *in = NULL;
	long long count = cert_box_inputs(b, &in), i, outside = 0;
	one_out *out;
	cert_region r;
	int k;
	CHECK(count > 0, "box %s: %lld inputs", b->name, count);
	if (count <= 0)
		return;
	CHECK(cert_inputs_region(in, count, &r) == 0, "box %s: no region (azimuths across 0)", b->name);
	for (i = 0; i < count; i++)
		outside += !cert_in_region(&r, &in[3 * i]);
	CHECK(outside == 0, "box %s: %lld inputs outside their own region", b->name, outside);
	printf("%s: %lld inputs, n.z %a .. %a, phi %.9g .. %.9g deg\n  (%s)\n", b->name, count, r.nz_lo, r.nz_hi,
	       r.phi_lo, r.phi_hi, b->why);
	if (!(out = calloc((size_t)nk, sizeof *out))) {
		CHECK(0, "out of memory");
		free(in);
		return;
	}
	measure_all(ks, nk, seeds, in, count, &r, out);
	for (k = 0; k < nk; k++) {
		if (out[k].meets_singular)
			printf("  %-22s skipped: the region meets its singular set\n", ks[k].name);
		else if (out[k].run)
			report(&ks[k], b, &out[k]);
	}
	free(out);
	free(in);
}

int main(int argc, char **argv)
{
	const int seeds = argc > 1 && strcmp(argv[1], "--seeds") == 0;
	static study_kernel ks[MAXK];
	int nk = kernels_select(NULL, 0, ks, MAXK), nb, i;
	const cert_box *b = cert_boxes(&nb);
	CHECK(nk > 0, "setup: %d kernels", nk);
	if (nk <= 0)
		return check_finish("test_enumerate");
	if (argc > 1 && !seeds) {
		fprintf(stderr, "usage: test_enumerate [--seeds]\n");
		return 2;
	}
	if (!seeds)
		printf("the rsqrt and invsqrt variants are left out (their seed bounds take ~20 s): --seeds adds them\n");
	side_crosscheck(20000);
	side64_crosscheck(6000);
	for (i = 0; i < nb; i++)
		one_box(&b[i], ks, nk, seeds);
	return check_finish("test_enumerate");
}
