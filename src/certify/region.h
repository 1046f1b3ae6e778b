/*
 * region.h - a region of the sphere for `onbstudy certify`.
 *
 * A region is a band of n.z and an azimuth sector, both closed-open except
 * at the top: nz_lo <= n.z <= nz_hi and phi_lo <= phi < phi_hi, with
 * phi = atan2(n.y, n.x) in degrees mapped to [0, 360) (phi of n.x = n.y = 0
 * is 0).  A band that reaches a pole (nz_lo = -1 or nz_hi = 1) also holds
 * every n.z beyond it: the tolerance domain has inputs with |n.z| up to
 * 1 + T, and they belong to the band of their pole.  Membership is decided on the P-format input n itself, the one
 * `onbstudy eval` replays.
 *
 * The domain for precision P (cert_domain):
 *   tolerance < 0 (the default): every P-format n that is the rounding to
 *     nearest of some real unit vector u (each n_i the nearest P-format
 *     value to u_i, subnormals included);
 *   tolerance T >= 0: every P-format n with | |n| - 1 | <= T.
 */
#ifndef ONB_CERTIFY_REGION_H
#define ONB_CERTIFY_REGION_H

typedef struct {
	double nz_lo, nz_hi;   /* band of n.z, -1 <= nz_lo <= nz_hi <= 1 */
	double phi_lo, phi_hi; /* sector in degrees, 0 <= phi_lo < phi_hi <= 360 */
} cert_region;

/* phi of (x, y) in degrees, in [0, 360); 0 when x = y = 0. */
double cert_phi_deg(double x, double y);

/* 1 when n (values exact in the format) lies in region r. */
int cert_in_region(const cert_region *r, const double n[3]);

/* 1 when n is in the domain (see above) for prec (PREC_FLOAT or
   PREC_DOUBLE of kernels.h) and tolerance; decided exactly. */
int cert_in_domain(const double n[3], int prec, double tolerance);

#endif
