/*
 * indep.h - a second, independent implementation of every method of
 * libonb, transliterated from each source (not from include/libonb/onb.h, which
 * this file must never include): each source's own vector type and
 * operators are written out in C with that language's semantics, then the
 * published function body follows them statement by statement.
 *
 * tests/test_indep.c compares these bit for bit with the library's inline,
 * out-of-line and batch versions; scripts/mutate.sh uses the same test to
 * catch mutations of include/libonb/onb.h.  Source by source:
 *   Frisvad 2012 (JGT 16(3)): Listing 1 naive, hughes_moeller; Listing 2
 *     frisvad; Listing 3 rsqrt, InvSqrt, SSE_rsqrt, SSE_rsqrt_1N.  Vec3f is
 *     three floats; operator*(float) scales, dot sums left to right,
 *     cross(a, b) = (a.y b.z - a.z b.y, a.z b.x - a.x b.z, a.x b.y - a.y b.x).
 *   Max 2017 (JCGT 6(1)): Listing 2 with t = -0.99998796.
 *   Duff et al. 2017 (JCGT 6(1)): Listing 2 revisedONB (tests `n.z < 0.`,
 *     a double literal), Listing 3 branchlessONB.
 *   Stark 2009 (JGT 14(1)), branch-free listing as reproduced by Hill 2011:
 *     SIGNBIT of differences, zm = 1^(xm & ym); stark_fixed: 1^(xm | ym).
 *   pbrt-v3 src/core/geometry.h: Vector3<T>::operator/ (Float inv = 1/f),
 *     Cross (operands copied to double), CoordinateSystem.
 *   RTOW "The Rest of Your Life": vec3 (double), operator/ = (1/t) * v,
 *     length = sqrt(length_squared()), onb::build_from_w (`> 0.9`, a
 *     double literal).
 *   sydneyzh blog, Python get_onb: t = [n0, n1, n2 + 1], normalize divides
 *     by math.sqrt of the sum of squares.
 * Engines' shipped code (the "wild" rows and the aliases): tests/indep_wild.h.
 * The double variants are the same code with double storage (the float
 * sources) or the sources themselves (RTOW, Python); the float variants of
 * RTOW and the blog are their code with float storage.  Literals are kept
 * as the sources write them.
 */
#ifndef INDEP_H
#define INDEP_H

#include <math.h>
#include <stdint.h>
#include <string.h>
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#define INDEP_SSE 1
#else
#define INDEP_SSE 0
#endif

typedef struct { float  x, y, z; } Vec3f;
typedef struct { double x, y, z; } Vec3d;

static Vec3f vf(float x, float y, float z) { Vec3f v; v.x = x; v.y = y; v.z = z; return v; }
static Vec3d vd(double x, double y, double z) { Vec3d v; v.x = x; v.y = y; v.z = z; return v; }
static float  dotf_(Vec3f a, Vec3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static double dotd_(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static Vec3f mulf_(Vec3f a, float s)  { return vf(a.x * s, a.y * s, a.z * s); }
static Vec3d muld_(Vec3d a, double s) { return vd(a.x * s, a.y * s, a.z * s); }
static Vec3f subf_(Vec3f a, Vec3f b)  { return vf(a.x - b.x, a.y - b.y, a.z - b.z); }
static Vec3d subd_(Vec3d a, Vec3d b)  { return vd(a.x - b.x, a.y - b.y, a.z - b.z); }
static Vec3f crossf_(Vec3f a, Vec3f b) { return vf(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static Vec3d crossd_(Vec3d a, Vec3d b) { return vd(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }

/* ---- Frisvad 2012, Listing 3 ---- */
enum { IND_RSQRT, IND_INVSQRT, IND_SSE, IND_SSE_1N, IND_NONE };
static float ind_rsqrtf(float x) { return (float)(1.0 / sqrt((double)x)); }
static double ind_rsqrtd(double x) { return 1.0 / sqrt(x); }
static float ind_invsqrtf(float x)
{
	float xhalf = 0.5f * x;
	int32_t i;
	memcpy(&i, &x, 4);
	i = 0x5f3759df - (i >> 1);
	memcpy(&x, &i, 4);
	x = x * (1.5f - xhalf * x * x);
	return x;
}
static double ind_invsqrtd(double x)
{
	double xhalf = 0.5 * x;
	int64_t i;
	memcpy(&i, &x, 8);
	i = INT64_C(0x5fe6eb50c7b537a9) - (i >> 1);
	memcpy(&x, &i, 8);
	x = x * (1.5 - xhalf * x * x);
	return x;
}
static float ind_sse_rsqrtf(float x)
{
#if INDEP_SSE
	_mm_store_ss(&x, _mm_rsqrt_ss(_mm_load_ss(&x)));
	return x;
#else
	return 1.0f / sqrtf(x);
#endif
}
static double ind_sse_rsqrtd(double x) { return (double)ind_sse_rsqrtf((float)x); }
static float ind_sse_rsqrt_1nf(float x) { float y = ind_sse_rsqrtf(x); return y * (1.5f - 0.5f * x * y * y); }
static double ind_sse_rsqrt_1nd(double x) { double y = ind_sse_rsqrtd(x); return y * (1.5 - 0.5 * x * y * y); }
static float ind_normf(float x, int k)
{
	return k == IND_INVSQRT ? ind_invsqrtf(x) : k == IND_SSE ? ind_sse_rsqrtf(x) :
	       k == IND_SSE_1N ? ind_sse_rsqrt_1nf(x) : ind_rsqrtf(x);
}
static double ind_normd(double x, int k)
{
	return k == IND_INVSQRT ? ind_invsqrtd(x) : k == IND_SSE ? ind_sse_rsqrtd(x) :
	       k == IND_SSE_1N ? ind_sse_rsqrt_1nd(x) : ind_rsqrtd(x);
}

/* ---- Frisvad 2012, Listing 1 ---- */
static void ind_naivef(Vec3f n, Vec3f *b1, Vec3f *b2, int k)
{
	if (n.x > 0.9f) *b1 = vf(0.0f, 1.0f, 0.0f);
	else            *b1 = vf(1.0f, 0.0f, 0.0f);
	*b1 = subf_(*b1, mulf_(n, dotf_(*b1, n)));
	if (k != IND_NONE)
		*b1 = mulf_(*b1, ind_normf(dotf_(*b1, *b1), k));
	*b2 = crossf_(n, *b1);
}
static void ind_naived(Vec3d n, Vec3d *b1, Vec3d *b2, int k)
{
	if (n.x > 0.9) *b1 = vd(0.0, 1.0, 0.0);
	else           *b1 = vd(1.0, 0.0, 0.0);
	*b1 = subd_(*b1, muld_(n, dotd_(*b1, n)));
	if (k != IND_NONE)
		*b1 = muld_(*b1, ind_normd(dotd_(*b1, *b1), k));
	*b2 = crossd_(n, *b1);
}
static void ind_hmf(Vec3f n, Vec3f *b1, Vec3f *b2, int k)
{
	if (fabsf(n.x) > fabsf(n.z)) *b2 = vf(-n.y, n.x, 0.0f);
	else                         *b2 = vf(0.0f, -n.z, n.y);
	if (k != IND_NONE)
		*b2 = mulf_(*b2, ind_normf(dotf_(*b2, *b2), k));
	*b1 = crossf_(*b2, n);
}
static void ind_hmd(Vec3d n, Vec3d *b1, Vec3d *b2, int k)
{
	if (fabs(n.x) > fabs(n.z)) *b2 = vd(-n.y, n.x, 0.0);
	else                       *b2 = vd(0.0, -n.z, n.y);
	if (k != IND_NONE)
		*b2 = muld_(*b2, ind_normd(dotd_(*b2, *b2), k));
	*b1 = crossd_(*b2, n);
}

/* ---- Frisvad 2012, Listing 2 (t = -0.9999999f); Max 2017 t ---- */
static void ind_frisvadf_t(Vec3f n, Vec3f *b1, Vec3f *b2, float t)
{
	if (n.z < t) {
		*b1 = vf(0.0f, -1.0f, 0.0f);
		*b2 = vf(-1.0f, 0.0f, 0.0f);
		return;
	}
	{
		const float a = 1.0f / (1.0f + n.z);
		const float b = -n.x * n.y * a;
		*b1 = vf(1.0f - n.x * n.x * a, b, -n.x);
		*b2 = vf(b, 1.0f - n.y * n.y * a, -n.y);
	}
}
static void ind_frisvadd_t(Vec3d n, Vec3d *b1, Vec3d *b2, double t)
{
	if (n.z < t) {
		*b1 = vd(0.0, -1.0, 0.0);
		*b2 = vd(-1.0, 0.0, 0.0);
		return;
	}
	{
		const double a = 1.0 / (1.0 + n.z);
		const double b = -n.x * n.y * a;
		*b1 = vd(1.0 - n.x * n.x * a, b, -n.x);
		*b2 = vd(b, 1.0 - n.y * n.y * a, -n.y);
	}
}

/* ---- Duff et al. 2017, Listing 2 (revisedONB) ---- */
static void ind_dufff(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	if (n.z < 0.) {
		const float a = 1.0f / (1.0f - n.z);
		const float b = n.x * n.y * a;
		*b1 = vf(1.0f - n.x * n.x * a, -b, n.x);
		*b2 = vf(b, n.y * n.y * a - 1.0f, -n.y);
	} else {
		const float a = 1.0f / (1.0f + n.z);
		const float b = -n.x * n.y * a;
		*b1 = vf(1.0f - n.x * n.x * a, b, -n.x);
		*b2 = vf(b, 1.0f - n.y * n.y * a, -n.y);
	}
}
static void ind_duffd(Vec3d n, Vec3d *b1, Vec3d *b2)
{
	if (n.z < 0.) {
		const double a = 1.0 / (1.0 - n.z);
		const double b = n.x * n.y * a;
		*b1 = vd(1.0 - n.x * n.x * a, -b, n.x);
		*b2 = vd(b, n.y * n.y * a - 1.0, -n.y);
	} else {
		const double a = 1.0 / (1.0 + n.z);
		const double b = -n.x * n.y * a;
		*b1 = vd(1.0 - n.x * n.x * a, b, -n.x);
		*b2 = vd(b, 1.0 - n.y * n.y * a, -n.y);
	}
}

/* ---- Duff et al. 2017, Listing 3 (branchlessONB) ---- */
static void ind_duff_blf(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	float sign = copysignf(1.0f, n.z);
	const float a = -1.0f / (sign + n.z);
	const float b = n.x * n.y * a;
	*b1 = vf(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
	*b2 = vf(b, sign + n.y * n.y * a, -n.y);
}
static void ind_duff_bld(Vec3d n, Vec3d *b1, Vec3d *b2)
{
	double sign = copysign(1.0, n.z);
	const double a = -1.0 / (sign + n.z);
	const double b = n.x * n.y * a;
	*b1 = vd(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
	*b2 = vd(b, sign + n.y * n.y * a, -n.y);
}

/* ---- this project's float-only methods (README "The methods"),
   written from their description, not from onb.h ---- */
/* duff_wide: Listing 3 on the float input in double, rounded once. */
static void ind_duff_widef(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	Vec3d d = vd(n.x, n.y, n.z), c1, c2;
	ind_duff_bld(d, &c1, &c2);
	*b1 = vf((float)c1.x, (float)c1.y, (float)c1.z);
	*b2 = vf((float)c2.x, (float)c2.y, (float)c2.z);
}
/* duff_comp: Fast2Sum (|a| >= |b|): s + e = a + b exactly */
static float ind_fast2sum(float a, float b, float *e) { float s = a + b; *e = (a - s) + b; return s; }
/* two-product by fma: p + e = a b exactly */
static float ind_2prod(float a, float b, float *e) { float p = a * b; *e = fmaf(a, b, -p); return p; }
/* (u + ul) times the reciprocal a + al, as hi p and lo pl */
static float ind_scale(float u, float ul, float a, float al, float *pl)
{
	float e, p = ind_2prod(u, a, &e);
	*pl = e + (u * al + ul * a);
	return p;
}
static void ind_duff_compf(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	const float s = copysignf(1.0f, n.z);
	float hl, xxl, xyl, yyl, pl, bl, ql, t1l, t2l;
	const float h = ind_fast2sum(s, n.z, &hl);
	const float a = -1.0f / h;
	const float al = a * (fmaf(a, h, 1.0f) + a * hl); /* -1/(h + hl) ~ a + al */
	const float xx = ind_2prod(n.x, n.x, &xxl), xy = ind_2prod(n.x, n.y, &xyl), yy = ind_2prod(n.y, n.y, &yyl);
	const float p = ind_scale(xx, xxl, a, al, &pl), b = ind_scale(xy, xyl, a, al, &bl), q = ind_scale(yy, yyl, a, al, &ql);
	const float t1 = ind_fast2sum(1.0f, s * p, &t1l), t2 = ind_fast2sum(s, q, &t2l);
	const float bb = b + bl;
	*b1 = vf(t1 + (t1l + s * pl), s * bb, -s * n.x);
	*b2 = vf(bb, t2 + (t2l + ql), -n.y);
}

/* ---- Stark 2009, branch-free perpendicular; our completion ---- */
#define IND_SIGNBIT(X) ((unsigned)(signbit(X) != 0))
static void ind_starkf(Vec3f u, Vec3f *b1, Vec3f *b2, int fixed)
{
	const Vec3f a = vf(fabsf(u.x), fabsf(u.y), fabsf(u.z));
	const unsigned uyx = IND_SIGNBIT(a.x - a.y);
	const unsigned uzx = IND_SIGNBIT(a.x - a.z);
	const unsigned uzy = IND_SIGNBIT(a.y - a.z);
	const unsigned xm = uyx & uzx;
	const unsigned ym = (1u ^ xm) & uzy;
	const unsigned zm = fixed ? 1u ^ (xm | ym) : 1u ^ (xm & ym);
	const Vec3f v = crossf_(u, vf((float)xm, (float)ym, (float)zm));
	*b1 = mulf_(v, 1.0f / sqrtf(dotf_(v, v)));
	*b2 = crossf_(u, *b1);
}
static void ind_starkd(Vec3d u, Vec3d *b1, Vec3d *b2, int fixed)
{
	const Vec3d a = vd(fabs(u.x), fabs(u.y), fabs(u.z));
	const unsigned uyx = IND_SIGNBIT(a.x - a.y);
	const unsigned uzx = IND_SIGNBIT(a.x - a.z);
	const unsigned uzy = IND_SIGNBIT(a.y - a.z);
	const unsigned xm = uyx & uzx;
	const unsigned ym = (1u ^ xm) & uzy;
	const unsigned zm = fixed ? 1u ^ (xm | ym) : 1u ^ (xm & ym);
	const Vec3d v = crossd_(u, vd((double)xm, (double)ym, (double)zm));
	*b1 = muld_(v, 1.0 / sqrt(dotd_(v, v)));
	*b2 = crossd_(u, *b1);
}

/* ---- pbrt-v3: Float = float (default build) or double ---- */
static Vec3f pbrt3_divf(Vec3f v, float f) { float inv = (float)1 / f; return vf(v.x * inv, v.y * inv, v.z * inv); }
static Vec3d pbrt3_divd(Vec3d v, double f) { double inv = (double)1 / f; return vd(v.x * inv, v.y * inv, v.z * inv); }
static Vec3f pbrt3_crossf(Vec3f v1, Vec3f v2)
{
	double v1x = v1.x, v1y = v1.y, v1z = v1.z;
	double v2x = v2.x, v2y = v2.y, v2z = v2.z;
	return vf((float)((v1y * v2z) - (v1z * v2y)), (float)((v1z * v2x) - (v1x * v2z)),
	          (float)((v1x * v2y) - (v1y * v2x)));
}
static Vec3d pbrt3_crossd(Vec3d v1, Vec3d v2)
{
	double v1x = v1.x, v1y = v1.y, v1z = v1.z;
	double v2x = v2.x, v2y = v2.y, v2z = v2.z;
	return vd((v1y * v2z) - (v1z * v2y), (v1z * v2x) - (v1x * v2z), (v1x * v2y) - (v1y * v2x));
}
static void ind_pbrt3f(Vec3f v1, Vec3f *v2, Vec3f *v3)
{
	if (fabsf(v1.x) > fabsf(v1.y))
		*v2 = pbrt3_divf(vf(-v1.z, 0.f, v1.x), sqrtf(v1.x * v1.x + v1.z * v1.z));
	else
		*v2 = pbrt3_divf(vf(0.f, v1.z, -v1.y), sqrtf(v1.y * v1.y + v1.z * v1.z));
	*v3 = pbrt3_crossf(v1, *v2);
}
static void ind_pbrt3d(Vec3d v1, Vec3d *v2, Vec3d *v3)
{
	if (fabs(v1.x) > fabs(v1.y))
		*v2 = pbrt3_divd(vd(-v1.z, 0.f, v1.x), sqrt(v1.x * v1.x + v1.z * v1.z));
	else
		*v2 = pbrt3_divd(vd(0.f, v1.z, -v1.y), sqrt(v1.y * v1.y + v1.z * v1.z));
	*v3 = pbrt3_crossd(v1, *v2);
}

/* ---- RTOW: unit_vector(v) = v / v.length(), v / t = (1/t) * v ---- */
static Vec3f rtow_unitf(Vec3f v) { float t = sqrtf(v.x * v.x + v.y * v.y + v.z * v.z); float s = 1 / t; return vf(s * v.x, s * v.y, s * v.z); }
static Vec3d rtow_unitd(Vec3d v) { double t = sqrt(v.x * v.x + v.y * v.y + v.z * v.z); double s = 1 / t; return vd(s * v.x, s * v.y, s * v.z); }
static void ind_rtowf(Vec3f w, Vec3f *b1, Vec3f *b2)
{
	Vec3f unit_w = rtow_unitf(w);
	Vec3f a = (fabsf(unit_w.x) > 0.9) ? vf(0, 1, 0) : vf(1, 0, 0);
	Vec3f v = rtow_unitf(crossf_(unit_w, a));
	Vec3f u = crossf_(unit_w, v);
	*b1 = u;
	*b2 = v;
}
static void ind_rtowd(Vec3d w, Vec3d *b1, Vec3d *b2)
{
	Vec3d unit_w = rtow_unitd(w);
	Vec3d a = (fabs(unit_w.x) > 0.9) ? vd(0, 1, 0) : vd(1, 0, 0);
	Vec3d v = rtow_unitd(crossd_(unit_w, a));
	Vec3d u = crossd_(unit_w, v);
	*b1 = u;
	*b2 = v;
}

/* ---- blog get_onb (Python floats; the float variant stores floats) ---- */
static Vec3f blog_normalizef(Vec3f v) { float l = sqrtf(v.x * v.x + v.y * v.y + v.z * v.z); return vf(v.x / l, v.y / l, v.z / l); }
static Vec3d blog_normalized(Vec3d v) { double l = sqrt(v.x * v.x + v.y * v.y + v.z * v.z); return vd(v.x / l, v.y / l, v.z / l); }
static void ind_blogf(Vec3f n, Vec3f *b1, Vec3f *b2)
{
	Vec3f t = vf(n.x, n.y, n.z + 1);
	Vec3f binormal = blog_normalizef(crossf_(n, t));
	Vec3f tangent = crossf_(n, binormal);
	*b1 = tangent;
	*b2 = binormal;
}
static void ind_blogd(Vec3d n, Vec3d *b1, Vec3d *b2)
{
	Vec3d t = vd(n.x, n.y, n.z + 1);
	Vec3d binormal = blog_normalized(crossd_(n, t));
	Vec3d tangent = crossd_(n, binormal);
	*b1 = tangent;
	*b2 = binormal;
}

/* the physics engines' ids first: indep_wild.h's alias table names ode */
#include "indep_wild_b.h"
#include "indep_wild_e.h"
#include "indep_wild_d.h"
#include "indep_wild.h"
#include "indep_wild_c.h"
#include "indep_wild_b5.h"
#include "indep_wild_b6.h"
#include "indep_wild_c6.h"

/* One entry per registry method: name, and both precisions by an id. */

enum { IM_NAIVE, IM_HM, IM_FRISVAD, IM_FRISVAD_MAX, IM_DUFF, IM_DUFF_BL, IM_STARK, IM_STARK_FIXED,
       IM_PBRT3, IM_RTOW, IM_BLOG, IM_DUFF_WIDE, IM_DUFF_COMP };
static void indep_f(int id, int k, Vec3f n, Vec3f *b1, Vec3f *b2)
{
	if (indep_wild_f(id, n, b1, b2) || indep_wild_b_f(id, n, b1, b2) || indep_wild_e_f(id, n, b1, b2) ||
	    indep_wild_d_f(id, n, b1, b2) || indep_wild_c_f(id, n, b1, b2) ||
	    indep_wild_b5_f(id, n, b1, b2) || indep_wild_b6_f(id, n, b1, b2) ||
	    indep_wild_c6_f(id, n, b1, b2))
		return;
	switch (id) {
	case IM_NAIVE:       ind_naivef(n, b1, b2, k); break;
	case IM_HM:          ind_hmf(n, b1, b2, k); break;
	case IM_FRISVAD:     ind_frisvadf_t(n, b1, b2, -0.9999999f); break;
	case IM_FRISVAD_MAX: ind_frisvadf_t(n, b1, b2, -0.99998796f); break;
	case IM_DUFF:        ind_dufff(n, b1, b2); break;
	case IM_DUFF_BL:     ind_duff_blf(n, b1, b2); break;
	case IM_STARK:       ind_starkf(n, b1, b2, 0); break;
	case IM_STARK_FIXED: ind_starkf(n, b1, b2, 1); break;
	case IM_PBRT3:       ind_pbrt3f(n, b1, b2); break;
	case IM_RTOW:        ind_rtowf(n, b1, b2); break;
	case IM_DUFF_WIDE:   ind_duff_widef(n, b1, b2); break;
	case IM_DUFF_COMP:   ind_duff_compf(n, b1, b2); break;
	default:             ind_blogf(n, b1, b2); break;
	}
}
static void indep_d(int id, int k, Vec3d n, Vec3d *b1, Vec3d *b2)
{
	if (indep_wild_d(id, n, b1, b2) || indep_wild_b_d(id, n, b1, b2) || indep_wild_e_d(id, n, b1, b2) ||
	    indep_wild_d_d(id, n, b1, b2) || indep_wild_c_d(id, n, b1, b2) ||
	    indep_wild_b5_d(id, n, b1, b2) || indep_wild_b6_d(id, n, b1, b2) ||
	    indep_wild_c6_d(id, n, b1, b2))
		return;
	switch (id) {
	case IM_NAIVE:       ind_naived(n, b1, b2, k); break;
	case IM_HM:          ind_hmd(n, b1, b2, k); break;
	case IM_FRISVAD:     ind_frisvadd_t(n, b1, b2, -0.9999999); break;
	case IM_FRISVAD_MAX: ind_frisvadd_t(n, b1, b2, -0.99998796); break;
	case IM_DUFF:        ind_duffd(n, b1, b2); break;
	case IM_DUFF_BL:     ind_duff_bld(n, b1, b2); break;
	case IM_STARK:       ind_starkd(n, b1, b2, 0); break;
	case IM_STARK_FIXED: ind_starkd(n, b1, b2, 1); break;
	case IM_PBRT3:       ind_pbrt3d(n, b1, b2); break;
	case IM_RTOW:        ind_rtowd(n, b1, b2); break;
	default:             ind_blogd(n, b1, b2); break;
	}
}

/* The library's methods as the tests see them: name, the inline double and
   float functions of include/libonb/onb.h, and the id of the independent
   implementation above with its normalization; the including file brings
   onb.h first (this file never includes it).  With INDEP_TABLE_DEFINE
   (defined before this header is included) it defines the table T and NT;
   without, only the row type. */
typedef void (*fn_d)(onb_vec3, onb_vec3 *, onb_vec3 *);
typedef void (*fn_f)(onb_vec3f, onb_vec3f *, onb_vec3f *);
typedef struct { const char *name; fn_d d; fn_f f; int id, k; } indep_row;
#ifdef INDEP_TABLE_DEFINE
static const indep_row T[] = {
	{ "naive", onb_naive, onb_naivef, IM_NAIVE, IND_RSQRT },
	{ "naive_invsqrt", onb_naive_invsqrt, onb_naive_invsqrtf, IM_NAIVE, IND_INVSQRT },
	{ "naive_rsqrt", onb_naive_rsqrt, onb_naive_rsqrtf, IM_NAIVE, IND_SSE },
	{ "naive_rsqrt_nr", onb_naive_rsqrt_nr, onb_naive_rsqrt_nrf, IM_NAIVE, IND_SSE_1N },
	{ "naive_nonorm", onb_naive_nonorm, onb_naive_nonormf, IM_NAIVE, IND_NONE },
	{ "hughes_moeller", onb_hughes_moeller, onb_hughes_moellerf, IM_HM, IND_RSQRT },
	{ "hughes_moeller_invsqrt", onb_hughes_moeller_invsqrt, onb_hughes_moeller_invsqrtf, IM_HM, IND_INVSQRT },
	{ "hughes_moeller_rsqrt", onb_hughes_moeller_rsqrt, onb_hughes_moeller_rsqrtf, IM_HM, IND_SSE },
	{ "hughes_moeller_rsqrt_nr", onb_hughes_moeller_rsqrt_nr, onb_hughes_moeller_rsqrt_nrf, IM_HM, IND_SSE_1N },
	{ "hughes_moeller_nonorm", onb_hughes_moeller_nonorm, onb_hughes_moeller_nonormf, IM_HM, IND_NONE },
	{ "frisvad", onb_frisvad, onb_frisvadf, IM_FRISVAD, 0 },
	{ "frisvad_max", onb_frisvad_max, onb_frisvad_maxf, IM_FRISVAD_MAX, 0 },
	{ "duff", onb_duff, onb_dufff, IM_DUFF, 0 },
	{ "duff_branchless", onb_duff_branchless, onb_duff_branchlessf, IM_DUFF_BL, 0 },
	{ "stark", onb_stark, onb_starkf, IM_STARK, 0 },
	{ "stark_fixed", onb_stark_fixed, onb_stark_fixedf, IM_STARK_FIXED, 0 },
	{ "pbrt_v3", onb_pbrt_v3, onb_pbrt_v3f, IM_PBRT3, 0 },
	{ "rtow", onb_rtow, onb_rtowf, IM_RTOW, 0 },
	{ "tangent_cross_z", onb_tangent_cross_z, onb_tangent_cross_zf, IM_BLOG, 0 },
	{ "q2rtx", onb_q2rtx, onb_q2rtxf, IW_Q2RTX, 0 },
	{ "filament", onb_filament, onb_filamentf, IW_FILAMENT, 0 },
	{ "filament_hm", onb_filament_hm, onb_filament_hmf, IW_FILAMENT_HM, 0 },
	{ "capsaicin", onb_capsaicin, onb_capsaicinf, IW_CAPSAICIN, 0 },
	{ "capsaicin_fixed", onb_capsaicin_fixed, onb_capsaicin_fixedf, IW_CAPSAICIN_FIXED, 0 },
	{ "unity", onb_unity, onb_unityf, IW_UNITY, 0 },
	{ "willems", onb_willems, onb_willemsf, IW_WILLEMS, 0 },
	{ "gltf_viewer", onb_gltf_viewer, onb_gltf_viewerf, IW_GLTF_VIEWER, 0 },
	{ "rtao", onb_rtao, onb_rtaof, IW_RTAO, 0 },
	{ "rtao_fixed", onb_rtao_fixed, onb_rtao_fixedf, IW_RTAO_FIXED, 0 },
	{ "mitsuba3", onb_mitsuba3, onb_mitsuba3f, IW_MITSUBA3, 0 },
	{ "cycles_cross111", onb_cycles_cross111, onb_cycles_cross111f, IW_CYCLES111, 0 },
	{ "cycles_cross111_avx2", onb_cycles_cross111_avx2, onb_cycles_cross111_avx2f, IW_CYCLES111_AVX2, 0 },
	{ "embree", onb_embree, onb_embreef, IW_EMBREE, 0 },
	{ "luxcore", onb_luxcore, onb_luxcoref, IW_LUXCORE, 0 },
	INDEP_WILD_E_ROWS
	INDEP_WILD_C6_ROWS
	{ "jolt", onb_jolt, onb_joltf, IW_JOLT, 0 },
	{ "jolt_fma", onb_jolt_fma, onb_jolt_fmaf, IW_JOLT_FMA, 0 },
	{ "bullet", onb_bullet, onb_bulletf, IW_BULLET, 0 },
	{ "mujoco", onb_mujoco, onb_mujocof, IW_MUJOCO, 0 },
	{ "eigen", onb_eigen, onb_eigenf, IW_EIGEN, 0 },
	{ "physx", onb_physx, onb_physxf, IW_PHYSX, 0 },
	{ "rp3d", onb_rp3d, onb_rp3df, IW_RP3D, 0 },
	{ "open3d", onb_open3d, onb_open3df, IW_OPEN3D, 0 },
	INDEP_WILD_C_ROWS
	INDEP_WILD_B5_ROWS
	INDEP_WILD_B6_ROWS
	{ "physx_fixed", onb_physx_fixed, onb_physx_fixedf, IW_PHYSX_FIXED, 0 },
	{ "open3d_fixed", onb_open3d_fixed, onb_open3d_fixedf, IW_OPEN3D_FIXED, 0 },
	{ "filament_fixed", onb_filament_fixed, onb_filament_fixedf, IW_FILAMENT_FIXED, 0 },
	{ "luxcore_fixed", onb_luxcore_fixed, onb_luxcore_fixedf, IW_LUXCORE_FIXED, 0 },
	/* float only (ONB_FLOAT_ONLY): no double function */
	{ "duff_wide", NULL, onb_duff_widef, IM_DUFF_WIDE, 0 },
	{ "duff_comp", NULL, onb_duff_compf, IM_DUFF_COMP, 0 },
};
#define NT (sizeof T / sizeof T[0])
#endif
#endif /* INDEP_H */
