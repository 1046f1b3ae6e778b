/*
 * bench/bench_core.h - the machinery of `onbstudy bench` (bench_core.c), apart
 * from the command so that tests/test_bench.c can check it: clocks, the
 * repetition runner, SoA buffers and checksums, inputs, and the
 * vectorization probe.
 */
#ifndef ONB_BENCH_CORE_H
#define ONB_BENCH_CORE_H

#include <stddef.h>
#include <stdint.h>
#include "libonb/onb.h"

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
/* A SoA loop over binary16 bit patterns (the half copy roofline). */
typedef void (*bench_batchh_fn)(size_t count, const uint16_t *nx, const uint16_t *ny, const uint16_t *nz,
                                uint16_t *b1x, uint16_t *b1y, uint16_t *b1z, uint16_t *b2x, uint16_t *b2y, uint16_t *b2z);
typedef struct {
	int     prec;           /* PREC_DOUBLE: double arrays, PREC_FLOAT: float,  */
	size_t  n;              /* PREC_HALF: binary16 bit patterns (uint16_t)     */
	void   *in[3];          /* nx, ny, nz                                      */
	void   *out[6];         /* b1x, b1y, b1z, b2x, b2y, b2z                    */
	onb_batch_fn  batch;    /* the kernel the adaptor calls (one of these)     */
	onb_batchf_fn batchf;
	bench_batchh_fn batchh; /* half: a SoA loop, else arrayh once per basis   */
	onb_arrayh_fn arrayh;
} bench_soa;

/* Allocates n items in one precision (64-byte aligned arrays, outputs
   zeroed); 0 or -1. */
int  bench_soa_alloc(bench_soa *s, size_t n, int prec);
void bench_soa_free(bench_soa *s);
/* bench_kernel that runs s->batch or s->batchf on [lo, hi). */
void bench_soa_kernel(void *soa, size_t lo, size_t hi);
/* The sum of the six outputs over [0, n), in index order, in double. */
double bench_soa_checksum(const bench_soa *s);

/* Uniform directions on the sphere, from a counter-based generator: item i
   depends only on (seed, i).  Double arrays; a float copy rounds each
   component once. */
void bench_fill_uniform(size_t n, uint64_t seed, double *x, double *y, double *z);

/* ---- vectorization probe --------------------------------------------- */
/* Disassembles the running executable (objdump -d /proc/self/exe) once and
   reports, for a function symbol, the widest register its packed
   floating-point arithmetic uses: "zmm", "ymm", "xmm", "scalar" (no
   packed arithmetic), or "unknown" (no objdump, or no such symbol). */
const char *bench_vector_width(const char *symbol);


#endif
