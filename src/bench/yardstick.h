/*
 * bench/yardstick.h - the benchmark's yardstick (yardstick.c): hand-written
 * -march=native SoA loops of four methods, and the copy roofline.
 */
#ifndef ONB_YARDSTICK_H
#define ONB_YARDSTICK_H

#include <stddef.h>
#include <stdint.h>
#include "libonb/onb.h"

/* ---- yardstick.c: compiled -O3 -march=native -------------------------- */
typedef struct {
	const char   *name;     /* the registry method it re-implements */
	onb_batch_fn  batch;
	onb_batchf_fn batchf;
} bench_yardstick;
const bench_yardstick *bench_yardsticks(size_t *count);
/* The roofline: b1 = n and b2 = n, read three arrays and write six. */
void bench_copy  (size_t count, const double *nx, const double *ny, const double *nz,
                  double *b1x, double *b1y, double *b1z, double *b2x, double *b2y, double *b2z);
void bench_copyf (size_t count, const float *nx, const float *ny, const float *nz,
                  float *b1x, float *b1y, float *b1z, float *b2x, float *b2y, float *b2z);
void bench_copyh (size_t count, const uint16_t *nx, const uint16_t *ny, const uint16_t *nz,
                  uint16_t *b1x, uint16_t *b1y, uint16_t *b1z, uint16_t *b2x, uint16_t *b2y, uint16_t *b2z);
/* The -march the yardstick was built for, as its predefined macros say. */
const char *bench_yardstick_isa(void);


#endif
