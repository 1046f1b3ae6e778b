/*
 * search.h - one region's bracket: the largest defect found on a real input
 * of the region, and a certified bound above every input of it (search.c).
 */
#ifndef ONB_CERTIFY_SEARCH_H
#define ONB_CERTIFY_SEARCH_H

#include "methods/kernels.h"
#include "bound.h"
#include "regions.h"
#include "bracket.h"
#include "probe.h"

/* The bracket of kernel k (model m) in precision prec (PREC_FLOAT or
   PREC_DOUBLE) over region r. */
void cert_region_run(cert_ctx *x, const study_kernel *k, const cm_method *m, int prec,
                     const cert_region *r, const cert_opts *o, cert_result *res);
/* The branch and bound of a region run before, again to its budget with
   no stall stop (search.c); res keeps the smaller bound. */
void cert_region_refine(cert_ctx *x, const study_kernel *k, const cm_method *m, int prec,
                        const cert_region *r, const cert_opts *o, cert_result *res);

/* The images pass of a region run before (found_images.c): the inputs of
   pool (a kernel and precision's best inputs of every region and its
   --starts) under the signed permutations, where they fall in r.  found
   can only rise; the status follows it. */
void cert_region_images(cert_ctx *x, const study_kernel *k, int prec, const cert_region *r, const cert_opts *o,
                        const cert_pool_in *pool, long np, cert_result *res);

#endif
