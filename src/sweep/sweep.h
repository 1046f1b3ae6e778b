/*
 * sweep/sweep.h - `onbstudy sweep` and `onbstudy merge` (sweep.c).  src/sweep/ holds the
 * sweep, whose data flows one way: plan.h (what to compute) -> engine.h
 * (sampling, kernels, reference, metrics and the worst-case walk) ->
 * state.h (the one owner of the accumulators, the grid layout, slices,
 * merging and state files) -> writers.h (the CSV files and stdout, from a
 * const state).  fx.h is its exact sums; threshold.c is Max's threshold
 * analysis, which shares the state files' merge command.
 */
#ifndef ONB_SWEEP_H
#define ONB_SWEEP_H

#include "sweep/plan.h"

int cmd_sweep(int argc, char **argv);
int cmd_merge(int argc, char **argv);
/* The writers' side of cmd_sweep (also used by the MPI driver): refuse an
   unusable output directory (0, or -1 after a message), and write a
   finished run's files (a shard's state, or the worst-case walk then the
   CSV files, results/latest, --plots); 0 or 1. */
int sweep_outdir(const char *out);
int sweep_write(const sweep_plan *pl, sweep_state *st, double seconds);

#endif
