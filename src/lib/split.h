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

/* How the scalar entries (outline.c, array.c) store each output vector:
   x and y in one store of the pair (8 bytes in float, 16 in double), then
   z.  A caller that copies the result as a struct reads it back the same
   way (GCC and clang: one load of x and y, one of z), and a load is
   forwarded from the store buffer only when one store holds all its
   bytes: after three separate stores, the load of x and y waited for
   them to reach the cache, about 15 cycles, and a call cost 2-3x the
   kernel (results/clients/entries.md, "callers").  A caller that reads
   the members one by one loads part of one store, which forwards too.
   Same bits: only the width of the stores changes.  DST points to three
   T without padding (the onb_vec3[f] structs are: checked below); V is a
   struct with members x, y, z of type T.  Generic over T (any type whose
   pair is a power of two bytes). */
#if defined(__GNUC__)
#define ONB__STORE3(T, dst, v)                                                 \
	do {                                                                       \
		typedef T onb__pair_ __attribute__((vector_size(2 * sizeof(T))));     \
		const onb__pair_ xy_ = {(v).x, (v).y};                                 \
		memcpy((dst), &xy_, sizeof xy_);                                       \
		memcpy((char *)(dst) + sizeof xy_, &(v).z, sizeof(T));                 \
	} while (0)
#else
#define ONB__STORE3(T, dst, v)                                                 \
	do {                                                                       \
		T xyz_[3];                                                             \
		xyz_[0] = (v).x; xyz_[1] = (v).y; xyz_[2] = (v).z;                     \
		memcpy((dst), xyz_, sizeof xyz_);                                      \
	} while (0)
#endif
typedef char onb__vec3_unpadded[sizeof(onb_vec3) == 3 * sizeof(double) ? 1 : -1];
typedef char onb__vec3f_unpadded[sizeof(onb_vec3f) == 3 * sizeof(float) ? 1 : -1];

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
