/*
 * reffast.c - the certified fast reference (see reffast.h).
 *
 * Notation: u = 2^-53, p = the MPFR reference's precision (>= 120).
 *
 * Every intermediate of a method's formula is an `xv`: a double-double
 * value v = h + l (normalized: h = RN(h + l)) and a bound e such that
 *     |v - X| <= e   and   |X_mpfr - X| <= e,
 * where X is the exact real value of that intermediate and X_mpfr the
 * value reference.c computes for it at p bits, through the same sequence
 * of operations.  Each operation below derives the new bound from the
 * operands' (propagation) plus the rounding of the double-double result
 * (relative 2^-100 at most, see each operation) plus MPFR's own rounding
 * (relative 2^-p <= 2^-120, absorbed in the same terms).  So a stored
 * figure RN(X_mpfr) is determined when the whole interval [v - 2e, v + 2e]
 * lies strictly inside one double's rounding interval (Ziv's test,
 * ziv_d): then the fast path writes that double and MPFR writes the same.
 * e = 0 means exact in both (then zeros keep their IEEE/MPFR sign).
 *
 * Bounds are computed in double and inflated by (1 + 2^-40), which covers
 * the few roundings (each <= u relative) of computing them; every nonzero
 * value must stay above 2^-900 (no underflow anywhere), else the input
 * takes the MPFR path.
 *
 * The defect terms (sums of products of doubles) are computed exactly
 * with error-free transformations (TwoProd, then repeated VecSum), and
 * their bound is MPFR's exact_sum error, derived in exact_dot.
 *
 * TwoProd uses fma when this file is compiled with FMA (the Makefile
 * builds it with -mfma on x86_64, with -ffp-contract=off kept so that no
 * other expression is contracted); Dekker's product otherwise.
 */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <stdint.h>
#include "reffast.h"

struct reffast_ctx {
	int prec;                 /* MPFR precision p of the reference mirrored */
	double up;                /* 2^-p */
	double last[3];           /* cache: the last input, its |n|-1 and 1/|n| */
	double last_norm;
	int have_last, last_ok, last_inv_ok;
	double inv_h, inv_l, inv_e;
};

typedef struct { double h, l, e; } xv;

#define INFL (1.0 + 0x1p-40)     /* inflation of every computed bound        */
#define DDREL 0x1p-100           /* relative rounding of a double-double op  */
#define TINY 0x1p-900            /* smallest magnitude allowed (no underflow) */
#define FLOOR 0x1p-1000          /* absolute floor added to inexact bounds   */

int reffast_usable(int ref_bits, const char **why)
{
	if (ref_bits < 120) {
		*why = "the fast reference's bounds assume an MPFR reference of at least 120 bits";
		return 0;
	}
#if defined(__FMA__)
	if (!fma_available()) {
		*why = "this build's fast reference uses FMA instructions and this CPU has none";
		return 0;
	}
#endif
	*why = "";
	return 1;
}

reffast_ctx *reffast_new(int ref_bits)
{
	reffast_ctx *c = calloc(1, sizeof *c);
	if (!c)
		return NULL;
	c->prec = ref_bits;
	c->up = ldexp(1.0, -ref_bits);
	return c;
}

void reffast_free(reffast_ctx *c) { free(c); }

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

/* ---- double-double arithmetic ---- */

/* AccurateDWPlusDW (Joldes, Muller, Popescu 2017, Algorithm 6): relative
   error <= 3u^2/(1 - 4u) < 2^-104. */
static inline void dd_add(double xh, double xl, double yh, double yl, double *zh, double *zl)
{
	double sh, sl, th, tl, c, vh, vl, w;
	two_sum(xh, yh, &sh, &sl);
	two_sum(xl, yl, &th, &tl);
	c = sl + th;
	fast_two_sum(sh, c, &vh, &vl);
	w = tl + vl;
	fast_two_sum(vh, w, zh, zl);
}

/* DWTimesDW1 (ibid., Algorithm 10: the low parts' cross products in
   plain double; relative error <= 7u^2 < 2^-103).  No underflow: the
   callers check the result. */
static inline void dd_mul(double xh, double xl, double yh, double yl, double *zh, double *zl)
{
	double ch, cl1, cl2, cl3;
	two_prod(xh, yh, &ch, &cl1);
	cl2 = xh * yl + xl * yh;
	cl3 = cl1 + cl2;
	fast_two_sum(ch, cl3, zh, zl);
}

static inline xv xc(double d) { xv r = { d, 0.0, 0.0 }; return r; }

/* An upper bound of |X| from v and e. */
static inline double mag(xv a) { return fabs(a.h) * (1.0 + 0x1p-50) + a.e; }

static inline int ok(xv r)
{
	const double a = fabs(r.h);
	return isfinite(r.h) && isfinite(r.e) && (a == 0.0 || a >= TINY);
}

static inline xv xneg(xv a) { xv r = { -a.h, -a.l, a.e }; return r; }

static inline int is_zero(xv a) { return a.h == 0.0 && a.e == 0.0; }

/* a + b (mpfr_add). */
static xv xadd(xv a, xv b, int *bad)
{
	xv r;
	if (is_zero(b) && a.h != 0.0) /* MPFR: x + 0 = x exactly */
		return a;
	if (is_zero(a) && b.h != 0.0)
		return b;
	if (a.l == 0.0 && b.l == 0.0) {
		/* TwoSum: exact.  IEEE and MPFR give zeros the same sign in RN. */
		two_sum(a.h, b.h, &r.h, &r.l);
		if (a.e == 0.0 && b.e == 0.0) {
			int ea, eb;
			/* Exact in MPFR when the sum spans at most 53 + 60 + 1 <= p bits. */
			(void)frexp(a.h, &ea);
			(void)frexp(b.h, &eb);
			if (r.l == 0.0 || a.h == 0.0 || b.h == 0.0 || abs(ea - eb) <= 60) {
				r.e = 0.0;
				if (!ok(r)) *bad = 1;
				return r;
			}
		}
	} else {
		dd_add(a.h, a.l, b.h, b.l, &r.h, &r.l);
	}
	/* propagation a.e + b.e; rounding of the dd sum (< 2^-104 |r|) and of
	   MPFR's sum (2^-p |X_mpfr| <= 2^-p (|r| + 2(a.e + b.e))) */
	r.e = ((a.e + b.e) * INFL + DDREL * fabs(r.h)) * INFL + FLOOR;
	if (!ok(r)) *bad = 1;
	return r;
}

static xv xsub(xv a, xv b, int *bad) { return xadd(a, xneg(b), bad); }

/* a b (mpfr_mul, mpfr_sqr). */
static xv xmul(xv a, xv b, int *bad)
{
	xv r;
	double prop;
	if (is_zero(a) || is_zero(b)) { /* exact zero, sign of the product */
		r = xc(a.h * b.h);
		if (!isfinite(r.h)) *bad = 1;
		return r;
	}
	if (a.l == 0.0 && b.l == 0.0) {
		two_prod(a.h, b.h, &r.h, &r.l); /* exact: no underflow (ok() below) */
		if (fabs(r.h) < 0x1p-960) { *bad = 1; return r; }
		if (a.e == 0.0 && b.e == 0.0) { /* 106 bits: exact in MPFR too */
			r.e = 0.0;
			if (!ok(r)) *bad = 1;
			return r;
		}
	} else {
		dd_mul(a.h, a.l, b.h, b.l, &r.h, &r.l);
	}
	/* |ab - a'b'| <= |a| eb + |b| ea + ea eb */
	prop = mag(a) * b.e + mag(b) * a.e + a.e * b.e;
	r.e = (prop * INFL + DDREL * fabs(r.h)) * INFL + FLOOR;
	if (!ok(r)) *bad = 1;
	return r;
}

/* 1/b (mpfr_ui_div(1, b)).  y0 = RN(1/bh), one Newton step in dd, and an
   a posteriori bound: with rho = 1 - b y1 (dd, error < 2^-99 since
   b y1 ~ 1), |y1 - 1/b| = |rho|/|b|. */
static xv xrecip(xv b, int *bad)
{
	xv r;
	double bmin, y0, ph, pl, rh, rl, rho;
	int ex;
	if (b.l == 0.0 && b.e == 0.0 && frexp(b.h, &ex) == (b.h > 0 ? 0.5 : -0.5)) {
		r = xc(1.0 / b.h); /* a power of two: exact */
		if (!ok(r)) *bad = 1;
		return r;
	}
	bmin = fabs(b.h) * (1.0 - 0x1p-50) - 2.0 * b.e;
	if (!(bmin > 0.5 * fabs(b.h)) || !(fabs(b.h) < 0x1p500)) {
		*bad = 1;
		return b;
	}
	y0 = 1.0 / b.h;
	dd_mul(b.h, b.l, y0, 0.0, &ph, &pl);
	dd_add(1.0, 0.0, -ph, -pl, &rh, &rl);
	fast_two_sum(y0, y0 * rh, &r.h, &r.l);
	dd_mul(b.h, b.l, r.h, r.l, &ph, &pl);
	dd_add(1.0, 0.0, -ph, -pl, &rh, &rl);
	rho = fabs(rh) + 0x1p-99;
	/* propagation eb/bmin^2; dd error rho/bmin; MPFR rounding 2^-p/bmin */
	r.e = ((b.e / bmin / bmin) * INFL + rho / bmin * INFL + 0x1p-119 / bmin) * INFL + FLOOR;
	if (!ok(r)) *bad = 1;
	return r;
}

/* 1/sqrt(s) (mpfr_rec_sqrt).  y0 = RN(1/sqrt(sh)), one Newton step, and
   a posteriori: rho = 1 - s y1^2 (dd, error < 2^-98), y1 = (1 + d)/sqrt(s)
   with |d| <= 0.51 |rho| for |rho| < 2^-40. */
static xv xrsqrt(xv s, int *bad)
{
	xv r;
	double smin, y0, qh, ql, ph, pl, rh, rl, rho;
	int ex;
	if (s.l == 0.0 && s.e == 0.0 && s.h > 0.0 && frexp(s.h, &ex) == 0.5 && (ex & 1)) {
		r = xc(1.0 / sqrt(s.h)); /* 4^k: exact */
		if (!ok(r)) *bad = 1;
		return r;
	}
	smin = s.h * (1.0 - 0x1p-50) - 2.0 * s.e;
	if (!(smin > 0.5 * s.h) || !(s.h < 0x1p500)) {
		*bad = 1;
		return s;
	}
	y0 = 1.0 / sqrt(s.h);
	two_prod(y0, y0, &qh, &ql);
	dd_mul(s.h, s.l, qh, ql, &ph, &pl);
	dd_add(1.0, 0.0, -ph, -pl, &rh, &rl);
	fast_two_sum(y0, 0.5 * y0 * rh, &r.h, &r.l);
	dd_mul(r.h, r.l, r.h, r.l, &qh, &ql);
	dd_mul(s.h, s.l, qh, ql, &ph, &pl);
	dd_add(1.0, 0.0, -ph, -pl, &rh, &rl);
	rho = fabs(rh) + 0x1p-98;
	if (!(rho < 0x1p-40)) {
		*bad = 1;
		return s;
	}
	{
		const double is = 1.0 / sqrt(smin) * (1.0 + 0x1p-50);  /* >= 1/sqrt(s) */
		/* propagation 0.5 es smin^-1.5; dd 0.51 |y1| rho; MPFR 2^-p / sqrt(smin) */
		r.e = ((0.5 * s.e * is * is * is) * INFL + 0.52 * fabs(r.h) * rho + 0x1p-119 * is) * INFL + FLOOR;
	}
	if (!ok(r)) *bad = 1;
	return r;
}

/* ---- Ziv's rounding test ---- */

/* RN to double of every real within 2e of v (X and X_mpfr both are): 1 and
   *out when they all round to the same double, strictly inside its
   rounding interval; else 0. */
static int ziv_d(xv v, double *out)
{
	double a, ulp, upg, dng, off, m, t;
	int ex;
	if (!isfinite(v.h))
		return 0;
	if (v.e == 0.0) { /* exact: v = X = X_mpfr, and h = RN(v) */
		*out = v.h;
		return 1;
	}
	a = fabs(v.h);
	if (a < TINY)
		return 0;
	(void)frexp(a, &ex);
	ulp = ldexp(1.0, ex - 53);
	upg = 0.5 * ulp;                                   /* half the gap above |h| */
	dng = a == ldexp(0.5, ex) ? 0.25 * ulp : 0.5 * ulp; /* half the gap below     */
	off = v.h > 0 ? v.l : -v.l;                        /* offset away from zero  */
	m = 2.0 * v.e * INFL;
	t = off + m;
	if (t > 0 && t * (1.0 + 0x1p-50) >= upg)
		return 0;
	t = m - off;
	if (t > 0 && t * (1.0 + 0x1p-50) >= dng)
		return 0;
	*out = v.h;
	return 1;
}

/* The same for RN to float (mpfr_get_flt), into a double. */
static int ziv_f(xv v, double *out)
{
	const float f = (float)v.h;
	double a, ulp, upg, dng, off, m, t;
	int ex;
	if (!isfinite(v.h) || !isfinite(f))
		return 0;
	if (v.e == 0.0 && v.l == 0.0) { /* one rounding of an exact double */
		*out = f;
		return 1;
	}
	a = fabs((double)f);
	if (a < 0x1p-126)
		return 0;
	(void)frexp(a, &ex);
	ulp = ldexp(1.0, ex - 24);
	upg = 0.5 * ulp;
	dng = a == ldexp(0.5, ex) ? 0.25 * ulp : 0.5 * ulp;
	off = (v.h - (double)f) + v.l;         /* h - f exact (Sterbenz); one rounding */
	if (f < 0)
		off = -off;
	m = 2.0 * v.e * INFL + fabs(off) * 0x1p-52;
	t = off + m;
	if (t > 0 && t * (1.0 + 0x1p-50) >= upg)
		return 0;
	t = m - off;
	if (t > 0 && t * (1.0 + 0x1p-50) >= dng)
		return 0;
	*out = f;
	return 1;
}

/* ---- exact sums of products (reference.c's exact_sum) ---- */

/* The sum of t[0..k-1] (k <= 8), as reference.c's exact_sum returns it at
   p bits; `bound` is the double reference.c computes (it picks
   exact_sum's path), allneg0 whether every MPFR term is -0.
   Our value: VecSum passes (Ogita, Rump, Oishi 2005) leave the exact sum
   unchanged and move it into t[k-1]; the rest is added in double with an
   error <= k u sum|t[i<k-1]|, and the pair is made a dd by TwoSum.
   Passes repeat (at most 4) until that bound is below 2^-95 of the sum.
   MPFR's error: its sequential path adds k terms at p bits (error
   <= (k-1) 2^-p sum|terms| <= 4 2^-p S, S <= bound (1 + 2^-40)); it
   refines with mpfr_sum (error <= 2^-p |X|) when |X_mpfr| < 2^(E-59),
   bound in [2^(E-1), 2^E), which certainly happens when |X| <= 2^(E-61).
   An exact zero sum is +0 in both paths, -0 when every term is -0. */
static xv sum_terms(const reffast_ctx *c, double *t, int k, double bound, int allneg0, int *bad)
{
	xv r;
	double lo = 0.0, sabs = 0.0, err = 0.0, V, merr;
	int pass, i, E;
	if (!isfinite(bound)) { *bad = 1; return xc(0.0); }
	for (pass = 0; pass < 4; pass++) {
		for (i = 1; i < k; i++)
			two_sum(t[i], t[i - 1], &t[i], &t[i - 1]);
		lo = 0.0;
		sabs = 0.0;
		for (i = 0; i < k - 1; i++) {
			lo += t[i];
			sabs += fabs(t[i]);
		}
		err = (double)k * 0x1p-53 * sabs * INFL;
		if (err <= 0x1p-95 * fabs(t[k - 1]))
			break;
	}
	two_sum(t[k - 1], lo, &r.h, &r.l);
	if (sabs == 0.0 && r.h == 0.0) { /* exact zero */
		r = xc(allneg0 ? -0.0 : 0.0);
		return r;
	}
	if (bound == 0.0) { *bad = 1; return r; } /* a product underflowed in double */
	(void)frexp(bound, &E);
	V = fabs(r.h) * (1.0 + 0x1p-50) + err;
	if (V <= ldexp(1.0, E - 61))
		merr = c->up * V;
	else
		merr = 4.0 * c->up * bound * INFL + c->up * V;
	r.e = (err + merr) * INFL + FLOOR;
	if (!ok(r)) *bad = 1;
	return r;
}

/* Products a b into t (hi, lo); 0 if one underflowed. */
static int prod_terms(double a, double b, double *t)
{
	two_prod(a, b, &t[0], &t[1]);
	if (t[0] == 0.0 ? (a != 0.0 && b != 0.0) : fabs(t[0]) < 0x1p-960)
		return 0;
	return 1;
}

/* dot_exact: a.b - z (z's term only when z != 0, as in reference.c). */
static xv xdot_exact(const reffast_ctx *c, const double *a, const double *b, double z, int *bad)
{
	double t[8];
	int i, k = 6, neg0 = 1;
	for (i = 0; i < 3; i++) {
		if (!prod_terms(a[i], b[i], t + 2 * i)) { *bad = 1; return xc(0.0); }
		neg0 &= signbit(a[i] * b[i]) != 0 && a[i] * b[i] == 0.0;
	}
	if (z != 0.0) {
		t[k++] = -z;
		neg0 = 0;
	}
	return sum_terms(c, t, k, fabs(a[0] * b[0]) + fabs(a[1] * b[1]) + fabs(a[2] * b[2]) + fabs(z), neg0, bad);
}

/* norm_m1_exact: |v| - 1 from RN(v.v - 1) in double, as reference.c. */
static int norm_m1_fast(const reffast_ctx *c, const double *v, double *out)
{
	double t[8], e;
	int i, bad = 0;
	xv s;
	for (i = 0; i < 3; i++)
		if (!prod_terms(v[i], v[i], t + 2 * i))
			return 0;
	t[6] = -1.0;
	s = sum_terms(c, t, 7, v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + 1.0, 0, &bad);
	if (bad || !ziv_d(s, &e))
		return 0;
	*out = e / (sqrt(1.0 + e) + 1.0);
	return 1;
}

/* ---- the method's formula, mirroring reference.c operation by operation ---- */

/* dot(): p0 = a0 b0, p1 = a1 b1, out = p0 + p1, p0 = a2 b2, out += p0 */
static xv xdot(const xv *a, const xv *b, int *bad)
{
	xv o = xadd(xmul(a[0], b[0], bad), xmul(a[1], b[1], bad), bad);
	return xadd(o, xmul(a[2], b[2], bad), bad);
}

static void xcross(xv *o, const xv *a, const xv *b, int *bad)
{
	o[0] = xsub(xmul(a[1], b[2], bad), xmul(a[2], b[1], bad), bad);
	o[1] = xsub(xmul(a[2], b[0], bad), xmul(a[0], b[2], bad), bad);
	o[2] = xsub(xmul(a[0], b[1], bad), xmul(a[1], b[0], bad), bad);
}

static void xnormalize(xv *a, int *bad)
{
	const xv r = xrsqrt(xdot(a, a, bad), bad);
	int i;
	if (*bad)
		return;
	for (i = 0; i < 3; i++)
		a[i] = xmul(a[i], r, bad);
}

static void xset3(xv *o, double x, double y, double z) { o[0] = xc(x); o[1] = xc(y); o[2] = xc(z); }

/* frisvad_formula: a = 1/(1+z), b = -x y a, b1 = (1 - x^2 a, b, -x), b2 = (b, 1 - y^2 a, -y) */
static void xfrisvad(const xv *n, xv *b1, xv *b2, int *bad)
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
static void xduff(const xv *n, int s, int branchless, xv *r1, xv *r2, int *bad)
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

/* reference(): the exact formula of kernel k on n along branch br, into
   r1, r2 (or the rotated direction into r1 for frisvad_rotate). */
static void xreference(const study_kernel *k, int br, const double loc[3], const double nd[3],
                       xv *r1, xv *r2, int *bad)
{
	xv n[3], u[3], w[3];
	const onb_method *m = k->m;
	int i;
	xset3(n, nd[0], nd[1], nd[2]);
	if (!m) { /* frisvad_rotate, Equation 3 */
		const xv t3 = xadd(n[2], xc(1.0), bad);
		if (is_zero(t3)) {
			xset3(r1, -loc[1], -loc[0], -loc[2]);
			return;
		}
		xfrisvad(n, u, r2, bad);
		if (*bad)
			return;
		for (i = 0; i < 3; i++) {
			r1[i] = xadd(xmul(xc(loc[0]), u[i], bad), xmul(xc(loc[1]), r2[i], bad), bad);
			r1[i] = xadd(r1[i], xmul(xc(loc[2]), n[i], bad), bad);
		}
		return;
	}
	switch (k->family) {
	case FAM_NAIVE: {
		const xv d = br ? n[1] : n[0];
		for (i = 0; i < 3; i++)
			r1[i] = xmul(n[i], d, bad);
		r1[br ? 1 : 0] = xsub(xc(1.0), r1[br ? 1 : 0], bad);
		r1[br ? 0 : 1] = xneg(r1[br ? 0 : 1]);
		r1[2] = xneg(r1[2]);
		if (m->norm != ONB__NORM_NONE)
			xnormalize(r1, bad);
		xcross(r2, n, r1, bad);
		break;
	}
	case FAM_HUGHES_MOELLER:
		if (br) {
			r2[0] = xneg(n[1]); r2[1] = n[0]; r2[2] = xc(0.0);
		} else {
			r2[0] = xc(0.0); r2[1] = xneg(n[2]); r2[2] = n[1];
		}
		if (m->norm != ONB__NORM_NONE)
			xnormalize(r2, bad);
		xcross(r1, r2, n, bad);
		break;
	case FAM_FRISVAD:
		if (br) {
			xset3(r1, 0.0, -1.0, 0.0);
			xset3(r2, -1.0, 0.0, 0.0);
		} else {
			xfrisvad(n, r1, r2, bad);
		}
		break;
	case FAM_DUFF:
		if (br)
			xduff(n, -1, 0, r1, r2, bad);
		else
			xfrisvad(n, r1, r2, bad);
		break;
	case FAM_DUFF_BRANCHLESS:
		xduff(n, br ? -1 : 1, 1, r1, r2, bad);
		break;
	case FAM_STARK:
		xset3(u, br == 0, br == 1, br == 2);
		xcross(r1, n, u, bad);
		xnormalize(r1, bad);
		xcross(r2, n, r1, bad);
		break;
	case FAM_PBRT_V3:
		if (br) {
			r1[0] = xneg(n[2]); r1[1] = xc(0.0); r1[2] = n[0];
		} else {
			r1[0] = xc(0.0); r1[1] = n[2]; r1[2] = xneg(n[1]);
		}
		xnormalize(r1, bad);
		xcross(r2, n, r1, bad);
		break;
	case FAM_RTOW:
		for (i = 0; i < 3; i++)
			w[i] = n[i];
		xnormalize(w, bad);
		xset3(u, br ? 0.0 : 1.0, br ? 1.0 : 0.0, 0.0);
		xcross(r2, w, u, bad);
		xnormalize(r2, bad);
		xcross(r1, w, r2, bad);
		break;
	case FAM_TANGENT_CROSS_Z:
		u[0] = n[0]; u[1] = n[1]; u[2] = xadd(n[2], xc(1.0), bad);
		xcross(r2, n, u, bad);
		xnormalize(r2, bad);
		xcross(r1, n, r2, bad);
		break;
	default: /* a family reference.c does not know: MPFR decides */
		*bad = 1;
	}
}

/* reference.c's float_distance: representable values between a and b. */
static double float_distance(double a, double b, int prec)
{
	if (prec == PREC_FLOAT) {
		float fa = (float)a, fb = (float)b;
		uint32_t ua, ub;
		int64_t oa, ob;
		memcpy(&ua, &fa, 4);
		memcpy(&ub, &fb, 4);
		oa = (ua >> 31) ? -(int64_t)(ua & 0x7fffffffu) : (int64_t)ua;
		ob = (ub >> 31) ? -(int64_t)(ub & 0x7fffffffu) : (int64_t)ub;
		return (double)(oa > ob ? oa - ob : ob - oa);
	} else {
		uint64_t ua, ub, ma, mb;
		memcpy(&ua, &a, 8);
		memcpy(&ub, &b, 8);
		ma = ua & 0x7fffffffffffffffu;
		mb = ub & 0x7fffffffffffffffu;
		if ((ua >> 63) != (ub >> 63))
			return (double)ma + (double)mb;
		return (double)(ma > mb ? ma - mb : mb - ma);
	}
}

/* forward(): the forward error of component cv against E. */
static int xforward(xv E, double cv, int prec, sample_metrics *s, double *refd)
{
	const int p = prec == PREC_FLOAT ? 24 : 53;
	const int emin = prec == PREC_FLOAT ? -125 : -1021;
	const double eps = prec == PREC_FLOAT ? 0x1p-23 : 0x1p-52;
	double diff, rounded, bits;
	int bad = 0;
	xv D;
	if (!ziv_d(E, refd))
		return 0;
	D = xsub(E, xc(cv), &bad);      /* mpfr_sub_d: one rounding at p bits */
	if (bad || !ziv_d(D, &diff))
		return 0;
	diff = fabs(diff);
	if (diff / eps > s->abs_eps_max)
		s->abs_eps_max = diff / eps;
	if (prec == PREC_FLOAT) {
		if (!ziv_f(E, &rounded))
			return 0;
	} else {
		rounded = *refd;
	}
	if (rounded != 0.0 && fabs(rounded) >= eps) {
		int ex;
		double ulp;
		(void)frexp(rounded, &ex);
		ulp = ldexp(1.0, (ex < emin ? emin : ex) - p);
		if (diff / ulp > s->ulp_max)
			s->ulp_max = diff / ulp;
		{
			static const double small[4] = { 0.0, 1.0, 1.5849625007211562, 2.0 };
			const double dist = float_distance(cv, rounded, prec);
			bits = dist < 4.0 ? small[(int)dist] : log2(dist + 1.0);
		}
		s->bits_sum += bits;
		s->nbits++;
		if (bits > s->bits_max)
			s->bits_max = bits;
	}
	return 1;
}

/* ref_eval's first half, unchanged: the input as the kernel receives it,
   the kernel's outputs and the rotated direction. */
static void run_kernel(const study_kernel *k, int prec, const double n_in[3], const double loc[3],
                       double n[3], sample_metrics *s)
{
	int i;
	for (i = 0; i < 3; i++) {
		if (prec == PREC_FLOAT) {
			volatile float f = (float)n_in[i];
			n[i] = f;
		} else {
			n[i] = n_in[i];
		}
	}
	memset(s, 0, sizeof *s);
	s->has_basis = k->m != NULL;
	s->ncomp = k->m ? 6 : 3;
	s->branch = k->branch(k, prec, n);
	s->in_norm = NAN;
	for (i = 0; i < NDEF; i++)
		s->d[i] = NAN;
	s->defect = s->sumsq = s->det = NAN;
	if (prec == PREC_FLOAT) {
		const onb_vec3f nf = { (float)n[0], (float)n[1], (float)n[2] };
		const float x = (float)loc[0], y = (float)loc[1], z = (float)loc[2];
		onb_vec3f b1, b2, w;
		if (k->m) {
			k->basisf(nf, &b1, &b2);
			w.x = x * b1.x + y * b2.x + z * nf.x;
			w.y = x * b1.y + y * b2.y + z * nf.y;
			w.z = x * b1.z + y * b2.z + z * nf.z;
			s->out[0] = b1.x; s->out[1] = b1.y; s->out[2] = b1.z;
			s->out[3] = b2.x; s->out[4] = b2.y; s->out[5] = b2.z;
		} else {
			w = k->rotf(nf, x, y, z);
			s->out[0] = w.x; s->out[1] = w.y; s->out[2] = w.z;
		}
		s->w[0] = w.x; s->w[1] = w.y; s->w[2] = w.z;
	} else {
		const onb_vec3 nd = { n[0], n[1], n[2] };
		onb_vec3 b1, b2, w;
		if (k->m) {
			k->basis(nd, &b1, &b2);
			w.x = loc[0] * b1.x + loc[1] * b2.x + loc[2] * nd.x;
			w.y = loc[0] * b1.y + loc[1] * b2.y + loc[2] * nd.y;
			w.z = loc[0] * b1.z + loc[1] * b2.z + loc[2] * nd.z;
			s->out[0] = b1.x; s->out[1] = b1.y; s->out[2] = b1.z;
			s->out[3] = b2.x; s->out[4] = b2.y; s->out[5] = b2.z;
		} else {
			w = k->rot(nd, loc[0], loc[1], loc[2]);
			s->out[0] = w.x; s->out[1] = w.y; s->out[2] = w.z;
		}
		s->w[0] = w.x; s->w[1] = w.y; s->w[2] = w.z;
	}
}

/* |n| - 1 and, for nonunit inputs, 1/|n| = rec_sqrt(dot(n, n)) of the
   input, once per input (the sweep evaluates every kernel in a row). */
static int input_terms(reffast_ctx *c, const double n[3], int normalize_n, xv *inv)
{
	if (!c->have_last || memcmp(c->last, n, sizeof c->last) != 0) {
		memcpy(c->last, n, sizeof c->last);
		c->have_last = 1;
		c->last_ok = norm_m1_fast(c, n, &c->last_norm);
		c->last_inv_ok = -1;
	}
	if (!c->last_ok)
		return 0;
	if (normalize_n) {
		if (c->last_inv_ok < 0) {
			int bad = 0;
			xv nv[3], r;
			xset3(nv, n[0], n[1], n[2]);
			r = xrsqrt(xdot(nv, nv, &bad), &bad);
			c->inv_h = r.h; c->inv_l = r.l; c->inv_e = r.e;
			c->last_inv_ok = !bad;
		}
		if (!c->last_inv_ok)
			return 0;
		inv->h = c->inv_h; inv->l = c->inv_l; inv->e = c->inv_e;
	}
	return 1;
}

/* b.n (or (b.n)/|n| against the normalized input), rounded to double. */
static int defect_dot(const reffast_ctx *c, const double *a, const double *b, double z,
                      int normalize_n, xv inv, double *out)
{
	int bad = 0;
	xv x = xdot_exact(c, a, b, z, &bad);
	if (normalize_n)
		x = xmul(x, inv, &bad);
	return !bad && ziv_d(x, out);
}

/* The orthonormality defect and the handedness, as ref_eval. */
static int basis_defects(const reffast_ctx *c, const study_kernel *k, const double n[3],
                         int normalize_n, xv inv, sample_metrics *s)
{
	long double det;
	int i;
	if (!norm_m1_fast(c, s->out, &s->d[DEF_N1]) || !norm_m1_fast(c, s->out + 3, &s->d[DEF_N2]) ||
	    !defect_dot(c, s->out, n, 0.0, normalize_n, inv, &s->d[DEF_D1N]) ||
	    !defect_dot(c, s->out + 3, n, 0.0, normalize_n, inv, &s->d[DEF_D2N]) ||
	    !defect_dot(c, s->out, s->out + 3, 0.0, 0, inv, &s->d[DEF_D12]))
		return 0;
	s->defect = 0.0;
	s->sumsq = 0.0;
	for (i = 0; i < NDEF; i++) {
		if (fabs(s->d[i]) > s->defect)
			s->defect = fabs(s->d[i]);
		s->sumsq += s->d[i] * s->d[i];
	}
	{
		long double b1x = s->out[0], b1y = s->out[1], b1z = s->out[2];
		long double b2x = s->out[3], b2y = s->out[4], b2z = s->out[5];
		det = b1x * (b2y * (long double)n[2] - b2z * (long double)n[1])
		    + b1y * (b2z * (long double)n[0] - b2x * (long double)n[2])
		    + b1z * (b2x * (long double)n[1] - b2y * (long double)n[0]);
	}
	s->det = (double)det;
	s->wrong_hand = !(s->det * k->m->handedness > 0.0);
	return 1;
}

int reffast_eval(reffast_ctx *c, const study_kernel *k, int prec, const double n_in[3],
                 const double loc[3], int normalize_n, sample_metrics *s)
{
	double n[3];
	xv inv = { 1.0, 0.0, 0.0 }, r1[3], r2[3];
	int i, bad = 0;
	run_kernel(k, prec, n_in, loc, n, s);
	if (!input_terms(c, n, normalize_n, &inv))
		return 0;
	s->in_norm = c->last_norm;
	for (i = 0; i < s->ncomp; i++)
		if (!isfinite(s->out[i]))
			break;
	if (i < s->ncomp || !isfinite(s->w[0]) || !isfinite(s->w[1]) || !isfinite(s->w[2])) {
		s->nonfinite = 1;
		s->ulp_max = s->abs_eps_max = s->bits_sum = s->bits_max = NAN;
		s->dir_norm = s->dir_cos = NAN;
		for (i = 0; i < 6; i++)
			s->ref[i] = NAN;
		return 1;
	}
	if (k->m && !basis_defects(c, k, n, normalize_n, inv, s))
		return 0;

	/* Forward error against the kernel's own formula. */
	xreference(k, s->branch, loc, n, r1, r2, &bad);
	if (bad)
		return 0;
	s->ulp_max = s->abs_eps_max = s->bits_sum = s->bits_max = 0.0;
	for (i = 0; i < 3; i++)
		if (!xforward(r1[i], s->out[i], prec, s, &s->ref[i]))
			return 0;
	if (k->m)
		for (i = 0; i < 3; i++)
			if (!xforward(r2[i], s->out[3 + i], prec, s, &s->ref[3 + i]))
				return 0;

	/* Direction error: | |w| - 1 | and | w.n - z |. */
	if (!norm_m1_fast(c, s->w, &s->dir_norm))
		return 0;
	s->dir_norm = fabs(s->dir_norm);
	{
		const double z = prec == PREC_FLOAT ? (double)(float)loc[2] : loc[2];
		xv x = xdot_exact(c, s->w, n, normalize_n ? 0.0 : z, &bad);
		if (normalize_n)
			x = xsub(xmul(x, inv, &bad), xc(z), &bad);
		if (bad || !ziv_d(x, &s->dir_cos))
			return 0;
		s->dir_cos = fabs(s->dir_cos);
	}
	return 1;
}
