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
	double nz_lo, nz_hi; /* the region's band: every input n has n.z in it,
	                        which branch decisions on n.z may use         */
	int prec;           /* PREC_FLOAT or PREC_DOUBLE                           */
	double tolerance;   /* < 0: roundings of unit vectors; else | |n| - 1 | <= T */
	/* 1: n.z is the format value zpoint itself (the default domain only):
	   [z_lo, z_hi] then holds the u.z that round to it, and n is not unit
	   at e = 0, so every quantity takes its centre Q(U, 0). */
	int has_zpoint;
	double zpoint;
	/* has_zpoint: the u.z of the box are exactly zpoint + [dz_lo, dz_hi].
	   The ends of a rounding cell in double are midpoints between doubles,
	   which are no doubles: z_lo and z_hi are then only the nearest doubles
	   to them (for sampling), and the bound reads dz_lo, dz_hi. */
	double dz_lo, dz_hi;
} mvf_box;

/* Runs: the values and gradients over the box (MVF_FULL), the values with
   every error term 0 (MVF_AT_ZERO: the centre Q(U, 0)), the values over the
   box without gradients (MVF_VALUES: the direct interval where a gradient
   cannot be enclosed); and for the centred form of Q(U, 0) = Q(c, 0) +
   sum_i (u_i - c_i) dQ/du_i(U, 0), c the box's midpoint in (x, y, z): the
   values at c (MVF_AT_MID) and the gradients in u over the box
   (MVF_CENTRED), both with every error term 0. */
enum { MVF_FULL = 0, MVF_AT_ZERO, MVF_VALUES, MVF_AT_MID, MVF_CENTRED };
void mvf_begin(mvf *m, const mvf_box *b, int mode, cv in[3]);
void mvf_quantities(mvf *m, const cv n[3], const cv out[6], cv q[5]);
void mvf_bounds(mvf *m, cv q, double *lo, double *hi, double *lin);
/* An enclosure of |b|^2 - 1 for b1 (which 0) or b2 (1) from how the run
   normalized it, whatever the box (mvf_quantities; 0: none). */
int  mvf_len_direct(const mvf *m, int which, double *lo, double *hi);
/* After mvf_quantities: output `which` (0: b1, 1: b2) is q K (1 + d) with
   q.n = 0 exactly for the actual values and |d| <= *u (plus |eta| <= *eta
   per component): bound.c's orthogonality rule (returns 0 otherwise). */
int  mvf_orth_direct(const mvf *m, int which, double *u, double *eta);
/* out_i = q_i K (1 + d_i) + eta_i for one K, each q_i the value q[i]
   itself, |d_i| <= *u, |eta_i| <= *eta (the length tags): 1, else 0. */
int  mvf_scaled_of(const mvf *m, const cv out[3], const cv q[3], double *u, double *eta);
/* sum_k r_k max|dQ/de_k| over the arithmetic's error terms alone (not the
   input's own rounding), and whether the full sum mvf_bounds gives is
   valid (0 when a normalization of a vector whose length can reach 0 over
   the box left the input terms' gradients unbounded). */
double mvf_lin_arith(mvf *m, cv q);
/* The same over the error terms from number `from` on (cm_formula_zero_after). */
double mvf_lin_from(mvf *m, cv q, int from);
int  mvf_input_grad_ok(const mvf *m);
/* An enclosure of |n|^2 - 1 over the box's domain: n = u + w, |u| = 1. */
void mvf_norm_n(mvf *m, double *lo, double *hi);
int  mvf_ratio_within_2(mvf *m, mpfi_srcptr x, mpfi_srcptr y);

#endif
