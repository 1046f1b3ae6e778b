/*
 * split.h - one object per entry point.  The Makefile compiles
 * array.c, outline.c and batch.c once per method and precision with
 * -DONB_ONE=NAME and -DONB_ONE_D (double) or -DONB_ONE_F (float), and once
 * with -DONB_COMMON for what is not per method.  ONB__SPLIT(D, F) then
 * expands D(NAME) or F(NAME) alone; without any of these defines it
 * expands D and F for every method (ONB_FLOAT_METHOD_LIST: F only), and
 * ONB__COMMON is 1.
 */
#ifndef ONB_SPLIT_H
#define ONB_SPLIT_H
#define ONB_BUILDING_LIB 1
#include "libonb/onb.h"

/* X(NAME) with ONB_ONE expanded first (X pastes its argument). */
#define ONB__APPLY(X, m) X(m)

#if defined(ONB_ONE) && defined(ONB_ONE_D)
#define ONB__SPLIT(D, F) ONB__APPLY(D, ONB_ONE)
#define ONB__COMMON 0
#elif defined(ONB_ONE) && defined(ONB_ONE_F)
#define ONB__SPLIT(D, F) ONB__APPLY(F, ONB_ONE)
#define ONB__COMMON 0
#elif defined(ONB_COMMON)
#define ONB__SPLIT(D, F)
#define ONB__COMMON 1
#else
#define ONB__SPLIT(D, F) ONB_METHOD_LIST(D) ONB_METHOD_LIST(F) ONB_FLOAT_METHOD_LIST(F)
#define ONB__COMMON 1
#endif
#endif
