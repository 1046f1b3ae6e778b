/*
 * sweep/writers.h - the sweep's output (writers.c): summary.csv, by_nz.csv,
 * worst.csv, grid.csv, reference.csv and the table on stdout, all from a
 * const state (the worst-case walk is the engine's, engine.h).
 */
#ifndef ONB_WRITERS_H
#define ONB_WRITERS_H

#include <stdio.h>
#include "sweep/state.h"

/* Every CSV file (the .partial.csv names when partial), then the table
   (fmt: the stdout format) of a run the engine has walked; 0 or -1. */
int  sweep_finish(const sweep_state *s, const char *outdir, int threads, const char *fmt, double seconds, int partial);
/* The reference path and its fallback rates, one line (prefix first), and
   per method and precision when per_method != 0. */
void sweep_print_reference(FILE *f, const sweep_state *s, const char *prefix, int per_method);


#endif
