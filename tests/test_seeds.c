/*
 * test_seeds.c - the seeds' error bounds (src/model/seeds.[ch]).
 *
 *   build/tests/test_seeds          make test (seconds): the seeds are the
 *       kernels' own; the float scan over two binades gives the same bound,
 *       bit for bit, as over 10 others (periodicity in the exponent parity),
 *       and no seed differs from its base binade's scaled by 2^-k; the
 *       error formula agrees with MPFR to 2^-50; the double proof holds on
 *       random doubles and its worst input is within 1e-9 of it.
 *   build/tests/test_seeds --full [N]   every positive normal float (twice:
 *       seed_bound_get, then with the periodicity check), the proof, N
 *       random doubles (default 10^7): what results/certify/seeds.txt holds.
 */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "libonb/onb.h"
#include "common/options.h"
#include "common/output.h"
#include "inputs/rng.h"
#include "model/seeds.h"
#include "model/model_int.h"
#include "model/newton_f.h"
#if ONB_HAVE_HW_RSQRT
#include <xmmintrin.h>   /* rsqrtps beside rsqrtss: onb.h itself no longer includes it */
#endif

static int pass, fail;
#define CHECK(c, ...) do { if (c) pass++; else { fail++; printf("FAIL %s:%d: ", __FILE__, __LINE__); printf(__VA_ARGS__); printf("\n"); } } while (0)

#define SEED 20261125u

static uint32_t fbits(float f) { uint32_t i; memcpy(&i, &f, sizeof i); return i; }
static uint64_t dbits(double d) { uint64_t i; memcpy(&i, &d, sizeof i); return i; }
static float bits_f(uint32_t i) { float f; memcpy(&f, &i, sizeof f); return f; }
static double bits_d(uint64_t i) { double d; memcpy(&d, &i, sizeof d); return d; }

/* A random positive normal float / double, every exponent equally likely. */
static float rand_f(uint64_t j)
{
	const uint64_t r = rng_u64(SEED, 1, j);
	return bits_f((uint32_t)((1 + r % 254) << 23) | (uint32_t)(r >> 41));
}
static double rand_d(uint64_t j)
{
	const uint64_t r = rng_u64(SEED, 2, j), m = rng_u64(SEED, 3, j);
	return bits_d(((1 + r % 2046) << 52) | (m >> 12));
}

/* The seeds are the kernels' own: the kernel is the seed plus its Newton
   step (or, for rsqrtss, the same instruction; rsqrtps lane by lane). */
static void test_model(void)
{
	long bad = 0, badv = 0;
	for (uint64_t j = 0; j < 200000; j++) {
		const float x = rand_f(j), y = seed_invsqrt_f(x), h = 0.5f * x;
		const double xd = rand_d(j), yd = seed_invsqrt_d(xd), hd = 0.5 * xd;
		bad += fbits(onb__invsqrtf(x)) != fbits(y * (1.5f - h * y * y));
		bad += dbits(onb__invsqrt(xd)) != dbits(yd * (1.5 - hd * yd * yd));
		bad += fbits(onb__hw_rsqrtf(x)) != fbits(seed_rsqrtss(x));
#if ONB_HAVE_HW_RSQRT
		badv += fbits(_mm_cvtss_f32(_mm_rsqrt_ps(_mm_set1_ps(x)))) != fbits(seed_rsqrtss(x));
#endif
	}
	CHECK(bad == 0, "%ld seeds differ from the kernels' (onb.h)", bad);
	CHECK(badv == 0, "%ld rsqrtps results differ from rsqrtss", badv);
}

/* newton_f, which the scan of newton_f.c runs, is bit for bit the
   model's executed step on the same seed (which test_model ties to the
   kernels); and the scan's range holds every sampled step's error. */
static void test_newton_steps(void)
{
	cm *c = cm_new(CM_EXEC);
	long bad = 0, out = 0;
	int k, s;
	for (k = 0; k < NNEWTON; k++)
		for (s = 0; s <= SEED_INVSQRT_F; s++)
			for (uint64_t j = 0; j < 50000; j++) {
				const double n[3] = { rand_f(j), 0.0, 0.0 };
				double lo, hi;
				cv in[3], y, r;
				float got, x;
				int e;
				cm_exec_begin(c, PREC_FLOAT, n, in);
				y = cm_seed(c, (seed_kind)s, in[0]);
				r = k == NEWTON_L3 ? cm_newton(c, PREC_FLOAT, in[0], y)
				  : k == NEWTON_L3_FUSED ? cm_newton_fused(c, PREC_FLOAT, in[0], y)
				  : k == NEWTON_EMBREE ? cm_newton_embree(c, PREC_FLOAT, in[0], y)
				  : cm_newton_embree_fused(c, PREC_FLOAT, in[0], y);
				got = newton_f((newton_kind)k, (seed_kind)s, (float)n[0]);
				bad += fbits(got) != fbits((float)cm_value(c, r));
				x = ldexpf(frexpf((float)n[0], &e), (int)(j & 1));   /* in [0.5, 2) */
				got = newton_f((newton_kind)k, (seed_kind)s, x);
				if (newton_range_f((newton_kind)k, (seed_kind)s, 126, 127, &lo, &hi) == 0) {
					const double err = got * sqrt((double)x) - 1.0;   /* within 1e-16 */
					out += !(err >= lo - 1e-15 && err <= hi + 1e-15);
				} else
					out++;
			}
	cm_free(c);
	CHECK(bad == 0, "%ld Newton steps (newton_f) differ from the model's executed steps", bad);
	CHECK(out == 0, "%ld Newton steps outside their binade's scanned range", out);
}

/* seed_err_f's claim: within a factor 1 +- 2^-50 of MPFR's value. */
static void test_err_formula(void)
{
	long bad = 0;
	for (uint64_t j = 0; j < 100000; j++) {
		const float x = rand_f(j);
		const float s = j & 1 ? seed_rsqrtss(x) : seed_invsqrt_f(x);
		const double e = seed_err_f(x, s), m = seed_err_d(x, s);
		if (!(fabs(e - m) <= m * 0x1p-50))
			bad++;
	}
	CHECK(bad == 0, "%ld inputs where seed_err_f is off MPFR by more than 2^-50", bad);
}

/* Two binades (eb 1, 2) against ten others: same bound, no exception. */
static void test_float_periodic(seed_kind k)
{
	static const int ranges[2][2] = { { 3, 6 }, { 249, 254 } };
	seed_bound base, other;
	uint64_t nonper = 0;
	CHECK(seed_scan_float(k, 1, 2, &base, NULL) == 0, "%s: scan failed", seed_name(k));
	for (int r = 0; r < 2; r++) {
		CHECK(seed_scan_float(k, ranges[r][0], ranges[r][1], &other, &nonper) == 0, "scan failed");
		CHECK(nonper == 0, "%s: %llu seeds in eb %d..%d are not the base binade's scaled",
		      seed_name(k), (unsigned long long)nonper, ranges[r][0], ranges[r][1]);
		CHECK(dbits(other.bound) == dbits(base.bound), "%s: bound %a on eb %d..%d, %a on eb 1..2",
		      seed_name(k), other.bound, ranges[r][0], ranges[r][1], base.bound);
	}
	if (k == SEED_INVSQRT_F) {   /* seed_bound_get scans eb 1..2 alone for this seed */
		seed_bound g;
		CHECK(seed_bound_get(k, &g) == 0 && dbits(g.bound) == dbits(base.bound) && g.worst_x == base.worst_x
		      && g.x_lo == 0x1p-126 && g.x_hi == 0x1.fffffep127, "%s: seed_bound_get is not the eb 1..2 scan "
		      "over every normal float", seed_name(k));
	}
	CHECK(base.worst <= base.bound && base.bound <= base.worst * (1 + 0x1p-47),
	      "%s: worst %a, bound %a", seed_name(k), base.worst, base.bound);
	for (uint64_t j = 0; j < 20000; j++) {
		const float x = rand_f(j);
		const double e = seed_err_d(x, k == SEED_RSQRTSS ? seed_rsqrtss(x) : seed_invsqrt_f(x));
		if (!(e <= base.bound)) {
			CHECK(0, "%s: x = %a has error %a > bound %a", seed_name(k), x, e, base.bound);
			break;
		}
	}
	printf("%-9s bound %a (%.6g) on eb 1..2, worst x = %a\n", seed_name(k), base.bound,
	       base.bound, base.worst_x);
}

/* n random doubles: error <= bound, s(x) = s(x0) 2^-k; returns the max. */
static double double_samples(const seed_bound *b, uint64_t n, double *argx)
{
	double mx = 0.0, ax = 0.0;
	long over = 0, nonper = 0;
	int64_t j;
#pragma omp parallel for schedule(static, 4096) reduction(+ : over, nonper)
	for (j = 0; j < (int64_t)n; j++) {
		const double x = rand_d((uint64_t)j), s = seed_invsqrt_d(x), e = seed_err_d(x, s);
		const uint64_t eb = dbits(x) >> 52, eb0 = 1024 - (eb & 1);
		const double x0 = bits_d((dbits(x) & ~(UINT64_C(0x7ff) << 52)) | (eb0 << 52));
		over += !(e <= b->bound);
		nonper += dbits(ldexp(seed_invsqrt_d(x0), -((int)eb - (int)eb0) / 2)) != dbits(s);
#pragma omp critical(test_seeds_max)
		if (e > mx || (e == mx && x < ax))
			mx = e, ax = x;
	}
	CHECK(over == 0, "%ld random doubles exceed the bound %a", over, b->bound);
	CHECK(nonper == 0, "%ld random doubles whose seed is not s(x0) 2^-k", nonper);
	*argx = ax;
	return mx;
}

static void test_double(uint64_t n)
{
	seed_bound b;
	long boxes = 0;
	double ax, mx, t0 = omp_get_wtime();
	CHECK(seed_prove_double(1e-12, &b, &boxes) == 0, "the double proof failed");
	printf("invsqrt_d bound %a (%.17g), proven in %.2f s (%ld boxes)\n", b.bound, b.bound,
	       omp_get_wtime() - t0, boxes);
	printf("invsqrt_d worst x = %a, error %a (%.17g)\n", b.worst_x, b.worst, b.worst);
	CHECK(b.worst <= b.bound && b.bound <= b.worst * (1 + 1e-9), "worst %a, bound %a",
	      b.worst, b.bound);
	mx = double_samples(&b, n, &ax);
	printf("invsqrt_d %llu random doubles: largest error %a (%.17g) at x = %a, bound - it = %.3g relative\n",
	       (unsigned long long)n, mx, mx, ax, (b.bound - mx) / b.bound);
	/* The largest error sits at a corner (the borrow boundary f = Fc, where
	   the slope is ~0.9 per unit of the mantissa): n uniform samples come
	   within ~1/n of it, so 20/n is missed with probability ~e^-20. */
	CHECK(mx >= b.bound * (1 - 20.0 / (double)n), "largest sampled error %a is not within %g of the bound %a",
	      mx, 20.0 / (double)n, b.bound);
}

/* --full: every positive normal float for both float seeds. */
static void full_float(seed_kind k)
{
	seed_bound b, c, base;
	uint64_t nonper = 0;
	double t0 = omp_get_wtime(), t1;
	CHECK(seed_bound_get(k, &b) == 0, "%s: seed_bound_get failed", seed_name(k));
	t1 = omp_get_wtime();
	printf("%-9s bound %a (%.17g) over [%a, %a]\n", seed_name(k), b.bound, b.bound, b.x_lo, b.x_hi);
	printf("%-9s worst x = %a, error %a (%.17g)\n", seed_name(k), b.worst_x, b.worst, b.worst);
	printf("%-9s how: %s\n", seed_name(k), b.how);
	printf("%-9s seed_bound_get: %.2f s for %u inputs on %d threads\n", seed_name(k), t1 - t0,
	       k == SEED_RSQRTSS ? (1u << 31) - (1u << 23) : 2u << 23, omp_get_max_threads());
	CHECK(seed_scan_float(k, 1, 254, &c, &nonper) == 0, "scan failed");
	CHECK(seed_scan_float(k, 1, 2, &base, NULL) == 0, "scan failed");
	CHECK(nonper == 0, "%s: %llu seeds are not their base binade's scaled by 2^-k", seed_name(k),
	      (unsigned long long)nonper);
	CHECK(dbits(base.bound) == dbits(b.bound) && dbits(c.bound) == dbits(b.bound),
	      "%s: full %a, eb 1..2 %a", seed_name(k), b.bound, base.bound);
	CHECK(c.worst_x == b.worst_x && c.x_lo == b.x_lo && c.x_hi == b.x_hi,
	      "%s: the full scan's worst x %a over [%a, %a], seed_bound_get's %a over [%a, %a]",
	      seed_name(k), c.worst_x, c.x_lo, c.x_hi, b.worst_x, b.x_lo, b.x_hi);
	printf("%-9s periodicity: %llu exceptions over every normal float (%.2f s with the check); "
	       "eb 1..2 alone gives %a\n", seed_name(k), (unsigned long long)nonper,
	       omp_get_wtime() - t1, base.bound);
}

int main(int argc, char **argv)
{
	const int full = argc > 1 && strcmp(argv[1], "--full") == 0;
	uint64_t n = full ? 10000000u : 200000u;
	if (argc > 3 || (argc >= 2 && !full) || (argc == 3 && (n = strtoull(argv[2], NULL, 10)) == 0)) {
		fprintf(stderr, "usage: test_seeds [--full [N]]\n");
		return 2;
	}
	if (full) {
		study_set_cmdline(argc, argv);
		study_provenance(stdout, "test_seeds --full (the rsqrt seeds' bounds)", SEED, omp_get_max_threads());
		printf("# rsqrtss cpu (CPUID): %s\n", seed_cpu());
		full_float(SEED_RSQRTSS);
		full_float(SEED_INVSQRT_F);
	} else {
		test_float_periodic(SEED_RSQRTSS);
		test_float_periodic(SEED_INVSQRT_F);
	}
	test_model();
	test_newton_steps();
	test_err_formula();
	test_double(n);
	printf("outside the domain (singular in the model):\n");
	seed_edge_report(stdout);
	printf("%d passed, %d failed\n", pass, fail);
	return fail != 0;
}
