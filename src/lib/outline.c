/*
 * outline.c - out-of-line copies of the inline kernels, for the registry,
 * for callers through a function pointer, and for the method names of a
 * client whose flags could change the bits (onb.h, ONB__INLINE 0).  One
 * object per function in the library (split.h); the tools
 * (onb_frisvad_threshold/rotate) go with the common object.
 */
#include "split.h"

#define ONB__OUTLINE_D(m)                                                      \
	void onb_##m##_outline(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)             \
	{ onb_##m(n, b1, b2); }
#define ONB__OUTLINE_F(m)                                                      \
	void onb_##m##_outlinef(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)         \
	{ onb_##m##f(n, b1, b2); }
ONB__SPLIT(ONB__OUTLINE_D, ONB__OUTLINE_F)

#if ONB__COMMON
void onb_frisvad_threshold_outline(onb_vec3 n, double t, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_frisvad_threshold(n, t, b1, b2);
}
void onb_frisvad_threshold_outlinef(onb_vec3f n, float t, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_frisvad_thresholdf(n, t, b1, b2);
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
