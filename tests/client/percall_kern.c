/*
 * percall_kern.c - the client side of scripts/client-bench.sh: one loop per
 * method and precision over the inline method names, compiled with the
 * client's flags (gcc -O2, clang -O3 -march=native, -ffast-math, ...).
 * Whether the names were inlined shows in this object's symbols:
 * `U onb_NAME_outline` (a call into libonb.a) or a local onb_NAME (a copy
 * called), else the kernel was inlined into the loop.
 */
#include <stddef.h>
#include "libonb/onb.h"
#include "percall.h"

#define LOOPS(m)                                                               \
	void loop_##m(size_t k, const onb_vec3 *n, onb_vec3 *b1, onb_vec3 *b2)     \
	{ size_t i; for (i = 0; i < k; i++) onb_##m(n[i], &b1[i], &b2[i]); }      \
	void loop_##m##f(size_t k, const onb_vec3f *n, onb_vec3f *b1, onb_vec3f *b2) \
	{ size_t i; for (i = 0; i < k; i++) onb_##m##f(n[i], &b1[i], &b2[i]); }
ONB_METHOD_LIST(LOOPS)
#define LOOPSF(m)                                                              \
	void loop_##m##f(size_t k, const onb_vec3f *n, onb_vec3f *b1, onb_vec3f *b2) \
	{ size_t i; for (i = 0; i < k; i++) onb_##m##f(n[i], &b1[i], &b2[i]); }
ONB_FLOAT_METHOD_LIST(LOOPSF)
