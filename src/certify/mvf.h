/*
 * mvf.h - the mean-value-form back end, as the branch and bound uses it.
 */
#ifndef ONB_CERTIFY_MVF_H
#define ONB_CERTIFY_MVF_H

#include <mpfi.h>
#include "model_int.h"

/* A box of real unit vectors: z = u.z in [z_lo, z_hi], azimuth in
   [phi_lo, phi_hi] radians; the input format and its domain. */
typedef struct {
	double z_lo, z_hi, phi_lo, phi_hi;
	int prec;           /* CM_F32 or CM_F64                           */
	double tolerance;   /* < 0: roundings of unit vectors; else | |n| - 1 | <= T */
} mvf_box;

void mvf_begin(mvf *m, const mvf_box *b, int zero_e, cv in[3]);
void mvf_quantities(mvf *m, const cv n[3], const cv out[6], cv q[5]);
void mvf_bounds(mvf *m, cv q, double *direct, double *lin);
int  mvf_ratio_within_2(mvf *m, mpfi_srcptr x, mpfi_srcptr y);

#endif
