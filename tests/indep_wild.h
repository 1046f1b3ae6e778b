/*
 * indep_wild.h - independent transliterations of engines' shipped code (the
 * registry's "wild" rows and aliases), written from each engine's source at
 * the commit its registry row names, never from include/libonb/onb.h.
 * Included by tests/indep.h (its Vec3f/Vec3d types), which calls
 * indep_wild_f/indep_wild_d first.  Each engine's own helpers (sign
 * functions, Sqr, mulsign, its rsqrt and Newton step, its cross) are
 * written out with that language's semantics, then the function body
 * follows them statement by statement:
 *   pbrt-v4 src/pbrt/util/vecmath.h CoordinateSystem: pstd::copysign,
 *     Sqr(v) = v * v, the literals 1 and -1 converted to Float.
 *   nvpro_core nvvkhl/shaders/func.h orthonormalBasis (float literals).
 *   Blender Cycles src/util/math.h make_orthonormals of 9056d818a:
 *     signf(f) = f < 0 ? -1 : 1.
 *   Falcor MathHelpers.slang branchlessONB: sign = n.z >= 0 ? 1 : -1 (ints).
 *   PasVulkan tangentspacebasis.glsl: GLSL sign() (0 for either zero; our
 *     reading for NaN: 0, both comparisons being false).
 *   Quake II RTX utils.glsl construct_ONB_frisvad (mat3 columns b1, n, b2).
 *   Filament TangentSpaceMesh.cpp frisvadKernel (y-up; returns {b, t}).
 *   Mitsuba 3 vector.h coordinate_system with Dr.Jit's scalar sign,
 *     rcp, square, mulsign, mulsign_neg and fmadd (no FMA).
 *   Blender Cycles math_float3.h make_orthonormals, its SSE4.2 helpers
 *     (dpps dot, lane-wise division, msub cross).
 *   Embree linearspace3.h frame(N), vec3fa.h dot/cross/normalize,
 *     emath.h rsqrt (rsqrtss and its Newton step).
 *   LuxCoreRender vector.h CoordinateSystem and Cross.
 */
#ifndef INDEP_WILD_H
#define INDEP_WILD_H

#include <float.h>

/* pbrt-v4: Float sign = pstd::copysign(Float(1), v1.z); Float a = -1 / (sign + v1.z); ... */
static float pbrt4_sqrf(float v) { return v * v; }
static double pbrt4_sqrd(double v) { return v * v; }
static void ind_pbrt4f(Vec3f v1, Vec3f *v2, Vec3f *v3)
{
	float sign = copysignf((float)1, v1.z);
	float a = (float)-1 / (sign + v1.z);
	float b = v1.x * v1.y * a;
	*v2 = vf((float)1 + sign * pbrt4_sqrf(v1.x) * a, sign * b, -sign * v1.x);
	*v3 = vf(b, sign + pbrt4_sqrf(v1.y) * a, -v1.y);
}
static void ind_pbrt4d(Vec3d v1, Vec3d *v2, Vec3d *v3)
{
	double sign = copysign((double)1, v1.z);
	double a = (double)-1 / (sign + v1.z);
	double b = v1.x * v1.y * a;
	*v2 = vd((double)1 + sign * pbrt4_sqrd(v1.x) * a, sign * b, -sign * v1.x);
	*v3 = vd(b, sign + pbrt4_sqrd(v1.y) * a, -v1.y);
}

/* nvpro_core orthonormalBasis(normal, tangent, bitangent) */
static void ind_nvprof(Vec3f normal, Vec3f *tangent, Vec3f *bitangent)
{
	float a, b;
	if (normal.z < -0.99998796F) {
		*tangent = vf(0.0F, -1.0F, 0.0F);
		*bitangent = vf(-1.0F, 0.0F, 0.0F);
		return;
	}
	a = 1.0F / (1.0F + normal.z);
	b = -normal.x * normal.y * a;
	*tangent = vf(1.0F - normal.x * normal.x * a, b, -normal.x);
	*bitangent = vf(b, 1.0f - normal.y * normal.y * a, -normal.y);
}

/* Cycles (9056d818a) make_orthonormals(N, &T, &B) with its signf */
static float cycles_signf(float f) { return (f < 0.0f) ? -1.0f : 1.0f; }
static void ind_cycles_dufff(Vec3f N, Vec3f *T, Vec3f *B)
{
	float sign = cycles_signf(N.z);
	float a = -1.0f / (sign + N.z);
	float b = N.x * N.y * a;
	*T = vf(1.0f + sign * N.x * N.x * a, sign * b, -sign * N.x);
	*B = vf(b, sign + N.y * N.y * a, -N.y);
}

/* Falcor branchlessONB(n, b1, b2) */
static void ind_falcorf(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	float sign = (float)(n.z >= 0 ? 1 : -1);
	const float a = -1.0f / (sign + n.z);
	const float b = n.x * n.y * a;
	*b1 = vf(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
	*b2 = vf(b, sign + n.y * n.y * a, -n.y);
}

/* PasVulkan getTangentSpaceBasisFromNormal(n, t, b) with GLSL sign() */
static float glsl_signf(float v) { return v > 0.0f ? 1.0f : (v < 0.0f ? -1.0f : 0.0f); }
static void ind_pasvulkanf(Vec3f n, Vec3f *t, Vec3f *b)
{
	float s = glsl_signf(glsl_signf(n.z) + 0.5f), a = -1.0f / (s + n.z), c = n.x * n.y * a;
	*t = vf(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
	*b = vf(c, s + n.y * n.y * a, -n.y);
}

/* ---- engines' methods (not aliases) ---- */

/* Quake II RTX construct_ONB_frisvad(normal): a mat3 whose columns are
   ret[0] = tangent, ret[1] = normal, ret[2] = bitangent; b1 = ret[0],
   b2 = ret[2].  The double variant keeps the float literal. */
static void ind_q2rtxf(Vec3f normal, Vec3f *r0, Vec3f *r2)
{
	if (normal.z < -0.999805696f) {
		*r0 = vf(0.0f, -1.0f, 0.0f);
		*r2 = vf(-1.0f, 0.0f, 0.0f);
	} else {
		float a = 1.0f / (1.0f + normal.z);
		float b = -normal.x * normal.y * a;
		*r0 = vf(1.0f - normal.x * normal.x * a, b, -normal.x);
		*r2 = vf(b, 1.0f - normal.y * normal.y * a, -normal.y);
	}
}
static void ind_q2rtxd(Vec3d normal, Vec3d *r0, Vec3d *r2)
{
	if (normal.z < (double)-0.999805696f) {
		*r0 = vd(0.0, -1.0, 0.0);
		*r2 = vd(-1.0, 0.0, 0.0);
	} else {
		double a = 1.0 / (1.0 + normal.z);
		double b = -normal.x * normal.y * a;
		*r0 = vd(1.0 - normal.x * normal.x * a, b, -normal.x);
		*r2 = vd(b, 1.0 - normal.y * normal.y * a, -normal.y);
	}
}

/* Filament frisvadKernel(n) -> {b, t}; the frame is {t, b, n}: b1 = t,
   b2 = b.  The threshold -1.0f + std::numeric_limits<float>::epsilon() is
   a float sum (exact), compared with n.y. */
static void ind_filamentf(Vec3f n, Vec3f *t, Vec3f *b)
{
	if (n.y < -1.0f + FLT_EPSILON) {
		*t = vf(-1.0f, 0.0f, 0.0f);
		*b = vf(0.0f, 0.0f, -1.0f);
	} else {
		float const va = 1.0f / (1.0f + n.y);
		float const vb = -n.z * n.x * va;
		*t = vf(vb, -n.z, 1.0f - n.z * n.z * va);
		*b = vf(1.0f - n.x * n.x * va, -n.x, vb);
	}
}
static void ind_filamentd(Vec3d n, Vec3d *t, Vec3d *b)
{
	if (n.y < (double)(-1.0f + FLT_EPSILON)) {
		*t = vd(-1.0, 0.0, 0.0);
		*b = vd(0.0, 0.0, -1.0);
	} else {
		double const va = 1.0 / (1.0 + n.y);
		double const vb = -n.z * n.x * va;
		*t = vd(vb, -n.z, 1.0 - n.z * n.z * va);
		*b = vd(1.0 - n.x * n.x * va, -n.x, vb);
	}
}

/* filament_fixed (this project's fix, not shipped): Duff et al.'s
   revisedONB (Listing 2 of their paper) on Filament's relabelled vector
   p = (n.z, n.x, n.y); on its lower branch the pair is turned to keep
   Filament's frame at -y, (u, v) -> (v, -u); then back to x, y, z as
   Filament does: (r.y, r.z, r.x). */
#define IND_REVISED_ONB(T, ONE)                                                   \
	static void ind_revised_##T(const T p[3], T u[3], T v[3])                 \
	{                                                                          \
		if (p[2] < (T)0) {                                                 \
			const T a = ONE / (ONE - p[2]);                            \
			const T b = p[0] * p[1] * a;                               \
			u[0] = ONE - p[0] * p[0] * a; u[1] = -b; u[2] = p[0];      \
			v[0] = b; v[1] = p[1] * p[1] * a - ONE; v[2] = -p[1];      \
		} else {                                                           \
			const T a = ONE / (ONE + p[2]);                            \
			const T b = -p[0] * p[1] * a;                              \
			u[0] = ONE - p[0] * p[0] * a; u[1] = b; u[2] = -p[0];      \
			v[0] = b; v[1] = ONE - p[1] * p[1] * a; v[2] = -p[1];      \
		}                                                                  \
	}
IND_REVISED_ONB(float, 1.0f)
IND_REVISED_ONB(double, 1.0)
#define IND_FILAMENT_FIXED(SFX, T, V, MK)                                         \
	static void ind_filament_fixed##SFX(V n, V *b1, V *b2)                     \
	{                                                                          \
		const T p[3] = { n.z, n.x, n.y };                                  \
		T u[3], v[3], w[3];                                                \
		int i;                                                             \
		ind_revised_##T(p, u, v);                                          \
		if (p[2] < (T)0)                                                   \
			for (i = 0; i < 3; i++) { w[i] = v[i]; v[i] = -u[i]; u[i] = w[i]; } \
		*b1 = MK(u[1], u[2], u[0]);                                        \
		*b2 = MK(v[1], v[2], v[0]);                                        \
	}
IND_FILAMENT_FIXED(f, float, Vec3f, vf)
IND_FILAMENT_FIXED(d, double, Vec3d, vd)

/* Mitsuba 3 coordinate_system(n) with Dr.Jit's scalar helpers (no FMA):
   sign = copysign(1, v); rcp(a) = 1 / a; square(v) = v * v; mulsign(v, s)
   = v xor (s & sign bit); mulsign_neg(v, s) = v xor (~s & sign bit);
   fmadd(a, b, c) = a * b + c. */
static float drjit_mulsignf(float v, float s, int neg)
{
	uint32_t a, b;
	memcpy(&a, &v, 4); memcpy(&b, &s, 4);
	a ^= (neg ? ~b : b) & 0x80000000u;
	memcpy(&v, &a, 4);
	return v;
}
static double drjit_mulsignd(double v, double s, int neg)
{
	uint64_t a, b;
	memcpy(&a, &v, 8); memcpy(&b, &s, 8);
	a ^= (neg ? ~b : b) & 0x8000000000000000ull;
	memcpy(&v, &a, 8);
	return v;
}
static void ind_mitsuba3f(Vec3f n, Vec3f *s, Vec3f *t)
{
	float sign = copysignf(1.0f, n.z), a = -(1.0f / (sign + n.z)), b = n.x * n.y * a;
	*s = vf(drjit_mulsignf((n.x * n.x) * a, n.z, 0) + 1, drjit_mulsignf(b, n.z, 0), drjit_mulsignf(n.x, n.z, 1));
	*t = vf(b, n.y * (n.y * a) + sign, -n.y);
}
static void ind_mitsuba3d(Vec3d n, Vec3d *s, Vec3d *t)
{
	double sign = copysign(1.0, n.z), a = -(1.0 / (sign + n.z)), b = n.x * n.y * a;
	*s = vd(drjit_mulsignd((n.x * n.x) * a, n.z, 0) + 1, drjit_mulsignd(b, n.z, 0), drjit_mulsignd(n.x, n.z, 1));
	*t = vd(b, n.y * (n.y * a) + sign, -n.y);
}

/* Blender Cycles make_orthonormals(N, &a, &b) as its SSE4.2 kernel runs
   it: dot = _mm_dp_ps(a, b, 0x7F) = (p0 + p1) + (p2 + 0), normalize(a) =
   a / sqrt(dot(a, a)) lane by lane, cross(a, b) = shuffle(a * shuffle(b)
   - shuffle(a) * b) (msub without FMA). */
static float cyc_dotf(Vec3f a, Vec3f b) { return (a.x * b.x + a.y * b.y) + (a.z * b.z + 0.0f); }
static double cyc_dotd(Vec3d a, Vec3d b) { return (a.x * b.x + a.y * b.y) + (a.z * b.z + 0.0); }
static Vec3f cyc_crossf(Vec3f a, Vec3f b)
{
	/* x = a, y = (b.y, b.z, b.x), z = (a.y b.x, a.z b.y, a.x b.z); x y - z, then lanes (1, 2, 0) */
	Vec3f m = vf(a.x * b.y - a.y * b.x, a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z);
	return vf(m.y, m.z, m.x);
}
static Vec3d cyc_crossd(Vec3d a, Vec3d b)
{
	Vec3d m = vd(a.x * b.y - a.y * b.x, a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z);
	return vd(m.y, m.z, m.x);
}
static void ind_cycles111f(Vec3f N, Vec3f *a, Vec3f *b)
{
	float l;
	if (N.x != N.y || N.x != N.z)
		*a = vf(N.z - N.y, N.x - N.z, N.y - N.x);  /* (1,1,1) x N */
	else
		*a = vf(N.z - N.y, N.x + N.z, -N.y - N.x); /* (-1,1,1) x N */
	l = sqrtf(cyc_dotf(*a, *a));
	*a = vf(a->x / l, a->y / l, a->z / l);
	*b = cyc_crossf(N, *a);
}
static void ind_cycles111d(Vec3d N, Vec3d *a, Vec3d *b)
{
	double l;
	if (N.x != N.y || N.x != N.z)
		*a = vd(N.z - N.y, N.x - N.z, N.y - N.x);
	else
		*a = vd(N.z - N.y, N.x + N.z, -N.y - N.x);
	l = sqrt(cyc_dotd(*a, *a));
	*a = vd(a->x / l, a->y / l, a->z / l);
	*b = cyc_crossd(N, *a);
}

/* The same in Cycles' AVX2 kernel: msub(a, b, c) = _mm_fmsub_ps(a, b, c),
   one rounding of a*b - c, with c = shuffle(a) * b rounded before. */
static Vec3f cyc_cross_fmsubf(Vec3f a, Vec3f b)
{
	Vec3f m = vf(fmaf(a.x, b.y, -(a.y * b.x)), fmaf(a.y, b.z, -(a.z * b.y)), fmaf(a.z, b.x, -(a.x * b.z)));
	return vf(m.y, m.z, m.x);
}
static Vec3d cyc_cross_fmsubd(Vec3d a, Vec3d b)
{
	Vec3d m = vd(fma(a.x, b.y, -(a.y * b.x)), fma(a.y, b.z, -(a.z * b.y)), fma(a.z, b.x, -(a.x * b.z)));
	return vd(m.y, m.z, m.x);
}
static void ind_cycles111_avx2f(Vec3f N, Vec3f *a, Vec3f *b)
{
	ind_cycles111f(N, a, b);
	*b = cyc_cross_fmsubf(N, *a);
}
static void ind_cycles111_avx2d(Vec3d N, Vec3d *a, Vec3d *b)
{
	ind_cycles111d(N, a, b);
	*b = cyc_cross_fmsubd(N, *a);
}

/* Embree frame(N) on Vec3fa (SSE4.2 kernel): dot as dpps, rsqrt =
   rsqrtss estimate r, then 1.5 r + ((x -0.5) r)(r r) (emath.h), normalize(a)
   = a * rsqrt(dot(a, a)), cross through msub without FMA; frame =
   (dx, dy, N).  Double: the float estimate of the float-rounded argument,
   widened, and the same step in double. */
static float emb_rsqrtf(float x)
{
	float r;
#if INDEP_SSE
	r = _mm_cvtss_f32(_mm_rsqrt_ss(_mm_set_ss(x)));
#else
	r = 1.0f / sqrtf(x);
#endif
	return 1.5f * r + ((x * -0.5f) * r) * (r * r);
}
static double emb_rsqrtd(double x)
{
	double r;
#if INDEP_SSE
	r = (double)_mm_cvtss_f32(_mm_rsqrt_ss(_mm_set_ss((float)x)));
#else
	r = (double)(1.0f / sqrtf((float)x));
#endif
	return 1.5 * r + ((x * -0.5) * r) * (r * r);
}
static void ind_embreef(Vec3f N, Vec3f *dx, Vec3f *dy)
{
	const Vec3f dx0 = vf(0, N.z, -N.y), dx1 = vf(-N.z, 0, N.x);
	const Vec3f u = cyc_dotf(dx0, dx0) > cyc_dotf(dx1, dx1) ? dx0 : dx1;
	Vec3f c;
	*dx = mulf_(u, emb_rsqrtf(cyc_dotf(u, u)));
	c = cyc_crossf(N, *dx);
	*dy = mulf_(c, emb_rsqrtf(cyc_dotf(c, c)));
}
static void ind_embreed(Vec3d N, Vec3d *dx, Vec3d *dy)
{
	const Vec3d dx0 = vd(0, N.z, -N.y), dx1 = vd(-N.z, 0, N.x);
	const Vec3d u = cyc_dotd(dx0, dx0) > cyc_dotd(dx1, dx1) ? dx0 : dx1;
	Vec3d c;
	*dx = muld_(u, emb_rsqrtd(cyc_dotd(u, u)));
	c = cyc_crossd(N, *dx);
	*dy = muld_(c, emb_rsqrtd(cyc_dotd(c, c)));
}

/* LuxCoreRender CoordinateSystem(v1, &v2, &v3); Frame: X = v2, Y = v3. */
static void ind_luxcoref(Vec3f v1, Vec3f *v2, Vec3f *v3)
{
	float len = sqrtf(v1.x * v1.x + v1.y * v1.y);
	if (len < 1e-5)
		*v3 = vf(1.f, 0.f, 0.f);
	else
		*v3 = vf(-v1.y / len, v1.x / len, 0);
	*v2 = vf((v1.y * v3->z) - (v1.z * v3->y), (v1.z * v3->x) - (v1.x * v3->z), (v1.x * v3->y) - (v1.y * v3->x));
}
static void ind_luxcored(Vec3d v1, Vec3d *v2, Vec3d *v3)
{
	double len = sqrt(v1.x * v1.x + v1.y * v1.y);
	if (len < 1e-5)
		*v3 = vd(1.0, 0.0, 0.0);
	else
		*v3 = vd(-v1.y / len, v1.x / len, 0);
	*v2 = vd((v1.y * v3->z) - (v1.z * v3->y), (v1.z * v3->x) - (v1.x * v3->z), (v1.x * v3->y) - (v1.y * v3->x));
}

/* luxcore_fixed (this project's fix, not shipped): results/wild/patches/
   luxcore_fixed.diff applied to CoordinateSystem, LuxCore's Vector ops
   spelled out: Normalize(v) = v / v.Length(), operator/(f) multiplies by
   inv = 1.f / f, Length() = sqrtf(x * x + y * y + z * z). */
static void ind_luxcore_fixedf(Vec3f v1, Vec3f *v2, Vec3f *v3)
{
	float len = sqrtf(v1.x * v1.x + v1.y * v1.y);
	if (len < 1e-5) {
		const Vec3f w = vf(1.f - v1.x * v1.x, -v1.x * v1.y, -v1.x * v1.z);
		const float inv = 1.f / sqrtf(w.x * w.x + w.y * w.y + w.z * w.z);
		*v3 = vf(w.x * inv, w.y * inv, w.z * inv);
	} else
		*v3 = vf(-v1.y / len, v1.x / len, 0);
	*v2 = vf((v1.y * v3->z) - (v1.z * v3->y), (v1.z * v3->x) - (v1.x * v3->z), (v1.x * v3->y) - (v1.y * v3->x));
}
static void ind_luxcore_fixedd(Vec3d v1, Vec3d *v2, Vec3d *v3)
{
	double len = sqrt(v1.x * v1.x + v1.y * v1.y);
	if (len < 1e-5) {
		const Vec3d w = vd(1.0 - v1.x * v1.x, -v1.x * v1.y, -v1.x * v1.z);
		const double inv = 1.0 / sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
		*v3 = vd(w.x * inv, w.y * inv, w.z * inv);
	} else
		*v3 = vd(-v1.y / len, v1.x / len, 0);
	*v2 = vd((v1.y * v3->z) - (v1.z * v3->y), (v1.z * v3->x) - (v1.x * v3->z), (v1.x * v3->y) - (v1.y * v3->x));
}

/* Ids of this file's transliterations, after indep.h's own. */
enum { IW_PBRT4 = 100, IW_NVPRO, IW_CYCLES_DUFF, IW_FALCOR, IW_PASVULKAN,
       IW_Q2RTX, IW_FILAMENT, IW_MITSUBA3, IW_CYCLES111, IW_EMBREE, IW_LUXCORE, IW_CYCLES111_AVX2,
       IW_FILAMENT_FIXED, IW_LUXCORE_FIXED };

/* 1 when id is one of this file's (outputs written), else 0; a double
   variant that the source does not have gives 0 too. */
static int indep_wild_f(int id, Vec3f n, Vec3f *b1, Vec3f *b2)
{
	switch (id) {
	case IW_PBRT4:       ind_pbrt4f(n, b1, b2); return 1;
	case IW_NVPRO:       ind_nvprof(n, b1, b2); return 1;
	case IW_CYCLES_DUFF: ind_cycles_dufff(n, b1, b2); return 1;
	case IW_FALCOR:      ind_falcorf(n, b1, b2); return 1;
	case IW_PASVULKAN:   ind_pasvulkanf(n, b1, b2); return 1;
	case IW_Q2RTX:       ind_q2rtxf(n, b1, b2); return 1;
	case IW_FILAMENT:    ind_filamentf(n, b1, b2); return 1;
	case IW_MITSUBA3:    ind_mitsuba3f(n, b1, b2); return 1;
	case IW_CYCLES111:   ind_cycles111f(n, b1, b2); return 1;
	case IW_CYCLES111_AVX2: ind_cycles111_avx2f(n, b1, b2); return 1;
	case IW_EMBREE:      ind_embreef(n, b1, b2); return 1;
	case IW_LUXCORE:     ind_luxcoref(n, b1, b2); return 1;
	case IW_FILAMENT_FIXED: ind_filament_fixedf(n, b1, b2); return 1;
	case IW_LUXCORE_FIXED: ind_luxcore_fixedf(n, b1, b2); return 1;
	default:             return 0;
	}
}
static int indep_wild_d(int id, Vec3d n, Vec3d *b1, Vec3d *b2)
{
	switch (id) {
	case IW_PBRT4:     ind_pbrt4d(n, b1, b2); return 1;
	case IW_Q2RTX:     ind_q2rtxd(n, b1, b2); return 1;
	case IW_FILAMENT:  ind_filamentd(n, b1, b2); return 1;
	case IW_MITSUBA3:  ind_mitsuba3d(n, b1, b2); return 1;
	case IW_CYCLES111: ind_cycles111d(n, b1, b2); return 1;
	case IW_CYCLES111_AVX2: ind_cycles111_avx2d(n, b1, b2); return 1;
	case IW_EMBREE:    ind_embreed(n, b1, b2); return 1;
	case IW_LUXCORE:   ind_luxcored(n, b1, b2); return 1;
	case IW_FILAMENT_FIXED: ind_filament_fixedd(n, b1, b2); return 1;
	case IW_LUXCORE_FIXED: ind_luxcore_fixedd(n, b1, b2); return 1;
	default:           return 0;
	}
}

/* The aliases as the test sees them: name, target, the transliteration's
   id, and the precisions the identity is claimed in (float, double). */
typedef struct { const char *name, *target; int id, fl, dbl; } indep_alias;
static const indep_alias IA[] = {
	{ "pbrt_v4", "duff_branchless", IW_PBRT4, 1, 1 },
	{ "nvpro", "frisvad_max", IW_NVPRO, 1, 0 },
	{ "cycles_duff", "duff", IW_CYCLES_DUFF, 1, 0 },
	{ "falcor", "duff", IW_FALCOR, 1, 0 },
	{ "pasvulkan", "duff", IW_PASVULKAN, 1, 0 },
	{ "ode", "bullet", IW_ODE, 1, 1 },  /* tests/indep_wild_b.h */
	INDEP_WILD_E_ALIASES                /* tests/indep_wild_e.h */
	INDEP_WILD_D_ALIASES                /* tests/indep_wild_d.h */
};
#define NIA (sizeof IA / sizeof IA[0])

#endif /* INDEP_WILD_H */
