/*
 * test_bench.c - the machinery of `onbstudy bench` counts every basis once
 * and keeps the right results: the runner's slices cover each item exactly
 * once per pass, checksums give known answers, the inline call loops and
 * the yardstick compute the registry's bits.  No wall-clock assertions.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "bench/bench_core.h"
#include "bench/bench_calls.h"
#include "bench/yardstick.h"

#include "check.h"
#include "common/prec.h"

typedef struct {
	size_t n;
	unsigned *visits;
} count_ctx;

static void count_kernel(void *ctx, size_t lo, size_t hi)
{
	count_ctx *c = ctx;
	size_t i;
	for (i = lo; i < hi; i++)
		c->visits[i]++;
}

static void test_runner(void)
{
	const size_t ns[] = { 1, 7, 1000, 1031 };
	const int threads[] = { 1, 2, 3 };
	size_t a, b, i;
	for (a = 0; a < sizeof ns / sizeof ns[0]; a++)
		for (b = 0; b < sizeof threads / sizeof threads[0]; b++) {
			count_ctx c;
			bench_cfg cfg;
			bench_result r;
			size_t bad = 0;
			c.n = ns[a];
			c.visits = calloc(c.n, sizeof *c.visits);
			cfg.threads = threads[b];
			cfg.warmup = 2;
			cfg.reps = 5;
			cfg.inner = 3;
			CHECK(bench_run(count_kernel, &c, c.n, &cfg, &r) == 0, "bench_run n=%zu", c.n);
			for (i = 0; i < c.n; i++)
				bad += c.visits[i] != (2 + 5) * 3;
			CHECK(bad == 0, "n=%zu threads=%d: %zu items not visited exactly 21 times", c.n, threads[b], bad);
			CHECK(r.n == c.n && r.passes == 15 && r.reps == 5, "result n=%zu passes=%zu reps=%d", r.n, r.passes, r.reps);
			CHECK(r.threads >= 1 && r.threads <= threads[b], "team of %d for %d", r.threads, threads[b]);
			CHECK(r.min_s >= 0.0 && r.min_s <= r.median_s, "min %g median %g", r.min_s, r.median_s);
			free(c.visits);
		}
	{
		bench_cfg cfg = { 1, 0, 0, 1 };
		bench_result r;
		count_ctx c = { 0, NULL };
		CHECK(bench_run(count_kernel, &c, 0, &cfg, &r) == -1, "reps = 0 refused");
		cfg.reps = BENCH_MAX_REPS + 1;
		CHECK(bench_run(count_kernel, &c, 0, &cfg, &r) == -1, "too many reps refused");
	}
}

static void test_stats(void)
{
	double v3[] = { 3.0, 1.0, 2.0 }, v4[] = { 4.0, 1.0, 3.0, 2.0 };
	CHECK(bench_min(v3, 3) == 1.0, "min");
	CHECK(bench_median(v3, 3) == 2.0, "median of 3");
	CHECK(bench_median(v4, 4) == 2.5, "median of 4");
}

/* Batch kernels through the runner: every output written once, checksum
   known.  frisvad of n = +z is exactly b1 = +x, b2 = +y: 2 per basis. */
static void test_soa_checksum(void)
{
	int prec, thr;
	const onb_method *m = onb_find("frisvad");
	for (prec = 0; prec < 2; prec++)
		for (thr = 1; thr <= 3; thr++) {
			bench_soa s;
			bench_cfg cfg = { 0, 1, 3, 2 };
			bench_result r;
			size_t i, n = 1003;
			cfg.threads = thr;
			CHECK(bench_soa_alloc(&s, n, prec) == 0, "alloc");
			for (i = 0; i < n; i++) {
				if (prec == PREC_DOUBLE)
					((double *)s.in[2])[i] = 1.0;
				else
					((float *)s.in[2])[i] = 1.0f;
			}
			s.batch = m->batch;
			s.batchf = m->batchf;
			CHECK(bench_run(bench_soa_kernel, &s, n, &cfg, &r) == 0, "run");
			CHECK(bench_soa_checksum(&s) == 2.0 * (double)n, "%s %d threads: checksum %.17g, want %zu",
			      prec_name(prec), thr, bench_soa_checksum(&s), 2 * n);
			bench_soa_free(&s);
		}
}

/* The six-output sum in the order of bench_pair_checksum and the latency loop. */
static double sum6(onb_vec3 b1, onb_vec3 b2) { return ((b1.x + b1.y) + b1.z) + ((b2.x + b2.y) + b2.z); }
static double sum6f(onb_vec3f b1, onb_vec3f b2)
{
	return (((double)b1.x + b1.y) + b1.z) + (((double)b2.x + b2.y) + b2.z);
}

static void test_calls(void)
{
	enum { N = 515 };
	static double gx[N], gy[N], gz[N];
	static onb_vec3 in[N];
	static onb_vec3f inf_[N];
	static bench_pair out[N];
	static bench_pairf outf[N];
	size_t nm, k, i;
	const onb_method *ms = onb_methods(&nm);
	bench_fill_uniform(N, 7, gx, gy, gz);
	for (i = 0; i < N; i++) {
		CHECK(fabs(gx[i] * gx[i] + gy[i] * gy[i] + gz[i] * gz[i] - 1.0) < 1e-14, "input %zu not unit", i);
		in[i].x = gx[i]; in[i].y = gy[i]; in[i].z = gz[i];
		inf_[i].x = (float)gx[i]; inf_[i].y = (float)gy[i]; inf_[i].z = (float)gz[i];
	}
	for (k = 0; k < nm; k++) {
		const bench_call *c = bench_call_find(ms[k].name);
		double want = 0.0, wantf = 0.0, got;
		size_t badbits = 0;
		CHECK(c != NULL, "no call loop for %s", ms[k].name);
		if (!c)
			continue;
		memset(out, 0xff, sizeof out);
		memset(outf, 0xff, sizeof outf);
		/* float-only methods (ONB_FLOAT_ONLY) have no double loops */
		CHECK(!c->tp == !ms[k].basis && !c->lat == !ms[k].basis, "%s: double call loops iff a double method", ms[k].name);
		if (c->tp)
			c->tp(N, in, out);
		c->tpf(N, inf_, outf);
		for (i = 0; i < N; i++) {
			onb_vec3 b1, b2;
			onb_vec3f b1f, b2f;
			if (ms[k].basis) {
				ms[k].basis(in[i], &b1, &b2);
				badbits += memcmp(&b1, &out[i].b1, sizeof b1) || memcmp(&b2, &out[i].b2, sizeof b2);
				want += sum6(b1, b2);
			}
			ms[k].basisf(inf_[i], &b1f, &b2f);
			badbits += memcmp(&b1f, &outf[i].b1, sizeof b1f) || memcmp(&b2f, &outf[i].b2, sizeof b2f);
			wantf += sum6f(b1f, b2f);
		}
		CHECK(badbits == 0, "%s: %zu inline call results differ from the registry's", ms[k].name, badbits);
		CHECK(bench_pair_checksumf(N, outf) == wantf, "%s: float throughput checksum", ms[k].name);
		if (c->tp) {
			CHECK(bench_pair_checksum(N, out) == want, "%s: throughput checksum", ms[k].name);
			got = c->lat(N, in);
			CHECK(got == want, "%s: latency chain checksum %.17g, want %.17g (every call once, inputs unchanged)",
			      ms[k].name, got, want);
		}
		got = c->latf(N, inf_);
		CHECK(got == wantf, "%s: float latency chain checksum %.17g, want %.17g", ms[k].name, got, wantf);
	}
	{
		/* known answer through the chain: frisvad(+z) sums to 2 per call */
		const bench_call *c = bench_call_find("frisvad"), *ch = bench_call_find("chain");
		static onb_vec3 z[N];
		static onb_vec3f zf[N];
		for (i = 0; i < N; i++) {
			z[i].x = z[i].y = 0.0; z[i].z = 1.0;
			zf[i].x = zf[i].y = 0.0f; zf[i].z = 1.0f;
		}
		CHECK(c->lat(N, z) == 2.0 * N && c->latf(N, zf) == 2.0 * N, "frisvad chain of +z");
		/* the chain alone: b1 = b2 = n, so 2 per call of +z */
		CHECK(ch && ch->lat(N, z) == 2.0 * N && ch->latf(N, zf) == 2.0 * N, "chain pseudo-method");
		CHECK(bench_call_find("no_such_method") == NULL, "unknown call loop");
	}
}

/* The yardstick re-implements four formulas by hand: same bits as libonb. */
static void test_yardstick(void)
{
	enum { N = 1000 };
	size_t ny, k, i;
	const bench_yardstick *y = bench_yardsticks(&ny);
	static double in[3][N], a[6][N], b[6][N];
	static float inf_[3][N], af[6][N], bf[6][N];
	bench_fill_uniform(N, 11, in[0], in[1], in[2]);
	/* the edges: poles, thresholds, signed zeros */
	in[0][0] = 0.0; in[1][0] = 0.0; in[2][0] = -1.0;
	in[0][1] = 0.0; in[1][1] = 0.0; in[2][1] = 1.0;
	in[0][2] = 0.0; in[1][2] = 0.0; in[2][2] = -0.0;
	in[0][3] = 1.0; in[1][3] = 0.0; in[2][3] = 0.0;
	in[0][4] = sqrt(1.0 - 0.9999999 * 0.9999999); in[1][4] = 0.0; in[2][4] = -0.9999999;
	in[0][5] = 0.6; in[1][5] = 0.0; in[2][5] = 0.8;
	in[0][6] = -1.0; in[1][6] = 0.0; in[2][6] = 0.0;
	for (k = 0; k < 3; k++)
		for (i = 0; i < N; i++)
			inf_[k][i] = (float)in[k][i];
	CHECK(ny >= 4, "four yardsticks");
	for (k = 0; k < ny; k++) {
		const onb_method *m = onb_find(y[k].name);
		size_t j, bad = 0, badf = 0;
		CHECK(m != NULL, "yardstick %s is a registry method", y[k].name);
		if (!m)
			continue;
		m->batch(N, in[0], in[1], in[2], a[0], a[1], a[2], a[3], a[4], a[5]);
		y[k].batch(N, in[0], in[1], in[2], b[0], b[1], b[2], b[3], b[4], b[5]);
		m->batchf(N, inf_[0], inf_[1], inf_[2], af[0], af[1], af[2], af[3], af[4], af[5]);
		y[k].batchf(N, inf_[0], inf_[1], inf_[2], bf[0], bf[1], bf[2], bf[3], bf[4], bf[5]);
		for (j = 0; j < 6; j++)
			for (i = 0; i < N; i++) {
				bad += memcmp(&a[j][i], &b[j][i], sizeof(double)) != 0;
				badf += memcmp(&af[j][i], &bf[j][i], sizeof(float)) != 0;
			}
		CHECK(bad == 0 && badf == 0, "yardstick %s: %zu double and %zu float outputs differ from libonb", y[k].name, bad, badf);
	}
	bench_copy(N, in[0], in[1], in[2], b[0], b[1], b[2], b[3], b[4], b[5]);
	bench_copyf(N, inf_[0], inf_[1], inf_[2], bf[0], bf[1], bf[2], bf[3], bf[4], bf[5]);
	{
		size_t bad = 0;
		for (i = 0; i < N; i++)
			for (k = 0; k < 6; k++)
				bad += memcmp(&b[k][i], &in[k % 3][i], sizeof(double)) != 0 || memcmp(&bf[k][i], &inf_[k % 3][i], sizeof(float)) != 0;
		CHECK(bad == 0, "copy kernel: %zu outputs differ from inputs", bad);
	}
}

/* The probe finds our symbols when objdump exists (it cannot judge them
   without it, and says so). */
static void test_probe(void)
{
	const char *w = bench_vector_width("bench_copyf");
	if (system("objdump --version >/dev/null 2>&1") != 0) {
		CHECK(strcmp(w, "unknown") == 0, "no objdump: probe must say unknown, said %s", w);
		return;
	}
	CHECK(strcmp(w, "unknown") != 0, "probe did not find bench_copyf");
	w = bench_vector_width("bench_tp_duff_branchlessf");
	CHECK(strcmp(w, "unknown") != 0, "probe did not find bench_tp_duff_branchlessf");
	CHECK(strcmp(bench_vector_width("no_such_symbol_here"), "unknown") == 0, "probe invents symbols");
}

static void test_tsc(void)
{
	double g = bench_tsc_ghz(0.002);
	if (bench_tsc_constant())
		CHECK(g > 0.1 && g < 20.0, "TSC at %g GHz", g);
	else
		CHECK(g == 0.0, "no constant TSC but %g GHz", g);
}

int main(void)
{
	test_stats();
	test_runner();
	test_soa_checksum();
	test_calls();
	test_yardstick();
	test_probe();
	test_tsc();
	return check_finish(NULL);
}
