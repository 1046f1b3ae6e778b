/*
 * indep_wild_e.h - independent transliterations of renderers' shipped code
 * (issue 44, the renderers group: helper wild3), written from each source
 * at the commit its registry alias row names, never from
 * include/libonb/onb.h.  Included by tests/indep.h (its Vec3f/Vec3d)
 * before indep_wild.h, whose alias table IA[] takes this file's rows
 * through INDEP_WILD_E_ALIASES.
 *   OpenShadingLanguage testrender TangentFrame::from_normal
 *     (src/testrender/sampling.h): Vec3 is Imath's V3f (float), copysignf,
 *     the int literals 1 and -1 converted to float, products left to right.
 *   Tungsten TangentFrame(const Vec3f &n) (src/core/math/TangentFrame.hpp,
 *     since dd58767 "[Duff et al. 17]"): Vec3f, copysignf, products left
 *     to right; tangent is b1, bitangent b2.
 *   Nori coordinateSystem (src/common.cpp) with Eigen's Vector3f cross
 *     (cross_impl: lhs(1)*rhs(2) - lhs(2)*rhs(1), ...); Frame(n) = (s, t, n).
 *   Mitsuba 0.6 coordinateSystem (src/libcore/util.cpp) with its
 *     TVector3 cross (vector.h), Float = float or double (DOUBLE_PRECISION).
 *   Jolt Vec3::GetNormalizedPerpendicular's non-SSE path with std::max
 *     and JPH::Sqrt, Vec3 / float as a 4-lane division, and the NEON Cross
 *     (vmulq/vsubq on shuffled lanes), nothing fused (the arm64 build).
 *   OSL testrender ortho (src/testrender/raytracer.h) with Imath's
 *     Vec3::normalize, length, lengthTiny and cross (ImathVec.h).
 *   Cycles make_orthonormals as its arm64 kernel runs it (sse2neon):
 *     _mm_dp_ps(a, a, 0x7F) as vaddvq_f32 of the products with lane 3
 *     zeroed, vsqrtq_f32, vdivq_f32, and msub = vfmaq_f32(vnegq_f32(c), a, b).
 * OSL's and Tungsten's sources are float only (their alias rows claim float).
 */
#ifndef INDEP_WILD_E_H
#define INDEP_WILD_E_H

#include <float.h>

/* OSL: sign = copysignf(1.0f, n.z); a = -1 / (sign + n.z); b = n.x * n.y * a;
   u = Vec3(1 + sign * n.x * n.x * a, sign * b, -sign * n.x);
   v = Vec3(b, sign + n.y * n.y * a, -n.y); return { u, v, n } */
static void ind_osl_from_normalf(Vec3f n, Vec3f *u, Vec3f *v)
{
	const float sign = copysignf(1.0f, n.z);
	const float a = (float)-1 / (sign + n.z);
	const float b = n.x * n.y * a;
	const float ux = (float)1 + ((sign * n.x) * n.x) * a;
	*u = vf(ux, sign * b, -sign * n.x);
	*v = vf(b, sign + (n.y * n.y) * a, -n.y);
}

/* Tungsten: float sign = copysignf(1.0f, normal.z());
   const float a = -1.0f/(sign + normal.z()); const float b = normal.x()*normal.y()*a;
   tangent = Vec3f(1.0f + sign*normal.x()*normal.x()*a, sign*b, -sign*normal.x());
   bitangent = Vec3f(b, sign + normal.y()*normal.y()*a, -normal.y()); */
static void ind_tungstenf(Vec3f normal, Vec3f *tangent, Vec3f *bitangent)
{
	float sign = copysignf(1.0f, normal.z);
	const float a = -1.0f / (sign + normal.z);
	const float b = normal.x * normal.y * a;
	float t0 = sign * normal.x;
	t0 = t0 * normal.x;
	t0 = t0 * a;
	*tangent = vf(1.0f + t0, sign * b, -sign * normal.x);
	*bitangent = vf(b, sign + normal.y * normal.y * a, -normal.y);
}

/* Nori: if (std::abs(a.x()) > std::abs(a.y())) { float invLen = 1.0f / std::sqrt(a.x() * a.x() + a.z() * a.z());
   c = Vector3f(a.z() * invLen, 0.0f, -a.x() * invLen); } else { ... (0.0f, a.z() * invLen, -a.y() * invLen) }
   b = c.cross(a); */
#define NORI_CS(T, S, V, MK, ABS, SQRT) \
static void ind_nori_cs##S(V a, V *b, V *c) \
{ \
	V cc; \
	if (ABS(a.x) > ABS(a.y)) { \
		T invLen = (T)1.0f / SQRT(a.x * a.x + a.z * a.z); \
		cc = MK(a.z * invLen, (T)0.0f, -a.x * invLen); \
	} else { \
		T invLen = (T)1.0f / SQRT(a.y * a.y + a.z * a.z); \
		cc = MK((T)0.0f, a.z * invLen, -a.y * invLen); \
	} \
	*c = cc; \
	/* Eigen cross_impl / Mitsuba cross(v1 = c, v2 = a) */ \
	*b = MK((cc.y * a.z) - (cc.z * a.y), (cc.z * a.x) - (cc.x * a.z), (cc.x * a.y) - (cc.y * a.x)); \
}
NORI_CS(float, f, Vec3f, vf, fabsf, sqrtf)
NORI_CS(double, d, Vec3d, vd, fabs, sqrt)

/* Jolt non-SSE: float x = mF32[0], y = mF32[1], z = mF32[2]; float xx = x * x, yy = y * y, zz = z * z;
   Vec3 perp_x(z, 0.0f, -x); Vec3 perp_y(0.0f, z, -y);
   return (xx > yy ? perp_x : perp_y) / JPH::Sqrt(max(xx, yy) + zz); then NEON Cross. */
#define JOLT_A64(T, S, V, MK, SQRT) \
static T ja_max##S(T a, T b) { return (a < b) ? b : a; }   /* std::max */ \
static void ind_jolt_arm64##S(V n, V *b1, V *b2) \
{ \
	T x = n.x, y = n.y, z = n.z; \
	T xx = x * x, yy = y * y, zz = z * z; \
	T px[4] = { z, (T)0.0f, -x, -x }, py[4] = { (T)0.0f, z, -y, -y }, q[4], l, t1[4], t2[4], t3[4], a[4]; \
	const T *sel = xx > yy ? px : py; \
	int i; \
	l = SQRT(ja_max##S(xx, yy) + zz); \
	for (i = 0; i < 4; i++) q[i] = sel[i] / l;            /* vdivq_f32(mValue, vdupq_n_f32(l)) */ \
	a[0] = x; a[1] = y; a[2] = z; a[3] = z; \
	/* Cross(this = n, inV2 = q): t1 = shuffle(q, 1,2,0,0) * n; t2 = shuffle(n, 1,2,0,0) * q; t3 = t1 - t2; shuffle(t3, 1,2,0,0) */ \
	t1[0] = q[1]; t1[1] = q[2]; t1[2] = q[0]; t1[3] = q[0]; \
	t2[0] = a[1]; t2[1] = a[2]; t2[2] = a[0]; t2[3] = a[0]; \
	for (i = 0; i < 4; i++) { t1[i] = t1[i] * a[i]; t2[i] = t2[i] * q[i]; t3[i] = t1[i] - t2[i]; } \
	*b1 = MK(q[0], q[1], q[2]); \
	*b2 = MK(t3[1], t3[2], t3[0]); \
}
JOLT_A64(float, f, Vec3f, vf, sqrtf)
JOLT_A64(double, d, Vec3d, vd, sqrt)

/* Cycles arm64: a = (N.z - N.y, N.x - N.z, N.y - N.x) if N.x != N.y || N.x != N.z,
   else (N.z - N.y, N.x + N.z, -N.y - N.x); lanes m = a*a, m[3] = 0; d = (m0 + m1) + (m2 + m3) (FADDP, FADDP);
   a = a / sqrt(d) lane-wise; cross(N, a): x = N, y = shuffle<1,2,0,3>(a), z = shuffle<1,2,0,3>(N) * a;
   r = vfmaq_f32(-z, x, y); b = shuffle<1,2,0,3>(r). */
static void ind_cycles_neonf(Vec3f N, Vec3f *pa, Vec3f *pb)
{
	float a[4], m[4], x[4], y[4], z[4], r[4], d, nrm;
	int i;
	if (N.x != N.y || N.x != N.z) { a[0] = N.z - N.y; a[1] = N.x - N.z; a[2] = N.y - N.x; }
	else                          { a[0] = N.z - N.y; a[1] = N.x + N.z; a[2] = -N.y - N.x; }
	a[3] = 0.0f;
	for (i = 0; i < 4; i++) m[i] = a[i] * a[i];
	m[3] = 0.0f;
	d = (m[0] + m[1]) + (m[2] + m[3]);
	nrm = sqrtf(d);
	for (i = 0; i < 4; i++) a[i] = a[i] / nrm;
	x[0] = N.x; x[1] = N.y; x[2] = N.z; x[3] = 0.0f;
	y[0] = a[1]; y[1] = a[2]; y[2] = a[0]; y[3] = a[3];
	z[0] = x[1] * a[0]; z[1] = x[2] * a[1]; z[2] = x[0] * a[2]; z[3] = x[3] * a[3];
	for (i = 0; i < 4; i++) r[i] = fmaf(x[i], y[i], -z[i]);
	*pa = vf(a[0], a[1], a[2]);
	*pb = vf(r[1], r[2], r[0]);
}

/* OSL ortho: x = (fabsf(n.x) > .01f ? Vec3(n.z, 0, -n.x) : Vec3(0, -n.z, n.y)).normalize(); y = n.cross(x).
   Imath: length() { T length2 = dot(*this); if (length2 < T(2) * numeric_limits<T>::min()) return lengthTiny();
   return std::sqrt(length2); }  normalize() { T l = length(); if (l != T(0)) { x /= l; y /= l; z /= l; } } */
#define IMATH_ORTHO(T, S, V, MK, SQRT, FABS, TMIN) \
static T im_lengthTiny##S(V v) \
{ \
	T absX = (v.x >= (T)0) ? v.x : -v.x, absY = (v.y >= (T)0) ? v.y : -v.y, absZ = (v.z >= (T)0) ? v.z : -v.z; \
	T max = absX; \
	if (max < absY) max = absY; \
	if (max < absZ) max = absZ; \
	if (max == (T)0) return (T)0; \
	absX /= max; absY /= max; absZ /= max; \
	return max * SQRT(absX * absX + absY * absY + absZ * absZ); \
} \
static T im_length##S(V v) \
{ \
	T length2 = v.x * v.x + v.y * v.y + v.z * v.z; \
	if (length2 < (T)2 * TMIN) return im_lengthTiny##S(v); \
	return SQRT(length2); \
} \
static void ind_osl_ortho##S(V n, V *x, V *y) \
{ \
	V v = FABS(n.x) > .01f ? MK(n.z, (T)0, -n.x) : MK((T)0, -n.z, n.y); \
	T l = im_length##S(v); \
	if (l != (T)0) { v.x /= l; v.y /= l; v.z /= l; } \
	*x = v; \
	*y = MK(n.y * v.z - n.z * v.y, n.z * v.x - n.x * v.z, n.x * v.y - n.y * v.x); \
}
IMATH_ORTHO(float, f, Vec3f, vf, sqrtf, fabsf, FLT_MIN)
IMATH_ORTHO(double, d, Vec3d, vd, sqrt, fabs, DBL_MIN)

/* ids of this file (indep_wild.h's are 100+, indep_wild_b.h's 200+) */
enum { IW_OSL_TESTRENDER = 500, IW_TUNGSTEN, IW_NORI, IW_MITSUBA06, IW_JOLT_ARM64, IW_CYCLES_NEON, IW_OSL_ORTHO };

static int indep_wild_e_f(int id, Vec3f n, Vec3f *b1, Vec3f *b2)
{
	switch (id) {
	case IW_OSL_TESTRENDER: ind_osl_from_normalf(n, b1, b2); return 1;
	case IW_TUNGSTEN:       ind_tungstenf(n, b1, b2); return 1;
	case IW_NORI:           /* Nori and Mitsuba 0.6: one text */
	case IW_MITSUBA06:      ind_nori_csf(n, b1, b2); return 1;
	case IW_JOLT_ARM64:     ind_jolt_arm64f(n, b1, b2); return 1;
	case IW_CYCLES_NEON:    ind_cycles_neonf(n, b1, b2); return 1;
	case IW_OSL_ORTHO:      ind_osl_orthof(n, b1, b2); return 1;
	default:                return 0;
	}
}
static int indep_wild_e_d(int id, Vec3d n, Vec3d *b1, Vec3d *b2)
{
	switch (id) {   /* OSL and Tungsten: float-only sources */
	case IW_NORI:           /* Nori is float only: the same arithmetic in double */
	case IW_MITSUBA06:      ind_nori_csd(n, b1, b2); return 1;
	case IW_JOLT_ARM64:     ind_jolt_arm64d(n, b1, b2); return 1;
	case IW_OSL_ORTHO:      ind_osl_orthod(n, b1, b2); return 1;   /* float source: the same in double */
	default:                return 0;
	}
}

/* rows of indep_wild.h's IA[]: name, target, id, float, double */
#define INDEP_WILD_E_ALIASES \
	{ "osl_testrender", "duff_branchless", IW_OSL_TESTRENDER, 1, 0 }, \
	{ "tungsten", "duff_branchless", IW_TUNGSTEN, 1, 0 }, \
	{ "mitsuba06", "nori", IW_MITSUBA06, 1, 1 }, \
	{ "cycles_neon", "cycles_cross111_avx2", IW_CYCLES_NEON, 1, 0 },

/* rows of indep.h's method table T (after luxcore's) */
#define INDEP_WILD_E_ROWS \
	{ "nori", onb_nori, onb_norif, IW_NORI, 0 }, \
	{ "osl_ortho", onb_osl_ortho, onb_osl_orthof, IW_OSL_ORTHO, 0 }, \
	{ "jolt_arm64", onb_jolt_arm64, onb_jolt_arm64f, IW_JOLT_ARM64, 0 },

#endif /* INDEP_WILD_E_H */
