/*
 * half.c - every method in binary16 (onb.h, ONB_HAVE_HALF): onb_NAMEh and
 * onb_NAME_arrayh, the kernels of include/libonb/onb.h written once more
 * with each operation rounded to binary16, as a GPU's half arithmetic
 * rounds it.
 *
 * Why the operations are spelled out (hadd, hmul, ...): x86-64 compilers
 * have no binary16 arithmetic without AVX512-FP16, and evaluate a
 * `_Float16` expression in float, rounding once at its end (GCC 12 does so
 * in ISO and GNU modes alike: (1 + 2^-11) + 2^-11 gives 1 + 2^-10, where
 * binary16 gives 1).  So no kernel here writes a bare half expression:
 * each operation is done in float on half operands and converted to
 * binary16 by a cast, which C requires to round (C99 6.3.1.5, 5.2.4.2.2:
 * casts remove any extra range and precision).
 *
 * Why that is the correctly rounded binary16 result: float has 24 >=
 * 2*11 + 2 bits and covers binary16's range (its subnormals, 2^-24, are
 * normal floats), so one +, -, *, / or sqrt of binary16 operands computed
 * in float and rounded to binary16 is the correctly rounded binary16
 * result (double rounding is innocuous: Figueroa 1995).  That argument does
 * not cover fma, whose exact result need not fit in 24 bits; hfma uses the
 * double fma instead: for binary16 a, b, c the product ab is exact (22
 * bits), and r = ab + c is a multiple of 2^min(p, q) with 2^p, 2^q the last
 * bits of ab and c.  Either r fits in 53 bits (fma exact: one rounding) or
 * |r| >= 2^(min(p,q) + 53), which puts r within 2^-31 relative of c (if
 * p < q) or within 2^-42 relative of ab (if q < p) for a finite result:
 * in the first case r is far (2^-12 relative) from every binary16
 * midpoint, in the second |c| >= 2^-24 exceeds half an ulp of double at
 * any |r| < 2^16, so the double rounding cannot land on a midpoint that
 * r is not.  Hence RN16(RN64(ab + c)) = RN16(ab + c).
 * tests/test_half.c checks every kernel against an independent MPFR
 * evaluation at 11 bits with binary16's exponent range and subnormals
 * (the rounding model's CM_EXEC back end, src/model/model.c), bit for bit.
 *
 * Constants: the float kernel's, rounded to binary16 (onb.h's
 * ONB__DECLARE_H comment lists what they become).
 *
 * Conversions: without F16C, GCC converts _Float16 to and from float
 * through libgcc's soft-float routines (__extendhfsf2, __truncsfhf2: a
 * call each, several per operation).  So on x86-64 with GCC this file is
 * compiled twice: as it is (the kernels named onb__NAMEh_soft, HN below),
 * and with -mf16c -DONB__HALF_F16C (build/lib/half_f16c.o: onb__NAMEh_f16c,
 * vcvtph2ps and vcvtps2ph), and each public onb_NAMEh is an ifunc that
 * picks the F16C copy where the CPU has it (onb_half_isa names the one
 * that runs).  Same bits: both conversions are exact (half to float) or
 * round to nearest even under the default MXCSR (float to half, imm8 4),
 * and every operation is the same float operation; tests/test_half.c
 * compares the two copies bit for bit.  Arithmetic stays emulated in
 * float either way: neither copy uses AVX512-FP16's native half
 * instructions.
 */
#define ONB_BUILDING_LIB 1
#include "libonb/onb.h"

/* Two copies and ifuncs (see the top): GCC on x86-64, as batch.c's clones. */
#if ONB_HAVE_HALF && defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(ONB_NO_CLONES) && \
    (!defined(__F16C__) || defined(ONB__HALF_F16C))
#define ONB__HALF_DISPATCH 1
#else
#define ONB__HALF_DISPATCH 0
#endif

#if ONB_HAVE_HALF && (ONB__HALF_DISPATCH || !defined(ONB__HALF_F16C))

/* HN(NAMEh): a kernel's name in this compilation (see the top). */
#if ONB__HALF_DISPATCH && defined(ONB__HALF_F16C)
#define HN(f) onb__##f##_f16c
#elif ONB__HALF_DISPATCH
#define HN(f) onb__##f##_soft
#else
#define HN(f) onb_##f
#endif

typedef onb_half  H;
typedef onb_vec3h V;

/* One rounding each (see the top). */
static inline H hadd(H a, H b) { return (H)((float)a + (float)b); }
static inline H hsub(H a, H b) { return (H)((float)a - (float)b); }
static inline H hmul(H a, H b) { return (H)((float)a * (float)b); }
static inline H hdiv(H a, H b) { return (H)((float)a / (float)b); }
static inline H hsqrt(H a)     { return (H)sqrtf((float)a); }
static inline H hfma(H a, H b, H c) { return (H)fma((double)a, (double)b, (double)c); }
static inline H hneg(H a)      { return (H)(-(float)a); }        /* exact */
static inline H habs(H a)      { return (H)fabsf((float)a); }    /* exact */
static inline H hcst(double v) { return (H)v; }
/* the binary16 constants of the kernels */
#define H0 ((H)0.0)
#define H1 ((H)1.0)

/* x*x + y*y + z*z and the cross product, left to right as onb.h writes them */
static inline H hdot(V p, V q) { return hadd(hadd(hmul(p.x, q.x), hmul(p.y, q.y)), hmul(p.z, q.z)); }
static inline V hcross(V p, V q)
{
	V r;
	r.x = hsub(hmul(p.y, q.z), hmul(p.z, q.y));
	r.y = hsub(hmul(p.z, q.x), hmul(p.x, q.z));
	r.z = hsub(hmul(p.x, q.y), hmul(p.y, q.x));
	return r;
}
static inline V hscale(V p, H s) { p.x = hmul(p.x, s); p.y = hmul(p.y, s); p.z = hmul(p.z, s); return p; }
static inline V hvec(H x, H y, H z) { V r; r.x = x; r.y = y; r.z = z; return r; }

/* ---- normalizations (onb__rsqf) ---- */
/* Listing 3's Newton step y (1.5 - 0.5 x y y): h = 0.5 x, (h y) y. */
static inline H hnewton(H x, H y)
{
	const H h = hmul(hcst(0.5), x);
	return hmul(y, hsub(hcst(1.5), hmul(hmul(h, y), y)));
}
/* The seed of Listing 3's InvSqrt (0x5f3759df) on x widened to float,
   rounded to binary16. */
static inline H hinvsqrt_seed(H x)
{
	float f = (float)x;
	uint32_t i;
	memcpy(&i, &f, sizeof i);
	i = 0x5f3759dfu - (i >> 1);
	memcpy(&f, &i, sizeof f);
	return (H)f;
}
static inline H hrsq(H x, int norm)
{
	switch (norm) {
	case ONB__NORM_INVSQRT:  return hnewton(x, hinvsqrt_seed(x));
	case ONB__NORM_RSQRT:    return (H)onb__hw_rsqrtf((float)x);
	case ONB__NORM_RSQRT_NR: return hnewton(x, (H)onb__hw_rsqrtf((float)x));
	case ONB__NORM_NONE:     return H1;
	default:                 return (H)(1.0 / sqrt((double)x));
	}
}

/* onb__naive_post: u *= s, b1 = u, b2 = cross(n, u) */
static inline void hpost(V n, V u, H s, V *b1, V *b2)
{
	u = hscale(u, s);
	*b1 = u;
	*b2 = hcross(n, u);
}

/* ---- naive ---- */
static void naiveh(V n, V *b1, V *b2, int norm)
{
	V b;
	H d;
	if (n.x > hcst(0.9)) b = hvec(H0, H1, H0);
	else                 b = hvec(H1, H0, H0);
	d = hdot(b, n);
	b.x = hsub(b.x, hmul(n.x, d));
	b.y = hsub(b.y, hmul(n.y, d));
	b.z = hsub(b.z, hmul(n.z, d));
	hpost(n, b, hrsq(hdot(b, b), norm), b1, b2);
}
void HN(naiveh)(V n, V *b1, V *b2)           { naiveh(n, b1, b2, ONB__NORM_LIBM); }
void HN(naive_invsqrth)(V n, V *b1, V *b2)   { naiveh(n, b1, b2, ONB__NORM_INVSQRT); }
void HN(naive_rsqrth)(V n, V *b1, V *b2)     { naiveh(n, b1, b2, ONB__NORM_RSQRT); }
void HN(naive_rsqrt_nrh)(V n, V *b1, V *b2)  { naiveh(n, b1, b2, ONB__NORM_RSQRT_NR); }
void HN(naive_nonormh)(V n, V *b1, V *b2)    { naiveh(n, b1, b2, ONB__NORM_NONE); }

/* ---- hughes_moeller ---- */
static void hughes_moellerh(V n, V *b1, V *b2, int norm)
{
	V v;
	H s;
	if (habs(n.x) > habs(n.z)) v = hvec(hneg(n.y), n.x, H0);
	else                       v = hvec(H0, hneg(n.z), n.y);
	s = hrsq(hdot(v, v), norm);
	v = hscale(v, s);
	*b2 = v;
	*b1 = hcross(v, n);
}
void HN(hughes_moellerh)(V n, V *b1, V *b2)           { hughes_moellerh(n, b1, b2, ONB__NORM_LIBM); }
void HN(hughes_moeller_invsqrth)(V n, V *b1, V *b2)   { hughes_moellerh(n, b1, b2, ONB__NORM_INVSQRT); }
void HN(hughes_moeller_rsqrth)(V n, V *b1, V *b2)     { hughes_moellerh(n, b1, b2, ONB__NORM_RSQRT); }
void HN(hughes_moeller_rsqrt_nrh)(V n, V *b1, V *b2)  { hughes_moellerh(n, b1, b2, ONB__NORM_RSQRT_NR); }
void HN(hughes_moeller_nonormh)(V n, V *b1, V *b2)    { hughes_moellerh(n, b1, b2, ONB__NORM_NONE); }

/* ---- frisvad, frisvad_max, q2rtx: Listing 2 with threshold t ---- */
void HN(frisvad_thresholdh)(V n, H t, V *b1, V *b2)
{
	H a, b;
	if (n.z < t) {
		*b1 = hvec(H0, hneg(H1), H0);
		*b2 = hvec(hneg(H1), H0, H0);
		return;
	}
	a = hdiv(H1, hadd(H1, n.z));
	b = hmul(hmul(hneg(n.x), n.y), a);
	*b1 = hvec(hsub(H1, hmul(hmul(n.x, n.x), a)), b, hneg(n.x));
	*b2 = hvec(b, hsub(H1, hmul(hmul(n.y, n.y), a)), hneg(n.y));
}
void HN(frisvadh)(V n, V *b1, V *b2)     { HN(frisvad_thresholdh)(n, (H)ONB_FRISVAD_TF, b1, b2); }
void HN(frisvad_maxh)(V n, V *b1, V *b2) { HN(frisvad_thresholdh)(n, (H)ONB_FRISVAD_MAX_TF, b1, b2); }
void HN(q2rtxh)(V n, V *b1, V *b2)       { HN(frisvad_thresholdh)(n, (H)ONB_Q2RTX_TF, b1, b2); }

/* Frisvad 2012, Equation 3 (onb_frisvad_rotatef) */
V HN(frisvad_rotateh)(V n, H x, H y, H z)
{
	const H s = hadd(H1, n.z);
	H a, b;
	if (s <= H0 && s >= H0)
		return hvec(hneg(y), hneg(x), hneg(z));
	a = hdiv(H1, s);
	b = hmul(hmul(hneg(n.x), n.y), a);
	return hvec(hadd(hadd(hmul(x, hsub(H1, hmul(hmul(n.x, n.x), a))), hmul(y, b)), hmul(z, n.x)),
	            hadd(hadd(hmul(x, b), hmul(y, hsub(H1, hmul(hmul(n.y, n.y), a)))), hmul(z, n.y)),
	            hadd(hadd(hmul(x, hneg(n.x)), hmul(y, hneg(n.y))), hmul(z, n.z)));
}

/* ---- duff, duff_branchless, mitsuba3 ---- */
/* Duff et al.'s lower branch's a and b (n.z < 0), and its upper branch
   whole (Frisvad's formula); q2rtx_fixed shares both.  Macros: the
   compiled kernels stay the same bytes (CODE_KEY("half"): certify
   --precision half's keys). */
#define H_DUFF_LOWER_AB                                                        \
	const H a = hdiv(H1, hsub(H1, n.z));                                       \
	const H b = hmul(hmul(n.x, n.y), a)
#define H_DUFF_UPPER                                                           \
	{                                                                          \
		const H a = hdiv(H1, hadd(H1, n.z));                                   \
		const H b = hmul(hmul(hneg(n.x), n.y), a);                             \
		*b1 = hvec(hsub(H1, hmul(hmul(n.x, n.x), a)), b, hneg(n.x));           \
		*b2 = hvec(b, hsub(H1, hmul(hmul(n.y, n.y), a)), hneg(n.y));           \
	}
void HN(duffh)(V n, V *b1, V *b2)
{
	if (n.z < H0) {
		H_DUFF_LOWER_AB;
		*b1 = hvec(hsub(H1, hmul(hmul(n.x, n.x), a)), hneg(b), n.x);
		*b2 = hvec(b, hsub(hmul(hmul(n.y, n.y), a), H1), hneg(n.y));
	} else
		H_DUFF_UPPER
}
static inline H hsign(H z) { return (H)copysignf(1.0f, (float)z); }
void HN(duff_branchlessh)(V n, V *b1, V *b2)
{
	const H sign = hsign(n.z);
	const H a = hdiv(hneg(H1), hadd(sign, n.z));
	const H b = hmul(hmul(n.x, n.y), a);
	*b1 = hvec(hadd(H1, hmul(hmul(hmul(sign, n.x), n.x), a)), hmul(sign, b), hmul(hneg(sign), n.x));
	*b2 = hvec(b, hadd(sign, hmul(hmul(n.y, n.y), a)), hneg(n.y));
}
void HN(mitsuba3h)(V n, V *b1, V *b2)
{
	const H sign = hsign(n.z);
	const H a = hneg(hdiv(H1, hadd(sign, n.z)));
	const H b = hmul(hmul(n.x, n.y), a);
	*b1 = hvec(hadd(hmul(sign, hmul(hmul(n.x, n.x), a)), H1), hmul(sign, b), hmul(hneg(sign), n.x));
	*b2 = hvec(b, hadd(hmul(n.y, hmul(n.y, a)), sign), hneg(n.y));
}

/* ---- stark, stark_fixed ---- */
static void starkh(V n, V *b1, V *b2, int fixed)
{
	const H ax = habs(n.x), ay = habs(n.y), az = habs(n.z);
	const int xm = (hsub(ax, ay) < H0) & (hsub(ax, az) < H0);
	const int ym = (hsub(ay, az) < H0) & !xm;
	const int zm = fixed ? !(xm | ym) : !(xm & ym);
	const V e = hvec(xm ? H1 : H0, ym ? H1 : H0, zm ? H1 : H0);
	const V p = hcross(n, e);
	hpost(n, p, hdiv(H1, hsqrt(hdot(p, p))), b1, b2);
}
void HN(starkh)(V n, V *b1, V *b2)       { starkh(n, b1, b2, 0); }
void HN(stark_fixedh)(V n, V *b1, V *b2) { starkh(n, b1, b2, 1); }

/* ---- pbrt_v3: Cross widened to double, each component rounded once ---- */
void HN(pbrt_v3h)(V n, V *b1, V *b2)
{
	V u;
	H inv;
	double vx, vy, vz, wx, wy, wz;
	if (habs(n.x) > habs(n.y)) {
		inv = hdiv(H1, hsqrt(hadd(hmul(n.x, n.x), hmul(n.z, n.z))));
		u = hvec(hmul(hneg(n.z), inv), hmul(H0, inv), hmul(n.x, inv));
	} else {
		inv = hdiv(H1, hsqrt(hadd(hmul(n.y, n.y), hmul(n.z, n.z))));
		u = hvec(hmul(H0, inv), hmul(n.z, inv), hmul(hneg(n.y), inv));
	}
	*b1 = u;
	vx = (double)n.x; vy = (double)n.y; vz = (double)n.z;
	wx = (double)u.x; wy = (double)u.y; wz = (double)u.z;
	b2->x = (H)(vy * wz - vz * wy);
	b2->y = (H)(vz * wx - vx * wz);
	b2->z = (H)(vx * wy - vy * wx);
}

/* ---- rtow ---- */
void HN(rtowh)(V w, V *b1, V *b2)
{
	const H inv = hdiv(H1, hsqrt(hdot(w, w)));
	const V uw = hvec(hmul(inv, w.x), hmul(inv, w.y), hmul(inv, w.z));
	const V a = habs(uw.x) > hcst(0.9) ? hvec(H0, H1, H0) : hvec(H1, H0, H0);
	const V c = hcross(uw, a);
	const H il = hdiv(H1, hsqrt(hdot(c, c)));
	const V v = hvec(hmul(il, c.x), hmul(il, c.y), hmul(il, c.z));
	*b1 = hcross(uw, v);
	*b2 = v;
}

/* ---- tangent_cross_z ---- */
void HN(tangent_cross_zh)(V n, V *b1, V *b2)
{
	const V t = hvec(n.x, n.y, hadd(n.z, H1));
	V c = hcross(n, t);
	const H l = hsqrt(hdot(c, c));
	c = hvec(hdiv(c.x, l), hdiv(c.y, l), hdiv(c.z, l));
	*b2 = c;
	*b1 = hcross(n, c);
}

/* ---- filament, filament_fixed (y-up) ---- */
void HN(filamenth)(V n, V *b1, V *b2)
{
	H va, vb;
	if (n.y < (H)ONB_FILAMENT_TF) {
		*b1 = hvec(hneg(H1), H0, H0);
		*b2 = hvec(H0, H0, hneg(H1));
		return;
	}
	va = hdiv(H1, hadd(H1, n.y));
	vb = hmul(hmul(hneg(n.z), n.x), va);
	*b1 = hvec(vb, hneg(n.z), hsub(H1, hmul(hmul(n.z, n.z), va)));
	*b2 = hvec(hsub(H1, hmul(hmul(n.x, n.x), va)), hneg(n.x), vb);
}
/* filament_hm: FLT_EPSILON (2^-23) is a binary16 subnormal, exact */
void HN(filament_hmh)(V n, V *b1, V *b2)
{
	V t;
	if (habs(n.x) > hadd(habs(n.z), (H)ONB_FILAMENT_HM_EPS)) t = hvec(hneg(n.y), n.x, H0);
	else                                                      t = hvec(H0, hneg(n.z), n.y);
	t = hscale(t, hdiv(H1, hsqrt(hdot(t, t))));
	*b1 = t;
	*b2 = hcross(n, t);
}
/* ---- capsaicin, capsaicin_fixed ---- */
static void capsaicinh(V n, int sel, V *b1, V *b2)
{
	V b;
	if (sel) {
		const H k = hdiv(H1, hsqrt(hadd(hmul(n.z, n.z), hmul(n.y, n.y))));
		b = hvec(H0, hmul(hneg(n.z), k), hmul(n.y, k));
	} else {
		const H k = hdiv(H1, hsqrt(hadd(hmul(n.x, n.x), hmul(n.y, n.y))));
		b = hvec(hmul(n.y, k), hmul(hneg(n.x), k), H0);
	}
	*b1 = b;
	*b2 = hcross(n, b);
}
void HN(capsaicinh)(V n, V *b1, V *b2) { capsaicinh(n, habs(n.z) > H0, b1, b2); }
void HN(capsaicin_fixedh)(V n, V *b1, V *b2) { capsaicinh(n, habs(n.z) > habs(n.x), b1, b2); }
/* ---- unity (GetLocalFrame): FastSign(z) = z >= 0 ? 1 : -1 ---- */
void HN(unityh)(V n, V *b1, V *b2)
{
	const H sz = n.z >= H0 ? H1 : hneg(H1);
	const H a = hdiv(H1, hadd(sz, n.z));
	const H ya = hmul(n.y, a), b = hmul(n.x, ya), c = hmul(n.x, sz);
	*b1 = hvec(hsub(hmul(hmul(c, n.x), a), H1), hmul(sz, b), c);
	*b2 = hvec(b, hsub(hmul(n.y, ya), sz), n.y);
}
/* ---- shader sources: normalize(v) = v / sqrt(dot(v, v)) ---- */
static V hnormalize_div(V v)
{
	const H l = hsqrt(hdot(v, v));
	return hvec(hdiv(v.x, l), hdiv(v.y, l), hdiv(v.z, l));
}
/* willems: up = z when |n.z| < 0.999, else x */
void HN(willemsh)(V n, V *b1, V *b2)
{
	const V up = habs(n.z) < hcst(0.999) ? hvec(H0, H0, H1) : hvec(H1, H0, H0);
	*b1 = hnormalize_div(hcross(up, n));
	*b2 = hnormalize_div(hcross(n, *b1));
}
/* gltf_viewer: up = y, or +-z when 1 - |n.y| <= 1e-7 */
void HN(gltf_viewerh)(V n, V *b1, V *b2)
{
	const H d = hadd(hadd(hmul(n.x, H0), hmul(n.y, H1)), hmul(n.z, H0));
	V up = hvec(H0, H1, H0);
	if (hsub(H1, habs(d)) <= hcst(0.0000001))
		up = hvec(H0, H0, d > H0 ? H1 : hneg(H1));
	*b1 = hnormalize_div(hcross(up, n));
	*b2 = hcross(n, *b1);
}
/* rtao, rtao_fixed: right = 0.3 n + c, b2 = normalize(n x right), b1 = b2 x n */
static void rtaoh(V n, V *b1, V *b2, int fixed)
{
	V c = hvec(hcst(-0.72), hcst(0.56), hcst(-0.34)), r;
	if (fixed && habs(hdot(n, c)) > hcst(0.875))
		c = hvec(hcst(0.56), hcst(0.72), H0);
	r = hvec(hadd(hmul(hcst(0.3), n.x), c.x), hadd(hmul(hcst(0.3), n.y), c.y), hadd(hmul(hcst(0.3), n.z), c.z));
	*b2 = hnormalize_div(hcross(n, r));
	*b1 = hcross(*b2, n);
}
void HN(rtaoh)(V n, V *b1, V *b2)       { rtaoh(n, b1, b2, 0); }
void HN(rtao_fixedh)(V n, V *b1, V *b2) { rtaoh(n, b1, b2, 1); }
void HN(filament_fixedh)(V n, V *b1, V *b2)
{
	H a, b;
	if (n.y < H0) {
		a = hdiv(H1, hsub(H1, n.y));
		b = hmul(hmul(n.z, n.x), a);
		*b1 = hvec(hsub(hmul(hmul(n.x, n.x), a), H1), hneg(n.x), b);
		*b2 = hvec(b, hneg(n.z), hneg(hsub(H1, hmul(hmul(n.z, n.z), a))));
		return;
	}
	a = hdiv(H1, hadd(H1, n.y));
	b = hmul(hmul(hneg(n.z), n.x), a);
	*b1 = hvec(b, hneg(n.z), hsub(H1, hmul(hmul(n.z, n.z), a)));
	*b2 = hvec(hsub(H1, hmul(hmul(n.x, n.x), a)), hneg(n.x), b);
}

/* ---- cycles_cross111, cycles_cross111_avx2 ---- */
static V cycles111_b1h(V n)
{
	V a;
	H l;
	if (!(n.x <= n.y && n.x >= n.y && n.x <= n.z && n.x >= n.z))
		a = hvec(hsub(n.z, n.y), hsub(n.x, n.z), hsub(n.y, n.x));
	else
		a = hvec(hsub(n.z, n.y), hadd(n.x, n.z), hsub(hneg(n.y), n.x));
	l = hsqrt(hdot(a, a));
	return hvec(hdiv(a.x, l), hdiv(a.y, l), hdiv(a.z, l));
}
void HN(cycles_cross111h)(V n, V *b1, V *b2) { hpost(n, cycles111_b1h(n), H1, b1, b2); }
void HN(cycles_cross111_avx2h)(V n, V *b1, V *b2)
{
	const V a = cycles111_b1h(n);
	*b1 = a;
	*b2 = hvec(hfma(n.y, a.z, hneg(hmul(n.z, a.y))),
	           hfma(n.z, a.x, hneg(hmul(n.x, a.z))),
	           hfma(n.x, a.y, hneg(hmul(n.y, a.x))));
}

/* ---- embree: rsqrtss on the widened argument, rounded, Newton in half ---- */
static inline H hembree_rsqrt(H x)
{
	const H r = (H)onb__hw_rsqrtf((float)x);
	return hadd(hmul(hcst(1.5), r), hmul(hmul(hmul(x, hcst(-0.5)), r), hmul(r, r)));
}
void HN(embreeh)(V n, V *b1, V *b2)
{
	const H zz = hmul(n.z, n.z), d0 = hadd(zz, hmul(n.y, n.y)), d1 = hadd(zz, hmul(n.x, n.x));
	V u, c;
	H s;
	if (d0 > d1) { u = hvec(H0, n.z, hneg(n.y)); s = hembree_rsqrt(d0); }
	else         { u = hvec(hneg(n.z), H0, n.x); s = hembree_rsqrt(d1); }
	u = hscale(u, s);
	c = hcross(n, u);
	s = hembree_rsqrt(hdot(c, c));
	*b1 = u;
	*b2 = hscale(c, s);
}

/* ---- luxcore: the 1e-5 comparison in double, as the float kernel's ---- */
void HN(luxcoreh)(V n, V *b1, V *b2)
{
	const H len = hsqrt(hadd(hmul(n.x, n.x), hmul(n.y, n.y)));
	V v;
	if ((double)len < 1e-5) v = hvec(H1, H0, H0);
	else                    v = hvec(hdiv(hneg(n.y), len), hdiv(n.x, len), H0);
	hpost(n, v, H1, b2, b1);
}
void HN(luxcore_fixedh)(V n, V *b1, V *b2)
{
	const H len = hsqrt(hadd(hmul(n.x, n.x), hmul(n.y, n.y)));
	V v;
	if ((double)len < 1e-5) {
		v = hvec(hsub(H1, hmul(n.x, n.x)), hmul(hneg(n.x), n.y), hmul(hneg(n.x), n.z));
		v = hscale(v, hdiv(H1, hsqrt(hdot(v, v))));
	} else
		v = hvec(hdiv(hneg(n.y), len), hdiv(n.x, len), H0);
	hpost(n, v, H1, b2, b1);
}

/* ---- jolt, jolt_fma ---- */
static V jolt_perph(V n)
{
	const H xx = hmul(n.x, n.x), yy = hmul(n.y, n.y), zz = hmul(n.z, n.z);
	if (xx > yy) {
		const H len = hsqrt(hadd(xx, zz));
		return hvec(hdiv(n.z, len), hdiv(H0, len), hdiv(hsub(H0, n.x), len));
	} else {
		const H len = hsqrt(hadd(yy, zz));
		return hvec(hdiv(H0, len), hdiv(n.z, len), hdiv(hsub(H0, n.y), len));
	}
}
void HN(jolth)(V n, V *b1, V *b2)
{
	const V p = jolt_perph(n);
	*b1 = p;
	*b2 = hcross(n, p);
}
void HN(jolt_fmah)(V n, V *b1, V *b2)
{
	const V p = jolt_perph(n);
	*b1 = p;
	*b2 = hvec(hfma(p.z, n.y, hneg(hmul(n.z, p.y))),
	           hfma(p.x, n.z, hneg(hmul(n.x, p.z))),
	           hfma(p.y, n.x, hneg(hmul(n.y, p.x))));
}

/* ---- osl_ortho: Imath normalize (lengthTiny below 2 * the smallest normal) ---- */
static H osl_lenh(H x, H y, H z)
{
	const H l2 = hadd(hadd(hmul(x, x), hmul(y, y)), hmul(z, z));
	H ax, ay, az, m;
	if (!((float)l2 < 2.0f * 0x1p-14f))
		return hsqrt(l2);
	ax = ((float)x >= 0.0f) ? x : hneg(x); ay = ((float)y >= 0.0f) ? y : hneg(y); az = ((float)z >= 0.0f) ? z : hneg(z);
	m = ax;
	if ((float)m < (float)ay) m = ay;
	if ((float)m < (float)az) m = az;
	if ((float)m == 0.0f)
		return H0;
	ax = hdiv(ax, m); ay = hdiv(ay, m); az = hdiv(az, m);
	return hmul(m, hsqrt(hadd(hadd(hmul(ax, ax), hmul(ay, ay)), hmul(az, az))));
}
void HN(osl_orthoh)(V n, V *b1, V *b2)
{
	V p;
	H l;
	if ((float)habs(n.x) > (float)hcst((double).01f)) p = hvec(n.z, H0, hneg(n.x));
	else                                              p = hvec(H0, hneg(n.z), n.y);
	l = osl_lenh(p.x, p.y, p.z);
	if ((float)l != 0.0f) p = hvec(hdiv(p.x, l), hdiv(p.y, l), hdiv(p.z, l));
	*b1 = p;
	*b2 = hcross(n, p);
}

/* ---- ospray: |x| < |y| picks (0, z, -y), 1/sqrt of the three-term dot, cross in the format ---- */
void HN(osprayh)(V n, V *b1, V *b2)
{
	V u;
	if ((float)habs(n.x) < (float)habs(n.y)) u = hvec(H0, n.z, hneg(n.y));
	else                                     u = hvec(hneg(n.z), H0, n.x);
	u = hscale(u, hdiv(H1, hsqrt(hdot(u, u))));
	*b1 = u;
	*b2 = hcross(n, u);
}

/* ---- osl_gabornoise: n Imath-normalized, |v.x| < 0.9f, a Imath-normalized, b = v x a ---- */
void HN(osl_gabornoiseh)(V n, V *b1, V *b2)
{
	V v = n, a;
	H l = osl_lenh(v.x, v.y, v.z);
	if ((float)l != 0.0f) v = hvec(hdiv(v.x, l), hdiv(v.y, l), hdiv(v.z, l));
	if ((float)habs(v.x) < (float)hcst((double).9f)) a = hvec(H0, v.z, hneg(v.y));
	else                                            a = hvec(hneg(v.z), H0, v.x);
	l = osl_lenh(a.x, a.y, a.z);
	if ((float)l != 0.0f) a = hvec(hdiv(a.x, l), hdiv(a.y, l), hdiv(a.z, l));
	*b1 = a;
	*b2 = hcross(v, a);
}

/* ---- cauldron2: up = z when |n.z| < 0.99999f (1 in binary16), else x; b2 not normalized ---- */
void HN(cauldron2h)(V n, V *b1, V *b2)
{
	const V up = habs(n.z) < hcst((double)0.99999f) ? hvec(H0, H0, H1) : hvec(H1, H0, H0);
	*b1 = hnormalize_div(hcross(up, n));
	*b2 = hcross(n, *b1);
}

/* ---- threejs: cauldron2's with 0.999f ---- */
void HN(threejsh)(V n, V *b1, V *b2)
{
	const V up = habs(n.z) < hcst((double)0.999f) ? hvec(H0, H0, H1) : hvec(H1, H0, H0);
	*b1 = hnormalize_div(hcross(up, n));
	*b2 = hcross(n, *b1);
}

/* ---- q2rtx_fixed: Frisvad above, Duff's lower branch turned a quarter below ---- */
void HN(q2rtx_fixedh)(V n, V *b1, V *b2)
{
	if (n.z < H0) {
		H_DUFF_LOWER_AB;
		*b1 = hvec(b, hsub(hmul(hmul(n.y, n.y), a), H1), hneg(n.y));
		*b2 = hvec(hneg(hsub(H1, hmul(hmul(n.x, n.x), a))), b, hneg(n.x));
	} else
		H_DUFF_UPPER
}

/* ---- jolt_arm64: the non-SSE perpendicular (-x, std::max) ---- */
void HN(jolt_arm64h)(V n, V *b1, V *b2)
{
	const H xx = hmul(n.x, n.x), yy = hmul(n.y, n.y), zz = hmul(n.z, n.z);
	const H len = hsqrt(hadd(xx < yy ? yy : xx, zz));
	V p;
	if (xx > yy) p = hvec(hdiv(n.z, len), hdiv(H0, len), hdiv(hneg(n.x), len));
	else         p = hvec(hdiv(H0, len), hdiv(n.z, len), hdiv(hneg(n.y), len));
	*b1 = p;
	*b2 = hcross(n, p);
}

/* ---- nori: c = perpendicular * (1/len), b1 = c x n, b2 = c ---- */
void HN(norih)(V a, V *b, V *c)
{
	V t;
	if (habs(a.x) > habs(a.y)) {
		const H inv = hdiv(H1, hsqrt(hadd(hmul(a.x, a.x), hmul(a.z, a.z))));
		t = hvec(hmul(a.z, inv), H0, hmul(hneg(a.x), inv));
	} else {
		const H inv = hdiv(H1, hsqrt(hadd(hmul(a.y, a.y), hmul(a.z, a.z))));
		t = hvec(H0, hmul(a.z, inv), hmul(hneg(a.y), inv));
	}
	*c = t;
	*b = hcross(t, a);
}

/* ---- bullet ---- */
void HN(bulleth)(V n, V *b1, V *b2)
{
	if (habs(n.z) > hcst(0x1.6a09e667f3bcdp-1) /* SIMDSQRT12 in binary16 */) {
		const H a = hadd(hmul(n.y, n.y), hmul(n.z, n.z)), k = hdiv(H1, hsqrt(a));
		*b1 = hvec(H0, hmul(hneg(n.z), k), hmul(n.y, k));
		*b2 = hvec(hmul(a, k), hmul(hneg(n.x), b1->z), hmul(n.x, b1->y));
	} else {
		const H a = hadd(hmul(n.x, n.x), hmul(n.y, n.y)), k = hdiv(H1, hsqrt(a));
		*b1 = hvec(hmul(hneg(n.y), k), hmul(n.x, k), H0);
		*b2 = hvec(hmul(hneg(n.z), b1->y), hmul(n.z, b1->x), hmul(a, k));
	}
}

/* ---- mujoco: 1e-15 is 0 in binary16 ---- */
static V mj_normalizeh(V v)
{
	const H s = hsqrt(hdot(v, v));
	if (s < hcst(1e-15))
		return hvec(H1, H0, H0);
	return hscale(v, hdiv(H1, s));
}
void HN(mujocoh)(V n, V *b1, V *b2)
{
	const V m = mj_normalizeh(n);
	V e = hvec(H0, H0, H0);
	H d;
	if (m.y < hcst(0.5) && m.y > hcst(-0.5)) e.y = H1; else e.z = H1;
	d = hdot(m, e);
	e.x = hsub(e.x, hmul(m.x, d)); e.y = hsub(e.y, hmul(m.y, d)); e.z = hsub(e.z, hmul(m.z, d));
	e = mj_normalizeh(e);
	*b1 = e;
	*b2 = hcross(m, e);
}

/* ---- eigen: NumTraits<Eigen::half>::dummy_precision() = half(1e-2f) ---- */
void HN(eigenh)(V n, V *b1, V *b2)
{
	const H zp = hmul(habs(n.z), (H)1e-2f);
	V p;
	if (!(habs(n.x) <= zp) || !(habs(n.y) <= zp)) {
		const H r = hdiv(H1, hsqrt(hadd(hmul(n.x, n.x), hmul(n.y, n.y))));
		p = hvec(hmul(hneg(n.y), r), hmul(n.x, r), H0);
	} else {
		const H r = hdiv(H1, hsqrt(hadd(hmul(n.y, n.y), hmul(n.z, n.z))));
		p = hvec(H0, hmul(hneg(n.z), r), hmul(n.y, r));
	}
	*b1 = p;
	*b2 = hcross(n, p);
}

/* ---- physx, physx_fixed: 0.9999f is 1 in binary16 ---- */
static V physx_normh(V v)
{
	const H m = hsqrt(hdot(v, v));
	return m > H0 ? hscale(v, hdiv(H1, m)) : v;
}
void HN(physxh)(V n, V *b1, V *b2)
{
	V r, u;
	if (habs(n.y) <= (H)0.9999f) {
		r = physx_normh(hvec(n.z, H0, hneg(n.x)));
		u = hvec(hmul(n.y, r.z), hsub(hmul(n.z, r.x), hmul(n.x, r.z)), hmul(hneg(n.y), r.x));
	} else {
		r = hvec(H1, H0, H0);
		u = physx_normh(hvec(H0, n.z, hneg(n.y)));
	}
	*b1 = r;
	*b2 = u;
}
void HN(physx_fixedh)(V n, V *b1, V *b2)
{
	V u;
	if (habs(n.y) <= (H)0.9999f) {
		HN(physxh)(n, b1, b2);
		return;
	}
	u = physx_normh(hvec(H0, n.z, hneg(n.y)));
	*b1 = hcross(u, n);
	*b2 = u;
}

/* ---- rp3d ---- */
void HN(rp3dh)(V n, V *b1, V *b2)
{
	const H ax = habs(n.x), ay = habs(n.y), az = habs(n.z);
	const int k = ax < ay ? (ax < az ? 0 : 2) : (ay < az ? 1 : 2);
	V p;
	H l;
	if (k == 0) {
		l = hsqrt(hadd(hmul(n.y, n.y), hmul(n.z, n.z)));
		p = hvec(hdiv(H0, l), hdiv(hneg(n.z), l), hdiv(n.y, l));
	} else if (k == 1) {
		l = hsqrt(hadd(hmul(n.x, n.x), hmul(n.z, n.z)));
		p = hvec(hdiv(hneg(n.z), l), hdiv(H0, l), hdiv(n.x, l));
	} else {
		l = hsqrt(hadd(hmul(n.x, n.x), hmul(n.y, n.y)));
		p = hvec(hdiv(hneg(n.y), l), hdiv(n.x, l), hdiv(H0, l));
	}
	*b1 = p;
	*b2 = hcross(n, p);
}

/* ---- open3d, open3d_fixed: Eigen's scalar order v0^2 + (v1^2 + v2^2),
   as for a Vector3f (Eigen::half is not vectorized either) ---- */
static inline H o3d_sq(V v) { return hadd(hmul(v.x, v.x), hadd(hmul(v.y, v.y), hmul(v.z, v.z))); }
static V o3d_normalizeh(V v)
{
	const H s2 = o3d_sq(v);
	if (s2 > H0) {
		const H s = hsqrt(s2);
		v = hvec(hdiv(v.x, s), hdiv(v.y, s), hdiv(v.z, s));
	}
	return v;
}
static void o3d_finish(V n, V p, V *b1, V *b2)
{
	p = o3d_normalizeh(p);
	*b1 = p;
	*b2 = o3d_normalizeh(hcross(n, p));
}
void HN(open3dh)(V n, V *b1, V *b2)
{
	const V d = hvec(hsub(H0, n.x), hsub(H1, n.y), hsub(H1, n.z));
	if (o3d_sq(d) > hcst(1e-3))
		o3d_finish(n, hvec(hsub(n.y, n.z), hneg(n.x), n.x), b1, b2);
	else
		o3d_finish(n, hvec(n.y, hsub(n.z, n.x), hneg(n.y)), b1, b2);
}
void HN(open3d_fixedh)(V n, V *b1, V *b2)
{
	const H c = hcst(0x1.6a09e667f3bcdp-1); /* 1/sqrt(2) in binary16 */
	const V d = hvec(hsub(H0, n.x), hsub(c, n.y), hsub(c, n.z));
	const V e = hvec(hadd(H0, n.x), hadd(c, n.y), hadd(c, n.z));
	if (o3d_sq(d) > hcst(1e-3) && o3d_sq(e) > hcst(1e-3))
		o3d_finish(n, hvec(hsub(n.y, n.z), hneg(n.x), n.x), b1, b2);
	else
		o3d_finish(n, hvec(n.y, hsub(n.z, n.x), hneg(n.y)), b1, b2);
}

/* ---- raylib: the smallest |component|'s axis (ties to the earlier),
   Vector3Normalize (1/length, skipped when length is 0), cross(n, b1) ---- */
void HN(raylibh)(V n, V *b1, V *b2)
{
	H min = habs(n.x), len;
	V e = hvec(H1, H0, H0), p;
	if (habs(n.y) < min) { min = habs(n.y); e = hvec(H0, H1, H0); }
	if (habs(n.z) < min) e = hvec(H0, H0, H1);
	p = hcross(n, e);
	len = hsqrt(hdot(p, p));
	if (len != H0)
		p = hscale(p, hdiv(H1, len));
	*b1 = p;
	*b2 = hcross(n, p);
}

/* ---- godot, godot_fixed: RIGHT or UP (fixed: or BACK), p / |p| by
   division, (0,0,0) when p.p is 0 or every |n_i| < 1e-5 ---- */
static void godoth(V n, V *b1, V *b2, int fixed)
{
	const H eps = hcst(0.00001);
	V p = hvec(H0, H0, H0);
	if (!(habs(n.x) < eps && habs(n.y) < eps && habs(n.z) < eps)) {
		V e = hvec(H0, H0, H0);
		H lsq;
		if (habs(n.x) <= habs(n.y) && habs(n.x) <= habs(n.z)) e.x = H1;
		else if (!fixed || habs(n.y) <= habs(n.z)) e.y = H1;
		else e.z = H1;
		p = hcross(n, e);
		lsq = hdot(p, p);
		if (lsq == H0) {
			p = hvec(H0, H0, H0);
		} else {
			const H len = hsqrt(lsq);
			p = hvec(hdiv(p.x, len), hdiv(p.y, len), hdiv(p.z, len));
		}
	}
	*b1 = p;
	*b2 = hcross(n, p);
}
void HN(godoth)(V n, V *b1, V *b2)       { godoth(n, b1, b2, 0); }
void HN(godot_fixedh)(V n, V *b1, V *b2) { godoth(n, b1, b2, 1); }

/* ---- directxmath: (y + z, 0 - x, 0 - x) or (y - z, 0 - x, x), divided by
   its length (+0 for a zero length, NaN for an infinite square), cross ---- */
void HN(directxmathh)(V n, V *b1, V *b2)
{
	const int same = (n.z < H0) == (n.y < H0);
	V p = hvec(same ? hadd(n.y, n.z) : hsub(n.y, n.z), hsub(H0, n.x), same ? hsub(H0, n.x) : n.x);
	const H lsq = hdot(p, p), len = hsqrt(lsq);
	if (lsq == (H)INFINITY)
		p = hvec((H)NAN, (H)NAN, (H)NAN);
	else if (len == H0)
		p = hvec(H0, H0, H0);
	else
		p = hvec(hdiv(p.x, len), hdiv(p.y, len), hdiv(p.z, len));
	*b1 = p;
	*b2 = hcross(n, p);
}

/* ---- ogre: Hocevar's vector, normalisedCopy (1/length from a sum
   started at 0, skipped when length is 0), cross(n, b1) ---- */
void HN(ogreh)(V n, V *b1, V *b2)
{
	V p = habs(n.x) > habs(n.z) ? hvec(hneg(n.y), n.x, H0) : hvec(H0, hneg(n.z), n.y);
	H sq = H0, len;
	sq = hadd(sq, hmul(p.x, p.x)); sq = hadd(sq, hmul(p.y, p.y)); sq = hadd(sq, hmul(p.z, p.z));
	len = hsqrt(sq);
	if (len > H0)
		p = hscale(p, hdiv(H1, len));
	*b1 = p;
	*b2 = hcross(n, p);
}

/* ---- bx, bx_fixed: bx::sqrt (0 below kFloatSmallest) and rcpSafe with
   kFloatSmallest rounded to binary16 (0) ---- */
static void bxh(V n, V *b1, V *b2, int fixed)
{
	const H small = hcst(0x1p-126);
	const H ax = n.x < H0 ? hneg(n.x) : n.x, ay = n.y < H0 ? hneg(n.y) : n.y, az = n.z < H0 ? hneg(n.z) : n.z;
	const int first = fixed ? ax > ay : ax > az;
	const H a = first ? n.x : n.y, s2 = hadd(hmul(a, a), hmul(n.z, n.z));
	const H s = s2 < small ? H0 : hsqrt(s2), as = s < H0 ? hneg(s) : s;
	const H inv = hdiv(H1, (H)copysignf((float)(small > as ? small : as), (float)s));
	V t = first ? hvec(hmul(hneg(n.z), inv), H0, hmul(n.x, inv)) : hvec(H0, hmul(n.z, inv), hmul(hneg(n.y), inv));
	*b1 = t;
	*b2 = hcross(n, t);
}
void HN(bxh)(V n, V *b1, V *b2)       { bxh(n, b1, b2, 0); }
void HN(bx_fixedh)(V n, V *b1, V *b2) { bxh(n, b1, b2, 1); }

/* ---- blender: len_squared_v2 > FLT_EPSILON (2^-23, a binary16
   subnormal), else the fixed frame; b2 = n x b1 without the zero
   products ---- */
void HN(blenderh)(V n, V *b1, V *b2)
{
	const H f = hadd(hmul(n.x, n.x), hmul(n.y, n.y));
	if (f > hcst(0x1p-23)) {
		const H d = hdiv(H1, hsqrt(f));
		*b1 = hvec(hmul(n.y, d), hmul(hneg(n.x), d), H0);
		*b2 = hvec(hmul(hneg(n.z), b1->y), hmul(n.z, b1->x), hsub(hmul(n.x, b1->y), hmul(n.y, b1->x)));
	} else {
		*b1 = hvec(n.z < H0 ? hneg(H1) : H1, H0, H0);
		*b2 = hvec(H0, H1, H0);
	}
}

/* ---- box3d: b3Perp, b3Normalize (1000*FLT_MIN rounds to 0 in binary16),
   b2 = b3Cross(b1, n) ---- */
void HN(box3dh)(V n, V *b1, V *b2)
{
	const H half = hcst(0.5);
	const V p = n.x < hneg(half) || half < n.x ? hvec(n.y, hneg(n.x), H0) : hvec(H0, n.z, hneg(n.y));
	const H ls = hdot(p, p);
	*b1 = ls > hcst(1000.0 * 0x1p-126) ? hscale(p, hdiv(H1, hsqrt(ls))) : hvec(H0, H0, H0);
	*b2 = hcross(*b1, n);
}

/* ---- appleseed: the smallest |component| (strict <, ties to z, then
   to y over x), u with it zeroed, u * (1/sqrt(u.u)), b2 = cross(b1, n) ---- */
void HN(appleseedh)(V n, V *b1, V *b2)
{
	const H ax = habs(n.x), ay = habs(n.y), az = habs(n.z);
	V u;
	if (ax < ay)
		u = ax < az ? hvec(H0, hneg(n.z), n.y) : hvec(hneg(n.y), n.x, H0);
	else
		u = ay < az ? hvec(hneg(n.z), H0, n.x) : hvec(hneg(n.y), n.x, H0);
	*b1 = hscale(u, hdiv(H1, hsqrt(hdot(u, u))));
	*b2 = hcross(*b1, n);
}

/* ---- babylon: JavaScript's double, no float or half path: the double row
   (V8's fdlibm) on n widened, b1 and b2 rounded once to binary16, as
   onb_babylonf rounds them to float ---- */
void HN(babylonh)(V n, V *b1, V *b2)
{
	onb_vec3 nd, d1, d2;
	nd.x = (double)n.x; nd.y = (double)n.y; nd.z = (double)n.z;
	onb_babylon_outline(nd, &d1, &d2);
	*b1 = hvec((H)d1.x, (H)d1.y, (H)d1.z);
	*b2 = hvec((H)d2.x, (H)d2.y, (H)d2.z);
}

/* ---- duff_wide: duff_branchless's formula in double, each output
   rounded once to binary16 (as duff_widef rounds to float) ---- */
void HN(duff_wideh)(V n, V *b1, V *b2)
{
	const double x = (double)n.x, y = (double)n.y, z = (double)n.z;
	const double sign = copysign(1.0, z);
	const double a = -1.0 / (sign + z);
	const double b = x * y * a;
	*b1 = hvec((H)(1.0 + sign * x * x * a), (H)(sign * b), (H)(-sign * x));
	*b2 = hvec((H)b, (H)(sign + y * y * a), (H)(-y));
}

/* ---- duff_comp: duff_compf's error-free transformations in binary16 ---- */
void HN(duff_comph)(V n, V *b1, V *b2)
{
	const H x = n.x, y = n.y, z = n.z;
	const H s = hsign(z);
	const H h = hadd(s, z), hl = hadd(hsub(s, h), z);
	const H a = hdiv(hneg(H1), h);
	const H e = hfma(a, h, H1);
	const H al = hmul(a, hadd(e, hmul(a, hl)));
	const H xx = hmul(x, x), xxl = hfma(x, x, hneg(xx));
	const H xy = hmul(x, y), xyl = hfma(x, y, hneg(xy));
	const H yy = hmul(y, y), yyl = hfma(y, y, hneg(yy));
	const H p = hmul(xx, a), pl = hadd(hfma(xx, a, hneg(p)), hadd(hmul(xx, al), hmul(xxl, a)));
	const H b = hmul(xy, a), bl = hadd(hfma(xy, a, hneg(b)), hadd(hmul(xy, al), hmul(xyl, a)));
	const H q = hmul(yy, a), ql = hadd(hfma(yy, a, hneg(q)), hadd(hmul(yy, al), hmul(yyl, a)));
	const H sp = hmul(s, p);
	const H t1 = hadd(H1, sp), t1l = hadd(hsub(H1, t1), sp);
	const H t2 = hadd(s, q), t2l = hadd(hsub(s, t2), q);
	const H bb = hadd(b, bl);
	*b1 = hvec(hadd(t1, hadd(t1l, hmul(s, pl))), hmul(s, bb), hmul(hneg(s), x));
	*b2 = hvec(bb, hadd(t2, hadd(t2l, ql)), hneg(y));
}

#if !defined(ONB__HALF_F16C)
#if ONB__HALF_DISPATCH
/* The public names: ifuncs resolved once, at load time, to the F16C copy
   where the CPU has F16C, else to this file's own (soft) copy.  A resolver
   runs while the dynamic loader relocates, before a sanitizer's runtime
   is set up, so it must not be instrumented (an instrumented resolver
   crashed every sanitized binary at load). */
#define ONB__RESOLVER __attribute__((no_sanitize_address, no_sanitize_undefined))
#define ONB__HRESOLVE(m)                                                      \
	void onb__##m##h_f16c(V n, V *b1, V *b2);                                 \
	ONB__RESOLVER static void (*onb__##m##h_resolve(void))(V, V *, V *)       \
	{                                                                         \
		__builtin_cpu_init();                                                 \
		return __builtin_cpu_supports("f16c") ? onb__##m##h_f16c : onb__##m##h_soft; \
	}                                                                         \
	void onb_##m##h(V n, V *b1, V *b2) __attribute__((ifunc("onb__" #m "h_resolve")));
ONB_METHOD_LIST(ONB__HRESOLVE)
ONB_FLOAT_METHOD_LIST(ONB__HRESOLVE)
void onb__frisvad_thresholdh_f16c(V n, H t, V *b1, V *b2);
ONB__RESOLVER static void (*onb__frisvad_thresholdh_resolve(void))(V, H, V *, V *)
{
	__builtin_cpu_init();
	return __builtin_cpu_supports("f16c") ? onb__frisvad_thresholdh_f16c : onb__frisvad_thresholdh_soft;
}
void onb_frisvad_thresholdh(V n, H t, V *b1, V *b2) __attribute__((ifunc("onb__frisvad_thresholdh_resolve")));
V onb__frisvad_rotateh_f16c(V n, H x, H y, H z);
ONB__RESOLVER static V (*onb__frisvad_rotateh_resolve(void))(V, H, H, H)
{
	__builtin_cpu_init();
	return __builtin_cpu_supports("f16c") ? onb__frisvad_rotateh_f16c : onb__frisvad_rotateh_soft;
}
V onb_frisvad_rotateh(V n, H x, H y, H z) __attribute__((ifunc("onb__frisvad_rotateh_resolve")));
#endif

/* The conversions the half kernels run with: "f16c" (vcvtph2ps and
   vcvtps2ph, chosen at load time), "soft" (libgcc's routines) or "inline"
   (a build that converts with instructions everywhere: -mf16c, arm64's fcvt); the arithmetic is float's,
   each result rounded to binary16, in every case. */
const char *onb_half_isa(void)
{
#if ONB__HALF_DISPATCH
	__builtin_cpu_init();
	return __builtin_cpu_supports("f16c") ? "f16c" : "soft";
#elif defined(__F16C__) || defined(__aarch64__)
	return "inline";
#else
	return "soft";
#endif
}

/* ---- the array entries, on binary16 bit patterns ---- */
static inline H hget(uint16_t b) { H h; memcpy(&h, &b, sizeof h); return h; }
static inline uint16_t hbits(H h) { uint16_t b; memcpy(&b, &h, sizeof b); return b; }
#define ONB__ARRAY_H(m)                                                       \
	void onb_##m##_arrayh(const uint16_t *n, uint16_t *b1, uint16_t *b2)      \
	{                                                                         \
		V v, r1, r2;                                                          \
		v.x = hget(n[0]); v.y = hget(n[1]); v.z = hget(n[2]);                 \
		onb_##m##h(v, &r1, &r2);                                              \
		b1[0] = hbits(r1.x); b1[1] = hbits(r1.y); b1[2] = hbits(r1.z);        \
		b2[0] = hbits(r2.x); b2[1] = hbits(r2.y); b2[2] = hbits(r2.z);        \
	}
ONB_METHOD_LIST(ONB__ARRAY_H)
ONB_FLOAT_METHOD_LIST(ONB__ARRAY_H)
#endif /* !ONB__HALF_F16C */

#else
/* No _Float16 here: no half entry points (onb.h, ONB_HAVE_HALF). */
typedef int onb__no_half;
#endif
