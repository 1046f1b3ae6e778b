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
 * Speed (each step measured, none changes a stored bit):
 *  - one formula per input and family: the kernels of a family (naive's
 *    four normalizations, frisvad and frisvad_max, duff_branchless and the
 *    float-only duff_wide and duff_comp...) share the formula's value, its
 *    roundings and its floor (fentry, formula());
 *  - the shape figures (defects, |w| - 1, w.n - z) are decided first by a
 *    lean dot (fdot_round: three TwoSums for floats, two TwoSum levels over
 *    TwoProd for doubles), four lanes at a time in AVX vectors where the
 *    build has them (fdot4, same operations lane by lane); the general
 *    VecSum path decides what they leave;
 *  - the hot helpers are inlined and Ziv's test has no branch on signs.
 *
 * TwoProd uses fma when this file is compiled with FMA (the Makefile
 * builds it with -mfma on x86_64, with -ffp-contract=off kept so that no
 * other expression is contracted); Dekker's product otherwise.
 */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <stdint.h>
#include <float.h>
#if defined(__GNUC__) && defined(__AVX__) && defined(__FMA__)
#include <immintrin.h>
#endif
#include "reference/reffast.h"
#include "arith/pair.h"

/* The formula of a family on one input, shared by every kernel of that
   family on that input (the sweep evaluates all kernels of an input in a
   row): its value with bounds and its floor figures.  The key is the
   input (n, loc, precision, normalize_n) plus the formula: family, branch
   and whether it normalizes (naive and hughes_moeller have a _nonorm). */
#define FCACHE 32
/* The context is shared by both instantiations (xv_pd, xv_pl: pair.h),
   so its entries hold either kind. */
typedef struct {
	const study_family *fam;  /* the formula's family, and its key in it (formula_key) */
	int key;
	int ok;                   /* the formula's bounds hold (else MPFR decides) */
	int floor_ok;             /* floor figures determined                      */
	union { xv_pd d[6]; xv_pl l[6]; } xr; /* r1[3], r2[3] (XR: this file's) */
	double floor, floor_dir_norm, floor_dir_cos;
	/* per component, what the forward error takes from the formula alone
	   (E rounded to double and to the format, see xforward): 0 not yet,
	   1 done, 2 done with E's double undetermined (ref[] left to MPFR),
	   -1 MPFR must decide */
	signed char fwd[6];
	double refd[6], rounded[6];
	double t4[6][4];          /* E as four doubles (to_e4, double only)     */
} fentry;

/* The samples decided on this input, by the bits of the kernel's outputs
   and direction (out[], w[]): a kernel that returns the same bits as an
   earlier one on the same input has the same shape figures (defects, det,
   direction errors: functions of those bits, n and loc alone), and, when
   its formula is the same too (frisvad and frisvad_max almost always;
   duff_branchless, duff_wide and duff_comp; the naive and hughes_moeller
   normalizations), every figure. */
#define MEMO 48
typedef struct {
	uint64_t hash;            /* of out[], w[] and has_basis                */
	const study_family *fam;  /* the formula's family and key (fentry)        */
	int key;
	int rc;                   /* what reffast_eval returned for it          */
	sample_metrics smp;
} memo_entry;

struct reffast_ctx {
	int prec;                 /* MPFR precision p of the reference mirrored */
	double key_n[3], key_loc[3]; /* the input the formula cache holds        */
	int key_prec, key_norm, nf;
	fentry fc[FCACHE];
	int nmemo;
	memo_entry memo[MEMO];
	double up;                /* 2^-p */
	double last[3];           /* cache: the last input, its |n|-1 and 1/|n| */
	double last_norm;
	int have_last, last_ok, last_inv_ok;
	long double inv_h, inv_l;
	double inv_e;
};


/* The two instantiations of everything below (see the top of the pair
   arithmetic): reffast.c with pairs of long doubles, reffast_f.c (this
   file again with REFFAST_PAIR_DOUBLE) with pairs of doubles. */
int reffast_eval_pairs_of_doubles(reffast_ctx *c, const study_kernel *k, int prec, const double n_in[3],
                                  const double loc[3], int normalize_n, sample_metrics *s);
int reffast_eval_pairs_of_long_doubles(reffast_ctx *c, const study_kernel *k, int prec, const double n_in[3],
                                       const double loc[3], int normalize_n, sample_metrics *s);

#ifndef REFFAST_PAIR_DOUBLE
int reffast_usable(int ref_bits, const char **why)
{
#if LDBL_MANT_DIG != 64
	*why = "the fast reference needs the x87 80-bit long double";
	(void)ref_bits;
	return 0;
#endif
	{
		/* the long double must round at 64 bits at run time too: valgrind,
		   for one, emulates x87 arithmetic in double */
		volatile long double one = 1.0L, tiny = 0x1p-63L;
		if (one + tiny == one) {
			*why = "long double arithmetic does not carry 64 bits here (an emulator?)";
			return 0;
		}
	}
	if (ref_bits < 127) {
		*why = "the fast reference's bounds assume an MPFR reference of at least 127 bits";
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

/* Float inputs take the pairs of doubles, double inputs the long doubles. */
int reffast_eval(reffast_ctx *c, const study_kernel *k, int prec, const double n_in[3],
                 const double loc[3], int normalize_n, sample_metrics *s)
{
	if (prec == PREC_FLOAT)
		return reffast_eval_pairs_of_doubles(c, k, prec, n_in, loc, normalize_n, s);
	return reffast_eval_pairs_of_long_doubles(c, k, prec, n_in, loc, normalize_n, s);
}
#endif

#include "arith/pair_kit.h"  /* the pair arithmetic and Ziv's test */

/* ---- exact sums of products (reference.c's exact_sum) ---- */

/* The sum of t[0..k-1] (k <= 8), as reference.c's exact_sum returns it at
   p bits; `bound` is the double reference.c computes (it picks
   exact_sum's path), allneg0 whether every MPFR term is -0.
   Our value: VecSum passes (Ogita, Rump, Oishi 2005) leave the exact sum
   unchanged and move it into t[k-1]; the rest is added in double with an
   error <= k u sum|t[i<k-1]|, and the pair is made a dd by TwoSum.
   Passes repeat (at most 4) until that bound is below 2^-95 of the sum;
   it is 0 when the last pass's TwoSums were all exact.  Zero
   terms are dropped first: they change no partial sum, ours or MPFR's.
   MPFR's error: its sequential path adds k terms at p bits (error
   <= (k-1) 2^-p sum|terms| <= 4 2^-p S, S <= bound (1 + 2^-40)); it
   refines with mpfr_sum (error <= 2^-p |X|) when |X_mpfr| < 2^(E-59),
   bound in [2^(E-1), 2^E), which certainly happens when |X| <= 2^(E-61).
   An exact zero sum is +0 in both paths, -0 when every term is -0. */
HOT xv sum_terms(const reffast_ctx *c, double *t, int k, double bound, int allneg0, int *bad)
{
	xv r;
	double lo = 0.0, sabs = 0.0, err = 0.0, merr, orig[8];
	int pass, i, m = 0, exact = 1;
	if (!isfinite(bound)) { *bad = 1; return xc(0.0); }
	/* zero terms change no partial sum, here or in MPFR: drop them (the
	   low parts of products of floats, which are exact in double) */
	for (i = 0; i < k; i++)
		if (t[i] != 0.0) {
			if (fabs(t[i]) < 0x1p-1000) { *bad = 1; return xc(0.0); }
			orig[m] = t[m] = t[i];
			m++;
		}
	if (m == 0)
		return xc(allneg0 ? -0.0 : 0.0); /* exact zero: +0, -0 when every term is -0 */
	for (pass = 0; pass < 4; pass++) {
		for (i = 1; i < m; i++)
			two_sum(t[i], t[i - 1], &t[i], &t[i - 1]);
		/* lo = t[0] + ... + t[m-2] by TwoSum, noting whether it is exact */
		lo = 0.0;
		sabs = 0.0;
		exact = 1;
		for (i = 0; i < m - 1; i++) {
			double q;
			two_sum(lo, t[i], &lo, &q);
			exact &= q == 0.0;
			sabs += fabs(t[i]);
		}
		err = exact ? 0.0 : (double)m * 0x1p-53 * sabs * INFL;
		if (err <= 0x1p-95 * fabs(t[m - 1]))
			break;
	}
	{
		double sh, sl;
		two_sum(t[m - 1], lo, &sh, &sl);
		fast_two_sum_l(sh, sl, &r.h, &r.l); /* normalized as a pair of long doubles */
	}
	if (sabs == 0.0 && r.h == 0.0)
		return xc(0.0); /* an exact zero sum of nonzero terms: +0 in RN, IEEE and MPFR */
	if (bound == 0.0) { /* a product underflowed in double */
		*bad = 1;
		r.e = 0.0;
		return r;
	}
	{
		const int E = dexp(bound) + 1; /* bound in [2^(E-1), 2^E) */
		int minlsb = 100000;
		if (err == 0.0) {
			for (i = 0; i < m; i++)
				if (dlsb(orig[i]) < minlsb)
					minlsb = dlsb(orig[i]);
		}
		if (err == 0.0 && E + 1 - minlsb <= c->prec) {
			/* every partial sum of MPFR's terms (at most bound (1 + 2^-50) <
			   2^(E+1), lowest bit at or above 2^minlsb) fits p bits: MPFR's
			   sum is exact, and so is ours (no TwoSum above lost a bit) */
			merr = 0.0;
		} else {
			const double V = (double)PFABS(r.h) * (1.0 + 0x1p-50) + err;
			if (V <= pow2(E - 61))
				merr = c->up * V;
			else
				merr = 4.0 * c->up * bound * INFL + c->up * V;
		}
	}
	r.e = err == 0.0 && merr == 0.0 ? 0.0 : (err + merr) * INFL + FLOOR;
	if (!ok(r)) *bad = 1;
	return r;
}

/* Products a b into t (hi, lo); 0 if one underflowed. */
HOT int prod_terms(double a, double b, double *t)
{
	two_prod(a, b, &t[0], &t[1]);
	if (t[0] == 0.0 ? (a != 0.0 && b != 0.0) : fabs(t[0]) < 0x1p-960)
		return 0;
	return 1;
}

/* dot_exact: a.b - z (z's term only when z != 0, as in reference.c). */
HOT xv xdot_exact(const reffast_ctx *c, const double *a, const double *b, double z, int *bad)
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

/* The exact zero sum of a dot's terms, as MPFR's exact sum gives it: -0
   when every term is -0 (the products p0, p1, p2; z's term counts only
   when z != 0), else +0. */
static inline double zero_sum(double p0, double p1, double p2, double z)
{
	return z == 0.0 && p0 == 0.0 && p1 == 0.0 && p2 == 0.0 && signbit(p0) && signbit(p1) && signbit(p2) ? -0.0
	                                                                                                   : 0.0;
}

/* The lean dot: a.b - z as a value with its bound (an xv: 1), or 0 when
   the general path must take it (an underflow; X near zero but not
   exactly zero).  For vectors of floats (the float precision's outputs,
   inputs and directions; z = 0, 1 or a float) the products are exact in
   double (48 bits, no underflow above 2^-298), and so in MPFR.  Three
   TwoSums in MPFR's order leave X = s3 + e1 + e2 + e3 exactly:
   lo = RN(RN(e1 + e2) + e3) is within 2u (|e1| + |e2| + |e3|) of their
   sum, and MPFR's value within 3 2^-p S + 2^-p |X| of X (sequential sums
   at p bits, S = sum of |terms|; or mpfr_sum, 2^-p |X|); the bound of
   s3 + lo covers both (an exact X = s3 passes Ziv's test with it too). */
#ifdef REFFAST_PAIR_DOUBLE
HOT int fdot_pair(const reffast_ctx *c, const double *a, const double *b, double z, xv *v)
{
	const double p0 = a[0] * b[0], p1 = a[1] * b[1], p2 = a[2] * b[2];
	double s1, e1, s2, e2, s3, e3, S, E;
	two_sum(p0, p1, &s1, &e1);
	two_sum(s1, p2, &s2, &e2);
	two_sum(s2, -z, &s3, &e3);
	if (s3 == 0.0 && e1 == 0.0 && e2 == 0.0 && e3 == 0.0) {
		*v = xc(zero_sum(p0, p1, p2, z)); /* X = 0 exactly, and in MPFR (its sums are exact) */
		return 1;
	}
	if (s3 == 0.0 || !isfinite(s3))
		return 0;
	/* no branch on whether the e's are zero (data-dependent, so often
	   mispredicted): an exact X = s3 passes Ziv's test as well */
	S = (fabs(p0) + fabs(p1) + fabs(p2) + fabs(z)) * INFL;
	E = 2.0 * 0x1p-53 * (fabs(e1) + fabs(e2) + fabs(e3)) * INFL;
	two_sum(s3, (e1 + e2) + e3, &v->h, &v->l);
	v->e = (E + 3.0 * c->up * S + c->up * 2.0 * fabs(v->h)) * INFL + FLOOR;
	return 1;
}
#else
/* The same for vectors of doubles (the double precision's): products by
   TwoProd, p_i + t_i = a_i b_i exactly (no underflow: checked), exact in
   MPFR too (106 bits).  Two levels of TwoSums: s3 + e1 + e2 + e3 = the
   sum of p0, p1, p2, -z (MPFR's order), then u5 + f1 + ... + f5 = t0 +
   t1 + t2 + e1 + e2 + e3, so X = s3 + u5 + sum f exactly.  F = the f's
   added plainly: error <= 4u sum|f| <= 4u * u * 6u S, about 2^-150 S,
   far below a defect's ulp (defects of double outputs sit near 2^-53 S).
   MPFR's error as in the float case. */
HOT int fdot_pair(const reffast_ctx *c, const double *a, const double *b, double z, xv *v)
{
	double p[3], t[3], s1, e1, s2, e2, s3, e3, u, f[5], F, h, l, S;
	int i;
	for (i = 0; i < 3; i++) {
		two_prod(a[i], b[i], &p[i], &t[i]);
		if (p[i] == 0.0 ? (a[i] != 0.0 && b[i] != 0.0) : fabs(p[i]) < 0x1p-960)
			return 0; /* underflow: TwoProd is not exact */
	}
	two_sum(p[0], p[1], &s1, &e1);
	two_sum(s1, p[2], &s2, &e2);
	two_sum(s2, -z, &s3, &e3);
	if (!isfinite(s3))
		return 0;
	two_sum(t[0], t[1], &u, &f[0]);
	two_sum(u, t[2], &u, &f[1]);
	two_sum(u, e1, &u, &f[2]);
	two_sum(u, e2, &u, &f[3]);
	two_sum(u, e3, &u, &f[4]);
	F = (((f[0] + f[1]) + f[2]) + f[3]) + f[4];
	two_sum(s3, u, &h, &l);
	S = (fabs(p[0]) + fabs(p[1]) + fabs(p[2]) + fabs(z)) * INFL;
	if (f[0] == 0.0 && f[1] == 0.0 && f[2] == 0.0 && f[3] == 0.0 && f[4] == 0.0) {
		/* X = h + l exactly.  At h = 0, X = 0, in MPFR too (its sums of the
		   exact products are exact).  Otherwise X is decided as an exact
		   value when MPFR's sum is exact too, all its partial sums fitting
		   p bits (as in sum_terms): a defect of doubles often has 54 bits,
		   and then lies exactly on a midpoint. */
		if (h == 0.0) {
			*v = xc(zero_sum(p[0], p[1], p[2], z));
			return 1;
		}
		{
			const double terms[7] = { p[0], t[0], p[1], t[1], p[2], t[2], z };
			int minlsb = 100000;
			for (i = 0; i < 7; i++)
				if (terms[i] != 0.0 && dlsb(terms[i]) < minlsb)
					minlsb = dlsb(terms[i]);
			if (dexp(S) + 2 - minlsb <= c->prec) {
				two_sum_l(h, l, &v->h, &v->l); /* 54 bits or so: exact in a long double */
				v->e = 0.0;
				return 1;
			}
		}
	}
	if (h == 0.0)
		return 0; /* near zero, not exactly: the general path's */
	{
		/* (h, l + F) within u|l + F| of X; normalized by TwoSum (under heavy
		   cancellation F reaches an ulp of h) */
		double vh, vl;
		two_sum(h, l + F, &vh, &vl);
		v->h = vh;
		v->l = vl;
	}
	v->e = ((4.0 * 0x1p-53 * (fabs(f[0]) + fabs(f[1]) + fabs(f[2]) + fabs(f[3]) + fabs(f[4])) +
	         0x1p-53 * fabs(l + F)) * INFL + 3.0 * c->up * S + c->up * 2.0 * fabs(h)) * INFL + FLOOR;
	return 1;
}
#endif

/* RN(a.b - z) in double from the lean dot: 1 and *out when decided, 0
   when the general path must decide. */
HOT int fdot_round(const reffast_ctx *c, const double *a, const double *b, double z, double *out)
{
	xv v;
	return fdot_pair(c, a, b, z, &v) && ziv_d(v, out);
}

/* Four fdot_round of floats at once, in AVX vectors (GCC's vector
   extension; contraction stays off for them too): lane j is a_j . b_j -
   z_j, computed by exactly the scalar function's operations, so a lane
   decides exactly when fdot_round would and to the same value.  Returns
   the mask of the lanes decided (bit j), their values in out[j]. */
#if defined(__GNUC__) && defined(__AVX__) && (defined(REFFAST_PAIR_DOUBLE) || defined(__FMA__))
#define REFFAST_VEC 1
typedef double v4d __attribute__((vector_size(32)));
typedef long long v4i __attribute__((vector_size(32)));
typedef float v4f __attribute__((vector_size(16)));
#define VABS(x) ((v4d)((v4i)(x) & 0x7fffffffffffffffLL))
#define VTWO_SUM(a, b, s, t) do { const v4d x_ = (a) + (b), z_ = x_ - (a); \
	(t) = ((a) - (x_ - z_)) + ((b) - z_); (s) = x_; } while (0)

/* ziv() of four pairs (h, l) with bounds e > 0 at 53 or 24 bits: the
   lanes that fail (all bits set; NaN and infinite lanes fail), the
   candidates in *out.  The same
   operations as the scalar test's inexact branch, lane by lane. */
static v4i vziv(v4d h, v4d l, v4d e, int bits, v4d *out)
{
	const v4d c = bits == 24 ? __builtin_convertvector(__builtin_convertvector(h, v4f), v4d) : h;
	const v4i cb = (v4i)c;
	const v4d off = (v4d)((v4i)((h - c) + l) ^ (cb & (long long)0x8000000000000000ULL));
	const v4d m = 2.0 * e * INFL + VABS(off) * OFF_SLOP;
	const v4d ulp = (v4d)((cb & 0x7ff0000000000000LL) - ((long long)(bits - 1) << 52));
	const v4d upg = 0.5 * ulp;
	const v4d dng = upg - (v4d)((v4i)(0.25 * ulp) & ((cb & 0x000fffffffffffffLL) == 0));
	*out = c;
	return ~((VABS(h) <= DBL_MAX) & (VABS(c) <= DBL_MAX)) | (VABS(c) < (bits == 24 ? 0x1p-126 : TINY)) |
	       ((off + m) * (1.0 + 0x1p-50) >= upg) | ((m - off) * (1.0 + 0x1p-50) >= dng);
}

/* The lanes that did not fail: their values into out[j], bit j of the mask. */
static int vlanes(v4i fail, v4d r, double out[4])
{
	int j, mask = 0;
	for (j = 0; j < 4; j++)
		if (!fail[j]) {
			out[j] = r[j];
			mask |= 1 << j;
		}
	return mask;
}

#ifdef REFFAST_PAIR_DOUBLE
static inline v4i fdot4(const reffast_ctx *c, const v4d a[3], const v4d b[3], v4d z, v4d *out)
{
	const v4d p0 = a[0] * b[0], p1 = a[1] * b[1], p2 = a[2] * b[2];
	v4d s1, e1, s2, e2, s3, e3, h, l, S, E, e, r;
	v4i fail;
	VTWO_SUM(p0, p1, s1, e1);
	VTWO_SUM(s1, p2, s2, e2);
	VTWO_SUM(s2, -z, s3, e3);
	S = (VABS(p0) + VABS(p1) + VABS(p2) + VABS(z)) * INFL;
	E = 2.0 * 0x1p-53 * (VABS(e1) + VABS(e2) + VABS(e3)) * INFL;
	VTWO_SUM(s3, (e1 + e2) + e3, h, l);
	e = (E + 3.0 * c->up * S + c->up * 2.0 * VABS(h)) * INFL + FLOOR;
	fail = (s3 == 0.0) | ~(VABS(s3) <= DBL_MAX) | vziv(h, l, e, 53, &r); /* NaN fails too */
	/* an exact zero fails here and is decided by the scalar fdot_round
	   (deciding it here too measured 10% slower: the same figures) */
	*out = r;
	return fail;
}
#else
/* The double precision's fdot_round, four lanes (TwoProd by the fma
   instruction); a lane that fails here (exact midpoints among them) takes
   the scalar function, which decides those too. */
static inline v4i fdot4(const reffast_ctx *c, const v4d a[3], const v4d b[3], v4d z, v4d *out)
{
	v4d p[3], t[3], s1, e1, s2, e2, s3, e3, u, f0, f1, f2, f3, f4, F, h, l, vh, vl, S, e, r;
	v4i fail = (v4i){ 0, 0, 0, 0 };
	int i;
	for (i = 0; i < 3; i++) {
		p[i] = a[i] * b[i];
		t[i] = (v4d)_mm256_fmadd_pd((__m256d)a[i], (__m256d)b[i], (__m256d)-p[i]);
		fail |= ((p[i] == 0.0) & (a[i] != 0.0) & (b[i] != 0.0)) | ((p[i] != 0.0) & (VABS(p[i]) < 0x1p-960));
	}
	VTWO_SUM(p[0], p[1], s1, e1);
	VTWO_SUM(s1, p[2], s2, e2);
	VTWO_SUM(s2, -z, s3, e3);
	VTWO_SUM(t[0], t[1], u, f0);
	VTWO_SUM(u, t[2], u, f1);
	VTWO_SUM(u, e1, u, f2);
	VTWO_SUM(u, e2, u, f3);
	VTWO_SUM(u, e3, u, f4);
	F = (((f0 + f1) + f2) + f3) + f4;
	VTWO_SUM(s3, u, h, l);
	S = (VABS(p[0]) + VABS(p[1]) + VABS(p[2]) + VABS(z)) * INFL;
	VTWO_SUM(h, l + F, vh, vl);
	e = ((4.0 * 0x1p-53 * (VABS(f0) + VABS(f1) + VABS(f2) + VABS(f3) + VABS(f4)) + 0x1p-53 * VABS(l + F)) * INFL +
	     3.0 * c->up * S + c->up * 2.0 * VABS(h)) * INFL + FLOOR;
	fail |= ~(VABS(s3) <= DBL_MAX) | (h == 0.0) | vziv(vh, vl, e, 53, &r);
	*out = r;
	return fail;
}
#endif

/* |v| - 1 = e / (sqrt(1 + e) + 1) from e = v.v - 1 in the lanes of
   `lanes` (norm_m1_fast's operations lane by lane: IEEE sqrt and division
   round the same), e itself in the others. */
static inline v4d vnorm_m1(v4d e, v4i lanes)
{
	const v4d one = { 1.0, 1.0, 1.0, 1.0 };
	return (v4d)(((v4i)(e / (__builtin_ia32_sqrtpd256(one + e) + one)) & lanes) | ((v4i)e & ~lanes));
}

/* The lanes of shape() below, decided in two vectors: bits 0-4 the five
   defects of b (0, 1 and 5 are |v| - 1 already), 5 |w| - 1, 6 w.n - z;
   lanes against n/|n| (normalize_n) are left to the scalar path. */
static int shape_vec(const reffast_ctx *c, int has_basis, const double b[6], const double n[3],
                     const double w[3], double z, int normalize_n, double v[8])
{
	int mask;
	const v4d zb = { 0.0, 1.0, z, 0.0 };
	const v4i normb = { 0, -1, 0, 0 }, norma = { -1, -1, 0, 0 };
	v4d a[3], bb[3], ra, rb;
	v4i fa, fb;
	int i;
	for (i = 0; i < 3; i++) {
		const v4d ai = { b[i], w[i], w[i], 0.0 }, bi = { b[3 + i], w[i], n[i], 0.0 };
		a[i] = ai; bb[i] = bi;
	}
	fb = fdot4(c, a, bb, zb, &rb);
	mask = vlanes(fb, vnorm_m1(rb, normb), v + 4) << 4;
	if (has_basis) {
		const v4d za = { 1.0, 1.0, 0.0, 0.0 };
		for (i = 0; i < 3; i++) {
			const v4d ai = { b[i], b[3 + i], b[i], b[3 + i] }, bi = { b[i], b[3 + i], n[i], n[i] };
			a[i] = ai; bb[i] = bi;
		}
		fa = fdot4(c, a, bb, za, &ra);
		mask |= vlanes(fa, vnorm_m1(ra, norma), v);
	} else {
		mask &= ~(1 << 4);
	}
	mask &= 0x7f;
	if (normalize_n)
		mask &= ~(4 | 8 | 64);
	return mask;
}
#endif

/* norm_m1_exact: |v| - 1 from RN(v.v - 1) in double, as reference.c. */
HOT int norm_m1_fast(const reffast_ctx *c, const double *v, double *out)
{
	double t[8], e;
	int i, bad = 0;
	xv s;
	if (!fdot_round(c, v, v, 1.0, &e)) {
		for (i = 0; i < 3; i++)
			if (!prod_terms(v[i], v[i], t + 2 * i))
				return 0;
		t[6] = -1.0;
		s = sum_terms(c, t, 7, v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + 1.0, 0, &bad);
		if (bad || !ziv_d(s, &e))
			return 0;
	}
	*out = e / (sqrt(1.0 + e) + 1.0);
	return 1;
}

/* reference(): the exact formula of kernel k on n along branch br, into
   r1, r2 (or the rotated direction into r1 for frisvad_rotate), by its
   family's pair formula (src/families/). */
static void xreference(const study_kernel *k, int br, const double loc[3], const double nd[3],
                       xv *r1, xv *r2, int *bad)
{
	xv n[3];
	xset3(n, nd[0], nd[1], nd[2]);
#ifdef REFFAST_PAIR_DOUBLE
	k->fam->pair_d(k->m, br, loc, n, r1, r2, bad);
#else
	k->fam->pair_l(k->m, br, loc, n, r1, r2, bad);
#endif
}

/* forward(): the forward error of component cv against E.  1 when every
   figure is determined, 2 when ref[] is not (then NaN), 0 when MPFR must
   decide.  A diff = |RN(E - cv)| that stays undetermined (E - cv within
   MPFR's rounding noise of a double, as when the kernel is exact and
   MPFR's E carries 2^-127 of noise) enters only the maxima abs_eps_max
   and ulp_max: its upper bound goes to undet[0] (in eps) and undet[1]
   (in ulps), and the caller checks that neither reaches the maxima. */
/* xforward's figures from its parts: diff = RN(E - cv) when have_diff,
   else its bound `upper`; rounded = E rounded to the format (0 when E is
   tiny). */
static void fwd_accumulate(int prec, double cv, int have_diff, double diff, double upper, double rounded,
                           sample_metrics *s, double undet[2])
{
	const int p = prec == PREC_FLOAT ? 24 : 53;
	const int emin = prec == PREC_FLOAT ? -125 : -1021;
	const double eps = prec == PREC_FLOAT ? 0x1p-23 : 0x1p-52;
	double bits;
	if (have_diff) {
		/* x / 2^k and x * 2^-k are the same correctly rounded value */
		const double d = fabs(diff) * (prec == PREC_FLOAT ? 0x1p23 : 0x1p52);
		diff = fabs(diff);
		s->abs_eps_max = d > s->abs_eps_max ? d : s->abs_eps_max;
	} else if (upper / eps > undet[0]) {
		undet[0] = upper / eps;
	}
	if (rounded != 0.0 && fabs(rounded) >= eps) {
		int ex = dexp(rounded) + 1; /* frexp's exponent */
		ex = (ex < emin ? emin : ex) - p;
		if (!have_diff) {
			const double ulp = pow2(ex);
			if (upper / ulp > undet[1])
				undet[1] = upper / ulp;
		} else {
			const double d = diff * pow2(-ex); /* diff / ulp */
			s->ulp_max = d > s->ulp_max ? d : s->ulp_max;
		}
		{
			static const double small[4] = { 0.0, 1.0, 1.5849625007211562, 2.0 };
			const double dist = ref_float_distance(cv, rounded, prec);
			bits = dist < 4.0 ? small[(int)dist] : log2(dist + 1.0);
		}
		s->bits_sum += bits;
		s->nbits++;
		s->bits_max = bits > s->bits_max ? bits : s->bits_max;
	}
}

/* The parts of a forward error that depend on E alone: *refd (E to
   double; NaN when undetermined but E is tiny) and *rounded (E to the
   format; 0 when tiny).  1, 2 (ref[] left to MPFR) or -1 (MPFR decides). */
static int fwd_parts(xv E, int prec, double *refd, double *rounded)
{
	const double eps = prec == PREC_FLOAT ? 0x1p-23 : 0x1p-52;
	/* |E| < eps/2 for sure: E rounds below eps, no ulp or bits from it */
	const int tiny = (double)PFABS(E.h) * (1.0 + 0x1p-50) + 2.0 * E.e * INFL < 0.5 * eps;
	int rc = 1;
	if (!ziv_d(E, refd)) {
		/* The exact double of E is undetermined (an exact zero that MPFR
		   computes as rounding noise, say).  When tiny, it takes part in
		   no other figure: only ref[] is left to MPFR, and only if the
		   sample is kept among the worst. */
		if (!tiny)
			return -1;
		*refd = NAN;
		rc = 2;
	}
	if (tiny) {
		*rounded = 0.0;
	} else if (prec == PREC_FLOAT) {
		if (!ziv_f(E, rounded))
			return -1;
	} else {
		*rounded = *refd;
	}
	return rc;
}

/* An upper bound of |X| for a difference X within e of h + l (|l| at
   most an ulp of h): the bound an undetermined diff leaves in undet[]. */
static inline double diff_upper(double h, double e)
{
	return (fabs(h) * (1.0 + 0x1p-50) + 2.0 * e * INFL) * (1.0 + 0x1p-50);
}

/* The forward error of component value cv against E, from E's parts
   (fwd_parts): 1, 2 (ref[] left to MPFR) or 0 (MPFR decides). */
#ifndef REFFAST_PAIR_DOUBLE
/* The double precision's forward error in SSE doubles instead of x87
   pairs: E = h + l as four doubles, h1 = RN(h), h2 = h - h1, l1 = RN(l),
   l2 = l - l1 (each remainder exact in the long double and at most 11
   bits: a double), so h1 + h2 + l1 + l2 = E exactly.  Once per component
   and formula (fentry). */
static void to_e4(xv E, double t[4])
{
	t[0] = (double)E.h;
	t[1] = (double)(E.h - (ld)t[0]);
	t[2] = (double)E.l;
	t[3] = (double)(E.l - (ld)t[2]);
}

/* Ziv's test at 53 bits on an exact pair of doubles h + l (|l| <= ulp(h)/2)
   with a bound e > 0: ziv()'s inexact branch, whose candidate RN(h) is h. */
static inline int dziv53(double h, double l, double e, double *out)
{
	const double a = fabs(h);
	double ulp, off, m;
	if (!(a <= DBL_MAX) || a < TINY)
		return 0;
	ulp = pow2(dexp(a) - 52);
	off = l * copysign(1.0, h);
	m = 2.0 * e * INFL + fabs(off) * 0x1p-52;
	if ((off + m) * (1.0 + 0x1p-50) >= 0.5 * ulp || (m - off) * (1.0 + 0x1p-50) >= (dpow2(a) ? 0.25 : 0.5) * ulp)
		return 0;
	*out = h;
	return 1;
}

/* RN(E - cv) for an inexact E (bound e) from its four doubles t (to_e4):
   TwoSum s + r = h1 - cv, a + b = s + h2 and c + d = a + l1 exactly (the
   large parts first: E - cv cancels most of h1), q = ((b + r) + d) + l2
   within 2^-51 (|b| + |r| + |d| + |l2|) of their sum, and TwoSum makes
   (dh, dl) = c + q exact.  So dh + dl is within e + 2^-51 (...) of
   X - cv, and MPFR's mpfr_sub_d (one rounding at p >= 127 bits of
   X_mpfr - cv, |X_mpfr - X| <= e) within e + 2^-127 (|dh| (1 + 2^-50)
   + 2 eD): 2^-120 |dh| and the inflations cover it.  0 when MPFR must
   decide (D not ok()). */
static int e4_diff(const double t[4], double e, double cv, int *have, double *diff, double *upper)
{
	double s, r, a, b, c, d, q, dh, dl, eD;
	two_sum(t[0], -cv, &s, &r);
	two_sum(s, t[1], &a, &b);
	two_sum(a, t[2], &c, &d);
	q = ((b + r) + d) + t[3];
	two_sum(c, q, &dh, &dl);
	eD = ((e + 0x1p-51 * (fabs(b) + fabs(r) + fabs(d) + fabs(t[3]))) * INFL + 0x1p-120 * fabs(dh)) * INFL + FLOOR;
	if (!(fabs(dh) <= DBL_MAX) || !(eD <= DBL_MAX) || (dh != 0.0 && fabs(dh) < TINY))
		return 0;
	*have = dziv53(dh, dl, eD, diff);
	if (!*have)
		*upper = diff_upper(dh, eD);
	return 1;
}
#endif

/* RN(E - cv) into *diff (*have = 1), or else an upper bound of its
   magnitude into *upper (*have = 0); 0 when MPFR must decide. */
static int fwd_diff(xv E, const double *t4, double cv, int *have, double *diff, double *upper)
{
	int bad = 0;
	xv D;
#ifndef REFFAST_PAIR_DOUBLE
	if (E.e > 0.0) {
		double t[4];
		if (!t4) {
			to_e4(E, t);
			t4 = t;
		}
		return e4_diff(t4, E.e, cv, have, diff, upper);
	}
	D = xsub(E, xc(cv), &bad); /* mpfr_sub_d: one rounding at p bits */
#else
	(void)t4;
	D = E.e > 0.0 ? xsub_inexact(E, cv, &bad) : xsub(E, xc(cv), &bad);
#endif
	if (bad)
		return 0;
	*have = ziv_d(D, diff);
	if (!*have)
		*upper = diff_upper((double)D.h, D.e);
	return 1;
}

static int xforward(xv E, const double *t4, double cv, int prec, int parts, double rounded, sample_metrics *s,
                    double undet[2])
{
	double diff = 0.0, upper = 0.0;
	int have_diff = 0;
	if (parts < 0 || !fwd_diff(E, t4, cv, &have_diff, &diff, &upper))
		return 0;
	fwd_accumulate(prec, cv, have_diff, diff, upper, rounded, s, undet);
	return parts;
}

/* The forward figures of every component of the kernel's output against
   the formula r1, r2: 1 (ref[] determined), 2 (ref[] left to MPFR) or 0
   (MPFR decides the sample). */
static int forward_all(fentry *e, const xv *r1, const xv *r2, int prec, sample_metrics *s, double undet[2])
{
	int i, rc = 1;
	for (i = 0; i < s->ncomp; i++) {
		const xv E = i < 3 ? r1[i] : r2[i - 3];
		double refd = NAN, rounded = 0.0;
		int parts, f;
		if (e && e->fwd[i]) {
			parts = e->fwd[i];
			refd = e->refd[i];
			rounded = e->rounded[i];
		} else {
			parts = fwd_parts(E, prec, &refd, &rounded);
			if (e) {
				e->fwd[i] = (signed char)parts;
				e->refd[i] = refd;
				e->rounded[i] = rounded;
#ifndef REFFAST_PAIR_DOUBLE
				to_e4(E, e->t4[i]);
#endif
			}
		}
		s->ref[i] = refd;
		f = xforward(E, e ? e->t4[i] : NULL, s->out[i], prec, parts, rounded, s, undet);
		if (!f)
			return 0;
		if (f == 2)
			rc = 2;
	}
	return rc;
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
	xv x;
	if (fdot_pair(c, a, b, z, &x)) {
		if (normalize_n)
			x = xmul(x, inv, &bad);
		if (!bad && ziv_d(x, out))
			return 1;
		bad = 0;
	}
	x = xdot_exact(c, a, b, z, &bad);
	if (normalize_n)
		x = xmul(x, inv, &bad);
	return !bad && ziv_d(x, out);
}

/* The shape of a basis b and a direction w (reference.c basis_defects
   and dir_errors): the five defects d[] of b for the input n (when
   has_basis), | |w| - 1 | and | w.n - z | (w.(n/|n|) - z when
   normalize_n).  The vector path decides most lanes at once; the others
   take the scalar one.  0 when MPFR must decide. */
static int shape(const reffast_ctx *c, int has_basis, const double b[6], const double n[3], const double w[3],
                 double z, int normalize_n, xv inv, double d[NDEF], double *dir_norm, double *dir_cos)
{
	double v[8];
	int dec = 0, bad = 0;
#ifdef REFFAST_VEC
	dec = shape_vec(c, has_basis, b, n, w, z, normalize_n, v);
#endif
	if (has_basis) {
		if ((!(dec & 1) && !norm_m1_fast(c, b, &v[0])) || (!(dec & 2) && !norm_m1_fast(c, b + 3, &v[1])) ||
		    (!(dec & 4) && !defect_dot(c, b, n, 0.0, normalize_n, inv, &v[2])) ||
		    (!(dec & 8) && !defect_dot(c, b + 3, n, 0.0, normalize_n, inv, &v[3])) ||
		    (!(dec & 16) && !defect_dot(c, b, b + 3, 0.0, 0, inv, &v[4])))
			return 0;
		memcpy(d, v, NDEF * sizeof *d);
	}
	if (!(dec & 32) && !norm_m1_fast(c, w, &v[5]))
		return 0;
	if (!(dec & 64)) {
		if (!normalize_n) {
			if (!defect_dot(c, w, n, z, 0, inv, &v[6]))
				return 0;
		} else {
			xv x;
			/* (w.n) / |n| - z: the lean dot first, the general one if it
			   cannot decide */
			if (!fdot_pair(c, w, n, 0.0, &x) || (x = xsub(xmul(x, inv, &bad), xc(z), &bad), bad) ||
			    !ziv_d(x, &v[6])) {
				bad = 0;
				x = xsub(xmul(xdot_exact(c, w, n, 0.0, &bad), inv, &bad), xc(z), &bad);
				if (bad || !ziv_d(x, &v[6]))
					return 0;
			}
		}
	}
	*dir_norm = fabs(v[5]);
	*dir_cos = fabs(v[6]);
	return 1;
}

/* The accuracy floor (reference.c floor_eval and
   the README's "The accuracy floor"): the exact formula r1, r2 rounded once to
   the format (Ziv's test decides RN of the exact value, as floor_round
   does in MPFR), the defects and direction error of that basis by the
   same helpers as the kernel's, into f (floor, floor_dir_norm,
   floor_dir_cos).  It depends on the kernel only through its formula, so
   the caller keeps it per formula.  0 when anything is undetermined (the
   caller then runs ref_eval). */
static int floor_fast(const reffast_ctx *c, const fentry *e, const study_kernel *k, int prec, int br,
                      const double n[3], const double loc[3], int normalize_n, xv inv, const xv *r1, const xv *r2,
                      double f[3])
{
	const int nc = k->m ? 6 : 3, zero = k->m ? k->fam->exact_zero(k->m, br) : -1;
	double fb[6], w[3], d[NDEF];
	int i;
	for (i = 0; i < nc; i++) {
		if (i == zero) {
			fb[i] = 0.0; /* identically zero (reference.c floor_basis) */
			continue;
		}
		/* the forward error's parts already hold E to the format, the same
		   ziv() on the same value: RN_f(E) unless E was tiny (then 0.0
		   there), RN_d(E) when determined */
		if (e && e->fwd[i] > 0 && (prec == PREC_FLOAT ? e->rounded[i] != 0.0 : e->fwd[i] == 1)) {
			fb[i] = prec == PREC_FLOAT ? e->rounded[i] : e->refd[i];
			continue;
		}
		if (!ziv(i < 3 ? r1[i] : r2[i - 3], prec == PREC_FLOAT ? 24 : 53, &fb[i]))
			return 0;
	}
	f[0] = NAN;
	if (k->m) {
		if (prec == PREC_FLOAT) {
			const float x = (float)loc[0], y = (float)loc[1], z = (float)loc[2];
			for (i = 0; i < 3; i++) {
				const float v = x * (float)fb[i] + y * (float)fb[3 + i] + z * (float)n[i];
				w[i] = v;
			}
		} else {
			for (i = 0; i < 3; i++)
				w[i] = loc[0] * fb[i] + loc[1] * fb[3 + i] + loc[2] * n[i];
		}
	} else {
		for (i = 0; i < 3; i++)
			w[i] = fb[i];
	}
	if (!shape(c, k->m != NULL, fb, n, w, prec == PREC_FLOAT ? (double)(float)loc[2] : loc[2], normalize_n, inv,
	           d, &f[1], &f[2]))
		return 0;
	if (k->m) {
		f[0] = 0.0;
		for (i = 0; i < NDEF; i++)
			if (fabs(d[i]) > f[0])
				f[0] = fabs(d[i]);
	}
	return 1;
}

/* The key of kernel k's formula on branch br, within its family:
   branch * 2 + the family's variant (naive's and hughes_moeller's
   normalized formula and the unnormalized one). */
static int formula_key(const study_kernel *k, int br)
{
	return br * 2 + k->fam->variant(k->m);
}

/* Start the formula cache and the memo anew when the input (n, loc,
   precision, normalize_n) is not the one they hold. */
static void same_input(reffast_ctx *c, int prec, const double n[3], const double loc[3], int normalize_n)
{
	if (c->key_prec != prec || c->key_norm != normalize_n || memcmp(c->key_n, n, sizeof c->key_n) != 0 ||
	    memcmp(c->key_loc, loc, sizeof c->key_loc) != 0) {
		memcpy(c->key_n, n, sizeof c->key_n);
		memcpy(c->key_loc, loc, sizeof c->key_loc);
		c->key_prec = prec;
		c->key_norm = normalize_n;
		c->nf = 0;
		c->nmemo = 0;
	}
}

/* A cheap hash of the kernel's output bits (out[], w[]) and has_basis:
   memo_find compares the bits themselves. */
static uint64_t out_hash(const sample_metrics *s, int has_basis)
{
	uint64_t a, b, w0, w2;
	memcpy(&a, &s->out[0], 8);
	memcpy(&b, &s->out[4], 8);
	memcpy(&w0, &s->w[0], 8);
	memcpy(&w2, &s->w[2], 8);
	return (a ^ (b << 17 | b >> 47) ^ (w0 << 31 | w0 >> 33) ^ w2) + (uint64_t)has_basis;
}

/* The memo's entry with the same output bits as s (and has_basis), the
   one of the same formula key if there is one; NULL if none. */
static const memo_entry *memo_find(const reffast_ctx *c, uint64_t hash, const study_family *fam, int key,
                                   const sample_metrics *s)
{
	const memo_entry *any = NULL;
	int i;
	for (i = 0; i < c->nmemo; i++) {
		const memo_entry *m = &c->memo[i];
		if (m->hash != hash || memcmp(m->smp.out, s->out, sizeof s->out) != 0 ||
		    memcmp(m->smp.w, s->w, sizeof s->w) != 0 || m->smp.has_basis != s->has_basis)
			continue;
		if (m->fam == fam && m->key == key)
			return m;
		any = m;
	}
	return any;
}

/* The kernel's handedness verdict from det (ref_defect_summary's rule):
   the memo's sample may come from a kernel of the other hand. */
static inline void set_hand(const study_kernel *k, sample_metrics *s)
{
	if (k->m)
		s->wrong_hand = !(s->det * k->m->handedness > 0.0);
}

/* The shape figures (defects, det, direction errors: functions of the
   output bits, n and loc alone) of an earlier sample m into s. */
static void copy_shape(const study_kernel *k, const sample_metrics *m, sample_metrics *s)
{
	memcpy(s->d, m->d, sizeof s->d);
	s->defect = m->defect;
	s->sumsq = m->sumsq;
	s->det = m->det;
	s->dir_norm = m->dir_norm;
	s->dir_cos = m->dir_cos;
	set_hand(k, s);
}

/* The cache entry of kernel k's formula on branch br for this input (the
   formula evaluated into it on a miss), its value in *r1, *r2 (pointers
   into the entry: no copy); when the cache is full, NULL and the formula
   evaluated into scratch (3 + 3 values) instead. */
static fentry *formula(reffast_ctx *c, const study_kernel *k, int br, const double n[3], const double loc[3],
                       xv *scratch, const xv **r1, const xv **r2, int *bad)
{
	const int key = formula_key(k, br);
	fentry *e;
	int i;
	for (i = 0; i < c->nf; i++)
		if (c->fc[i].fam == k->fam && c->fc[i].key == key) {
			e = &c->fc[i];
			*r1 = XR(e);
			*r2 = XR(e) + 3;
			*bad = !e->ok;
			return e;
		}
	if (c->nf == FCACHE) {
		xreference(k, br, loc, n, scratch, scratch + 3, bad);
		*r1 = scratch;
		*r2 = scratch + 3;
		return NULL;
	}
	e = &c->fc[c->nf++];
	e->fam = k->fam;
	e->key = key;
	xreference(k, br, loc, n, XR(e), XR(e) + 3, bad);
	e->ok = !*bad;
	e->floor_ok = -1;
	memset(e->fwd, 0, sizeof e->fwd);
	*r1 = XR(e);
	*r2 = XR(e) + 3;
	return e;
}

/* s->floor, floor_dir_norm, floor_dir_cos from the cache entry e (filled
   on first use), and the ratio; 0 when MPFR must decide. */
static int floor_figures(const reffast_ctx *c, fentry *e, const study_kernel *k, int prec, const double n[3],
                         const double loc[3], int normalize_n, xv inv, const xv *r1, const xv *r2,
                         sample_metrics *s)
{
	double f[3] = { NAN, NAN, NAN };
	if (!e || e->floor_ok < 0) {
		const int ok = floor_fast(c, e, k, prec, s->branch, n, loc, normalize_n, inv, r1, r2, f);
		if (e) {
			e->floor_ok = ok;
			e->floor = f[0]; e->floor_dir_norm = f[1]; e->floor_dir_cos = f[2];
		}
		if (!ok)
			return 0;
	} else {
		if (!e->floor_ok)
			return 0;
		f[0] = e->floor; f[1] = e->floor_dir_norm; f[2] = e->floor_dir_cos;
	}
	s->floor = f[0];
	s->floor_dir_norm = f[1];
	s->floor_dir_cos = f[2];
	{
		const double u2 = prec == PREC_FLOAT ? 0x1p-48 : 0x1p-106;
		const double ev = k->m ? s->defect : fmax(s->dir_norm, s->dir_cos);
		const double fv = k->m ? s->floor : fmax(s->floor_dir_norm, s->floor_dir_cos);
		/* fmax(x, u2) for x = NaN is u2, as here; no libm call */
		s->floor_ratio = (ev > u2 ? ev : u2) / (fv > u2 ? fv : u2);
	}
	return 1;
}

int EVAL_NAME(reffast_ctx *c, const study_kernel *k, int prec, const double n_in[3],
              const double loc[3], int normalize_n, sample_metrics *s)
{
	double n[3];
	xv inv = { 1.0, 0.0, 0.0 }, scratch[6];
	const xv *r1, *r2;
	int i, bad = 0, rc = REFFAST_DONE;
	double undet[2] = { 0.0, 0.0 };
	fentry *e;
	const memo_entry *mm;
	uint64_t hash;
	int key;
	ref_run_kernel(k, prec, n_in, loc, n, s);
	if (!input_terms(c, n, normalize_n, &inv))
		return REFFAST_MPFR;
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
		return REFFAST_MPFR; /* the floor of a singular input: left to MPFR */
	}
	same_input(c, prec, n, loc, normalize_n);
	key = formula_key(k, s->branch);
	hash = out_hash(s, s->has_basis);
	mm = memo_find(c, hash, k->fam, key, s);
	if (mm && mm->fam == k->fam && mm->key == key) { /* the same bits and formula: the same figures */
		*s = mm->smp;
		set_hand(k, s);
		return mm->rc;
	}
	e = formula(c, k, s->branch, n, loc, scratch, &r1, &r2, &bad);
	if (bad)
		return 0;
	if (mm) { /* the same bits, another formula: the same shape figures */
		copy_shape(k, &mm->smp, s);
	} else {
		if (!shape(c, k->m != NULL, s->out, n, s->w, prec == PREC_FLOAT ? (double)(float)loc[2] : loc[2],
		           normalize_n, inv, s->d, &s->dir_norm, &s->dir_cos))
			return 0;
		if (k->m)
			ref_defect_summary(k, n, s);
	}

	/* Forward error against the kernel's own formula. */
	s->ulp_max = s->abs_eps_max = s->bits_sum = s->bits_max = 0.0;
	{
		const int f = forward_all(e, r1, r2, prec, s, undet);
		if (!f)
			return 0;
		if (f == 2)
			rc = REFFAST_NOREF;
	}
	/* an undetermined diff no larger than the determined maxima (in the
	   same units: eps and ulps are powers of two) leaves them unchanged */
	if (!(undet[0] <= s->abs_eps_max) || !(undet[1] <= s->ulp_max))
		return 0;

	if (!floor_figures(c, e, k, prec, n, loc, normalize_n, inv, r1, r2, s))
		return 0;
	if (c->nmemo < MEMO) {
		memo_entry *m = &c->memo[c->nmemo++];
		m->hash = hash;
		m->fam = k->fam;
		m->key = key;
		m->rc = rc;
		m->smp = *s;
	}
	return rc;
}
