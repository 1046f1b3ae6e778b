/*
 * speed.h - the batch throughput that `onbstudy scene` ranks methods by
 *.  The scene never times itself: a few hundred normals timed
 * on a shared machine gave a different "fastest" method run after run.
 * Speed comes instead from one of, in this order:
 *   1. a file named with --speed FILE: a bench.csv of `onbstudy bench`;
 *   2. the per-machine cache, measured by `onbstudy scene --refresh-speed`
 *      and reused: $XDG_CACHE_HOME/onbstudy (else ~/.cache/onbstudy),
 *      speed-<key>.csv, where key hashes the CPU model, the git revision,
 *      the compiler flags, the batch ISA and the precision;
 *   3. the committed reference run, results/reference/bench.csv beside the
 *      executable (or in the working directory).
 * Every figure is the batch kernel's throughput on 1 thread with an
 * L2-resident working set (bench's "batch,1,l2" row), with an interval:
 *   cache     a distribution-free ~95% confidence interval of the median
 *             over the repetitions (order statistics of the binomial(n, 1/2));
 *   bench.csv the file keeps the median and the best repetition only, so
 *             the interval is median -/+ (best - median).
 */
#ifndef ONB_SPEED_H
#define ONB_SPEED_H

#include <stddef.h>

typedef struct {
	char   method[64];
	double med, lo, hi;   /* M bases/s: median and interval */
} speed_row;

enum { SPEED_FILE = 1, SPEED_CACHE, SPEED_REFERENCE };

typedef struct {
	speed_row *rows;
	size_t n;
	int kind;             /* SPEED_* */
	int reps;             /* repetitions behind each figure (0: unknown) */
	char path[4096];      /* the file read */
	char desc[512];       /* its provenance, one line */
} speed_table;

/* Loads (or, with refresh, measures and caches) the speeds of precision
   prec.  file: an explicit bench.csv, or NULL.  reps: repetitions of a
   refresh (>= 3).  Returns 0, or -1 with a message on stderr. */
int  speed_load(int prec, const char *file, int refresh, int reps, speed_table *t);
void speed_free(speed_table *t);
/* The row of method `name`, or NULL. */
const speed_row *speed_find(const speed_table *t, const char *name);
/* Rank (1-based) of the lower end of a distribution-free confidence
   interval of the median of n samples, at >= 95% where n allows
   (n >= 6); 1 (the minimum) below that. */
int  speed_ci_rank(int n);
/* The cache file for precision prec on this machine and build. */
int  speed_cache_path(int prec, char *buf, size_t n);

#endif
