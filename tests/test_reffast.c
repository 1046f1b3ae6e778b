/*
 * test_reffast.c - the fast reference against MPFR, input by
 * input: whenever reffast_eval says a sample is determined, every byte of
 * its sample_metrics equals ref_eval's at 127 bits.  Inputs: every
 * distribution of the sweep (both precisions, every kernel, the FMA
 * copies when the CPU has them), the exhaustive south pole, and the
 * inputs that defeat the fast path (signed zeros, axes, subnormal and
 * tiny components, huge and non-finite inputs, each method's fallback
 * branch).  It also fails if the fast path decides too few samples (so a
 * path that always falls back cannot pass) and prints the fallback rate,
 * and if a second context, called right after the first on the same
 * sample, decides differently (the fast path once read a bound it had
 * not set yet, so its decisions followed stack garbage).
 * Usage: test_reffast [N] (inputs per distribution, default 2000).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <float.h>
#include "reference/reference.h"
#include "reference/reffast.h"
#include "inputs/inputs.h"
#include "methods/kernels.h"

#include "check.h"

static study_kernel ks[256];
static int nk;
static unsigned long long decided[2], total[2], noref[2], mismatches, undetermined;
static reffast_ctx *fc2; /* a second context: decisions must not depend on stack garbage */

static void show(const char *what, const sample_metrics *a)
{
	int i;
	printf("  %s: br %d nf %d hand %d in_norm %a d", what, a->branch, a->nonfinite, a->wrong_hand, a->in_norm);
	for (i = 0; i < NDEF; i++)
		printf(" %a", a->d[i]);
	printf(" ulp %a abs %a bits %a/%d max %a dir %a %a ref", a->ulp_max, a->abs_eps_max, a->bits_sum, a->nbits,
	       a->bits_max, a->dir_norm, a->dir_cos);
	for (i = 0; i < 6; i++)
		printf(" %a", a->ref[i]);
	printf("\n");
}

/* One input through every kernel; 1 if every decided sample matched. */
static int one(ref_ctx *rc, reffast_ctx *fc, int p, const double n[3], const double loc[3], int nonunit)
{
	int k, good = 1, f;
	for (k = 0; k < nk; k++) {
		sample_metrics a, b;
		if (!kernel_runs(&ks[k], p))
			continue; /* a float-only method, in double */
		memset(&a, 0, sizeof a);
		memset(&b, 0, sizeof b);
		ref_eval(rc, &ks[k], p, n, loc, nonunit, &a);
		total[p]++;
		f = reffast_eval(fc, &ks[k], p, n, loc, nonunit, &b);
		if (fc2) {
			/* the same call on a second context, right after the first
			   (other garbage on the stack, no MPFR call between): the same
			   decision and bytes, or the fast path read something unset */
			sample_metrics c2;
			memset(&c2, 0, sizeof c2);
			if (reffast_eval(fc2, &ks[k], p, n, loc, nonunit, &c2) != f ||
			    (f != REFFAST_MPFR && memcmp(&b, &c2, sizeof b) != 0)) {
				if (undetermined++ < 5)
					printf("NONDETERMINISTIC %s %s n = (%a, %a, %a)\n", ks[k].name, prec_name(p),
					       n[0], n[1], n[2]);
				good = 0;
			}
		}
		if (f == REFFAST_MPFR)
			continue;
		decided[p]++;
		if (f == REFFAST_NOREF) {
			/* ref[] is left to MPFR where undetermined (NaN), else equal */
			int i;
			noref[p]++;
			for (i = 0; i < 6; i++)
				if (isnan(b.ref[i]) && !isnan(a.ref[i]))
					b.ref[i] = a.ref[i];
		}
		if (memcmp(&a, &b, sizeof a) != 0) {
			if (mismatches++ < 10) {
				printf("MISMATCH %s %s n = (%a, %a, %a) loc (%a, %a, %a)%s\n", ks[k].name, prec_name(p),
				       n[0], n[1], n[2], loc[0], loc[1], loc[2], nonunit ? " nonunit" : "");
				show("mpfr", &a);
				show("fast", &b);
			}
			good = 0;
		}
	}
	return good;
}

static void dist(ref_ctx *rc, reffast_ctx *fc, int d, int p, uint64_t count, uint64_t from, double ex_from)
{
	dist_spec ds;
	uint64_t i, bad = 0;
	unsigned long long d0 = decided[p], t0 = total[p];
	memset(&ds, 0, sizeof ds);
	ds.dist = d; ds.prec = p; ds.seed = 1; ds.count = count;
	ds.ex_from = fmt_round(ex_from, p); ds.ex_values = count / 4; ds.ex_azimuths = 4;
	ds.grid_rows = 24; ds.grid_cols = 48;
	if (dist_prepare(&ds) != 0) {
		CHECK(0, "dist_prepare %s", dist_name(d));
		return;
	}
	if (d != DIST_THRESHOLD && d != DIST_GRID)
		ds.count = count;
	for (i = from; i < ds.count; i++) {
		double n[3], lv[3], aux;
		dist_sample(&ds, i, n, lv, &aux);
		bad += !one(rc, fc, p, n, lv, d == DIST_NONUNIT);
	}
	CHECK(bad == 0, "%s %s: %llu inputs where the fast path disagrees with MPFR", dist_name(d), prec_name(p),
	      (unsigned long long)bad);
	printf("  %-10s %-6s %6llu inputs: fast path decided %.3f%% of %llu samples\n", dist_name(d), prec_name(p),
	       (unsigned long long)(ds.count - from),
	       100.0 * (double)(decided[p] - d0) / (double)(total[p] - t0 ? total[p] - t0 : 1), total[p] - t0);
	dist_free(&ds);
}

/* The inputs that defeat the fast path: they must still agree. */
static void special(ref_ctx *rc, reffast_ctx *fc)
{
	static const double v[][3] = {
		{ 0, 0, 1 }, { 0, 0, -1 }, { -0.0, -0.0, -1 }, { 0, -0.0, 1 }, { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 },
		{ 0, -1, 0 }, { 0x1p-1074, 0, -1 }, { 0x1p-1074, 0x1p-1074, 1 }, { 0x1p-149, -0x1p-149, -1 },
		{ 0x1p-600, 0x1p-600, -1 }, { 1e-160, -1e-160, 1 }, { 3e-8, 4e-8, -1 }, { 0x1p-30, 0, -1 },
		{ 0.6, 0.8, 0 }, { 0.6, 0.8, -0.0 }, { 0, 0, 0 }, { 0, 0, -0.0 }, { 1e300, 1e300, 1e300 },
		{ NAN, 0, 1 }, { INFINITY, 0, 0 }, { 0.5, 0.5, 0.5 }, { 0.95, 0.1, 0.2 }, { 0.91, 0.3, -0.28 },
		{ 1, 1, 1 }, { 0x1.fffffep-1, 0, 0 }, { 0, 0, -0x1.fffffep-1 }, { 0, 0, -0x1.fffffffffffffp-1 },
	};
	static const double loc[][3] = { { 0, 0, 1 }, { 0.6, 0, 0.8 }, { 0, -0.0, 1 }, { 0.3, 0.4, 0x1.d38p-1 } };
	size_t i, j;
	int p, bad = 0;
	for (p = 0; p < 2; p++)
		for (i = 0; i < sizeof v / sizeof v[0]; i++)
			for (j = 0; j < sizeof loc / sizeof loc[0]; j++) {
				bad += !one(rc, fc, p, v[i], loc[j], 0);
				bad += !one(rc, fc, p, v[i], loc[j], 1);
			}
	CHECK(bad == 0, "special inputs: %d disagreements", bad);
}

int main(int argc, char **argv)
{
	ref_ctx *rc = ref_new(127);
	reffast_ctx *fc = reffast_new(127);
	const char *why;
	const uint64_t N = argc > 1 ? (uint64_t)atoll(argv[1]) : 2000;
	int p, d;
	if (!reffast_usable(127, &why)) {
		printf("SKIP test_reffast: %s\n", why);
		return 0;
	}
	nk = kernels_select(NULL, fma_available(), ks, 256);
	fc2 = reffast_new(127);
	CHECK(nk > 0 && rc && fc && fc2, "setup");
	special(rc, fc);
	for (p = 0; p < 2; p++)
		for (d = 0; d < NDIST; d++)
			dist(rc, fc, d, p, d == DIST_EXHAUSTIVE ? 4 * N : N, 0, -1.0);
	/* the float south pole, where 1 + n.z cancels: the first 4N inputs past
	   -1 are in the run above; these are further in (n.z near -0.99) */
	dist(rc, fc, DIST_EXHAUSTIVE, PREC_FLOAT, 4 * N, 0, -0.99);
	CHECK(mismatches == 0, "%llu samples where a decided fast result differs from MPFR", mismatches);
	CHECK(undetermined == 0, "%llu samples decided differently by a second context", undetermined);
	for (p = 0; p < 2; p++) {
		const double rate = 1.0 - (double)decided[p] / (double)total[p];
		printf("  %s: fast path decided %llu of %llu samples (fallback %.4f%%; %llu with ref[] left to MPFR)\n",
		       prec_name(p), decided[p], total[p], 100.0 * rate, noref[p]);
		/* the mix is heavy in special inputs (threshold, axes); a path
		   that gave up more often than this would not be a fast path */
		CHECK(rate < 0.05, "%s: fallback rate %.4f%% is above 5%%", prec_name(p), 100.0 * rate);
	}
	ref_free(rc);
	reffast_free(fc);
	reffast_free(fc2);
	return check_finish("test_reffast");
}
