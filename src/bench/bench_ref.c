/*
 * bench_ref.c - `onbstudy bench --reference`: referenced
 * evaluations per second per core, with the fast reference (reffast.c,
 * MPFR where it cannot decide) and with MPFR alone, on the default
 * sweep's inputs: every method on a slice of each distribution of each
 * precision, one thread.  Written to bench-reference.csv with provenance.
 *
 * What a sweep adds is not timed: its MPFR re-evaluation for ref[] of the
 * rows it keeps among the worst (a few hundred per default sweep, filled
 * when a thread folds its accumulators; the count is in the sweep's log),
 * the 1-in-509 cross-check at 191 bits, input generation and the
 * accumulators.  Both paths run the same
 * inputs in the same order; the rate is the median over repetitions.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "bench/bench_ref.h"
#include "bench/bench_core.h"
#include "common/options.h"
#include "common/output.h"
#include "inputs/inputs.h"
#include "methods/kernels.h"
#include "reference/reference.h"
#include "reference/reffast.h"

#define BR_MAX_INPUTS (1 << 15)
#define BR_MAX_KERNELS 256

typedef struct {
	double n[3], loc[3];
	int nonunit;
} br_input;

static int cmp_double(const void *a, const void *b)
{
	const double x = *(const double *)a, y = *(const double *)b;
	return x < y ? -1 : x > y;
}

/* Inputs of precision p: per distribution of the default sweep, `per`
   consecutive indices spread over its range. */
static int br_inputs(int p, unsigned long long seed, int per, br_input *in)
{
	int d, m = 0;
	for (d = 0; d < NDIST; d++) {
		dist_spec ds;
		uint64_t i, step;
		memset(&ds, 0, sizeof ds);
		ds.dist = d; ds.prec = p; ds.seed = seed; ds.count = 32768;
		ds.ex_from = fmt_round(-1.0, p); ds.ex_values = 65536; ds.ex_azimuths = 4;
		ds.grid_rows = 24; ds.grid_cols = 48;
		if (dist_prepare(&ds) != 0)
			return -1;
		step = ds.count / (uint64_t)per ? ds.count / (uint64_t)per : 1;
		for (i = 0; i < (uint64_t)per && i * step < ds.count && m < BR_MAX_INPUTS; i++) {
			double aux;
			dist_sample(&ds, i * step, in[m].n, in[m].loc, &aux);
			in[m].nonunit = d == DIST_NONUNIT;
			m++;
		}
		dist_free(&ds);
	}
	return m;
}

/* One pass over the inputs and kernels; returns the evaluations, counts
   the fast path's fallbacks. */
static unsigned long long br_pass(const br_input *in, int m, const study_kernel *ks, int nk, int p,
                                  ref_ctx *rc, reffast_ctx *fc, unsigned long long *fallback, double *check)
{
	unsigned long long ev = 0;
	int i, k;
	for (i = 0; i < m; i++)
		for (k = 0; k < nk; k++) {
			sample_metrics s;
			if (!kernel_runs(&ks[k], p))
				continue;
			if (!fc || reffast_eval(fc, &ks[k], p, in[i].n, in[i].loc, in[i].nonunit, &s) == REFFAST_MPFR) {
				ref_eval(rc, &ks[k], p, in[i].n, in[i].loc, in[i].nonunit, &s);
				if (fc)
					(*fallback)++;
			}
			if (!s.nonfinite)
				*check += s.ulp_max + s.bits_sum; /* keeps the work observable */
			ev++;
		}
	return ev;
}

int bench_reference(const char *out, int quick, unsigned long long seed)
{
	char load0[64], load1[64];
	static study_kernel ks[BR_MAX_KERNELS];
	static br_input in[BR_MAX_INPUTS];
	const int per = quick ? 64 : 1024, reps = quick ? 3 : 7;
	const char *why;
	int nk = kernels_select(NULL, 0, ks, BR_MAX_KERNELS), p, path, r;
	study_out f;
	double rate[2][2] = { { 0, 0 }, { 0, 0 } }, check = 0.0;
	unsigned long long evs[2] = { 0, 0 }, fb[2] = { 0, 0 };
	ref_ctx *rc = ref_new(127);
	reffast_ctx *fc = reffast_new(127);
	if (nk < 0 || !rc || !fc) {
		ref_free(rc);
		reffast_free(fc);
		study_error("bench --reference: out of memory");
		return 1;
	}
	if (!reffast_usable(127, &why)) {
		ref_free(rc);
		reffast_free(fc);
		study_error("bench --reference: %s", why);
		return 1;
	}
	bench_loadavg(load0, sizeof load0);
	for (p = 0; p < 2; p++) {
		const int m = br_inputs(p, seed, per, in);
		if (m < 0)
			return 1;
		{
			/* the two paths alternate, after one untimed pass of each, so
			   that a shared machine's load drift falls on both alike */
			double t[2][16];
			for (r = -1; r < reps; r++)
				for (path = 0; path < 2; path++) {
					unsigned long long fbr = 0;
					const double t0 = bench_now();
					evs[p] = br_pass(in, m, ks, nk, p, rc, path ? NULL : fc, &fbr, &check);
					if (r < 0)
						continue;
					t[path][r] = bench_now() - t0;
					if (!path)
						fb[p] = fbr;
				}
			for (path = 0; path < 2; path++) {
				qsort(t[path], (size_t)reps, sizeof t[path][0], cmp_double);
				rate[p][path] = (double)evs[p] / t[path][reps / 2];
			}
		}
	}
	bench_loadavg(load1, sizeof load1);
	ref_free(rc);
	reffast_free(fc);
	if (study_out_open(&f, out, "bench-reference.csv") != 0)
		return 1;
	study_provenance(f.f, "bench --reference", seed, 1);
	fprintf(f.f, "# load average (1, 5, 15 min): %s at the start, %s at the end (2 cores; above 1 other processes shared this core)\n",
	        load0, load1);
	fprintf(f.f, "# referenced evaluations per second on one core, median of %d passes (alternating fast and mpfr, after one untimed pass of each) over every method on %d inputs of each "
	        "distribution of the default sweep (default sizes); fast: reffast.c with MPFR where it cannot decide; mpfr: MPFR alone "
	        "(127 bits); not timed: a sweep's MPFR refill of ref[] for kept worst rows, its 1-in-509 cross-check, its accumulators\n",
	        reps, per);
	fprintf(f.f, "precision,evaluations,fast_per_s,mpfr_per_s,speedup,fast_fallback_rate\n");
	for (p = 0; p < 2; p++)
		fprintf(f.f, "%s,%llu,%.0f,%.0f,%.3f,%.6f\n", prec_name(p), evs[p], rate[p][0], rate[p][1],
		        rate[p][0] / rate[p][1], evs[p] ? (double)fb[p] / (double)evs[p] : 0.0);
	if (study_out_commit(&f) != 0)
		return 1;
	printf("reference path, referenced evaluations per second on one core (median of %d):\n", reps);
	for (p = 0; p < 2; p++)
		printf("  %-6s fast %10.0f  mpfr %10.0f  speedup %.2fx  (fast path fell back to MPFR on %.3f%%)\n",
		       prec_name(p), rate[p][0], rate[p][1], rate[p][0] / rate[p][1],
		       evs[p] ? 100.0 * (double)fb[p] / (double)evs[p] : 0.0);
	printf("wrote %s/bench-reference.csv%s\n", out, check == 12345.0 ? " " : "");
	return 0;
}
