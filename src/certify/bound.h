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
   a box too wide for the intervals).  For frisvad_rotate (m->direction)
   the bound is on its direction error max(| |w| - 1 |, |w.n - z|) over
   every loc = (x, y, z) that is a rounding of a unit vector. */
double bound_box(bound_ctx *b, const cm_method *m, const mvf_box *x);
/* The arithmetic profile of the bounds to come (arith.h; NULL or ieee: the
   IEEE model), and the operation kind (AR_*; AR_NOPS: a rule proven for
   round to nearest alone, frisvad_rotate's direction bound) whose
   allowance left some box without a bound since then (-1: none). */
void bound_set_arith(bound_ctx *b, const arith_profile *p);
int  bound_unbounded_op(const bound_ctx *b);
/* Why the last bound_box had no finite bound (-1: it had one): the first
   infinite path's operation kind with arith.h's AR_AT_POLE or AR_OVERFLOW
   (its operand's enclosure reached the operation's pole, its result may
   overflow), the kind alone (the profile gives it no bound), AR_NOPS (a
   rule proven for round to nearest alone) or AR_LOST (the enclosure was
   lost elsewhere in the mean value form). */
int  bound_box_cause(const bound_ctx *b);
/* Whether some box since the last call had a path whose value may exceed
   the format's largest finite value (an overflow: binary16's 65504), which
   left it without a bound (reset by the call). */
int  bound_overflow_seen(bound_ctx *b);
/* The same with terms of frisvad_rotate's bound left out, which makes it
   unsound: tests/test_certify_dir.c shows that its checks catch that. */
#define BOUND_DROP_DOT 1u   /* the rounding of w's dot products */
double bound_box_ablate(bound_ctx *b, const cm_method *m, const mvf_box *x, unsigned drop);

#endif
