/*
 * bench/bench.h - `onbstudy bench` (bench.c).  src/bench/ holds the benchmark: its
 * machinery (bench_core.h: clocks, the repetition runner, SoA buffers, the
 * vectorization probe), the inline call loops (bench_calls.h), the
 * -march=native yardstick (yardstick.h), referenced evaluations per second
 * (bench_ref.h) and the trade table that joins bench.csv with a sweep's
 * summary.csv (table.h).
 */
#ifndef ONB_BENCH_H
#define ONB_BENCH_H

int cmd_bench(int argc, char **argv);

#endif
