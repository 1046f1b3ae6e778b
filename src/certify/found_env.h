/*
 * found_env.h - the state of one region's found side (probe_env) and what
 * every file of the found side shares (found_env.c): the double-double
 * dot product of the screen, and the gate of exact measurements.  Below
 * found.c and found_dir.c, which both use it.
 */
#ifndef ONB_CERTIFY_FOUND_ENV_H
#define ONB_CERTIFY_FOUND_ENV_H

#include "bracket.h"
#include "probe.h"
#include "regions.h"

/* The inputs with the largest defects seen, as screened: where the
   walks start. */
#define FOUND_TOP 16

typedef struct {
	double d;      /* the screened defect */
	double n[3];
} found_cand;

typedef struct {
	cert_ctx *x;
	const study_kernel *k;
	int prec;
	const cert_region *r;
	const cert_opts *o;
	cert_result *res;
	found_cand top[FOUND_TOP];
	int ntop;
	uint64_t rng;
	double gate;   /* the largest screened defect measured so far */
	int no_stall;  /* the branch and bound runs to its budget (search.c) */
} probe_env;

/* Should an input of screened defect d be measured exactly?  When d
   reaches found and exceeds every screened defect measured before by
   more than 2^-40 relative (the screen is good to about 1e-15 relative,
   and the walks meet the same defect again and again on flat ground). */
int found_worth_measuring(probe_env *e, double d);

/* s += v kept as a double-double (s, c) with Neumaier's compensation. */
void found_acc(double *s, double *c, double v);

/* p . q - sub in double-double (found_env.c). */
double found_dot_dd(const double *p, const double *q, double sub);

#endif
