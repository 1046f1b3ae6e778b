/*
 * bench_core.c - clocks, the repetition runner, SoA buffers, checksums,
 * inputs and the vectorization probe of `onbstudy bench` (see bench.h).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <omp.h>
#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#define BENCH_HAVE_TSC 1
#else
#define BENCH_HAVE_TSC 0
#endif
#include "bench/bench_core.h"
#include "inputs/rng.h"
#include "common/prec.h"

double bench_now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

uint64_t bench_tsc(void)
{
#if BENCH_HAVE_TSC
	return (uint64_t)__rdtsc();
#else
	return 0;
#endif
}

int bench_tsc_constant(void)
{
	static int known = -1;
	if (known < 0) {
		FILE *f = fopen("/proc/cpuinfo", "r");
		char line[8192];
		known = 0;
		if (f) {
			while (fgets(line, sizeof line, f)) {
				if (strncmp(line, "flags", 5) == 0) {
					known = BENCH_HAVE_TSC && strstr(line, " constant_tsc") && strstr(line, " nonstop_tsc");
					break;
				}
			}
			fclose(f);
		}
	}
	return known;
}

double bench_tsc_ghz(double seconds)
{
	double t0, t1;
	uint64_t c0, c1;
	if (!bench_tsc_constant())
		return 0.0;
	t0 = bench_now();
	c0 = bench_tsc();
	do
		t1 = bench_now();
	while (t1 - t0 < seconds);
	c1 = bench_tsc();
	return (double)(c1 - c0) / ((t1 - t0) * 1e9);
}

static int cmp_double(const void *a, const void *b)
{
	const double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

double bench_median(double *v, size_t n)
{
	if (n == 0)
		return NAN;
	qsort(v, n, sizeof *v, cmp_double);
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double bench_min(const double *v, size_t n)
{
	size_t i;
	double m = n ? v[0] : NAN;
	for (i = 1; i < n; i++)
		if (v[i] < m)
			m = v[i];
	return m;
}

int bench_run(bench_kernel k, void *ctx, size_t n, const bench_cfg *cfg, bench_result *r)
{
	double t[BENCH_MAX_REPS], c[BENCH_MAX_REPS];
	int team = 1;
	const int reps = cfg->reps, warmup = cfg->warmup;
	const size_t inner = cfg->inner;
	if (reps < 1 || reps > BENCH_MAX_REPS || warmup < 0 || inner < 1 || cfg->threads < 1)
		return -1;
	memset(r, 0, sizeof *r);
#pragma omp parallel num_threads(cfg->threads)
	{
		const int id = omp_get_thread_num(), nt = omp_get_num_threads();
		const size_t lo = (size_t)((double)n * id / nt), hi = id + 1 == nt ? n : (size_t)((double)n * (id + 1) / nt);
		double t0 = 0.0;
		uint64_t c0 = 0;
		int rep;
		size_t j;
#pragma omp master
		team = nt;
		for (rep = -warmup; rep < reps; rep++) {
#pragma omp barrier
#pragma omp master
			{
				t0 = bench_now();
				c0 = bench_tsc();
			}
			for (j = 0; j < inner; j++)
				k(ctx, lo, hi);
#pragma omp barrier
#pragma omp master
			if (rep >= 0) {
				uint64_t c1 = bench_tsc();
				t[rep] = bench_now() - t0;
				c[rep] = (double)(c1 - c0);
			}
		}
	}
	r->n = n;
	r->reps = reps;
	r->passes = (size_t)reps * inner;
	r->threads = team;
	r->min_s = bench_min(t, (size_t)reps) / (double)inner;
	r->median_s = bench_median(t, (size_t)reps) / (double)inner;
	if (bench_tsc_constant()) {
		r->min_ticks = bench_min(c, (size_t)reps) / (double)inner;
		r->median_ticks = bench_median(c, (size_t)reps) / (double)inner;
	}
	return 0;
}

size_t bench_calibrate(bench_kernel k, void *ctx, size_t n, int threads, double target_s, size_t max_inner)
{
	/* Grow the passes per repetition until one timed repetition lasts
	   target_s, barriers and thread wake-ups included: on a busy machine
	   a slow first pass must not leave repetitions so short that the
	   wake-up of a descheduled thread dominates them. */
	bench_cfg cfg;
	bench_result r;
	size_t inner = 1;
	int tries;
	cfg.threads = threads;
	cfg.warmup = 1;
	cfg.reps = 1;
	for (tries = 0; tries < 40; tries++) {
		double grow;
		cfg.inner = inner;
		if (bench_run(k, ctx, n, &cfg, &r) != 0)
			return 1;
		cfg.warmup = 0;
		if (r.min_s * (double)inner >= target_s || inner >= max_inner)
			break;
		grow = r.min_s > 0.0 ? ceil(1.2 * target_s / (r.min_s * (double)inner)) : 100.0;
		if (grow < 2.0)
			grow = 2.0;
		if (grow > 100.0)
			grow = 100.0;
		inner = (double)inner * grow > (double)max_inner ? max_inner : (size_t)((double)inner * grow);
	}
	return inner;
}

/* ---- SoA buffers ---------------------------------------------------- */

int bench_soa_alloc(bench_soa *s, size_t n, int prec)
{
	const size_t w = prec == PREC_DOUBLE ? sizeof(double) : prec == PREC_HALF ? sizeof(uint16_t) : sizeof(float);
	const size_t bytes = ((n * w + 63) / 64) * 64 + 64;
	int i;
	memset(s, 0, sizeof *s);
	s->prec = prec;
	s->n = n;
	for (i = 0; i < 9; i++) {
		void *p = NULL;
		if (posix_memalign(&p, 64, bytes) != 0) {
			bench_soa_free(s);
			return -1;
		}
		memset(p, 0, bytes);
		if (i < 3)
			s->in[i] = p;
		else
			s->out[i - 3] = p;
	}
	return 0;
}

void bench_soa_free(bench_soa *s)
{
	int i;
	for (i = 0; i < 3; i++)
		free(s->in[i]);
	for (i = 0; i < 6; i++)
		free(s->out[i]);
	memset(s, 0, sizeof *s);
}

void bench_soa_kernel(void *soa, size_t lo, size_t hi)
{
	const bench_soa *s = soa;
	if (hi <= lo)
		return;
	if (s->prec == PREC_HALF) {
		const uint16_t *const *in = (const uint16_t *const *)s->in;
		uint16_t *const *o = (uint16_t *const *)s->out;
		size_t i;
		if (s->batchh) {
			s->batchh(hi - lo, in[0] + lo, in[1] + lo, in[2] + lo,
			          o[0] + lo, o[1] + lo, o[2] + lo, o[3] + lo, o[4] + lo, o[5] + lo);
			return;
		}
		for (i = lo; i < hi; i++) { /* libonb has no half batch: its array entry per basis */
			uint16_t n[3], b1[3], b2[3];
			n[0] = in[0][i]; n[1] = in[1][i]; n[2] = in[2][i];
			s->arrayh(n, b1, b2);
			o[0][i] = b1[0]; o[1][i] = b1[1]; o[2][i] = b1[2];
			o[3][i] = b2[0]; o[4][i] = b2[1]; o[5][i] = b2[2];
		}
	} else if (s->prec == PREC_DOUBLE) {
		const double *const *in = (const double *const *)s->in;
		double *const *o = (double *const *)s->out;
		s->batch(hi - lo, in[0] + lo, in[1] + lo, in[2] + lo,
		         o[0] + lo, o[1] + lo, o[2] + lo, o[3] + lo, o[4] + lo, o[5] + lo);
	} else {
		const float *const *in = (const float *const *)s->in;
		float *const *o = (float *const *)s->out;
		s->batchf(hi - lo, in[0] + lo, in[1] + lo, in[2] + lo,
		          o[0] + lo, o[1] + lo, o[2] + lo, o[3] + lo, o[4] + lo, o[5] + lo);
	}
}

double bench_soa_checksum(const bench_soa *s)
{
	double sum = 0.0;
	size_t i;
	int k;
	for (i = 0; i < s->n; i++) {
		double b = 0.0;
		for (k = 0; k < 6; k++)
			b += s->prec == PREC_DOUBLE ? ((const double *)s->out[k])[i] :
			     s->prec == PREC_HALF ? prec_half_value(((const uint16_t *)s->out[k])[i]) :
			     (double)((const float *)s->out[k])[i];
		sum += b;
	}
	return sum;
}

/* ---- inputs ----------------------------------------------------------- */


void bench_fill_uniform(size_t n, uint64_t seed, double *x, double *y, double *z)
{
	const double two_pi = 6.283185307179586476925286766559;
	size_t i;
	for (i = 0; i < n; i++) {
		const uint64_t a = rng_mix64(seed ^ rng_mix64(2 * (uint64_t)i));
		const uint64_t b = rng_mix64(seed ^ rng_mix64(2 * (uint64_t)i + 1));
		const double u = (double)(a >> 11) * 0x1p-53, v = (double)(b >> 11) * 0x1p-53;
		const double zz = 2.0 * u - 1.0, r = sqrt(fmax(0.0, 1.0 - zz * zz)), ph = two_pi * v;
		x[i] = r * cos(ph);
		y[i] = r * sin(ph);
		z[i] = zz;
	}
}

/* ---- vectorization probe ------------------------------------------------ */

typedef struct {
	char name[96];
	int width; /* 0 scalar, 1 xmm, 2 ymm, 3 zmm */
} probe_fn;

static probe_fn *probe_tab;
static size_t probe_n;
static int probe_state; /* 0 not run, 1 ok, -1 failed */

static int packed_arith(const char *mn)
{
	static const char *ops[] = { "add", "sub", "mul", "div", "sqrt", "rsqrt", "min", "max", NULL };
	size_t k, l;
	if (mn[0] == 'v')
		mn++;
	for (k = 0; ops[k]; k++) {
		l = strlen(ops[k]);
		if (strncmp(mn, ops[k], l) == 0 && (strcmp(mn + l, "ps") == 0 || strcmp(mn + l, "pd") == 0 ||
		                                    strncmp(mn + l, "ps ", 3) == 0 || strncmp(mn + l, "pd ", 3) == 0))
			return 1;
	}
	return 0;
}

static void probe_run(void)
{
	FILE *p;
	char line[1024], cmd[128];
	size_t cap = 0;
	probe_fn *cur = NULL;
	probe_state = -1;
	/* /proc/<pid>/exe: in the shell that popen starts, /proc/self is objdump */
	snprintf(cmd, sizeof cmd, "objdump -d --no-show-raw-insn /proc/%ld/exe 2>/dev/null", (long)getpid());
	p = popen(cmd, "r");
	if (!p)
		return;
	while (fgets(line, sizeof line, p)) {
		char *lt = strchr(line, '<');
		if (line[0] != ' ' && lt && strstr(line, ">:")) {
			char *gt = strstr(lt, ">:");
			size_t l = (size_t)(gt - lt - 1);
			cur = NULL;
			if (l < sizeof cur->name && (strncmp(lt + 1, "onb_", 4) == 0 || strncmp(lt + 1, "bench_", 6) == 0)) {
				if (probe_n == cap) {
					probe_fn *t;
					cap = cap ? 2 * cap : 256;
					t = realloc(probe_tab, cap * sizeof *t);
					if (!t)
						break;
					probe_tab = t;
				}
				cur = &probe_tab[probe_n++];
				memcpy(cur->name, lt + 1, l);
				cur->name[l] = '\0';
				cur->width = 0;
			}
		} else if (cur) {
			/* "  4011a0:\tvmulps %zmm1,%zmm2,%zmm3" */
			char *tab = strchr(line, '\t');
			char mn[32];
			/* packed arithmetic at any width; packed loads and stores
			   (the copy kernel) only at ymm or zmm, since scalar code moves
			   xmm registers with movaps too */
			if (tab && sscanf(tab + 1, "%31s", mn) == 1 &&
			    (packed_arith(mn) || (strstr(mn, "mov") && strchr(tab, '(') && (strstr(tab, "%ymm") || strstr(tab, "%zmm"))))) {
				int w = strstr(tab, "%zmm") ? 3 : strstr(tab, "%ymm") ? 2 : 1;
				if (w > cur->width)
					cur->width = w;
			}
		}
	}
	if (pclose(p) == 0 && probe_n > 0)
		probe_state = 1;
}

const char *bench_vector_width(const char *symbol)
{
	static const char *names[] = { "scalar", "xmm", "ymm", "zmm" };
	size_t i;
	if (probe_state == 0)
		probe_run();
	if (probe_state < 0)
		return "unknown";
	for (i = 0; i < probe_n; i++)
		if (strcmp(probe_tab[i].name, symbol) == 0)
			return names[probe_tab[i].width];
	return "unknown";
}

/* /proc/loadavg's first three fields, or "unknown" (bench and bench --reference). */
void bench_loadavg(char *buf, size_t n)
{
	FILE *f = fopen("/proc/loadavg", "r");
	double a = 0, b = 0, c = 0;
	if (f && fscanf(f, "%lf %lf %lf", &a, &b, &c) == 3)
		snprintf(buf, n, "%.2f %.2f %.2f", a, b, c);
	else
		snprintf(buf, n, "unknown");
	if (f)
		fclose(f);
}
