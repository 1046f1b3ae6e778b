/*
 * mvf.c - the mean-value-form back end of the models (CM_MVF).
 *
 * Every value is an outward-rounded MPFI interval that encloses it for all
 * points of the box: real unit vectors u in a box of (n.z, azimuth) and
 * every error term e_k in [-r_k, r_k].  Beside it, the value carries its
 * gradient in the e's, also as intervals over the whole box (forward
 * differentiation).  A rounding of an exact result v to format f is
 *     fl(v) = v (1 + e) + eta,   |e| <= u,   |eta| <= eta_f,
 * with eta only where |v| can fall below the smallest normal number
 * (u = 2^-24, eta_f = 2^-150 in float; 2^-53 and 2^-1074 in double);
 * round_to uses the tighter form fl(v) = v + d, |d| <= half an ulp of
 * the largest binade v can reach, which implies both.
 * An operation the box proves exact adds no term: a product by 0 or +-1,
 * by a power of two that cannot underflow, of two floats in double (a
 * widened float stays a float), a conversion that widens, x + 0, x - 0
 * and 0 - x (0 a constant or a product by 0), negation, and x - y with
 * y/2 <= x <= 2y (Sterbenz); each only when the other operand is in the
 * format of the result.
 *
 * Mean value theorem: for any quantity Q of the outputs,
 *     Q(u, e) = Q(u, 0) + sum_k e_k dQ/de_k(u, xi),  xi between 0 and e,
 * so |Q| <= |Q(U, 0)| + sum_k r_k max|dQ/de_k(U, E)| over the box, which
 * is what mvf_quantity bounds.  Where Q(u, 0) = 0 identically (the method
 * is exact on the unit sphere), the first term is 0.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <mpfi.h>
#include "model_int.h"
#include "mvf.h"
#include "newton_f.h"
#include "arith.h"
#include "fastfi.h"

#define MV_PREC   80
#define MV_MAXVAR 192
#define REL_MEMO  256   /* a power of two */

/* MPFI's set, neg, interv_d and set_d, bit for bit, faster (fastfi.h). */
static void fi_set(mpfi_ptr a, mpfi_srcptr b) { fastfi_set(a, b, MV_PREC); }
static void fi_neg(mpfi_ptr a, mpfi_srcptr b) { fastfi_neg(a, b, MV_PREC); }
static void fi_interv_d(mpfi_ptr a, double lo, double hi) { fastfi_interv_d(a, lo, hi, MV_PREC); }
static void fi_set_d(mpfi_ptr a, double v)
{
	if (!fastfi_set_d(&a->left, v, MV_PREC) || !fastfi_set_d(&a->right, v, MV_PREC))
		mpfi_set_d(a, v);
}

typedef struct {
	mpfi_t v;        /* the value over the box                         */
	mpfi_t *g;       /* d v / d e_k, meaningful where nz[k]             */
	unsigned char *nz;
	int ng;          /* entries 0..ng-1 may be nonzero                  */
	int fmt;         /* PREC_FLOAT or PREC_DOUBLE: the format the value lies in  */
	int is_cst;      /* an exact constant cval                          */
	double cval;
	/* A seed y of 1/sqrt(x): y = r/sqrt(x) with r in [rel_lo, rel_hi], x the
	   value rsqrt_of (-1: not a seed).  A rounded conversion a = x (1 + d):
	   cvt_of = x, d in [-cvt_u, cvt_u] (-1: not one). */
	int rsqrt_of, cvt_of, seed_k;
	double rel_lo, rel_hi, cvt_u;
	/* Inputs only: br, the values the input can take given the region (n.z
	   within the band) and the branches taken so far (has_br: it is set);
	   input, which input (0..2, or -1). */
	int has_br, input;
	double in_h;     /* inputs: |n_i - u_i| <= in_h (0: not yet set)    */
	mpfi_t br;
	/* Scale-free normalization (norm_tag, norm_out): base, the value with
	   negations and widenings stripped (itself for others); theta_free: no
	   gradient in the arithmetic's error terms (a function of n alone).
	   What the actual value is known to be (not the points between u and
	   n): nonzero, an integer multiple of quantum (0: unknown), at least
	   act_lo in magnitude; sub_a, sub_b: an exact a - b (-1: not one). */
	/* An arithmetic profile's run (mvf_set_arith): the value is a rounded
	   product pa * pb (or its negation, pneg), which a contracting
	   implementation may read exact where it feeds a sum (-1: none). */
	int pa, pb, pneg;
	int base, bsign, theta_free, nonzero, opaque;
	double quantum, act_lo;
	cv sub_a, sub_b;
	/* A norm tag (tg_p != 0): the value is (S (1 + eps + rho))^(p/2) (1 + o),
	   S = sum of the squares of the tg_nb base values tg_b (theta-free),
	   eps in [tg_lo, tg_hi], |rho S| <= tg_abs (roundings that may
	   underflow), o in [tg_olo, tg_ohi]; p = 2, 1 or -1.  tg_var: the
	   error term of the common factor of its outputs (-1: none yet). */
	int tg_p, tg_nb, tg_var;
	cv tg_b[3];
	double tg_lo, tg_hi, tg_abs, tg_olo, tg_ohi, tg_glo, tg_ghi;
	/* A length tag (len_track), for the outputs' lengths alone, with no
	   need of theta-freeness: ls_p = 2, the actual value is S (1 + eps) +
	   alpha, S the sum of the squares of the actual values of the bases
	   ls_b, eps in [ls_lo, ls_hi], |alpha| <= ls_abs; ls_p = -1 or 1, it
	   is (1 + o)^(-ls_p) x^(ls_p/2) for the value x = ls_x (ls_p = 2), o in
	   [ls_olo, ls_ohi].  ls_k >= 0: the value is q K (1 + d) + eta (or
	   q / K ...), q of base ls_q, K = ls_k, |d| <= ls_u, |eta| <= ls_eta. */
	int ls_p, ls_nb, ls_x, ls_k, ls_q;
	int ls_qv, ls_sg;   /* the factor q itself, and the sign of the value against q K */
	cv ls_b[3];
	double ls_lo, ls_hi, ls_abs, ls_olo, ls_ohi, ls_u, ls_eta;
} mval;

struct mvf {
	mval val[CM_MAXV];
	int n;
	double r[MV_MAXVAR];   /* the range of each error term */
	unsigned char in_var[MV_MAXVAR]; /* a term of the input (or its offset) */
	int nvar;
	int grad_lost;         /* the input terms' gradients are unbounded */
	int len_ok[2];         /* mvf_quantities: len_direct held for b1, b2 */
	int orth_ok[2];        /* mvf_quantities: orth_direct held for b1, b2 */
	double orth_u[2], orth_eta[2];
	double len_lo[2], len_hi[2];
	double nh[3];          /* |n_i - u_i| <= nh[i] */
	double phi_lo, phi_hi; /* the box's azimuths (radians) ...          */
	double rr_lo;          /* ... and |(u_x, u_y)| >= rr_lo over it      */
	double tol;            /* the box's tolerance (< 0: roundings) */
	cv st_a[16], st_b[16]; /* a != b for the actual values (branches) */
	int nst;
	int failed;
	int overflow;          /* a failure of this run: a value may overflow */
	int overflow_seen;     /* ... of some run since mvf_overflow_seen asked */
	int no_point;          /* two enclosures of one value are disjoint: no
	                          input of the box takes the path */
	int zero_e;            /* every e is 0: values only, no gradients */
	int nograd;            /* values over the whole box, no gradients */
	int centred;           /* with zero_e: gradients in the inputs' offsets */
	/* An arithmetic profile other than ieee (arith.h), or NULL; unb_op:
	   the first operation (AR_ kind) whose allowance gave no bound in this
	   run (-1: none). */
	const arith_profile *ar;
	int unb_op;
	int lost_op;           /* the first operation whose exact enclosure was
	                          lost (an AR_ kind with AR_AT_POLE or
	                          AR_OVERFLOW), -1: none */
	mpfi_t t1, t2, t3;     /* scratch of round_to, grad_lin, sterbenz */
	mpfi_t s1, s2;         /* scratch of the operations: scale factors */
	mpfi_t one, mone;
	mpfi_t u[3];           /* the inputs' exact values u_i over the box */
	mpfr_t f1, f2;
	mpfr_t p1, p2;         /* scratch of imul */
	/* mvf_begin's geometry of the last box (box_geometry): every path and
	   mode of one box starts from it.  geo_ok: it is set. */
	int geo_ok;
	double geo_key[8];
	mpfi_t geo_in[3], geo_t1, geo_t2, geo_s1, geo_s2;
	mpfr_t geo_f1, geo_f2;
	double geo_rr_lo;
	mpfr_t cd;             /* fi_cmp_d's double */
	/* rel_mul and rel_div's results, by their arguments (rel_memo) */
	struct { double a, b, r; int kind; } memo[REL_MEMO];
};

mvf *mvf_new(void)
{
	mvf *m = calloc(1, sizeof *m);
	int i, k;
	if (!m)
		return NULL;
	for (i = 0; i < CM_MAXV; i++) {
		mval *x = &m->val[i];
		mpfi_init2(x->v, MV_PREC);
		mpfi_init2(x->br, MV_PREC);
		x->g = malloc(MV_MAXVAR * sizeof *x->g);
		x->nz = calloc(MV_MAXVAR, 1);
		if (!x->g || !x->nz)
			abort(); /* a few MB at start-up: nothing sensible to do */
		for (k = 0; k < MV_MAXVAR; k++)
			mpfi_init2(x->g[k], MV_PREC);
	}
	mpfi_init2(m->t1, MV_PREC);
	mpfi_init2(m->t2, MV_PREC);
	mpfi_init2(m->t3, MV_PREC);
	mpfi_init2(m->s1, MV_PREC);
	mpfi_init2(m->s2, MV_PREC);
	mpfi_init2(m->one, MV_PREC);
	mpfi_init2(m->mone, MV_PREC);
	fi_set_d(m->one, 1.0);
	fi_set_d(m->mone, -1.0);
	for (i = 0; i < 3; i++)
		mpfi_init2(m->u[i], MV_PREC);
	mpfr_init2(m->f1, MV_PREC);
	mpfr_init2(m->f2, MV_PREC);
	mpfr_init2(m->p1, MV_PREC);
	mpfr_init2(m->p2, MV_PREC);
	for (i = 0; i < 3; i++)
		mpfi_init2(m->geo_in[i], MV_PREC);
	mpfi_init2(m->geo_t1, MV_PREC);
	mpfi_init2(m->geo_t2, MV_PREC);
	mpfi_init2(m->geo_s1, MV_PREC);
	mpfi_init2(m->geo_s2, MV_PREC);
	mpfr_init2(m->geo_f1, MV_PREC);
	mpfr_init2(m->geo_f2, MV_PREC);
	mpfr_init2(m->cd, MV_PREC);
	for (i = 0; i < REL_MEMO; i++)
		m->memo[i].kind = -1;
	return m;
}

void mvf_free(mvf *m)
{
	int i, k;
	if (!m)
		return;
	for (i = 0; i < CM_MAXV; i++) {
		for (k = 0; k < MV_MAXVAR; k++)
			mpfi_clear(m->val[i].g[k]);
		free(m->val[i].g);
		free(m->val[i].nz);
		mpfi_clear(m->val[i].v);
		mpfi_clear(m->val[i].br);
	}
	mpfi_clear(m->t1);
	mpfi_clear(m->t2);
	mpfi_clear(m->t3);
	mpfi_clear(m->s1);
	mpfi_clear(m->s2);
	mpfi_clear(m->one);
	mpfi_clear(m->mone);
	for (i = 0; i < 3; i++)
		mpfi_clear(m->u[i]);
	mpfr_clear(m->f1);
	mpfr_clear(m->f2);
	mpfr_clear(m->p1);
	mpfr_clear(m->p2);
	for (i = 0; i < 3; i++)
		mpfi_clear(m->geo_in[i]);
	mpfi_clear(m->geo_t1);
	mpfi_clear(m->geo_t2);
	mpfi_clear(m->geo_s1);
	mpfi_clear(m->geo_s2);
	mpfr_clear(m->geo_f1);
	mpfr_clear(m->geo_f2);
	mpfr_clear(m->cd);
	free(m);
}

void mvf_fail(mvf *m) { m->failed = 1; }
int mvf_failed(const mvf *m) { return m->failed; }

int mvf_overflowed(const mvf *m) { return m->overflow; }

int mvf_overflow_seen(mvf *m)
{
	const int r = m->overflow_seen;
	m->overflow_seen = 0;
	return r;
}

int mvf_no_point(const mvf *m) { return m->no_point; }

/* The rest of this run is not wanted (a path no point of the box takes):
   every later operation returns at once. */
void mvf_abandon(mvf *m) { m->failed = 1; }

/* No gradients in this run: MVF_VALUES, MVF_AT_ZERO and MVF_AT_MID. */
static int no_grad(const mvf *m) { return m->nograd || (m->zero_e && !m->centred); }

/* The format's parameters (common/prec.h's prec_fmt: binary32, binary64,
   binary16): unit roundoff, smallest normal, and half the subnormal step
   (the largest error of a rounding that underflows; 2^-1075 is no double,
   so 2^-1074 there). */
static prec_format mutant[PREC_COUNT];   /* mvf_mutate_format: bits > 0 */

static const prec_format *fmt_of(int f)
{
	const int i = f >= 0 && f < PREC_COUNT ? f : PREC_DOUBLE;
	return mutant[i].bits > 0 ? &mutant[i] : prec_fmt(i);
}

void mvf_mutate_format(int f, int bits)
{
	if (f < 0 || f >= PREC_COUNT)
		return;
	mutant[f] = *prec_fmt(f);
	mutant[f].bits = bits;
	mutant[f].u = ldexp(1.0, -bits);
	mutant[f].sub_step = ldexp(1.0, mutant[f].emin - bits + 1);
	if (bits <= 0)
		mutant[f].bits = 0;
}

static double unit_round(int f) { return fmt_of(f)->u; }
static double normal_min(int f) { return fmt_of(f)->normal_min; }
static double tiny_of(int f)
{
	const double t = fmt_of(f)->sub_step / 2;
	return t > 0.0 ? t : fmt_of(f)->sub_step;
}

/* Every value of format a is one of format f (binary16 in binary32 in
   binary64: the significands and the exponent ranges nest). */
static int fmt_in(int a, int f) { return prec_fmt(a)->bits <= prec_fmt(f)->bits; }

/* Value x is in format f: its format's values are, or it is a constant
   that f represents (1 in binary16, which mvf_cst marks a float). */
static int val_in(const mval *x, int f)
{
	return fmt_in(x->fmt, f) || (x->is_cst && (f == PREC_HALF ? prec_half_round(x->cval) == x->cval
	                                                          : f == PREC_DOUBLE || (double)(float)x->cval == x->cval));
}

/* mpfr_cmp_d(x, d), without its temporary where d is a normal double. */
static int fi_cmp_d(mvf *m, mpfr_srcptr x, double d)
{
	if (!fastfi_set_d(m->cd, d, MV_PREC))
		return mpfr_cmp_d(x, d);
	return mpfr_cmp(x, m->cd);
}

/* |V| can exceed format f's largest finite value: a rounding to f there
   may overflow to infinity, which no error term bounds.  The run fails
   (its box is unbounded) and says why (mvf_overflowed). */
static int may_overflow(mvf *m, mpfi_srcptr v, int f)
{
	mpfi_mag(m->f1, v);
	if (fi_cmp_d(m, m->f1, fmt_of(f)->max) <= 0)
		return 0;
	m->overflow = m->overflow_seen = 1;
	m->failed = 1;
	return 1;
}

/* A fresh value slot with an empty gradient. */
static cv fresh(mvf *m, int fmt)
{
	mval *x;
	if (m->n >= CM_MAXV) {
		m->failed = 1;
		return CM_MAXV - 1;
	}
	x = &m->val[m->n];
	x->ng = 0;   /* nz[k] for k >= ng is stale: mark clears it as ng grows */
	x->fmt = fmt;
	x->is_cst = 0;
	x->rsqrt_of = x->cvt_of = x->seed_k = -1;
	x->has_br = 0;
	x->input = -1;
	x->in_h = 0.0;
	x->base = m->n;
	x->bsign = 1;
	x->theta_free = 0;
	x->nonzero = 0;
	x->opaque = 0;
	x->quantum = x->act_lo = 0.0;
	x->sub_a = x->sub_b = -1;
	x->ls_p = 0;
	x->ls_k = -1;
	x->ls_qv = -1;
	x->ls_sg = 1;
	x->tg_p = 0;
	x->tg_var = -1;
	x->pa = x->pb = -1;
	x->pneg = 0;
	return m->n++;
}

static int new_var(mvf *m, double range)
{
	if (m->nograd)
		return -1;
	if (m->nvar >= MV_MAXVAR) {
		m->failed = 1;
		return MV_MAXVAR - 1;
	}
	m->r[m->nvar] = range;
	m->in_var[m->nvar] = 0;
	return m->nvar++;
}

/* Entry k of x's gradient is nonzero; the entries between the old ng
   and k are zero (nz[] past ng is left over from earlier values). */
static void mark(mval *x, int k)
{
	while (x->ng < k)
		x->nz[x->ng++] = 0;
	if (x->ng == k)
		x->ng = k + 1;
	x->nz[k] = 1;
}

static void set_grad(mval *x, int k, mpfi_srcptr g)
{
	if (k < 0)
		return;
	fi_set(x->g[k], g);
	mark(x, k);
}

/* a = b * c: MPFI 1.5's mpfi_mul, case for case and so bit for bit, with
   the scratch allocated once (mpfi_mul allocates one or two temporaries
   whenever an operand is not positive: a tenth of certify's time). */
static void imul(mvf *m, mpfi_ptr a, mpfi_srcptr b, mpfi_srcptr c)
{
	mpfr_srcptr bl = &b->left, br = &b->right, cl = &c->left, cr = &c->right;
	mpfr_ptr lo;   /* the left end: into a itself unless a is an operand */
	if (mpfr_get_prec(&a->left) != MV_PREC || mpfr_get_prec(&a->right) != MV_PREC || mpfr_nan_p(bl) ||
	    mpfr_nan_p(br) || mpfr_nan_p(cl) || mpfr_nan_p(cr) || (mpfr_zero_p(bl) && mpfr_zero_p(br)) ||
	    (mpfr_zero_p(cl) && mpfr_zero_p(cr)) || (mpfr_sgn(bl) >= 0 && mpfr_sgn(cl) >= 0)) {
		mpfi_mul(a, b, c);   /* no temporaries there */
		return;
	}
	lo = a != b && a != c ? &a->left : m->p1;
	if (mpfr_sgn(bl) >= 0) {                       /* b >= 0; c < 0 somewhere */
		if (mpfr_sgn(cr) <= 0) {
			mpfr_mul(lo, br, cl, MPFR_RNDD);
			mpfr_mul(&a->right, bl, cr, MPFR_RNDU);
		} else {
			mpfr_mul(lo, br, cl, MPFR_RNDD);
			mpfr_mul(&a->right, br, cr, MPFR_RNDU);
		}
	} else if (mpfr_sgn(br) <= 0) {                /* b <= 0 */
		if (mpfr_sgn(cl) >= 0) {
			mpfr_mul(lo, bl, cr, MPFR_RNDD);
			mpfr_mul(&a->right, br, cl, MPFR_RNDU);
		} else if (mpfr_sgn(cr) <= 0) {
			mpfr_mul(lo, br, cr, MPFR_RNDD);
			mpfr_mul(&a->right, bl, cl, MPFR_RNDU);
		} else {
			mpfr_mul(lo, bl, cr, MPFR_RNDD);
			mpfr_mul(&a->right, bl, cl, MPFR_RNDU);
		}
	} else if (mpfr_sgn(cl) >= 0) {                /* b contains 0 */
		mpfr_mul(lo, bl, cr, MPFR_RNDD);
		mpfr_mul(&a->right, br, cr, MPFR_RNDU);
	} else if (mpfr_sgn(cr) <= 0) {
		mpfr_mul(lo, br, cl, MPFR_RNDD);
		mpfr_mul(&a->right, bl, cl, MPFR_RNDU);
	} else {                                       /* both contain 0 */
		mpfr_mul(m->p1, bl, cr, MPFR_RNDD);
		mpfr_mul(m->p2, br, cl, MPFR_RNDD);
		if (mpfr_cmp(m->p1, m->p2) < 0)
			mpfr_swap(m->p1, m->p2);
		/* now p2 is the smaller: the left end */
		mpfr_mul(m->p1, bl, cl, MPFR_RNDU);
		mpfr_mul(&a->right, br, cr, MPFR_RNDU);
		if (mpfr_cmp(m->p1, &a->right) > 0)
			mpfr_set(&a->right, m->p1, MPFR_RNDU);
		mpfr_set(&a->left, m->p2, MPFR_RNDD);
		return;
	}
	if (lo != &a->left)
		mpfr_set(&a->left, lo, MPFR_RNDD);   /* exact: one precision */
}

/* g = s x: a copy or a negation when s is the constant 1 or -1 (what
   imul would give, exactly: the product by +-1 is exact), else imul. */
static void scale(mvf *m, mpfi_ptr g, mpfi_srcptr x, mpfi_srcptr s)
{
	if (s == m->one)
		fi_set(g, x);
	else if (s == m->mone)
		fi_neg(g, x);
	else
		imul(m, g, x, s);
}

/* r->g = sa * a->g + sb * b->g (sa, sb intervals; b may be NULL), each
   entry written in place unless r is a or b. */
static void grad_lin(mvf *m, mval *r, const mval *a, mpfi_srcptr sa, const mval *b, mpfi_srcptr sb)
{
	const int alias = r == a || r == b;
	int k, ng = a->ng;
	if (no_grad(m))
		return;
	if (b && b->ng > ng)
		ng = b->ng;
	for (k = 0; k < ng; k++) {
		int ia = k < a->ng && a->nz[k], ib = b && k < b->ng && b->nz[k];
		mpfi_ptr g = alias ? m->t3 : r->g[k];
		if (!ia && !ib)
			continue;
		if (ia) {
			scale(m, g, a->g[k], sa);
			if (ib) {
				scale(m, m->t2, b->g[k], sb);
				mpfi_add(g, g, m->t2);
			}
		} else
			scale(m, g, b->g[k], sb);
		if (alias)
			set_grad(r, k, g);
		else
			mark(r, k);
	}
}

cv mvf_cst(mvf *m, double v)
{
	cv i = fresh(m, (double)(float)v == v ? PREC_FLOAT : PREC_DOUBLE);
	fi_set_d(m->val[i].v, v);
	m->val[i].is_cst = 1;
	m->val[i].cval = v;
	m->val[i].theta_free = 1;
	m->val[i].nonzero = v != 0.0;
	m->val[i].act_lo = fabs(v);
	return i;
}

/* Round slot r (an exact result v) to format f: fl(v) = v + d with
   |d| <= half an ulp of the binade of max|V| (2^(E - p) for 2^E <= max|V|,
   E at least the smallest normal exponent, so subnormal results are
   covered too).  That is u |v| or less, and half of it just below a power
   of two, where u |v| would count the error twice. */
/* Half an ulp of format f in the binade of max|V| (the largest error of
   rounding any value of V to nearest); 0 when V = {0}. */
static double half_ulp_of(mvf *m, mpfi_srcptr v, int f)
{
	const int p = fmt_of(f)->bits, emin = fmt_of(f)->emin;
	long e;
	double h;
	mpfi_mag(m->f1, v);
	if (mpfr_zero_p(m->f1))
		return 0.0;
	e = (long)mpfr_get_exp(m->f1) - 1;            /* 2^e <= max|V| < 2^(e+1) */
	if (mpfr_cmp_ui_2exp(m->f1, 1, e) == 0)
		e--;   /* max|V| = 2^e: below it the ulp halves, and 2^e itself is exact */
	if (e < emin)
		e = emin;
	h = ldexp(1.0, (int)(e - p));
	return h == 0.0 ? 0x1p-1074 : h;              /* 2^-1075 is not a double */
}

/* 1 when x has a gradient entry: its value depends on some error term. */
static int has_grad(const mval *x)
{
	int k;
	for (k = 0; k < x->ng; k++)
		if (x->nz[k])
			return 1;
	return 0;
}

/* x->v += [-h, h] for a rounding v -> v + d.  Rounding maps values >= 0 to
   >= 0, so the actual result keeps the sign of V; but in a run with
   gradients x->v also encloses the points v(theta e) + theta d (0 <= theta
   <= 1) where the mean value form evaluates, and when v depends on other
   error terms, v(theta e) can lie below the actual v while theta d is
   still the actual (negative) d: the sign is kept there only when v does
   not move with the e's (an input u_i, a constant). */
static void add_sym(mvf *m, mval *x, double h)
{
	const int keep = no_grad(m) || !has_grad(x);
	const int nonneg = keep && mpfi_is_nonneg(x->v), nonpos = keep && mpfi_is_nonpos(x->v);
	fi_interv_d(m->t1, -h, h);
	mpfi_add(x->v, x->v, m->t1);
	if (nonneg || nonpos) {
		fi_interv_d(m->t1, nonneg ? 0.0 : -INFINITY, nonneg ? INFINITY : 0.0);
		mpfi_intersect(x->v, x->v, m->t1);
	}
}

/* The rounding of v to format f: v + e, |e| <= h = half an ulp of v's
   binade, or cap when that is smaller (round_sum). */
static void round_to_cap(mvf *m, cv r, int f, double cap)
{
	mval *x = &m->val[r];
	double h;
	x->fmt = f;
	if (mpfi_nan_p(x->v) || !mpfi_bounded_p(x->v)) {
		m->failed = 1;
		return;
	}
	if (may_overflow(m, x->v, f))
		return;
	if (m->zero_e || (h = fmin(half_ulp_of(m, x->v, f), cap)) == 0.0)
		return;                                   /* v = 0: exact */
	set_grad(x, new_var(m, h), m->one);
	add_sym(m, x, h);
}

static void round_to(mvf *m, cv r, int f) { round_to_cap(m, r, f, INFINITY); }

/* The error of a rounded sum a + b of two values of format f is at most
   min(|a|, |b|): a and b are themselves candidates for the nearest value
   (1 + y^2 with y^2 below half an ulp of 1 is 1, its error y^2, not half
   an ulp).  INFINITY when an operand is of a wider format. */
static double round_sum_cap(mvf *m, const mval *a, const mval *b, int f)
{
	double ca, cb;
	if (!val_in(a, f) || !val_in(b, f))
		return INFINITY;
	mpfi_mag(m->f1, a->v);
	ca = mpfr_get_d(m->f1, MPFR_RNDU);
	mpfi_mag(m->f1, b->v);
	cb = mpfr_get_d(m->f1, MPFR_RNDU);
	return fmin(ca, cb);
}

static int is_cst(const mval *x, double v) { return x->is_cst && x->cval == v; }

/* x is 0 at every point of the box and for every e (a constant 0, a
   product by 0): v + 0 and v - 0 are v, exact when v is in the format. */
static int is_zero(const mval *x) { return is_cst(x, 0.0) || mpfi_is_zero(x->v); }

static int is_pow2(const mval *x)
{
	int e;
	return x->is_cst && x->cval != 0.0 && fabs(frexp(x->cval, &e)) == 0.5;
}

/* Sterbenz: x - y is exact when y/2 <= x <= 2y (x, y of one sign and in
   the format).  neg_b: the operation is x + b, i.e. y = -b. */
static int sterbenz(mvf *m, const mval *a, const mval *b, int neg_b, int f)
{
	mpfi_srcptr y = b->v;
	if (!val_in(a, f) || !val_in(b, f))
		return 0;
	if (neg_b) {
		fi_neg(m->t1, b->v);
		y = m->t1;
	}
	if (mpfi_is_strictly_neg(a->v) && mpfi_is_strictly_neg(y)) {
		fi_neg(m->t2, a->v);
		fi_neg(m->t1, y);
		return mvf_ratio_within_2(m, m->t2, m->t1);
	}
	if (mpfi_is_strictly_pos(a->v) && mpfi_is_strictly_pos(y))
		return mvf_ratio_within_2(m, a->v, y);
	return 0;
}

/* For positive intervals x, y: y/2 <= x <= 2y at every point. */
int mvf_ratio_within_2(mvf *m, mpfi_srcptr x, mpfi_srcptr y)
{
	mpfi_get_left(m->f1, x);
	mpfi_get_right(m->f2, y);
	mpfr_div_2ui(m->f2, m->f2, 1, MPFR_RNDU);
	if (mpfr_cmp(m->f1, m->f2) < 0)
		return 0;
	mpfi_get_right(m->f1, x);
	mpfi_get_left(m->f2, y);
	mpfr_mul_2ui(m->f2, m->f2, 1, MPFR_RNDD);
	return mpfr_cmp(m->f1, m->f2) <= 0;
}

/* 1 when the box proves the operation exact in format f. */
static int exact_op(mvf *m, int op, int f, const mval *a, const mval *b, const mval *r)
{
	switch (op) {
	case MVF_NEG:
		return 1;
	case MVF_CVT:
		return val_in(a, f);
	case MVF_MUL:
		if (is_zero(a) || is_zero(b))
			return 1;
		if (((is_cst(a, 1.0) || is_cst(a, -1.0)) && val_in(b, f)) ||
		    ((is_cst(b, 1.0) || is_cst(b, -1.0)) && val_in(a, f)))
			return 1;
		if (f == PREC_DOUBLE && val_in(a, PREC_FLOAT) && val_in(b, PREC_FLOAT))
			return 1; /* 24 + 24 bits fit in 53 */
		if ((is_pow2(a) && val_in(b, f)) || (is_pow2(b) && val_in(a, f))) {
			mpfi_mig(m->f1, r->v);   /* no underflow; may_overflow (op_value) sees the top */
			return fi_cmp_d(m, m->f1, normal_min(f)) >= 0;
		}
		return 0;
	case MVF_ADD:
	case MVF_SUB:
		if ((is_zero(a) && val_in(b, f)) || (is_zero(b) && val_in(a, f)))
			return 1;
		return sterbenz(m, a, b, op == MVF_ADD, f);
	default:
		return 0;
	}
}

static void copy_grad(mvf *m, mval *r, const mval *a)
{
	int k;
	if (no_grad(m))
		return;
	for (k = 0; k < a->ng; k++)
		if (a->nz[k])
			set_grad(r, k, a->g[k]);
}

/* r->g += d->g */
static void grad_add(mvf *m, mval *r, const mval *d)
{
	int k;
	if (no_grad(m))
		return;
	for (k = 0; k < d->ng; k++) {
		if (!d->nz[k])
			continue;
		if (k < r->ng && r->nz[k])
			mpfi_add(r->g[k], r->g[k], d->g[k]);
		else
			set_grad(r, k, d->g[k]);
	}
}

/* The exact operation into r (value and gradient); 0 when it cannot be
   enclosed (a division by an interval holding 0, a square root whose
   derivative is unbounded). */
static int exact_eval(mvf *m, int op, mval *r, const mval *a, const mval *b, const mval *d)
{
	switch (op) {
	case MVF_ADD:
		mpfi_add(r->v, a->v, b->v);
		grad_lin(m, r, a, m->one, b, m->one);
		return 1;
	case MVF_SUB:
		mpfi_sub(r->v, a->v, b->v);
		grad_lin(m, r, a, m->one, b, m->mone);
		return 1;
	case MVF_MUL:
	case MVF_FMA:
		if (a == b)
			mpfi_sqr(r->v, a->v);   /* x*x >= 0: not the product of two intervals */
		else
			imul(m, r->v, a->v, b->v);
		grad_lin(m, r, a, b->v, b, a->v);
		if (op == MVF_FMA) {
			mpfi_add(r->v, r->v, d->v);
			grad_add(m, r, d);
		}
		return 1;
	case MVF_DIV:
		if (mpfi_has_zero(b->v))
			return 0;
		mpfi_div(r->v, a->v, b->v);
		mpfi_inv(m->s1, b->v);          /* d(a/b) = da/b - db a/b^2 */
		mpfi_div(m->s2, r->v, b->v);
		fi_neg(m->s2, m->s2);
		grad_lin(m, r, a, m->s1, b, m->s2);
		return 1;
	case MVF_SQRT:
		if (!mpfi_is_nonneg(a->v))
			return 0;
		mpfi_sqrt(r->v, a->v);
		if (no_grad(m))
			return 1;
		if (!mpfi_is_strictly_pos(a->v))
			return 0;
		mpfi_mul_2ui(m->s1, r->v, 1);   /* d sqrt(a) = da / (2 sqrt(a)) */
		mpfi_inv(m->s1, m->s1);
		grad_lin(m, r, a, m->s1, NULL, NULL);
		return 1;
	case MVF_NEG:
		fi_neg(r->v, a->v);
		grad_lin(m, r, a, m->mone, NULL, NULL);
		return 1;
	default: /* MVF_CVT */
		fi_set(r->v, a->v);
		copy_grad(m, r, a);
		return 1;
	}
}

/* ---- Scale-free normalization ----
   A kernel that normalizes a vector a computed exactly from n (a function
   of n alone: differences Sterbenz proves exact, negations, the inputs
   themselves) divides a_i by l = |a| (1 + g) or multiplies it by
   f = (1 + g)/|a|, g the relative error of the sum of squares, the square
   root and the reciprocal.  Then b_i = (a_i/|a|)(1 + g)(1 + d_i): the unit
   vector a/|a| times relative errors whose size does not depend on |a|.
   Intervals of a_i and of l over a box apart cannot see that when the
   box's |a| ranges over orders of magnitude or reaches 0 (a normalization
   of (1,1,1) x n next to the diagonal): there a_i/l is a wide or unbounded
   interval.  So the operations carry a norm tag (mval.tg_*): a sum of the
   squares of theta-free values is S (1 + eps) + alpha, its square root
   and reciprocal powers of that, and the product or quotient of a tagged
   value's base component by it becomes (a_i/|a|) (1 + g), a_i/|a| in
   [-1, 1] from the squares of the components (norm_out), g one error term
   shared by the three components. */

static double round_up_d(double x) { return nextafter(x, INFINITY); }

/* (1 + a)(1 + b) - 1 and (1 + a)/(1 + b) - 1, rounded up or down (kind:
   2 div + up), from m->memo where these arguments were seen: functions of
   their arguments alone, and a few pairs recur in every run. */
static double rel_eval(mvf *m, double a, double b, int kind)
{
	const mpfr_rnd_t d = kind & 1 ? MPFR_RNDU : MPFR_RNDD;
	mpfr_set_d(m->f1, a, MPFR_RNDN);
	mpfr_add_ui(m->f1, m->f1, 1, d);
	mpfr_set_d(m->f2, b, MPFR_RNDN);
	if (kind & 2) {
		mpfr_add_ui(m->f2, m->f2, 1, kind & 1 ? MPFR_RNDD : MPFR_RNDU);
		mpfr_div(m->f1, m->f1, m->f2, d);
	} else {
		mpfr_add_ui(m->f2, m->f2, 1, d);
		mpfr_mul(m->f1, m->f1, m->f2, d);
	}
	mpfr_sub_ui(m->f1, m->f1, 1, d);
	return mpfr_get_d(m->f1, d);
}

static double rel_memo(mvf *m, double a, double b, int kind)
{
	uint64_t ka, kb;
	unsigned h;
	memcpy(&ka, &a, sizeof ka);
	memcpy(&kb, &b, sizeof kb);
	h = (unsigned)(((ka * UINT64_C(0x9e3779b97f4a7c15)) ^ (kb * UINT64_C(0xc2b2ae3d27d4eb4f)) ^ (uint64_t)kind) >> 56) &
	    (REL_MEMO - 1);
	if (m->memo[h].kind != kind || memcmp(&m->memo[h].a, &a, sizeof a) != 0 || memcmp(&m->memo[h].b, &b, sizeof b) != 0) {
		m->memo[h].a = a;
		m->memo[h].b = b;
		m->memo[h].kind = kind;
		m->memo[h].r = rel_eval(m, a, b, kind);
	}
	return m->memo[h].r;
}

static double rel_mul(mvf *m, double a, double b, int up) { return rel_memo(m, a, b, up ? 1 : 0); }

static double rel_div(mvf *m, double a, double b, int up) { return rel_memo(m, a, b, up ? 3 : 2); }

/* a != b is known for the actual values (a branch took a strict side) */
static int strict_pair(const mvf *m, cv a, cv b)
{
	int i;
	for (i = 0; i < m->nst; i++)
		if ((m->st_a[i] == a && m->st_b[i] == b) || (m->st_a[i] == b && m->st_b[i] == a))
			return 1;
	return 0;
}

static void note_lo(mvf *m, cv i, double lo)
{
	mval *x = &m->val[i], *y = &m->val[x->base];
	if (!(lo > 0.0))
		return;
	x->nonzero = y->nonzero = 1;
	if (lo > x->act_lo)
		x->act_lo = lo;
	if (lo > y->act_lo)
		y->act_lo = lo;
}

/* What a branch's side says about the actual values: a strict a < b or
   a > b (a != b), |a| > |b| (|a| >= mig |b|, a != 0), a >= c > 0. */
void mvf_note_strict(mvf *m, int op, int absolute, cv ia, cv ib, int side)
{
	cv lo = op == CM_LT ? ia : ib, hi = op == CM_LT ? ib : ia;   /* side 1: lo < hi */
	mval *a = &m->val[lo], *b = &m->val[hi];
	if (!side) {   /* hi <= lo: lo >= c > 0 or hi <= c < 0 with c a constant */
		if (absolute)
			return;
		if (b->is_cst && b->cval > 0.0)
			note_lo(m, lo, b->cval);
		if (a->is_cst && a->cval < 0.0)
			note_lo(m, hi, -a->cval);
		return;
	}
	if (absolute) {   /* |lo| < |hi| */
		mpfi_mig(m->f1, a->v);
		note_lo(m, hi, mpfr_get_d(m->f1, MPFR_RNDD));
		m->val[hi].nonzero = m->val[m->val[hi].base].nonzero = 1;
		return;
	}
	if (b->is_cst && b->cval <= 0.0)
		note_lo(m, lo, -b->cval);
	if (a->is_cst && a->cval >= 0.0)
		note_lo(m, hi, a->cval);
	if (b->is_cst && b->cval == 0.0)
		m->val[lo].nonzero = m->val[a->base].nonzero = 1;
	if (a->is_cst && a->cval == 0.0)
		m->val[hi].nonzero = m->val[b->base].nonzero = 1;
	if (m->nst < 16) {
		m->st_a[m->nst] = a->base;
		m->st_b[m->nst++] = b->base;
	}
}

/* The smallest |v| of an actual nonzero value v (0: unknown), and 1 in
   *nz when v != 0 is known. */
static double actual_lo(const mvf *m, const mval *x, int *nz)
{
	double lo = x->act_lo;
	*nz = x->nonzero || x->act_lo > 0.0 ||
	      (x->sub_a >= 0 && strict_pair(m, m->val[x->sub_a].base, m->val[x->sub_b].base));
	if (*nz && x->quantum > lo)
		lo = x->quantum;
	return lo;
}

/* Bookkeeping after r = op(a, b): theta-freeness, bases and signs, what
   the actual value is known to be, and the norm tags. */
static void track(mvf *m, int op, int f, int exact, cv ir, cv ia, cv ib)
{
	mval *r = &m->val[ir];
	const mval *a = &m->val[ia], *b = ib >= 0 ? &m->val[ib] : NULL;
	const double u = m->zero_e ? 0.0 : unit_round(f), eta = m->zero_e ? 0.0 : tiny_of(f);
	exact = exact || m->zero_e;
	r->theta_free = exact && a->theta_free && (!b || b->theta_free);
	if (op == MVF_NEG || op == MVF_CVT || ((op == MVF_ADD || op == MVF_SUB) && b && is_zero(b))) {
		if (op == MVF_CVT && !exact)
			return;
		r->base = a->base;
		r->bsign = op == MVF_NEG ? -a->bsign : a->bsign;
		r->nonzero = a->nonzero;
		r->quantum = a->quantum;
		r->act_lo = a->act_lo;
		r->sub_a = a->sub_a;
		r->sub_b = a->sub_b;
		if (op == MVF_CVT && a->tg_p) {   /* an exact widening keeps the tag */
			memcpy(r->tg_b, a->tg_b, sizeof r->tg_b);
			r->tg_p = a->tg_p; r->tg_nb = a->tg_nb;
			r->tg_lo = a->tg_lo; r->tg_hi = a->tg_hi; r->tg_abs = a->tg_abs;
			r->tg_olo = a->tg_olo; r->tg_ohi = a->tg_ohi;
		}
		return;
	}
	if ((op == MVF_ADD || op == MVF_SUB) && b && is_zero(a) && exact) {
		r->base = b->base;
		r->bsign = op == MVF_SUB ? -b->bsign : b->bsign;
		r->nonzero = b->nonzero;
		r->quantum = b->quantum;
		r->act_lo = b->act_lo;
		return;
	}
	if (op == MVF_SUB && exact && r->theta_free) {   /* Sterbenz: on the grid of both */
		if (a->quantum > 0.0 && b->quantum > 0.0)
			r->quantum = a->quantum < b->quantum ? a->quantum : b->quantum;
		r->sub_a = ia;
		r->sub_b = ib;
		return;
	}
	if (op == MVF_MUL && ia == ib && a->theta_free) {   /* a^2 (1 + d) + eta */
		r->tg_p = 2; r->tg_nb = 1; r->tg_b[0] = a->base;
		r->tg_lo = exact ? 0.0 : -u; r->tg_hi = exact ? 0.0 : u;
		r->tg_abs = exact ? 0.0 : eta;
		r->tg_olo = r->tg_ohi = 0.0;
		return;
	}
	if (op == MVF_ADD && b && a->tg_p == 2 && b->tg_p == 2 && a->tg_nb + b->tg_nb <= 3) {
		int i, j;
		for (i = 0; i < a->tg_nb; i++)
			for (j = 0; j < b->tg_nb; j++)
				if (a->tg_b[i] == b->tg_b[j])
					return;
		r->tg_p = 2;
		r->tg_nb = a->tg_nb + b->tg_nb;
		memcpy(r->tg_b, a->tg_b, (size_t)a->tg_nb * sizeof *r->tg_b);
		memcpy(r->tg_b + a->tg_nb, b->tg_b, (size_t)b->tg_nb * sizeof *r->tg_b);
		/* S1 (1 + e1) + S2 (1 + e2) = (S1 + S2)(1 + e), e in hull(e1, e2) */
		r->tg_lo = rel_mul(m, fmin(a->tg_lo, b->tg_lo), exact ? 0.0 : -u, 0);
		r->tg_hi = rel_mul(m, fmax(a->tg_hi, b->tg_hi), exact ? 0.0 : u, 1);
		r->tg_abs = round_up_d(round_up_d(a->tg_abs + b->tg_abs) * (1.0 + 2 * u));
		if (!exact)
			r->tg_abs = round_up_d(r->tg_abs + eta);
		r->tg_olo = r->tg_ohi = 0.0;
		return;
	}
	if ((op == MVF_SQRT && a->tg_p == 2) || (op == MVF_DIV && is_cst(a, 1.0) && b && b->tg_p == 1)) {
		const mval *t = op == MVF_SQRT ? a : b;
		memcpy(r->tg_b, t->tg_b, sizeof r->tg_b);
		r->tg_nb = t->tg_nb;
		r->tg_lo = t->tg_lo; r->tg_hi = t->tg_hi; r->tg_abs = t->tg_abs;
		if (op == MVF_SQRT) {   /* a square root is normal or 0: relative */
			r->tg_p = 1;
			r->tg_olo = exact ? 0.0 : -u; r->tg_ohi = exact ? 0.0 : u;
		} else {                /* 1/l: the reciprocal of (1 + o), rounded */
			r->tg_p = -1;
			r->tg_olo = rel_div(m, exact ? 0.0 : -u, t->tg_ohi, 0);
			r->tg_ohi = rel_div(m, exact ? 0.0 : u, t->tg_olo, 1);
		}
	}
}

/* A lower bound on S = |a|^2 for the actual a of tag t (0: none known):
   each component's square at least mig^2 of its interval, or the square of
   what the branches and its grid say; and a length l >= act_lo > 0 known
   from a branch on it gives S (1 + eps) + alpha >= (act_lo / (1 + o))^2. */
/* Into m->f2 (rounded down): the sum over the values bases[0..nb-1] of
   the square of a lower bound on each one's magnitude, the mig of its
   interval or what the branches and its grid say (actual_lo). */
static void squares_lo(mvf *m, const cv *bases, int nb)
{
	int j, nz;
	mpfr_set_zero(m->f2, 1);
	for (j = 0; j < nb; j++) {
		const mval *b = &m->val[bases[j]];
		const double lo = actual_lo(m, b, &nz);
		mpfi_mig(m->f1, b->v);
		if (fi_cmp_d(m, m->f1, lo) < 0)
			mpfr_set_d(m->f1, lo, MPFR_RNDD);
		mpfr_sqr(m->f1, m->f1, MPFR_RNDD);
		mpfr_add(m->f2, m->f2, m->f1, MPFR_RNDD);
	}
}

static double norm_lact(mvf *m, const mval *t)
{
	squares_lo(m, t->tg_b, t->tg_nb);
	if (t->tg_p == 1 && t->act_lo > 0.0) {
		mpfr_set_d(m->f1, t->act_lo, MPFR_RNDD);
		mpfr_div_d(m->f1, m->f1, nextafter(1.0 + t->tg_ohi, INFINITY), MPFR_RNDD);
		mpfr_sqr(m->f1, m->f1, MPFR_RNDD);
		mpfr_sub_d(m->f1, m->f1, t->tg_abs, MPFR_RNDD);
		mpfr_div_d(m->f1, m->f1, nextafter(1.0 + t->tg_hi, INFINITY), MPFR_RNDD);
		if (mpfr_cmp(m->f1, m->f2) > 0)
			mpfr_set(m->f2, m->f1, MPFR_RNDD);
	}
	return mpfr_get_d(m->f2, MPFR_RNDD);
}

/* The common factor C of tag t's outputs, into m->s1: (1 + o)/sqrt(1 + e)
   for a reciprocal length (p = -1), 1/((1 + o) sqrt(1 + e)) for a length,
   e in [eps_lo - rho, eps_hi + rho], rho = alpha/S <= tg_abs/L.  0 when no
   bound (an absolute term and no lower bound on S). */
static int norm_factor(mvf *m, const mval *t)
{
	double rho = 0.0, L;
	if (t->tg_abs > 0.0) {
		L = norm_lact(m, t);
		if (!(L > 0.0))
			return 0;
		mpfr_set_d(m->f1, t->tg_abs, MPFR_RNDU);
		mpfr_div_d(m->f1, m->f1, L, MPFR_RNDU);
		rho = mpfr_get_d(m->f1, MPFR_RNDU);
	}
	mpfr_set_d(m->f1, t->tg_lo, MPFR_RNDD);
	mpfr_sub_d(m->f1, m->f1, rho, MPFR_RNDD);
	mpfr_add_ui(m->f1, m->f1, 1, MPFR_RNDD);
	mpfr_set_d(m->f2, t->tg_hi, MPFR_RNDU);
	mpfr_add_d(m->f2, m->f2, rho, MPFR_RNDU);
	mpfr_add_ui(m->f2, m->f2, 1, MPFR_RNDU);
	if (mpfr_sgn(m->f1) <= 0)
		return 0;
	mpfi_interv_fr(m->s1, m->f1, m->f2);
	mpfi_sqrt(m->s1, m->s1);                          /* sqrt(1 + e)      */
	fi_interv_d(m->s2, t->tg_olo, t->tg_ohi);
	mpfi_add_d(m->s2, m->s2, 1.0);                    /* 1 + o            */
	if (t->tg_p == -1) {
		mpfi_div(m->s1, m->s2, m->s1);
	} else {
		imul(m, m->s1, m->s1, m->s2);
		mpfi_inv(m->s1, m->s1);
	}
	return 1;
}

/* A lower bound on the length of (x, y) at the box's points u and at the
   points p = u + theta (n - u) (the angle between p and u is at most
   asin(|p - u| / r) for either length r): rr_lo, or from the inputs'
   intervals, which hold the p's and what the branches say of n (Eigen's
   |y| > 1e-5 |z|). */
static double planar_rr(mvf *m, const mval *t)
{
	mpfi_mig(m->f2, m->val[t->tg_b[0]].v);
	mpfr_sqr(m->f2, m->f2, MPFR_RNDD);
	mpfi_mig(m->p1, m->val[t->tg_b[1]].v);
	mpfr_sqr(m->p1, m->p1, MPFR_RNDD);
	mpfr_add(m->f2, m->f2, m->p1, MPFR_RNDD);
	mpfr_sqrt(m->f2, m->f2, MPFR_RNDD);
	return fmax(m->rr_lo, mpfr_get_d(m->f2, MPFR_RNDD));
}

/* 1 when norm_unit_phi applies to tag t: a is (n_x, n_y) up to order and
   signs, in a run with error terms. */
static int norm_planar(mvf *m, const mval *t)
{
	int i0, i1;
	if (m->zero_e || t->tg_nb != 2 || !(planar_rr(m, t) > 0.0))
		return 0;
	i0 = m->val[t->tg_b[0]].input;
	i1 = m->val[t->tg_b[1]].input;
	return (i0 == 0 && i1 == 1) || (i0 == 1 && i1 == 0);
}

/* Where a is (n_x, n_y) up to order and signs (Eigen's and LuxCore's
   (-y, x, 0)): a/|a| is the direction of (n_x, n_y), which lies within
   asin(d / r) of the box's azimuths, d = |(n_x - u_x, n_y - u_y)| <=
   |(nh_x, nh_y)| and r = |(u_x, u_y)| >= rr_lo (and so at every point
   u + theta (n - u) where the mean value form evaluates).  So n_x/|a| is
   in cos([phi_lo - D, phi_hi + D]) and n_y/|a| in sin(...), D = 1.05 d/rr_lo
   >= asin(d/rr_lo) for d/rr_lo <= 1/2.  Intersected into out (b_j/|a|,
   flipped by sign); nothing in the runs without error terms (their
   inputs are other points). */
static void norm_unit_phi(mvf *m, const mval *t, int j, int sign, mpfi_ptr out)
{
	const int ij = m->val[t->tg_b[j]].input;
	if (!norm_planar(m, t))
		return;
	mpfr_set_d(m->f1, m->nh[0], MPFR_RNDU);
	mpfr_sqr(m->f1, m->f1, MPFR_RNDU);
	mpfr_set_d(m->f2, m->nh[1], MPFR_RNDU);
	mpfr_sqr(m->f2, m->f2, MPFR_RNDU);
	mpfr_add(m->f1, m->f1, m->f2, MPFR_RNDU);
	mpfr_sqrt(m->f1, m->f1, MPFR_RNDU);
	mpfr_div_d(m->f1, m->f1, planar_rr(m, t), MPFR_RNDU);   /* d / rr */
	if (fi_cmp_d(m, m->f1, 0.5) > 0)
		return;
	mpfr_mul_d(m->f1, m->f1, 1.05, MPFR_RNDU);           /* D */
	mpfr_set_d(m->f2, m->phi_lo, MPFR_RNDD);
	mpfr_sub(m->f2, m->f2, m->f1, MPFR_RNDD);
	mpfr_add_d(m->f1, m->f1, m->phi_hi, MPFR_RNDU);
	mpfi_interv_fr(m->t3, m->f2, m->f1);
	if (ij == 0)
		mpfi_cos(m->t3, m->t3);
	else
		mpfi_sin(m->t3, m->t3);
	if (sign < 0)
		fi_neg(m->t3, m->t3);
	mpfi_intersect(m->t3, m->t3, out);
	if (mpfi_is_empty(m->t3)) {   /* no input of the box takes this path */
		m->no_point = 1;
		m->failed = 1;
		return;
	}
	fi_set(out, m->t3);
}

/* b_j / |a| over the box into out: its square from the squares of the
   components, P/(P + Q) (increasing in P, decreasing in Q), its sign from
   b_j's; sign flips it; then norm_unit_phi. */
static void norm_unit(mvf *m, const mval *t, int j, int sign, mpfi_ptr out)
{
	int k;
	mpfr_t plo, phi;
	mpfi_sqr(m->t1, m->val[t->tg_b[j]].v);            /* P */
	fi_set_d(m->t2, 0.0);
	for (k = 0; k < t->tg_nb; k++)
		if (k != j) {
			mpfi_sqr(m->t3, m->val[t->tg_b[k]].v);
			mpfi_add(m->t2, m->t2, m->t3);          /* Q */
		}
	mpfr_inits2(MV_PREC, plo, phi, (mpfr_ptr)0);
	mpfi_get_left(plo, m->t1);
	mpfi_get_right(m->f1, m->t2);
	mpfr_add(m->f1, m->f1, plo, MPFR_RNDU);
	if (mpfr_zero_p(plo) || !mpfr_number_p(m->f1))
		mpfr_set_zero(plo, 1);
	else
		mpfr_div(plo, plo, m->f1, MPFR_RNDD);
	mpfi_get_right(phi, m->t1);
	mpfi_get_left(m->f1, m->t2);
	mpfr_add(m->f1, m->f1, phi, MPFR_RNDD);
	if (mpfr_sgn(m->f1) <= 0)
		mpfr_set_ui(phi, 1, MPFR_RNDU);
	else
		mpfr_div(phi, phi, m->f1, MPFR_RNDU);
	if (mpfr_cmp_ui(phi, 1) > 0)
		mpfr_set_ui(phi, 1, MPFR_RNDU);
	mpfr_sqrt(plo, plo, MPFR_RNDD);
	mpfr_sqrt(phi, phi, MPFR_RNDU);
	{
		const int pos = mpfi_is_nonneg(m->val[t->tg_b[j]].v), neg = mpfi_is_nonpos(m->val[t->tg_b[j]].v);
		if ((pos && sign > 0) || (neg && !pos && sign < 0)) {
			mpfi_interv_fr(out, plo, phi);
		} else if (pos || neg) {
			mpfr_neg(plo, plo, MPFR_RNDN);
			mpfr_neg(phi, phi, MPFR_RNDN);
			mpfi_interv_fr(out, phi, plo);
		} else {
			mpfr_neg(plo, phi, MPFR_RNDN);
			mpfi_interv_fr(out, plo, phi);
		}
	}
	mpfr_clears(plo, phi, (mpfr_ptr)0);
	norm_unit_phi(m, t, j, sign, out);
}

/* The input terms' gradient of x = sign b_j / |a| (b_j the base of x),
   times the common factor's range cf, into r: (1/|a|)(dx - x sum_j'
   (b_j'/|a|) db_j').  Needs |a| > 0 over the whole box (the points between
   u and n too), from the intervals alone; else the input terms are lost
   (the full mean value form is then not used) or, in a centred run, the
   run fails. */
static void norm_in_grad(mvf *m, const mval *t, const mval *x, mpfi_srcptr ahat, mpfi_srcptr cf, mval *r)
{
	int j, k, ng = x->ng, any = 0;
	mpfi_t inv, g, h, bh[3];
	for (j = 0; j < t->tg_nb; j++)
		if (m->val[t->tg_b[j]].ng > ng)
			ng = m->val[t->tg_b[j]].ng;
	for (k = 0; k < ng && !any; k++) {
		any = k < x->ng && x->nz[k];
		for (j = 0; j < t->tg_nb && !any; j++)
			any = k < m->val[t->tg_b[j]].ng && m->val[t->tg_b[j]].nz[k];
	}
	if (!any)
		return;
	mpfi_init2(inv, MV_PREC); mpfi_init2(g, MV_PREC); mpfi_init2(h, MV_PREC);
	for (j = 0; j < 3; j++)
		mpfi_init2(bh[j], MV_PREC);
	fi_set_d(inv, 0.0);
	for (j = 0; j < t->tg_nb; j++) {
		mpfi_sqr(g, m->val[t->tg_b[j]].v);
		mpfi_add(inv, inv, g);
		norm_unit(m, t, j, 1, bh[j]);
	}
	if (!mpfi_is_strictly_pos(inv)) {
		if (m->centred)
			m->failed = 1;
		else
			m->grad_lost = 1;
	} else {
		mpfi_sqrt(inv, inv);
		mpfi_inv(inv, inv);                          /* 1/|a| */
		for (k = 0; k < ng; k++) {
			int used = k < x->ng && x->nz[k];
			fi_set_d(h, 0.0);
			for (j = 0; j < t->tg_nb; j++) {
				const mval *b = &m->val[t->tg_b[j]];
				if (k < b->ng && b->nz[k]) {
					imul(m, g, bh[j], b->g[k]);
					mpfi_add(h, h, g);
					used = 1;
				}
			}
			if (!used)
				continue;
			imul(m, h, h, ahat);
			if (k < x->ng && x->nz[k])
				mpfi_sub(h, x->g[k], h);
			else
				fi_neg(h, h);
			imul(m, h, h, inv);
			imul(m, h, h, cf);
			set_grad(r, k, h);
		}
	}
	mpfi_clear(inv); mpfi_clear(g); mpfi_clear(h);
	for (j = 0; j < 3; j++)
		mpfi_clear(bh[j]);
}

/* 1 when |a|^2 varies by less than a factor 4 over the box (the plain
   interval operations keep a_i / l tight there). */
static int norm_narrow(mvf *m, const mval *t)
{
	int j;
	fi_set_d(m->t2, 0.0);
	for (j = 0; j < t->tg_nb; j++) {
		mpfi_sqr(m->t3, m->val[t->tg_b[j]].v);
		mpfi_add(m->t2, m->t2, m->t3);
	}
	mpfi_get_left(m->f1, m->t2);
	mpfi_get_right(m->f2, m->t2);
	mpfr_div_2ui(m->f2, m->f2, 2, MPFR_RNDU);
	return mpfr_sgn(m->f1) > 0 && mpfr_cmp(m->f2, m->f1) < 0;
}

/* b = x / l or x * f with l, f a length or reciprocal length of a vector
   whose component x is (its base): b = (x/|a|) C, C the common factor;
   rounded once.  Returns 0 when the pattern does not apply. */
static int norm_out(mvf *m, int op, int f, cv ir, cv ia, cv ib)
{
	mval *r = &m->val[ir], *t, *x;
	mpfi_t ahat, cf;
	double gr;
	int j;
	if (op == MVF_DIV && m->val[ib].tg_p == 1) {
		x = &m->val[ia]; t = &m->val[ib];
	} else if (op == MVF_MUL && m->val[ib].tg_p == -1) {
		x = &m->val[ia]; t = &m->val[ib];
	} else if (op == MVF_MUL && m->val[ia].tg_p == -1) {
		x = &m->val[ib]; t = &m->val[ia];
	} else {
		return 0;
	}
	if (!x->theta_free || x->is_cst || is_zero(x) || x->opaque)
		return 0;
	if (!t->opaque && norm_narrow(m, t) && !norm_planar(m, t))
		return 0;   /* |a| nearly constant over the box: the plain operations do as well */
	for (j = 0; j < t->tg_nb && t->tg_b[j] != x->base; j++)
		;
	if (j == t->tg_nb || !norm_factor(m, t))
		return 0;
	mpfi_init2(ahat, MV_PREC);
	mpfi_init2(cf, MV_PREC);
	fi_set(cf, m->s1);                              /* C              */
	mpfi_sub_d(m->s2, cf, 1.0);
	mpfi_mag(m->f1, m->s2);
	gr = mpfr_get_d(m->f1, MPFR_RNDU);                /* |C - 1| <= gr  */
	norm_unit(m, t, j, x->bsign, ahat);
	if (!m->zero_e) {
		fi_interv_d(cf, -gr, gr);
		mpfi_add_d(cf, cf, 1.0);
	}
	imul(m, r->v, ahat, cf);
	r->fmt = f;
	r->theta_free = m->zero_e;
	if (!no_grad(m)) {
		if (!m->zero_e && gr > 0.0) {
			if (t->tg_var < 0)
				t->tg_var = new_var(m, gr);
			set_grad(r, t->tg_var, ahat);
		}
		norm_in_grad(m, t, x, ahat, cf, r);
	}
	mpfi_clear(ahat);
	mpfi_clear(cf);
	if (!m->failed)
		round_to(m, ir, f);
	return 1;
}

/* 1/l for a length l whose interval reaches 0 over the box: bounded by the
   lower bound on the actual |a|; its value only serves norm_out (opaque to
   every other operation: no gradient is kept). */
static int norm_recip(mvf *m, int f, cv ir, cv ia, cv ib)
{
	mval *r = &m->val[ir];
	const mval *l = &m->val[ib];
	double L;
	if (!is_cst(&m->val[ia], 1.0) || l->tg_p != 1 || !mpfi_has_zero(l->v))
		return 0;
	L = norm_lact(m, l);
	mpfr_set_d(m->f1, L, MPFR_RNDD);
	mpfr_set_d(m->f2, nextafter(1.0 + l->tg_lo, 0.0), MPFR_RNDD);   /* S (1 + e) + alpha */
	mpfr_mul(m->f1, m->f1, m->f2, MPFR_RNDD);
	mpfr_sub_d(m->f1, m->f1, l->tg_abs, MPFR_RNDD);
	if (mpfr_sgn(m->f1) <= 0)
		return 0;
	mpfr_sqrt(m->f1, m->f1, MPFR_RNDD);
	mpfr_mul_d(m->f1, m->f1, nextafter(1.0 + l->tg_olo, 0.0), MPFR_RNDD);
	mpfr_ui_div(m->f1, 1, m->f1, MPFR_RNDU);
	mpfr_mul_d(m->f1, m->f1, 1.0 + 2 * unit_round(f), MPFR_RNDU);
	mpfi_get_right(m->f2, l->v);
	mpfr_ui_div(m->f2, 1, m->f2, MPFR_RNDD);
	mpfr_mul_d(m->f2, m->f2, 1.0 - 2 * unit_round(f), MPFR_RNDD);
	mpfi_interv_fr(r->v, m->f2, m->f1);
	r->fmt = f;
	r->opaque = 1;
	if (may_overflow(m, r->v, f))
		return 1;
	track(m, MVF_DIV, f, 0, ir, ia, ib);
	return 1;
}

int mvf_nvar(const mvf *m) { return m->nvar; }

/* The input's own rounding terms are in_var; the arithmetic's the rest. */
double mvf_lin_arith(mvf *m, cv iq) { return mvf_lin_from(m, iq, 0); }

double mvf_lin_from(mvf *m, cv iq, int from)
{
	const mval *q = &m->val[iq];
	int k;
	if (m->failed)
		return INFINITY;
	mpfr_set_zero(m->f2, 1);
	for (k = from > 0 ? from : 0; k < q->ng; k++) {
		if (!q->nz[k] || m->in_var[k])
			continue;
		mpfi_mag(m->f1, q->g[k]);
		mpfr_mul_d(m->f1, m->f1, m->r[k], MPFR_RNDU);
		mpfr_add(m->f2, m->f2, m->f1, MPFR_RNDU);
	}
	return mpfr_get_d(m->f2, MPFR_RNDU);
}

int mvf_input_grad_ok(const mvf *m) { return !m->grad_lost; }

/* |n|^2 - 1 = 2 u.w + |w|^2 with |u| = 1 and |w_i| <= nh[i]: |2 u.w| is at
   most 2 sum max|U_i| nh[i] and 2 |w|; with a tolerance, |n| in [1 - T, 1 + T]. */
void mvf_norm_n(mvf *m, double *lo, double *hi)
{
	int i;
	if (m->tol >= 0.0) {
		mpfr_set_d(m->f1, 1.0 - m->tol, MPFR_RNDD);
		mpfr_sqr(m->f1, m->f1, MPFR_RNDD);
		mpfr_sub_ui(m->f1, m->f1, 1, MPFR_RNDD);
		*lo = mpfr_get_d(m->f1, MPFR_RNDD);
		mpfr_set_d(m->f1, m->tol, MPFR_RNDU);
		mpfr_add_ui(m->f1, m->f1, 1, MPFR_RNDU);
		mpfr_sqr(m->f1, m->f1, MPFR_RNDU);
		mpfr_sub_ui(m->f1, m->f1, 1, MPFR_RNDU);
		*hi = mpfr_get_d(m->f1, MPFR_RNDU);
		return;
	}
	mpfr_set_zero(m->f2, 1);                       /* sum max|U_i| nh[i] */
	for (i = 0; i < 3; i++) {
		mpfi_mag(m->f1, m->u[i]);
		mpfr_mul_d(m->f1, m->f1, m->nh[i], MPFR_RNDU);
		mpfr_add(m->f2, m->f2, m->f1, MPFR_RNDU);
	}
	mpfr_set_zero(m->f1, 1);                       /* |w|^2 */
	for (i = 0; i < 3; i++) {
		mpfr_t t;
		mpfr_init2(t, MV_PREC);
		mpfr_set_d(t, m->nh[i], MPFR_RNDU);
		mpfr_sqr(t, t, MPFR_RNDU);
		mpfr_add(m->f1, m->f1, t, MPFR_RNDU);
		mpfr_clear(t);
	}
	*hi = mpfr_get_d(m->f1, MPFR_RNDU);            /* |w|^2, for now */
	mpfr_sqrt(m->f1, m->f1, MPFR_RNDU);
	if (mpfr_cmp(m->f1, m->f2) < 0)
		mpfr_set(m->f2, m->f1, MPFR_RNDU);
	mpfr_mul_2ui(m->f2, m->f2, 1, MPFR_RNDU);      /* |2 u.w| */
	*lo = -mpfr_get_d(m->f2, MPFR_RNDU);
	mpfr_add_d(m->f2, m->f2, *hi, MPFR_RNDU);
	*hi = mpfr_get_d(m->f2, MPFR_RNDU);
}

/* The length of a tagged sum of squares that reaches 0 over the box: its
   value (the square root's rounding included), without a gradient (the
   square root's is unbounded at 0); only norm_out and norm_recip use it. */
static int norm_sqrt(mvf *m, int f, cv ir, cv ia)
{
	mval *r = &m->val[ir];
	const mval *a = &m->val[ia];
	const double u = m->zero_e ? 0.0 : unit_round(f);
	if (a->tg_p != 2 || mpfi_is_strictly_pos(a->v))
		return 0;
	fi_interv_d(m->t1, 0.0, INFINITY);
	mpfi_intersect(r->v, a->v, m->t1);
	if (mpfi_is_empty(r->v) || !mpfi_bounded_p(r->v))
		return 0;
	mpfi_sqrt(r->v, r->v);
	fi_interv_d(m->t1, -u, u);
	mpfi_add_d(m->t1, m->t1, 1.0);
	imul(m, r->v, r->v, m->t1);
	r->fmt = f;
	r->opaque = 1;
	track(m, MVF_SQRT, f, 0, ir, ia, -1);
	return 1;
}

/* A contracted sum of squares, fma(a, a, d) with d a tagged sum of squares
   of other bases: a^2 is exact inside the fma, so
   RN(a^2 + S_d (1 + e_d) + t) = (S_a + S_d)(1 + e')(1 + delta) + t' with e'
   in hull(0, e_d): the tag that ADD gives a^2 (1 + d1) + S_d (1 + e_d),
   with d1 = 0.  Without it the length of (x, y) near a pole, an fma in a
   contracted build, holds 0 and its reciprocal is unbounded. */
static cv op_value(mvf *m, int op, int f, cv ia, cv ib, cv id);

static void fma_square_tag(mvf *m, int f, int exact, cv ir, cv ia, cv ib, cv id)
{
	mval *r = &m->val[ir];
	const mval *a = &m->val[ia], *d = &m->val[id];
	const double u = m->zero_e ? 0.0 : unit_round(f), eta = m->zero_e ? 0.0 : tiny_of(f);
	int i;
	exact = exact || m->zero_e;
	if (ia != ib || !a->theta_free || d->tg_p != 2 || d->tg_nb > 2)
		return;
	for (i = 0; i < d->tg_nb; i++)
		if (d->tg_b[i] == a->base)
			return;
	r->tg_p = 2;
	r->tg_nb = d->tg_nb + 1;
	memcpy(r->tg_b, d->tg_b, (size_t)d->tg_nb * sizeof *r->tg_b);
	r->tg_b[d->tg_nb] = a->base;
	r->tg_lo = rel_mul(m, fmin(0.0, d->tg_lo), exact ? 0.0 : -u, 0);
	r->tg_hi = rel_mul(m, fmax(0.0, d->tg_hi), exact ? 0.0 : u, 1);
	r->tg_abs = round_up_d(d->tg_abs * (1.0 + 2 * u));
	if (!exact)
		r->tg_abs = round_up_d(r->tg_abs + eta);
	r->tg_olo = r->tg_ohi = 0.0;
}

/* A length tag's sum of squares a^2 (1 + d) + eta, or fma(a, a, c) and
   a + c for a tagged c (terms >= 0: S1 (1 + e1) + S2 (1 + e2) = (S1 + S2)
   (1 + e), e in hull(e1, e2)); 0 when a's base is among c's already. */
static int len_square(mvf *m, mval *r, const mval *c, cv base, double u, double eta)
{
	int i;
	if (c->ls_nb + 1 > 3)
		return 0;
	for (i = 0; i < c->ls_nb; i++)
		if (c->ls_b[i] == base)
			return 0;
	memcpy(r->ls_b, c->ls_b, sizeof r->ls_b);
	r->ls_b[c->ls_nb] = base;
	r->ls_nb = c->ls_nb + 1;
	r->ls_lo = rel_mul(m, fmin(0.0, c->ls_lo), -u, 0);
	r->ls_hi = rel_mul(m, fmax(0.0, c->ls_hi), u, 1);
	r->ls_abs = round_up_d(round_up_d(c->ls_abs * (1.0 + 2 * u)) + eta);
	r->ls_p = 2;
	return 1;
}

static int len_add(mvf *m, mval *r, const mval *a, const mval *b, double u, double eta)
{
	int i, j;
	if (a->ls_nb + b->ls_nb > 3)
		return 0;
	for (i = 0; i < a->ls_nb; i++)
		for (j = 0; j < b->ls_nb; j++)
			if (a->ls_b[i] == b->ls_b[j])
				return 0;
	memcpy(r->ls_b, a->ls_b, (size_t)a->ls_nb * sizeof *r->ls_b);
	memcpy(r->ls_b + a->ls_nb, b->ls_b, (size_t)b->ls_nb * sizeof *r->ls_b);
	r->ls_nb = a->ls_nb + b->ls_nb;
	r->ls_lo = rel_mul(m, fmin(a->ls_lo, b->ls_lo), -u, 0);
	r->ls_hi = rel_mul(m, fmax(a->ls_hi, b->ls_hi), u, 1);
	r->ls_abs = round_up_d(round_up_d(round_up_d(a->ls_abs + b->ls_abs) * (1.0 + 2 * u)) + eta);
	r->ls_p = 2;
	return 1;
}

/* A reciprocal length (1 + o)/sqrt(x) of a tagged sum of squares x. */
static void len_recip(mval *r, cv ix, double olo, double ohi)
{
	r->ls_p = -1;
	r->ls_x = ix;
	r->ls_olo = olo;
	r->ls_ohi = ohi;
}

/* The length tags after r = op(a, b, d), each operation taken as rounded
   (an exact one is a rounding with d = 0): squares and their sums, square
   roots, reciprocals, and the outputs q K, q / L of a tagged K, L. */
static void len_track(mvf *m, int op, int f, cv ir, cv ia, cv ib, cv id)
{
	mval *r = &m->val[ir];
	const mval *a = &m->val[ia], *b = ib >= 0 ? &m->val[ib] : NULL, *d = id >= 0 ? &m->val[id] : NULL;
	const double u = unit_round(f), eta = tiny_of(f);
	static const mval none = { .ls_nb = 0, .ls_lo = 0.0, .ls_hi = 0.0, .ls_abs = 0.0 };
	if (m->failed || m->zero_e)
		return;
	if (op == MVF_NEG || (op == MVF_CVT && val_in(a, f))) {   /* exact: the same lengths */
		r->ls_k = a->ls_k; r->ls_q = a->ls_q; r->ls_u = a->ls_u; r->ls_eta = a->ls_eta;
		r->ls_qv = a->ls_qv; r->ls_sg = op == MVF_NEG ? -a->ls_sg : a->ls_sg;
		if (op == MVF_CVT) {
			r->ls_p = a->ls_p; r->ls_nb = a->ls_nb; r->ls_x = a->ls_x;
			memcpy(r->ls_b, a->ls_b, sizeof r->ls_b);
			r->ls_lo = a->ls_lo; r->ls_hi = a->ls_hi; r->ls_abs = a->ls_abs;
			r->ls_olo = a->ls_olo; r->ls_ohi = a->ls_ohi;
		}
		return;
	}
	if (op == MVF_CVT) {   /* a rounded narrowing: x (1 + d) + eta, K (1 + d) */
		if (a->ls_p == 2) {
			memcpy(r->ls_b, a->ls_b, sizeof r->ls_b);
			r->ls_nb = a->ls_nb;
			r->ls_lo = rel_mul(m, a->ls_lo, -u, 0);
			r->ls_hi = rel_mul(m, a->ls_hi, u, 1);
			r->ls_abs = round_up_d(round_up_d(a->ls_abs * (1.0 + 2 * u)) + eta);
			r->ls_p = 2;
		} else if (a->ls_p == 1 || a->ls_p == -1) {
			mpfi_mig(m->f1, a->v);
			if (fi_cmp_d(m, m->f1, normal_min(f)) >= 0) {
				len_recip(r, a->ls_x, rel_mul(m, a->ls_olo, -u, 0), rel_mul(m, a->ls_ohi, u, 1));
				r->ls_p = a->ls_p;
			}
		}
	} else if (op == MVF_MUL && ia == ib)
		len_square(m, r, &none, a->base, u, eta);
	else if (op == MVF_FMA && ia == ib && d->ls_p == 2)
		len_square(m, r, d, a->base, u, eta);
	else if (op == MVF_ADD && a->ls_p == 2 && b->ls_p == 2)
		len_add(m, r, a, b, u, eta);
	else if (op == MVF_SQRT && a->ls_p == 2) {
		len_recip(r, ia, -u, u);
		r->ls_p = 1;
	} else if (op == MVF_DIV && is_cst(a, 1.0) && b->ls_p == 1)
		len_recip(r, b->ls_x, rel_div(m, -u, b->ls_ohi, 0), rel_div(m, u, b->ls_olo, 1));
	else if ((op == MVF_MUL && (b->ls_p == -1 || a->ls_p == -1)) || (op == MVF_DIV && b->ls_p == 1)) {
		const int k_is_a = op == MVF_MUL && b->ls_p != -1;
		r->ls_k = k_is_a ? ia : ib;
		r->ls_q = k_is_a ? b->base : a->base;
		r->ls_qv = k_is_a ? ib : ia;
		r->ls_sg = 1;
		r->ls_u = u;
		r->ls_eta = eta;
	}
}

static cv prof_op(mvf *m, int op, int f, cv ia, cv ib, cv id);
cv mvf_op(mvf *m, int op, int f, cv ia, cv ib, cv id)
{
	cv ir;
	if (m->ar)
		return prof_op(m, op, f, ia, ib, id);
	ir = op_value(m, op, f, ia, ib, id);
	len_track(m, op, f, ir, ia, ib, id);
	return ir;
}

static cv op_value(mvf *m, int op, int f, cv ia, cv ib, cv id)
{
	cv ir = fresh(m, f);
	mval *r = &m->val[ir];
	const mval *a = &m->val[ia], *b = ib >= 0 ? &m->val[ib] : NULL, *d = id >= 0 ? &m->val[id] : NULL;
	int exact = 1;
	if (m->failed)
		return ir;
	if ((op == MVF_MUL || op == MVF_DIV) && (norm_out(m, op, f, ir, ia, ib) || (op == MVF_DIV && norm_recip(m, f, ir, ia, ib))))
		return ir;
	if (op == MVF_SQRT && norm_sqrt(m, f, ir, ia))
		return ir;
	if (a->opaque || (b && b->opaque) || (d && d->opaque)) {
		m->failed = 1;   /* a value bounded without its gradient */
		return ir;
	}
	if (!exact_eval(m, op, r, a, b, d) || mpfi_nan_p(r->v) || !mpfi_bounded_p(r->v)) {
		m->failed = 1;
		return ir;
	}
	if (op != MVF_NEG && may_overflow(m, r->v, f))
		return ir;
	if (op == MVF_NEG) {
		r->fmt = a->fmt;
	} else if (!exact_op(m, op, f, a, b, r)) {
		exact = 0;
		round_to_cap(m, ir, f, op == MVF_ADD || op == MVF_SUB ? round_sum_cap(m, a, b, f) : INFINITY);
	} else if ((op == MVF_ADD || op == MVF_SUB) && (is_zero(a) || is_zero(b))) {
		r->fmt = is_zero(a) ? b->fmt : a->fmt;   /* +-v itself */
	} else if (op == MVF_CVT) {
		/* a widening keeps the value a float (so a product of two
		   widened floats in double is exact), and a seed a seed */
		if (fmt_in(a->fmt, r->fmt))
			r->fmt = a->fmt;
		r->rsqrt_of = a->rsqrt_of;
		r->seed_k = a->seed_k;
		r->rel_lo = a->rel_lo;
		r->rel_hi = a->rel_hi;
	}
	if (op == MVF_CVT && f == PREC_FLOAT && a->fmt == PREC_DOUBLE) {
		mpfi_mig(m->f1, a->v);
		if (fi_cmp_d(m, m->f1, normal_min(PREC_FLOAT)) >= 0) {
			r->cvt_of = ia;
			r->cvt_u = unit_round(PREC_FLOAT);
		}
	}
	if (op == MVF_CVT && f == PREC_FLOAT && a->fmt == PREC_HALF) {   /* the float of a half x: x itself */
		r->cvt_of = ia;
		r->cvt_u = 0.0;
	}
	if (op == MVF_CVT && f == PREC_HALF && !exact && a->rsqrt_of >= 0) {
		/* a float seed of 1/sqrt(x) rounded to half (the half kernels'
		   invsqrt and rsqrt): r (1 + d)/sqrt(x), |d| <= u where normal */
		mpfi_mig(m->f1, r->v);
		if (fi_cmp_d(m, m->f1, normal_min(f)) >= 0) {
			r->rsqrt_of = a->rsqrt_of;
			r->seed_k = a->seed_k;
			r->rel_lo = rel_mul(m, a->rel_lo - 1.0, -unit_round(f), 0) + 1.0;
			r->rel_hi = rel_mul(m, a->rel_hi - 1.0, unit_round(f), 1) + 1.0;
			r->rel_lo = nextafter(r->rel_lo, 0.0);
			r->rel_hi = nextafter(r->rel_hi, INFINITY);
		}
	}
	track(m, op, f, exact, ir, ia, ib);
	if (op == MVF_FMA)
		fma_square_tag(m, f, exact, ir, ia, ib, id);
	return ir;
}

/* With every e 0, an approximate 1/sqrt(a) is 1/sqrt(a) (in m->s1 on
   entry), with its gradient -1/(2 a sqrt(a)) in a centred run. */
static void exact_rsqrt(mvf *m, mval *r, const mval *a)
{
	fi_set(r->v, m->s1);
	mpfi_div(m->s2, m->s1, a->v);
	mpfi_div_2ui(m->s2, m->s2, 1);
	fi_neg(m->s2, m->s2);
	grad_lin(m, r, a, m->s2, NULL, NULL);
}

cv mvf_seed(mvf *m, seed_kind k, cv ia)
{
	int f = k == SEED_INVSQRT_D ? PREC_DOUBLE : PREC_FLOAT;
	cv ir = fresh(m, f);
	mval *r = &m->val[ir];
	const mval *a = &m->val[ia];
	seed_bound sb;
	if (m->failed)
		return ir;
	mpfi_get_left(m->f1, a->v);
	mpfi_get_right(m->f2, a->v);
	if (seed_bound_get(k, &sb) != 0 || fi_cmp_d(m, m->f1, sb.x_lo) < 0 || fi_cmp_d(m, m->f2, sb.x_hi) > 0) {
		m->failed = 1; /* outside the inputs whose seed error was bounded */
		return ir;
	}
	mpfi_sqrt(m->s1, a->v);                          /* 1/sqrt(a)               */
	mpfi_inv(m->s1, m->s1);
	fi_interv_d(m->t1, 1.0 - sb.bound, 1.0 + sb.bound);
	imul(m, r->v, m->s1, m->t1);                    /* (1 + e)/sqrt(a)         */
	r->rsqrt_of = ia;
	r->seed_k = (int)k;
	r->rel_lo = 1.0 - sb.bound;
	r->rel_hi = 1.0 + sb.bound;
	if (m->zero_e) {
		exact_rsqrt(m, r, a);
		return ir;
	}
	if (a->ls_p == 2)
		len_recip(r, ia, -sb.bound, sb.bound);
	mpfi_div(m->s2, r->v, a->v);                     /* d/da = -(1 + e)/(2 a^1.5) */
	mpfi_div_2ui(m->s2, m->s2, 1);
	fi_neg(m->s2, m->s2);
	grad_lin(m, r, a, m->s2, NULL, NULL);
	set_grad(r, new_var(m, sb.bound), m->s1);        /* d/de = 1/sqrt(a)        */
	return ir;
}

static int empty_br(const mval *x) { return x->has_br && mpfi_is_empty(x->br); }

void mvf_compare(mvf *m, int op, int absolute, cv ia, cv ib, int *can_true, int *can_false)
{
	mpfi_srcptr a = m->val[ia].has_br ? m->val[ia].br : m->val[ia].v;
	mpfi_srcptr b = m->val[ib].has_br ? m->val[ib].br : m->val[ib].v;
	if (empty_br(&m->val[ia]) || empty_br(&m->val[ib])) {
		*can_true = *can_false = 0;
		return;
	}
	if (absolute) {
		mpfi_abs(m->s1, a);
		mpfi_abs(m->s2, b);
		a = m->s1;
		b = m->s2;
	}
	if (op == CM_GT) { /* a > b */
		mpfi_srcptr t = a;
		a = b;
		b = t;
	}
	/* a < b possible when min a < max b; false possible when max a >= min b */
	mpfi_get_left(m->f1, a);
	mpfi_get_right(m->f2, b);
	*can_true = mpfr_cmp(m->f1, m->f2) < 0;
	mpfi_get_right(m->f1, a);
	mpfi_get_left(m->f2, b);
	*can_false = mpfr_cmp(m->f1, m->f2) >= 0;
}

void mvf_sign_possible(mvf *m, cv ia, int *can_set, int *can_clear)
{
	mpfi_srcptr a = m->val[ia].has_br ? m->val[ia].br : m->val[ia].v;
	if (empty_br(&m->val[ia])) {
		*can_set = *can_clear = 0;
		return;
	}
	mpfi_get_left(m->f1, a);
	mpfi_get_right(m->f2, a);
	*can_set = mpfr_sgn(m->f1) <= 0;   /* -0 possible wherever 0 is */
	*can_clear = mpfr_sgn(m->f2) >= 0;
}

/* Start a run over box b: the inputs n_i = u_i (1 + d_i) + eta_i, or
   u_i (1 + t) with |t| <= tolerance when tolerance >= 0. */
static void band_constraint(mvf *m, const mvf_box *b, cv iz);
static void refine_input(mvf *m, mval *x);
static void input_errors(mvf *m, const mvf_box *b, cv in[3]);
static void centre_inputs(mvf *m, int mode, const cv in[3]);
static void input_grid(mvf *m, const mvf_box *b, const cv in[3]);

/* The inputs' exact values over box b into in[]: u.z, and
   (u.x, u.y) = r (cos phi, sin phi) with r = sqrt(1 - z^2); rr_lo, the
   smallest r.  Every path and mode of a box computes the same (the
   interval sine and cosine cost a fifth of bounding a box), so the last
   box's values, and the scratch they leave, are kept and copied. */
static void box_geometry(mvf *m, const mvf_box *b, const cv in[3])
{
	const double key[8] = { b->z_lo, b->z_hi, b->phi_lo, b->phi_hi, b->zpoint, b->dz_lo, b->dz_hi,
	                        (double)b->has_zpoint };
	int i;
	m->phi_lo = b->phi_lo;
	m->phi_hi = b->phi_hi;
	if (m->geo_ok && memcmp(key, m->geo_key, sizeof key) == 0) {
		for (i = 0; i < 3; i++)
			fi_set(m->val[in[i]].v, m->geo_in[i]);
		fi_set(m->t1, m->geo_t1);
		fi_set(m->t2, m->geo_t2);
		fi_set(m->s1, m->geo_s1);
		fi_set(m->s2, m->geo_s2);
		mpfr_set(m->f1, m->geo_f1, MPFR_RNDN);
		if (b->has_zpoint)
			mpfr_set(m->f2, m->geo_f2, MPFR_RNDN);
		m->rr_lo = m->geo_rr_lo;
		return;
	}
	if (b->has_zpoint) {   /* zpoint + [dz_lo, dz_hi], rounded outward */
		mpfr_set_d(m->f1, b->zpoint, MPFR_RNDN);
		mpfr_add_d(m->f1, m->f1, b->dz_lo, MPFR_RNDD);
		mpfr_set_d(m->f2, b->zpoint, MPFR_RNDN);
		mpfr_add_d(m->f2, m->f2, b->dz_hi, MPFR_RNDU);
		mpfi_interv_fr(m->t1, m->f1, m->f2);
	} else {
		fi_interv_d(m->t1, b->z_lo, b->z_hi);             /* z             */
	}
	/* 1 - z^2 two ways, both enclosures: (1 - z)(1 + z) keeps its relative
	   accuracy near the poles, 1 - z^2 (one use of z) is tight near the
	   equator, where the product's two factors move against each other */
	mpfi_d_sub(m->s1, 1.0, m->t1);
	mpfi_add_d(m->s2, m->t1, 1.0);
	imul(m, m->s1, m->s1, m->s2);
	mpfi_sqr(m->s2, m->t1);
	mpfi_d_sub(m->s2, 1.0, m->s2);
	mpfi_intersect(m->s1, m->s1, m->s2);
	fi_interv_d(m->s2, 0.0, 1.0);                         /* |z| <= 1      */
	mpfi_intersect(m->s1, m->s1, m->s2);
	if (mpfi_is_empty(m->s1))
		fi_interv_d(m->s1, 0.0, 1.0);
	mpfi_sqrt(m->s1, m->s1);                                /* r = sqrt(1 - z^2) */
	mpfi_get_left(m->f1, m->s1);
	m->rr_lo = mpfr_get_d(m->f1, MPFR_RNDD);
	if (b->has_zpoint)
		fi_set_d(m->val[in[2]].v, b->zpoint);   /* exact: no error term */
	else
		fi_set(m->val[in[2]].v, m->t1);
	fi_interv_d(m->t2, b->phi_lo, b->phi_hi);             /* phi, radians  */
	mpfi_cos(m->s2, m->t2);
	imul(m, m->val[in[0]].v, m->s1, m->s2);
	mpfi_sin(m->s2, m->t2);
	imul(m, m->val[in[1]].v, m->s1, m->s2);
	for (i = 0; i < 3; i++)
		fi_set(m->geo_in[i], m->val[in[i]].v);
	fi_set(m->geo_t1, m->t1);
	fi_set(m->geo_t2, m->t2);
	fi_set(m->geo_s1, m->s1);
	fi_set(m->geo_s2, m->s2);
	mpfr_set(m->geo_f1, m->f1, MPFR_RNDN);
	mpfr_set(m->geo_f2, m->f2, MPFR_RNDN);
	m->geo_rr_lo = m->rr_lo;
	memcpy(m->geo_key, key, sizeof key);
	m->geo_ok = 1;
}

void mvf_begin(mvf *m, const mvf_box *b, int mode, cv in[3])
{
	int i;
	m->n = 0;
	m->nvar = 0;
	m->failed = 0;
	m->overflow = 0;
	m->no_point = 0;
	m->grad_lost = 0;
	m->unb_op = -1;
	m->lost_op = -1;
	m->nst = 0;
	m->tol = b->tolerance;
	m->nh[0] = m->nh[1] = m->nh[2] = 0.0;
	m->zero_e = mode == MVF_AT_ZERO || mode == MVF_AT_MID || mode == MVF_CENTRED;
	m->centred = mode == MVF_CENTRED;
	m->nograd = mode == MVF_VALUES;
	for (i = 0; i < 3; i++) {
		in[i] = fresh(m, b->prec);
		m->val[in[i]].theta_free = 1;
	}
	box_geometry(m, b, in);
	for (i = 0; i < 3; i++) {
		m->val[in[i]].input = i;
		fi_set(m->u[i], m->val[in[i]].v);
	}
	m->val[in[2]].input = b->has_zpoint ? -1 : 2;
	if (mode == MVF_AT_MID || mode == MVF_CENTRED)
		centre_inputs(m, mode, in);
	if (m->zero_e)
		return;   /* Q(U, 0) along a given path: no decision is made */
	input_errors(m, b, in);
	band_constraint(m, b, in[2]);
	input_grid(m, b, in);
}

/* What the actual inputs are: format values (multiples of the ulp of the
   smallest binade their interval reaches), functions of n alone; and for
   n.z given, |n.z - u.z| <= max(-dz_lo, dz_hi). */
static void input_grid(mvf *m, const mvf_box *b, const cv in[3])
{
	const int p = fmt_of(b->prec)->bits;
	int i;
	for (i = 0; i < 3; i++) {
		mval *x = &m->val[in[i]];
		mpfi_mig(m->f1, x->v);
		if (fi_cmp_d(m, m->f1, normal_min(b->prec)) < 0)
			x->quantum = fmt_of(b->prec)->sub_step;
		else
			x->quantum = ldexp(1.0, (int)mpfr_get_exp(m->f1) - p);
	}
	if (b->has_zpoint)
		m->nh[2] = fmax(-b->dz_lo, b->dz_hi);
}

/* The inputs for the centred form of Q(U, 0) (bound.c): u = c + t with c
   the midpoint of the box of (x, y, z) and t an offset variable per input
   that is an interval, |t_i| <= the half-width.  MVF_AT_MID sets each
   input to c_i; MVF_CENTRED keeps U_i and gives it the gradient 1 in t_i. */
static void centre_inputs(mvf *m, int mode, const cv in[3])
{
	int i;
	for (i = 0; i < 3; i++) {
		mval *x = &m->val[in[i]];
		double r;
		mpfi_get_left(m->f1, x->v);
		mpfi_get_right(m->f2, x->v);
		if (mpfr_equal_p(m->f1, m->f2))   /* n.z given: exact */
			continue;
		mpfi_mid(m->f1, x->v);
		if (mode == MVF_AT_MID) {
			mpfi_set_fr(x->v, m->f1);
			continue;
		}
		mpfi_get_right(m->f2, x->v);
		mpfr_sub(m->f2, m->f2, m->f1, MPFR_RNDU);
		r = mpfr_get_d(m->f2, MPFR_RNDU);
		mpfi_get_left(m->f2, x->v);
		mpfr_sub(m->f2, m->f1, m->f2, MPFR_RNDU);
		r = fmax(r, mpfr_get_d(m->f2, MPFR_RNDU));
		set_grad(x, new_var(m, r), m->one);
		if (x->ng > 0)
			m->in_var[x->ng - 1] = 1;
	}
}

/* n.z lies in the region's band: branch decisions on it may know that. */
static void band_constraint(mvf *m, const mvf_box *b, cv iz)
{
	mval *z = &m->val[iz];
	fi_interv_d(m->t1, b->nz_lo, b->nz_hi);
	mpfi_intersect(z->br, z->v, m->t1);
	z->has_br = 1;  /* empty: no input of the box is in the band, no path */
	refine_input(m, z);
}

/* An input's value for the arithmetic after a constraint: the mean value
   form evaluates the model at n_i(theta e) = u_i + theta w_i, between u_i
   and the actual n_i; the actual n_i lies in br, and |w_i| <= in_h, so
   u_i lies in U_i and within in_h of br: the hull of that and br encloses
   every point the form needs (a branch on n.y near -1 then keeps the u.y
   below the threshold out of the formula's side). */
static void refine_input(mvf *m, mval *x)
{
	if (x->input < 0 || !x->has_br || mpfi_is_empty(x->br))
		return;
	fi_set(m->t2, m->u[x->input]);
	if (x->in_h > 0.0) {
		fi_interv_d(m->t3, -x->in_h, x->in_h);
		mpfi_add(m->t3, m->t3, x->br);
		mpfi_intersect(m->t3, m->t3, m->t2);
		if (!mpfi_is_empty(m->t3))
			fi_set(m->t2, m->t3);
	}
	mpfi_union(m->t2, m->t2, x->br);
	mpfi_intersect(x->v, x->v, m->t2);
}

/* After a branch found a length l = (S (1 + eps) + rho S)^(1/2) (1 + o)
   (a norm tag, p = 1) at most hi(b): S <= ((hi(b)/(1 + o))^2 + |rho S|) /
   (1 + eps), so every input among its bases has |n_i| <= sqrt of that
   (LuxCore's fallback |(x, y)| < 1e-5: |n.x| <= 1e-5 there, not the box's
   |x|). */
static void constrain_length(mvf *m, const mval *t, const mval *b)
{
	int j;
	if (!(1.0 + t->tg_olo > 0.0) || !(1.0 + t->tg_lo > 0.0))
		return;
	mpfi_get_right(m->f1, b->v);
	if (mpfr_sgn(m->f1) < 0 || !mpfr_number_p(m->f1))
		return;
	mpfr_set_d(m->f2, t->tg_olo, MPFR_RNDD);
	mpfr_add_ui(m->f2, m->f2, 1, MPFR_RNDD);
	mpfr_div(m->f1, m->f1, m->f2, MPFR_RNDU);
	mpfr_sqr(m->f1, m->f1, MPFR_RNDU);
	mpfr_add_d(m->f1, m->f1, t->tg_abs, MPFR_RNDU);
	mpfr_set_d(m->f2, t->tg_lo, MPFR_RNDD);
	mpfr_add_ui(m->f2, m->f2, 1, MPFR_RNDD);
	mpfr_div(m->f1, m->f1, m->f2, MPFR_RNDU);
	mpfr_sqrt(m->f1, m->f1, MPFR_RNDU);                   /* |n_i| <= s */
	mpfr_neg(m->f2, m->f1, MPFR_RNDD);
	for (j = 0; j < t->tg_nb; j++) {
		mval *x = &m->val[t->tg_b[j]];
		if (x->input < 0)
			continue;
		mpfi_interv_fr(m->t1, m->f2, m->f1);
		if (!x->has_br) {
			fi_set(x->br, x->v);
			x->has_br = 1;
		}
		mpfi_intersect(x->br, x->br, m->t1);
		refine_input(m, x);
	}
}

/* After a branch on input a against b took `side`: the input's possible
   values know it.  op CM_LT: a < b (side 1) or a >= b (side 0); CM_GT:
   a > b or a <= b; absolute: the same of |a| and |b|.  b's interval holds
   its actual value, and a's the actual input, so a > b gives a >= lo(b),
   a <= b gives a <= hi(b), |a| <= |b| gives |a| <= mag(b), and |a| > |b|
   gives |a| >= g = mig(b): a >= g where a > -g, a <= -g where a < g. */
void mvf_constrain(mvf *m, int op, int absolute, cv ia, cv ib, int side)
{
	mval *a = &m->val[ia];
	const mval *b = &m->val[ib];
	const int below = (op == CM_LT) == (side != 0);   /* a <= b on this side */
	if (m->zero_e || m->failed || mpfi_nan_p(b->v) || mpfi_is_empty(b->v))
		return;
	if (a->input < 0) {
		if (a->tg_p == 1 && below)
			constrain_length(m, a, b);
		return;
	}
	mpfr_set_inf(m->f1, -1);
	mpfr_set_inf(m->f2, 1);
	if (!absolute && below) {
		mpfi_get_right(m->f2, b->v);
	} else if (!absolute) {
		mpfi_get_left(m->f1, b->v);
	} else if (below) {
		mpfi_mag(m->f2, b->v);
		mpfr_neg(m->f1, m->f2, MPFR_RNDD);
	} else {
		mpfi_mig(m->f1, b->v);                        /* g */
		mpfr_neg(m->f2, m->f1, MPFR_RNDD);            /* -g, exact */
		if (mpfr_cmp(&a->v->left, m->f2) > 0)
			mpfr_set_inf(m->f2, 1);               /* [g, inf) */
		else if (mpfr_cmp(&a->v->right, m->f1) < 0)
			mpfr_set_inf(m->f1, -1);              /* (-inf, -g] */
		else
			return;
	}
	mpfi_interv_fr(m->t1, m->f1, m->f2);
	if (!a->has_br) {
		fi_set(a->br, a->v);
		a->has_br = 1;
	}
	mpfi_intersect(a->br, a->br, m->t1);
	refine_input(m, a);
}

/* The same for the sign bit of input a (set: a <= 0, clear: a >= 0). */
void mvf_constrain_sign(mvf *m, cv ia, int set)
{
	mval *a = &m->val[ia];
	if (a->input < 0 || m->zero_e)
		return;
	fi_interv_d(m->t1, set ? -INFINITY : 0.0, set ? 0.0 : INFINITY);
	if (!a->has_br) {
		fi_set(a->br, a->v);
		a->has_br = 1;
	}
	mpfi_intersect(a->br, a->br, m->t1);
	refine_input(m, a);
}

int mvf_zero_e(const mvf *m) { return m->zero_e; }


/* The inputs' error terms: n_i = u_i (1 + d_i) + eta_i, or u_i (1 + t). */
static void input_errors(mvf *m, const mvf_box *b, cv in[3])
{
	double u = unit_round(b->prec);
	int i, t_var = -1;
	if (b->tolerance >= 0 && (t_var = new_var(m, b->tolerance)) >= 0)
		m->in_var[t_var] = 1;
	for (i = 0; i < (b->has_zpoint ? 2 : 3); i++) {
		mval *x = &m->val[in[i]];
		fi_set(m->s2, x->v);                              /* u_i           */
		if (b->tolerance >= 0) {
			mpfi_mag(m->f1, m->s2);
			x->in_h = mpfr_get_d(m->f1, MPFR_RNDU) * b->tolerance;
			x->in_h = x->in_h > 0.0 ? nextafter(x->in_h, INFINITY) : 0.0;
			m->nh[i] = x->in_h;
			set_grad(x, t_var, m->s2);
			fi_interv_d(m->t1, 1.0 - b->tolerance, 1.0 + b->tolerance);
			imul(m, x->v, x->v, m->t1);
			continue;
		}
		/* n_i = u_i + w_i, |w_i| <= half an ulp of the binade of max|u_i| */
		{
			double h = half_ulp_of(m, x->v, b->prec);
			(void)u;
			if (h > 0.0) {
				int k = new_var(m, h);
				x->in_h = m->nh[i] = h;
				if (k >= 0)
					m->in_var[k] = 1;
				set_grad(x, k, m->one);
				add_sym(m, x, h);
			}
		}
	}
}

/* Exact operations on model values, for the defect quantities. */
static cv ex(mvf *m, int op, cv a, cv b)
{
	cv ir = fresh(m, PREC_DOUBLE);
	mval *r = &m->val[ir];
	if (a < 0) {   /* no value: not met (fresh and mvf_cst always give one) */
		m->failed = 1;
		return ir;
	}
	if (m->val[a].opaque || (b >= 0 && m->val[b].opaque))
		m->failed = 1;
	if (!m->failed && (!exact_eval(m, op, r, &m->val[a], b >= 0 ? &m->val[b] : NULL, NULL) ||
	                   mpfi_nan_p(r->v) || !mpfi_bounded_p(r->v)))
		m->failed = 1;
	return ir;
}

static cv ex_dot(mvf *m, const cv *p, const cv *q)
{
	cv s = ex(m, MVF_MUL, p[0], q[0]);
	s = ex(m, MVF_ADD, s, ex(m, MVF_MUL, p[1], q[1]));
	return ex(m, MVF_ADD, s, ex(m, MVF_MUL, p[2], q[2]));
}

/* A lower bound on S, the sum of the squares of the actual values of
   length tag x's bases (0: none known). */
static double len_lact(mvf *m, const mval *x)
{
	squares_lo(m, x->ls_b, x->ls_nb);
	return mpfr_get_d(m->f2, MPFR_RNDD);
}

/* An enclosure [*lo, *hi] of |b|^2 - 1 for the actual outputs b = out[0..2]
   from their length tags alone, whatever the box: b_i = q_i K (1 + d_i) +
   eta_i (or q_i / K) for one tagged K = (1 + o)^-+1 x^-+1/2, x = S (1 + eps)
   + alpha and S the sum of the q_i^2 (a zero output has no q), so
   |b~|^2 = (1 + d)^2 (1 + o)^+-2 / (1 + eps + alpha/S), |b| = |b~| +-
   sqrt(3) eta.  Returns 0 when the outputs are not of that form. */
static int len_direct(mvf *m, const cv out[3], double *lo, double *hi)
{
	const mval *k = NULL, *x;
	cv seen[3];
	double u = 0.0, eta = 0.0, L;
	int ns = 0, i, j;
	for (i = 0; i < 3; i++) {
		const mval *b = &m->val[out[i]];
		if (is_zero(b))
			continue;
		if (b->ls_k < 0 || (k && k != &m->val[b->ls_k]))
			return 0;
		k = &m->val[b->ls_k];
		for (j = 0; j < ns; j++)
			if (seen[j] == b->ls_q)
				return 0;
		seen[ns++] = b->ls_q;
		u = fmax(u, b->ls_u);
		eta = fmax(eta, b->ls_eta);
	}
	if (!k || (k->ls_p != 1 && k->ls_p != -1) || (x = &m->val[k->ls_x])->ls_p != 2 || x->ls_nb != ns)
		return 0;
	for (i = 0; i < ns; i++) {
		for (j = 0; j < ns && seen[j] != x->ls_b[i]; j++)
			;
		if (j == ns)
			return 0;
	}
	mpfi_get_left(m->f1, x->v);                      /* S >= (x - alpha)/(1 + eps) */
	mpfr_sub_d(m->f1, m->f1, x->ls_abs, MPFR_RNDD);
	mpfr_div_d(m->f1, m->f1, round_up_d(1.0 + x->ls_hi), MPFR_RNDD);
	L = fmax(mpfr_get_d(m->f1, MPFR_RNDD), len_lact(m, x));
	if (x->ls_abs > 0.0 && !(L > 0.0))
		return 0;
	mpfr_set_d(m->f1, x->ls_abs, MPFR_RNDU);
	if (x->ls_abs > 0.0)
		mpfr_div_d(m->f1, m->f1, L, MPFR_RNDU);            /* rho = alpha/S   */
	mpfr_sub_d(m->f2, m->f1, x->ls_lo, MPFR_RNDU);
	mpfr_ui_sub(m->f2, 1, m->f2, MPFR_RNDD);               /* 1 + eps - rho   */
	mpfr_add_d(m->f1, m->f1, x->ls_hi, MPFR_RNDU);
	mpfr_add_ui(m->f1, m->f1, 1, MPFR_RNDU);
	if (mpfr_sgn(m->f2) <= 0)
		return 0;
	mpfi_interv_fr(m->s1, m->f2, m->f1);
	fi_interv_d(m->s2, 1.0 + k->ls_olo, 1.0 + k->ls_ohi);   /* exact: |o| >= 2^-60 */
	mpfi_sqr(m->s2, m->s2);
	if (k->ls_p == 1)
		mpfi_inv(m->s2, m->s2);
	mpfi_div(m->s1, m->s2, m->s1);
	fi_interv_d(m->s2, 1.0 - u, 1.0 + u);
	mpfi_sqr(m->s2, m->s2);
	imul(m, m->s1, m->s1, m->s2);                           /* |b~|^2         */
	mpfi_sqrt(m->s1, m->s1);
	mpfr_set_d(m->f1, eta, MPFR_RNDU);
	mpfr_mul_d(m->f1, m->f1, 1.7320508075688774, MPFR_RNDU);
	mpfi_interv_fr(m->s2, m->f1, m->f1);
	fi_neg(m->t1, m->s2);
	mpfi_put(m->s2, m->t1);
	mpfi_add(m->s1, m->s1, m->s2);
	if (mpfi_has_zero(m->s1))
		return 0;
	mpfi_sqr(m->s1, m->s1);
	mpfi_sub_d(m->s1, m->s1, 1.0);
	mpfi_get_left(m->f1, m->s1);
	*lo = mpfr_get_d(m->f1, MPFR_RNDD);
	mpfi_get_right(m->f1, m->s1);
	*hi = mpfr_get_d(m->f1, MPFR_RNDU);
	return !(isnan(*lo) || isnan(*hi));
}

/* Adds sg times the linear form of v in the inputs n[] to row[] (v an
   input, 0, or an exact difference of such, signs and widenings aside);
   returns 0 when v is none of those. */
static int lin_form(const mvf *m, cv v, int sg, const cv n[3], int depth, int row[3])
{
	const mval *x, *b;
	int j;
	if (v < 0 || v >= m->n)
		return 0;
	x = &m->val[v];
	b = &m->val[x->base];
	sg *= x->bsign;
	for (j = 0; j < 3; j++)
		if (x->base == m->val[n[j]].base) {
			row[j] += sg * m->val[n[j]].bsign;
			return 1;
		}
	if (is_zero(b))
		return 1;
	if (b->sub_a < 0 || b->sub_b < 0 || depth > 1)
		return 0;
	return lin_form(m, b->sub_a, sg, n, depth + 1, row) && lin_form(m, b->sub_b, -sg, n, depth + 1, row);
}

/* Outputs b_i = q_i K (1 + d_i) + eta_i (or q_i / K ...), |d_i| <= u, of
   one tagged K, with q = M n for an antisymmetric integer M (q.n = 0 for
   the actual values: q made of the inputs by negations, zeros and exact
   differences): then b.n = sum_i q_i K d_i n_i + eta.n, so
   |b.n| <= u |q K| |n| + sqrt(3) eta |n|, and |q K| <= (|b| + sqrt(3) eta)
   / (1 - u).  Returns 0 when the outputs are not of that form. */
static int orth_direct(mvf *m, const cv out[3], const cv n[3], double *u, double *eta)
{
	int M[3][3] = { { 0 } }, i, j, k = -1;
	*u = *eta = 0.0;
	for (i = 0; i < 3; i++) {
		const mval *b = &m->val[out[i]];
		if (is_zero(b))
			continue;
		if (b->ls_k < 0 || b->ls_qv < 0 || (k >= 0 && b->ls_k != k))
			return 0;
		k = b->ls_k;
		if (!lin_form(m, b->ls_qv, b->ls_sg, n, 0, M[i]))
			return 0;
		*u = fmax(*u, b->ls_u);
		*eta = fmax(*eta, b->ls_eta);
	}
	if (k < 0)
		return 0;
	for (i = 0; i < 3; i++)
		for (j = 0; j < 3; j++)
			if (M[i][j] + M[j][i] != 0)
				return 0;
	return 1;
}

int mvf_scaled_of(const mvf *m, const cv out[3], const cv q[3], double *u, double *eta)
{
	int i, k = -1;
	*u = *eta = 0.0;
	if (m->failed || m->zero_e || m->ar)
		return 0;
	for (i = 0; i < 3; i++) {
		const mval *b = &m->val[out[i]];
		if (b->ls_k < 0 || b->ls_qv != q[i] || b->ls_sg != 1 || (k >= 0 && b->ls_k != k))
			return 0;
		k = b->ls_k;
		*u = fmax(*u, b->ls_u);
		*eta = fmax(*eta, b->ls_eta);
	}
	return 1;
}

int mvf_orth_direct(const mvf *m, int which, double *u, double *eta)
{
	if (!m->orth_ok[which])
		return 0;
	*u = m->orth_u[which];
	*eta = m->orth_eta[which];
	return 1;
}

int mvf_len_direct(const mvf *m, int which, double *lo, double *hi)
{
	if (!m->len_ok[which])
		return 0;
	*lo = m->len_lo[which];
	*hi = m->len_hi[which];
	return 1;
}

void mvf_quantities(mvf *m, const cv n[3], const cv out[6], cv q[5])
{
	int i;
	for (i = 0; i < 2; i++)
		m->len_ok[i] = !m->ar && !m->failed && !m->zero_e && len_direct(m, out + 3 * i, &m->len_lo[i], &m->len_hi[i]);
	for (i = 0; i < 2; i++)
		m->orth_ok[i] = !m->ar && !m->failed && !m->zero_e && orth_direct(m, out + 3 * i, n, &m->orth_u[i], &m->orth_eta[i]);
	cv one = mvf_cst(m, 1.0);
	/* |b|^2 - 1, not |b| - 1: a wide box's b.b can reach 0, where the
	   derivative of the square root is unbounded (bound.c converts) */
	q[CQ_N1] = ex(m, MVF_SUB, ex_dot(m, out, out), one);
	q[CQ_N2] = ex(m, MVF_SUB, ex_dot(m, out + 3, out + 3), one);
	q[CQ_D1N] = ex_dot(m, out, n);
	q[CQ_D2N] = ex_dot(m, out + 3, n);
	q[CQ_D12] = ex_dot(m, out, out + 3);
}

/* Q over the box directly, as [*lo, *hi] (rounded outward), and
   sum_k r_k max|dQ/de_k|, rounded up. */
void mvf_bounds(mvf *m, cv iq, double *lo, double *hi, double *lin)
{
	const mval *q = &m->val[iq];
	int k;
	if (m->failed) {
		*lo = -INFINITY;
		*hi = *lin = INFINITY;
		return;
	}
	mpfi_get_left(m->f1, q->v);
	*lo = mpfr_get_d(m->f1, MPFR_RNDD);
	mpfi_get_right(m->f1, q->v);
	*hi = mpfr_get_d(m->f1, MPFR_RNDU);
	mpfr_set_zero(m->f2, 1);
	for (k = 0; k < q->ng; k++) {
		if (!q->nz[k])
			continue;
		mpfi_mag(m->f1, q->g[k]);
		mpfr_mul_d(m->f1, m->f1, m->r[k], MPFR_RNDU);
		mpfr_add(m->f2, m->f2, m->f1, MPFR_RNDU);
	}
	*lin = mpfr_get_d(m->f2, MPFR_RNDU);
	if (isnan(*lo) || isnan(*hi)) {
		*lo = -INFINITY;
		*hi = INFINITY;
	}
}

/* f(r) = r (1.5 - 0.5 r^2 p) at the point (r, p), enclosed in m->t1. */
static void newton_poly(mvf *m, double r, mpfi_srcptr p, mpfi_ptr out)
{
	fi_set_d(m->t2, r);
	mpfi_sqr(m->t3, m->t2);
	imul(m, m->t3, m->t3, p);
	mpfi_div_2ui(m->t3, m->t3, 1);
	mpfi_d_sub(m->t3, 1.5, m->t3);
	imul(m, out, m->t3, m->t2);
}

/* The relative error of Listing 3's Newton step y1 = y (1.5 - 0.5 x y y)
   on a seed y = r/sqrt(x): with h = 0.5 x exact and the roundings
   (1 + d1..d4) of h y, (h y) y, 1.5 - t and y t,
       y1 sqrt(x) = f(r) (1 + d3)(1 + d4),  f(r) = r (1.5 - 0.5 r^2 p),
   p = (1 + d1)(1 + d2): x cancels, which intervals in x cannot see.  f is
   concave in r > 0 and decreasing in p, so its range over the box is at
   the corners and at its peak r = 1/sqrt(p), f = 1/sqrt(p).  Returns the
   bound of |y1 sqrt(x) - 1|, or -1 when y is no seed of x. */
static int newton_scanned(mvf *m, int f, cv ix, cv iy, newton_kind k, double *lo, double *hi);
static double newton_rel(mvf *m, int f, cv ix, cv iy, newton_kind k)
{
	const int embree = k == NEWTON_EMBREE || k == NEWTON_EMBREE_FUSED;
	const mval *y = &m->val[iy];
	double u = unit_round(f), rlo = y->rel_lo, rhi = y->rel_hi, lo, hi;
	if (y->rsqrt_of < 0)
		return -1.0;
	if (y->rsqrt_of != ix) { /* seed of (float)x: r (1 + d)^(-1/2) */
		const mval *a = &m->val[y->rsqrt_of];
		if (a->cvt_of != ix)
			return -1.0;
		rlo = rlo / sqrt(1.0 + a->cvt_u) * (1.0 - 0x1p-50);
		rhi = rhi / sqrt(1.0 - a->cvt_u) * (1.0 + 0x1p-50);
	}
	fi_interv_d(m->s1, 1.0 - u, 1.0 + u);
	if (embree) {   /* p = (1 + da)(1 + db)(1 + dc)/(1 + dd): see mvf_newton_embree */
		mpfi_sqr(m->t1, m->s1);
		imul(m, m->t1, m->t1, m->s1);
		mpfi_div(m->s1, m->t1, m->s1);
	} else {
		mpfi_sqr(m->s1, m->s1);                 /* p              */
	}
	mpfi_get_left(m->f1, m->s1);
	mpfi_set_fr(m->s2, m->f1);                      /* p_lo: the max  */
	newton_poly(m, rlo, m->s2, m->t1);
	mpfi_get_right(m->f2, m->t1);
	newton_poly(m, rhi, m->s2, m->t1);
	mpfi_get_right(m->f1, m->t1);
	mpfr_max(m->f2, m->f2, m->f1, MPFR_RNDU);
	mpfi_sqrt(m->t1, m->s2);
	mpfi_inv(m->t1, m->t1);                         /* peak 1/sqrt(p_lo) */
	mpfi_get_right(m->f1, m->t1);
	mpfr_max(m->f2, m->f2, m->f1, MPFR_RNDU);
	hi = mpfr_get_d(m->f2, MPFR_RNDU);
	mpfi_get_right(m->f1, m->s1);
	mpfi_set_fr(m->s2, m->f1);                      /* p_hi: the min  */
	newton_poly(m, rlo, m->s2, m->t1);
	mpfi_get_left(m->f2, m->t1);
	newton_poly(m, rhi, m->s2, m->t1);
	mpfi_get_left(m->f1, m->t1);
	mpfr_min(m->f2, m->f2, m->f1, MPFR_RNDD);
	lo = mpfr_get_d(m->f2, MPFR_RNDD);
	fi_interv_d(m->t1, lo, hi);                   /* times (1 + d3)(1 + d4) */
	fi_interv_d(m->s1, 1.0 - u, 1.0 + u);
	imul(m, m->t1, m->t1, m->s1);
	imul(m, m->t1, m->t1, m->s1);
	mpfi_sub_d(m->t1, m->t1, 1.0);
	mpfi_mag(m->f1, m->t1);
	hi = mpfr_get_d(m->f1, MPFR_RNDU);
	if (newton_scanned(m, f, ix, iy, k, &lo, &rhi))
		hi = fmin(hi, fmax(-lo, rhi));
	return hi;
}

/* The scan's range [*lo, *hi] of y1 sqrt(x) - 1 (newton_f.c), where y is a
   float seed of the float x itself and x lies in at most 4 binades. */
static int newton_scanned(mvf *m, int f, cv ix, cv iy, newton_kind k, double *lo, double *hi)
{
	const mval *y = &m->val[iy];
	double a, b;
	int ea, eb;
	if (f != PREC_FLOAT || y->rsqrt_of != ix || y->seed_k < 0 || m->zero_e)
		return 0;
	mpfi_get_left(m->f1, m->val[ix].v);
	mpfi_get_right(m->f2, m->val[ix].v);
	a = mpfr_get_d(m->f1, MPFR_RNDD);
	b = mpfr_get_d(m->f2, MPFR_RNDU);
	if (!(a >= 0x1p-126 && b < 0x1p127))
		return 0;
	frexp(a, &ea);
	frexp(b, &eb);
	return eb - ea < 4 && newton_range_f(k, (seed_kind)y->seed_k, ea + 126, eb + 126, lo, hi) == 0;
}

/* y1 = (1 + o)/sqrt(x): o's range, [-newton_rel, newton_rel] or the scan's. */
static void newton_o(mvf *m, int f, cv ix, cv iy, newton_kind k, double e, double *lo, double *hi)
{
	*lo = -e;
	*hi = e;
	if (newton_scanned(m, f, ix, iy, k, lo, hi)) {
		*lo = fmax(*lo, -e);
		*hi = fmin(*hi, e);
	}
}

/* Listing 3's Newton step, as y1 = (1 + e)/sqrt(x) with |e| <= newton_rel.
   Needs h, h y and (h y) y normal: x >= 2^-100 (float) or 2^-1000. */
static cv newton_common(mvf *m, int f, cv ix, cv iy, newton_kind k);
cv mvf_newton(mvf *m, int f, cv ix, cv iy, int fused)
{
	return newton_common(m, f, ix, iy, fused ? NEWTON_L3_FUSED : NEWTON_L3);
}

/* Embree's step 1.5 y + ((x (-0.5)) y)(y y) on a seed y = r/sqrt(x): with
   the roundings dd of 1.5 y, da, db, dc of the three products and dy of the
   sum (x (-0.5) exact), y1 sqrt(x) = (1 + dd)(1 + dy) f(r), f(r) =
   r (1.5 - 0.5 r^2 p), p = (1 + da)(1 + db)(1 + dc)/(1 + dd): Listing 3's
   form with another p.  Returns -1 when y is no seed of x (then the model
   runs the operations one by one).  The result carries a norm tag when x
   does: y1 = (1 + o)/sqrt(S (1 + eps + rho)). */
cv mvf_newton_embree(mvf *m, int f, cv ix, cv iy, int fused)
{
	const newton_kind k = fused ? NEWTON_EMBREE_FUSED : NEWTON_EMBREE;
	cv ir;
	const mval *x = &m->val[ix];
	mval *r;
	double e;
	if (m->ar || m->failed || newton_rel(m, f, ix, iy, k) < 0.0)
		return -1;
	ir = newton_common(m, f, ix, iy, k);
	r = &m->val[ir];
	e = m->zero_e ? 0.0 : newton_rel(m, f, ix, iy, k);
	if (!m->failed && x->tg_p == 2) {
		memcpy(r->tg_b, x->tg_b, sizeof r->tg_b);
		r->tg_nb = x->tg_nb;
		r->tg_lo = x->tg_lo; r->tg_hi = x->tg_hi; r->tg_abs = x->tg_abs;
		r->tg_p = -1;
		r->tg_olo = -e;
		r->tg_ohi = e;
	}
	return ir;
}

static cv newton_common(mvf *m, int f, cv ix, cv iy, newton_kind k)
{
	cv ir = fresh(m, f);
	mval *r = &m->val[ir];
	const mval *x = &m->val[ix];
	double e = newton_rel(m, f, ix, iy, k), olo, ohi;
	mpfi_get_left(m->f1, x->v);
	/* h = x/2, h y and (h y) y normal, y = (1 + e)/sqrt(x) finite */
	if (m->failed || e < 0.0 ||
	    fi_cmp_d(m, m->f1, f == PREC_FLOAT ? 0x1p-100 : f == PREC_HALF ? 0x1p-12 : 0x1p-1000) < 0) {
		m->failed = 1;
		return ir;
	}
	mpfi_sqrt(m->s1, x->v);
	mpfi_inv(m->s1, m->s1);                          /* 1/sqrt(x)      */
	if (m->zero_e) {
		exact_rsqrt(m, r, x);
		return ir;
	}
	if (x->ls_p == 2) {
		newton_o(m, f, ix, iy, k, e, &olo, &ohi);
		len_recip(r, ix, olo, ohi);
	}
	fi_interv_d(m->t1, 1.0 - e, 1.0 + e);
	imul(m, r->v, m->s1, m->t1);
	mpfi_div(m->s2, r->v, x->v);                     /* d/dx = -(1 + e)/(2 x^1.5) */
	mpfi_div_2ui(m->s2, m->s2, 1);
	fi_neg(m->s2, m->s2);
	grad_lin(m, r, x, m->s2, NULL, NULL);
	set_grad(r, new_var(m, e), m->s1);
	return ir;
}

/* ---- Arithmetic profiles (arith.h) ----
   Under a profile other than ieee, every operation is the exact operation
   on its operands as read, plus one error term of the size the profile
   allows (arith_err_abs: ulps of the result's binade, or relative, plus
   the smallest normal where a result may be flushed).  None of the tags
   above (norm, length, cross, Newton, Sterbenz's and round_sum's
   nearest-only caps) are used: they were proven for round to nearest.
   Exactness is kept only where every allowed result is the exact one: a
   product by 0 or +-1, a sum with 0, a widening (each in the format, and
   no flush where the result can be subnormal).
   An operand that may be subnormal may be read as 0 (a term of the
   smallest normal at that use alone), and under contraction a rounded
   product that feeds a sum is read again with a fresh rounding term: the
   term's range holds 0 (the fused a*b + c, one rounding, of an allowance
   no wider than the sum's) and the shared product's own rounding. */

void mvf_set_arith(mvf *m, const arith_profile *p) { m->ar = arith_is_ieee(p) ? NULL : p; }
int mvf_unbounded_op(const mvf *m) { return m->unb_op; }
int mvf_lost_op(const mvf *m) { return m->lost_op; }

/* The run fails at an operation of kind k whose exact result has no
   enclosure (why: AR_AT_POLE or AR_OVERFLOW). */
static void prof_lost(mvf *m, int k, int why)
{
	if (m->lost_op < 0)
		m->lost_op = k | why;
	m->failed = 1;
}

static void mag_range(mvf *m, mpfi_srcptr v, double *vmin, double *vmax)
{
	mpfi_mig(m->f1, v);
	*vmin = mpfr_get_d(m->f1, MPFR_RNDD);
	mpfi_mag(m->f1, v);
	*vmax = mpfr_get_d(m->f1, MPFR_RNDU);
}

/* x += [-h, h] with a fresh error term (nothing in a run with every e 0);
   no sign is kept: an allowance of several ulps can cross 0. */
static void prof_term(mvf *m, cv ix, double h, int op)
{
	mval *x = &m->val[ix];
	if (m->zero_e || h == 0.0)
		return;
	if (!(h < INFINITY)) {
		if (m->unb_op < 0)
			m->unb_op = op;
		m->failed = 1;
		return;
	}
	set_grad(x, new_var(m, h), m->one);
	fi_interv_d(m->t1, -h, h);
	mpfi_add(x->v, x->v, m->t1);
}

/* A copy of value ia in a fresh slot (value, gradient, format). */
static cv prof_copy(mvf *m, cv ia)
{
	cv ir = fresh(m, m->val[ia].fmt);
	mval *r = &m->val[ir];
	fi_set(r->v, m->val[ia].v);
	copy_grad(m, r, &m->val[ia]);
	r->fmt = m->val[ia].fmt;
	return ir;
}

/* Operand ia as an operation reads it (fuse: the operation is a sum, into
   which a product may be contracted). */
static cv prof_read(mvf *m, cv ia, int fuse)
{
	const mval *a = &m->val[ia];
	double vmin, vmax;
	cv ir = ia;
	if (fuse && m->ar->contract && a->pa >= 0) {
		const int neg = a->pneg, fa = a->fmt;
		ir = fresh(m, fa);
		if (!exact_eval(m, MVF_MUL, &m->val[ir], &m->val[a->pa], &m->val[a->pb], NULL)) {
			m->failed = 1;
			return ir;
		}
		mag_range(m, m->val[ir].v, &vmin, &vmax);
		prof_term(m, ir, arith_err_abs(m->ar, AR_MUL, fa, vmin, vmax), AR_MUL);
		if (neg) {
			cv in = fresh(m, fa);
			exact_eval(m, MVF_NEG, &m->val[in], &m->val[ir], NULL, NULL);
			ir = in;
		}
		a = &m->val[ir];
	}
	if (a->is_cst || !m->ar->fmt[a->fmt].flush)
		return ir;
	mag_range(m, a->v, &vmin, &vmax);
	if (vmin >= arith_normal_min(a->fmt))
		return ir;
	if (ir == ia)
		ir = prof_copy(m, ia);
	prof_term(m, ir, arith_normal_min(a->fmt), -1);
	return ir;
}

cv mvf_read(mvf *m, cv ia)
{
	return m->ar && !m->failed ? prof_read(m, ia, 0) : ia;
}

/* Every allowed result is the exact one (see above). */
static int prof_exact(mvf *m, int op, int f, const mval *a, const mval *b, const mval *r)
{
	double vmin, vmax;
	int ok;
	switch (op) {   /* fmt_in, not the enum's order: PREC_HALF is 2 */
	case MVF_NEG: return 1;
	case MVF_CVT: ok = fmt_in(a->fmt, f); break;
	case MVF_MUL:
		ok = is_zero(a) || is_zero(b) || ((is_cst(a, 1.0) || is_cst(a, -1.0)) && fmt_in(b->fmt, f)) ||
		     ((is_cst(b, 1.0) || is_cst(b, -1.0)) && fmt_in(a->fmt, f));
		break;
	case MVF_ADD: case MVF_SUB:
		ok = (is_zero(a) && fmt_in(b->fmt, f)) || (is_zero(b) && fmt_in(a->fmt, f));
		break;
	default: return 0;
	}
	if (!ok || !m->ar->fmt[f].flush)
		return ok;
	mag_range(m, r->v, &vmin, &vmax);
	return vmax == 0.0 || vmin >= arith_normal_min(f);
}

/* The exact operation on the operands as read, then the allowance of
   kind k in format f. */
static cv prof_round(mvf *m, int op, int k, int f, cv ia, cv ib, cv id)
{
	const int fuse = op == MVF_ADD || op == MVF_SUB;
	cv xa = prof_read(m, ia, fuse), xb = ib >= 0 ? prof_read(m, ib, fuse) : -1, xd = id >= 0 ? prof_read(m, id, 1) : -1;
	cv ir = fresh(m, f);
	mval *r = &m->val[ir];
	const mval *a = &m->val[xa], *b = xb >= 0 ? &m->val[xb] : NULL;
	double vmin, vmax;
	if (m->failed)
		return ir;
	if (op == MVF_DIV && m->ar->fmt[f].div_lo > 0.0) {   /* the allowance's range of |y| */
		mag_range(m, b->v, &vmin, &vmax);
		if (vmin < m->ar->fmt[f].div_lo || vmax > m->ar->fmt[f].div_hi) {
			prof_term(m, ir, INFINITY, k);
			return ir;
		}
	}
	if (a->opaque || (b && b->opaque) || !exact_eval(m, op, r, a, b, xd >= 0 ? &m->val[xd] : NULL) ||
	    mpfi_nan_p(r->v) || !mpfi_bounded_p(r->v)) {
		prof_lost(m, k, op == MVF_DIV || op == MVF_SQRT ? AR_AT_POLE : AR_OVERFLOW);
		return ir;
	}
	if (op == MVF_NEG) {
		r->fmt = a->fmt;
		r->pa = a->pa; r->pb = a->pb; r->pneg = !a->pneg;
		return ir;
	}
	if (prof_exact(m, op, f, a, b, r)) {
		if (op == MVF_CVT && a->fmt != r->fmt && fmt_in(a->fmt, r->fmt))
			r->fmt = a->fmt;   /* a widening: the value stays in the narrower format */
		return ir;
	}
	mag_range(m, r->v, &vmin, &vmax);
	prof_term(m, ir, arith_err_abs(m->ar, k, f, vmin, vmax), k);
	if (op == MVF_MUL) {
		r->pa = xa;
		r->pb = xb;
	}
	return ir;
}

/* An exact 1/sqrt(a) (two exact steps), then the allowance of kind k. */
static cv prof_rsqrt(mvf *m, int k, int f, cv ia)
{
	cv xa = prof_read(m, ia, 0), is = fresh(m, f), ir = fresh(m, f);
	double vmin, vmax;
	if (m->failed)
		return ir;
	if (!exact_eval(m, MVF_SQRT, &m->val[is], &m->val[xa], NULL, NULL) ||
	    !exact_eval(m, MVF_DIV, &m->val[ir], &m->val[mvf_cst(m, 1.0)], &m->val[is], NULL) ||
	    !mpfi_bounded_p(m->val[ir].v)) {
		prof_lost(m, k, AR_AT_POLE);
		return ir;
	}
	mag_range(m, m->val[ir].v, &vmin, &vmax);
	prof_term(m, ir, arith_err_abs(m->ar, k, f, vmin, vmax), k);
	return ir;
}

/* An exact 1/b, then the allowance of a reciprocal (Direct3D's rcp). */
static cv prof_rcp(mvf *m, int f, cv ib)
{
	cv xb = prof_read(m, ib, 0), ir = fresh(m, f);
	double vmin, vmax;
	if (m->failed)
		return ir;
	if (!exact_eval(m, MVF_DIV, &m->val[ir], &m->val[mvf_cst(m, 1.0)], &m->val[xb], NULL) ||
	    !mpfi_bounded_p(m->val[ir].v)) {
		prof_lost(m, AR_RCP, AR_AT_POLE);
		return ir;
	}
	mag_range(m, m->val[ir].v, &vmin, &vmax);
	prof_term(m, ir, arith_err_abs(m->ar, AR_RCP, f, vmin, vmax), AR_RCP);
	return ir;
}

static cv prof_op(mvf *m, int op, int f, cv ia, cv ib, cv id)
{
	const int k = arith_kind(op);
	const ar_allow *al = &m->ar->fmt[f].op[k];
	if (m->failed)
		return fresh(m, f);
	if (op == MVF_CVT && fmt_in(m->val[ia].fmt, f))
		return prof_round(m, op, k, f, ia, ib, id);   /* a widening: exact whatever the profile */
	if (op != MVF_NEG && al->how == AR_NONE) {
		cv ir = fresh(m, f);
		prof_term(m, ir, INFINITY, k);
		return ir;
	}
	if (op != MVF_NEG && al->how == AR_SPLIT) {
		if (op == MVF_FMA)      /* a product, then a sum: two roundings */
			return prof_op(m, MVF_ADD, f, prof_op(m, MVF_MUL, f, ia, ib, -1), id, -1);
		if (op == MVF_SQRT)     /* 1.0/inversesqrt(a) */
			return prof_op(m, MVF_DIV, f, mvf_cst(m, 1.0), prof_rsqrt(m, AR_RSQRT, f, ia), -1);
		if (op == MVF_DIV)      /* a * rcp(b) */
			return prof_op(m, MVF_MUL, f, ia, prof_rcp(m, f, ib), -1);
	}
	return prof_round(m, op, k, f, ia, ib, id);
}
