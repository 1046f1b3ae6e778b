/*
 * outline.c - out-of-line copies of the inline kernels, for the registry,
 * for callers through a function pointer, and for the method names of a
 * client whose flags could change the bits (onb.h, ONB__INLINE 0).  One
 * object per function in the library (split.h); the tools
 * (onb_frisvad_threshold/rotate) go with the common object.
 */
#include "split.h"

/* The results are stored as x and y in one store, then z (split.h,
   ONB__STORE3): a caller that copies them as structs reads them from the
   store buffer without a stall. */
#define ONB__OUTLINE_D(m)                                                      \
	void onb_##m##_outline(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)             \
	{                                                                          \
		onb_vec3 u1, u2;                                                       \
		onb_##m(n, &u1, &u2);                                                  \
		ONB__STORE3(double, b1, u1);                                           \
		ONB__STORE3(double, b2, u2);                                           \
	}
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(_WIN32)
/* GCC on x86-64 (System V ABI): n arrives as x and y in the low 8 bytes of
   xmm0 and z in xmm1.  Given the struct, GCC spills xmm0 to the stack to
   reach y (an 8-byte store, then 4-byte loads), which puts a store-to-load
   forwarding, about 5 cycles, before the kernel's first comparison: for
   the branchy kernels (stark_fixed: 1.6x the array entry) that was the
   whole difference.  The same registers declared as a vector of two floats
   and a float (identical in the ABI) are read with a shuffle instead.
   The header's declaration is unchanged; the bit tests call this entry
   through it (tests/test_lib.c: inline == out of line for every method). */
typedef float onb__xy __attribute__((vector_size(8)));
#define ONB__OUTLINE_F(m)                                                      \
	void onb__##m##_outlinef_xy(onb__xy xy, float z, onb_vec3f *b1, onb_vec3f *b2) \
		__asm__("onb_" #m "_outlinef");                                        \
	void onb__##m##_outlinef_xy(onb__xy xy, float z, onb_vec3f *b1, onb_vec3f *b2) \
	{                                                                          \
		onb_vec3f n, u1, u2;                                                   \
		n.x = xy[0]; n.y = xy[1]; n.z = z;                                     \
		onb_##m##f(n, &u1, &u2);                                               \
		ONB__STORE3(float, b1, u1);                                            \
		ONB__STORE3(float, b2, u2);                                            \
	}
#else
#define ONB__OUTLINE_F(m)                                                      \
	void onb_##m##_outlinef(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)         \
	{                                                                          \
		onb_vec3f u1, u2;                                                      \
		onb_##m##f(n, &u1, &u2);                                               \
		ONB__STORE3(float, b1, u1);                                            \
		ONB__STORE3(float, b2, u2);                                            \
	}
#endif
ONB__SPLIT(ONB__OUTLINE_D, ONB__OUTLINE_F)

#if ONB__COMMON
void onb_frisvad_threshold_outline(onb_vec3 n, double t, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 u1, u2;
	onb_frisvad_threshold(n, t, &u1, &u2);
	ONB__STORE3(double, b1, u1);
	ONB__STORE3(double, b2, u2);
}
void onb_frisvad_threshold_outlinef(onb_vec3f n, float t, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f u1, u2;
	onb_frisvad_thresholdf(n, t, &u1, &u2);
	ONB__STORE3(float, b1, u1);
	ONB__STORE3(float, b2, u2);
}
onb_vec3 onb_frisvad_rotate_outline(onb_vec3 n, double x, double y, double z)
{
	return onb_frisvad_rotate(n, x, y, z);
}
onb_vec3f onb_frisvad_rotate_outlinef(onb_vec3f n, float x, float y, float z)
{
	return onb_frisvad_rotatef(n, x, y, z);
}
#endif
