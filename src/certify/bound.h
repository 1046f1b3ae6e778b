/*
 * bound.h - a certified upper bound on a method's defect over one box of
 * the sphere (bound.c), from the model's mean value form (mvf.c).
 */
#ifndef ONB_CERTIFY_BOUND_H
#define ONB_CERTIFY_BOUND_H

#include "models.h"
#include "model/mvf.h"

typedef struct bound_ctx bound_ctx;

bound_ctx *bound_new(void);     /* one per thread; NULL on failure */
void bound_free(bound_ctx *b);

/* The bound on max(| |b1|-1 |, | |b2|-1 |, |b1.n|, |b2.n|, |b1.b2|) of method
   m over box x: the larger over every branch path that a point of the box
   can take.  +inf when some path cannot be enclosed (a singular point, or
   a box too wide for the intervals). */
double bound_box(bound_ctx *b, const cm_method *m, const mvf_box *x);

#endif
