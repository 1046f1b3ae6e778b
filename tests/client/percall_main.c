/*
 * percall_main.c - scripts/client-bench.sh's driver, built with the
 * library's flags: times each loop of percall_kern.c (ns per call, thread
 * CPU time: the median of RUNS runs of REPS passes over K inputs) and
 * compares its outputs with libonb.a's out-of-line copies (the studied
 * bits) bit for bit.  One line per method and precision:
 *   method precision ns_median ns_min ns_max differing_inputs K
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#include <math.h>
#include <time.h>
#include "libonb/onb.h"
#include "clientkit.h"
#include "percall.h"

#define K 4096
#define RUNS 7

static onb_vec3 nd[K], d1[K], d2[K], r1[K], r2[K];
static onb_vec3f nf[K], f1[K], f2[K], s1[K], s2[K];
static int reps = 200;

/* Unit directions from integers (an LCG), the six poles among them. */
static void inputs(void)
{
	uint32_t s = 2025u;
	int i;
	static const double poles[6][3] = { {1,0,0}, {-1,0,0}, {0,1,0}, {0,-1,0}, {0,0,1}, {0,0,-1} };
	for (i = 0; i < K; i++) {
		double v[3], l = lcg_dir(&s, v);
		if (i < 6) { v[0] = poles[i][0]; v[1] = poles[i][1]; v[2] = poles[i][2]; l = 1.0; }
		nd[i].x = v[0] / l; nd[i].y = v[1] / l; nd[i].z = v[2] / l;
		nf[i].x = (float)nd[i].x; nf[i].y = (float)nd[i].y; nf[i].z = (float)nd[i].z;
	}
}

typedef void (*loopd)(size_t, const onb_vec3 *, onb_vec3 *, onb_vec3 *);
typedef void (*loopf)(size_t, const onb_vec3f *, onb_vec3f *, onb_vec3f *);

static void report(const char *m, const char *p, double *t, long diff)
{
	qsort(t, RUNS, sizeof *t, cmpd);
	printf("%-24s %-6s %7.2f %7.2f %7.2f %5ld %d\n", m, p, t[RUNS / 2], t[0], t[RUNS - 1], diff, K);
}

static void time_d(const char *m, loopd f, onb_basis_fn ref)
{
	double t[RUNS];
	long diff = 0;
	int r, i;
	for (r = 0; r < RUNS; r++) {
		double t0 = now();
		for (i = 0; i < reps; i++)
			f(K, nd, d1, d2);
		t[r] = (now() - t0) * 1e9 / ((double)reps * K);
	}
	for (i = 0; i < K; i++) {
		ref(nd[i], &r1[i], &r2[i]);
		diff += memcmp(&r1[i], &d1[i], sizeof r1[i]) != 0 || memcmp(&r2[i], &d2[i], sizeof r2[i]) != 0;
	}
	report(m, "double", t, diff);
}

static void time_f(const char *m, loopf f, onb_basisf_fn ref)
{
	double t[RUNS];
	long diff = 0;
	int r, i;
	for (r = 0; r < RUNS; r++) {
		double t0 = now();
		for (i = 0; i < reps; i++)
			f(K, nf, f1, f2);
		t[r] = (now() - t0) * 1e9 / ((double)reps * K);
	}
	for (i = 0; i < K; i++) {
		ref(nf[i], &s1[i], &s2[i]);
		diff += memcmp(&s1[i], &f1[i], sizeof s1[i]) != 0 || memcmp(&s2[i], &f2[i], sizeof s2[i]) != 0;
	}
	report(m, "float", t, diff);
}

int main(int argc, char **argv)
{
	if (argc > 1 && (reps = atoi(argv[1])) < 1) {
		fprintf(stderr, "usage: percall [passes >= 1]\n");
		return 2;
	}
	inputs();
#define RUN(m) time_d(#m, loop_##m, onb_##m##_outline); time_f(#m, loop_##m##f, onb_##m##_outlinef);
	ONB_METHOD_LIST(RUN)
#define RUNF(m) time_f(#m, loop_##m##f, onb_##m##_outlinef);
	ONB_FLOAT_METHOD_LIST(RUNF)
	return 0;
}
