/*
 * reference.c - the MPFR reference of every method family, and the
 * per-input metrics (see reference.h).
 *
 * Each family's formula (its family file in src/families/) is written
 * exactly as its kernel in include/libonb/onb.h computes it, with every
 * operation exact or rounded at the context's precision (128 bits by
 * default: 2.4 times double's 53).  The branch is not recomputed in MPFR:
 * it is the branch the kernel took (the family's branch rule), so a
 * kernel is compared with its own formula on its own side of every
 * threshold.  The normalization variants (_invsqrt, _rsqrt,
 * _rsqrt_nr) are compared with the exactly normalized formula, so their
 * forward error includes the approximation; _nonorm is compared with the
 * unnormalized formula, which it computes faithfully.
 */
#include <stdlib.h>
#include <string.h>
#include <stdio.h>
#include <stdint.h>
#include <float.h>
#include "reference/reference.h"
#include "arith/mpfr_kit.h"
#include "reference/ziv.h"

struct ref_ctx {
	mpfr_prec_t prec;
	mpfr_kit k;      /* the formulas' scratch: t[], p0, p1 (products), u[], w[] */
	mpfr_t n[3], b1[3], b2[3], r1[3], r2[3];
	mpfr_t q[4];     /* exact products for dot_exact */
	mpfr_t nsq[3];   /* the current input's squares, exact: |n|^2's terms */
	double last[3];  /* the input of the previous call, its |n|-1 and n/|n| */
	double last_norm;
	int have_last;
	int exact;       /* the formula's last evaluation was exact (ziv.h)         */
	double sum_err;  /* exact_sum's bound on |out - exact sum|                  */
	int sum_k;       /* and its number of terms, still in q[]                  */
	mpfr_t lo, hi;   /* sum_d's interval                                       */
	mpfr_t sc;       /* ref_round's scratch (its precision changes)            */
	ziv_ctx *z;      /* the roundings of the formula, by Ziv's strategy        */
	ziv_out zo;      /* and their results for the current kernel and input     */
};


ref_ctx *ref_new(mpfr_prec_t prec)
{
	ref_ctx *c = malloc(sizeof *c);
	if (!c)
		return NULL;
	c->prec = prec;
	c->have_last = 0;
	c->z = NULL;
	kit_init(&c->k, prec);
	kit_vinit(c->n, 3, prec); kit_vinit(c->nsq, 3, prec < 106 ? 106 : prec); kit_vinit(c->b1, 3, prec);
	kit_vinit(c->b2, 3, prec); kit_vinit(c->r1, 3, prec); kit_vinit(c->r2, 3, prec);
	kit_vinit(c->q, 4, prec < 106 ? 106 : prec);
	mpfr_init2(c->lo, prec);
	mpfr_init2(c->hi, prec);
	mpfr_init2(c->sc, 64);
	c->z = ziv_new(prec);
	if (!c->z) {
		ref_free(c);
		return NULL;
	}
	return c;
}

void ref_free(ref_ctx *c)
{
	if (!c)
		return;
	kit_clear(&c->k);
	kit_vclear(c->n, 3); kit_vclear(c->nsq, 3); kit_vclear(c->b1, 3); kit_vclear(c->b2, 3);
	kit_vclear(c->r1, 3); kit_vclear(c->r2, 3);
	kit_vclear(c->q, 4);
	mpfr_clear(c->lo);
	mpfr_clear(c->hi);
	mpfr_clear(c->sc);
	ziv_free(c->z);
	free(c);
}

mpfr_prec_t ref_prec(const ref_ctx *c) { return c->prec; }

#define R MPFR_RNDN

/* Products go through p0 and p1, at the context's precision: a product
   of two doubles (every defect, every input) is exact there, and the
   reference's own intermediate products round at 2^-prec relative, far
   below what any metric reports (ref_agree checks it on every run). */

/* Sums of exact products, for a, b and z holding doubles (the rounded
   outputs and the input; da, db are the same values as C doubles).  Each
   product is exact at the context's precision (106 bits suffice).  The
   fast path adds them at that precision, with an error below
   2^-(prec-2) * sum|term|; when the result is smaller than 2^-60 of that
   sum (heavy cancellation: b2.n of a near-orthogonal basis reaches
   2^-125), mpfr_sum rounds the exact sum once instead.  Either way the
   result has a relative error below 2^-(prec-63), 2^-64 at 127 bits.
   The bound sum|term| is taken in double from da and db, which costs
   nothing.  (A plain dot at 127 bits failed the two-precision check.)
   c->sum_err gets a rigorous bound on |out - sum| for sum_d: each of the
   k - 1 <= 3 additions rounds by at most 2^-P of a partial sum, itself
   at most sum|term| <= bound (1 + 5u); mpfr_sum, by 2^-P |out|.  Infinite
   where the bound is too small to hold in a double. */
static void exact_sum(ref_ctx *c, mpfr_t out, int k, double bound)
{
	mpfr_ptr q[4];
	int i, e;
	mpfr_add(out, c->q[0], c->q[1], R);
	for (i = 2; i < k; i++)
		mpfr_add(out, out, c->q[i], R);
	c->sum_k = k;
	c->sum_err = bound == 0.0 ? 0.0 : bound >= 0x1p-800 ? 3.0 * ldexp(bound, -(int)c->prec) * (1.0 + 0x1p-40) : INFINITY;
	if (bound == 0.0 || !isfinite(bound) || mpfr_nan_p(out) || mpfr_inf_p(out))
		return; /* exact zero terms, or NaN/Inf: nothing to refine */
	(void)frexp(bound, &e);
	if (!mpfr_zero_p(out) && mpfr_get_exp(out) > e - 59)
		return;
	for (i = 0; i < k; i++)
		q[i] = c->q[i];
	mpfr_sum(out, q, (unsigned long)k, R);
	{
		const double a = fabs(mpfr_get_d(out, MPFR_RNDA));
		c->sum_err = a >= 0x1p-800 ? ldexp(a, -(int)c->prec) * (1.0 + 0x1p-40) : INFINITY;
	}
}

/* RN to double of the exact sum that exact_sum has just left in out,
   correct whatever the precision: decided from out and c->sum_err when
   both ends round alike, else by mpfr_sum of the terms (still in c->q)
   at double's quantum there (ref_round_sum). */
static double sum_d(ref_ctx *c, mpfr_t out)
{
	mpfr_ptr q[4];
	int i;
	if (!mpfr_number_p(out) || c->sum_err == 0.0)
		return ref_round(out, ref_format_of(PREC_DOUBLE), c->sc); /* NaN, inf, or exact */
	if (c->sum_err < DBL_MAX) {
		double a, b;
		mpfr_sub_d(c->lo, out, c->sum_err, MPFR_RNDD);
		mpfr_add_d(c->hi, out, c->sum_err, MPFR_RNDU);
		a = ref_round(c->lo, ref_format_of(PREC_DOUBLE), c->sc);
		b = ref_round(c->hi, ref_format_of(PREC_DOUBLE), c->sc);
		if (memcmp(&a, &b, sizeof a) == 0)
			return a;
	}
	for (i = 0; i < c->sum_k; i++)
		q[i] = c->q[i];
	return ref_round_sum(q, (unsigned long)c->sum_k, ref_format_of(PREC_DOUBLE), c->sc);
}

/* out = a.b - z */
static void dot_exact(ref_ctx *c, mpfr_t out, mpfr_t *a, mpfr_t *b, const double *da, const double *db, double z)
{
	mpfr_mul(c->q[0], a[0], b[0], R);
	mpfr_mul(c->q[1], a[1], b[1], R);
	mpfr_mul(c->q[2], a[2], b[2], R);
	if (z != 0.0)
		mpfr_set_d(c->q[3], -z, R);
	exact_sum(c, out, z != 0.0 ? 4 : 3,
	          fabs(da[0] * db[0]) + fabs(da[1] * db[1]) + fabs(da[2] * db[2]) + fabs(z));
}

/* |v| - 1 for v holding doubles, accurate however close |v| is to 1:
   e = vx^2 + vy^2 + vz^2 - 1 by exact_sum (correct to 2^-64 relative),
   then |v| - 1 = e/(sqrt(1 + e) + 1), whose denominator in [1, 2.42] for
   |v| <= 1.2 needs no more than double: the result's relative error is
   below 2^-50, far under the 6 digits reported.  (sqrt(s) - 1 at 127
   bits loses everything below 2^-127 absolute: it failed the
   two-precision check on inputs with |n| - 1 ~ 1e-30.) */
static double norm_m1_exact(ref_ctx *c, mpfr_t *v, const double *dv)
{
	double e;
	mpfr_sqr(c->q[0], v[0], R);
	mpfr_sqr(c->q[1], v[1], R);
	mpfr_sqr(c->q[2], v[2], R);
	mpfr_set_si(c->q[3], -1, R);
	exact_sum(c, c->k.p0, 4, dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2] + 1.0);
	e = sum_d(c, c->k.p0);
	return e / (sqrt(1.0 + e) + 1.0);
}

/* The exact formula of kernel k on n along branch br, into r1, r2 (or the
   rotated direction of loc into r1 for frisvad_rotate): its family's
   (src/families/). */
static void reference(ref_ctx *c, const study_kernel *k, int br, const double loc[3])
{
	ziv_watch();
	k->fam->mpfr(&c->k, k->m, br, loc, c->n, c->r1, c->r2);
	c->exact = ziv_exact();
}

/* The forward error of component i, the kernel's cv against the
   formula's exact X, from the roundings Ziv's strategy decided (c->zo):
   abs_eps_max, ulp_max, the bits, and ref[i] = X to double.  A diff
   RN(X - cv) left undecided (X = cv exactly, computed inexactly) enters
   only the maxima: its bound goes to undet[0] (in eps) and undet[1] (in
   ulps), which the caller compares with the maxima (forward_all). */
static void forward(ref_ctx *c, int i, double cv, int prec, sample_metrics *s, double undet[2])
{
	const ref_format *f = ref_format_of(prec);
	const double eps = ldexp(1.0, 1 - f->p), rounded = c->zo.fmt[i];
	const int have_diff = !isnan(c->zo.diff[i]);
	const double diff = have_diff ? fabs(c->zo.diff[i]) : c->zo.diff_up[i];
	s->ref[i] = c->zo.d[i];
	if (!isfinite(s->ref[i]))
		return;
	if (have_diff && diff / eps > s->abs_eps_max)
		s->abs_eps_max = diff / eps;
	else if (!have_diff && diff / eps > undet[0])
		undet[0] = diff / eps;
	/* Components whose exact value is below eps (zero ones above all) are
	   measured by the absolute error only: their ulps and bits would
	   measure the reference's own last bits, not the method.  The ulp is
	   that of the exact value rounded to the format (the same thing but
	   at powers of two), floored at the smallest normal's. */
	if (rounded != 0.0 && fabs(rounded) >= eps) {
		int E;
		double ulp, bits;
		(void)frexp(rounded, &E);
		ulp = ldexp(1.0, (E < f->emin ? f->emin : E) - f->p);
		if (have_diff && diff / ulp > s->ulp_max)
			s->ulp_max = diff / ulp;
		else if (!have_diff && diff / ulp > undet[1])
			undet[1] = diff / ulp;
		{
			static const double small[4] = { 0.0, 1.0, 1.5849625007211562, 2.0 };
			const double dist = ref_float_distance(cv, rounded, prec);
			bits = dist < 4.0 ? small[(int)dist] : log2(dist + 1.0);
		}
		s->bits_sum += bits;
		s->nbits++;
		if (bits > s->bits_max)
			s->bits_max = bits;
	}
}

/* Every component's forward error; the undecided diffs are decided
   (ziv_diff) only when their bounds could raise a maximum. */
static void forward_all(ref_ctx *c, int prec, sample_metrics *s)
{
	int i, pass;
	for (pass = 0; pass < 2; pass++) {
		double undet[2] = { 0.0, 0.0 };
		s->ulp_max = s->abs_eps_max = s->bits_sum = s->bits_max = 0.0;
		s->nbits = 0;
		for (i = 0; i < s->ncomp; i++)
			forward(c, i, s->out[i], prec, s, undet);
		if (undet[0] <= s->abs_eps_max && undet[1] <= s->ulp_max)
			return;
		for (i = 0; i < s->ncomp; i++)
			ziv_diff(c->z, i, &c->zo);
	}
}

static int finite6(const double *v, int k)
{
	int i;
	for (i = 0; i < k; i++)
		if (!isfinite(v[i]))
			return 0;
	return 1;
}

/* RN to double of (a.n)/|n| - z for the dot whose exact products
   dot_exact has just left in c->q[0..2], the input's |n|^2 from its
   exact squares: correct whatever the context's precision
   (ref_round_quot).  A product by a rounded 1/|n| rounded the result
   twice. */
static double over_norm(ref_ctx *c, double z)
{
	mpfr_ptr s[3], q[3];
	int i;
	for (i = 0; i < 3; i++) {
		s[i] = c->q[i];
		q[i] = c->nsq[i];
	}
	return ref_round_quot(s, 3, q, 3, z, ref_format_of(PREC_DOUBLE));
}

/* The five defects of the basis b (doubles) for the input n held in
   c->n: |b1|-1, |b2|-1, b1.n, b2.n (against n/|n| when normalize_n),
   b1.b2. */
static void basis_defects(ref_ctx *c, const double b[6], const double n[3], int normalize_n, double d[NDEF])
{
	mpfr_t *t = c->k.t;
	kit_set3(c->b1, b[0], b[1], b[2]);
	kit_set3(c->b2, b[3], b[4], b[5]);
	d[DEF_N1] = norm_m1_exact(c, c->b1, b);
	d[DEF_N2] = norm_m1_exact(c, c->b2, b + 3);
	/* b.n, or b.(n/|n|) = (b.n)/|n| against the normalized input */
	dot_exact(c, t[0], c->b1, c->n, b, n, 0.0);
	d[DEF_D1N] = normalize_n ? over_norm(c, 0.0) : sum_d(c, t[0]);
	dot_exact(c, t[0], c->b2, c->n, b + 3, n, 0.0);
	d[DEF_D2N] = normalize_n ? over_norm(c, 0.0) : sum_d(c, t[0]);
	dot_exact(c, t[0], c->b1, c->b2, b, b + 3, 0.0); d[DEF_D12] = sum_d(c, t[0]);
}

/* | |w| - 1 | and | w.n - z | (w.(n/|n|) - z when normalize_n) of the
   direction w (doubles) for the input n held in c->n. */
static void dir_errors(ref_ctx *c, const double w[3], const double n[3], const double loc[3], int prec,
                       int normalize_n, double *dir_norm, double *dir_cos)
{
	mpfr_t *t = c->k.t;
	const double z = prec == PREC_FLOAT ? (double)(float)loc[2] : prec == PREC_HALF ? prec_half_round(loc[2]) : loc[2];
	kit_set3(c->k.w, w[0], w[1], w[2]);
	*dir_norm = fabs(norm_m1_exact(c, c->k.w, w));
	if (normalize_n) {
		dot_exact(c, t[0], c->k.w, c->n, w, n, 0.0);
		*dir_cos = fabs(over_norm(c, z));
	} else {
		dot_exact(c, t[0], c->k.w, c->n, w, n, z);
		*dir_cos = fabs(sum_d(c, t[0]));
	}
}

/* ---- binary16 ---------------------------------------------- */
/* w = x b1 + y b2 + z n in binary16 arithmetic, each operation rounded
   (as the float kernels' w is in float): products and sums of binary16
   values are exact in double, so one prec_half_round after each is the
   correctly rounded binary16 result.  loc is rounded to binary16 first. */
static void half_direction(const double b[6], const double n[3], const double loc[3], double w[3])
{
	const double x = prec_half_round(loc[0]), y = prec_half_round(loc[1]), z = prec_half_round(loc[2]);
	int i;
	for (i = 0; i < 3; i++)
		w[i] = prec_half_round(prec_half_round(prec_half_round(x * b[i]) + prec_half_round(y * b[3 + i])) +
		                       prec_half_round(z * n[i]));
}

/* The binary16 kernel (onb_NAME_arrayh, on encodings) on n (binary16
   values): s->out and s->w.  kernel_runs() admits only kernels that have it. */
static void run_kernel_half(const study_kernel *k, const double n[3], const double loc[3], sample_metrics *s)
{
	uint16_t hn[3], hb[6];
	int i;
	for (i = 0; i < 3; i++)
		hn[i] = prec_half_bits(n[i]);
	k->m->arrayh(hn, hb, hb + 3);
	for (i = 0; i < 6; i++)
		s->out[i] = prec_half_value(hb[i]);
	half_direction(s->out, n, loc, s->w);
}

/* ---- the accuracy floor ------------------------------------ */
/* The floor of a kernel on an input: the metrics of its family's exact
   formula, on the kernel's branch, with each output component rounded
   ONCE (to nearest, ties to even) to the format: what a perfect
   implementation of that formula would return.  The roundings are Ziv's
   (ziv.c, c->zo.fmt): correct whatever the reference's precision. */
/* s->floor, s->floor_dir_norm, s->floor_dir_cos (NaN when the exact
   formula is not finite there, e.g. tangent_cross_z at +-z).  For a basis
   method the floor's direction is w = x b1 + y b2 + z n from the rounded
   exact basis, in the format's arithmetic as the kernel's w is; for
   frisvad_rotate it is the exact rotated direction rounded once. */
static void floor_eval(ref_ctx *c, const study_kernel *k, int prec, const double n[3], const double loc[3],
                       int normalize_n, sample_metrics *s)
{
	double fb[6], w[3], d[NDEF];
	int i;
	s->floor = s->floor_dir_norm = s->floor_dir_cos = s->floor_ratio = NAN;
	memcpy(fb, c->zo.fmt, sizeof fb);
	if (!finite6(fb, k->m ? 6 : 3))
		return;
	if (k->m) {
		if (prec == PREC_FLOAT) {
			const float x = (float)loc[0], y = (float)loc[1], z = (float)loc[2];
			float b[6], v[3];
			for (i = 0; i < 6; i++)
				b[i] = (float)fb[i];
			for (i = 0; i < 3; i++) {
				v[i] = x * b[i] + y * b[3 + i] + z * (float)n[i];
				w[i] = v[i];
			}
		} else if (prec == PREC_HALF) {
			half_direction(fb, n, loc, w);
		} else {
			for (i = 0; i < 3; i++)
				w[i] = loc[0] * fb[i] + loc[1] * fb[3 + i] + loc[2] * n[i];
		}
		basis_defects(c, fb, n, normalize_n, d);
		s->floor = 0.0;
		for (i = 0; i < NDEF; i++)
			if (fabs(d[i]) > s->floor)
				s->floor = fabs(d[i]);
	} else {
		for (i = 0; i < 3; i++)
			w[i] = fb[i];
	}
	dir_errors(c, w, n, loc, prec, normalize_n, &s->floor_dir_norm, &s->floor_dir_cos);
	/* The ratio.  Errors and floors below u^2 (3.6e-15 in float, 1.2e-32
	   in double) count as u^2: zero for any use of the format; at
	   n = (-1, 0, -2^-126) in float the floor is 6.9e-77 and duff's defect
	   1.2e-38, a raw ratio of 1.7e38 (onbstudy eval). */
	if (!s->nonfinite) {
		const double u2 = prec == PREC_FLOAT ? 0x1p-48 : prec == PREC_HALF ? 0x1p-22 : 0x1p-106;
		const double e = k->m ? s->defect : fmax(s->dir_norm, s->dir_cos);
		const double f = k->m ? s->floor : fmax(s->floor_dir_norm, s->floor_dir_cos);
		s->floor_ratio = fmax(e, u2) / fmax(f, u2);
	}
}

/* The input the kernel receives (n_in rounded to the format) into n, and
   s cleared for it.  The reference reads exactly the values the kernel receives. */
static void read_input(const study_kernel *k, int prec, const double n_in[3], double n[3], sample_metrics *s)
{
	int i;
	for (i = 0; i < 3; i++) {
		if (prec == PREC_FLOAT) {
			volatile float f = (float)n_in[i];
			n[i] = f;
		} else if (prec == PREC_HALF) {
			n[i] = prec_half_round(n_in[i]);
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
}

/* Run the kernel, and the direction through its basis: s->out, s->w. */
static void run_kernel(const study_kernel *k, int prec, const double n[3], const double loc[3], sample_metrics *s)
{
	if (prec == PREC_HALF) {
		run_kernel_half(k, n, loc, s);
	} else if (prec == PREC_FLOAT) {
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

void ref_run_kernel(const study_kernel *k, int prec, const double n_in[3], const double loc[3],
                    double n[3], sample_metrics *s)
{
	read_input(k, prec, n_in, n, s);
	run_kernel(k, prec, n, loc, s);
}

/* The input's own |n| - 1 and exact squares once per input, not per kernel:
   the sweep evaluates every kernel on an input in a row.  Compared by
   bit pattern, so -0 and +0 are different inputs. */
static void input_norm(ref_ctx *c, const double n[3])
{
	if (!c->have_last || memcmp(c->last, n, sizeof c->last) != 0) {
		kit_set3(c->n, n[0], n[1], n[2]);
		c->last_norm = norm_m1_exact(c, c->n, n);
		mpfr_sqr(c->nsq[0], c->n[0], R); /* exact: 106 bits or more */
		mpfr_sqr(c->nsq[1], c->n[1], R);
		mpfr_sqr(c->nsq[2], c->n[2], R);
		memcpy(c->last, n, sizeof c->last);
		c->have_last = 1;
	}
}

void ref_defect_summary(const study_kernel *k, const double n[3], sample_metrics *s)
{
	long double det;
	int i;
	s->defect = 0.0;
	s->sumsq = 0.0;
	for (i = 0; i < NDEF; i++) {
		if (fabs(s->d[i]) > s->defect)
			s->defect = fabs(s->d[i]);
		s->sumsq += s->d[i] * s->d[i];
	}
	/* det(b1, b2, n) = b1 . (b2 x n), in long double: its sign is
	   what matters, and |det| ~ 1 unless the basis has collapsed. */
	{
		long double b1x = s->out[0], b1y = s->out[1], b1z = s->out[2];
		long double b2x = s->out[3], b2y = s->out[4], b2z = s->out[5];
		det = b1x * (b2y * (long double)n[2] - b2z * (long double)n[1])
		    + b1y * (b2z * (long double)n[0] - b2x * (long double)n[2])
		    + b1z * (b2x * (long double)n[1] - b2y * (long double)n[0]);
	}
	s->det = (double)det;
	s->wrong_hand = !(s->det * k->m->handedness > 0.0);
}

/* Orthonormality defect of the rounded outputs, and their handedness. */
static void basis_output_defects(ref_ctx *c, const study_kernel *k, const double n[3], int normalize_n,
                                 sample_metrics *s)
{
	basis_defects(c, s->out, n, normalize_n, s->d);
	ref_defect_summary(k, n, s);
}

void ref_eval(ref_ctx *c, const study_kernel *k, int prec, const double n_in[3],
              const double loc[3], int normalize_n, sample_metrics *s)
{
	int i;
	double n[3];
	ref_run_kernel(k, prec, n_in, loc, n, s);
	input_norm(c, n);
	s->in_norm = c->last_norm;

	if (!finite6(s->out, s->ncomp) || !finite6(s->w, 3)) {
		s->nonfinite = 1;
		s->ulp_max = s->abs_eps_max = s->bits_sum = s->bits_max = NAN;
		s->dir_norm = s->dir_cos = NAN;
		for (i = 0; i < 6; i++)
			s->ref[i] = NAN;
		/* the floor does not depend on the kernel's output */
		reference(c, k, s->branch, loc);
		ziv_round(c->z, k, prec, s->branch, n, loc, c->r1, c->r2, c->exact, NULL, &c->zo);
		floor_eval(c, k, prec, n, loc, normalize_n, s);
		return;
	}

	if (k->m)
		basis_output_defects(c, k, n, normalize_n, s);

	/* Forward error against the kernel's own formula. */
	reference(c, k, s->branch, loc);
	ziv_round(c->z, k, prec, s->branch, n, loc, c->r1, c->r2, c->exact, s->out, &c->zo);
	forward_all(c, prec, s);

	/* Direction error: | |w| - 1 | and | w.n - z |. */
	dir_errors(c, s->w, n, loc, prec, normalize_n, &s->dir_norm, &s->dir_cos);

	/* The accuracy floor: the same metrics for the exact formula (r1, r2,
	   still in c) rounded once to the format. */
	floor_eval(c, k, prec, n, loc, normalize_n, s);
}

/* Agreement of one metric: relative 2^-40, or absolute `abs_tol` (the
   noise floor of a forward metric: the reference's own rounding at 127
   bits reaches 2^-23 ulps of an exact value just above eps, so forward
   errors are compared to 2^-16 ulps or eps; the defects are sums of
   exact products and must agree to 2^-40 relative). */
static int close_enough(double a, double b, double abs_tol)
{
	if (isnan(a) || isnan(b))
		return isnan(a) && isnan(b);
	if (a == b)
		return 1;
	return fabs(a - b) <= 0x1p-40 * fmax(fabs(a), fabs(b)) || fabs(a - b) <= abs_tol;
}

int ref_agree(const sample_metrics *a, const sample_metrics *b, char *why, size_t n)
{
	const struct { const char *name; double x, y, tol; } v[] = {
		{ "|b1|-1", a->d[0], b->d[0], 0.0 }, { "|b2|-1", a->d[1], b->d[1], 0.0 },
		{ "b1.n", a->d[2], b->d[2], 0.0 }, { "b2.n", a->d[3], b->d[3], 0.0 },
		{ "b1.b2", a->d[4], b->d[4], 0.0 }, { "|n|-1", a->in_norm, b->in_norm, 0.0 },
		{ "ulp", a->ulp_max, b->ulp_max, 0x1p-16 }, { "abs/eps", a->abs_eps_max, b->abs_eps_max, 0x1p-16 },
		{ "bits", a->bits_sum, b->bits_sum, 0x1p-16 }, { "|w|-1", a->dir_norm, b->dir_norm, 0.0 },
		{ "w.n-z", a->dir_cos, b->dir_cos, 0.0 },
		{ "floor", a->floor, b->floor, 0.0 }, { "floor |w|-1", a->floor_dir_norm, b->floor_dir_norm, 0.0 },
		{ "floor w.n-z", a->floor_dir_cos, b->floor_dir_cos, 0.0 },
	};
	size_t i;
	for (i = 0; i < sizeof v / sizeof v[0]; i++)
		if (!close_enough(v[i].x, v[i].y, v[i].tol)) {
			snprintf(why, n, "%s: %a at one precision, %a at the other", v[i].name, v[i].x, v[i].y);
			return 0;
		}
	return 1;
}

void ref_defects(ref_ctx *c, const double n[3], const double b[6], double d[NDEF])
{
	mpfr_t *t = c->k.t;
	kit_set3(c->n, n[0], n[1], n[2]);
	c->have_last = 0; /* c->n no longer holds the cached input */
	kit_set3(c->b1, b[0], b[1], b[2]);
	kit_set3(c->b2, b[3], b[4], b[5]);
	d[DEF_N1] = norm_m1_exact(c, c->b1, b);
	d[DEF_N2] = norm_m1_exact(c, c->b2, b + 3);
	dot_exact(c, t[0], c->b1, c->n, b, n, 0.0); d[DEF_D1N] = sum_d(c, t[0]);
	dot_exact(c, t[0], c->b2, c->n, b + 3, n, 0.0); d[DEF_D2N] = sum_d(c, t[0]);
	dot_exact(c, t[0], c->b1, c->b2, b, b + 3, 0.0); d[DEF_D12] = sum_d(c, t[0]);
}
