/*
 * model.c - the model context and its exact-execution back end (CM_EXEC);
 * CM_MVF operations are passed on to mvf.c.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
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

void cm_free(cm *c)
{
	if (!c)
		return;
	if (c->m)
		mvf_free(c->m);
	free(c);
}

int cm_backend(const cm *c) { return c->backend; }
int cm_failed(const cm *c) { return c->failed || (c->m && mvf_failed(c->m)); }

void cm_exec_begin(cm *c, int f, const double n[3], cv in[3])
{
	int i;
	c->n = 0;
	c->failed = 0;
	for (i = 0; i < 3; i++) {
		c->x[c->n] = f == PREC_FLOAT ? (double)(float)n[i] : n[i];
		in[i] = c->n++;
	}
}

double cm_value(const cm *c, cv v) { return c->x[v]; }

static cv put(cm *c, double v)
{
	if (c->n >= CM_MAXV) {
		c->failed = 1;
		return CM_MAXV - 1;
	}
	c->x[c->n] = v;
	return c->n++;
}

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
	return c->backend == CM_MVF ? mvf_op(c->m, MVF_ADD, f, a, b, -1)
	                            : put(c, fmt(f, c->x[a] + c->x[b]));
}
cv cm_sub(cm *c, int f, cv a, cv b)
{
	return c->backend == CM_MVF ? mvf_op(c->m, MVF_SUB, f, a, b, -1)
	                            : put(c, fmt(f, c->x[a] - c->x[b]));
}
cv cm_mul(cm *c, int f, cv a, cv b)
{
	return c->backend == CM_MVF ? mvf_op(c->m, MVF_MUL, f, a, b, -1)
	                            : put(c, fmt(f, c->x[a] * c->x[b]));
}
cv cm_div(cm *c, int f, cv a, cv b)
{
	return c->backend == CM_MVF ? mvf_op(c->m, MVF_DIV, f, a, b, -1)
	                            : put(c, fmt(f, c->x[a] / c->x[b]));
}
cv cm_sqrt(cm *c, int f, cv a)
{
	return c->backend == CM_MVF ? mvf_op(c->m, MVF_SQRT, f, a, -1, -1)
	                            : put(c, fmt(f, sqrt(c->x[a])));
}
cv cm_fma(cm *c, int f, cv a, cv b, cv d)
{
	if (c->backend == CM_MVF)
		return mvf_op(c->m, MVF_FMA, f, a, b, d);
	if (f == PREC_FLOAT)
		return put(c, (double)fmaf((float)c->x[a], (float)c->x[b], (float)c->x[d]));
	return put(c, fma(c->x[a], c->x[b], c->x[d]));
}
cv cm_cvt(cm *c, int f, cv a)
{
	return c->backend == CM_MVF ? mvf_op(c->m, MVF_CVT, f, a, -1, -1) : put(c, fmt(f, c->x[a]));
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
	if (c->backend == CM_MVF)
		return mvf_newton(c->m, f, x, y, 0);
	h = fmt(f, 0.5 * c->x[x]);
	t = fmt(f, fmt(f, h * c->x[y]) * c->x[y]);
	return put(c, fmt(f, c->x[y] * fmt(f, 1.5 - t)));
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
	if (c->backend != CM_MVF)
		return;
	c->zero_late = zero;
	c->late_var = mvf_nvar(c->m);
}

void cm_formula_exact_n(cm *c, unsigned zero, unsigned norm)
{
	c->zero_n |= zero;
	c->norm_n |= norm & CQ_LENGTHS;
}
