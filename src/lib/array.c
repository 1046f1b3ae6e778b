/*
 * array.c - array entry points for renderers with their own vector types:
 * double n[3] / float n[3] in, b1[3] and b2[3] out.  Compiled with the
 * library's flags (Makefile FPFLAGS), so a caller built with
 * -ffp-contract=fast or -ffast-math still gets the studied bits.
 */
#include "onb.h"

#define ONB__ARRAY(m)                                                          \
	void onb_##m##_array(const double n[3], double b1[3], double b2[3])       \
	{                                                                          \
		onb_vec3 v, u1, u2;                                                    \
		v.x = n[0]; v.y = n[1]; v.z = n[2];                                    \
		onb_##m(v, &u1, &u2);                                                  \
		b1[0] = u1.x; b1[1] = u1.y; b1[2] = u1.z;                              \
		b2[0] = u2.x; b2[1] = u2.y; b2[2] = u2.z;                              \
	}                                                                          \
	void onb_##m##_arrayf(const float n[3], float b1[3], float b2[3])         \
	{                                                                          \
		onb_vec3f v, u1, u2;                                                   \
		v.x = n[0]; v.y = n[1]; v.z = n[2];                                    \
		onb_##m##f(v, &u1, &u2);                                               \
		b1[0] = u1.x; b1[1] = u1.y; b1[2] = u1.z;                              \
		b2[0] = u2.x; b2[1] = u2.y; b2[2] = u2.z;                              \
	}
ONB_METHOD_LIST(ONB__ARRAY)

/* The float-only methods: float arrays only. */
#define ONB__ARRAY_F(m)                                                        \
	void onb_##m##_arrayf(const float n[3], float b1[3], float b2[3])         \
	{                                                                          \
		onb_vec3f v, u1, u2;                                                   \
		v.x = n[0]; v.y = n[1]; v.z = n[2];                                    \
		onb_##m##f(v, &u1, &u2);                                               \
		b1[0] = u1.x; b1[1] = u1.y; b1[2] = u1.z;                              \
		b2[0] = u2.x; b2[1] = u2.y; b2[2] = u2.z;                              \
	}
ONB_FLOAT_METHOD_LIST(ONB__ARRAY_F)

onb_status onb_basis_array(const onb_method *method, const double n[3], double b1[3], double b2[3])
{
	onb_vec3 v, u1, u2;
	if (!method || !method->basis)
		return ONB_BAD_METHOD;
	v.x = n[0]; v.y = n[1]; v.z = n[2];
	method->basis(v, &u1, &u2);
	b1[0] = u1.x; b1[1] = u1.y; b1[2] = u1.z;
	b2[0] = u2.x; b2[1] = u2.y; b2[2] = u2.z;
	return ONB_OK;
}

onb_status onb_basis_arrayf(const onb_method *method, const float n[3], float b1[3], float b2[3])
{
	onb_vec3f v, u1, u2;
	if (!method || !method->basisf)
		return ONB_BAD_METHOD;
	v.x = n[0]; v.y = n[1]; v.z = n[2];
	method->basisf(v, &u1, &u2);
	b1[0] = u1.x; b1[1] = u1.y; b1[2] = u1.z;
	b2[0] = u2.x; b2[1] = u2.y; b2[2] = u2.z;
	return ONB_OK;
}
