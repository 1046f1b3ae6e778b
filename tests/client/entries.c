/*
 * entries.c - what one basis costs through each of libonb's entries, in
 * the same throughput loop (independent calls over K inputs):
 *   inline    the method name onb_NAME[f], inlined (built with the
 *             library's flags, so the header inlines it)
 *   outline   onb_NAME_outline[f](n, &b1, &b2): by value, out of line
 *   array     onb_NAME_array[f](&n.x, &b1.x, &b2.x)
 *   registry  onb_basis_array[f](method, &n.x, &b1.x, &b2.x)
 * ns per basis (thread CPU time): the median of RUNS runs of REPS passes.  One line per
 * method and precision:
 *   method precision inline outline array registry
 * scripts/entry-bench.sh runs it several times and writes the table of
 * results/clients/entries.md.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include <math.h>
#include <time.h>
#include "libonb/onb.h"
#include "clientkit.h"

#define K 4096
#define RUNS 7

static onb_vec3 nd[K], d1[K], d2[K];
static onb_vec3f nf[K], f1[K], f2[K];
static int reps = 100;
static const char *only; /* one method's rows alone (for perf stat) */

/* Unit directions from an LCG. */
static void inputs(void)
{
	uint32_t s = 2025u;
	int i;
	for (i = 0; i < K; i++) {
		double v[3], l = lcg_dir(&s, v);
		nd[i].x = v[0] / l; nd[i].y = v[1] / l; nd[i].z = v[2] / l;
		nf[i].x = (float)nd[i].x; nf[i].y = (float)nd[i].y; nf[i].z = (float)nd[i].z;
	}
}

/* One timed loop: the median ns per basis of RUNS runs of `body`. */
#define TIME(result, body)                                                     \
	do {                                                                       \
		double t_[RUNS];                                                       \
		int r_, p_;                                                            \
		size_t i;                                                              \
		for (r_ = 0; r_ < RUNS; r_++) {                                        \
			double t0_ = now();                                                \
			for (p_ = 0; p_ < reps; p_++)                                      \
				for (i = 0; i < K; i++) { body; }                              \
			t_[r_] = (now() - t0_) * 1e9 / ((double)reps * K);                 \
		}                                                                      \
		qsort(t_, RUNS, sizeof *t_, cmpd);                                     \
		result = t_[RUNS / 2];                                                 \
	} while (0)

#define BENCH_D(m)                                                             \
	static void bench_##m(void)                                                \
	{                                                                          \
		const onb_method *meth = onb_find(#m);                                 \
		double a, b, c, d;                                                     \
		if (only && strcmp(only, #m) != 0)                                     \
			return;                                                            \
		TIME(a, onb_##m(nd[i], &d1[i], &d2[i]));                               \
		TIME(b, onb_##m##_outline(nd[i], &d1[i], &d2[i]));                     \
		TIME(c, onb_##m##_array(&nd[i].x, &d1[i].x, &d2[i].x));                \
		TIME(d, onb_basis_array(meth, &nd[i].x, &d1[i].x, &d2[i].x));          \
		printf("%-24s double %7.2f %7.2f %7.2f %7.2f\n", #m, a, b, c, d);     \
	}
#define BENCH_F(m)                                                             \
	static void bench_##m##f(void)                                             \
	{                                                                          \
		const onb_method *meth = onb_find(#m);                                 \
		double a, b, c, d;                                                     \
		if (only && strcmp(only, #m) != 0)                                     \
			return;                                                            \
		TIME(a, onb_##m##f(nf[i], &f1[i], &f2[i]));                            \
		TIME(b, onb_##m##_outlinef(nf[i], &f1[i], &f2[i]));                    \
		TIME(c, onb_##m##_arrayf(&nf[i].x, &f1[i].x, &f2[i].x));               \
		TIME(d, onb_basis_arrayf(meth, &nf[i].x, &f1[i].x, &f2[i].x));         \
		printf("%-24s float  %7.2f %7.2f %7.2f %7.2f\n", #m, a, b, c, d);     \
	}
ONB_METHOD_LIST(BENCH_D)
ONB_METHOD_LIST(BENCH_F)
ONB_FLOAT_METHOD_LIST(BENCH_F)

int main(int argc, char **argv)
{
	if ((argc > 1 && (reps = atoi(argv[1])) < 1) || argc > 3 || (argc > 2 && !onb_find(argv[2]))) {
		fprintf(stderr, "usage: entries [passes >= 1 [method]]\n");
		return 2;
	}
	if (argc > 2)
		only = argv[2];
	inputs();
#define RUN(m) bench_##m##f(); bench_##m();
	ONB_METHOD_LIST(RUN)
#define RUNF(m) bench_##m##f();
	ONB_FLOAT_METHOD_LIST(RUNF)
	return 0;
}
