/*
 * clientkit.h - what the client timing programs share (entries.c and
 * percall_main.c): the thread's CPU clock, the comparison their medians
 * sort with, and the unit directions they time, from an LCG.  Needs
 * _POSIX_C_SOURCE 200809L (clock_gettime) before the first include.
 */
#ifndef ONB_TESTS_CLIENTKIT_H
#define ONB_TESTS_CLIENTKIT_H

#include <math.h>
#include <stdint.h>
#include <time.h>

/* The thread's CPU time, not the wall clock: on a shared machine the time
   this thread spends descheduled is not counted. */
static inline double now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static inline int cmpd(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* The next direction v of the LCG in *s (each component in [-1, 1),
   |v| >= 1/16 so that v / |v| is well rounded); returns |v|. */
static inline double lcg_dir(uint32_t *s, double v[3])
{
	double l;
	int c;
	do {
		for (c = 0; c < 3; c++) {
			*s = *s * 1664525u + 1013904223u;
			v[c] = (double)(int32_t)*s * 0x1p-31;
		}
		l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
	} while (l < 0x1p-4);
	return l;
}

#endif
