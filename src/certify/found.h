/*
 * found.h - the found side of one region's bracket (found.c), shared with
 * the branch and bound (search.c): inputs of the region evaluated on the
 * real kernel, the largest defect kept with its input.
 */
#ifndef ONB_CERTIFY_FOUND_H
#define ONB_CERTIFY_FOUND_H

#include "found_env.h"
#include "found_dir.h"

/* Evaluate input n (in the format) if it lies in the region and the domain
   (in_domain: 1 when known to be in it, so not asked again); returns its
   screened defect, or -1 when it was not evaluated or gave a non-finite
   output (then res->nonfinite is set). */
double found_try(probe_env *e, const double n[3], int in_domain);

/* An input near the unit vector at (z, phi radians), completed so that it
   is the rounding of a unit vector (found.c), tried. */
void found_try_u(probe_env *e, double z, double phi);

/* The sampled start of the found side, and its walks: ulp walks from
   random inputs of the region (when restarts) and from the best inputs
   seen, then every input of a small neighbourhood of the best ones. */
void found_sample(probe_env *e);
void found_walks(probe_env *e, int restarts);

/* Is start s one of kernel `name`'s in precision prec (its values in the
   format)? */
int found_start_fits(const cert_start *s, const char *name, int prec);

/* The best inputs seen into res->keep_n, largest screened defect first. */
void found_keep(probe_env *e);

/* Fine climbs (1 to 4 ulps a step) from the best inputs seen whose
   screened defect reaches `frac` of found, `nbest` of them at most. */
void found_polish(probe_env *e, int nbest, double frac);

/* The images pass (found_images.c): every input of pool under the 48
   signed permutations of its components, tried where it lies in the
   region, then polished. */
void found_images(probe_env *e, const cert_pool_in *pool, long np);

/* |c| = sqrt(1 - a^2 - b^2) rounded to the format prec (a, b in it), as
   cert_complete gives it, without MPFR where double arithmetic decides the
   rounding for certain; NaN where it does not (then ask cert_complete). */
double found_complete_fast(int prec, double a, double b);

#endif
