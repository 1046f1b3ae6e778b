/*
 * indep_wild_c.h - independent transliterations of the math libraries'
 * single-perpendicular functions (issue 44, libraries group): raylib
 * raymath.h (Vector3Perpendicular, Vector3Normalize, Vector3CrossProduct)
 * and Godot core/math/vector3.h (get_any_perpendicular with
 * is_zero_approx, cross, normalized), written from each source at the
 * commit its registry row names, never from include/libonb/onb.h, and
 * completed as docs/wild-specs/README.md says: b1 = the source's vector
 * (through the library's own normalize where the source does not
 * normalize), b2 = the library's cross(n, b1).  godot_fixed is this
 * project's fix (BACK where |z| < |y| and x is not the smallest),
 * transliterated from that description on top of Godot's lines.
 * Included by tests/indep.h (its Vec3f/Vec3d), which calls
 * indep_wild_c_f/indep_wild_c_d.  raylib is float only: its double rows
 * are the same source in double; Godot's real_t is float or double.
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

/* ids 500 and up (the rows INDEP_WILD_C_ROWS in tests/indep.h's table) */
enum { IW_RAYLIB = 500, IW_GODOT, IW_GODOT_FIXED };
#define INDEP_WILD_C_SWITCH(S, V) \
static int indep_wild_c_##S(int id, V n, V *b1, V *b2) \
{ \
	switch (id) { \
	case IW_RAYLIB:      ind_raylib##S(n, b1, b2); return 1; \
	case IW_GODOT:       ind_godot##S(n, b1, b2, 0); return 1; \
	case IW_GODOT_FIXED: ind_godot##S(n, b1, b2, 1); return 1; \
	default:             return 0; \
	} \
}
INDEP_WILD_C_SWITCH(f, Vec3f)
INDEP_WILD_C_SWITCH(d, Vec3d)
/* the table rows, in registry order (after open3d) */
#define INDEP_WILD_C_ROWS \
	{ "raylib", onb_raylib, onb_raylibf, IW_RAYLIB, 0 }, \
	{ "godot", onb_godot, onb_godotf, IW_GODOT, 0 }, \
	{ "godot_fixed", onb_godot_fixed, onb_godot_fixedf, IW_GODOT_FIXED, 0 },

#endif /* INDEP_WILD_C_H */
