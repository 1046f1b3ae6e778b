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

/* Exact sums of products, the lean dot and its AVX lanes, |v| - 1. */
#include "reference/reffast_dot.inc"

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

/* The forward errors of the outputs against the formula's value. */
#include "reference/reffast_fwd.inc"

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
