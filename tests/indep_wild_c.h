/*
 * indep_wild_c.h - independent transliterations of the math libraries'
 * single-perpendicular functions (issue 44, libraries group): raylib
 * raymath.h (Vector3Perpendicular, Vector3Normalize, Vector3CrossProduct),
 * Godot core/math/vector3.h (get_any_perpendicular with is_zero_approx,
 * cross, normalized), DirectXMath DirectXMathVector.inl
 * (XMVector3Orthogonal, XMVector3Normalize, XMVector3Cross as SSE lanes),
 * Ogre OgreVector.h (perpendicular, normalise, crossProduct) and bx
 * math.inl (calcTangentFrame with sqrtSimd and rcpSafe),
 * written from each source at the commit its registry row names, never
 * from include/libonb/onb.h, and completed as docs/wild-specs/README.md
 * says: b1 = the source's vector (through the library's own normalize
 * where the source does not normalize), b2 = the library's cross(n, b1).
 * godot_fixed (BACK where |z| < |y| and x is not
 * the smallest) and bx_fixed (pbrt-v3's branch |x| > |y|) are this
 * project's fixes, transliterated from that description on top of the
 * engines' lines.
 * Included by tests/indep.h (its Vec3f/Vec3d), which calls
 * indep_wild_c_f/indep_wild_c_d.  raylib, DirectXMath and bx are float only:
 * their double rows are the same source in double; Godot's real_t is float or double.
 */
#ifndef INDEP_WILD_C_H
#define INDEP_WILD_C_H

/* ---- raylib raymath.h, with Vector3 of scalar T ---- */
#define RAYLIB_MATH(T, S, SQRT, FABS) \
typedef struct { T x; T y; T z; } rlVector3_##S; \
static rlVector3_##S rlVector3CrossProduct_##S(rlVector3_##S v1, rlVector3_##S v2) \
{ \
	rlVector3_##S result = { v1.y*v2.z - v1.z*v2.y, v1.z*v2.x - v1.x*v2.z, v1.x*v2.y - v1.y*v2.x }; \
	return result; \
} \
static rlVector3_##S rlVector3Perpendicular_##S(rlVector3_##S v) \
{ \
	rlVector3_##S result = { 0, 0, 0 }; \
	T min = FABS(v.x); \
	rlVector3_##S cardinalAxis = { (T)1.0f, (T)0.0f, (T)0.0f }; \
	if (FABS(v.y) < min) { \
		rlVector3_##S tmp = { (T)0.0f, (T)1.0f, (T)0.0f }; \
		min = FABS(v.y); \
		cardinalAxis = tmp; \
	} \
	if (FABS(v.z) < min) { \
		rlVector3_##S tmp = { (T)0.0f, (T)0.0f, (T)1.0f }; \
		cardinalAxis = tmp; \
	} \
	result.x = v.y*cardinalAxis.z - v.z*cardinalAxis.y; \
	result.y = v.z*cardinalAxis.x - v.x*cardinalAxis.z; \
	result.z = v.x*cardinalAxis.y - v.y*cardinalAxis.x; \
	return result; \
} \
static rlVector3_##S rlVector3Normalize_##S(rlVector3_##S v) \
{ \
	rlVector3_##S result = v; \
	T length = SQRT(v.x*v.x + v.y*v.y + v.z*v.z); \
	if (length != (T)0.0f) { \
		T ilength = (T)1.0f/length; \
		result.x *= ilength; \
		result.y *= ilength; \
		result.z *= ilength; \
	} \
	return result; \
}
RAYLIB_MATH(float, f, sqrtf, fabsf)
RAYLIB_MATH(double, d, sqrt, fabs)
static void ind_raylibf(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	rlVector3_f v = { n.x, n.y, n.z }, t, b;
	t = rlVector3Normalize_f(rlVector3Perpendicular_f(v));
	b = rlVector3CrossProduct_f(v, t);
	*b1 = vf(t.x, t.y, t.z); *b2 = vf(b.x, b.y, b.z);
}
static void ind_raylibd(Vec3d n, Vec3d *b1, Vec3d *b2)
{
	rlVector3_d v = { n.x, n.y, n.z }, t, b;
	t = rlVector3Normalize_d(rlVector3Perpendicular_d(v));
	b = rlVector3CrossProduct_d(v, t);
	*b1 = vd(t.x, t.y, t.z); *b2 = vd(b.x, b.y, b.z);
}

/* ---- Godot core/math/vector3.h with real_t = T; CMP_EPSILON 0.00001
   (math_defs.h), Math::is_zero_approx(real_t) = abs(v) < (real_t)CMP_EPSILON ---- */
#define GODOT_VECTOR3(T, S, SQRT, FABS) \
typedef struct { T x, y, z; } gdVector3_##S; \
static gdVector3_##S gd_make_##S(T x, T y, T z) { gdVector3_##S r; r.x = x; r.y = y; r.z = z; return r; } \
static int gd_is_zero_approx1_##S(T v) { return FABS(v) < (T)0.00001; } \
static int gd_is_zero_approx_##S(gdVector3_##S v) \
{ \
	return gd_is_zero_approx1_##S(v.x) && gd_is_zero_approx1_##S(v.y) && gd_is_zero_approx1_##S(v.z); \
} \
static gdVector3_##S gd_cross_##S(gdVector3_##S a, gdVector3_##S p_with) \
{ \
	return gd_make_##S((a.y * p_with.z) - (a.z * p_with.y), (a.z * p_with.x) - (a.x * p_with.z), \
	                   (a.x * p_with.y) - (a.y * p_with.x)); \
} \
static T gd_length_squared_##S(gdVector3_##S v) \
{ \
	T x2 = v.x * v.x; \
	T y2 = v.y * v.y; \
	T z2 = v.z * v.z; \
	return x2 + y2 + z2; \
} \
static gdVector3_##S gd_normalized_##S(gdVector3_##S v) \
{ \
	T lengthsq = gd_length_squared_##S(v); \
	if (lengthsq == 0) { \
		v.x = v.y = v.z = 0; \
	} else { \
		T length = SQRT(lengthsq); \
		v.x /= length; \
		v.y /= length; \
		v.z /= length; \
	} \
	return v; \
} \
/* fixed: this project's fix, BACK (0,0,1) where |y| > |z| on the UP side */ \
static gdVector3_##S gd_get_any_perpendicular_##S(gdVector3_##S v, int fixed) \
{ \
	const gdVector3_##S RIGHT = gd_make_##S(1, 0, 0), UP = gd_make_##S(0, 1, 0), BACK = gd_make_##S(0, 0, 1); \
	if (gd_is_zero_approx_##S(v)) \
		return gd_make_##S(0, 0, 0); \
	if (FABS(v.x) <= FABS(v.y) && FABS(v.x) <= FABS(v.z)) \
		return gd_normalized_##S(gd_cross_##S(v, RIGHT)); \
	if (fixed && !(FABS(v.y) <= FABS(v.z))) \
		return gd_normalized_##S(gd_cross_##S(v, BACK)); \
	return gd_normalized_##S(gd_cross_##S(v, UP)); \
}
GODOT_VECTOR3(float, f, sqrtf, fabsf)
GODOT_VECTOR3(double, d, sqrt, fabs)
static void ind_godotf(Vec3f n, Vec3f *b1, Vec3f *b2, int fixed)
{
	gdVector3_f v = gd_make_f(n.x, n.y, n.z), t = gd_get_any_perpendicular_f(v, fixed), b = gd_cross_f(v, t);
	*b1 = vf(t.x, t.y, t.z); *b2 = vf(b.x, b.y, b.z);
}
static void ind_godotd(Vec3d n, Vec3d *b1, Vec3d *b2, int fixed)
{
	gdVector3_d v = gd_make_d(n.x, n.y, n.z), t = gd_get_any_perpendicular_d(v, fixed), b = gd_cross_d(v, t);
	*b1 = vd(t.x, t.y, t.z); *b2 = vd(b.x, b.y, b.z);
}


/* ---- DirectXMath (x86 _XM_SSE_INTRINSICS_, no FMA): XMVECTOR as four
   float lanes; XMVectorSplatZ, XMVectorSwizzle, XMVectorSubtract,
   XMVectorLess and XMVectorEqualInt as lane masks, XMVectorPermute,
   XMVectorSelect; XMVector3Normalize's SSE path (mul, add_ss of the
   shuffled squares, sqrt, cmpneq with 0 and with +inf, div, and/andnot/or
   with g_XMQNaN); XMVector3Cross's SSE path (two shuffles, mul, and
   XM_FNMADD_PS = c - a*b) ---- */
#define DXM_LANES(T, S, SQRT) \
typedef struct { T f[4]; unsigned m[4]; } xmv_##S; \
static xmv_##S xm_set_##S(T a, T b, T c, T d) { xmv_##S r; r.f[0] = a; r.f[1] = b; r.f[2] = c; r.f[3] = d; r.m[0] = r.m[1] = r.m[2] = r.m[3] = 0; return r; } \
static xmv_##S XMVectorZero_##S(void) { return xm_set_##S(0, 0, 0, 0); } \
static xmv_##S XMVectorSplatZ_##S(xmv_##S v) { return xm_set_##S(v.f[2], v.f[2], v.f[2], v.f[2]); } \
static xmv_##S XMVectorSwizzle_YZYY_##S(xmv_##S v) { return xm_set_##S(v.f[1], v.f[2], v.f[1], v.f[1]); } \
static xmv_##S XMVectorSubtract_##S(xmv_##S a, xmv_##S b) { return xm_set_##S(a.f[0] - b.f[0], a.f[1] - b.f[1], a.f[2] - b.f[2], a.f[3] - b.f[3]); } \
static xmv_##S XMVectorAdd_##S(xmv_##S a, xmv_##S b) { return xm_set_##S(a.f[0] + b.f[0], a.f[1] + b.f[1], a.f[2] + b.f[2], a.f[3] + b.f[3]); } \
static xmv_##S XMVectorLess_##S(xmv_##S a, xmv_##S b) { xmv_##S r = xm_set_##S(0, 0, 0, 0); int i; for (i = 0; i < 4; i++) r.m[i] = a.f[i] < b.f[i] ? ~0u : 0u; return r; } \
static xmv_##S XMVectorEqualInt_##S(xmv_##S a, xmv_##S b) { xmv_##S r = xm_set_##S(0, 0, 0, 0); int i; for (i = 0; i < 4; i++) r.m[i] = a.m[i] == b.m[i] ? ~0u : 0u; return r; } \
/* XMVectorPermute<1X, 0X, 0X, 0X>(a, b) = (b.x, a.x, a.x, a.x) */ \
static xmv_##S XMVectorPermute_1X0X0X0X_##S(xmv_##S a, xmv_##S b) { return xm_set_##S(b.f[0], a.f[0], a.f[0], a.f[0]); } \
/* XMVectorSelect(v1, v2, c): v2 where the control lane is set, else v1 */ \
static xmv_##S XMVectorSelect_##S(xmv_##S v1, xmv_##S v2, xmv_##S c) { xmv_##S r = v1; int i; for (i = 0; i < 4; i++) if (c.m[i]) r.f[i] = v2.f[i]; return r; } \
static xmv_##S XMVector3Orthogonal_##S(xmv_##S V) \
{ \
	xmv_##S Zero = XMVectorZero_##S(); \
	xmv_##S Z = XMVectorSplatZ_##S(V); \
	xmv_##S YZYY = XMVectorSwizzle_YZYY_##S(V); \
	xmv_##S NegativeV = XMVectorSubtract_##S(Zero, V); \
	xmv_##S ZIsNegative = XMVectorLess_##S(Z, Zero); \
	xmv_##S YZYYIsNegative = XMVectorLess_##S(YZYY, Zero); \
	xmv_##S Sv = XMVectorAdd_##S(YZYY, Z); \
	xmv_##S D = XMVectorSubtract_##S(YZYY, Z); \
	xmv_##S Select = XMVectorEqualInt_##S(ZIsNegative, YZYYIsNegative); \
	xmv_##S R0 = XMVectorPermute_1X0X0X0X_##S(NegativeV, Sv); \
	xmv_##S R1 = XMVectorPermute_1X0X0X0X_##S(V, D); \
	return XMVectorSelect_##S(R1, R0, Select); \
} \
static xmv_##S XMVector3Normalize_##S(xmv_##S V) \
{ \
	T sq[4], len, r[4]; \
	int i, nonzero, finite_sq; \
	for (i = 0; i < 4; i++) sq[i] = V.f[i] * V.f[i]; \
	/* add_ss of lane 0 with lane 1 (shuffle 2,1,2,1), then with lane 2 */ \
	sq[0] = sq[0] + sq[1]; \
	sq[0] = sq[0] + sq[2]; \
	len = SQRT(sq[0]); \
	nonzero = (T)0 != len || len != len; /* cmpneq: unordered is true */ \
	finite_sq = sq[0] != (T)INFINITY || sq[0] != sq[0]; \
	for (i = 0; i < 4; i++) { \
		r[i] = V.f[i] / len; \
		if (!nonzero) r[i] = 0; /* and with the zero mask: +0 */ \
		if (!finite_sq) r[i] = (T)NAN; /* g_XMQNaN */ \
	} \
	return xm_set_##S(r[0], r[1], r[2], r[3]); \
} \
static xmv_##S XMVector3Cross_##S(xmv_##S V1, xmv_##S V2) \
{ \
	/* PERMUTE(V1, 3,0,2,1) = (y, z, x, w); PERMUTE(V2, 3,1,0,2) = (z, x, y, w) */ \
	xmv_##S t1 = xm_set_##S(V1.f[1], V1.f[2], V1.f[0], V1.f[3]); \
	xmv_##S t2 = xm_set_##S(V2.f[2], V2.f[0], V2.f[1], V2.f[3]); \
	T res[4]; \
	int i; \
	for (i = 0; i < 4; i++) res[i] = t1.f[i] * t2.f[i]; \
	t1 = xm_set_##S(t1.f[1], t1.f[2], t1.f[0], t1.f[3]); \
	t2 = xm_set_##S(t2.f[2], t2.f[0], t2.f[1], t2.f[3]); \
	for (i = 0; i < 4; i++) res[i] = res[i] - t1.f[i] * t2.f[i]; \
	return xm_set_##S(res[0], res[1], res[2], 0); \
}
DXM_LANES(float, f, sqrtf)
DXM_LANES(double, d, sqrt)
static void ind_directxmathf(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	xmv_f v = xm_set_f(n.x, n.y, n.z, 0), t = XMVector3Normalize_f(XMVector3Orthogonal_f(v)), b = XMVector3Cross_f(v, t);
	*b1 = vf(t.f[0], t.f[1], t.f[2]); *b2 = vf(b.f[0], b.f[1], b.f[2]);
}
static void ind_directxmathd(Vec3d n, Vec3d *b1, Vec3d *b2)
{
	xmv_d v = xm_set_d(n.x, n.y, n.z, 0), t = XMVector3Normalize_d(XMVector3Orthogonal_d(v)), b = XMVector3Cross_d(v, t);
	*b1 = vd(t.f[0], t.f[1], t.f[2]); *b2 = vd(b.f[0], b.f[1], b.f[2]);
}


/* ---- Ogre OgreVector.h: VectorBase<3, Real> as an array with ptr()
   loops (dotProduct from ret = 0, length() = sqrt(squaredLength()),
   normalise() with fInvLength = 1.0f / fLength when fLength > 0),
   perpendicular() (Hocevar) and crossProduct ---- */
#define OGRE_VECTOR3(T, S, SQRT, FABS) \
typedef struct { T v[3]; } ogVector3_##S; \
static ogVector3_##S og_make_##S(T x, T y, T z) { ogVector3_##S r; r.v[0] = x; r.v[1] = y; r.v[2] = z; return r; } \
static T og_dotProduct_##S(const ogVector3_##S *a, const ogVector3_##S *b) \
{ \
	T ret = 0; \
	int i; \
	for (i = 0; i < 3; i++) \
		ret += a->v[i] * b->v[i]; \
	return ret; \
} \
static T og_normalise_##S(ogVector3_##S *a) \
{ \
	T fLength = SQRT(og_dotProduct_##S(a, a)); \
	if (fLength > (T)(0.0f)) { \
		T fInvLength = 1.0f / fLength; \
		int i; \
		for (i = 0; i < 3; i++) \
			a->v[i] *= fInvLength; \
	} \
	return fLength; \
} \
static ogVector3_##S og_perpendicular_##S(ogVector3_##S a) \
{ \
	const T x = a.v[0], y = a.v[1], z = a.v[2]; \
	ogVector3_##S perp = FABS(x) > FABS(z) ? og_make_##S(-y, x, (T)0.0) : og_make_##S((T)0.0, -z, y); \
	og_normalise_##S(&perp); /* normalisedCopy */ \
	return perp; \
} \
static ogVector3_##S og_crossProduct_##S(ogVector3_##S a, ogVector3_##S r) \
{ \
	return og_make_##S(a.v[1] * r.v[2] - a.v[2] * r.v[1], a.v[2] * r.v[0] - a.v[0] * r.v[2], \
	                   a.v[0] * r.v[1] - a.v[1] * r.v[0]); \
}
OGRE_VECTOR3(float, f, sqrtf, fabsf)
OGRE_VECTOR3(double, d, sqrt, fabs)
static void ind_ogref(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	ogVector3_f v = og_make_f(n.x, n.y, n.z), t = og_perpendicular_f(v), b = og_crossProduct_f(v, t);
	*b1 = vf(t.v[0], t.v[1], t.v[2]); *b2 = vf(b.v[0], b.v[1], b.v[2]);
}
static void ind_ogred(Vec3d n, Vec3d *b1, Vec3d *b2)
{
	ogVector3_d v = og_make_d(n.x, n.y, n.z), t = og_perpendicular_d(v), b = og_crossProduct_d(v, t);
	*b1 = vd(t.v[0], t.v[1], t.v[2]); *b2 = vd(b.v[0], b.v[1], b.v[2]);
}


/* ---- bx include/bx/inline/math.inl (x86, BX_SIMD_SUPPORTED):
   abs (a < 0 ? -a : a), max (a > b ? a : b), copySign, rcp (1/a),
   sqrtSimd (NaN pattern below 0, 0 below kFloatSmallest, else sqrtps),
   rcpSafe, cross and calcTangentFrame(_outT, _outB, _n); fixed: this
   project's branch abs(nx) > abs(ny) ---- */
#define BX_MATH(T, S, SQRT) \
static T bx_abs_##S(T a) { return a < (T)0.0f ? -a : a; } \
static T bx_max_##S(T a, T b) { return a > b ? a : b; } \
static T bx_rcp_##S(T a) { return (T)1.0f / a; } \
static T bx_sqrt_##S(T a) \
{ \
	const T kFloatSmallest = (T)1.175494351e-38f; \
	if (a < (T)0.0f) return (T)NAN; \
	else if (a < kFloatSmallest) return (T)0.0f; \
	return SQRT(a); \
} \
static T bx_rcpSafe_##S(T a) { return bx_rcp_##S((T)copysign((double)bx_max_##S((T)1.175494351e-38f, bx_abs_##S(a)), (double)a)); } \
static void bx_calcTangentFrame_##S(T outT[3], T outB[3], const T n[3], int fixed) \
{ \
	const T nx = n[0], ny = n[1], nz = n[2]; \
	if (bx_abs_##S(nx) > bx_abs_##S(fixed ? ny : nz)) { \
		const T invLen = bx_rcpSafe_##S(bx_sqrt_##S(nx*nx + nz*nz)); \
		outT[0] = -nz * invLen; \
		outT[1] = (T)0.0f; \
		outT[2] = nx * invLen; \
	} else { \
		const T invLen = bx_rcpSafe_##S(bx_sqrt_##S(ny*ny + nz*nz)); \
		outT[0] = (T)0.0f; \
		outT[1] = nz * invLen; \
		outT[2] = -ny * invLen; \
	} \
	outB[0] = n[1]*outT[2] - n[2]*outT[1]; \
	outB[1] = n[2]*outT[0] - n[0]*outT[2]; \
	outB[2] = n[0]*outT[1] - n[1]*outT[0]; \
}
BX_MATH(float, f, sqrtf)
BX_MATH(double, d, sqrt)
static void ind_bxf(Vec3f n, Vec3f *b1, Vec3f *b2, int fixed)
{
	float v[3] = { n.x, n.y, n.z }, t[3], b[3];
	bx_calcTangentFrame_f(t, b, v, fixed);
	*b1 = vf(t[0], t[1], t[2]); *b2 = vf(b[0], b[1], b[2]);
}
static void ind_bxd(Vec3d n, Vec3d *b1, Vec3d *b2, int fixed)
{
	double v[3] = { n.x, n.y, n.z }, t[3], b[3];
	bx_calcTangentFrame_d(t, b, v, fixed);
	*b1 = vd(t[0], t[1], t[2]); *b2 = vd(b[0], b[1], b[2]);
}

/* ids 700 and up (indep_wild_e.h has 500) (the rows INDEP_WILD_C_ROWS in tests/indep.h's table) */
enum { IW_RAYLIB = 700, IW_GODOT, IW_GODOT_FIXED, IW_DIRECTXMATH, IW_OGRE, IW_BX, IW_BX_FIXED };
#define INDEP_WILD_C_SWITCH(S, V) \
static int indep_wild_c_##S(int id, V n, V *b1, V *b2) \
{ \
	switch (id) { \
	case IW_RAYLIB:      ind_raylib##S(n, b1, b2); return 1; \
	case IW_GODOT:       ind_godot##S(n, b1, b2, 0); return 1; \
	case IW_GODOT_FIXED: ind_godot##S(n, b1, b2, 1); return 1; \
	case IW_DIRECTXMATH: ind_directxmath##S(n, b1, b2); return 1; \
	case IW_OGRE:        ind_ogre##S(n, b1, b2); return 1; \
	case IW_BX:          ind_bx##S(n, b1, b2, 0); return 1; \
	case IW_BX_FIXED:    ind_bx##S(n, b1, b2, 1); return 1; \
	default:             return 0; \
	} \
}
INDEP_WILD_C_SWITCH(f, Vec3f)
INDEP_WILD_C_SWITCH(d, Vec3d)
/* the table rows, in registry order (after open3d) */
#define INDEP_WILD_C_ROWS \
	{ "raylib", onb_raylib, onb_raylibf, IW_RAYLIB, 0 }, \
	{ "godot", onb_godot, onb_godotf, IW_GODOT, 0 }, \
	{ "directxmath", onb_directxmath, onb_directxmathf, IW_DIRECTXMATH, 0 }, \
	{ "ogre", onb_ogre, onb_ogref, IW_OGRE, 0 }, \
	{ "bx", onb_bx, onb_bxf, IW_BX, 0 }, \
	{ "godot_fixed", onb_godot_fixed, onb_godot_fixedf, IW_GODOT_FIXED, 0 }, \
	{ "bx_fixed", onb_bx_fixed, onb_bx_fixedf, IW_BX_FIXED, 0 },

#endif /* INDEP_WILD_C_H */
