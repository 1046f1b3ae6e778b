/*
 * model.c - the model context and its exact-execution back end (CM_EXEC);
 * CM_MVF operations are passed on to mvf.c.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <mpfr.h>
#include "libonb/onb.h"
#include "model.h"
#include "model_int.h"

cm *cm_new(int backend)
{
	cm *c = calloc(1, sizeof *c);
	if (!c)
		return NULL;
	c->backend = backend;
	if (backend == CM_MVF && !(c->m = mvf_new())) {
		free(c);
		return NULL;
	}
	return c;
}

/* CM_EXEC in binary16: each operation done by MPFR at 11 bits and
   brought into binary16's range (prec.h's format table) by
   mpfr_check_range and mpfr_subnormalize: underflow to a subnormal or to
   zero, overflow to infinity, with no double rounding.  This shares no
   code with libonb's half kernels (src/lib/half.c, which round float
   results through _Float16 casts), so the model's bits checking theirs
   (tests/test_half.c) is an independent per-operation evaluation. */
struct cm_half { mpfr_t a, b, d, r; };
enum { HX_SET, HX_ADD, HX_SUB, HX_MUL, HX_DIV, HX_SQRT, HX_FMA };

static struct cm_half *half_scratch(cm *c)
{
	if (!c->half && (c->half = malloc(sizeof *c->half)) != NULL) {
		mpfr_inits2(64, c->half->a, c->half->b, c->half->d, (mpfr_ptr)0);
		mpfr_init2(c->half->r, prec_fmt(PREC_HALF)->bits);
	}
	return c->half;
}

static double half_op(cm *c, int op, double a, double b, double d)
{
	struct cm_half *h = half_scratch(c);
	const prec_format *F = prec_fmt(PREC_HALF);
	const mpfr_exp_t emin = mpfr_get_emin(), emax = mpfr_get_emax();
	int t = 0;
	if (!h) {
		c->failed = 1;
		return NAN;
	}
	mpfr_set_d(h->a, a, MPFR_RNDN);   /* exact: 64 >= 53 bits */
	mpfr_set_d(h->b, b, MPFR_RNDN);
	mpfr_set_d(h->d, d, MPFR_RNDN);
	switch (op) {
	case HX_ADD:  t = mpfr_add(h->r, h->a, h->b, MPFR_RNDN); break;
	case HX_SUB:  t = mpfr_sub(h->r, h->a, h->b, MPFR_RNDN); break;
	case HX_MUL:  t = mpfr_mul(h->r, h->a, h->b, MPFR_RNDN); break;
	case HX_DIV:  t = mpfr_div(h->r, h->a, h->b, MPFR_RNDN); break;
	case HX_SQRT: t = mpfr_sqrt(h->r, h->a, MPFR_RNDN); break;
	case HX_FMA:  t = mpfr_fma(h->r, h->a, h->b, h->d, MPFR_RNDN); break;
	default:      t = mpfr_set(h->r, h->a, MPFR_RNDN); break;
	}
	/* MPFR's x = m 2^e with m in [1/2, 1): binary16's subnormal step
	   2^(emin - p + 1) is 2^(emin_mpfr - 1), its largest finite < 2^(emax + 1) */
	mpfr_set_emin(F->emin - F->bits + 2);
	mpfr_set_emax(F->emax + 1);
	t = mpfr_check_range(h->r, t, MPFR_RNDN);
	mpfr_subnormalize(h->r, t, MPFR_RNDN);
	mpfr_set_emin(emin);
	mpfr_set_emax(emax);
	return mpfr_get_d(h->r, MPFR_RNDN);  /* exact */
}

double cm_round(cm *c, int f, double v)
{
	if (f == PREC_HALF)   /* a NaN keeps its sign bit, as a conversion does */
		return isnan(v) ? v : half_op(c, HX_SET, v, 0.0, 0.0);
	if (f == PREC_FLOAT) {
		volatile float r = (float)v;
		return r;
	}
	return v;
}

void cm_free(cm *c)
{
	if (!c)
		return;
	if (c->m)
		mvf_free(c->m);
	if (c->half) {
		mpfr_clears(c->half->a, c->half->b, c->half->d, c->half->r, (mpfr_ptr)0);
		free(c->half);
	}
	free(c);
}

int cm_backend(const cm *c) { return c->backend; }
int cm_failed(const cm *c) { return c->failed || (c->m && mvf_failed(c->m)); }

void cm_exec_begin(cm *c, int f, const double n[3], cv in[3])
{
	int i;
	c->n = 0;
	c->failed = 0;
	c->emu_k = 0;
	c->exec_f = f;
	for (i = 0; i < 3; i++) {
		c->x[c->n] = cm_round(c, f, n[i]);
		c->pa[c->n] = c->pb[c->n] = -1;
		in[i] = c->n++;
	}
}

double cm_value(const cm *c, cv v) { return c->x[v]; }

cv cm__put(cm *c, double v)
{
	if (c->n >= CM_MAXV) {
		c->failed = 1;
		return CM_MAXV - 1;
	}
	c->x[c->n] = v;
	c->pa[c->n] = c->pb[c->n] = -1;
	return c->n++;
}
#define put cm__put

void cm_set_arith(cm *c, const arith_profile *p)
{
	c->ar = arith_is_ieee(p) ? NULL : p;
	if (c->m)
		mvf_set_arith(c->m, c->ar);
}

const arith_profile *cm_arith(const cm *c) { return c->ar ? c->ar : arith_ieee(); }
int cm_unbounded_op(const cm *c) { return c->m ? mvf_unbounded_op(c->m) : -1; }
int cm_lost_op(const cm *c) { return c->m ? mvf_lost_op(c->m) : -1; }

void cm_set_emu(cm *c, int mode, unsigned long long seed, const unsigned char *choice, int n)
{
	c->emu_mode = mode;
	c->emu_rng = seed;
	c->emu_choice = choice;
	c->emu_nchoice = n;
}

int cm_emu_ops(const cm *c) { return c->emu_k; }
unsigned cm_emu_avail(const cm *c, int k) { return k >= 0 && k < CM_EMU_MAXOP ? c->emu_avail[k] : 0u; }

/* An operation of CM_EXEC under a profile (emu.c). */
#define EMU(op, f, a, b, d) if (c->ar && c->backend == CM_EXEC) return cm__emu_op(c, op, f, a, b, d)

/* Round an exactly-or-correctly computed double to format f (through a
   volatile: GCC 12.2 at -O2 can drop a (double)(float) rounding, see
   fmt_round in src/study/inputs.c). */
static double fmt(int f, double v)
{
	if (f == PREC_FLOAT) {
		volatile float r = (float)v;
		return r;
	}
	return v;
}

/* Float operations are done in double and rounded to float: for +, -, *,
   / and sqrt of float operands that double rounding is innocuous
   (53 >= 2*24 + 2), so the result is the correctly rounded float one. */
cv cm_cst(cm *c, double v)
{
	return c->backend == CM_MVF ? mvf_cst(c->m, v) : put(c, v);
}

cv cm_add(cm *c, int f, cv a, cv b)
{
	EMU(MVF_ADD, f, a, b, -1);
	return c->backend == CM_MVF ? mvf_op(c->m, MVF_ADD, f, a, b, -1)
	     : f == PREC_HALF ? put(c, half_op(c, HX_ADD, c->x[a], c->x[b], 0.0))
	                            : put(c, fmt(f, c->x[a] + c->x[b]));
}
cv cm_sub(cm *c, int f, cv a, cv b)
{
	EMU(MVF_SUB, f, a, b, -1);
	return c->backend == CM_MVF ? mvf_op(c->m, MVF_SUB, f, a, b, -1)
	     : f == PREC_HALF ? put(c, half_op(c, HX_SUB, c->x[a], c->x[b], 0.0))
	                            : put(c, fmt(f, c->x[a] - c->x[b]));
}
cv cm_mul(cm *c, int f, cv a, cv b)
{
	EMU(MVF_MUL, f, a, b, -1);
	return c->backend == CM_MVF ? mvf_op(c->m, MVF_MUL, f, a, b, -1)
	     : f == PREC_HALF ? put(c, half_op(c, HX_MUL, c->x[a], c->x[b], 0.0))
	                            : put(c, fmt(f, c->x[a] * c->x[b]));
}
cv cm_div(cm *c, int f, cv a, cv b)
{
	EMU(MVF_DIV, f, a, b, -1);
	return c->backend == CM_MVF ? mvf_op(c->m, MVF_DIV, f, a, b, -1)
	     : f == PREC_HALF ? put(c, half_op(c, HX_DIV, c->x[a], c->x[b], 0.0))
	                            : put(c, fmt(f, c->x[a] / c->x[b]));
}
cv cm_sqrt(cm *c, int f, cv a)
{
	EMU(MVF_SQRT, f, a, -1, -1);
	return c->backend == CM_MVF ? mvf_op(c->m, MVF_SQRT, f, a, -1, -1)
	     : f == PREC_HALF ? put(c, half_op(c, HX_SQRT, c->x[a], 0.0, 0.0))
	                            : put(c, fmt(f, sqrt(c->x[a])));
}
/* V8's fdlibm (src/lib/fdlibm.c), in double.  CM_MVF has no enclosure of
   these functions: the run fails (no bound), see model.h. */
cv cm_libm(cm *c, int fn, cv a, cv b)
{
	double x, r;
	if (c->backend == CM_MVF) {
		mvf_fail(c->m);
		return mvf_cst(c->m, 0.0);
	}
	x = c->x[a];
	switch (fn) {
	case CM_ACOS:  r = onb__fdlibm_acos(x); break;
	case CM_ATAN2: r = onb__fdlibm_atan2(x, c->x[b]); break;
	case CM_SIN:   r = onb__fdlibm_sin(x); break;
	default:       r = onb__fdlibm_cos(x); break;
	}
	return put(c, r);
}
cv cm_fma(cm *c, int f, cv a, cv b, cv d)
{
	EMU(MVF_FMA, f, a, b, d);
	if (c->backend == CM_MVF)
		return mvf_op(c->m, MVF_FMA, f, a, b, d);
	if (f == PREC_HALF)
		return put(c, half_op(c, HX_FMA, c->x[a], c->x[b], c->x[d]));
	if (f == PREC_FLOAT)
		return put(c, (double)fmaf((float)c->x[a], (float)c->x[b], (float)c->x[d]));
	return put(c, fma(c->x[a], c->x[b], c->x[d]));
}
cv cm_cvt(cm *c, int f, cv a)
{
	EMU(MVF_CVT, f, a, -1, -1);
	return c->backend == CM_MVF ? mvf_op(c->m, MVF_CVT, f, a, -1, -1) : put(c, cm_round(c, f, c->x[a]));
}
cv cm_neg(cm *c, cv a)
{
	return c->backend == CM_MVF ? mvf_op(c->m, MVF_NEG, PREC_DOUBLE, a, -1, -1) : put(c, -c->x[a]);
}

/* The seeds as the kernels compute them (include/libonb/onb.h). */
static double exec_seed(seed_kind k, double a)
{
	if (k == SEED_RSQRTSS)
		return (double)onb__hw_rsqrtf((float)a);
	if (k == SEED_INVSQRT_F) {
		float x = (float)a;
		uint32_t i;
		memcpy(&i, &x, sizeof i);
		i = 0x5f3759dfu - (i >> 1);
		memcpy(&x, &i, sizeof x);
		return (double)x;
	} else {
		uint64_t i;
		memcpy(&i, &a, sizeof i);
		i = UINT64_C(0x5fe6eb50c7b537a9) - (i >> 1);
		memcpy(&a, &i, sizeof a);
		return a;
	}
}

cv cm_seed(cm *c, seed_kind k, cv a)
{
	return c->backend == CM_MVF ? mvf_seed(c->m, k, a) : put(c, exec_seed(k, c->x[a]));
}

cv cm_newton(cm *c, int f, cv x, cv y)
{
	double h, t;
	if (c->ar)   /* a profile: the operations one by one, as the kernel does them */
		return cm_mul(c, f, y, cm_sub(c, f, cm_cst(c, 1.5),
		              cm_mul(c, f, cm_mul(c, f, cm_mul(c, f, cm_cst(c, 0.5), x), y), y)));
	if (c->backend == CM_MVF)
		return mvf_newton(c->m, f, x, y, 0);
	h = cm_round(c, f, 0.5 * c->x[x]);   /* each product and difference exact in double for float and half operands */
	t = cm_round(c, f, cm_round(c, f, h * c->x[y]) * c->x[y]);
	return put(c, cm_round(c, f, c->x[y] * cm_round(c, f, 1.5 - t)));
}

/* The contracted steps.  GCC fuses the last product of Listing 3's step
   (y (1.5 - y (h y)): one rounding fewer) and Embree's 1.5 y (its sum
   rounded once).  Each is the plain step with that rounding's error set
   to 0, and the plain enclosures (newton_rel in mvf.c) hold for every
   error in [-u, u] independently, 0 included: they bound the fused steps
   too, and keep Newton's cancellation, which an operation-by-operation
   mean value form loses (hughes_moeller_rsqrt_nr float+fma: 1.68e4 u
   against 21.7 u). */
cv cm_newton_fused(cm *c, int f, cv x, cv y)
{
	if (c->backend == CM_MVF)
		return mvf_newton(c->m, f, x, y, 1);
	return cm_mul(c, f, y, cm_fma(c, f, cm_neg(c, y), cm_mul(c, f, cm_mul(c, f, x, cm_cst(c, 0.5)), y), cm_cst(c, 1.5)));
}

cv cm_newton_embree_fused(cm *c, int f, cv x, cv y)
{
	cv r;
	if (c->backend == CM_MVF && (r = mvf_newton_embree(c->m, f, x, y, 1)) >= 0)
		return r;
	return cm_fma(c, f, y, cm_cst(c, 1.5),
	              cm_mul(c, f, cm_mul(c, f, cm_mul(c, f, x, cm_cst(c, -0.5)), y), cm_mul(c, f, y, y)));
}

cv cm_newton_embree(cm *c, int f, cv x, cv y)
{
	cv r;
	if (c->backend == CM_MVF && (r = mvf_newton_embree(c->m, f, x, y, 0)) >= 0)
		return r;
	return cm_add(c, f, cm_mul(c, f, cm_cst(c, 1.5), y),
	              cm_mul(c, f, cm_mul(c, f, cm_mul(c, f, x, cm_cst(c, -0.5)), y), cm_mul(c, f, y, y)));
}

/* Branches: CM_EXEC compares the values; CM_MVF takes the path's side. */
static int take(cm *c, int id, int exec_side, int lo_possible, int hi_possible)
{
	int side;
	if (c->backend == CM_EXEC)
		return exec_side;
	side = (int)((c->path >> id) & 1u);
	c->seen |= 1u << id;
	if (!(side ? hi_possible : lo_possible) && !mvf_zero_e(c->m)) {
		c->infeasible = 1;
		mvf_abandon(c->m);   /* its bound is not wanted: skip the rest */
	}
	return side;
}

int cm_branch(cm *c, int id, int op, cv a, cv b)
{
	int t = 0, f = 0;
	if (c->ar)
		cm__emu_read2(c, &a, &b);
	if (c->backend == CM_EXEC)
		return op == CM_LT ? c->x[a] < c->x[b] : c->x[a] > c->x[b];
	mvf_compare(c->m, op, 0, a, b, &t, &f);
	t = take(c, id, 0, f, t);
	mvf_constrain(c->m, op, 0, a, b, t);
	mvf_note_strict(c->m, op, 0, a, b, t);
	return t;
}

int cm_branch_abs(cm *c, int id, int op, cv a, cv b)
{
	int t = 0, f = 0;
	if (c->ar)
		cm__emu_read2(c, &a, &b);
	if (c->backend == CM_EXEC)
		return op == CM_LT ? fabs(c->x[a]) < fabs(c->x[b]) : fabs(c->x[a]) > fabs(c->x[b]);
	mvf_compare(c->m, op, 1, a, b, &t, &f);
	t = take(c, id, 0, f, t);
	mvf_constrain(c->m, op, 1, a, b, t);
	mvf_note_strict(c->m, op, 1, a, b, t);
	return t;
}

int cm_branch_sign(cm *c, int id, cv a)
{
	int t = 0, f = 0;
	if (c->ar && c->backend == CM_EXEC)
		return cm__emu_sign(c, a);
	if (c->ar)
		a = mvf_read(c->m, a);
	if (c->backend == CM_EXEC)
		return signbit(c->x[a]) != 0;
	mvf_sign_possible(c->m, a, &t, &f);
	t = take(c, id, 0, f, t);
	mvf_constrain_sign(c->m, a, t);
	return t;
}

void cm_formula_nonzero(cm *c, unsigned mask)
{
	c->nonzero |= mask;
}

void cm_formula_zero_after(cm *c, unsigned zero)
{
	c->zero_late = zero;   /* CM_EXEC: kept for certify's keys (keys.c) */
	if (c->backend != CM_MVF)
		return;
	c->late_var = mvf_nvar(c->m);
}

void cm_formula_exact_n(cm *c, unsigned zero, unsigned norm)
{
	c->zero_n |= zero;
	c->norm_n |= norm & CQ_LENGTHS;
}
