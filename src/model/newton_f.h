/*
 * newton_f.h - the float Newton steps on a float seed, scanned over every
 * float input of the binades asked for (newton_f.c).
 */
#ifndef ONB_NEWTON_F_H
#define ONB_NEWTON_F_H
#include "seeds.h"

/* Listing 3's y (1.5 - (0.5 x y) y), GCC's contraction of it
   y fma(-y, (x 0.5) y, 1.5), Embree's 1.5 y + ((x (-0.5)) y)(y y) and its
   contraction fma(y, 1.5, ...). */
typedef enum { NEWTON_L3, NEWTON_L3_FUSED, NEWTON_EMBREE, NEWTON_EMBREE_FUSED, NNEWTON } newton_kind;

/* y1 = step k on seed s of x, as the kernels compute it. */
float newton_f(newton_kind k, seed_kind s, float x);

/* [*lo, *hi] holds y1 sqrt(x) - 1 for y1 = newton_step_f(k, x, seed s of
   x) (newton_f) and every float x with biased exponent in [eb_lo, eb_hi] (1..254),
   rounded outward.  Each binade is scanned once per process (2^23 inputs)
   and cached; thread-safe.  Returns 0, or -1 for a float seed kind other
   than rsqrtss and invsqrt_f, or a step outside s^2 x in [0.5, 2]. */
int newton_range_f(newton_kind k, seed_kind s, int eb_lo, int eb_hi, double *lo, double *hi);

#endif
