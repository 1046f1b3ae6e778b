/*
 * indep_wild_d.h - independent transliterations of the shader sources'
 * orthonormal bases (issue 44, the shader group: the registry's rows and
 * aliases rtxdi, ...), written from each source at the commit its registry
 * row names, never from include/libonb/onb.h.  Included by tests/indep.h
 * (its Vec3f/Vec3d, vf/vd), which calls indep_wild_d_f/indep_wild_d_d
 * first.  Shader sources are read under IEEE arithmetic (HLSL/GLSL float
 * as C float, no contraction); each function names how it reads the
 * language's built-ins.  Ids 300 and up.
 */
#ifndef INDEP_WILD_D_H
#define INDEP_WILD_D_H

/* RTXDI shaders/HelperFunctions.hlsli branchlessONB (HLSL float): the
   ternary sign (z >= 0.0f ? 1.0f : -1.0f, so -0 takes +1 and NaN -1),
   products left to right as HLSL groups them. */
static void ind_rtxdif(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	float sign = n.z >= 0.0f ? 1.0f : -1.0f;
	float a = -1.0f / (sign + n.z);
	float b = n.x * n.y * a;
	*b1 = vf(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
	*b2 = vf(b, sign + n.y * n.y * a, -n.y);
}

/* Filament TangentSpaceMesh.cpp hughesMollerMethod (C++ float), with
   filament::math's helpers: dot = r{} then r += lv[i]*rv[i] in index order,
   length = std::sqrt(dot(v, v)), normalize(v) = v * (T(1) / length(v)),
   cross(u, v) = (u.y v.z - u.z v.y, u.z v.x - u.x v.z, u.x v.y - u.y v.x);
   abs(float) as std::abs.  The frame {t, b, n}: b1 = t, b2 = b. */
#define FIL_HM(T, S, SQRT, ABS, V, MK) \
static T filhm_dot_##S(V a, V b) { T r = 0; r += a.x * b.x; r += a.y * b.y; r += a.z * b.z; return r; } \
static V filhm_cross_##S(V u, V v) { return MK(u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x); } \
static void ind_filament_hm##S(V n, V *b1, V *b2) \
{ \
	const T epsilon = (T)0x1p-23f;  /* std::numeric_limits<float>::epsilon() */ \
	V b, t; \
	T inv; \
	if (ABS(n.x) > ABS(n.z) + epsilon) \
		t = MK(-n.y, n.x, (T)0.0f); \
	else \
		t = MK((T)0.0f, -n.z, n.y); \
	inv = (T)1 / SQRT(filhm_dot_##S(t, t)); \
	t = MK(t.x * inv, t.y * inv, t.z * inv); \
	b = filhm_cross_##S(n, t); \
	*b1 = t; *b2 = b; \
}
FIL_HM(float, f, sqrtf, fabsf, Vec3f, vf)
FIL_HM(double, d, sqrt, fabs, Vec3d, vd)

/* AMD Capsaicin src/core/src/math/sampling.hlsl GetOrthoVectors (HLSL
   float): squared(v) = v * v (math.hlsl), the swizzles p2 = sel ? n : n.zyx
   and b1 = sel ? b1 : b1.zyx as vectors, 1.0f / sqrt(...) as a division by
   a correctly rounded sqrt, HLSL cross(a, b) = a.yzx * b.zxy - a.zxy * b.yzx.
   fixed: this project's one-line fix, sel = abs(n.z) > abs(n.x). */
#define CAPS(T, S, SQRT, ABS, V, MK) \
static T caps_squared_##S(T v) { return v * v; } \
static V caps_zyx_##S(V v) { return MK(v.z, v.y, v.x); } \
static V caps_cross_##S(V a, V b) { return MK(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); } \
static void ind_capsaicin##S(V n, V *b1, V *b2, int fixed) \
{ \
	int sel = fixed ? ABS(n.z) > ABS(n.x) : ABS(n.z) > 0; \
	V p2 = sel ? n : caps_zyx_##S(n); \
	T k = (T)1.0f / SQRT(caps_squared_##S(p2.z) + caps_squared_##S(n.y)); \
	V b = MK((T)0.0f, -p2.z * k, n.y * k); \
	b = sel ? b : caps_zyx_##S(b); \
	*b1 = b; \
	*b2 = caps_cross_##S(n, b); \
}
CAPS(float, f, sqrtf, fabsf, Vec3f, vf)
CAPS(double, d, sqrt, fabs, Vec3d, vd)

/* Unity Graphics CommonLighting.hlsl GetLocalFrame (HLSL, real = float),
   FastSign(s) = CopySign(1.0, s, true) = (s >= 0) ? abs(1.0) : -abs(1.0)
   (Common.hlsl); the real3x3 rows localX, localY, localZ: b1 = localX,
   b2 = localY. */
#define UNITY_LF(T, S, V, MK) \
static T unity_copysign_##S(T x, T s) { return (s >= 0) ? (x < 0 ? -x : x) : -(x < 0 ? -x : x); } \
static void ind_unity##S(V localZ, V *localX, V *localY) \
{ \
	T x = localZ.x; \
	T y = localZ.y; \
	T z = localZ.z; \
	T sz = unity_copysign_##S((T)1.0, z); \
	T a = 1 / (sz + z); \
	T ya = y * a; \
	T b = x * ya; \
	T c = x * sz; \
	*localX = MK(c * x * a - 1, sz * b, c); \
	*localY = MK(b, y * ya - sz, y); \
}
UNITY_LF(float, f, Vec3f, vf)
UNITY_LF(double, d, Vec3d, vd)

/* GLSL/HLSL built-ins as the language specifications define them, read
   under IEEE: dot(x, y) = x[0]*y[0] + x[1]*y[1] + x[2]*y[2]; length(x) =
   sqrt(dot(x, x)); normalize(x) = x / length(x); cross(x, y) = (x[1]*y[2]
   - y[1]*x[2], x[2]*y[0] - y[2]*x[0], x[0]*y[1] - y[0]*x[1]); abs. */
#define GLSL_LIB(T, S, V, MK, SQRT) \
static T glsl_dot_##S(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; } \
static V glsl_normalize_##S(V a) { T len = SQRT(glsl_dot_##S(a, a)); return MK(a.x / len, a.y / len, a.z / len); } \
static V glsl_cross_##S(V a, V b) { return MK(a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y); } \
static T glsl_abs_##S(T v) { return v < 0 ? -v : v > 0 ? v : v * v; }
GLSL_LIB(float, f, Vec3f, vf, sqrtf)
GLSL_LIB(double, d, Vec3d, vd, sqrt)

/* Sascha Willems Vulkan shaders/glsl/pbribl/prefilterenvmap.frag
   importanceSample_GGX (GLSL float): vec3 up = abs(normal.z) < 0.999 ?
   vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0); tangentX =
   normalize(cross(up, normal)); tangentY = normalize(cross(normal,
   tangentX)); world = tangentX*H.x + tangentY*H.y + normal*H.z. */
#define WILLEMS_TS(T, S, V, MK) \
static void ind_willems##S(V normal, V *tangentX, V *tangentY) \
{ \
	V up = glsl_abs_##S(normal.z) < (T)0.999 ? MK(0, 0, 1) : MK(1, 0, 0); \
	*tangentX = glsl_normalize_##S(glsl_cross_##S(up, normal)); \
	*tangentY = glsl_normalize_##S(glsl_cross_##S(normal, *tangentX)); \
}
WILLEMS_TS(float, f, Vec3f, vf)
WILLEMS_TS(double, d, Vec3d, vd)

/* Khronos glTF-Sample-Viewer source/shaders/ibl_filtering.frag
   generateTBN (b3a7e668; GLSL mediump read as float): bitangent = (0,1,0);
   NdotUp = dot(normal, (0,1,0)); epsilon = 0.0000001; if (1.0 -
   abs(NdotUp) <= epsilon) bitangent = NdotUp > 0.0 ? (0,0,1) : (0,0,-1);
   tangent = normalize(cross(bitangent, normal)); bitangent =
   cross(normal, tangent); mat3(tangent, bitangent, normal). */
#define GLTF_TBN(T, S, V, MK) \
static void ind_gltf##S(V normal, V *tangent, V *bitangent_out) \
{ \
	V bitangent = MK(0, 1, 0); \
	T NdotUp = glsl_dot_##S(normal, MK(0, 1, 0)); \
	T epsilon = (T)0.0000001; \
	if ((T)1.0 - glsl_abs_##S(NdotUp) <= epsilon) { \
		if (NdotUp > 0) \
			bitangent = MK(0, 0, 1); \
		else \
			bitangent = MK(0, 0, -1); \
	} \
	*tangent = glsl_normalize_##S(glsl_cross_##S(bitangent, normal)); \
	*bitangent_out = glsl_cross_##S(normal, *tangent); \
}
GLTF_TBN(float, f, Vec3f, vf)
GLTF_TBN(double, d, Vec3d, vd)

/* DirectX-Graphics-Samples RTAO RayGen.hlsli GetRandomRayDirection (HLSL
   float): w = surfaceNormal; right = 0.3f * w + float3(-0.72f, 0.56f,
   -0.34f); v = normalize(cross(w, right)); u = cross(v, w); the ray
   sample.x*u + sample.y*v + sample.z*w: b1 = u, b2 = v.  fixed: this
   project's patch (results/wild/patches/rtao_fixed.diff): the second
   vector float3(0.56f, 0.72f, 0.0f) where abs(dot(w, C)) > 0.875f. */
#define RTAO_RG(T, S, V, MK) \
static void ind_rtao##S(V surfaceNormal, V *u, V *v, int fixed) \
{ \
	V w = surfaceNormal, C = MK((T)-0.72, (T)0.56, (T)-0.34), right; \
	if (fixed && glsl_abs_##S(glsl_dot_##S(w, C)) > (T)0.875) \
		C = MK((T)0.56, (T)0.72, (T)0.0); \
	right = MK((T)0.3 * w.x + C.x, (T)0.3 * w.y + C.y, (T)0.3 * w.z + C.z); \
	*v = glsl_normalize_##S(glsl_cross_##S(w, right)); \
	*u = glsl_cross_##S(*v, w); \
}
RTAO_RG(float, f, Vec3f, vf)
RTAO_RG(double, d, Vec3d, vd)

enum { IW_RTXDI = 300, IW_FILAMENT_HM, IW_CAPSAICIN, IW_CAPSAICIN_FIXED, IW_UNITY,
       IW_WILLEMS, IW_GLTF_VIEWER, IW_RTAO, IW_RTAO_FIXED };
/* this file's rows of indep_wild.h's alias table IA[] */
#define INDEP_WILD_D_ALIASES \
	{ "rtxdi", "duff", IW_RTXDI, 1, 0 },

/* 1 when id is one of this file's (outputs written), else 0; a double
   variant that the source does not have gives 0 too. */
static int indep_wild_d_f(int id, Vec3f n, Vec3f *b1, Vec3f *b2)
{
	switch (id) {
	case IW_RTXDI: ind_rtxdif(n, b1, b2); return 1;
	case IW_FILAMENT_HM: ind_filament_hmf(n, b1, b2); return 1;
	case IW_CAPSAICIN: ind_capsaicinf(n, b1, b2, 0); return 1;
	case IW_CAPSAICIN_FIXED: ind_capsaicinf(n, b1, b2, 1); return 1;
	case IW_UNITY: ind_unityf(n, b1, b2); return 1;
	case IW_WILLEMS: ind_willemsf(n, b1, b2); return 1;
	case IW_GLTF_VIEWER: ind_gltff(n, b1, b2); return 1;
	case IW_RTAO: ind_rtaof(n, b1, b2, 0); return 1;
	case IW_RTAO_FIXED: ind_rtaof(n, b1, b2, 1); return 1;
	default:       return 0;
	}
}
static int indep_wild_d_d(int id, Vec3d n, Vec3d *b1, Vec3d *b2)
{
	switch (id) {
	case IW_FILAMENT_HM: ind_filament_hmd(n, b1, b2); return 1;
	case IW_CAPSAICIN: ind_capsaicind(n, b1, b2, 0); return 1;
	case IW_CAPSAICIN_FIXED: ind_capsaicind(n, b1, b2, 1); return 1;
	case IW_UNITY: ind_unityd(n, b1, b2); return 1;
	case IW_WILLEMS: ind_willemsd(n, b1, b2); return 1;
	case IW_GLTF_VIEWER: ind_gltfd(n, b1, b2); return 1;
	case IW_RTAO: ind_rtaod(n, b1, b2, 0); return 1;
	case IW_RTAO_FIXED: ind_rtaod(n, b1, b2, 1); return 1;
	default:       return 0;
	}
}

#endif /* INDEP_WILD_D_H */
