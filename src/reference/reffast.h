/*
 * reffast.h - the certified fast reference.
 *
 * reffast_eval fills the same sample_metrics as ref_eval (reference.h),
 * bit for bit, without MPFR: the defect and direction terms are sums of
 * exact products (error-free transformations), the method's formula runs
 * in double-double with a running error bound that covers both this
 * evaluation and the MPFR one at the reference's precision, and a
 * rounding test (Ziv's) decides whether each stored figure is determined.
 * When any figure is not, reffast_eval returns 0 and the caller runs
 * ref_eval: the MPFR path at the current precision.
 */
#ifndef ONB_REFFAST_H
#define ONB_REFFAST_H

#include "reference/reference.h"

typedef struct reffast_ctx reffast_ctx;

/* ref_bits: the precision of the MPFR reference this path stands in for;
   NULL on allocation failure. */
reffast_ctx *reffast_new(int ref_bits);
void reffast_free(reffast_ctx *c);

/* 1 when this build and CPU can run the fast path for an MPFR reference
   of ref_bits bits (at least 120: the bounds below assume it); else 0 and
   the reason in why. */
int reffast_usable(int ref_bits, const char **why);

/* Same arguments and output as ref_eval.  REFFAST_DONE when every field
   of s is determined (and then equal to what ref_eval at ref_bits
   writes); REFFAST_NOREF when every field but ref[] is (ref[] holds NaN
   where not: it only matters for a sample kept among the worst, and the
   caller must then run ref_eval); REFFAST_MPFR when the caller must call
   ref_eval (s is then unspecified). */
enum { REFFAST_MPFR = 0, REFFAST_DONE = 1, REFFAST_NOREF = 2 };
int reffast_eval(reffast_ctx *c, const study_kernel *k, int prec, const double n[3],
                 const double loc[3], int normalize_n, sample_metrics *s);

#endif
