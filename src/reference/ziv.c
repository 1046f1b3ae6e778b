/*
 * ziv.c - Ziv's strategy for the roundings of the exact formula (see
 * ziv.h, and docs/reference.md, "Correct rounding", for the argument).
 *
 * Levels: 0 is the caller's evaluation at p0 bits; level 1 is p0 + 64,
 * and each level above doubles the one below.  The error of a component
 * at level j >= 1 is estimated from the level below:
 *     err_j = |v_j - v_(j-1)| 2^(SAFE - (P_j - P_(j-1))),
 * none when no operation of level j's evaluation was inexact (MPFR's
 * inexact flag).  A rounding is decided when v_j - err_j and v_j + err_j
 * (each rounded outward) round to the same value, bit for bit (so the
 * sign of a zero too): RN is monotone, so every real between them does.
 * At the cap (a level of at least 8 (p - Q) + 2 p0 bits, Q the exponent
 * of the lowest bit of the input), a rounding still undecided is one
 * whose exact value lies on the boundary: an exact tie goes to even and
 * an exact zero is +0; anything else is reported and counted.
 */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include "reference/ziv.h"
#include "families/family.h"

#define ZIV_LEVELS 10  /* p0 = 127: 127, 191, 382, ..., 48896 bits */
#define ZIV_SAFE 8     /* the estimate's margin, in bits */

static const ref_format fmt_float = { 24, -125, 128 };
static const ref_format fmt_double = { 53, -1021, 1024 };
static const ref_format fmt_half = { 11, -13, 16 };

const ref_format *ref_format_of(int prec)
{
	return prec == PREC_FLOAT ? &fmt_float : prec == PREC_HALF ? &fmt_half : &fmt_double;
}

double ref_round(mpfr_srcptr x, const ref_format *f, mpfr_ptr t)
{
	const long q = (long)f->emin - f->p; /* the smallest subnormal is 2^q */
	long e, bits;
	if (!mpfr_regular_p(x))
		return mpfr_get_d(x, MPFR_RNDN); /* NaN, infinities and zeros as they are */
	e = mpfr_get_exp(x);
	bits = e - q; /* the format's bits at x's binade */
	if (bits > f->p)
		bits = f->p;
	if (bits < 1) {
		/* |x| < 2^q: 2^q above the midpoint 2^(q-1), else 0 (on it: the even 0) */
		int up = 0;
		if (bits == 0) {
			mpfr_set_prec(t, 2);
			mpfr_set_ui_2exp(t, 1, q - 1, MPFR_RNDN);
			up = mpfr_cmpabs(x, t) > 0;
		}
		return copysign(up ? ldexp(1.0, (int)q) : 0.0, mpfr_signbit(x) ? -1.0 : 1.0);
	}
	mpfr_set_prec(t, bits);
	mpfr_set(t, x, MPFR_RNDN); /* at that binade's quantum: the format's rounding */
	if (mpfr_get_exp(t) > f->emax)
		return mpfr_signbit(x) ? -INFINITY : INFINITY;
	return mpfr_get_d(t, MPFR_RNDN); /* exact: at most 53 bits, in range */
}

double ref_round_sum(mpfr_ptr *q, unsigned long k, const ref_format *f, mpfr_ptr t)
{
	const long q0 = (long)f->emin - f->p;
	long bits;
	int cmp;
	mpfr_set_prec(t, 2);
	mpfr_sum(t, q, k, MPFR_RNDZ); /* its exponent is the exact sum's */
	if (!mpfr_regular_p(t)) {
		if (mpfr_zero_p(t))
			mpfr_sum(t, q, k, MPFR_RNDN); /* an exact 0: RN's sign */
		return mpfr_get_d(t, MPFR_RNDN);
	}
	bits = mpfr_get_exp(t) - q0;
	if (bits > f->p)
		bits = f->p;
	if (bits >= 1) {
		mpfr_set_prec(t, bits);
		mpfr_sum(t, q, k, MPFR_RNDN); /* at the format's quantum there: correct */
		if (mpfr_get_exp(t) > f->emax)
			return mpfr_signbit(t) ? -INFINITY : INFINITY;
		return mpfr_get_d(t, MPFR_RNDN);
	}
	/* |S| < 2^q0: compare |S| with the midpoint 2^(q0-1) */
	{
		const int neg = mpfr_signbit(t);
		mpfr_ptr qq[8];
		mpfr_t m;
		unsigned long i;
		if (k > 7)
			return mpfr_get_d(t, MPFR_RNDN); /* not reached: sums of at most 4 */
		mpfr_init2(m, 2);
		mpfr_set_si_2exp(m, neg ? 1 : -1, q0 - 1, MPFR_RNDN);
		for (i = 0; i < k; i++)
			qq[i] = q[i];
		qq[k] = m;
		mpfr_sum(t, qq, k + 1, MPFR_RNDN); /* the sign of S -+ 2^(q0-1), exactly */
		cmp = mpfr_sgn(t) * (neg ? -1 : 1);
		mpfr_clear(m);
		return copysign(cmp > 0 ? ldexp(1.0, (int)q0) : 0.0, neg ? -1.0 : 1.0);
	}
}

/* One level of ref_round_quot at p bits: w = S/sqrt(Q) - z and the
   interval [lo, hi] that holds the exact value.  The quotient's relative
   error is below (1 + 2^-p)^3 (1 + 2^-(p+1)) - 1 < 2^(2-p): S and Q
   rounded once each, the correctly rounded rec_sqrt (Q's error halved
   under the root), the product; taken as 2^(3-p) of |v|, and the
   difference's rounding as 2^(1-p) of |w|. */
static void quot_level(mpfr_ptr *s, unsigned long ks, mpfr_ptr *q, unsigned long kq, double z,
                       mpfr_prec_t p, mpfr_t v, mpfr_t w, mpfr_t e, mpfr_t lo, mpfr_t hi)
{
	mpfr_set_prec(v, p); mpfr_set_prec(w, p); mpfr_set_prec(e, 64);
	mpfr_set_prec(lo, p); mpfr_set_prec(hi, p);
	mpfr_sum(w, q, kq, MPFR_RNDN);
	mpfr_rec_sqrt(w, w, MPFR_RNDN);
	mpfr_sum(v, s, ks, MPFR_RNDN);
	mpfr_mul(v, v, w, MPFR_RNDN);
	mpfr_abs(e, v, MPFR_RNDU);
	mpfr_mul_2si(e, e, 3 - (long)p, MPFR_RNDU);
	mpfr_sub_d(w, v, z, MPFR_RNDN);
	if (z != 0.0) {
		mpfr_abs(lo, w, MPFR_RNDU);
		mpfr_mul_2si(lo, lo, 1 - (long)p, MPFR_RNDU);
		mpfr_add(e, e, lo, MPFR_RNDU);
	}
	mpfr_sub(lo, w, e, MPFR_RNDD);
	mpfr_add(hi, w, e, MPFR_RNDU);
}

double ref_round_quot(mpfr_ptr *s, unsigned long ks, mpfr_ptr *q, unsigned long kq, double z,
                      const ref_format *f)
{
	mpfr_t v, w, e, lo, hi, t;
	mpfr_prec_t p;
	double a = 0.0, b = 1.0;
	mpfr_inits2(128, v, w, e, lo, hi, t, (mpfr_ptr)0);
	for (p = 128; p <= 16384; p *= 2) {
		quot_level(s, ks, q, kq, z, p, v, w, e, lo, hi);
		if (mpfr_zero_p(e)) { /* S = 0 exactly: w = -z, exact */
			a = b = ref_round(w, f, t);
			break;
		}
		if (!mpfr_number_p(lo) || !mpfr_number_p(hi)) {
			a = b = mpfr_get_d(w, MPFR_RNDN); /* NaN or infinite terms */
			break;
		}
		a = ref_round(lo, f, t);
		b = ref_round(hi, f, t);
		if (memcmp(&a, &b, sizeof a) == 0)
			break;
	}
	if (memcmp(&a, &b, sizeof a) != 0) /* at the cap */
		a = (mpfr_sgn(lo) <= 0 && mpfr_sgn(hi) >= 0) ? 0.0 : ref_round(w, f, t);
	mpfr_clears(v, w, e, lo, hi, t, (mpfr_ptr)0);
	return a;
}

typedef struct {
	mpfr_kit k;
	mpfr_t n[3], r1[3], r2[3];
} zlevel;

struct ziv_ctx {
	mpfr_prec_t p0;
	zlevel *lv[ZIV_LEVELS];          /* lv[0] unused: level 0 is the caller's */
	mpfr_t lo, hi, err, t, m;
	int tls;                         /* MPFR's flags are per thread          */
	/* the evaluation being decided (ziv_round, then ziv_diff) */
	const study_kernel *k;
	const ref_format *f;
	int br, nc, j, cap_j, have_cv;
	int exact[ZIV_LEVELS];
	double n[3], loc[3], cv[6];
	mpfr_ptr v[ZIV_LEVELS][6];
	ziv_stats st;
};

static mpfr_prec_t level_prec(const ziv_ctx *z, int j)
{
	mpfr_prec_t p = z->p0;
	if (j >= 1)
		p += 64;
	for (; j > 1; j--)
		p *= 2;
	return p;
}

ziv_ctx *ziv_new(mpfr_prec_t p0)
{
	ziv_ctx *z = calloc(1, sizeof *z);
	if (!z)
		return NULL;
	z->p0 = p0;
	mpfr_inits2(p0 + 64, z->lo, z->hi, z->m, (mpfr_ptr)0);
	mpfr_init2(z->err, 32);
	mpfr_init2(z->t, 64);
	z->tls = mpfr_buildopt_tls_p();
	return z;
}

void ziv_free(ziv_ctx *z)
{
	int j;
	if (!z)
		return;
	for (j = 1; j < ZIV_LEVELS; j++)
		if (z->lv[j]) {
			kit_clear(&z->lv[j]->k);
			kit_vclear(z->lv[j]->n, 3);
			kit_vclear(z->lv[j]->r1, 3);
			kit_vclear(z->lv[j]->r2, 3);
			free(z->lv[j]);
		}
	mpfr_clears(z->lo, z->hi, z->err, z->t, z->m, (mpfr_ptr)0);
	free(z);
}

void ziv_watch(void) { mpfr_clear_inexflag(); }

int ziv_exact(void) { return mpfr_buildopt_tls_p() && !mpfr_inexflag_p(); }

ziv_stats ziv_get_stats(const ziv_ctx *z) { return z->st; }

/* Evaluate level j (allocated on first use): 0 when out of memory. */
static int level_eval(ziv_ctx *z, int j)
{
	zlevel *L = z->lv[j];
	int i;
	if (!L) {
		const mpfr_prec_t p = level_prec(z, j);
		L = z->lv[j] = malloc(sizeof *L);
		if (!L)
			return 0;
		kit_init(&L->k, p);
		kit_vinit(L->n, 3, p);
		kit_vinit(L->r1, 3, p);
		kit_vinit(L->r2, 3, p);
	}
	kit_set3(L->n, z->n[0], z->n[1], z->n[2]);
	ziv_watch();
	z->k->fam->mpfr(&L->k, z->k->m, z->br, z->loc, L->n, L->r1, L->r2);
	z->exact[j] = z->tls && !mpfr_inexflag_p();
	for (i = 0; i < z->nc; i++)
		z->v[j][i] = i < 3 ? L->r1[i] : L->r2[i - 3];
	z->st.raised++;
	return 1;
}

/* err = the error estimate of component i at level j (see the top); 0
   when exact. */
static int estimate(ziv_ctx *z, int j, int i)
{
	if (z->exact[j])
		return 0;
	mpfr_sub(z->err, z->v[j][i], z->v[j - 1][i], MPFR_RNDA);
	mpfr_abs(z->err, z->err, MPFR_RNDN);
	mpfr_mul_2si(z->err, z->err, ZIV_SAFE, MPFR_RNDU);
	return !mpfr_zero_p(z->err);
}

/* RN to f of every real within err (when witherr) of v - a: 1 and *out
   when they all round to one value; else 0 and the two ends' roundings.
   *up: an upper bound of their magnitude. */
static int decide(ziv_ctx *z, mpfr_srcptr v, double a, int witherr, const ref_format *f, double *out,
                  double ends[2], double *up)
{
	const mpfr_prec_t p = mpfr_get_prec(v) + 64;
	mpfr_set_prec(z->lo, p);
	mpfr_set_prec(z->hi, p);
	if (a == 0.0) {
		mpfr_set(z->lo, v, MPFR_RNDD);
		mpfr_set(z->hi, v, MPFR_RNDU);
	} else {
		const int il = mpfr_sub_d(z->lo, v, a, MPFR_RNDD), ih = mpfr_sub_d(z->hi, v, a, MPFR_RNDU);
		if (!il && !ih && mpfr_zero_p(z->lo)) { /* x - x is +0 in RN */
			mpfr_set_zero(z->lo, 1);
			mpfr_set_zero(z->hi, 1);
		}
	}
	if (witherr) {
		mpfr_sub(z->lo, z->lo, z->err, MPFR_RNDD);
		mpfr_add(z->hi, z->hi, z->err, MPFR_RNDU);
	}
	ends[0] = ref_round(z->lo, f, z->t);
	ends[1] = ref_round(z->hi, f, z->t);
	if (up)
		*up = fmax(fabs(mpfr_get_d(z->lo, MPFR_RNDA)), fabs(mpfr_get_d(z->hi, MPFR_RNDA)));
	if (memcmp(&ends[0], &ends[1], sizeof ends[0]) != 0)
		return 0;
	*out = ends[0];
	return 1;
}

/* At the cap: the rounding whose ends e[0] < e[1] differ.  The exact
   value is on the boundary between them: +0 for two zeros, the even
   neighbour for two neighbours (an exact tie); anything else is
   reported. */
static double settle(ziv_ctx *z, const double e[2], const ref_format *f, mpfr_srcptr v)
{
	if (e[0] == 0.0 && e[1] == 0.0) {
		z->st.ties++;
		return 0.0;
	}
	mpfr_set_prec(z->m, 128);
	mpfr_set_d(z->m, e[0], MPFR_RNDN);
	mpfr_add_d(z->m, z->m, e[1], MPFR_RNDN); /* exact: two neighbours */
	mpfr_div_2ui(z->m, z->m, 1, MPFR_RNDN);
	mpfr_nextbelow(z->m);
	if (ref_round(z->m, f, z->t) == e[0]) {
		mpfr_nextabove(z->m);
		mpfr_nextabove(z->m);
		if (ref_round(z->m, f, z->t) == e[1]) {
			mpfr_nextbelow(z->m);
			z->st.ties++;
			return ref_round(z->m, f, z->t); /* the midpoint: ties to even */
		}
	}
	z->st.undecided++;
	fprintf(stderr, "onbstudy: the reference cannot decide a rounding of %s at %ld bits on (%a, %a, %a): "
	        "%a or %a; taking the first\n", z->k->name, (long)mpfr_get_prec(v), z->n[0], z->n[1], z->n[2],
	        e[0], e[1]);
	return e[0];
}

/* The lowest exponent of a set bit among the nonzero input values. */
static int input_lsb(const double *x, int k)
{
	int i, q = 0;
	for (i = 0; i < k; i++)
		if (x[i] != 0.0 && isfinite(x[i])) {
			int e;
			double m = frexp(x[i], &e) * 0x1p53; /* an integer */
			e -= 53;
			while (m == 2.0 * floor(m / 2.0)) {
				m /= 2.0;
				e++;
			}
			if (e < q)
				q = e;
		}
	return q;
}

/* Decide component i at level j (err_j, or exactness): its fmt and d
   (bit 0 when done) and its diff (bit 1), into o; at the cap, settle
   what is left.  Returns the bits still undecided. */
static int try_comp(ziv_ctx *z, int j, int i, int todo, ziv_out *o)
{
	const int witherr = j > 0 && estimate(z, j, i), cap = j == z->cap_j;
	mpfr_srcptr v = z->v[j][i];
	double e[2];
	if (todo & 1) {
		int ok = decide(z, v, 0.0, witherr, z->f, &o->fmt[i], e, NULL);
		if (!ok && cap) {
			o->fmt[i] = settle(z, e, z->f, v);
			ok = 1;
		}
		if (ok && z->f->p != 53) {
			ok = decide(z, v, 0.0, witherr, ref_format_of(PREC_DOUBLE), &o->d[i], e, NULL);
			if (!ok && cap) {
				o->d[i] = settle(z, e, ref_format_of(PREC_DOUBLE), v);
				ok = 1;
			}
		} else if (ok) {
			o->d[i] = o->fmt[i];
		}
		if (ok)
			todo &= ~1;
	}
	if (todo & 2) {
		if (decide(z, v, z->cv[i], witherr, ref_format_of(PREC_DOUBLE), &o->diff[i], e, &o->diff_up[i])) {
			todo &= ~2;
		} else if (cap) {
			o->diff[i] = settle(z, e, ref_format_of(PREC_DOUBLE), v);
			todo &= ~2;
		}
	}
	return todo;
}

/* Raise the level until the bits `need` of todo[] (per component) are
   decided or the cap is reached; every bit of todo[] is tried at each
   level, and updated. */
static void raise_levels(ziv_ctx *z, int *todo, int need, ziv_out *o)
{
	int i, left;
	for (;;) {
		for (i = 0, left = 0; i < z->nc; i++)
			left |= todo[i] & need;
		if (!left || z->j >= z->cap_j)
			return;
		if (!level_eval(z, z->j + 1)) {
			fprintf(stderr, "onbstudy: out of memory for the reference at %ld bits\n", (long)level_prec(z, z->j + 1));
			z->cap_j = z->j; /* settle at this level */
			for (i = 0; i < z->nc; i++)
				if (todo[i])
					todo[i] = try_comp(z, z->j, i, todo[i], o);
			return;
		}
		z->j++;
		for (i = 0; i < z->nc; i++)
			if (todo[i])
				todo[i] = try_comp(z, z->j, i, todo[i], o);
	}
}

void ziv_round(ziv_ctx *z, const study_kernel *k, int prec, int br, const double n[3], const double loc[3],
               mpfr_t *r1, mpfr_t *r2, int exact0, const double *cv, ziv_out *o)
{
	const int zero = k->m ? k->fam->exact_zero(k->m, br) : -1;
	int i, todo[6] = { 0, 0, 0, 0, 0, 0 };
	long capbits;
	z->k = k;
	z->f = ref_format_of(prec);
	z->br = br;
	z->nc = k->m ? 6 : 3;
	z->have_cv = cv != NULL;
	memcpy(z->n, n, sizeof z->n);
	memcpy(z->loc, loc, sizeof z->loc);
	z->j = 0;
	z->exact[0] = exact0;
	{
		const int q = input_lsb(n, 3), ql = k->m ? 0 : input_lsb(loc, 3);
		const ref_format *fd = ref_format_of(PREC_DOUBLE);
		const long sep = 8L * (z->f->p - (q < ql ? q : ql)), zbits = (long)fd->p - (fd->emin - fd->p);
		capbits = (sep > zbits ? sep : zbits) + 2L * (long)z->p0;
	}
	/* the estimate at level j comes from level j - 1 */
	for (z->cap_j = 1; z->cap_j < ZIV_LEVELS - 1 && level_prec(z, z->cap_j - 1) < capbits; z->cap_j++)
		;
	for (i = 0; i < z->nc; i++) {
		z->v[0][i] = i < 3 ? r1[i] : r2[i - 3];
		z->cv[i] = cv ? cv[i] : 0.0;
		o->diff[i] = o->diff_up[i] = NAN;
		if (i == zero && mpfr_number_p(z->v[0][i])) {
			/* identically 0 in exact arithmetic (the family says so),
			   whatever residue MPFR leaves: +0 (an exact -0 keeps its
			   sign in ref[]), and X - cv = -cv */
			o->fmt[i] = 0.0;
			o->d[i] = mpfr_zero_p(z->v[0][i]) && mpfr_signbit(z->v[0][i]) ? -0.0 : 0.0; /* an exact -0 stays */
			o->diff[i] = cv && cv[i] != 0.0 ? -cv[i] : 0.0;
			continue;
		}
		if (!mpfr_number_p(z->v[0][i])) {
			o->fmt[i] = o->d[i] = o->diff[i] = mpfr_get_d(z->v[0][i], MPFR_RNDN);
			continue;
		}
		todo[i] = cv ? 3 : 1;
		if (exact0)
			todo[i] = try_comp(z, 0, i, todo[i], o);
	}
	/* Without exactness, level 1 is always evaluated: the estimate needs
	   two levels.  Every level reached tries the diffs too, but only the
	   format's and double's roundings must be decided here: a diff left
	   undecided keeps its bound (ziv_diff decides it if needed). */
	raise_levels(z, todo, 1, o);
}

void ziv_diff(ziv_ctx *z, int i, ziv_out *o)
{
	int todo[6] = { 0, 0, 0, 0, 0, 0 };
	if (!isnan(o->diff[i]))
		return;
	todo[i] = try_comp(z, z->j, i, 2, o);
	raise_levels(z, todo, 2, o);
}
