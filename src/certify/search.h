/*
 * search.h - one region's bracket: the largest defect found on a real input
 * of the region, and a certified bound above every input of it (search.c).
 */
#ifndef ONB_CERTIFY_SEARCH_H
#define ONB_CERTIFY_SEARCH_H

#include <stdint.h>
#include "methods/kernels.h"
#include "bound.h"
#include "regions.h"

enum { CERT_PROVEN = 0, CERT_SINGULAR, CERT_BUDGET };

/* An input the found side starts a walk from (--starts): another run's
   worst input of a method, for one precision (-1: either). */
typedef struct {
	char method[48];
	int prec;
	double n[3];
} cert_start;

typedef struct {
	long budget;        /* boxes bounded per region at most                    */
	long samples;       /* kernel inputs sampled per region before the boxes   */
	double target;      /* proven when bound <= target * found (1.25)          */
	double tolerance;   /* < 0: the default domain                             */
	uint64_t seed;
	/* Called with every leaf of the branch and bound and its bound, when
	   set (tests: every input of the region lies in some leaf). */
	void (*leaf_fn)(void *arg, const mvf_box *b, double bound);
	void *leaf_arg;
	const cert_start *starts;   /* walks also start from these (those of the */
	long nstarts;               /* kernel, precision and region)            */
} cert_opts;

typedef struct {
	double bound;       /* certified: no input of the region exceeds it (+inf: none) */
	double found;       /* the largest defect measured on an input of the region */
	double found_n[3];  /* that input (in the format)                          */
	int status;         /* CERT_*                                              */
	int nonfinite;      /* a sampled input gave a non-finite output            */
	long boxes;
	long probes;        /* inputs of the region the found side evaluated      */
} cert_result;

typedef struct cert_ctx cert_ctx;
cert_ctx *cert_ctx_new(void);   /* one per thread; NULL on failure */
void cert_ctx_free(cert_ctx *x);

/* The bracket of kernel k (model m) in precision prec (PREC_FLOAT or
   PREC_DOUBLE) over region r. */
void cert_region_run(cert_ctx *x, const study_kernel *k, const cm_method *m, int prec,
                     const cert_region *r, const cert_opts *o, cert_result *res);

/* The defect of kernel k on input n as `onbstudy eval` measures it (the
   exact defect of the rounded outputs); *nonfinite set for NaN/inf. */
double cert_probe(cert_ctx *x, const study_kernel *k, int prec, const double n[3], int *nonfinite);

#endif
