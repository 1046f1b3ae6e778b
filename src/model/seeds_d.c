/*
 * seeds_d.c - the double InvSqrt seed 0x5fe6eb50c7b537a9 - (i >> 1)
 * (Lomont), bounded with outward-rounded interval arithmetic (MPFI).
 *
 * Structure.  A positive normal double x has biased exponent eb (1..2046)
 * and fraction F (52 bits): i = eb 2^52 + F.  Then
 *   i >> 1 = floor(eb / 2) 2^52 + h,   h = (eb odd ? 2^51 : 0) + f,
 * with f = floor(F / 2) in [0, 2^51).  With C = Ce 2^52 + Fc
 * (Ce = 0x5fe, Fc = 0x6eb50c7b537a9), C - (i >> 1) has
 *   exponent Eout = Ce - floor(eb / 2) - w,  fraction w 2^52 + Fc - h,
 * where w = (h > Fc) is the borrow across the exponent field.  Eout stays
 * in [510, 1534] (normal), and C > i >> 1 for every double, so there is
 * no wrap-around: for x = x0 4^k, s(x) = s(x0) 2^-k exactly and the
 * relative error s sqrt(x) - 1 depends on eb only through its parity.
 * The two parities, eb = 1023 (x in [1, 2)) and eb = 1024 (x in [2, 4)),
 * give three pieces where w is constant (eb odd: h >= 2^51 > Fc, always a
 * borrow; eb even: no borrow for f <= Fc, a borrow above).  On a piece s
 * is affine in f, and x = 2^(eb-1023) (1 + (2f + b) 2^-52), b in {0, 1}
 * (the floor).  The proof bounds g(f, b) = s(f) sqrt(x(f, b)) - 1 over
 * f in the piece (relaxed to reals) and b in [0, 1] by branch and bound
 * on f, each box enclosed by the intersection of the natural interval
 * extension and the mean-value form (g' by hand: s' sqrt(x) + s x' /
 * (2 sqrt(x))), all in MPFI at 128 bits, rounded outward.
 */
#include <math.h>
#include <mpfi.h>
#include <stdio.h>
#include <string.h>
#include "seeds.h"

#define CE 0x5feu
#define FC UINT64_C(0x6eb50c7b537a9)
#define F51 (UINT64_C(1) << 51)

typedef struct { int eb, w; uint64_t flo, fhi; } piece;

typedef struct {
	mpfi_t t, b, s, x, sq, g, mv, d, tmp; /* work intervals */
	mpfr_t r;
} work;

#define WORK_VARS(X) X(t) X(b) X(s) X(x) X(sq) X(g) X(mv) X(d) X(tmp)
#define INIT_ONE(v) mpfi_init2(W->v, 128);
#define CLEAR_ONE(v) mpfi_clear(W->v);
static void work_init(work *W)  { WORK_VARS(INIT_ONE) mpfr_init2(W->r, 128); }
static void work_clear(work *W) { WORK_VARS(CLEAR_ONE) mpfr_clear(W->r); }

static int eout(const piece *p) { return (int)CE - p->eb / 2 - p->w; }

/* s over f in t: 2^(Eout-1023) (1 + (w 2^52 + Fc - h) 2^-52) */
static void eval_s(work *W, const piece *p, mpfi_t f)
{
	const double hodd = (p->eb & 1) ? (double)F51 : 0.0;
	mpfi_add_d(W->s, f, hodd);                                 /* h */
	mpfi_d_sub(W->s, (double)FC + (p->w ? 0x1p52 : 0.0), W->s); /* fraction */
	mpfi_mul_2si(W->s, W->s, -52);
	mpfi_add_ui(W->s, W->s, 1);
	mpfi_mul_2si(W->s, W->s, eout(p) - 1023);
}

/* x over f in t, b in W->b: 2^(eb-1023) (1 + (2f + b) 2^-52) */
static void eval_x(work *W, const piece *p, mpfi_t f)
{
	mpfi_mul_2si(W->x, f, 1);
	mpfi_add(W->x, W->x, W->b);
	mpfi_mul_2si(W->x, W->x, -52);
	mpfi_add_ui(W->x, W->x, 1);
	mpfi_mul_2si(W->x, W->x, p->eb - 1023);
}

/* W->g = g(f, b) at f in f (natural extension); leaves s, x, sq set. */
static void eval_g(work *W, const piece *p, mpfi_t f)
{
	eval_s(W, p, f);
	eval_x(W, p, f);
	mpfi_sqrt(W->sq, W->x);
	mpfi_mul(W->g, W->s, W->sq);
	mpfi_sub_ui(W->g, W->g, 1);
}

/* Enclosure of g over the box [lo, hi] of f (b in [0, 1]) into W->g. */
static void enclose(work *W, const piece *p, uint64_t lo, uint64_t hi)
{
	const uint64_t mid = lo + (hi - lo) / 2;
	mpfi_interv_d(W->t, (double)lo, (double)hi);
	eval_g(W, p, W->t);
	/* g'(t) = s' sq + s x' / (2 sq), s' = -2^(Eout-1075), x' = 2^(eb-1074) */
	mpfi_set_d(W->d, -1.0);
	mpfi_mul_2si(W->d, W->d, eout(p) - 1075);
	mpfi_mul(W->d, W->d, W->sq);
	mpfi_div(W->tmp, W->s, W->sq);
	mpfi_mul_2si(W->tmp, W->tmp, p->eb - 1074 - 1);
	mpfi_add(W->d, W->d, W->tmp);
	mpfi_sub_d(W->tmp, W->t, (double)mid);                 /* t - mid */
	mpfi_mul(W->d, W->d, W->tmp);
	mpfi_swap(W->mv, W->g);                                /* keep the natural one */
	mpfi_set_d(W->tmp, (double)mid);
	eval_g(W, p, W->tmp);
	mpfi_add(W->g, W->g, W->d);                            /* mean-value form */
	mpfi_intersect(W->g, W->g, W->mv);
}

static double sup_abs(work *W)
{
	mpfi_mag(W->r, W->g);
	return mpfr_get_d(W->r, MPFR_RNDU);
}

static double point_of(const piece *p, uint64_t f, int b)
{
	const uint64_t i = ((uint64_t)p->eb << 52) | (2 * f + (uint64_t)b);
	double x;
	memcpy(&x, &i, sizeof x);
	return x;
}

typedef struct { double lower, upper, worst_x; long boxes; } bb_state;

/* The error at the real inputs f (b = 0 and 1): raises the lower bound. */
static void probe(work *W, const piece *p, uint64_t f, bb_state *st)
{
	for (int b = 0; b < 2; b++) {
		double v;
		mpfi_set_si(W->b, b);
		mpfi_set_d(W->t, (double)f);
		eval_g(W, p, W->t);
		mpfi_mig(W->r, W->g);
		v = mpfr_get_d(W->r, MPFR_RNDD);
		if (v > st->lower)
			st->lower = v, st->worst_x = point_of(p, f, b);
	}
	mpfi_interv_si(W->b, 0, 1);
}

/* Branch and bound over one piece: a box is closed when its enclosure's
   sup |g| is within (1 + rtol) of the best real input's error, or when it
   holds a single f; upper is the largest sup of a closed box. */
static int bound_piece(work *W, const piece *p, double rtol, bb_state *st)
{
	uint64_t stack[2 * 128][2];
	int top = 0;
	probe(W, p, p->flo, st);
	probe(W, p, p->fhi, st);
	stack[top][0] = p->flo, stack[top][1] = p->fhi, top++;
	while (top > 0) {
		const uint64_t lo = stack[top - 1][0], hi = stack[top - 1][1];
		const uint64_t mid = lo + (hi - lo) / 2;
		double sup;
		top--;
		enclose(W, p, lo, hi);
		sup = sup_abs(W);
		st->boxes++;
		if (!(sup == sup))
			return -1;
		if (hi == lo || sup <= st->lower * (1.0 + rtol)) {
			if (sup > st->upper)
				st->upper = sup;
			continue;
		}
		probe(W, p, mid, st);
		if (top + 2 > (int)(sizeof stack / sizeof stack[0]))
			return -1;
		stack[top][0] = mid + 1, stack[top][1] = hi, top++;
		stack[top][0] = lo, stack[top][1] = mid, top++;
	}
	return 0;
}

/* The pieces' formula must give the seed's own bits at their ends. */
static int piece_matches(const piece *p, uint64_t f)
{
	const double x = point_of(p, f, 1), s = seed_invsqrt_d(x);
	const uint64_t h = ((p->eb & 1) ? F51 : 0) + f;
	const uint64_t want = ((uint64_t)eout(p) << 52) | ((p->w ? UINT64_C(1) << 52 : 0) + FC - h);
	uint64_t got;
	memcpy(&got, &s, sizeof got);
	return got == want;
}

static int make_pieces(piece *pc)
{
	int n = 0;
	pc[n++] = (piece){ 1023, 1, 0, F51 - 1 };     /* x in [1, 2): h >= 2^51 > Fc */
	pc[n++] = (piece){ 1024, 0, 0, FC };          /* x in [2, 4), no borrow      */
	pc[n++] = (piece){ 1024, 1, FC + 1, F51 - 1 }; /* x in [2, 4), borrow          */
	for (int j = 0; j < n; j++)
		if (!piece_matches(&pc[j], pc[j].flo) || !piece_matches(&pc[j], pc[j].fhi))
			return -1;
	return n;
}

int seed_prove_double(double rtol, seed_bound *out, long *nboxes)
{
	piece pc[3];
	bb_state st = { 0.0, 0.0, 0.0, 0 };
	work W;
	int n = make_pieces(pc), rc = n < 0 ? -1 : 0;
	if (n < 0)
		fprintf(stderr, "seed_prove_double: the piece formula does not match the seed's bits\n");
	work_init(&W);
	mpfi_interv_si(W.b, 0, 1);
	for (int j = 0; j < n && rc == 0; j++)
		rc = bound_piece(&W, &pc[j], rtol, &st);
	work_clear(&W);
	if (rc != 0)
		return -1;
	out->bound = st.upper;
	out->worst_x = st.worst_x;
	out->worst = seed_err_d(st.worst_x, seed_invsqrt_d(st.worst_x));
	out->x_lo = 0x1p-1022;
	out->x_hi = 0x1.fffffffffffffp+1023;
	out->how = "0x5fe6eb50c7b537a9 - (i >> 1): MPFI branch and bound over the 3 mantissa pieces, "
		   "exact in the exponent (s(4x) = s(x)/2)";
	if (nboxes)
		*nboxes = st.boxes;
	return 0;
}
