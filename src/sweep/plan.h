/*
 * plan.h - a sweep's plan: what to compute (methods, precisions,
 * distributions and their sizes, seed, chunking, shard) and how to run it
 * (threads, output directory, stdout format).  Built from the command
 * line by plan_parse + plan_build, printable (--dry-run), and run by the
 * engine (engine.h).
 *
 * Chunking: the inputs of each (precision, distribution) are cut into
 * chunks of PLAN_CHUNK indices.  The chunks of the whole run are numbered
 * 0 .. chunks-1 ("global chunks"): first the float distributions in enum
 * order, then the double ones.  A shard K/N owns the chunks whose index
 * within their (precision, distribution) is K modulo N.
 */
#ifndef ONB_PLAN_H
#define ONB_PLAN_H

#include <stdio.h>
#include "sweep/state.h"
#include "model/arith.h"

#define PLAN_CHUNK 256

typedef struct {
	/* what defines the data: copied into sweep_state.cfg, saved in states */
	sweep_cfg cfg;
	study_kernel kernels[SWEEP_MAX_KERNELS];
	/* chunk layout: global chunk g of (p, d) is first[p][d] + c */
	uint64_t first[SWEEP_NPREC][NDIST], nchunks[SWEEP_NPREC][NDIST], chunks;
	unsigned long long evals;      /* referenced evaluations this shard runs (before the walk) */
	/* how to run it (changes no byte of the data) */
	int threads;                   /* resolved: never 0 */
	int quiet, plots, dry_run;
	int ref_given;                 /* --ref given (else a silent fallback to MPFR) */
	int fmt;                       /* 0 table, 1 csv, 2 json */
	int out_given;                 /* --out given (else results/latest follows the run) */
	char out[4096];
	/* --arith PROFILE (emusweep.h): the emulated conforming implementations
	   instead of the kernels; NULL for the plain sweep */
	const arith_profile *arith;
	int emu_random;                /* random implementations per input      */
	double widen;                  /* the mutation: allowances times this   */
	const char *bounds;            /* certify --arith CSV of whole-sphere bounds */
	/* parse-time only */
	const char *methods, *range;
	int samples_given, excount_given, plain_only; /* plain_only: an option --arith refuses */
} sweep_plan;

/* Options into pl (defaults first).  0; 1 after --help (printed); or
   ONB_EXIT_USAGE after one message. */
int  plan_parse(sweep_plan *pl, int argc, char **argv);
/* Kernels, input counts and the chunk layout.  0, or ONB_EXIT_USAGE /
   1 after one message. */
int  plan_build(sweep_plan *pl);
/* The input spec of (p, d), ready for dist_prepare (count set). */
void plan_dist_spec(const sweep_plan *pl, int p, int d, dist_spec *ds);
/* Global chunk g -> (p, d, chunk within it); 0, or -1 if g is past the end. */
int  plan_locate(const sweep_plan *pl, uint64_t g, int *p, int *d, uint64_t *c);
/* Whether global chunk g belongs to the plan's shard. */
int  plan_in_shard(const sweep_plan *pl, uint64_t g);
/* Human-readable plan; per_thread_rate > 0 adds the estimated time. */
void plan_print(const sweep_plan *pl, FILE *f, double per_thread_rate, unsigned long long calib_evals);
void plan_usage(FILE *f);
/* All cores OpenMP can use (threads = 0). */
int  plan_all_cores(void);

#endif
