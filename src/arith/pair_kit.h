/*
 * pair_kit.h - the fast reference's arithmetic, included once per
 * instantiation (pairs of long doubles, or pairs of doubles when
 * REFFAST_PAIR_DOUBLE is defined; so no include guard) by reffast.c,
 * reffast_f.c and each family's fast formula (src/families/).  Exponents by bit pattern,
 * error-free transformations, the pair ("double-long-double") arithmetic
 * with a running error bound on every value (xv: h + l, error e), and
 * Ziv's rounding test that decides whether a bounded value rounds to one
 * float or double; then the formulas' building blocks (dot, cross,
 * normalize, Frisvad's and Duff's formulas).  HOT, INFL, TINY, FLOOR and
 * the types xv_pd, xv_pl come from pair.h.
 */
#include <math.h>
#include <float.h>
#include <stdint.h>
#include <string.h>
#include "arith/pair.h"
/* ---- exponents by bit pattern (no libm call on the fast path) ---- */

/* Trailing zeros of m != 0. */
static inline int ctz64(uint64_t m)
{
#if defined(__GNUC__)
	return __builtin_ctzll(m);
#else
	int tz = 0;
	while (!(m & 1u)) { m >>= 1; tz++; }
	return tz;
#endif
}

/* floor(log2 |a|) of a normal double. */
static inline int dexp(double a)
{
	uint64_t u;
	memcpy(&u, &a, 8);
	return (int)((u >> 52) & 0x7ff) - 1023;
}

/* The exponent of the lowest set bit of a normal nonzero double. */
static inline int dlsb(double a)
{
	uint64_t u;
	memcpy(&u, &a, 8);
	u = (u & ((1ull << 52) - 1)) | (1ull << 52);
	return dexp(a) - 52 + ctz64(u);
}

/* 1 when the normal double a is a power of two. */
static inline int dpow2(double a)
{
	uint64_t u;
	memcpy(&u, &a, 8);
	return (u & ((1ull << 52) - 1)) == 0;
}

/* 2^e for -1022 <= e <= 1023. */
static inline double pow2(int e)
{
	const uint64_t u = (uint64_t)(e + 1023) << 52;
	double d;
	memcpy(&d, &u, 8);
	return d;
}

/* ---- error-free transformations (exact: no bound) ---- */

/* s + t = a + b exactly, s = RN(a + b) (Knuth). */
static inline void two_sum(double a, double b, double *s, double *t)
{
	const double x = a + b, z = x - a;
	*t = (a - (x - z)) + (b - z);
	*s = x;
}

/* s + t = a + b exactly when |a| >= |b| or a = 0 (Dekker). */
static inline void fast_two_sum(double a, double b, double *s, double *t)
{
	const double x = a + b;
	*t = b - (x - a);
	*s = x;
}

/* p + t = a b exactly unless a b underflows (the callers check |p|). */
static inline void two_prod(double a, double b, double *p, double *t)
{
	*p = a * b;
#if defined(__FMA__) || defined(FP_FAST_FMA)
	*t = fma(a, b, -*p);
#else
	{
		const double ca = 134217729.0 * a, cb = 134217729.0 * b;
		const double ah = ca - (ca - a), al = a - ah, bh = cb - (cb - b), bl = b - bh;
		*t = ((ah * bh - *p) + ah * bl + al * bh) + al * bl;
	}
#endif
}

/* ---- double-long-double arithmetic ----
   The formula runs in pairs of x87 long doubles (u = 2^-64): a pair
   carries 128 bits, so one operation rounds at 2^-124 relative or less,
   below MPFR's own 2^-127 only by a few bits, which is what a forward
   error needs: E - cv cancels 53 bits of E, and Ziv's test on it needs E
   to about 2^-115.  The algorithms and their bounds hold for any binary
   precision p (Joldes, Muller, Popescu 2017); TwoProd is Dekker's, with
   Veltkamp's split at 2^32 + 1 (exact for p = 64 without overflow). */
#ifdef REFFAST_PAIR_DOUBLE
/* This translation unit (reffast_f.c) is the float precision's: pairs of
   doubles (u = 2^-53, one operation < 2^-102 relative), enough there since
   E - cv cancels only 24 bits of E; TwoProd by fma. */
typedef double ld;
#define PFABS fabs
#define PSQRT sqrt
#define DDREL 0x1p-102           /* relative rounding of a pair operation    */
#define RHO_SLOP 0x1p-99         /* error of a residual 1 - b y (recip)      */
#define RHO_SLOP2 0x1p-98        /* error of a residual 1 - s y^2 (rsqrt)    */
#define OFF_SLOP 0x1p-52         /* rounding of (h - c) + l in ziv           */
#define PAIR_U 0x1p-52           /* twice u, for xsub_inexact                */
#define EVAL_NAME reffast_eval_pairs_of_doubles
#else
typedef long double ld;
#define PFABS fabsl
#define PSQRT sqrtl
#define DDREL 0x1p-124           /* relative rounding of a pair operation    */
#define RHO_SLOP 0x1p-121
#define RHO_SLOP2 0x1p-120
#define OFF_SLOP 0x1p-62
#define EVAL_NAME reffast_eval_pairs_of_long_doubles
#endif

static inline void two_sum_l(ld a, ld b, ld *s, ld *t)
{
	const ld x = a + b, z = x - a;
	*t = (a - (x - z)) + (b - z);
	*s = x;
}

static inline void fast_two_sum_l(ld a, ld b, ld *s, ld *t)
{
	const ld x = a + b;
	*t = b - (x - a);
	*s = x;
}

static inline void two_prod_l(ld a, ld b, ld *p, ld *t)
{
#ifdef REFFAST_PAIR_DOUBLE
	two_prod(a, b, p, t);
#else
	const ld ca = 4294967297.0L * a, cb = 4294967297.0L * b;
	const ld ah = ca - (ca - a), al = a - ah, bh = cb - (cb - b), bl = b - bh;
	*p = a * b;
	*t = ((ah * bh - *p) + ah * bl + al * bh) + al * bl;
#endif
}

/* AccurateDWPlusDW (ibid., Algorithm 6): relative error
   <= 3u^2/(1 - 4u) < 2^-126. */
static inline void dd_add(ld xh, ld xl, ld yh, ld yl, ld *zh, ld *zl)
{
	ld sh, sl, th, tl, c, vh, vl, w;
	two_sum_l(xh, yh, &sh, &sl);
	two_sum_l(xl, yl, &th, &tl);
	c = sl + th;
	fast_two_sum_l(sh, c, &vh, &vl);
	w = tl + vl;
	fast_two_sum_l(vh, w, zh, zl);
}

/* DWTimesDW1 (ibid., Algorithm 10: the low parts' cross products in
   plain arithmetic; relative error <= 7u^2 < 2^-125).  No underflow: the
   callers check the result. */
static inline void dd_mul(ld xh, ld xl, ld yh, ld yl, ld *zh, ld *zl)
{
	ld ch, cl1, cl2, cl3;
	two_prod_l(xh, yh, &ch, &cl1);
	cl2 = xh * yl + xl * yh;
	cl3 = cl1 + cl2;
	fast_two_sum_l(ch, cl3, zh, zl);
}

#ifdef REFFAST_PAIR_DOUBLE
typedef xv_pd xv;
#define XR(e) ((e)->xr.d)
#else
typedef xv_pl xv;
#define XR(e) ((e)->xr.l)
#endif

static inline xv xc(double d) { xv r = { d, 0.0, 0.0 }; return r; }

/* An upper bound of |X| from v and e. */
static inline double mag(xv a) { return (double)PFABS(a.h) * (1.0 + 0x1p-50) + a.e; }

static inline int ok(xv r)
{
	const ld a = PFABS(r.h);
	/* one branch for the caller, not three (NaN fails each comparison) */
	return ((double)a <= DBL_MAX) & (r.e <= DBL_MAX) & ((a == 0.0) | (a >= TINY));
}

static inline xv xneg(xv a) { xv r = { -a.h, -a.l, a.e }; return r; }

static inline int is_zero(xv a) { return a.h == 0.0 && a.e == 0.0; }

/* The exponents of the highest and lowest set bits of a nonzero a. */
static void bit_span(ld a, int *hi, int *lo)
{
#ifdef REFFAST_PAIR_DOUBLE
	*hi = dexp(a);
	*lo = dlsb(a);
#else
	/* the x87 format: 64-bit significand with its leading 1, then sign and
	   15-bit exponent (reffast_usable checks LDBL_MANT_DIG == 64) */
	unsigned char b[sizeof(ld)];
	uint64_t m;
	uint16_t se;
	memcpy(b, &a, sizeof b);
	memcpy(&m, b, 8);
	memcpy(&se, b + 8, 2);
	*hi = (int)(se & 0x7fff) - 16383;
	*lo = *hi - 63 + ctz64(m);
#endif
}

/* The sum of two exact pairs, when it is an exact pair again and fits
   MPFR's precision (then MPFR's sum is exact too): 1 and *r, else 0.
   Two VecSum passes over the four parts; the sum is a pair when the two
   lowest are then zero. */
static int exact_pair_sum(xv a, xv b, xv *r)
{
	ld t[4];
	int i, pass, h0, l0, h1, l1;
	t[0] = a.l; t[1] = b.l; t[2] = a.h; t[3] = b.h;
	for (pass = 0; pass < 2; pass++)
		for (i = 1; i < 4; i++)
			two_sum_l(t[i], t[i - 1], &t[i], &t[i - 1]);
	if (t[0] != 0.0 || t[1] != 0.0)
		return 0;
	fast_two_sum_l(t[3], t[2], &r->h, &r->l);
	if (r->h == 0.0) {
		if (r->l != 0.0)
			return 0;
		r->h = 0.0; /* x + (-x) = +0 in RN, in IEEE as in MPFR */
		r->e = 0.0;
		return 1;
	}
	bit_span(r->h, &h0, &l0);
	if (r->l != 0.0) {
		bit_span(r->l, &h1, &l1);
		l0 = l1;
	}
	r->e = 0.0; /* before ok(), which reads it */
	return h0 - l0 + 1 <= 127 && ok(*r);
}

/* a + b (mpfr_add).  Relative rounding: pair < 2^-126, MPFR <= 2^-127 of
   |X_mpfr| <= |r| + 2(ea + eb): DDREL |r| and the inflation cover both. */
HOT xv xadd(xv a, xv b, int *bad)
{
	xv r;
	if (is_zero(b) && a.h != 0.0) /* MPFR: x + 0 = x exactly */
		return a;
	if (is_zero(a) && b.h != 0.0)
		return b;
	if (a.l == 0.0 && b.l == 0.0) {
		/* TwoSum: exact.  IEEE and MPFR give zeros the same sign in RN. */
		two_sum_l(a.h, b.h, &r.h, &r.l);
		if (a.e == 0.0 && b.e == 0.0) {
			int ha, la, hb, lb;
			if (a.h == 0.0 || b.h == 0.0) {
				r.e = 0.0;
				if (!ok(r)) *bad = 1;
				return r;
			}
			bit_span(a.h, &ha, &la);
			bit_span(b.h, &hb, &lb);
			/* exact in MPFR when the sum's bits fit its precision */
			if ((ha > hb ? ha : hb) + 1 - (la < lb ? la : lb) + 1 <= 127) {
				r.e = 0.0;
				if (!ok(r)) *bad = 1;
				return r;
			}
		}
	} else if (a.e == 0.0 && b.e == 0.0 && exact_pair_sum(a, b, &r)) {
		return r;
	} else {
		dd_add(a.h, a.l, b.h, b.l, &r.h, &r.l);
	}
	r.e = ((a.e + b.e) * INFL + DDREL * (double)PFABS(r.h)) * INFL + FLOOR;
	if (!ok(r)) *bad = 1;
	return r;
}

HOT xv xsub(xv a, xv b, int *bad) { return xadd(a, xneg(b), bad); }

/* a - d for an inexact a (a.e > 0) and a double d (mpfr_sub_d), leaner
   than xadd: TwoSum gives s + t = h - d exactly, q = RN(t + l) is within
   u |q| of t + l (u the pair's unit roundoff: PAIR_U = 2u covers it),
   and TwoSum again makes the pair s + q exact.  So our value is within
   e + PAIR_U |q| of X - d, and MPFR's one rounding at p bits adds
   2^-p |X_mpfr - d| <= 2^-p (|r| (1 + 2^-50) + 2e): DDREL |r| and the
   inflation of e cover it, as in xadd. */
#ifdef REFFAST_PAIR_DOUBLE
HOT xv xsub_inexact(xv a, double d, int *bad)
{
	xv r;
	ld s, t, q;
	two_sum_l(a.h, -(ld)d, &s, &t);
	q = t + a.l;
	two_sum_l(s, q, &r.h, &r.l);
	r.e = ((a.e + PAIR_U * (double)PFABS(q)) * INFL + DDREL * (double)PFABS(r.h)) * INFL + FLOOR;
	if (!ok(r)) *bad = 1;
	return r;
}
#endif

/* a b (mpfr_mul, mpfr_sqr). */
HOT xv xmul(xv a, xv b, int *bad)
{
	xv r;
	double prop;
	if (is_zero(a) || is_zero(b)) { /* exact zero, sign of the product */
		r.h = a.h * b.h; r.l = 0.0; r.e = 0.0;
		if (!isfinite((double)r.h)) *bad = 1;
		return r;
	}
	if (a.l == 0.0 && b.l == 0.0) {
		two_prod_l(a.h, b.h, &r.h, &r.l); /* exact: no underflow (checked) */
		if (r.h != 0.0 && PFABS(r.h) < 0x1p-960) { *bad = 1; r.e = 0.0; return r; }
		if (a.e == 0.0 && b.e == 0.0) {
			int ha, la, hb, lb;
			bit_span(a.h, &ha, &la);
			bit_span(b.h, &hb, &lb);
			if ((ha - la + 1) + (hb - lb + 1) <= 127) { /* exact in MPFR too */
				r.e = 0.0;
				if (!ok(r)) *bad = 1;
				return r;
			}
		}
	} else {
		dd_mul(a.h, a.l, b.h, b.l, &r.h, &r.l);
	}
	/* |ab - a'b'| <= |a| eb + |b| ea + ea eb */
	prop = mag(a) * b.e + mag(b) * a.e + a.e * b.e;
	r.e = (prop * INFL + DDREL * (double)PFABS(r.h)) * INFL + FLOOR;
	if (!ok(r)) *bad = 1;
	return r;
}

/* 1 when a (nonzero, normal) is a power of two; *ex = floor(log2 |a|). */
static int is_pow2(ld a, int *ex)
{
	int lo;
	bit_span(a, ex, &lo);
	return lo == *ex;
}

/* 1/b (mpfr_ui_div(1, b)).  y0 = RN(1/bh), one Newton step, and an a
   posteriori bound: with rho = 1 - b y1 (error < 2^-122 since b y1 ~ 1),
   |y1 - 1/b| = |rho|/|b|.  Propagation eb/bmin^2; MPFR 2^-127/bmin. */
HOT xv xrecip(xv b, int *bad)
{
	xv r;
	ld y0, ph, pl, rh, rl;
	double bmin, rho;
	int ex;
	if (b.l == 0.0 && b.e == 0.0 && b.h != 0.0 && is_pow2(b.h, &ex)) {
		r.h = 1.0 / b.h; r.l = 0.0; r.e = 0.0; /* a power of two: exact */
		if (!ok(r)) *bad = 1;
		return r;
	}
	bmin = (double)PFABS(b.h) * (1.0 - 0x1p-50) - 2.0 * b.e;
	if (!(bmin > 0.5 * (double)PFABS(b.h)) || !(PFABS(b.h) < 0x1p500)) {
		*bad = 1;
		return b;
	}
	y0 = 1.0 / b.h;
	dd_mul(b.h, b.l, y0, 0.0, &ph, &pl);
	dd_add(1.0, 0.0, -ph, -pl, &rh, &rl);
	fast_two_sum_l(y0, y0 * rh, &r.h, &r.l);
	dd_mul(b.h, b.l, r.h, r.l, &ph, &pl);
	dd_add(1.0, 0.0, -ph, -pl, &rh, &rl);
	rho = (double)PFABS(rh) + RHO_SLOP;
	r.e = ((b.e / bmin / bmin) * INFL + rho / bmin * INFL + 0x1p-126 / bmin) * INFL + FLOOR;
	if (!ok(r)) *bad = 1;
	return r;
}

/* 1/sqrt(s) (mpfr_rec_sqrt).  y0 = RN(1/sqrt(sh)), one Newton step, and
   a posteriori: rho = 1 - s y1^2 (error < 2^-121), y1 = (1 + d)/sqrt(s)
   with |d| <= 0.51 |rho| for |rho| < 2^-40.  Propagation
   0.5 es smin^-1.5; MPFR 2^-127/sqrt(smin). */
HOT xv xrsqrt(xv s, int *bad)
{
	xv r;
	ld y0, qh, ql, ph, pl, rh, rl;
	double smin, rho;
	int ex;
	if (s.l == 0.0 && s.e == 0.0 && s.h > 0.0 && is_pow2(s.h, &ex) && !(ex & 1)) {
		r.h = 1.0 / PSQRT(s.h); r.l = 0.0; r.e = 0.0; /* 4^k: exact */
		if (!ok(r)) *bad = 1;
		return r;
	}
	smin = (double)s.h * (1.0 - 0x1p-50) - 2.0 * s.e;
	if (!(smin > 0.5 * (double)s.h) || !(s.h < 0x1p500)) {
		*bad = 1;
		return s;
	}
	y0 = 1.0 / PSQRT(s.h);
	two_prod_l(y0, y0, &qh, &ql);
	dd_mul(s.h, s.l, qh, ql, &ph, &pl);
	dd_add(1.0, 0.0, -ph, -pl, &rh, &rl);
	fast_two_sum_l(y0, 0.5 * y0 * rh, &r.h, &r.l);
	dd_mul(r.h, r.l, r.h, r.l, &qh, &ql);
	dd_mul(s.h, s.l, qh, ql, &ph, &pl);
	dd_add(1.0, 0.0, -ph, -pl, &rh, &rl);
	rho = (double)PFABS(rh) + RHO_SLOP2;
	if (!(rho < 0x1p-40)) {
		*bad = 1;
		return s;
	}
	{
		const double is = 1.0 / sqrt(smin) * (1.0 + 0x1p-50);  /* >= 1/sqrt(s) */
		r.e = ((0.5 * s.e * is * is * is) * INFL + 0.52 * (double)PFABS(r.h) * rho + 0x1p-126 * is) * INFL + FLOOR;
	}
	if (!ok(r)) *bad = 1;
	return r;
}

/* ---- Ziv's rounding test ---- */

/* RN to the format (53 or 24 bits) of every real within 2e of v (X and
   X_mpfr both are): 1 and *out when they all round to the same value,
   strictly inside its rounding interval; else 0.  c = RN(h) is the
   candidate; off = v - c = (h - c) + l, h - c exact, one rounding. */
HOT int ziv(xv v, int bits, double *out)
{
	double c, a, ulp, upg, dng, m, od;
	ld off;
	int ex, fail;
	if (!isfinite((double)v.h))
		return 0;
	c = bits == 24 ? (double)(float)v.h : (double)v.h;
	if (v.e == 0.0 && v.l == 0.0 && (ld)c == v.h) { /* exact, and representable */
		*out = c;
		return 1;
	}
	a = fabs(c);
	if (a < (bits == 24 ? 0x1p-126 : TINY) || !isfinite(c))
		return 0;
	ex = dexp(a);
	ulp = pow2(ex + 1 - bits);
	upg = 0.5 * ulp;                            /* half the gap above |c| */
	dng = dpow2(a) ? 0.25 * ulp : 0.5 * ulp;    /* half the gap below     */
	if (v.e == 0.0) {
		/* Exact v = h + l, |l| <= ulp(h)/2 of a long double, far below
		   the format's gaps: RN(v) = c = RN(h) (ties to even) unless h is
		   exactly a midpoint of the format and l breaks the tie. */
		const ld dh = v.h - (ld)c; /* exact */
		const double half = (dh > 0) == (c > 0) ? upg : dng; /* toward h's side */
		if (v.l != 0.0 && dh != 0.0 && PFABS(dh) == (ld)half) {
			if ((v.l > 0) == (dh > 0))
				c = bits == 24 ? (double)nextafterf((float)c, dh > 0 ? INFINITY : -INFINITY)
				               : nextafter(c, dh > 0 ? INFINITY : -INFINITY);
		}
		*out = c;
		return 1;
	}
	/* off: the offset of v from c, away from zero; no branch on signs
	   (random here: a mispredicted branch cost more than the test) */
	off = ((v.h - (ld)c) + v.l) * (ld)copysign(1.0, c);
	od = (double)off; /* one conversion (x87 to SSE goes through memory) */
	m = 2.0 * v.e * INFL + fabs(od) * OFF_SLOP;
	/* a t <= 0 passes either test, as it must */
	fail = ((od + m) * (1.0 + 0x1p-50) >= upg) | ((m - od) * (1.0 + 0x1p-50) >= dng);
	if (!fail)
		*out = c;
	return !fail;
}

HOT int ziv_d(xv v, double *out) { return ziv(v, 53, out); }
HOT int ziv_f(xv v, double *out) { return ziv(v, 24, out); }

/* ---- the formulas' building blocks, mirroring the MPFR kit (mpfr_kit.c)
   operation by operation ---- */

/* dot(): p0 = a0 b0, p1 = a1 b1, out = p0 + p1, p0 = a2 b2, out += p0 */
HOT xv xdot(const xv *a, const xv *b, int *bad)
{
	xv o = xadd(xmul(a[0], b[0], bad), xmul(a[1], b[1], bad), bad);
	return xadd(o, xmul(a[2], b[2], bad), bad);
}

HOT void xcross(xv *o, const xv *a, const xv *b, int *bad)
{
	o[0] = xsub(xmul(a[1], b[2], bad), xmul(a[2], b[1], bad), bad);
	o[1] = xsub(xmul(a[2], b[0], bad), xmul(a[0], b[2], bad), bad);
	o[2] = xsub(xmul(a[0], b[1], bad), xmul(a[1], b[0], bad), bad);
}

HOT void xnormalize(xv *a, int *bad)
{
	const xv r = xrsqrt(xdot(a, a, bad), bad);
	int i;
	if (*bad)
		return;
	for (i = 0; i < 3; i++)
		a[i] = xmul(a[i], r, bad);
}

static inline void xset3(xv *o, double x, double y, double z) { o[0] = xc(x); o[1] = xc(y); o[2] = xc(z); }

/* kit_axis_cross: o = sg (e_axis x n), exact, o[axis] = +0 */
HOT void xaxis_cross(xv *o, int axis, int sg, const xv *n)
{
	const int i = (axis + 1) % 3, j = (axis + 2) % 3;
	o[axis] = xc(0.0);
	o[i] = sg > 0 ? xneg(n[j]) : n[j];
	o[j] = sg > 0 ? n[i] : xneg(n[i]);
}

/* kit_perp_cross: b1 = sg (e_axis x n) normalized, b2 = n x b1 */
HOT void xperp_cross(int axis, int sg, const xv *n, xv *b1, xv *b2, int *bad)
{
	xaxis_cross(b1, axis, sg, n);
	xnormalize(b1, bad);
	xcross(b2, n, b1, bad);
}

/* kit_frisvad with sg = +1: a = 1/(1+z), b = -x y a, b1 = (1 - x^2 a, b, -x), b2 = (b, 1 - y^2 a, -y) */
HOT void xfrisvad(const xv *n, xv *b1, xv *b2, int *bad)
{
	const xv a = xrecip(xadd(n[2], xc(1.0), bad), bad);
	const xv b = xneg(xmul(xmul(n[0], n[1], bad), a, bad));
	if (*bad)
		return;
	b1[0] = xsub(xc(1.0), xmul(xmul(n[0], n[0], bad), a, bad), bad);
	b1[1] = b;
	b1[2] = xneg(n[0]);
	b2[0] = b;
	b2[1] = xsub(xc(1.0), xmul(xmul(n[1], n[1], bad), a, bad), bad);
	b2[2] = xneg(n[1]);
}

/* Duff's lower branch and the branchless form with s = +-1:
   a = -1/(s + z), b = x y a, b1 = (1 + s x^2 a, s b, -s x), b2 = (b, s + y^2 a, -y);
   Duff's lower branch (branchless = 0): a = 1/(1 - z), b = x y a,
   b1 = (1 - x^2 a, -b, x), b2 = (b, y^2 a - 1, -y). */
HOT void xduff(const xv *n, int s, int branchless, xv *r1, xv *r2, int *bad)
{
	xv a, b, t2;
	if (branchless) {
		a = xneg(xrecip(xadd(n[2], xc((double)s), bad), bad));
	} else {
		a = xrecip(xsub(xc(1.0), n[2], bad), bad);
	}
	b = xmul(xmul(n[0], n[1], bad), a, bad);
	if (*bad)
		return;
	t2 = xmul(xmul(n[0], n[0], bad), a, bad);
	if (branchless) {
		if (s < 0) t2 = xneg(t2);
		r1[0] = xadd(t2, xc(1.0), bad);
		r1[1] = s < 0 ? xneg(b) : b;
		r1[2] = s < 0 ? n[0] : xneg(n[0]);
		r2[0] = b;
		r2[1] = xadd(xmul(xmul(n[1], n[1], bad), a, bad), xc((double)s), bad);
	} else {
		r1[0] = xsub(xc(1.0), t2, bad);
		r1[1] = xneg(b);
		r1[2] = n[0];
		r2[0] = b;
		r2[1] = xsub(xmul(xmul(n[1], n[1], bad), a, bad), xc(1.0), bad);
	}
	r2[2] = xneg(n[1]);
}
