/*
 * checked.c - onb_basis_checked[f]: the entry point for renderers that
 * cannot promise unit, finite normals (interpolated shading normals,
 * normal maps, user meshes).
 */
#define ONB_BUILDING_LIB 1
#include "libonb/onb.h"

static void onb__safe_frame(onb_vec3 *b1, onb_vec3 *b2)
{
	b1->x = 1.0; b1->y = 0.0; b1->z = 0.0;
	b2->x = 0.0; b2->y = 1.0; b2->z = 0.0;
}
static void onb__safe_framef(onb_vec3f *b1, onb_vec3f *b2)
{
	b1->x = 1.0f; b1->y = 0.0f; b1->z = 0.0f;
	b2->x = 0.0f; b2->y = 1.0f; b2->z = 0.0f;
}

onb_status onb_basis_checked(const onb_method *method, onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2, onb_vec3 *n_used)
{
	onb_status st = ONB_OK;
	double l2;
	onb__safe_frame(b1, b2);
	if (n_used)
		*n_used = n;
	if (!method || !method->basis)
		return ONB_BAD_METHOD;
	if (!isfinite(n.x) || !isfinite(n.y) || !isfinite(n.z))
		return ONB_NONFINITE;
	l2 = n.x * n.x + n.y * n.y + n.z * n.z;
	if (!(fabs(l2 - 1.0) <= ONB_CHECK_TOL)) {
		/* Scale by the largest |component| first: no overflow for huge
		   input, no underflow to zero for subnormal input. */
		double s = fmax(fabs(n.x), fmax(fabs(n.y), fabs(n.z))), l;
		if (s == 0.0)
			return ONB_ZERO;
		n.x /= s; n.y /= s; n.z /= s;
		l = sqrt(n.x * n.x + n.y * n.y + n.z * n.z); /* in [1, sqrt(3)] */
		n.x /= l; n.y /= l; n.z /= l;
		st = ONB_RENORMALIZED;
	}
	if (n_used)
		*n_used = n;
	method->basis(n, b1, b2);
	return st;
}

onb_status onb_basis_checkedf(const onb_method *method, onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2, onb_vec3f *n_used)
{
	onb_status st = ONB_OK;
	float l2;
	onb__safe_framef(b1, b2);
	if (n_used)
		*n_used = n;
	if (!method || !method->basisf)
		return ONB_BAD_METHOD;
	if (!isfinite(n.x) || !isfinite(n.y) || !isfinite(n.z))
		return ONB_NONFINITE;
	l2 = n.x * n.x + n.y * n.y + n.z * n.z;
	if (!(fabsf(l2 - 1.0f) <= ONB_CHECK_TOLF)) {
		float s = fmaxf(fabsf(n.x), fmaxf(fabsf(n.y), fabsf(n.z))), l;
		if (s == 0.0f)
			return ONB_ZERO;
		n.x /= s; n.y /= s; n.z /= s;
		l = sqrtf(n.x * n.x + n.y * n.y + n.z * n.z);
		n.x /= l; n.y /= l; n.z /= l;
		st = ONB_RENORMALIZED;
	}
	if (n_used)
		*n_used = n;
	method->basisf(n, b1, b2);
	return st;
}

#if ONB_HAVE_HALF
/* Binary16: |n|^2 and the normalization in float, where the squares of
   binary16 values are exact and nothing overflows or underflows (65504^2
   and (2^-24)^2 are normal floats); n_used rounded back to binary16. */
static void onb__put_h(const onb_vec3h *v, uint16_t b[3])
{
	memcpy(&b[0], &v->x, 2); memcpy(&b[1], &v->y, 2); memcpy(&b[2], &v->z, 2);
}
static void onb__get_h(const uint16_t b[3], onb_vec3h *v)
{
	memcpy(&v->x, &b[0], 2); memcpy(&v->y, &b[1], 2); memcpy(&v->z, &b[2], 2);
}

onb_status onb_basis_checkedh(const onb_method *method, onb_vec3h n, onb_vec3h *b1, onb_vec3h *b2, onb_vec3h *n_used)
{
	onb_status st = ONB_OK;
	const float x = (float)n.x, y = (float)n.y, z = (float)n.z;
	const float l2 = x * x + y * y + z * z;
	uint16_t nb[3], r1[3], r2[3];
	b1->x = (onb_half)1.0f; b1->y = (onb_half)0.0f; b1->z = (onb_half)0.0f;
	b2->x = (onb_half)0.0f; b2->y = (onb_half)1.0f; b2->z = (onb_half)0.0f;
	if (n_used)
		*n_used = n;
	if (!method || !method->arrayh)
		return ONB_BAD_METHOD;
	if (!isfinite(x) || !isfinite(y) || !isfinite(z))
		return ONB_NONFINITE;
	if (!(fabsf(l2 - 1.0f) <= ONB_CHECK_TOLH)) {
		float l;
		if (l2 == 0.0f)
			return ONB_ZERO;
		l = sqrtf(l2);
		n.x = (onb_half)(x / l); n.y = (onb_half)(y / l); n.z = (onb_half)(z / l);
		st = ONB_RENORMALIZED;
	}
	if (n_used)
		*n_used = n;
	onb__put_h(&n, nb);
	method->arrayh(nb, r1, r2);
	onb__get_h(r1, b1);
	onb__get_h(r2, b2);
	return st;
}
#endif
