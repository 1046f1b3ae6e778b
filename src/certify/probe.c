/*
 * probe.c - the certify context of a thread, and one input measured as
 * `onbstudy eval` measures it (probe.h).
 */
#include <math.h>
#include <stdlib.h>
#include <mpfr.h>
#include "probe.h"

cert_ctx *cert_ctx_new(void)
{
	cert_ctx *x = calloc(1, sizeof *x);
	if (!x)
		return NULL;
	mpfr_init2(x->t, 320);
	mpfr_init2(x->s, 320);
	x->b = bound_new();
	x->rc = ref_new(127);
	if (!x->b || !x->rc) {
		cert_ctx_free(x);
		return NULL;
	}
	return x;
}

void cert_ctx_free(cert_ctx *x)
{
	if (!x)
		return;
	bound_free(x->b);
	mpfr_clear(x->t);
	mpfr_clear(x->s);
	if (x->rc)
		ref_free(x->rc);
	free(x);
}

double cert_probe(cert_ctx *x, const study_kernel *k, int prec, const double n[3], int *nonfinite)
{
	static const double loc[3] = { 0.0, 0.0, 1.0 };
	sample_metrics m;
	ref_eval(x->rc, k, prec, n, loc, 0, &m);
	*nonfinite = m.nonfinite;
	return m.nonfinite ? INFINITY : m.defect;
}
