/*
 * indep_wild_c6.h - independent transliterations (issue 44, helper
 * wildC6), written from each source at the commit its registry row names,
 * never from include/libonb/onb.h.  Included by tests/indep.h (its
 * Vec3f/Vec3d), which calls indep_wild_c6_f/indep_wild_c6_d.
 *   OSPRay's ISPC frame(N) (rkcommon f1641061 math/LinearSpace.ih:188-195)
 *     with rkcommon's vec.ih make_vec3f, abs, dot (a.x*b.x + a.y*b.y +
 *     a.z*b.z), normalize (v * (1.f/sqrt(dot(v, v)))) and cross, under
 *     IEEE (the ISPC sse4 target without fast-math).  vec3f is float: the
 *     double variant is the same text with float replaced by double.
 *   OpenShadingLanguage make_orthonormals (ad63273a
 *     src/liboslnoise/gabornoise.h:208-220) on Imath's Vec3<float>
 *     (d0a0b115 src/Imath/ImathVec.h: dot, length, lengthTiny, normalize
 *     dividing by l unless l == 0, cross, setValue).  Float only in OSL:
 *     the double variant is the same text on Vec3<double> (0.9f kept).
 *   AMD FidelityFX SDK Cauldron2 CreateTangentVectors (f4c1da8e
 *     Kits/Cauldron2/dx12/framework/shaders/raytracingcommon.hlsl:130-140),
 *     HLSL under IEEE: cross(x, y) = x.yzx * y.zxy - x.zxy * y.yzx,
 *     normalize(x) = x / length(x), length = sqrt(dot(x, x)), dot left to
 *     right; float2x3 rows tangents[0], tangents[1].  Float only: the
 *     double variant is the same text in double (0.99999f kept).
 *   three.js ggxConvolution (afbc335b src/nodes/pmrem/PMREMUtils.js:355-357),
 *     TSL: select(abs(N.z).lessThan(0.999), vec3(0,0,1), vec3(1,0,0)),
 *     normalize(cross(up, N)), cross(N, tangent); TSL's cross and
 *     normalize are the shading language's, as above (float; 0.999 a
 *     float constant, kept in the double variant).
 *   q2rtx_fixed: Quake II RTX's construct_ONB_frisvad (f2526e9a
 *     src/refresh/vkpt/shader/utils.glsl:241-257) as results/wild/patches/
 *     q2rtx_fixed.diff patches it, the mat3 columns ret[0], ret[2] as
 *     (b1, b2); `precise`: no contraction.
 */
#ifndef INDEP_WILD_C6_H
#define INDEP_WILD_C6_H

#include <float.h>

/* rkcommon vec.ih, written once per scalar type */
#define RKC_FRAME(T, S, SQRT, ABS, V) \
typedef struct { T x, y, z; } rk_vec3##S; \
static rk_vec3##S rk_make##S(T x, T y, T z) { rk_vec3##S r; r.x = x; r.y = y; r.z = z; return r; } \
static T rk_dot##S(rk_vec3##S a, rk_vec3##S b) { return a.x * b.x + a.y * b.y + a.z * b.z; } \
static rk_vec3##S rk_scale##S(rk_vec3##S a, T b) { return rk_make##S(a.x * b, a.y * b, a.z * b); } \
static rk_vec3##S rk_normalize##S(rk_vec3##S v) { return rk_scale##S(v, (T)1 / SQRT(rk_dot##S(v, v))); } \
static rk_vec3##S rk_cross##S(rk_vec3##S a, rk_vec3##S b) \
{ \
	return rk_make##S(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); \
} \
/* frame(N): dx0 = (0, N.z, -N.y), dx1 = (-N.z, 0, N.x), \
   dx = normalize(abs(N.x) < abs(N.y) ? dx0 : dx1), dy = cross(N, dx) */ \
static void ind_ospray##S(V n, V *vx, V *vy) \
{ \
	const rk_vec3##S N = rk_make##S(n.x, n.y, n.z); \
	const rk_vec3##S dx0 = rk_make##S((T)0, N.z, -N.y); \
	const rk_vec3##S dx1 = rk_make##S(-N.z, (T)0, N.x); \
	const rk_vec3##S dx = rk_normalize##S(ABS(N.x) < ABS(N.y) ? dx0 : dx1); \
	const rk_vec3##S dy = rk_cross##S(N, dx); \
	vx->x = dx.x; vx->y = dx.y; vx->z = dx.z; \
	vy->x = dy.x; vy->y = dy.y; vy->z = dy.z; \
}
RKC_FRAME(float, f, sqrtf, fabsf, Vec3f)
RKC_FRAME(double, d, sqrt, fabs, Vec3d)

/* Imath Vec3<T> as OSL's Vec3 uses it */
#define IMATH_GABOR(T, S, SQRT, TMIN, V) \
typedef struct { T x, y, z; } im3##S; \
static T im3_dot##S(const im3##S *a, const im3##S *b) { return a->x * b->x + a->y * b->y + a->z * b->z; } \
static T im3_lengthTiny##S(const im3##S *v) \
{ \
	T absX = (v->x >= (T)0) ? v->x : -v->x; \
	T absY = (v->y >= (T)0) ? v->y : -v->y; \
	T absZ = (v->z >= (T)0) ? v->z : -v->z; \
	T max = absX; \
	if (max < absY) max = absY; \
	if (max < absZ) max = absZ; \
	if (max == (T)0) return (T)0; \
	absX /= max; \
	absY /= max; \
	absZ /= max; \
	return max * SQRT(absX * absX + absY * absY + absZ * absZ); \
} \
static T im3_length##S(const im3##S *v) \
{ \
	T length2 = im3_dot##S(v, v); \
	if (length2 < (T)2 * TMIN) return im3_lengthTiny##S(v); \
	return SQRT(length2); \
} \
static void im3_normalize##S(im3##S *v) \
{ \
	T l = im3_length##S(v); \
	if (l != (T)0) { v->x /= l; v->y /= l; v->z /= l; } \
} \
static void im3_setValue##S(im3##S *v, T a, T b, T c) { v->x = a; v->y = b; v->z = c; } \
static im3##S im3_cross##S(const im3##S *a, const im3##S *v) \
{ \
	im3##S r; \
	r.x = a->y * v->z - a->z * v->y; \
	r.y = a->z * v->x - a->x * v->z; \
	r.z = a->x * v->y - a->y * v->x; \
	return r; \
} \
/* make_orthonormals(v, a, b): v.normalize(); a = fabsf(v.x) < 0.9f ? \
   (0.0f, v.z, -v.y) : (-v.z, 0.0f, v.x); a.normalize(); b = v.cross(a); \
   the frame (t, b, n) = (a, b, v) */ \
static void ind_osl_gabor##S(V n, V *t, V *bt) \
{ \
	im3##S v, a, b; \
	v.x = n.x; v.y = n.y; v.z = n.z; \
	im3_normalize##S(&v); \
	if ((v.x >= (T)0 ? v.x : -v.x) < 0.9f) \
		im3_setValue##S(&a, 0.0f, v.z, -v.y); \
	else \
		im3_setValue##S(&a, -v.z, 0.0f, v.x); \
	im3_normalize##S(&a); \
	b = im3_cross##S(&v, &a); \
	t->x = a.x; t->y = a.y; t->z = a.z; \
	bt->x = b.x; bt->y = b.y; bt->z = b.z; \
}
IMATH_GABOR(float, f, sqrtf, FLT_MIN, Vec3f)
IMATH_GABOR(double, d, sqrt, DBL_MIN, Vec3d)

/* HLSL float3 helpers, per component as the swizzles spell them */
#define HLSL_TANGENTS(T, S, SQRT, ABS, V) \
typedef struct { T x, y, z; } h3##S; \
static h3##S h3_make##S(T x, T y, T z) { h3##S r; r.x = x; r.y = y; r.z = z; return r; } \
static h3##S h3_cross##S(h3##S a, h3##S b) \
{ \
	/* a.yzx * b.zxy - a.zxy * b.yzx */ \
	const h3##S p = h3_make##S(a.y * b.z, a.z * b.x, a.x * b.y); \
	const h3##S q = h3_make##S(a.z * b.y, a.x * b.z, a.y * b.x); \
	return h3_make##S(p.x - q.x, p.y - q.y, p.z - q.z); \
} \
static h3##S h3_normalize##S(h3##S v) \
{ \
	const T len = SQRT(v.x * v.x + v.y * v.y + v.z * v.z); \
	return h3_make##S(v.x / len, v.y / len, v.z / len); \
} \
/* float3 up = abs(normal.z) < 0.99999f ? float3(0,0,1) : float3(1,0,0); \
   tangents[0] = normalize(cross(up, normal)); \
   tangents[1] = cross(normal, tangents[0]); */ \
static void ind_cauldron2##S(V n, V *t0, V *t1) \
{ \
	const h3##S normal = h3_make##S(n.x, n.y, n.z); \
	const h3##S up = ABS(normal.z) < 0.99999f ? h3_make##S((T)0.0, (T)0.0, (T)1.0) : h3_make##S((T)1.0, (T)0.0, (T)0.0); \
	const h3##S a = h3_normalize##S(h3_cross##S(up, normal)); \
	const h3##S b = h3_cross##S(normal, a); \
	t0->x = a.x; t0->y = a.y; t0->z = a.z; \
	t1->x = b.x; t1->y = b.y; t1->z = b.z; \
}
HLSL_TANGENTS(float, f, sqrtf, fabsf, Vec3f)
HLSL_TANGENTS(double, d, sqrt, fabs, Vec3d)

/* TSL: select( cond, a, b ) is cond ? a : b; lessThan is < */
static void ind_threejsf(Vec3f n, Vec3f *t, Vec3f *b)
{
	const h3f N = h3_makef(n.x, n.y, n.z);
	const int lt = fabsf(N.z) < 0.999f;
	const h3f up = lt ? h3_makef(0.0f, 0.0f, 1.0f) : h3_makef(1.0f, 0.0f, 0.0f);
	const h3f tangent = h3_normalizef(h3_crossf(up, N));
	const h3f bitangent = h3_crossf(N, tangent);
	t->x = tangent.x; t->y = tangent.y; t->z = tangent.z;
	b->x = bitangent.x; b->y = bitangent.y; b->z = bitangent.z;
}
static void ind_threejsd(Vec3d n, Vec3d *t, Vec3d *b)
{
	const h3d N = h3_maked(n.x, n.y, n.z);
	const int lt = fabs(N.z) < (double)0.999f;
	const h3d up = lt ? h3_maked(0.0, 0.0, 1.0) : h3_maked(1.0, 0.0, 0.0);
	const h3d tangent = h3_normalized(h3_crossd(up, N));
	const h3d bitangent = h3_crossd(N, tangent);
	t->x = tangent.x; t->y = tangent.y; t->z = tangent.z;
	b->x = bitangent.x; b->y = bitangent.y; b->z = bitangent.z;
}

/* construct_ONB_frisvad after q2rtx_fixed.diff: ret[1] = normal;
   if (normal.z < 0.0f) { a = 1/(1 - z); b = x*y*a;
     ret[0] = vec3(b, y*y*a - 1, -y); ret[2] = vec3(-(1 - x*x*a), b, -x); }
   else { a = 1/(1 + z); b = -x*y*a; ret[0] = vec3(1 - x*x*a, b, -x);
     ret[2] = vec3(b, 1 - y*y*a, -y); } */
#define Q2RTX_PATCHED(T, S, V) \
static void ind_q2rtx_fixed##S(V normal, V *ret0, V *ret2) \
{ \
	if (normal.z < (T)0.0f) { \
		const T a = (T)1.0f / ((T)1.0f - normal.z); \
		const T b = normal.x * normal.y * a; \
		ret0->x = b; ret0->y = normal.y * normal.y * a - (T)1.0f; ret0->z = -normal.y; \
		ret2->x = -((T)1.0f - normal.x * normal.x * a); ret2->y = b; ret2->z = -normal.x; \
	} else { \
		const T a = (T)1.0f / ((T)1.0f + normal.z); \
		const T b = -normal.x * normal.y * a; \
		ret0->x = (T)1.0f - normal.x * normal.x * a; ret0->y = b; ret0->z = -normal.x; \
		ret2->x = b; ret2->y = (T)1.0f - normal.y * normal.y * a; ret2->z = -normal.y; \
	} \
}
Q2RTX_PATCHED(float, f, Vec3f)
Q2RTX_PATCHED(double, d, Vec3d)

/* ids of this file (indep_wild_b5.h has 950+) */
enum { IW_OSPRAY = 1100, IW_OSL_GABOR, IW_CAULDRON2, IW_THREEJS, IW_Q2RTX_FIXED };

static int indep_wild_c6_f(int id, Vec3f n, Vec3f *b1, Vec3f *b2)
{
	switch (id) {
	case IW_OSPRAY:    ind_osprayf(n, b1, b2); return 1;
	case IW_OSL_GABOR: ind_osl_gaborf(n, b1, b2); return 1;
	case IW_CAULDRON2: ind_cauldron2f(n, b1, b2); return 1;
	case IW_THREEJS:   ind_threejsf(n, b1, b2); return 1;
	case IW_Q2RTX_FIXED: ind_q2rtx_fixedf(n, b1, b2); return 1;
	default:           return 0;
	}
}
static int indep_wild_c6_d(int id, Vec3d n, Vec3d *b1, Vec3d *b2)
{
	switch (id) {   /* float-only sources: the same text in double */
	case IW_OSPRAY:    ind_osprayd(n, b1, b2); return 1;
	case IW_OSL_GABOR: ind_osl_gabord(n, b1, b2); return 1;
	case IW_CAULDRON2: ind_cauldron2d(n, b1, b2); return 1;
	case IW_THREEJS:   ind_threejsd(n, b1, b2); return 1;
	case IW_Q2RTX_FIXED: ind_q2rtx_fixedd(n, b1, b2); return 1;
	default:           return 0;
	}
}

/* rows of indep.h's method table T */
#define INDEP_WILD_C6_ROWS \
	{ "ospray", onb_ospray, onb_osprayf, IW_OSPRAY, 0 }, \
	{ "osl_gabornoise", onb_osl_gabornoise, onb_osl_gabornoisef, IW_OSL_GABOR, 0 }, \
	{ "cauldron2", onb_cauldron2, onb_cauldron2f, IW_CAULDRON2, 0 }, \
	{ "threejs", onb_threejs, onb_threejsf, IW_THREEJS, 0 }, \
	{ "q2rtx_fixed", onb_q2rtx_fixed, onb_q2rtx_fixedf, IW_Q2RTX_FIXED, 0 },

#endif /* INDEP_WILD_C6_H */
