/*
 * regions.h - the regions `onbstudy certify` bounds, and each one's box of
 * real unit vectors (regions.c).
 */
#ifndef ONB_CERTIFY_REGIONS_H
#define ONB_CERTIFY_REGIONS_H

#include <stddef.h>
#include "region.h"
#include "model/mvf.h"
#include "methods/kernels.h"

/* The default regions for precision prec (PREC_FLOAT or PREC_DOUBLE): bands of n.z
   log-spaced in 1 + n.z near -1 (two per decade, down to the pole) and in
   1 - n.z near +1 (one per decade), linear in between, times nsec equal
   azimuth sectors.  Returns the count written to out (capacity cap). */
size_t regions_default(int prec, int nsec, cert_region *out, size_t cap);

/* The default regions cut to the band lo <= n.z <= hi (-1 <= lo <= hi <= 1):
   the bands that meet it, each clipped to it.  Returns the count. */
size_t regions_band(int prec, int nsec, double lo, double hi, cert_region *out, size_t cap);

/* The box of real unit vectors u whose rounding (or, with a tolerance,
   whose scaling) can land in r: r widened by the input's own rounding. */
void region_box(const cert_region *r, int prec, double tolerance, mvf_box *b);
/* 1 when band r holds no binary16 value (no input in half). */
int half_band_empty(const cert_region *r);

/* Whether the closure of region r meets the singular set of kernel k (its
   family's, src/families/). */
int region_meets_singular(const study_kernel *k, const cert_region *r);

#endif
