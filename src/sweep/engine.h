/*
 * engine.h - the sweep engine: runs chunks of a plan (plan.h) into a
 * sweep_state's accumulators (sweep.h), with OpenMP threads inside.
 *
 * Every accumulation is order-independent (exact fixed-point sums, maxima,
 * worst lists in a total order, grid cells written once), so the state
 * after running a set of chunks does not depend on the thread count, on
 * the order of the calls, or on how the chunks were split between calls,
 * processes (shards) or MPI ranks: running every chunk once, in any
 * grouping, and merging the states (sweep_merge_into) gives the same bytes.
 *
 *	engine *e = engine_new(&plan);         // prepares every distribution
 *	sweep_state st; engine_state_init(&plan, &st);
 *	engine_run(e, &st, 0, plan.chunks, &progress);   // or any [g0, g1)
 *	engine_free(e);  engine_walk(&st, threads);  // once, on the whole state
 *	... sweep_finish(&st, ...) writes the files from the const state
 */
#ifndef ONB_ENGINE_H
#define ONB_ENGINE_H

#include <signal.h>
#include "sweep/plan.h"
#include "common/progress.h"

typedef struct engine engine;

/* Set (from a signal handler, say) to stop: the running chunks finish,
   the rest are skipped, and engine_run returns ENGINE_STOPPED. */
extern volatile sig_atomic_t engine_stop;

enum { ENGINE_OK = 0, ENGINE_NOMEM = -1, ENGINE_DISAGREE = -2, ENGINE_STOPPED = 1 };

engine *engine_new(const sweep_plan *pl);          /* NULL after a message */
void    engine_free(engine *e);
/* The state's cfg and kernels from the plan, accumulators allocated and
   empty.  0, or -1 after a message. */
int     engine_state_init(const sweep_plan *pl, sweep_state *st);
/* Run the plan's global chunks g in [g0, g1) that belong to its shard
   into st (threads: pl->threads).  Returns an ENGINE_* code; after
   ENGINE_DISAGREE, engine_why() says which input.  pr: the engine adds
   the evaluations it completes to pr->done, and thread 0 prints the
   progress line (common/progress.h) when pr->bar is set. */
int     engine_run(engine *e, sweep_state *st, uint64_t g0, uint64_t g1, study_progress *pr);
const char *engine_why(const engine *e);
/* Evaluations per second per thread, timed on up to `chunks` chunks spread
   over the plan (for --dry-run); *evals gets how many were timed. */
double  engine_calibrate(engine *e, int chunks, unsigned long long *evals);

/* The worst-case walk, the engine's last stage, run once on a finished
   (merged) state before the writers: see engine.c.  0, or -1 after a
   message. */
int     engine_walk(sweep_state *s, int threads);


#endif
