/*
 * bench/bench_ref.h - `onbstudy bench --reference` (bench_ref.c).
 */
#ifndef ONB_BENCH_REF_H
#define ONB_BENCH_REF_H

/* Referenced evaluations per second per core into OUT/bench-reference.csv;
   0, or 1 after a message. */
int bench_reference(const char *out, int quick, unsigned long long seed);

#endif
