/*
 * inputs.h - the input distributions of the sweep.  src/inputs/ holds them
 * (inputs.c) and the counter-based random numbers they draw (rng.h); the
 * sweep, threshold and bench --reference sample through them.
 *
 * Every input is a pure function of (distribution, precision, seed,
 * index), so a run is the same whatever its thread count or sharding.
 * Values are rounded to the format, as a renderer would receive them.
 *   uniform     uniform on the sphere
 *   north/south 1 -+ n.z log-uniform in [eps, 0.1], azimuth uniform
 *   threshold   a few ulps either side of every branch threshold of every
 *               method, the axes, and signed zeros (a fixed list)
 *   exhaustive  every representable n.z from a start value (default -1),
 *               at a fixed set of azimuths
 *   nonunit     uniform directions scaled by 1 + d, |d| log-uniform in
 *               [1e-7, 1e-2], both signs
 *   grid        cell centres of an equal-area (Lambert cylindrical) grid
 */
#ifndef ONB_INPUTS_H
#define ONB_INPUTS_H

#include <stdint.h>

enum { DIST_UNIFORM = 0, DIST_NORTH, DIST_SOUTH, DIST_THRESHOLD, DIST_EXHAUSTIVE,
       DIST_NONUNIT, DIST_GRID, NDIST };

typedef struct {
	int dist, prec;
	uint64_t seed;
	uint64_t count;        /* number of inputs                          */
	double ex_from;        /* exhaustive: first n.z                     */
	uint64_t ex_values;    /* exhaustive: consecutive n.z values        */
	int ex_azimuths;       /* exhaustive: azimuths per n.z              */
	int grid_rows, grid_cols;
	double *list;          /* threshold: 3 doubles per input            */
} dist_spec;

const char *dist_name(int d);
int dist_find(const char *name);            /* -1 if unknown */
const char *const *dist_names(void);       /* the NDIST names, in enum order */

/* Build what the distribution needs (the threshold list); count is set
   here for threshold, exhaustive and grid.  0, or -1 after a message. */
int dist_prepare(dist_spec *d);
void dist_free(dist_spec *d);

/* Input i: n (rounded to the format), a local direction for the direction
   error (cosine-weighted, rounded), and aux (nonunit: d; grid: cell). */
void dist_sample(const dist_spec *d, uint64_t i, double n[3], double loc[3], double *aux);

/* Strata of the uniform distribution: input i lies in stratum
   i mod NSTRAT of u = 1 + n.z, [2^(h-NSTRAT+1), 2^(h-NSTRAT+2)) for h >= 1
   and [0, 2^(2-NSTRAT)) for h = 0, uniform within it: finer towards -z,
   where Frisvad's error lives.  Estimates combine the strata with their
   exact probabilities (dist_stratum_weight).  Other distributions are one
   stratum of weight 1. */
#define NSTRAT 24
int dist_stratum(const dist_spec *d, uint64_t i);
double dist_stratum_weight(int dist, int h);

/* The value k representable steps above x in the format (k may be < 0). */
double fmt_step(double x, int64_t k, int prec);
double fmt_round(double x, int prec);

#endif
