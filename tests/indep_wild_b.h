/*
 * indep_wild_b.h - independent transliterations of the physics engines' and
 * geometry libraries' shipped code (the registry's wild rows jolt,
 * jolt_fma, bullet, mujoco, eigen, physx, rp3d, open3d and the alias ode),
 * written from each source at the commit its registry row names, never
 * from include/libonb/onb.h.  Included by tests/indep.h (its Vec3f/Vec3d),
 * which calls indep_wild_b_f/indep_wild_b_d first.  Each engine's own vector type and helpers are
 * written out first, then its function body statement by statement:
 *   Jolt Vec3.inl: the SSE path as four-lane arrays (sub, mul, shuffles,
 *     unpackhi, cmpgt, blendv, max, sqrt, div); Cross with its shuffles;
 *     the FMA build fuses Cross's t1 - t2 into fma(t1's operands, -t2).
 *   Bullet btVector3.h btPlaneSpace1 with btScalar, SIMDSQRT12 and
 *     btRecipSqrt as btScalar.h defines them.
 *   ODE odemath.cpp dxPlaneSpace with dReal, glibc's M_SQRT1_2 (a double)
 *     and dRecipSqrt.
 *   MuJoCo mju_makeFrame with mju_normalize3, mju_dot3, mji_scl3,
 *     mji_subFrom3, mji_cross on frame[9].
 *   Eigen unitOrthogonal_selector<Derived, 3> with isMuchSmallerThan and
 *     dummy_precision, norm() = sqrt(squaredNorm()), cross_impl.
 *   PhysX PxComputeBasisVectors with PxVec3 normalize(), operator/=,
 *     magnitude().
 *   ReactPhysics3D getOneUnitOrthogonalVector with getMinAxis and
 *     operator/(Vector3, decimal), then normal.cross(frictionVector1).
 *   Open3D ConstructOrthogonalBasis with Eigen's normalized() and
 *     squaredNorm (Vector3d: (v0^2 + v1^2) + v2^2, Vector3f:
 *     v0^2 + (v1^2 + v2^2), as Eigen 3.4's redux evaluates them).
 * physx_fixed and open3d_fixed are this project's fixes (one change each
 * to the engine's lines, as docs/wild.md describes), transliterated from
 * that description on top of the engines' code.
 * The float-only sources (Jolt, PhysX) get the same code in double for the
 * double variants; literals are kept as the sources write them.
 */
#ifndef INDEP_WILD_B_H
#define INDEP_WILD_B_H

/* ---- Jolt: an SSE register as four lanes ---- */
#define JOLT_LANES(T, S, SQRT, FMA) \
typedef struct { T v[4]; } jq_##S; \
static jq_##S jq_set_##S(T a, T b, T c, T d) { jq_##S r; r.v[0] = a; r.v[1] = b; r.v[2] = c; r.v[3] = d; return r; } \
static jq_##S jq_sub_##S(jq_##S a, jq_##S b) { return jq_set_##S(a.v[0] - b.v[0], a.v[1] - b.v[1], a.v[2] - b.v[2], a.v[3] - b.v[3]); } \
static jq_##S jq_mul_##S(jq_##S a, jq_##S b) { return jq_set_##S(a.v[0] * b.v[0], a.v[1] * b.v[1], a.v[2] * b.v[2], a.v[3] * b.v[3]); } \
static jq_##S jq_add_##S(jq_##S a, jq_##S b) { return jq_set_##S(a.v[0] + b.v[0], a.v[1] + b.v[1], a.v[2] + b.v[2], a.v[3] + b.v[3]); } \
static jq_##S jq_div_##S(jq_##S a, jq_##S b) { return jq_set_##S(a.v[0] / b.v[0], a.v[1] / b.v[1], a.v[2] / b.v[2], a.v[3] / b.v[3]); } \
static jq_##S jq_sqrt_##S(jq_##S a) { return jq_set_##S(SQRT(a.v[0]), SQRT(a.v[1]), SQRT(a.v[2]), SQRT(a.v[3])); } \
/* _mm_shuffle_ps(a, b, _MM_SHUFFLE(d, c, bb, aa)): lanes a[aa], a[bb], b[c], b[d] */ \
static jq_##S jq_shuf_##S(jq_##S a, jq_##S b, int d, int c, int bb, int aa) { return jq_set_##S(a.v[aa], a.v[bb], b.v[c], b.v[d]); } \
static jq_##S jq_unpackhi_##S(jq_##S a, jq_##S b) { return jq_set_##S(a.v[2], b.v[2], a.v[3], b.v[3]); } \
/* cmpgt as a lane mask; maxps(a, b) = a > b ? a : b; blendv picks b where the mask is set */ \
static int jq_gt1_##S(T a, T b) { return a > b; } \
static jq_##S jq_max_##S(jq_##S a, jq_##S b) { return jq_set_##S(jq_gt1_##S(a.v[0], b.v[0]) ? a.v[0] : b.v[0], jq_gt1_##S(a.v[1], b.v[1]) ? a.v[1] : b.v[1], jq_gt1_##S(a.v[2], b.v[2]) ? a.v[2] : b.v[2], jq_gt1_##S(a.v[3], b.v[3]) ? a.v[3] : b.v[3]); } \
static jq_##S jq_blendv_##S(jq_##S a, jq_##S b, jq_##S x, jq_##S y) { int i; jq_##S r; for (i = 0; i < 4; i++) r.v[i] = jq_gt1_##S(x.v[i], y.v[i]) ? b.v[i] : a.v[i]; return r; } \
/* Vec3::GetNormalizedPerpendicular, JPH_USE_SSE and JPH_USE_SSE4_1 */ \
static jq_##S jolt_perp_##S(jq_##S mValue) \
{ \
	jq_##S zero = jq_set_##S(0, 0, 0, 0); \
	jq_##S neg = jq_sub_##S(zero, mValue); \
	jq_##S perp_x = jq_shuf_##S(jq_unpackhi_##S(mValue, zero), neg, 0, 0, 1, 0); \
	jq_##S perp_y = jq_shuf_##S(jq_unpackhi_##S(zero, mValue), neg, 1, 1, 1, 0); \
	jq_##S sq = jq_mul_##S(mValue, mValue); \
	jq_##S xx = jq_shuf_##S(sq, sq, 0, 0, 0, 0); \
	jq_##S yy = jq_shuf_##S(sq, sq, 1, 1, 1, 1); \
	jq_##S zz = jq_shuf_##S(sq, sq, 2, 2, 2, 2); \
	jq_##S result = jq_blendv_##S(perp_y, perp_x, xx, yy); \
	jq_##S len = jq_sqrt_##S(jq_add_##S(jq_max_##S(xx, yy), zz)); \
	return jq_div_##S(result, len); \
} \
/* Vec3::Cross (this = a, inV2 = b); fused: the default x86 build's vfmsub231ps */ \
static jq_##S jolt_cross_##S(jq_##S a, jq_##S b, int fused) \
{ \
	jq_##S t1 = jq_shuf_##S(b, b, 0, 0, 2, 1), s1 = t1, t2, t3; \
	int i; \
	t1 = jq_mul_##S(t1, a); \
	t2 = jq_shuf_##S(a, a, 0, 0, 2, 1); \
	t2 = jq_mul_##S(t2, b); \
	t3 = jq_sub_##S(t1, t2); \
	if (fused) \
		for (i = 0; i < 4; i++) \
			t3.v[i] = FMA(s1.v[i], a.v[i], -t2.v[i]); \
	return jq_shuf_##S(t3, t3, 0, 0, 2, 1); \
}
JOLT_LANES(float, f, sqrtf, fmaf)
JOLT_LANES(double, d, sqrt, fma)
/* ContactConstraintManager GetTangents: outTangent1 = n.GetNormalizedPerpendicular(), outTangent2 = n.Cross(outTangent1) */
static void ind_joltf(Vec3f n, Vec3f *t1, Vec3f *t2, int fused)
{
	jq_f v = jq_set_f(n.x, n.y, n.z, n.z), p = jolt_perp_f(v), c = jolt_cross_f(v, p, fused);
	*t1 = vf(p.v[0], p.v[1], p.v[2]);
	*t2 = vf(c.v[0], c.v[1], c.v[2]);
}
static void ind_joltd(Vec3d n, Vec3d *t1, Vec3d *t2, int fused)
{
	jq_d v = jq_set_d(n.x, n.y, n.z, n.z), p = jolt_perp_d(v), c = jolt_cross_d(v, p, fused);
	*t1 = vd(p.v[0], p.v[1], p.v[2]);
	*t2 = vd(c.v[0], c.v[1], c.v[2]);
}

/* ---- Bullet btPlaneSpace1 (btScalar float; double: BT_USE_DOUBLE_PRECISION) ---- */
#define BULLET_PLANESPACE(T, S, SQRT, FABS) \
static void bt_planespace1_##S(const T n[3], T p[3], T q[3]) \
{ \
	if (FABS(n[2]) > (T)0.7071067811865475244008443621048490) { \
		T a = n[1] * n[1] + n[2] * n[2]; \
		T k = ((T)((T)1.0 / SQRT((T)a))); \
		p[0] = 0; \
		p[1] = -n[2] * k; \
		p[2] = n[1] * k; \
		q[0] = a * k; \
		q[1] = -n[0] * p[2]; \
		q[2] = n[0] * p[1]; \
	} else { \
		T a = n[0] * n[0] + n[1] * n[1]; \
		T k = ((T)((T)1.0 / SQRT((T)a))); \
		p[0] = -n[1] * k; \
		p[1] = n[0] * k; \
		p[2] = 0; \
		q[0] = -n[2] * p[1]; \
		q[1] = n[2] * p[0]; \
		q[2] = a * k; \
	} \
}
BULLET_PLANESPACE(float, f, sqrtf, fabsf)
BULLET_PLANESPACE(double, d, sqrt, fabs)
static void ind_bulletf(Vec3f n, Vec3f *p, Vec3f *q)
{
	float a[3] = { n.x, n.y, n.z }, b[3], c[3];
	bt_planespace1_f(a, b, c);
	*p = vf(b[0], b[1], b[2]); *q = vf(c[0], c[1], c[2]);
}
static void ind_bulletd(Vec3d n, Vec3d *p, Vec3d *q)
{
	double a[3] = { n.x, n.y, n.z }, b[3], c[3];
	bt_planespace1_d(a, b, c);
	*p = vd(b[0], b[1], b[2]); *q = vd(c[0], c[1], c[2]);
}

/* ---- ODE dxPlaneSpace (dSINGLE: dReal float, dDOUBLE: double) ---- */
#define ODE_SQRT1_2 0.70710678118654752440 /* glibc <math.h>'s M_SQRT1_2, a double, which ODE's #ifndef keeps */
#define ODE_PLANESPACE(T, S, RECIP, FABS) \
static void ode_planespace_##S(const T n[3], T p[3], T q[3]) \
{ \
	if (FABS(n[2]) > ODE_SQRT1_2) { \
		T a = n[1]*n[1] + n[2]*n[2]; \
		T k = RECIP(a); \
		p[0] = 0; \
		p[1] = -n[2]*k; \
		p[2] = n[1]*k; \
		q[0] = a*k; \
		q[1] = -n[0]*p[2]; \
		q[2] = n[0]*p[1]; \
	} else { \
		T a = n[0]*n[0] + n[1]*n[1]; \
		T k = RECIP(a); \
		p[0] = -n[1]*k; \
		p[1] = n[0]*k; \
		p[2] = 0; \
		q[0] = -n[2]*p[1]; \
		q[1] = n[2]*p[0]; \
		q[2] = a*k; \
	} \
}
#define ODE_RECIP_F(x) ((1.0f/sqrtf(x)))
#define ODE_RECIP_D(x) (1.0/sqrt(x))
ODE_PLANESPACE(float, f, ODE_RECIP_F, fabsf)
ODE_PLANESPACE(double, d, ODE_RECIP_D, fabs)
static void ind_odef(Vec3f n, Vec3f *p, Vec3f *q)
{
	float a[3] = { n.x, n.y, n.z }, b[3], c[3];
	ode_planespace_f(a, b, c);
	*p = vf(b[0], b[1], b[2]); *q = vf(c[0], c[1], c[2]);
}
static void ind_oded(Vec3d n, Vec3d *p, Vec3d *q)
{
	double a[3] = { n.x, n.y, n.z }, b[3], c[3];
	ode_planespace_d(a, b, c);
	*p = vd(b[0], b[1], b[2]); *q = vd(c[0], c[1], c[2]);
}

/* ---- MuJoCo mju_makeFrame (mjtNum double; float: mjUSESINGLE) ---- */
#define MUJOCO_FRAME(T, S, SQRT, MINVAL) \
static T mju_normalize3_##S(T vec[3]) \
{ \
	T norm = SQRT(vec[0]*vec[0] + vec[1]*vec[1] + vec[2]*vec[2]); \
	if (norm < MINVAL) { \
		vec[0] = 1; vec[1] = 0; vec[2] = 0; \
	} else { \
		T normInv = 1/norm; \
		vec[0] *= normInv; vec[1] *= normInv; vec[2] *= normInv; \
	} \
	return norm; \
} \
static T mju_dot3_##S(const T v1[3], const T v2[3]) { return v1[0]*v2[0] + v1[1]*v2[1] + v1[2]*v2[2]; } \
static void mji_scl3_##S(T *res, const T vec[3], T scl) { res[0] = vec[0] * scl; res[1] = vec[1] * scl; res[2] = vec[2] * scl; } \
static void mji_subFrom3_##S(T *res, const T vec[3]) { res[0] -= vec[0]; res[1] -= vec[1]; res[2] -= vec[2]; } \
static void mji_cross_##S(T *res, const T a[3], const T b[3]) \
{ \
	res[0] = a[1]*b[2] - a[2]*b[1]; \
	res[1] = a[2]*b[0] - a[0]*b[2]; \
	res[2] = a[0]*b[1] - a[1]*b[0]; \
} \
/* the xaxis check (< 0.5: mjERROR) is the caller's: unit input never reaches it */ \
static void mju_makeFrame_##S(T frame[9]) \
{ \
	T tmp[3]; \
	(void)mju_normalize3_##S(frame); \
	if (mju_dot3_##S(frame+3, frame+3) < (T)0.25) { \
		frame[3] = frame[4] = frame[5] = 0; \
		if (frame[1] < (T)0.5 && frame[1] > (T)-0.5) frame[4] = 1; else frame[5] = 1; \
	} \
	mji_scl3_##S(tmp, frame, mju_dot3_##S(frame, frame+3)); \
	mji_subFrom3_##S(frame+3, tmp); \
	(void)mju_normalize3_##S(frame+3); \
	mji_cross_##S(frame+6, frame, frame+3); \
}
MUJOCO_FRAME(float, f, sqrtf, 1E-15f)
MUJOCO_FRAME(double, d, sqrt, 1E-15)
/* a contact: frame = [normal; 0 (the y-axis undefined); 0] */
static void ind_mujocof(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	float f[9] = { 0 };
	f[0] = n.x; f[1] = n.y; f[2] = n.z;
	mju_makeFrame_f(f);
	*b1 = vf(f[3], f[4], f[5]); *b2 = vf(f[6], f[7], f[8]);
}
static void ind_mujocod(Vec3d n, Vec3d *b1, Vec3d *b2)
{
	double f[9] = { 0 };
	f[0] = n.x; f[1] = n.y; f[2] = n.z;
	mju_makeFrame_d(f);
	*b1 = vd(f[3], f[4], f[5]); *b2 = vd(f[6], f[7], f[8]);
}

/* ---- Eigen unitOrthogonal (Vector3f: dummy_precision 1e-5f, Vector3d: 1e-12) and cross ---- */
#define EIGEN_UNITORTHO(T, S, SQRT, FABS, PREC) \
static int eigen_isMuchSmallerThan_##S(T x, T y) { return FABS(x) <= FABS(y) * PREC; } \
static T eigen_norm2_##S(T a, T b) { return SQRT(a * a + b * b); } \
static void eigen_unitOrthogonal_##S(const T src[3], T perp[3]) \
{ \
	if ((!eigen_isMuchSmallerThan_##S(src[0], src[2])) || (!eigen_isMuchSmallerThan_##S(src[1], src[2]))) { \
		T invnm = (T)1 / eigen_norm2_##S(src[0], src[1]); \
		perp[0] = -src[1] * invnm; \
		perp[1] = src[0] * invnm; \
		perp[2] = 0; \
	} else { \
		T invnm = (T)1 / eigen_norm2_##S(src[1], src[2]); \
		perp[0] = 0; \
		perp[1] = -src[2] * invnm; \
		perp[2] = src[1] * invnm; \
	} \
} \
static void eigen_cross_##S(const T lhs[3], const T rhs[3], T o[3]) \
{ \
	o[0] = lhs[1] * rhs[2] - lhs[2] * rhs[1]; \
	o[1] = lhs[2] * rhs[0] - lhs[0] * rhs[2]; \
	o[2] = lhs[0] * rhs[1] - lhs[1] * rhs[0]; \
}
EIGEN_UNITORTHO(float, f, sqrtf, fabsf, 1e-5f)
EIGEN_UNITORTHO(double, d, sqrt, fabs, 1e-12)
static void ind_eigenf(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	float v[3] = { n.x, n.y, n.z }, p[3], q[3];
	eigen_unitOrthogonal_f(v, p);
	eigen_cross_f(v, p, q);
	*b1 = vf(p[0], p[1], p[2]); *b2 = vf(q[0], q[1], q[2]);
}
static void ind_eigend(Vec3d n, Vec3d *b1, Vec3d *b2)
{
	double v[3] = { n.x, n.y, n.z }, p[3], q[3];
	eigen_unitOrthogonal_d(v, p);
	eigen_cross_d(v, p, q);
	*b1 = vd(p[0], p[1], p[2]); *b2 = vd(q[0], q[1], q[2]);
}

/* ---- PhysX PxComputeBasisVectors with PxVec3T<T> ---- */
#define PHYSX_BASIS(T, S, SQRT, FABS) \
typedef struct { T x, y, z; } PxVec3_##S; \
static PxVec3_##S pxv_##S(T x, T y, T z) { PxVec3_##S v; v.x = x; v.y = y; v.z = z; return v; } \
static T px_magnitudeSquared_##S(const PxVec3_##S *v) { return v->x * v->x + v->y * v->y + v->z * v->z; } \
static T px_magnitude_##S(const PxVec3_##S *v) { return SQRT(px_magnitudeSquared_##S(v)); } \
static void px_divassign_##S(PxVec3_##S *v, T f) { f = (T)1.0 / f; v->x *= f; v->y *= f; v->z *= f; } \
static T px_normalize_##S(PxVec3_##S *v) { const T m = px_magnitude_##S(v); if (m > (T)0.0) px_divassign_##S(v, m); return m; } \
static void PxComputeBasisVectors_##S(const PxVec3_##S *dir, PxVec3_##S *right, PxVec3_##S *up) \
{ \
	if (FABS(dir->y) <= 0.9999f) { \
		*right = pxv_##S(dir->z, 0.0f, -dir->x); \
		(void)px_normalize_##S(right); \
		*up = pxv_##S(dir->y * right->z, dir->z * right->x - dir->x * right->z, -dir->y * right->x); \
	} else { \
		*right = pxv_##S(1.0f, 0.0f, 0.0f); \
		*up = pxv_##S(0.0f, dir->z, -dir->y); \
		(void)px_normalize_##S(up); \
	} \
} \
/* this project's fix: the fallback's right = up.cross(dir) after up.normalize() */ \
static void PxComputeBasisVectorsFixed_##S(const PxVec3_##S *dir, PxVec3_##S *right, PxVec3_##S *up) \
{ \
	if (FABS(dir->y) <= 0.9999f) { \
		PxComputeBasisVectors_##S(dir, right, up); \
	} else { \
		*up = pxv_##S(0.0f, dir->z, -dir->y); \
		(void)px_normalize_##S(up); \
		*right = pxv_##S(up->y * dir->z - up->z * dir->y, up->z * dir->x - up->x * dir->z, up->x * dir->y - up->y * dir->x); \
	} \
}
PHYSX_BASIS(float, f, sqrtf, fabsf)
PHYSX_BASIS(double, d, sqrt, fabs)
static void ind_physxf(Vec3f n, Vec3f *right, Vec3f *up, int fixed)
{
	PxVec3_f dir = pxv_f(n.x, n.y, n.z), r, u;
	if (fixed) PxComputeBasisVectorsFixed_f(&dir, &r, &u); else PxComputeBasisVectors_f(&dir, &r, &u);
	*right = vf(r.x, r.y, r.z); *up = vf(u.x, u.y, u.z);
}
static void ind_physxd(Vec3d n, Vec3d *right, Vec3d *up, int fixed)
{
	PxVec3_d dir = pxv_d(n.x, n.y, n.z), r, u;
	if (fixed) PxComputeBasisVectorsFixed_d(&dir, &r, &u); else PxComputeBasisVectors_d(&dir, &r, &u);
	*right = vd(r.x, r.y, r.z); *up = vd(u.x, u.y, u.z);
}

/* ---- ReactPhysics3D (decimal float; double: IS_RP3D_DOUBLE_PRECISION_ENABLED) ---- */
#define RP3D_ORTHO(T, S, SQRT, FABS) \
typedef struct { T x, y, z; } rp3dVector3_##S; \
static rp3dVector3_##S rp3v_##S(T x, T y, T z) { rp3dVector3_##S v; v.x = x; v.y = y; v.z = z; return v; } \
static int rp3d_getMinAxis_##S(rp3dVector3_##S v) { return (v.x < v.y ? (v.x < v.z ? 0 : 2) : (v.y < v.z ? 1 : 2)); } \
static rp3dVector3_##S rp3d_div_##S(rp3dVector3_##S v, T number) { return rp3v_##S(v.x / number, v.y / number, v.z / number); } \
static rp3dVector3_##S rp3d_cross_##S(rp3dVector3_##S a, rp3dVector3_##S v) \
{ \
	return rp3v_##S(a.y * v.z - a.z * v.y, a.z * v.x - a.x * v.z, a.x * v.y - a.y * v.x); \
} \
static rp3dVector3_##S rp3d_getOneUnitOrthogonalVector_##S(rp3dVector3_##S v) \
{ \
	const T x = v.x, y = v.y, z = v.z; \
	rp3dVector3_##S vectorAbs = rp3v_##S(FABS(x), FABS(y), FABS(z)); \
	int minElement = rp3d_getMinAxis_##S(vectorAbs); \
	if (minElement == 0) \
		return rp3d_div_##S(rp3v_##S((T)0.0, -z, y), SQRT(y*y + z*z)); \
	else if (minElement == 1) \
		return rp3d_div_##S(rp3v_##S(-z, (T)0.0, x), SQRT(x*x + z*z)); \
	else \
		return rp3d_div_##S(rp3v_##S(-y, x, (T)0.0), SQRT(x*x + y*y)); \
}
RP3D_ORTHO(float, f, sqrtf, fabsf)
RP3D_ORTHO(double, d, sqrt, fabs)
static void ind_rp3df(Vec3f n, Vec3f *f1, Vec3f *f2)
{
	rp3dVector3_f normal = rp3v_f(n.x, n.y, n.z), a = rp3d_getOneUnitOrthogonalVector_f(normal), b = rp3d_cross_f(normal, a);
	*f1 = vf(a.x, a.y, a.z); *f2 = vf(b.x, b.y, b.z);
}
static void ind_rp3dd(Vec3d n, Vec3d *f1, Vec3d *f2)
{
	rp3dVector3_d normal = rp3v_d(n.x, n.y, n.z), a = rp3d_getOneUnitOrthogonalVector_d(normal), b = rp3d_cross_d(normal, a);
	*f1 = vd(a.x, a.y, a.z); *f2 = vd(b.x, b.y, b.z);
}

/* ---- Open3D ConstructOrthogonalBasis with Eigen's normalized() ---- */
/* Eigen 3.4 squaredNorm: a Vector3d vectorized as a Packet2d and the rest, a Vector3f by the scalar unroller's halves */
static double o3d_squaredNorm_d(const double v[3]) { return (v[0] * v[0] + v[1] * v[1]) + v[2] * v[2]; }
static float o3d_squaredNorm_f(const float v[3]) { return v[0] * v[0] + (v[1] * v[1] + v[2] * v[2]); }
#define OPEN3D_BASIS(T, S, SQRT, TOL, DIAG) \
static void o3d_normalized_##S(const T v[3], T o[3]) \
{ \
	T z = o3d_squaredNorm_##S(v); \
	if (z > (T)0) { T s = SQRT(z); o[0] = v[0] / s; o[1] = v[1] / s; o[2] = v[2] / s; } \
	else { o[0] = v[0]; o[1] = v[1]; o[2] = v[2]; } \
} \
/* fixed (this project's fix): the guard against +-(0, 1, 1)/sqrt(2), the unit diagonal */ \
static void o3d_ConstructOrthogonalBasis_##S(const T normal[3], T B0[3], T B1[3], int fixed) \
{ \
	static const T tol = TOL; \
	const T a = fixed ? DIAG : 1; \
	T d[3], e[3], c[3], cr[3]; \
	d[0] = 0 - normal[0]; d[1] = a - normal[1]; d[2] = a - normal[2]; \
	e[0] = 0 + normal[0]; e[1] = a + normal[1]; e[2] = a + normal[2]; \
	if (o3d_squaredNorm_##S(d) > tol && (!fixed || o3d_squaredNorm_##S(e) > tol)) { \
		c[0] = normal[1] - normal[2]; c[1] = -normal[0]; c[2] = normal[0]; \
	} else { \
		c[0] = normal[1]; c[1] = normal[2] - normal[0]; c[2] = -normal[1]; \
	} \
	o3d_normalized_##S(c, B0); \
	cr[0] = normal[1] * B0[2] - normal[2] * B0[1]; \
	cr[1] = normal[2] * B0[0] - normal[0] * B0[2]; \
	cr[2] = normal[0] * B0[1] - normal[1] * B0[0]; \
	o3d_normalized_##S(cr, B1); \
}
OPEN3D_BASIS(float, f, sqrtf, 1e-3f, 0x1.6a09e6p-1f)
OPEN3D_BASIS(double, d, sqrt, 1e-3, 0x1.6a09e667f3bcdp-1)
static void ind_open3df(Vec3f n, Vec3f *b1, Vec3f *b2, int fixed)
{
	float v[3] = { n.x, n.y, n.z }, p[3], q[3];
	o3d_ConstructOrthogonalBasis_f(v, p, q, fixed);
	*b1 = vf(p[0], p[1], p[2]); *b2 = vf(q[0], q[1], q[2]);
}
static void ind_open3dd(Vec3d n, Vec3d *b1, Vec3d *b2, int fixed)
{
	double v[3] = { n.x, n.y, n.z }, p[3], q[3];
	o3d_ConstructOrthogonalBasis_d(v, p, q, fixed);
	*b1 = vd(p[0], p[1], p[2]); *b2 = vd(q[0], q[1], q[2]);
}

/* ids 200 and up (the rows of the table in tests/indep.h) */
enum { IW_JOLT = 200, IW_JOLT_FMA, IW_BULLET, IW_ODE, IW_MUJOCO, IW_EIGEN, IW_PHYSX, IW_RP3D, IW_OPEN3D,
       IW_PHYSX_FIXED, IW_OPEN3D_FIXED };
/* The switch from id to transliteration, once per precision (S: f or d). */
#define INDEP_WILD_B_SWITCH(S, V) \
static int indep_wild_b_##S(int id, V n, V *b1, V *b2) \
{ \
	switch (id) { \
	case IW_JOLT:         ind_jolt##S(n, b1, b2, 0); return 1; \
	case IW_JOLT_FMA:     ind_jolt##S(n, b1, b2, 1); return 1; \
	case IW_BULLET:       ind_bullet##S(n, b1, b2); return 1; \
	case IW_ODE:          ind_ode##S(n, b1, b2); return 1; \
	case IW_MUJOCO:       ind_mujoco##S(n, b1, b2); return 1; \
	case IW_EIGEN:        ind_eigen##S(n, b1, b2); return 1; \
	case IW_PHYSX:        ind_physx##S(n, b1, b2, 0); return 1; \
	case IW_RP3D:         ind_rp3d##S(n, b1, b2); return 1; \
	case IW_OPEN3D:       ind_open3d##S(n, b1, b2, 0); return 1; \
	case IW_PHYSX_FIXED:  ind_physx##S(n, b1, b2, 1); return 1; \
	case IW_OPEN3D_FIXED: ind_open3d##S(n, b1, b2, 1); return 1; \
	default:              return 0; \
	} \
}
INDEP_WILD_B_SWITCH(f, Vec3f)
INDEP_WILD_B_SWITCH(d, Vec3d)

#endif /* INDEP_WILD_B_H */
