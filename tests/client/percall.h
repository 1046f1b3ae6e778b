/* percall.h - the loops of percall_kern.c, for percall_main.c. */
#ifndef PERCALL_H
#define PERCALL_H
#include <stddef.h>
#include "libonb/onb.h"
#define PERCALL_DECL(m)                                                        \
	void loop_##m(size_t k, const onb_vec3 *n, onb_vec3 *b1, onb_vec3 *b2);    \
	void loop_##m##f(size_t k, const onb_vec3f *n, onb_vec3f *b1, onb_vec3f *b2);
ONB_METHOD_LIST(PERCALL_DECL)
#define PERCALL_DECLF(m)                                                       \
	void loop_##m##f(size_t k, const onb_vec3f *n, onb_vec3f *b1, onb_vec3f *b2);
ONB_FLOAT_METHOD_LIST(PERCALL_DECLF)
#endif
