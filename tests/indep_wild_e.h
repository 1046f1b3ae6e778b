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
 * Both sources are float only (no double variant: the rows claim float).
 */
#ifndef INDEP_WILD_E_H
#define INDEP_WILD_E_H

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

/* ids of this file (indep_wild.h's are 100+, indep_wild_b.h's 200+) */
enum { IW_OSL_TESTRENDER = 500, IW_TUNGSTEN };

static int indep_wild_e_f(int id, Vec3f n, Vec3f *b1, Vec3f *b2)
{
	switch (id) {
	case IW_OSL_TESTRENDER: ind_osl_from_normalf(n, b1, b2); return 1;
	case IW_TUNGSTEN:       ind_tungstenf(n, b1, b2); return 1;
	default:                return 0;
	}
}
static int indep_wild_e_d(int id, Vec3d n, Vec3d *b1, Vec3d *b2)
{
	(void)id; (void)n; (void)b1; (void)b2;
	return 0;   /* float-only sources */
}

/* rows of indep_wild.h's IA[]: name, target, id, float, double */
#define INDEP_WILD_E_ALIASES \
	{ "osl_testrender", "duff_branchless", IW_OSL_TESTRENDER, 1, 0 }, \
	{ "tungsten", "duff_branchless", IW_TUNGSTEN, 1, 0 },

#endif /* INDEP_WILD_E_H */
