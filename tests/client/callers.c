/*
 * callers.c - what one basis costs through libonb's out-of-line entries
 * in the ways a renderer calls them.  Built with the client's flags, as C
 * and as C++ (scripts/entry-bench.sh: gcc, g++, clang, clang++ at -O2 and
 * -O3 -march=native), linked to libonb.a.  The patterns, each in the same
 * throughput loop (independent calls over K inputs):
 *   array    onb_NAME_array[f](&n[i].x, &b1[i].x, &b2[i].x): the reference
 *   out      onb_NAME_outline[f](n[i], &b1[i], &b2[i]): results stored
 *            straight into arrays
 *   copy     onb_vec3[f] u, v; onb_NAME_outline[f](n[i], &u, &v);
 *            b1[i] = u; b2[i] = v: results kept in locals, copied as structs
 *   members  the same locals, read member by member into separate arrays
 *            (b1x[i] = u.x; b1y[i] = u.y; ...)
 *   acopy    T u[3], v[3]; onb_NAME_array[f](&n[i].x, u, v); then
 *            b1[i].x = u[0]; ...: the array entry into locals, copied
 *   name     onb_NAME[f](n[i], &u, &v); b1[i] = u; b2[i] = v: the method
 *            name, which onb.h inlines or turns into a call of
 *            onb_NAME_outline[f] depending on the build (ONB_INLINE_ACTIVE)
 * Each run times every pattern once, in turn, so that a change of the
 * machine's load hits all of them alike; a figure is the median of RUNS
 * runs of `passes` passes, in ns per basis (thread CPU time).  Prints
 *   # inline_active 0|1
 * then one line per method and precision:
 *   method precision array out copy members acopy name
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
#define NPAT 6

static onb_vec3 nd[K], d1[K], d2[K];
static onb_vec3f nf[K], f1[K], f2[K];
static double dx1[K], dy1[K], dz1[K], dx2[K], dy2[K], dz2[K];
static float fx1[K], fy1[K], fz1[K], fx2[K], fy2[K], fz2[K];
static int reps = 100;
static const char *only; /* one method's rows alone */

/* Unit directions from an LCG (the same as entries.c's). */
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

/* One pass set of pattern P (0..NPAT-1) in run R: t[P][R] in ns per basis. */
#define PASS(P, R, ...)                                                        \
	do {                                                                       \
		double t0_ = now();                                                    \
		int p_;                                                                \
		size_t i;                                                              \
		for (p_ = 0; p_ < reps; p_++)                                          \
			for (i = 0; i < K; i++) { __VA_ARGS__; }                           \
		t[P][R] = (now() - t0_) * 1e9 / ((double)reps * K);                    \
	} while (0)

/* The median of each pattern's runs, printed as one line. */
static void report(const char *m, const char *prec, double t[NPAT][RUNS])
{
	int p;
	printf("%-24s %-6s", m, prec);
	for (p = 0; p < NPAT; p++) {
		qsort(t[p], RUNS, sizeof t[p][0], cmpd);
		printf(" %7.2f", t[p][RUNS / 2]);
	}
	printf("\n");
}

/* V: onb_vec3 or onb_vec3f; T: its element; S: "" or "f"; the arrays. */
#define BENCH(m, sfx, V, T, prec, n, b1, b2, x1, y1, z1, x2, y2, z2)            \
	static void bench_##m##sfx(void)                                           \
	{                                                                          \
		double t[NPAT][RUNS];                                                  \
		int r;                                                                 \
		if (only && strcmp(only, #m) != 0)                                     \
			return;                                                            \
		for (r = 0; r < RUNS; r++) {                                           \
			PASS(0, r, onb_##m##_array##sfx(&n[i].x, &b1[i].x, &b2[i].x));     \
			PASS(1, r, onb_##m##_outline##sfx(n[i], &b1[i], &b2[i]));          \
			PASS(2, r, V u; V v; onb_##m##_outline##sfx(n[i], &u, &v);         \
			     b1[i] = u; b2[i] = v);                                        \
			PASS(3, r, V u; V v; onb_##m##_outline##sfx(n[i], &u, &v);         \
			     x1[i] = u.x; y1[i] = u.y; z1[i] = u.z;                        \
			     x2[i] = v.x; y2[i] = v.y; z2[i] = v.z);                       \
			PASS(4, r, T u[3]; T v[3]; onb_##m##_array##sfx(&n[i].x, u, v);    \
			     b1[i].x = u[0]; b1[i].y = u[1]; b1[i].z = u[2];               \
			     b2[i].x = v[0]; b2[i].y = v[1]; b2[i].z = v[2]);              \
			PASS(5, r, V u; V v; onb_##m##sfx(n[i], &u, &v);                   \
			     b1[i] = u; b2[i] = v);                                        \
		}                                                                      \
		report(#m, prec, t);                                                   \
	}
#define BENCH_D(m) BENCH(m, , onb_vec3, double, "double", nd, d1, d2, dx1, dy1, dz1, dx2, dy2, dz2)
#define BENCH_F(m) BENCH(m, f, onb_vec3f, float, "float", nf, f1, f2, fx1, fy1, fz1, fx2, fy2, fz2)
ONB_METHOD_LIST(BENCH_D)
ONB_METHOD_LIST(BENCH_F)
ONB_FLOAT_METHOD_LIST(BENCH_F)

int main(int argc, char **argv)
{
	if ((argc > 1 && (reps = atoi(argv[1])) < 1) || argc > 3 || (argc > 2 && !onb_find(argv[2]))) {
		fprintf(stderr, "usage: callers [passes >= 1 [method]]\n");
		return 2;
	}
	if (argc > 2)
		only = argv[2];
	inputs();
	printf("# inline_active %d\n", ONB_INLINE_ACTIVE);
#define RUN(m) bench_##m##f(); bench_##m();
	ONB_METHOD_LIST(RUN)
#define RUNF(m) bench_##m##f();
	ONB_FLOAT_METHOD_LIST(RUNF)
	return 0;
}
