/*
 * probe.c - the certify context of a thread, one input measured as
 * `onbstudy eval` measures it, and an input completed to unit length
 * (probe.h).
 */
#include <math.h>
#include <stdlib.h>
#include <mpfr.h>
#include "probe.h"
#include "common/prec.h"

cert_ctx *cert_ctx_new(void)
{
	cert_ctx *x = calloc(1, sizeof *x);
	if (!x)
		return NULL;
	mpfr_init2(x->t, 320);
	mpfr_init2(x->s, 320);
	x->b = bound_new();
	x->rc = ref_new(127);
	x->emu = cm_new(CM_EXEC);
	if (!x->b || !x->rc || !x->emu) {
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
	cm_free(x->emu);
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

double cert_complete(cert_ctx *x, int prec, double a, double b, int *sure)
{
	const int p = prec == PREC_FLOAT ? 24 : 53;
	mpfr_set_d(x->t, a, MPFR_RNDN);
	mpfr_sqr(x->t, x->t, MPFR_RNDN);
	mpfr_set_d(x->s, b, MPFR_RNDN);
	mpfr_fma(x->t, x->s, x->s, x->t, MPFR_RNDN);
	mpfr_ui_sub(x->t, 1, x->t, MPFR_RNDN);
	*sure = 0;
	if (mpfr_sgn(x->t) < 0)
		return NAN;
	mpfr_sqrt(x->t, x->t, MPFR_RNDN);
	*sure = mpfr_cmp_d(x->t, 0.5) > 0 && mpfr_can_round(x->t, 316, MPFR_RNDN, MPFR_RNDZ, p + 1);
	return p == 24 ? (double)mpfr_get_flt(x->t, MPFR_RNDN) : mpfr_get_d(x->t, MPFR_RNDN);
}

int cert_biggest(const double n[3])
{
	int i, b = 0;
	for (i = 1; i < 3; i++)
		if (fabs(n[i]) > fabs(n[b]))
			b = i;
	return b;
}
