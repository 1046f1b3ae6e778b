/*
 * indep_wild_b5.h - independent transliterations (issue 44, libraries
 * group 3) of Blender BLI's ortho_basis_v3v3_v3 (math_vector.cc, with
 * len_squared_v2 from BLI_math_vector_inline.c) and Box3D's b3Perp,
 * b3Normalize, b3Cross (include/box3d/math_functions.h) as the contact
 * solver uses them (tangent1 = b3Perp(normal), tangent2 =
 * b3Cross(tangent1, normal)), and appleseed's Basis3<T>::build (basis.h,
 * with vector.h's dot, normalize, operator/ and cross), written from each source at the commit its
 * registry row names, never from include/libonb/onb.h, on the sources'
 * float arrays and structs.  Both libraries are float only: the double
 * rows are the same source with the scalar type double and the constants
 * (FLT_EPSILON, 1000.0f * FLT_MIN) kept as the float source has them.
 * Included by tests/indep.h (its Vec3f/Vec3d), which calls
 * indep_wild_b5_f/indep_wild_b5_d.
 */
#ifndef INDEP_WILD_B5_H
#define INDEP_WILD_B5_H

#include <float.h>

/* ---- Blender BLI, float r[3] arrays of scalar T ---- */
#define BLI_ORTHO(T, S, SQRT) \
static T bli_len_squared_v2_##S(const T v[2]) { return v[0] * v[0] + v[1] * v[1]; } \
static void bli_ortho_basis_v3v3_v3_##S(T r_n1[3], T r_n2[3], const T n[3]) \
{ \
	const T eps = FLT_EPSILON; \
	const T f = bli_len_squared_v2_##S(n); \
	if (f > eps) { \
		const T d = (T)1.0f / SQRT(f); \
		r_n1[0] = n[1] * d; \
		r_n1[1] = -n[0] * d; \
		r_n1[2] = (T)0.0f; \
		r_n2[0] = -n[2] * r_n1[1]; \
		r_n2[1] = n[2] * r_n1[0]; \
		r_n2[2] = n[0] * r_n1[1] - n[1] * r_n1[0]; \
	} \
	else { \
		r_n1[0] = (n[2] < (T)0.0f) ? (T)-1.0f : (T)1.0f; \
		r_n1[1] = r_n1[2] = r_n2[0] = r_n2[2] = (T)0.0f; \
		r_n2[1] = (T)1.0f; \
	} \
}
BLI_ORTHO(float, f, sqrtf)
BLI_ORTHO(double, d, sqrt)
static void ind_blenderf(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	const float v[3] = { n.x, n.y, n.z };
	float t[3], b[3];
	bli_ortho_basis_v3v3_v3_f(t, b, v);
	*b1 = vf(t[0], t[1], t[2]); *b2 = vf(b[0], b[1], b[2]);
}
static void ind_blenderd(Vec3d n, Vec3d *b1, Vec3d *b2)
{
	const double v[3] = { n.x, n.y, n.z };
	double t[3], b[3];
	bli_ortho_basis_v3v3_v3_d(t, b, v);
	*b1 = vd(t[0], t[1], t[2]); *b2 = vd(b[0], b[1], b[2]);
}

/* ---- Box3D math_functions.h, b3Vec3 of scalar T ---- */
#define BOX3D_MATH(T, S, SQRT) \
typedef struct { T x, y, z; } b3Vec3_##S; \
static b3Vec3_##S b3Normalize_##S(b3Vec3_##S a) \
{ \
	T lengthSquared = a.x * a.x + a.y * a.y + a.z * a.z; \
	if (lengthSquared > (T)(1000.0f * FLT_MIN)) { \
		T s = (T)1.0f / SQRT(lengthSquared); \
		b3Vec3_##S u = { s * a.x, s * a.y, s * a.z }; \
		return u; \
	} \
	{ \
		b3Vec3_##S z = { (T)0.0f, (T)0.0f, (T)0.0f }; \
		return z; \
	} \
} \
static b3Vec3_##S b3Perp_##S(b3Vec3_##S a) \
{ \
	b3Vec3_##S p; \
	if (a.x < (T)-0.5f || (T)0.5f < a.x) { \
		p.x = a.y; p.y = -a.x; p.z = (T)0.0f; \
	} else { \
		p.x = (T)0.0f; p.y = a.z; p.z = -a.y; \
	} \
	return b3Normalize_##S(p); \
} \
static b3Vec3_##S b3Cross_##S(b3Vec3_##S a, b3Vec3_##S b) \
{ \
	b3Vec3_##S c; \
	c.x = a.y * b.z - a.z * b.y; \
	c.y = a.z * b.x - a.x * b.z; \
	c.z = a.x * b.y - a.y * b.x; \
	return c; \
}
BOX3D_MATH(float, f, sqrtf)
BOX3D_MATH(double, d, sqrt)
static void ind_box3df(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	b3Vec3_f normal = { n.x, n.y, n.z };
	b3Vec3_f tangent1 = b3Perp_f(normal);
	b3Vec3_f tangent2 = b3Cross_f(tangent1, normal);
	*b1 = vf(tangent1.x, tangent1.y, tangent1.z); *b2 = vf(tangent2.x, tangent2.y, tangent2.z);
}
static void ind_box3dd(Vec3d n, Vec3d *b1, Vec3d *b2)
{
	b3Vec3_d normal = { n.x, n.y, n.z };
	b3Vec3_d tangent1 = b3Perp_d(normal);
	b3Vec3_d tangent2 = b3Cross_d(tangent1, normal);
	*b1 = vd(tangent1.x, tangent1.y, tangent1.z); *b2 = vd(tangent2.x, tangent2.y, tangent2.z);
}

/* ---- appleseed foundation/math/basis.h (Basis3<T>::build) and vector.h
   (dot as a loop from T(0.0), norm = sqrt(square_norm), normalize = v /
   norm with the float/double operator/ as v * (1 / rhs), cross) ---- */
#define APPLESEED_MATH(T, S, SQRT, ABS) \
typedef struct { T x, y, z; } asVector3_##S; \
static T as_comp_##S(const asVector3_##S *v, int i) { return i == 0 ? v->x : i == 1 ? v->y : v->z; } \
static T as_dot_##S(asVector3_##S lhs, asVector3_##S rhs) \
{ \
	T result = (T)0.0; \
	int i; \
	for (i = 0; i < 3; ++i) \
		result += as_comp_##S(&lhs, i) * as_comp_##S(&rhs, i); \
	return result; \
} \
static asVector3_##S as_normalize_##S(asVector3_##S v) \
{ \
	const T nrm = SQRT(as_dot_##S(v, v)); \
	const T rcp = (T)1.0 / nrm; \
	asVector3_##S r = { v.x * rcp, v.y * rcp, v.z * rcp }; \
	return r; \
} \
static asVector3_##S as_cross_##S(asVector3_##S lhs, asVector3_##S rhs) \
{ \
	asVector3_##S result; \
	result.x = lhs.y * rhs.z - rhs.y * lhs.z; \
	result.y = lhs.z * rhs.x - rhs.z * lhs.x; \
	result.z = lhs.x * rhs.y - rhs.x * lhs.y; \
	return result; \
} \
static void as_basis3_build_##S(asVector3_##S normal, asVector3_##S *m_u, asVector3_##S *m_v) \
{ \
	asVector3_##S m_n = normal, u; \
	if (ABS(m_n.x) < ABS(m_n.y)) { \
		if (ABS(m_n.x) < ABS(m_n.z)) { u.x = (T)0.0; u.y = -m_n.z; u.z = m_n.y; } \
		else { u.x = -m_n.y; u.y = m_n.x; u.z = (T)0.0; } \
	} else { \
		if (ABS(m_n.y) < ABS(m_n.z)) { u.x = -m_n.z; u.y = (T)0.0; u.z = m_n.x; } \
		else { u.x = -m_n.y; u.y = m_n.x; u.z = (T)0.0; } \
	} \
	*m_u = as_normalize_##S(u); \
	*m_v = as_cross_##S(*m_u, m_n); \
}
APPLESEED_MATH(float, f, sqrtf, fabsf)
APPLESEED_MATH(double, d, sqrt, fabs)
static void ind_appleseedf(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	asVector3_f nn = { n.x, n.y, n.z }, u, v;
	as_basis3_build_f(nn, &u, &v);
	*b1 = vf(u.x, u.y, u.z); *b2 = vf(v.x, v.y, v.z);
}
static void ind_appleseedd(Vec3d n, Vec3d *b1, Vec3d *b2)
{
	asVector3_d nn = { n.x, n.y, n.z }, u, v;
	as_basis3_build_d(nn, &u, &v);
	*b1 = vd(u.x, u.y, u.z); *b2 = vd(v.x, v.y, v.z);
}

/* ids 950 and up (the rows INDEP_WILD_B5_ROWS in tests/indep.h's table) */
enum { IW_BLENDER = 950, IW_BOX3D, IW_APPLESEED };
#define INDEP_WILD_B5_SWITCH(S, V) \
static int indep_wild_b5_##S(int id, V n, V *b1, V *b2) \
{ \
	switch (id) { \
	case IW_BLENDER: ind_blender##S(n, b1, b2); return 1; \
	case IW_BOX3D:   ind_box3d##S(n, b1, b2); return 1; \
	case IW_APPLESEED: ind_appleseed##S(n, b1, b2); return 1; \
	default:         return 0; \
	} \
}
INDEP_WILD_B5_SWITCH(f, Vec3f)
INDEP_WILD_B5_SWITCH(d, Vec3d)
/* the table rows, in registry order (after bx) */
#define INDEP_WILD_B5_ROWS \
	{ "blender", onb_blender, onb_blenderf, IW_BLENDER, 0 }, \
	{ "box3d", onb_box3d, onb_box3df, IW_BOX3D, 0 }, \
	{ "appleseed", onb_appleseed, onb_appleseedf, IW_APPLESEED, 0 },

#endif /* INDEP_WILD_B5_H */
