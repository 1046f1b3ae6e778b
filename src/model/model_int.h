/*
 * model_int.h - inside the model context: shared by model.c, model_kit.h and
 * mvf.c, never by the command.
 */
#ifndef ONB_CERTIFY_MODEL_INT_H
#define ONB_CERTIFY_MODEL_INT_H

#include "model.h"

#define CM_MAXV 256   /* values of one model run (the largest uses ~90)   */

/* The five defect quantities: |b1|-1, |b2|-1, b1.n, b2.n, b1.b2. */
enum { CQ_N1 = 0, CQ_N2, CQ_D1N, CQ_D2N, CQ_D12, NCQ };
#define CQ_ALL    0x1fu
#define CQ_LENGTHS 0x3u

typedef struct mvf mvf;

struct cm {
	int backend;
	int failed;
	int n;                 /* CM_EXEC: values in use                     */
	double x[CM_MAXV];     /* CM_EXEC: the values                        */
	mvf *m;                /* CM_MVF: the interval arena                 */
	unsigned path;         /* CM_MVF: side of branch point k = bit k     */
	unsigned seen;         /* CM_MVF: the branch points this run met     */
	int infeasible;        /* CM_MVF: the path takes a side no point can */
	unsigned nonzero;      /* quantities not zero in exact arithmetic on
	                          the unit sphere along this path (CQ_ bits)  */
};

/* CM_EXEC: start a run on input n (rounded to format f); in[] receives the
   handles of n.x, n.y, n.z. */
void cm_exec_begin(cm *c, int f, const double n[3], cv in[3]);

/* A model declares, along its current path, which defect quantities are
   not identically zero in exact arithmetic on unit input (e.g. the
   lengths of an unnormalized basis, everything in Frisvad's fallback). */
void cm_formula_nonzero(cm *c, unsigned mask);

/* mvf.c */
enum { MVF_ADD, MVF_SUB, MVF_MUL, MVF_DIV, MVF_SQRT, MVF_FMA, MVF_CVT, MVF_NEG };
mvf *mvf_new(void);
void mvf_free(mvf *m);
int  mvf_failed(const mvf *m);
int  mvf_zero_e(const mvf *m);
cv   mvf_cst(mvf *m, double v);
cv   mvf_op(mvf *m, int op, int f, cv a, cv b, cv d);
cv   mvf_seed(mvf *m, seed_kind k, cv a);
cv   mvf_newton(mvf *m, int f, cv x, cv y);
void mvf_compare(mvf *m, int op, int absolute, cv a, cv b, int *can_true, int *can_false);
void mvf_sign_possible(mvf *m, cv a, int *can_set, int *can_clear);
void mvf_constrain(mvf *m, int op, int absolute, cv a, cv b, int side);
void mvf_constrain_sign(mvf *m, cv a, int set);

#endif
