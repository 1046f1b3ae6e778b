/*
 * found_dir.h - the found side for frisvad_rotate, whose direction error
 * depends on the local direction as well as on n (found_dir.c).
 */
#ifndef ONB_CERTIFY_FOUND_DIR_H
#define ONB_CERTIFY_FOUND_DIR_H

#include "found_env.h"

/* The largest screened direction error on n over the locs its basis
   points at (the best measured as eval measures it: res->found, found_n,
   found_loc), or -1; and ulp walks in loc from the found input. */
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
