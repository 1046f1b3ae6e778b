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
 */
#ifndef INDEP_WILD_H
#define INDEP_WILD_H

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

/* Ids of this file's transliterations, after indep.h's own. */
enum { IW_PBRT4 = 100, IW_NVPRO, IW_CYCLES_DUFF, IW_FALCOR, IW_PASVULKAN };

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
	default:             return 0;
	}
}
static int indep_wild_d(int id, Vec3d n, Vec3d *b1, Vec3d *b2)
{
	switch (id) {
	case IW_PBRT4: ind_pbrt4d(n, b1, b2); return 1;
	default:       return 0;
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
};
#define NIA (sizeof IA / sizeof IA[0])

#endif /* INDEP_WILD_H */
