/*
 * model_int.h - inside the model context: shared by model.c, model_kit.h and
 * mvf.c, never by the command.
 */
#ifndef ONB_CERTIFY_MODEL_INT_H
#define ONB_CERTIFY_MODEL_INT_H

#include "model.h"
#include "arith.h"

#define CM_MAXV 256   /* values of one model run (the largest uses ~90)   */

/* The five defect quantities: |b1|-1, |b2|-1, b1.n, b2.n, b1.b2. */
enum { CQ_N1 = 0, CQ_N2, CQ_D1N, CQ_D2N, CQ_D12, NCQ };
#define CQ_ALL    0x1fu
#define CQ_LENGTHS 0x3u

typedef struct mvf mvf;

struct cm {
	int backend;
	int failed;
	/* The kernel as compiled with FMA contraction (-mfma
	   -ffp-contract=fast, the study's --fma copies): the models' MADD and
	   ADDM are then one fused operation where GCC fuses them. */
	int contract;
	int n;                 /* CM_EXEC: values in use                     */
	double x[CM_MAXV];     /* CM_EXEC: the values                        */
	mvf *m;                /* CM_MVF: the interval arena                 */
	unsigned path;         /* CM_MVF: side of branch point k = bit k     */
	unsigned seen;         /* CM_MVF: the branch points this run met     */
	int infeasible;        /* CM_MVF: the path takes a side no point can */
	unsigned nonzero;      /* quantities not zero in exact arithmetic on
	                          the unit sphere along this path (CQ_ bits)  */
	unsigned zero_n;       /* zero in exact arithmetic for every n, unit
	                          or not, along this path                     */
	unsigned norm_n;       /* lengths |b|^2 - 1 equal to |n|^2 - 1 in exact
	                          arithmetic for every n, along this path     */
	unsigned zero_late;    /* zero for every n and every value computed
	                          before the error term late_var, given exact
	                          arithmetic from there on                    */
	int late_var;
	/* bound.c's cross rule: 2 when the kernel returns b2 = cross(n, b1)
	   (either order of the factors, each component a - b with one or both
	   of its products rounded, or fused: fma(p, q, -fl(r s))) of the
	   input n and the b1 it returns; 1 for b1 from b2 alike; 0 none */
	int cross_to;
	cv cross_q[3];         /* the cross product's values as computed     */
	/* bound.c (run_path): 1 when output cross_to - 1 is cross_q itself, 2
	   when it is cross_q K (1 + d) + eta for one K (a normalization),
	   |d| <= cross_u, |eta| <= cross_eta; 0 neither */
	int cross_kind;
	double cross_u, cross_eta;
	struct cm_half *half;  /* CM_EXEC in binary16: MPFR scratch (model.c) */
	/* An arithmetic profile other than ieee (cm_set_arith), or NULL; and
	   CM_EXEC's emulation of a conforming implementation under it
	   (cm_set_emu): mode, generator, the choices of the operations, the
	   choice bits that applied to each operation of the last run, the
	   operations counted, and the products (value v = x[pa[v]] * x[pb[v]]
	   rounded; -1 none) a contraction may read exact. */
	const arith_profile *ar;
	int emu_mode, emu_nchoice, emu_k, exec_f;
	unsigned long long emu_rng;
	const unsigned char *emu_choice;
	unsigned char emu_avail[CM_EMU_MAXOP];
	short pa[CM_MAXV], pb[CM_MAXV];
};

/* CM_EXEC: start a run on input n (rounded to format f); in[] receives the
   handles of n.x, n.y, n.z. */
void cm_exec_begin(cm *c, int f, const double n[3], cv in[3]);

/* A model declares, along its current path, which defect quantities are
   not identically zero in exact arithmetic on unit input (e.g. the
   lengths of an unnormalized basis, everything in Frisvad's fallback). */
void cm_formula_nonzero(cm *c, unsigned mask);
/* Along the current path, in exact arithmetic and for every n (unit or
   not): the quantities in `zero` are 0, and the lengths in `norm` have
   |b|^2 - 1 = |n|^2 - 1 (b = n x b1 with b1 a unit vector orthogonal to
   n).  Their bound then needs no expansion in the input's own rounding:
   Q(n, e) = Q(n, 0) + sum over the arithmetic's e_k alone. */
void cm_formula_exact_n(cm *c, unsigned zero, unsigned norm);
/* From here on, the quantities in `zero` are 0 in exact arithmetic
   whatever n and the values computed so far are (b2 = n x b1 is orthogonal
   to n and to b1 for any b1): only the error terms of the operations that
   follow enter their bound. */
void cm_formula_zero_after(cm *c, unsigned zero);
int  mvf_nvar(const mvf *m);

/* model.c and emu.c: CM_EXEC's values, and its emulation of a conforming
   implementation under a profile (model.h, cm_set_emu). */
cv   cm__put(cm *c, double v);
cv   cm__emu_op(cm *c, int op, int f, cv a, cv b, cv d);
void cm__emu_read2(cm *c, cv *a, cv *b);   /* comparison operands as read */
int  cm__emu_sign(cm *c, cv a);            /* CM_EXEC's sign test         */

/* mvf.c */
enum { MVF_ADD, MVF_SUB, MVF_MUL, MVF_DIV, MVF_SQRT, MVF_FMA, MVF_CVT, MVF_NEG };
mvf *mvf_new(void);
void mvf_free(mvf *m);
int  mvf_failed(const mvf *m);
void mvf_fail(mvf *m);   /* mark the run failed (cm_libm: no enclosure) */
/* The run failed because a value may exceed its format's largest finite
   value (binary16's 65504: a rounding there may overflow to infinity);
   mvf_overflow_seen: whether any run did since the last call (reset). */
int  mvf_overflowed(const mvf *m);
int  mvf_overflow_seen(mvf *m);
/* Tests only: the model of format f with a significand of `bits` bits
   (u = 2^-bits; binary16's 11 as 12 is a mutant whose bounds a scan of
   the kernels must break); bits 0 restores the format. */
void mvf_mutate_format(int f, int bits);
void mvf_abandon(mvf *m);
int  mvf_no_point(const mvf *m);   /* the path is infeasible for the box */
int  mvf_zero_e(const mvf *m);
cv   mvf_cst(mvf *m, double v);
cv   mvf_op(mvf *m, int op, int f, cv a, cv b, cv d);
cv   mvf_seed(mvf *m, seed_kind k, cv a);
cv   mvf_newton(mvf *m, int f, cv x, cv y, int fused);
cv   mvf_newton_embree(mvf *m, int f, cv x, cv y, int fused);
void mvf_compare(mvf *m, int op, int absolute, cv a, cv b, int *can_true, int *can_false);
void mvf_sign_possible(mvf *m, cv a, int *can_set, int *can_clear);
void mvf_constrain(mvf *m, int op, int absolute, cv a, cv b, int side);
void mvf_constrain_sign(mvf *m, cv a, int set);
void mvf_note_strict(mvf *m, int op, int absolute, cv a, cv b, int side);
/* Arithmetic profiles (arith.h; mvf.c's last section): the profile of the
   runs to come (NULL or ieee: the IEEE model as it is), the operation kind
   (AR_*) that left this run unbounded (-1: none), and operand a as a
   comparison reads it (flushed where it may be subnormal). */
void mvf_set_arith(mvf *m, const arith_profile *p);
int  mvf_unbounded_op(const mvf *m);
int  mvf_lost_op(const mvf *m);
cv   mvf_read(mvf *m, cv a);

#endif
