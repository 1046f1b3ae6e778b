/*
 * array.c - array entry points for renderers with their own vector types:
 * n (3 values) in, b1 and b2 (3 values each) out, through plain pointers,
 * so `&v.x` of a {x, y, z} struct passes without a warning.  Compiled with
 * the library's flags (Makefile FPFLAGS), so a caller built with
 * -ffp-contract=fast or -ffast-math still gets the studied bits.
 *
 * One object per entry point (split.h): the Makefile compiles this file
 * once per method and precision (-DONB_ONE=NAME -DONB_ONE_D or
 * -DONB_ONE_F) and once for the registry calls (-DONB_COMMON), so a static
 * link pulls only the functions a client calls.  Without these defines,
 * as in a plain build of every file in src/lib, it defines everything.
 */
#include "split.h"

#define ONB__ARRAY_D(m)                                                        \
	void onb_##m##_array(const double *n, double *b1, double *b2)             \
	{                                                                          \
		onb_vec3 v, u1, u2;                                                    \
		v.x = n[0]; v.y = n[1]; v.z = n[2];                                    \
		onb_##m(v, &u1, &u2);                                                  \
		ONB__STORE3(double, b1, u1);                                           \
		ONB__STORE3(double, b2, u2);                                           \
	}
#define ONB__ARRAY_F(m)                                                        \
	void onb_##m##_arrayf(const float *n, float *b1, float *b2)               \
	{                                                                          \
		onb_vec3f v, u1, u2;                                                   \
		v.x = n[0]; v.y = n[1]; v.z = n[2];                                    \
		onb_##m##f(v, &u1, &u2);                                               \
		ONB__STORE3(float, b1, u1);                                            \
		ONB__STORE3(float, b2, u2);                                            \
	}
ONB__SPLIT(ONB__ARRAY_D, ONB__ARRAY_F)

#if ONB__COMMON
/* The registry's rows point to the array entries above, so a method chosen
   at run time costs one indirect call more than onb_NAME_array[f], with no
   copy through a by-value struct (onb.h inlines that path too).  A table of the caller's own that lacks
   them goes through method->basis[f]; its n is copied with memcpy, not
   three stores into the struct (the struct goes in registers, x and y in
   one 8-byte lane: a load of two 4-byte stores just made is not forwarded
   from the store buffer, a stall of about 15 cycles), which needs structs
   without padding (split.h checks). */

/* Apart, so that the usual path below needs no stack frame of its own. */
#if defined(__GNUC__)
#define ONB__APART __attribute__((noinline))
#else
#define ONB__APART
#endif
static ONB__APART onb_status onb__by_value(const onb_method *method, const double *n, double *b1, double *b2)
{
	onb_vec3 v, u1, u2;
	memcpy(&v, n, sizeof v);
	method->basis(v, &u1, &u2);
	ONB__STORE3(double, b1, u1);
	ONB__STORE3(double, b2, u2);
	return ONB_OK;
}

static ONB__APART onb_status onb__by_valuef(const onb_method *method, const float *n, float *b1, float *b2)
{
	onb_vec3f v, u1, u2;
	memcpy(&v, n, sizeof v);
	method->basisf(v, &u1, &u2);
	ONB__STORE3(float, b1, u1);
	ONB__STORE3(float, b2, u2);
	return ONB_OK;
}

onb_status (onb_basis_array)(const onb_method *method, const double *n, double *b1, double *b2)
{
	if (!method || !method->basis)
		return ONB_BAD_METHOD;
	if (!method->array)
		return onb__by_value(method, n, b1, b2);
	method->array(n, b1, b2);
	return ONB_OK;
}

onb_status (onb_basis_arrayf)(const onb_method *method, const float *n, float *b1, float *b2)
{
	if (!method || !method->basisf)
		return ONB_BAD_METHOD;
	if (!method->arrayf)
		return onb__by_valuef(method, n, b1, b2);
	method->arrayf(n, b1, b2);
	return ONB_OK;
}
#endif
