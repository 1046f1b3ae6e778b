/*
 * bench.h - the machinery of `onbstudy bench` and `onbstudy table`, apart
 * from the commands so that tests/test_bench.c and tests/test_table.c can
 * check it: timers, the repetition runner, checksums, inputs, the inline
 * call loops, the yardstick loops, the vectorization probe and the
 * trade-table join.
 */
#ifndef ONB_BENCH_H
#define ONB_BENCH_H

#include <stddef.h>
#include <stdint.h>
#include "onb.h"

/* ---- clocks ------------------------------------------------------- */
double   bench_now(void);        /* CLOCK_MONOTONIC, seconds            */
void     bench_loadavg(char *buf, size_t n); /* /proc/loadavg's first three fields, or "unknown" */
uint64_t bench_tsc(void);        /* rdtsc, or 0 off x86                 */
/* 1 when /proc/cpuinfo lists both constant_tsc and nonstop_tsc: TSC ticks
   then count wall time at the nominal frequency (not the turbo clock). */
int      bench_tsc_constant(void);
/* TSC ticks per nanosecond, calibrated against CLOCK_MONOTONIC over
   `seconds`; 0 without a usable TSC. */
double   bench_tsc_ghz(double seconds);

/* ---- the repetition runner ---------------------------------------- */
/* A kernel processes the items [lo, hi) of its job once. */
typedef void (*bench_kernel)(void *ctx, size_t lo, size_t hi);

typedef struct {
	int    threads;   /* OpenMP threads; each runs its own slice of [0, n)  */
	int    warmup;    /* untimed repetitions first                          */
	int    reps;      /* timed repetitions (<= BENCH_MAX_REPS)               */
	size_t inner;     /* passes over [0, n) per repetition (>= 1)           */
} bench_cfg;

#define BENCH_MAX_REPS 64

typedef struct {
	size_t   n;             /* items per pass                                 */
	int      reps;          /* timed repetitions                              */
	size_t   passes;        /* timed passes in total = reps * inner           */
	int      threads;       /* threads the OpenMP team really had             */
	double   median_s;      /* seconds per pass: median over repetitions      */
	double   min_s;         /* ...and minimum                                 */
	double   median_ticks;  /* TSC ticks per pass (0 without TSC)             */
	double   min_ticks;
} bench_result;

/* Runs warmup + reps repetitions of `inner` passes of k over [0, n), the
   items split into one contiguous slice per thread, and times each
   repetition between two barriers.  Returns 0, or -1 on a bad cfg. */
int bench_run(bench_kernel k, void *ctx, size_t n, const bench_cfg *cfg, bench_result *r);
/* The number of passes per repetition for which one repetition takes at
   least target_s (grown from 1 by timed trial repetitions; at most
   max_inner). */
size_t bench_calibrate(bench_kernel k, void *ctx, size_t n, int threads, double target_s, size_t max_inner);
/* Median and minimum of v[0..n) (v is reordered). */
double bench_median(double *v, size_t n);
double bench_min(const double *v, size_t n);

/* ---- structure-of-arrays buffers and the batch kernel adaptor ------- */
typedef struct {
	int     dbl;            /* 1: double arrays, 0: float arrays               */
	size_t  n;
	void   *in[3];          /* nx, ny, nz                                      */
	void   *out[6];         /* b1x, b1y, b1z, b2x, b2y, b2z                    */
	onb_batch_fn  batch;    /* the kernel the adaptor calls (one of the two)   */
	onb_batchf_fn batchf;
} bench_soa;

/* Allocates n items in one precision (64-byte aligned arrays, outputs
   zeroed); 0 or -1. */
int  bench_soa_alloc(bench_soa *s, size_t n, int dbl);
void bench_soa_free(bench_soa *s);
/* bench_kernel that runs s->batch or s->batchf on [lo, hi). */
void bench_soa_kernel(void *soa, size_t lo, size_t hi);
/* The sum of the six outputs over [0, n), in index order, in double. */
double bench_soa_checksum(const bench_soa *s);

/* Uniform directions on the sphere, from a counter-based generator: item i
   depends only on (seed, i).  Double arrays; a float copy rounds each
   component once. */
void bench_fill_uniform(size_t n, uint64_t seed, double *x, double *y, double *z);

/* ---- the inline call loops (macro-generated in bench_calls.c) -------- */
typedef struct { onb_vec3  b1, b2; } bench_pair;
typedef struct { onb_vec3f b1, b2; } bench_pairf;
typedef struct {
	const char *name;
	/* Throughput: out[i] = method(in[i]) for i < n, independent calls to
	   the static inline function, as a shading loop over structs makes. */
	void   (*tp) (size_t n, const onb_vec3  *in, bench_pair  *out);
	void   (*tpf)(size_t n, const onb_vec3f *in, bench_pairf *out);
	/* Latency: a chain of n calls, each input in[i] plus t, where
	   t = (b1.x + b2.x) * 0 of the previous call: an exact zero the
	   compiler cannot fold, so each call waits for the last.  Returns the
	   sum of the six outputs of every call. */
	double (*lat) (size_t n, const onb_vec3  *in);
	double (*latf)(size_t n, const onb_vec3f *in);
} bench_call;

/* The entry of registry method `name`, or NULL.  The pseudo-method
   "chain" returns b1 = b2 = n: its latency is the cost of the chain alone. */
const bench_call *bench_call_find(const char *name);
/* The instruction set the call loops were compiled for ("inline-sse2"...). */
const char *bench_calls_isa(void);
double bench_pair_checksum (size_t n, const bench_pair  *p);
double bench_pair_checksumf(size_t n, const bench_pairf *p);

/* ---- yardstick.c: compiled -O3 -march=native -------------------------- */
typedef struct {
	const char   *name;     /* the registry method it re-implements */
	onb_batch_fn  batch;
	onb_batchf_fn batchf;
} bench_yardstick;
const bench_yardstick *bench_yardsticks(size_t *count);
/* The roofline: b1 = n and b2 = n, read three arrays and write six. */
void bench_copy  (size_t count, const double *nx, const double *ny, const double *nz,
                  double *b1x, double *b1y, double *b1z, double *b2x, double *b2y, double *b2z);
void bench_copyf (size_t count, const float *nx, const float *ny, const float *nz,
                  float *b1x, float *b1y, float *b1z, float *b2x, float *b2y, float *b2z);
/* The -march the yardstick was built for, as its predefined macros say. */
const char *bench_yardstick_isa(void);

/* ---- vectorization probe --------------------------------------------- */
/* Disassembles the running executable (objdump -d /proc/self/exe) once and
   reports, for a function symbol, the widest register its packed
   floating-point arithmetic uses: "zmm", "ymm", "xmm", "scalar" (no
   packed arithmetic), or "unknown" (no objdump, or no such symbol). */
const char *bench_vector_width(const char *symbol);

/* ---- the trade table (table.c) ---------------------------------------- */
typedef struct {
	char   method[64];
	int    dbl;               /* precision: 1 double, 0 float                */
	double batch1;            /* batch M bases/s, 1 thread, L2-resident      */
	double batchn;            /* batch M bases/s, all threads, L2-resident   */
	int    threads;           /* threads of batchn                           */
	double call_ns;           /* call_throughput ns per call                 */
	double rmse_uniform;
	double max_south;         /* max_defect on south                         */
	double max_threshold;     /* max_defect on threshold                     */
	double max_worst;         /* max of max_defect over uniform, south, threshold */
	long   nonfinite;         /* nonfinite over the three                    */
	/* The accuracy floor on uniform (issue 16; NaN when summary.csv
	   predates it): max_defect, the floor's max, x_floor = their ratio
	   (how far the method's worst case sits above the best the format can
	   hold), and the per-input ratio's RMS and max. */
	double max_uniform, max_floor_uniform, x_floor, rms_ratio_uniform, max_ratio_uniform;
	int    has_speed, has_accuracy;
	int    pareto;            /* 1 on the front of its precision             */
} tradeoff_row;

/* Reads bench.csv and summary.csv (lines starting with '#' skipped,
   columns found by header name) and joins them into rows (one per method
   and precision found in bench.csv, in its order) and marks the front.
   Returns the number of rows, or -1 with a message.  *rows is malloc'ed. */
int  tradeoff_load(const char *bench_csv, const char *summary_csv, double tol, tradeoff_row **rows);
/* Marks the Pareto front per precision, speeds within the fraction tol
   counting as equal (see table.c). */
void tradeoff_pareto(tradeoff_row *rows, int n, double tol);

/* bench_ref.c: `onbstudy bench --reference` (issue 14); 0, or 1 after a message. */
int bench_reference(const char *out, int quick, unsigned long long seed);

#endif
