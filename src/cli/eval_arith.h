/*
 * cli/eval_arith.h - `onbstudy eval --arith PROFILE X Y Z` (eval_arith.c):
 * the outputs and defects an arithmetic profile allows at one input.
 */
#ifndef ONB_EVAL_ARITH_H
#define ONB_EVAL_ARITH_H

#include "methods/kernels.h"
#include "model/arith.h"

/* Every method of ks (with a rounding model) in the precisions prec_on
   at input in (rounded to each): samples random implementations from
   seed, the adversary, the bound near the input; csv: rows. */
int eval_arith(const arith_profile *p, const study_kernel *ks, int nk, const int prec_on[PREC_COUNT], const double in[3],
               int samples, unsigned long long seed, int csv);

#endif
