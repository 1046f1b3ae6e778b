/*
 * probe.h - one input measured: the certify context of a thread (cert_ctx),
 * the defect of a kernel on one input as `onbstudy eval` measures it, and
 * an input completed to unit length (probe.c).  Below the found side (found.c), the branch and bound
 * (search.c) and the enumeration of a box (enumerate.c).
 */
#ifndef ONB_CERTIFY_PROBE_H
#define ONB_CERTIFY_PROBE_H

#include <mpfr.h>
#include "methods/kernels.h"
#include "bound.h"
#include "reference/reference.h"

typedef struct cert_ctx cert_ctx;
cert_ctx *cert_ctx_new(void);   /* one per thread; NULL on failure */
void cert_ctx_free(cert_ctx *x);

struct cert_ctx {
	bound_ctx *b;
	ref_ctx *rc;
	cm *emu;       /* CM_EXEC: --arith's emulations (emulate.h) */
	mpfr_t t, s;   /* scratch of the completion of an input to unit length */
};

/* The defect of kernel k on input n as `onbstudy eval` measures it (the
   exact defect of the rounded outputs); *nonfinite set for NaN/inf. */
double cert_probe(cert_ctx *x, const study_kernel *k, int prec, const double n[3], int *nonfinite);

/* |c| = sqrt(1 - a^2 - b^2) rounded to nearest in the format prec (a, b in
   it), NaN when a^2 + b^2 > 1; *sure = 1 when that rounding is certain (the
   320-bit value is within 2^-316 relative of the exact one, and
   mpfr_can_round says that decides it): then (a, b, +-c) is the rounding
   of the unit vector (a, b, +-sqrt(1 - a^2 - b^2)), a domain member. */
double cert_complete(cert_ctx *x, int prec, double a, double b, int *sure);

/* The index of n's component of largest magnitude (the first of equals). */
int cert_biggest(const double n[3]);

#endif
