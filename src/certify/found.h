/*
 * found.h - the found side of one region's bracket (found.c), shared with
 * the branch and bound (search.c): inputs of the region evaluated on the
 * real kernel, the largest defect kept with its input.
 */
#ifndef ONB_CERTIFY_FOUND_H
#define ONB_CERTIFY_FOUND_H

#include "bracket.h"
#include "probe.h"
#include "regions.h"

/* The inputs with the largest defects seen, as screened: where the
   walks start. */
#define FOUND_TOP 16

typedef struct {
	double d;      /* the screened defect */
	double n[3];
} found_cand;

typedef struct {
	cert_ctx *x;
	const study_kernel *k;
	int prec;
	const cert_region *r;
	const cert_opts *o;
	cert_result *res;
	found_cand top[FOUND_TOP];
	int ntop;
	uint64_t rng;
	double gate;   /* the largest screened defect measured so far */
	int no_stall;  /* the branch and bound runs to its budget (search.c) */
} probe_env;

/* Evaluate input n (in the format) if it lies in the region and the domain
   (in_domain: 1 when known to be in it, so not asked again); returns its
   screened defect, or -1 when it was not evaluated or gave a non-finite
   output (then res->nonfinite is set). */
double found_try(probe_env *e, const double n[3], int in_domain);

/* Should an input of screened defect d be measured exactly?  When d
   reaches found and exceeds every screened defect measured before by
   more than 2^-40 relative (the screen is good to about 1e-15 relative,
   and the walks meet the same defect again and again on flat ground). */
int found_worth_measuring(probe_env *e, double d);

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

/* p . q - sub in double-double (found.c). */
double found_dot_dd(const double *p, const double *q, double sub);

/* frisvad_rotate (found_dir.c): the largest screened direction error on n
   over the locs its basis points at (the best measured as eval measures
   it: res->found, found_n, found_loc), or -1; and ulp walks in loc from
   the found input. */
double found_dir_try(probe_env *e, const double n[3]);
/* The directions (not yet rounded, not unit) where frisvad_rotate's
   direction error on n can be largest: the eigenvectors of G - I and
   (b1.n, b2.n, |n|^2 - 1), both signs, (0.6, 0, 0.8), +z and two random
   ones from *rng.  Returns their count. */
#define FOUND_DIR_CAND 12
int found_dir_candidates(int prec, const double n[3], uint64_t *rng, double c[FOUND_DIR_CAND][3]);
void found_dir_walk(probe_env *e, long steps);
/* An earlier run's worst (n, loc) (--starts), measured where n lies in
   the region and both in the domain. */
void found_dir_start(probe_env *e, const double n[3], const double loc[3]);

#endif
