/*
 * onb.h - orthonormal bases {b1, b2, n} from a 3D unit vector n.
 *
 * The whole public face of libonb.  C99, libm only.
 *
 * Index
 *   Types ............ onb_vec3 (double), onb_vec3f (float), onb_method
 *   Methods .......... one static inline pair per method, double plain,
 *                      float with the `f` suffix (as in <math.h>):
 *     onb_naive            onb_naivef             Frisvad 2012 Listing 1
 *     onb_naive_invsqrt    onb_naive_invsqrtf       + Listing 3 InvSqrt
 *     onb_naive_rsqrt      onb_naive_rsqrtf         + Listing 3 SSE_rsqrt
 *     onb_naive_rsqrt_nr   onb_naive_rsqrt_nrf      + Listing 3 SSE_rsqrt_1N
 *     onb_naive_nonorm     onb_naive_nonormf        + no normalization
 *     onb_hughes_moeller*  (same five variants)   Hughes & Moller 1999
 *     onb_frisvad          onb_frisvadf           Frisvad 2012 Listing 2
 *     onb_frisvad_max      onb_frisvad_maxf       Max 2017 threshold
 *     onb_duff             onb_dufff              Duff et al. 2017 Listing 2
 *     onb_duff_branchless  onb_duff_branchlessf   Duff et al. 2017 Listing 3
 *     onb_stark            onb_starkf             Stark 2009, as published
 *     onb_stark_fixed      onb_stark_fixedf         + Hill 2011's zm fix
 *     onb_pbrt_v3          onb_pbrt_v3f           pbrt-v3 CoordinateSystem
 *     onb_rtow             onb_rtowf              RTTROYL onb::build_from_w
 *     onb_tangent_cross_z  onb_tangent_cross_zf   blog get_onb
 *     (float only)         onb_duff_widef         this project: Duff in double
 *     (float only)         onb_duff_compf         this project: Duff, fma-compensated
 *   Tools ............ onb_frisvad_threshold[f]  Listing 2 with t as a parameter
 *                      onb_frisvad_rotate[f]     Frisvad 2012 Equation 3
 *                      onb_basis_checked[f]      normalize + status + method
 *   Batch (libonb.a) . onb_<method>_batch[f]     structure-of-arrays loops
 *   Registry ......... onb_methods, onb_find, onb_batch_isa
 *
 * Conventions
 *   - Precondition of every method: n is a unit vector as received in the
 *     format (so |n| = 1 within a few ulps).  Methods never normalize n except
 *     `rtow`, whose source does.  Non-unit, zero and non-finite input is
 *     defined (no UB, no hang) but garbage in, garbage out: see
 *     docs/library.md, "Library contract", or use onb_basis_checked.
 *   - Handedness is det(b1, b2, n): +1 means b1 x b2 = n.
 *   - Each method is written out by hand for double and float, exactly as
 *     published, flaws included.  A fix of a published method is a new,
 *     named method, never an edit of an old one.
 *   - Error bounds quoted in the comments are maxima of the orthonormality
 *     defect max(|b1|-1, |b2|-1, b1.n, b2.n, b1.b2) measured by
 *     `onbstudy sweep` against MPFR; tests/test_lib.c checks the bounds.
 *
 * Floating-point flags (docs/library.md, "Compiler flags"):
 *   - The method names are inline kernels where the caller's flags cannot
 *     change their bits, and calls to libonb.a's out-of-line copies (the
 *     studied bits) where they could: under -ffast-math, and under GCC
 *     with an FMA target outside ISO C mode.  The block after the
 *     includes below gives the exact rule and the defines that override
 *     it (ONB_FP_CONTRACT_OFF, ONB_INLINE_FOLLOWS_CLIENT_FP,
 *     ONB_FORCE_OUTLINE).  onb.h compiles under every flag, -ffast-math
 *     included, with no define.
 *   - onb_NAME_outline[f], onb_NAME_array[f] and method->basis[f] are
 *     always the out-of-line copies, compiled with the library's flags.
 */
#ifndef ONB_H
#define ONB_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* Which code the method names (onb_duff_branchless, ...) run in the
   including file (docs/library.md, "Compiler flags"):
     ONB__INLINE 1  the kernels below, inlined into the caller;
     ONB__INLINE 0  calls to libonb.a's out-of-line copies, compiled with
                    the library's flags: the studied bits, whatever the
                    caller's flags.
   Inline whenever the caller's flags cannot change the bits:
     - GCC: no FMA target (__FP_FAST_FMA[F] undefined), or ISO C mode
       (-std=c99/c11/c17: GCC's default there is -ffp-contract=off), or the
       client defines ONB_FP_CONTRACT_OFF to promise -ffp-contract=off
       (GCC gives no macro for it);
     - clang, without -ffast-math: `#pragma clang fp contract(off)` below
       keeps a*b+c unfused and does not stop inlining;
   out of line under -ffast-math (__FAST_MATH__), and under GCC with an FMA
   target in GNU C or C++ mode (default -ffp-contract=fast), unless
     - ONB_INLINE_FOLLOWS_CLIENT_FP: inline, and no pragma: the kernels
       follow the caller's flags (contraction, -ffast-math), which changes
       their bits and voids the study's error figures for them;
     - ONB_FORCE_OUTLINE: out of line, whatever the compiler and flags.
   Out of line too where float arithmetic is wider than binary32
   (FLT_EVAL_METHOD 1 or 2: GCC on s390x, or on i386 with x87 maths, in
   ISO C mode): the float kernels would be evaluated in double there and
   rounded differently; the library's copies are binary32.
   libonb's own sources define ONB_BUILDING_LIB (inline, built with
   -ffp-contract=off by the Makefile). */
#ifdef __FLT_EVAL_METHOD__
#define ONB__EVAL_METHOD __FLT_EVAL_METHOD__
#else
#include <float.h>
#define ONB__EVAL_METHOD FLT_EVAL_METHOD
#endif
#define ONB__WIDE_FLOAT (ONB__EVAL_METHOD == 1 || ONB__EVAL_METHOD == 2)
#if defined(ONB_BUILDING_LIB) && ONB__WIDE_FLOAT
#error "libonb: float arithmetic is wider than binary32 here (FLT_EVAL_METHOD 1 or 2), so the float kernels would not round as published; build the library with -fexcess-precision=fast (GCC in ISO C mode, e.g. on s390x) or -std=gnu99, or -mfpmath=sse on i386 (docs/library.md)"
#endif
#if defined(ONB_BUILDING_LIB) || defined(ONB_INLINE_FOLLOWS_CLIENT_FP)
#define ONB__INLINE 1
#elif defined(ONB_FORCE_OUTLINE) || defined(__FAST_MATH__) || ONB__WIDE_FLOAT
#define ONB__INLINE 0
#elif defined(__clang__)
#define ONB__INLINE 1
#elif defined(__GNUC__)
#if (!defined(__FP_FAST_FMA) && !defined(__FP_FAST_FMAF)) || \
    (defined(__STRICT_ANSI__) && !defined(__cplusplus)) || defined(ONB_FP_CONTRACT_OFF)
#define ONB__INLINE 1
#else
#define ONB__INLINE 0
#endif
#else
#define ONB__INLINE 1
#endif

/* No contraction into FMA inside the kernels, where a pragma does it
   without stopping inlining.  Popped at the end of the header. */
#if ONB__INLINE && !defined(ONB_INLINE_FOLLOWS_CLIENT_FP) && defined(__clang__)
#pragma float_control(push)
#pragma clang fp contract(off)
#define ONB__FP_PRAGMAS 1
#else
#define ONB__FP_PRAGMAS 0
#endif

/* Kernel names: the method names themselves when inline; otherwise the
   kernels are renamed (and never instantiated) and the method names are
   wrappers around the out-of-line copies, defined at the end. */
#if ONB__INLINE
#define ONB__K(m) onb_##m
#else
#define ONB__K(m) onb__k_##m
#endif

/* Casts that C++ -Wold-style-cast accepts. */
#ifdef __cplusplus
#define ONB__CAST(t, x) static_cast<t>(x)
#else
#define ONB__CAST(t, x) ((t)(x))
#endif

/* The hardware rsqrt (the _rsqrt variants): on x86-64 GCC and clang reach
   rsqrtss through their builtin, without <xmmintrin.h>; other compilers
   include it.  Elsewhere (arm64, s390x, ...) the variants run 1/sqrt and
   the registry says so (ONB_FELL_BACK). */
#if (defined(__SSE__) || defined(_M_X64) || defined(__x86_64__)) && !defined(ONB_NO_HW_RSQRT)
#define ONB_HAVE_HW_RSQRT 1
#if !defined(__GNUC__)
#include <xmmintrin.h>
#endif
#else
#define ONB_HAVE_HW_RSQRT 0
#endif

#ifdef __cplusplus
extern "C" {
#endif

#define ONB_VERSION "0.1.0"

typedef struct { double x, y, z; } onb_vec3;
typedef struct { float  x, y, z; } onb_vec3f;

/* ------------------------------------------------------------------ */
/* Reciprocal square roots of Frisvad 2012, Listing 3                  */
/* ------------------------------------------------------------------ */

/* Listing 3 `rsqrt`: static_cast<float>(1.0/sqrt(x)), i.e. computed in
   double and rounded once to float: correctly rounded for float. */
static inline double onb__rsqrt_libm (double x) { return 1.0 / sqrt(x); }
static inline float  onb__rsqrt_libmf(float x)  { return ONB__CAST(float, 1.0 / sqrt(ONB__CAST(double, x))); }

/* Listing 3 `InvSqrt`: the bit trick and one Newton step.  Unsigned
   arithmetic reads the listing's int shift without implementation-defined
   behaviour; for x >= 0 (a dot product) the bits are the same. */
static inline float onb__invsqrtf(float x)
{
	float xhalf = 0.5f * x;
	uint32_t i;
	memcpy(&i, &x, sizeof i);
	i = 0x5f3759dfu - (i >> 1); /* rsqrt seed, 32-bit */
	memcpy(&x, &i, sizeof x);
	x = x * (1.5f - xhalf * x * x);
	return x;
}
static inline double onb__invsqrt(double x)
{
	double xhalf = 0.5 * x;
	uint64_t i;
	memcpy(&i, &x, sizeof i);
	i = UINT64_C(0x5fe6eb50c7b537a9) - (i >> 1); /* rsqrt seed, 64-bit (Lomont) */
	memcpy(&x, &i, sizeof x);
	x = x * (1.5 - xhalf * x * x);
	return x;
}

/* Listing 3 `SSE_rsqrt`: the hardware approximation (rsqrtss, relative
   error <= 1.5*2^-12).  Double has no such instruction below AVX-512, so
   the double variant rounds x to float, runs rsqrtss and widens the result:
   the same 12-bit approximation a float renderer gets, on every x86-64.
   Without SSE both fall back to 1/sqrt and the registry says so
   (ONB_FELL_BACK). */
static inline float onb__hw_rsqrtf(float x)
{
#if ONB_HAVE_HW_RSQRT && defined(__GNUC__)
	typedef float onb__v4sf __attribute__((__vector_size__(16)));
	onb__v4sf v = { x, 0.0f, 0.0f, 0.0f };
	v = __builtin_ia32_rsqrtss(v);
	return v[0];
#elif ONB_HAVE_HW_RSQRT
	return _mm_cvtss_f32(_mm_rsqrt_ss(_mm_set_ss(x)));
#else
	return 1.0f / sqrtf(x);
#endif
}
static inline double onb__hw_rsqrt(double x) { return ONB__CAST(double, onb__hw_rsqrtf(ONB__CAST(float, x))); }

/* Listing 3 `SSE_rsqrt_1N`: one Newton step on the hardware estimate y. */
static inline float  onb__newtonf(float x, float y)   { return y * (1.5f - 0.5f * x * y * y); }
static inline double onb__newton (double x, double y) { return y * (1.5 - 0.5 * x * y * y); }
static inline float  onb__hw_rsqrt_nrf(float x)  { return onb__newtonf(x, onb__hw_rsqrtf(x)); }
static inline double onb__hw_rsqrt_nr (double x) { return onb__newton(x, onb__hw_rsqrt(x)); }

/* Normalization selectors of the naive and hughes_moeller families.  The
   family kernels take one as a constant, which inlining folds away. */
enum {
	ONB__NORM_LIBM = 0, /* Listing 3 rsqrt       */
	ONB__NORM_INVSQRT,  /* Listing 3 InvSqrt     */
	ONB__NORM_RSQRT,    /* Listing 3 SSE_rsqrt   */
	ONB__NORM_RSQRT_NR, /* Listing 3 SSE_rsqrt_1N*/
	ONB__NORM_NONE      /* no normalization      */
};

static inline double onb__rsq(double x, int norm)
{
	switch (norm) {
	case ONB__NORM_INVSQRT:  return onb__invsqrt(x);
	case ONB__NORM_RSQRT:    return onb__hw_rsqrt(x);
	case ONB__NORM_RSQRT_NR: return onb__hw_rsqrt_nr(x);
	case ONB__NORM_NONE:     return 1.0;
	default:                 return onb__rsqrt_libm(x);
	}
}
static inline float onb__rsqf(float x, int norm)
{
	switch (norm) {
	case ONB__NORM_INVSQRT:  return onb__invsqrtf(x);
	case ONB__NORM_RSQRT:    return onb__hw_rsqrtf(x);
	case ONB__NORM_RSQRT_NR: return onb__hw_rsqrt_nrf(x);
	case ONB__NORM_NONE:     return 1.0f;
	default:                 return onb__rsqrt_libmf(x);
	}
}

/* ------------------------------------------------------------------ */
/* naive (Frisvad 2012, Listing 1, credited there to a reviewer)       */
/* ------------------------------------------------------------------ */
/* b1 = x-axis, or y-axis when n.x > 0.9; b1 -= n*dot(b1, n); b1 *= rsqrt(
   dot(b1, b1)); b2 = cross(n, b1).  Handedness +1.
   Threshold: n.x > 0.9 (one-sided: n.x < -0.9 keeps the x-axis).
   Singular: n = -x exactly (b1 - n*dot = 0, 0*inf = NaN); precision falls
   as n approaches -x, where b1 cancels (relative error ~ eps/|1 + n.x|).
   The dot products are evaluated in full, zeros included, as the Vec3f
   code of the listing does.
   The kernel is split at the normalization (pre/post) so that the batch
   loops can vectorize the hardware rsqrt; the scalar function chains the
   same three steps, so both give the same bits.
   Bound (tests/test_lib.c; u = 2^-24 or 2^-53): defect D <= 12u (1 +
   1/sqrt(1 - (n.e)^2)) for unit-to-rounding n, e the chosen axis.  The
   variants: _invsqrt adds 1.76e-3 to the lengths (Lomont 2003), _rsqrt
   1.5 * 2^-12, _rsqrt_nr 1.5 (1.5 * 2^-12)^2 + 3u; _nonorm's lengths are
   the unnormalized ones. */
static inline double onb__naive_pre(onb_vec3 n, onb_vec3 *b1)
{
	double bx, by, bz, d;
	if (n.x > 0.9) { bx = 0.0; by = 1.0; bz = 0.0; }
	else           { bx = 1.0; by = 0.0; bz = 0.0; }
	d = bx * n.x + by * n.y + bz * n.z;
	bx -= n.x * d;
	by -= n.y * d;
	bz -= n.z * d;
	b1->x = bx; b1->y = by; b1->z = bz;
	return bx * bx + by * by + bz * bz;
}
static inline float onb__naive_pref(onb_vec3f n, onb_vec3f *b1)
{
	float bx, by, bz, d;
	if (n.x > 0.9f) { bx = 0.0f; by = 1.0f; bz = 0.0f; }
	else            { bx = 1.0f; by = 0.0f; bz = 0.0f; }
	d = bx * n.x + by * n.y + bz * n.z;
	bx -= n.x * d;
	by -= n.y * d;
	bz -= n.z * d;
	b1->x = bx; b1->y = by; b1->z = bz;
	return bx * bx + by * by + bz * bz;
}
static inline void onb__naive_post(onb_vec3 n, onb_vec3 u, double s, onb_vec3 *b1, onb_vec3 *b2)
{
	u.x *= s; u.y *= s; u.z *= s;
	*b1 = u;
	b2->x = n.y * u.z - n.z * u.y;
	b2->y = n.z * u.x - n.x * u.z;
	b2->z = n.x * u.y - n.y * u.x;
}
static inline void onb__naive_postf(onb_vec3f n, onb_vec3f u, float s, onb_vec3f *b1, onb_vec3f *b2)
{
	u.x *= s; u.y *= s; u.z *= s;
	*b1 = u;
	b2->x = n.y * u.z - n.z * u.y;
	b2->y = n.z * u.x - n.x * u.z;
	b2->z = n.x * u.y - n.y * u.x;
}
static inline void onb__naive(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2, int norm)
{
	onb_vec3 u;
	double l2 = onb__naive_pre(n, &u);
	onb__naive_post(n, u, onb__rsq(l2, norm), b1, b2);
}
static inline void onb__naivef(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2, int norm)
{
	onb_vec3f u;
	float l2 = onb__naive_pref(n, &u);
	onb__naive_postf(n, u, onb__rsqf(l2, norm), b1, b2);
}

static inline void ONB__K(naive)            (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__naive (n, b1, b2, ONB__NORM_LIBM); }
static inline void ONB__K(naivef)           (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__naivef(n, b1, b2, ONB__NORM_LIBM); }
static inline void ONB__K(naive_invsqrt)    (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__naive (n, b1, b2, ONB__NORM_INVSQRT); }
static inline void ONB__K(naive_invsqrtf)   (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__naivef(n, b1, b2, ONB__NORM_INVSQRT); }
static inline void ONB__K(naive_rsqrt)      (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__naive (n, b1, b2, ONB__NORM_RSQRT); }
static inline void ONB__K(naive_rsqrtf)     (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__naivef(n, b1, b2, ONB__NORM_RSQRT); }
static inline void ONB__K(naive_rsqrt_nr)   (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__naive (n, b1, b2, ONB__NORM_RSQRT_NR); }
static inline void ONB__K(naive_rsqrt_nrf)  (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__naivef(n, b1, b2, ONB__NORM_RSQRT_NR); }
static inline void ONB__K(naive_nonorm)     (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__naive (n, b1, b2, ONB__NORM_NONE); }
static inline void ONB__K(naive_nonormf)    (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__naivef(n, b1, b2, ONB__NORM_NONE); }

/* ------------------------------------------------------------------ */
/* hughes_moeller (Hughes & Moller 1999, as in Frisvad 2012 Listing 1) */
/* ------------------------------------------------------------------ */
/* b2 = (-n.y, n.x, 0) if |n.x| > |n.z|, else (0, -n.z, n.y); b2 *= rsqrt(
   dot(b2, b2)); b1 = cross(b2, n).  Handedness +1.
   Threshold: |n.x| = |n.z| (the frame jumps there).  No singular unit
   direction: the chosen vector has squared length >= 1/2 - O(eps) for
   unit n.  Note this is Frisvad's listing, which compares x with z only;
   the 1999 paper's "smallest component" variant is not this one.
   Bound (tests/test_lib.c): D <= 12u; the normalization variants add to
   the lengths what naive's do. */
static inline double onb__hughes_moeller_pre(onb_vec3 n, onb_vec3 *b2)
{
	double bx, by, bz;
	if (fabs(n.x) > fabs(n.z)) { bx = -n.y; by = n.x;  bz = 0.0; }
	else                       { bx = 0.0;  by = -n.z; bz = n.y; }
	b2->x = bx; b2->y = by; b2->z = bz;
	return bx * bx + by * by + bz * bz;
}
static inline float onb__hughes_moeller_pref(onb_vec3f n, onb_vec3f *b2)
{
	float bx, by, bz;
	if (fabsf(n.x) > fabsf(n.z)) { bx = -n.y; by = n.x;  bz = 0.0f; }
	else                         { bx = 0.0f; by = -n.z; bz = n.y; }
	b2->x = bx; b2->y = by; b2->z = bz;
	return bx * bx + by * by + bz * bz;
}
static inline void onb__hughes_moeller_post(onb_vec3 n, onb_vec3 v, double s, onb_vec3 *b1, onb_vec3 *b2)
{
	v.x *= s; v.y *= s; v.z *= s;
	*b2 = v;
	b1->x = v.y * n.z - v.z * n.y;
	b1->y = v.z * n.x - v.x * n.z;
	b1->z = v.x * n.y - v.y * n.x;
}
static inline void onb__hughes_moeller_postf(onb_vec3f n, onb_vec3f v, float s, onb_vec3f *b1, onb_vec3f *b2)
{
	v.x *= s; v.y *= s; v.z *= s;
	*b2 = v;
	b1->x = v.y * n.z - v.z * n.y;
	b1->y = v.z * n.x - v.x * n.z;
	b1->z = v.x * n.y - v.y * n.x;
}
static inline void onb__hughes_moeller(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2, int norm)
{
	onb_vec3 v;
	double l2 = onb__hughes_moeller_pre(n, &v);
	onb__hughes_moeller_post(n, v, onb__rsq(l2, norm), b1, b2);
}
static inline void onb__hughes_moellerf(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2, int norm)
{
	onb_vec3f v;
	float l2 = onb__hughes_moeller_pref(n, &v);
	onb__hughes_moeller_postf(n, v, onb__rsqf(l2, norm), b1, b2);
}

static inline void ONB__K(hughes_moeller)           (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__hughes_moeller (n, b1, b2, ONB__NORM_LIBM); }
static inline void ONB__K(hughes_moellerf)          (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__hughes_moellerf(n, b1, b2, ONB__NORM_LIBM); }
static inline void ONB__K(hughes_moeller_invsqrt)   (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__hughes_moeller (n, b1, b2, ONB__NORM_INVSQRT); }
static inline void ONB__K(hughes_moeller_invsqrtf)  (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__hughes_moellerf(n, b1, b2, ONB__NORM_INVSQRT); }
static inline void ONB__K(hughes_moeller_rsqrt)     (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__hughes_moeller (n, b1, b2, ONB__NORM_RSQRT); }
static inline void ONB__K(hughes_moeller_rsqrtf)    (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__hughes_moellerf(n, b1, b2, ONB__NORM_RSQRT); }
static inline void ONB__K(hughes_moeller_rsqrt_nr)  (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__hughes_moeller (n, b1, b2, ONB__NORM_RSQRT_NR); }
static inline void ONB__K(hughes_moeller_rsqrt_nrf) (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__hughes_moellerf(n, b1, b2, ONB__NORM_RSQRT_NR); }
static inline void ONB__K(hughes_moeller_nonorm)    (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__hughes_moeller (n, b1, b2, ONB__NORM_NONE); }
static inline void ONB__K(hughes_moeller_nonormf)   (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__hughes_moellerf(n, b1, b2, ONB__NORM_NONE); }

/* ------------------------------------------------------------------ */
/* frisvad (Frisvad 2012, Listing 2 / Equations 4-6)                   */
/* ------------------------------------------------------------------ */
/* a = 1/(1 + n.z), b = -n.x*n.y*a, b1 = (1 - n.x*n.x*a, b, -n.x),
   b2 = (b, 1 - n.y*n.y*a, -n.y); when n.z < t, the fallback
   b1 = (0, -1, 0), b2 = (-1, 0, 0).  Handedness +1 (fallback included).
   onb_frisvad uses the published t = -0.9999999 (the float literal
   -0.9999999f = -0x1.fffffcp-1 in float; the decimal -0.9999999 rounded
   to double in double, our reading for a listing written only in float).
   Singular: none exactly (the fallback covers n.z = -1), but the formula
   loses all precision as n.z -> -1: its error grows like eps/(1 + n.z),
   and in float it reaches O(1) just above the threshold.  That failure is
   the published behaviour and is kept.
   Bound (tests/test_lib.c): D <= 12u (1 + 2/(1 + n.z)) above t (from
   |b1|^2 - 1 = nx^2 delta/(1 + n.z)^2 with |n|^2 = 1 + delta), and
   sqrt(1 - n.z^2) + 12u for the fallback below t. */
static inline void ONB__K(frisvad_threshold)(onb_vec3 n, double t, onb_vec3 *b1, onb_vec3 *b2)
{
	double a, b;
	if (n.z < t) {
		b1->x = 0.0;  b1->y = -1.0; b1->z = 0.0;
		b2->x = -1.0; b2->y = 0.0;  b2->z = 0.0;
		return;
	}
	a = 1.0 / (1.0 + n.z);
	b = -n.x * n.y * a;
	b1->x = 1.0 - n.x * n.x * a; b1->y = b; b1->z = -n.x;
	b2->x = b; b2->y = 1.0 - n.y * n.y * a; b2->z = -n.y;
}
static inline void ONB__K(frisvad_thresholdf)(onb_vec3f n, float t, onb_vec3f *b1, onb_vec3f *b2)
{
	float a, b;
	if (n.z < t) {
		b1->x = 0.0f;  b1->y = -1.0f; b1->z = 0.0f;
		b2->x = -1.0f; b2->y = 0.0f;  b2->z = 0.0f;
		return;
	}
	a = 1.0f / (1.0f + n.z);
	b = -n.x * n.y * a;
	b1->x = 1.0f - n.x * n.x * a; b1->y = b; b1->z = -n.x;
	b2->x = b; b2->y = 1.0f - n.y * n.y * a; b2->z = -n.y;
}

#define ONB_FRISVAD_T      (-0.9999999)    /* Frisvad 2012, Listing 2 */
#define ONB_FRISVAD_TF     (-0.9999999f)
#define ONB_FRISVAD_MAX_T  (-0.99998796)   /* Max 2017, minimax for float */
#define ONB_FRISVAD_MAX_TF (-0.99998796f)

static inline void ONB__K(frisvad) (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { ONB__K(frisvad_threshold)(n, ONB_FRISVAD_T,  b1, b2); }
static inline void ONB__K(frisvadf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { ONB__K(frisvad_thresholdf)(n, ONB_FRISVAD_TF, b1, b2); }

/* frisvad_max (Nelson Max 2017, JCGT 6(1), "Improved accuracy when
   building an orthonormal basis"): Listing 2 with t = -0.99998796, where the
   formula's error above t and the fallback's error below t balance in
   float (both ~5e-3 at t).  Handedness +1.  The double variant keeps the
   same published t, although the double minimax lies much nearer -1
   (`onbstudy threshold --precision double` finds it). */
static inline void ONB__K(frisvad_max) (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { ONB__K(frisvad_threshold)(n, ONB_FRISVAD_MAX_T,  b1, b2); }
static inline void ONB__K(frisvad_maxf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { ONB__K(frisvad_thresholdf)(n, ONB_FRISVAD_MAX_TF, b1, b2); }

/* Frisvad 2012, Equation 3: the direction (x, y, z) given around the
   z-axis, rotated to the same direction around n, without the basis:
   w = x*(1 - nx^2 a, -nx ny a, -nx) + y*(-nx ny a, 1 - ny^2 a, -ny) + z*n
   with a = 1/(1 + n.z).  Singular case as published: when 1 + n.z == 0
   (n = -z), w = (-y, -x, -z).  No threshold: just above -1 the float
   result has the formula's full O(eps/(1 + n.z)) error. */
static inline onb_vec3 ONB__K(frisvad_rotate)(onb_vec3 n, double x, double y, double z)
{
	onb_vec3 w;
	double s = 1.0 + n.z, a, b;
	if (s <= 0.0 && s >= 0.0) { w.x = -y; w.y = -x; w.z = -z; return w; } /* s == 0, without -Wfloat-equal */
	a = 1.0 / s;
	b = -n.x * n.y * a;
	w.x = x * (1.0 - n.x * n.x * a) + y * b + z * n.x;
	w.y = x * b + y * (1.0 - n.y * n.y * a) + z * n.y;
	w.z = x * -n.x + y * -n.y + z * n.z;
	return w;
}
static inline onb_vec3f ONB__K(frisvad_rotatef)(onb_vec3f n, float x, float y, float z)
{
	onb_vec3f w;
	float s = 1.0f + n.z, a, b;
	if (s <= 0.0f && s >= 0.0f) { w.x = -y; w.y = -x; w.z = -z; return w; } /* s == 0 */
	a = 1.0f / s;
	b = -n.x * n.y * a;
	w.x = x * (1.0f - n.x * n.x * a) + y * b + z * n.x;
	w.y = x * b + y * (1.0f - n.y * n.y * a) + z * n.y;
	w.z = x * -n.x + y * -n.y + z * n.z;
	return w;
}

/* ------------------------------------------------------------------ */
/* duff (Duff et al. 2017, JCGT 6(1), Listing 2, "revisedONB")         */
/* ------------------------------------------------------------------ */
/* Frisvad's formula for n.z >= 0, and its mirror for n.z < 0:
   a = 1/(1 - n.z), b = n.x*n.y*a, b1 = (1 - n.x*n.x*a, -b, n.x),
   b2 = (b, n.y*n.y*a - 1, -n.y).  Handedness +1 in both branches.
   Threshold: the sign of n.z (n.z = -0 takes the n.z >= 0 branch, since
   -0 < 0 is false).  No singular unit direction: 1 +- n.z >= 1.  The
   frame is discontinuous across n.z = 0 (b2 flips sign in y).
   Bound (tests/test_lib.c): D <= 12u on unit-to-rounding n, n = +-z
   included. */
static inline void ONB__K(duff)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	if (n.z < 0.0) {
		const double a = 1.0 / (1.0 - n.z);
		const double b = n.x * n.y * a;
		b1->x = 1.0 - n.x * n.x * a; b1->y = -b; b1->z = n.x;
		b2->x = b; b2->y = n.y * n.y * a - 1.0; b2->z = -n.y;
	} else {
		const double a = 1.0 / (1.0 + n.z);
		const double b = -n.x * n.y * a;
		b1->x = 1.0 - n.x * n.x * a; b1->y = b; b1->z = -n.x;
		b2->x = b; b2->y = 1.0 - n.y * n.y * a; b2->z = -n.y;
	}
}
static inline void ONB__K(dufff)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	if (n.z < 0.0f) {
		const float a = 1.0f / (1.0f - n.z);
		const float b = n.x * n.y * a;
		b1->x = 1.0f - n.x * n.x * a; b1->y = -b; b1->z = n.x;
		b2->x = b; b2->y = n.y * n.y * a - 1.0f; b2->z = -n.y;
	} else {
		const float a = 1.0f / (1.0f + n.z);
		const float b = -n.x * n.y * a;
		b1->x = 1.0f - n.x * n.x * a; b1->y = b; b1->z = -n.x;
		b2->x = b; b2->y = 1.0f - n.y * n.y * a; b2->z = -n.y;
	}
}

/* duff_branchless (Duff et al. 2017, Listing 3; pbrt-v4 CoordinateSystem,
   Mitsuba 3 coordinate_system): sign = copysign(1, n.z),
   a = -1/(sign + n.z), b = n.x*n.y*a,
   b1 = (1 + sign*n.x*n.x*a, sign*b, -sign*n.x), b2 = (b, sign + n.y*n.y*a, -n.y).
   Handedness +1.  Threshold: the sign bit of n.z, so n.z = -0 takes the
   lower branch (unlike `duff`).  No singular unit direction.
   Bound (tests/test_lib.c): D <= 12u, as duff. */
static inline void ONB__K(duff_branchless)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double sign = copysign(1.0, n.z);
	const double a = -1.0 / (sign + n.z);
	const double b = n.x * n.y * a;
	b1->x = 1.0 + sign * n.x * n.x * a; b1->y = sign * b; b1->z = -sign * n.x;
	b2->x = b; b2->y = sign + n.y * n.y * a; b2->z = -n.y;
}
static inline void ONB__K(duff_branchlessf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float sign = copysignf(1.0f, n.z);
	const float a = -1.0f / (sign + n.z);
	const float b = n.x * n.y * a;
	b1->x = 1.0f + sign * n.x * n.x * a; b1->y = sign * b; b1->z = -sign * n.x;
	b2->x = b; b2->y = sign + n.y * n.y * a; b2->z = -n.y;
}

/* ------------------------------------------------------------------ */
/* stark (Stark 2009, JGT 14(1), "Efficient construction of            */
/* perpendicular vectors without branching"), as published             */
/* ------------------------------------------------------------------ */
/* p = cross(n, (xm, ym, zm)) with Stark's branch-free listing:
   uyx = SIGNBIT(|x| - |y|), uzx = SIGNBIT(|x| - |z|), uzy = SIGNBIT(|y| -
   |z|), xm = uyx & uzx, ym = (1^xm) & uzy, zm = 1^(xm & ym).  Since xm and
   ym are never both 1, the published zm is always 1 (Hill 2011, "Perpendicular
   Possibilities", points this out: the intent is 1^(xm | ym), which is
   `stark_fixed`).  So e = (1,0,1) when |x| is smallest, (0,1,1) when |y|
   is, (0,0,1) otherwise.  SIGNBIT of a difference of two absolute values
   is `< 0` (x - x = +0); the uint-to-float conversion of 0 and 1 is a
   select.  Then (our completion, as the issue reads it) b1 = p / |p| with
   1/sqrt, b2 = cross(n, b1).  Handedness +1.  Thresholds: |x| = |y|,
   |x| = |z|, |y| = |z|.  No singular unit direction: |p|^2 >= 2/3 -
   O(eps).  Bound (tests/test_lib.c): D <= 12u. */
static inline double onb__stark_pre(onb_vec3 n, onb_vec3 *p, int fixed)
{
	const double ax = fabs(n.x), ay = fabs(n.y), az = fabs(n.z);
	const int xm = (ax - ay < 0.0) & (ax - az < 0.0);
	const int ym = (ay - az < 0.0) & !xm;
	const int zm = fixed ? !(xm | ym) : !(xm & ym);
	const double ex = xm ? 1.0 : 0.0, ey = ym ? 1.0 : 0.0, ez = zm ? 1.0 : 0.0;
	p->x = n.y * ez - n.z * ey;
	p->y = n.z * ex - n.x * ez;
	p->z = n.x * ey - n.y * ex;
	return p->x * p->x + p->y * p->y + p->z * p->z;
}
static inline float onb__stark_pref(onb_vec3f n, onb_vec3f *p, int fixed)
{
	const float ax = fabsf(n.x), ay = fabsf(n.y), az = fabsf(n.z);
	const int xm = (ax - ay < 0.0f) & (ax - az < 0.0f);
	const int ym = (ay - az < 0.0f) & !xm;
	const int zm = fixed ? !(xm | ym) : !(xm & ym);
	const float ex = xm ? 1.0f : 0.0f, ey = ym ? 1.0f : 0.0f, ez = zm ? 1.0f : 0.0f;
	p->x = n.y * ez - n.z * ey;
	p->y = n.z * ex - n.x * ez;
	p->z = n.x * ey - n.y * ex;
	return p->x * p->x + p->y * p->y + p->z * p->z;
}
static inline void ONB__K(stark)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 p;
	const double s = 1.0 / sqrt(onb__stark_pre(n, &p, 0));
	onb__naive_post(n, p, s, b1, b2);
}
static inline void ONB__K(starkf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f p;
	const float s = 1.0f / sqrtf(onb__stark_pref(n, &p, 0));
	onb__naive_postf(n, p, s, b1, b2);
}

/* stark_fixed: Stark's listing with zm = 1^(xm | ym), the correction of
   Hill 2011 (blog.selfshadow.com/2011/10/17/perp-vectors, after Listing 3),
   so that e_k is the axis of n's smallest |component| as Stark's text
   says.  Otherwise as `stark`.  |p|^2 >= 2/3 - O(eps).  Bound: D <= 12u. */
static inline void ONB__K(stark_fixed)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 p;
	const double s = 1.0 / sqrt(onb__stark_pre(n, &p, 1));
	onb__naive_post(n, p, s, b1, b2);
}
static inline void ONB__K(stark_fixedf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f p;
	const float s = 1.0f / sqrtf(onb__stark_pref(n, &p, 1));
	onb__naive_postf(n, p, s, b1, b2);
}

/* ------------------------------------------------------------------ */
/* pbrt_v3 (pbrt-v3 src/core/geometry.h, CoordinateSystem)             */
/* ------------------------------------------------------------------ */
/* if |v.x| > |v.y|: b1 = (-v.z, 0, v.x) / sqrt(v.x^2 + v.z^2)
   else:            b1 = (0, v.z, -v.y) / sqrt(v.y^2 + v.z^2)
   b2 = cross(v, b1).  pbrt-v3's Vector3 operator/ multiplies by
   inv = (Float)1/f, which we keep.  pbrt-v3's Cross widens both operands
   to double, subtracts the (exact, for float operands) products in double
   and converts the result to the vector's type: the float variant does
   the same (the double variant is pbrt-v3 built with
   PBRT_FLOAT_AS_DOUBLE, where the widening is a no-op).  Handedness +1.
   Threshold: |x| = |y|.
   No singular unit direction (squared length >= 1/2 - O(eps)).
   Bound (tests/test_lib.c): D <= 12u. */
static inline void ONB__K(pbrt_v3)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 u;
	double inv;
	if (fabs(n.x) > fabs(n.y)) {
		inv = 1.0 / sqrt(n.x * n.x + n.z * n.z);
		u.x = -n.z * inv; u.y = 0.0 * inv; u.z = n.x * inv;
	} else {
		inv = 1.0 / sqrt(n.y * n.y + n.z * n.z);
		u.x = 0.0 * inv; u.y = n.z * inv; u.z = -n.y * inv;
	}
	onb__naive_post(n, u, 1.0, b1, b2);
}
static inline void ONB__K(pbrt_v3f)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f u;
	float inv;
	if (fabsf(n.x) > fabsf(n.y)) {
		inv = 1.0f / sqrtf(n.x * n.x + n.z * n.z);
		u.x = -n.z * inv; u.y = 0.0f * inv; u.z = n.x * inv;
	} else {
		inv = 1.0f / sqrtf(n.y * n.y + n.z * n.z);
		u.x = 0.0f * inv; u.y = n.z * inv; u.z = -n.y * inv;
	}
	*b1 = u;
	{	/* pbrt-v3 Cross: operands widened to double (products exact), the
		   difference rounded to double, then converted to float */
		const double vx = ONB__CAST(double, n.x), vy = ONB__CAST(double, n.y), vz = ONB__CAST(double, n.z), wx = ONB__CAST(double, u.x), wy = ONB__CAST(double, u.y), wz = ONB__CAST(double, u.z);
		b2->x = ONB__CAST(float, vy * wz - vz * wy);
		b2->y = ONB__CAST(float, vz * wx - vx * wz);
		b2->z = ONB__CAST(float, vx * wy - vy * wx);
	}
}

/* ------------------------------------------------------------------ */
/* rtow ("Ray Tracing: The Rest of Your Life", onb::build_from_w)      */
/* ------------------------------------------------------------------ */
/* unit_w = w / |w| (the book's operator/ multiplies by 1/t);
   a = (0,1,0) if |unit_w.x| > 0.9 else (1,0,0); v = unit(cross(unit_w, a));
   u = cross(unit_w, v).  Returned in the book's axis order: b1 = u,
   b2 = v, with unit_w (not n) as the implied third axis.  Handedness -1:
   u x v = -w.  The only method here that normalizes its input.
   Threshold: |w.x| = 0.9.  Singular: w = 0 only.
   Bound (tests/test_lib.c): D <= 12u, measured against unit(w). */
static inline void ONB__K(rtow)(onb_vec3 w, onb_vec3 *b1, onb_vec3 *b2)
{
	double inv = 1.0 / sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
	onb_vec3 uw, a, c, v;
	double il;
	uw.x = inv * w.x; uw.y = inv * w.y; uw.z = inv * w.z;
	if (fabs(uw.x) > 0.9) { a.x = 0.0; a.y = 1.0; a.z = 0.0; }
	else                  { a.x = 1.0; a.y = 0.0; a.z = 0.0; }
	c.x = uw.y * a.z - uw.z * a.y;
	c.y = uw.z * a.x - uw.x * a.z;
	c.z = uw.x * a.y - uw.y * a.x;
	il = 1.0 / sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
	v.x = il * c.x; v.y = il * c.y; v.z = il * c.z;
	b1->x = uw.y * v.z - uw.z * v.y;
	b1->y = uw.z * v.x - uw.x * v.z;
	b1->z = uw.x * v.y - uw.y * v.x;
	*b2 = v;
}
static inline void ONB__K(rtowf)(onb_vec3f w, onb_vec3f *b1, onb_vec3f *b2)
{
	float inv = 1.0f / sqrtf(w.x * w.x + w.y * w.y + w.z * w.z);
	onb_vec3f uw, a, c, v;
	float il;
	uw.x = inv * w.x; uw.y = inv * w.y; uw.z = inv * w.z;
	if (fabsf(uw.x) > 0.9f) { a.x = 0.0f; a.y = 1.0f; a.z = 0.0f; }
	else                    { a.x = 1.0f; a.y = 0.0f; a.z = 0.0f; }
	c.x = uw.y * a.z - uw.z * a.y;
	c.y = uw.z * a.x - uw.x * a.z;
	c.z = uw.x * a.y - uw.y * a.x;
	il = 1.0f / sqrtf(c.x * c.x + c.y * c.y + c.z * c.z);
	v.x = il * c.x; v.y = il * c.y; v.z = il * c.z;
	b1->x = uw.y * v.z - uw.z * v.y;
	b1->y = uw.z * v.x - uw.x * v.z;
	b1->z = uw.x * v.y - uw.y * v.x;
	*b2 = v;
}

/* ------------------------------------------------------------------ */
/* tangent_cross_z (blog "Vector transformation using projection       */
/* between orthonormal bases", Python get_onb)                         */
/* ------------------------------------------------------------------ */
/* t = (n.x, n.y, n.z + 1) (our reading of the post's garbled
   `t = [n, n, n + 1]`), binormal = normalize(cross(n, t)) with
   normalize(v) = v / |v| (division, as a Python list comprehension
   would), tangent = cross(n, binormal); returned [tangent, binormal, n],
   so b1 = tangent, b2 = binormal.  Handedness -1.
   Singular: n = +z and n = -z exactly (cross(n, t) = 0, 0/0 = NaN), and
   in float any n with n.x^2 + n.y^2 below the smallest subnormal, where
   the squared length underflows.
   Bound (tests/test_lib.c): D <= 12u away from +-z. */
static inline void ONB__K(tangent_cross_z)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double tx = n.x, ty = n.y, tz = n.z + 1.0;
	double cx = n.y * tz - n.z * ty;
	double cy = n.z * tx - n.x * tz;
	double cz = n.x * ty - n.y * tx;
	const double l = sqrt(cx * cx + cy * cy + cz * cz);
	cx = cx / l; cy = cy / l; cz = cz / l;
	b2->x = cx; b2->y = cy; b2->z = cz;
	b1->x = n.y * cz - n.z * cy;
	b1->y = n.z * cx - n.x * cz;
	b1->z = n.x * cy - n.y * cx;
}
static inline void ONB__K(tangent_cross_zf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float tx = n.x, ty = n.y, tz = n.z + 1.0f;
	float cx = n.y * tz - n.z * ty;
	float cy = n.z * tx - n.x * tz;
	float cz = n.x * ty - n.y * tx;
	const float l = sqrtf(cx * cx + cy * cy + cz * cz);
	cx = cx / l; cy = cy / l; cz = cz / l;
	b2->x = cx; b2->y = cy; b2->z = cz;
	b1->x = n.y * cz - n.z * cy;
	b1->y = n.z * cx - n.x * cz;
	b1->z = n.x * cy - n.y * cx;
}

/* ------------------------------------------------------------------ */
/* This project's own methods (issue 16), not published ones: Duff's   */
/* branchless formula pushed to the accuracy floor, float only         */
/* ------------------------------------------------------------------ */
/* The floor: the exact duff_branchless basis of the float input, rounded
   once to float, still has a defect (the output roundings, plus the
   input's own distance from the unit sphere); `onbstudy sweep` reports it
   per input (README, "The accuracy floor").  Float duff_branchless sits up
   to about 2x above it, because its products and its 1 + s x^2 a round
   before the output does.  These two methods remove those intermediate
   roundings.  Same branch and handedness as duff_branchless (the sign bit
   of n.z; -0 takes the lower branch), same exact formula, so the MPFR
   reference family is duff_branchless.  Float only: for double input the
   analogue needs double-double arithmetic (see the README).
   There is no double version: the registry's basis and batch are NULL
   and its flags carry ONB_FLOAT_ONLY. */

/* duff_wide: the float input widened to double, duff_branchless's formula
   in double, each output rounded once to float.  Each output component
   before its final rounding is within a few 2^-53 of the exact formula,
   so it is the correctly rounded exact value except within a few 2^-53 of
   a float rounding boundary.
   Bound (tests/test_lib.c): D <= 12u (u = 2^-24); measured (onbstudy sweep):
   largest defect within 1.05x of the floor's largest on every distribution. */
static inline void ONB__K(duff_widef)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const double x = ONB__CAST(double, n.x), y = ONB__CAST(double, n.y), z = ONB__CAST(double, n.z);
	const double sign = copysign(1.0, z);
	const double a = -1.0 / (sign + z);
	const double b = x * y * a;
	b1->x = ONB__CAST(float, 1.0 + sign * x * x * a); b1->y = ONB__CAST(float, sign * b); b1->z = ONB__CAST(float, -sign * x);
	b2->x = ONB__CAST(float, b); b2->y = ONB__CAST(float, sign + y * y * a); b2->z = ONB__CAST(float, -y);
}

/* duff_comp: the same formula in float arithmetic, with each rounding
   before the output compensated by error-free transformations: h = s + z
   and its error (Fast2Sum, |s| >= |z|), a = -1/h with the division's exact
   residual fma(a, h, 1), the products x x, x y, y y and their products
   with a split by fma into hi + lo, and 1 + s x^2 a, s + y^2 a by
   Fast2Sum; the lo parts are summed (in float) and added once at the end.
   Each output is then within about u + O(u^2) relative of the exact
   formula (faithful, correctly rounded in most cases).  Seven fmaf()
   calls: built without an FMA target (as libonb.a's scalar code is, see
   the Makefile) they are libm calls; the batch runs an FMA clone when the
   CPU has FMA.  fma is correctly rounded everywhere, so the bits do not
   depend on which.
   Bound (tests/test_lib.c): D <= 12u. */
static inline void ONB__K(duff_compf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float x = n.x, y = n.y, z = n.z;
	const float s = copysignf(1.0f, z);
	const float h = s + z, hl = (s - h) + z;         /* s + z = h + hl          */
	const float a = -1.0f / h;
	const float e = fmaf(a, h, 1.0f);                /* a h + 1, exactly        */
	const float al = a * (e + a * hl);               /* -1/(h + hl) ~ a + al    */
	const float xx = x * x, xxl = fmaf(x, x, -xx);
	const float xy = x * y, xyl = fmaf(x, y, -xy);
	const float yy = y * y, yyl = fmaf(y, y, -yy);
	const float p = xx * a, pl = fmaf(xx, a, -p) + (xx * al + xxl * a); /* x^2 a */
	const float b = xy * a, bl = fmaf(xy, a, -b) + (xy * al + xyl * a); /* x y a */
	const float q = yy * a, ql = fmaf(yy, a, -q) + (yy * al + yyl * a); /* y^2 a */
	const float sp = s * p;
	const float t1 = 1.0f + sp, t1l = (1.0f - t1) + sp; /* 1 + s x^2 a          */
	const float t2 = s + q, t2l = (s - t2) + q;          /* s + y^2 a            */
	const float bb = b + bl;
	b1->x = t1 + (t1l + s * pl); b1->y = s * bb; b1->z = -s * x;
	b2->x = bb; b2->y = t2 + (t2l + ql); b2->z = -y;
}

/* ------------------------------------------------------------------ */
/* Out-of-line library: batch kernels and registry                     */
/* ------------------------------------------------------------------ */

typedef void (*onb_basis_fn) (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2);
typedef void (*onb_basisf_fn)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2);

/* Structure-of-arrays batch: for i < count, (b1[i], b2[i]) = method(n[i]).
   The nine arrays must not overlap.  Bit-identical to the scalar function
   built with the library's flags (see the Makefile).  The loop runs the
   widest clone the CPU supports (onb_batch_isa names it). */
typedef void (*onb_batch_fn)(size_t count,
	const double *nx, const double *ny, const double *nz,
	double *b1x, double *b1y, double *b1z,
	double *b2x, double *b2y, double *b2z);
typedef void (*onb_batchf_fn)(size_t count,
	const float *nx, const float *ny, const float *nz,
	float *b1x, float *b1y, float *b1z,
	float *b2x, float *b2y, float *b2z);

/* onb_method.flags */
#define ONB_HW_RSQRT     0x1u /* uses the hardware rsqrt approximation        */
#define ONB_FELL_BACK    0x2u /* ...which this build lacks: runs 1/sqrt instead */
#define ONB_APPROX_NORM  0x4u /* normalization is approximate or absent        */
#define ONB_NORMALIZES_N 0x8u /* the method normalizes n itself (rtow)        */
#define ONB_FLOAT_ONLY   0x10u /* float only: basis and batch (double) are NULL */

typedef struct onb_method {
	const char   *name;       /* e.g. "duff_branchless"                        */
	const char   *family;     /* the exact formula the MPFR reference follows  */
	const char   *source;     /* one line: publication and listing             */
	const char   *singular;   /* unit directions where it fails, or "none"     */
	const char   *thresholds; /* its branch conditions                         */
	int           handedness; /* det(b1, b2, n): +1, -1, or 0 if it depends on n */
	unsigned      flags;      /* ONB_* above                                   */
	double        threshold;  /* Frisvad-family t, or NAN                      */
	int           norm;       /* normalization variant, for the reference      */
	onb_basis_fn  basis;      /* out-of-line scalar, double (NULL: float only) */
	onb_basisf_fn basisf;     /* out-of-line scalar, float                     */
	onb_batch_fn  batch;      /* SoA batch, double (NULL: float only)          */
	onb_batchf_fn batchf;     /* SoA batch, float                              */
} onb_method;

/* All methods, in a fixed order; *count receives their number. */
const onb_method *onb_methods(size_t *count);
/* The method called `name`, or NULL. */
const onb_method *onb_find(const char *name);
/* The instruction set the batch kernels run on this CPU:
   "avx512f", "avx2" or "sse2" (or "generic" off x86-64). */
const char *onb_batch_isa(void);

/* Status of onb_basis_checked. */
typedef enum {
	ONB_OK = 0,          /* n was unit within ONB_CHECK_TOL, used as given  */
	ONB_RENORMALIZED,    /* n was finite, non-zero, not unit: normalized    */
	ONB_ZERO,            /* n was zero (or too small to normalize)          */
	ONB_NONFINITE,       /* n had a NaN or an infinity                      */
	ONB_BAD_METHOD       /* method was NULL, or has no double (float only) */
} onb_status;

/* Relative tolerance on |n|^2 - 1 under which n is used unchanged. */
#define ONB_CHECK_TOL  1e-12
#define ONB_CHECK_TOLF 1e-6f

/* Checked entry point for renderers: validates n, normalizes it when it is
   not unit (scaling first, so no overflow or underflow), then calls
   method->basis (or basisf).  On ONB_ZERO, ONB_NONFINITE and
   ONB_BAD_METHOD, b1 and b2 are set to (1,0,0) and (0,1,0) and the status
   tells the caller not to trust them.  *n_used (may be NULL) receives the
   normal actually passed to the method. */
onb_status onb_basis_checked (const onb_method *method, onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2, onb_vec3  *n_used);
onb_status onb_basis_checkedf(const onb_method *method, onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2, onb_vec3f *n_used);

/* Out-of-line copies and batch kernels, one set per method.  Declared by
   an X-macro so the list stays in one place; registry.c defines them. */
#define ONB_METHOD_LIST(X) \
	X(naive) X(naive_invsqrt) X(naive_rsqrt) X(naive_rsqrt_nr) X(naive_nonorm) \
	X(hughes_moeller) X(hughes_moeller_invsqrt) X(hughes_moeller_rsqrt) \
	X(hughes_moeller_rsqrt_nr) X(hughes_moeller_nonorm) \
	X(frisvad) X(frisvad_max) X(duff) X(duff_branchless) X(stark) X(stark_fixed) X(pbrt_v3) \
	X(rtow) X(tangent_cross_z)

#define ONB__DECLARE(m) \
	void onb_##m##_outline (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2); \
	void onb_##m##_outlinef(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2); \
	void onb_##m##_batch (size_t count, const double *nx, const double *ny, const double *nz, \
		double *b1x, double *b1y, double *b1z, double *b2x, double *b2y, double *b2z); \
	void onb_##m##_batchf(size_t count, const float *nx, const float *ny, const float *nz, \
		float *b1x, float *b1y, float *b1z, float *b2x, float *b2y, float *b2z);
ONB_METHOD_LIST(ONB__DECLARE)
#undef ONB__DECLARE

/* The float-only methods (ONB_FLOAT_ONLY), after the others in the
   registry: out-of-line copy and batch kernel in float only. */
#define ONB_FLOAT_METHOD_LIST(X) X(duff_wide) X(duff_comp)
#define ONB__DECLARE_F(m) \
	void onb_##m##_outlinef(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2); \
	void onb_##m##_batchf(size_t count, const float *nx, const float *ny, const float *nz, \
		float *b1x, float *b1y, float *b1z, float *b2x, float *b2y, float *b2z);
ONB_FLOAT_METHOD_LIST(ONB__DECLARE_F)
#undef ONB__DECLARE_F

/* Array entry points, for renderers with their own vector types: n points
   to 3 values (x, y, z) read, b1 and b2 to 3 values each written; none of
   them may overlap.  Plain pointers, not n[3] parameters, so that `&v.x`
   of a renderer's struct { float x, y, z; } compiles without GCC's
   -Wstringop-overread/-overflow (docs/library.md shows that case).  Out of
   line in libonb.a, so they keep the studied bits whatever the caller's
   flags: onb_NAME_array[f](n, b1, b2) per method, or by registry entry. */
#define ONB__DECLARE_ARRAY(m) \
	void onb_##m##_array (const double *n, double *b1, double *b2); \
	void onb_##m##_arrayf(const float  *n, float  *b1, float  *b2);
ONB_METHOD_LIST(ONB__DECLARE_ARRAY)
#undef ONB__DECLARE_ARRAY
/* method->basis(f) on arrays (3 values each, as above); a NULL method (or
   function: a float-only method in double) leaves b1, b2 untouched and
   returns ONB_BAD_METHOD, else ONB_OK (no check of n: see
   onb_basis_checked). */
onb_status onb_basis_array (const onb_method *method, const double *n, double *b1, double *b2);
onb_status onb_basis_arrayf(const onb_method *method, const float  *n, float  *b1, float  *b2);
#define ONB__DECLARE_ARRAY_F(m) \
	void onb_##m##_arrayf(const float *n, float *b1, float *b2);
ONB_FLOAT_METHOD_LIST(ONB__DECLARE_ARRAY_F)
#undef ONB__DECLARE_ARRAY_F

/* The tools out of line, for callers whose flags could change their bits. */
void onb_frisvad_threshold_outline (onb_vec3  n, double t, onb_vec3  *b1, onb_vec3  *b2);
void onb_frisvad_threshold_outlinef(onb_vec3f n, float  t, onb_vec3f *b1, onb_vec3f *b2);
onb_vec3  onb_frisvad_rotate_outline (onb_vec3  n, double x, double y, double z);
onb_vec3f onb_frisvad_rotate_outlinef(onb_vec3f n, float  x, float  y, float  z);

/* Out of line (ONB__INLINE 0, see the top): the method names call
   libonb.a's copies, so the caller gets the studied bits. */
#if !ONB__INLINE
#define ONB__WRAP(m) \
	static inline void onb_##m(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2) \
	{ onb_##m##_outline(n, b1, b2); } \
	static inline void onb_##m##f(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) \
	{ onb_##m##_outlinef(n, b1, b2); }
ONB_METHOD_LIST(ONB__WRAP)
#undef ONB__WRAP
#define ONB__WRAP_F(m) \
	static inline void onb_##m##f(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) \
	{ onb_##m##_outlinef(n, b1, b2); }
ONB_FLOAT_METHOD_LIST(ONB__WRAP_F)
#undef ONB__WRAP_F
static inline void onb_frisvad_threshold(onb_vec3 n, double t, onb_vec3 *b1, onb_vec3 *b2)
{ onb_frisvad_threshold_outline(n, t, b1, b2); }
static inline void onb_frisvad_thresholdf(onb_vec3f n, float t, onb_vec3f *b1, onb_vec3f *b2)
{ onb_frisvad_threshold_outlinef(n, t, b1, b2); }
static inline onb_vec3 onb_frisvad_rotate(onb_vec3 n, double x, double y, double z)
{ return onb_frisvad_rotate_outline(n, x, y, z); }
static inline onb_vec3f onb_frisvad_rotatef(onb_vec3f n, float x, float y, float z)
{ return onb_frisvad_rotate_outlinef(n, x, y, z); }
#endif

#ifdef __cplusplus
}
#endif

#if ONB__FP_PRAGMAS == 1
#pragma float_control(pop)
#endif

#endif /* ONB_H */
