/*
 * regions.c - bands and sectors of the sphere, and their boxes.
 */
#include <math.h>
#include <string.h>
#include <mpfr.h>
#include "regions.h"
#include "inputs/inputs.h"

#define DEG (3.14159265358979323846 / 180.0)
/* The error of cert_phi_deg's azimuth, in radians, with a margin of 6
   (region_box). */
#define PHI_SLACK 1e-14

double cert_phi_deg(double x, double y)
{
	double p;
	if (x == 0.0 && y == 0.0)
		return 0.0;
	p = atan2(y, x) / DEG;
	if (p < 0.0)
		p += 360.0;
	return p >= 360.0 ? 0.0 : p;
}

int cert_in_region(const cert_region *r, const double n[3])
{
	double p = cert_phi_deg(n[0], n[1]);
	/* the bands at the poles are open beyond them: with a tolerance, n.z
	   can exceed 1 in magnitude (|n| up to 1 + T), and such an n belongs
	   to the band that holds its pole */
	return (n[2] >= r->nz_lo || r->nz_lo <= -1.0) && (n[2] <= r->nz_hi || r->nz_hi >= 1.0) &&
	       p >= r->phi_lo && (p < r->phi_hi || r->phi_hi >= 360.0);
}

/* The band edges: 1 + n.z = 10^-k/2 near -1 down to 10^-lo_dec, the same
   in 1 - n.z near +1 (whole decades), linear steps of 0.3 in between. */
static size_t band_edges(int prec, double *e, size_t cap)
{
	/* binary16's values next to -1 are 2^-11 = 4.9e-4 apart: 10^-4 is the pole */
	const int lo_dec = prec == PREC_FLOAT ? 7 : prec == PREC_HALF ? 4 : 16;
	size_t n = 0;
	int k;
	e[n++] = -1.0;
	for (k = 2 * lo_dec; k >= 2 && n < cap; k--)
		e[n++] = -1.0 + pow(10.0, -0.5 * k);
	for (k = -2; k <= 3 && n < cap; k++)
		e[n++] = 0.3 * k;
	for (k = 2; k <= lo_dec && n < cap; k++)
		e[n++] = 1.0 - pow(10.0, -(double)k);
	if (n < cap)
		e[n++] = 1.0;
	return n;
}

size_t regions_default(int prec, int nsec, cert_region *out, size_t cap)
{
	double e[128];
	size_t ne = band_edges(prec, e, 128), i, n = 0;
	int s;
	for (i = 0; i + 1 < ne; i++)
		for (s = 0; s < nsec && n < cap; s++) {
			out[n].nz_lo = e[i];
			out[n].nz_hi = e[i + 1];
			out[n].phi_lo = 360.0 * s / nsec;
			out[n].phi_hi = 360.0 * (s + 1) / nsec;
			n++;
		}
	return n;
}

size_t regions_band(int prec, int nsec, double lo, double hi, cert_region *out, size_t cap)
{
	size_t n = regions_default(prec, nsec, out, cap), i, m = 0;
	for (i = 0; i < n; i++) {
		cert_region r = out[i];
		if (r.nz_hi <= lo || r.nz_lo >= hi)
			if (!(lo == hi && r.nz_lo <= lo && lo <= r.nz_hi))
				continue;
		r.nz_lo = fmax(r.nz_lo, lo);
		r.nz_hi = fmin(r.nz_hi, hi);
		out[m++] = r;
		if (lo == hi && m == (size_t)nsec)
			break;
	}
	return m;
}

/* Binary16's grid is coarse enough to matter: the inputs' n.z are the
   binary16 values z1..z2 of the band, so u.z lies within half a gap of
   them (the rounding cells of z1 and z2), not within the band widened by
   u; at the pole, u.z >= -1 + 2^-12 for n.z >= -1 + 2^-11, where the
   widened band reaches -1 and Frisvad's 1/(1 + z) has no bound.  A band
   without a binary16 value is empty (half_band_empty). */
static void half_grid(const cert_region *r, double *z1, double *z2)
{
	*z1 = prec_half_round(r->nz_lo);
	if (*z1 < r->nz_lo)
		*z1 = fmt_step(*z1, 1, PREC_HALF);
	*z2 = prec_half_round(r->nz_hi);
	if (*z2 > r->nz_hi)
		*z2 = fmt_step(*z2, -1, PREC_HALF);
	*z1 = fmax(*z1, -1.0);
	*z2 = fmin(*z2, 1.0);
}

int half_band_empty(const cert_region *r)
{
	double z1, z2;
	half_grid(r, &z1, &z2);
	return z1 > z2;
}

static void half_band(const cert_region *r, mvf_box *b)
{
	double z1, z2;
	half_grid(r, &z1, &z2);
	if (z1 > z2)
		return;
	b->nz_lo = fmax(b->nz_lo, z1);
	b->nz_hi = fmin(b->nz_hi, z2);
	b->z_lo = fmax(b->z_lo, z1 - 0.5 * (z1 - fmt_step(z1, -1, PREC_HALF)));
	b->z_hi = fmin(b->z_hi, z2 + 0.5 * (fmt_step(z2, 1, PREC_HALF) - z2));
}

void region_box(const cert_region *r, int prec, double tolerance, mvf_box *b)
{
	const double u = prec_fmt(prec)->u, eta = prec_fmt(prec)->sub_step;
	/* relative widening: |u.z| <= |n.z| / (1 - T) with a tolerance */
	const double w = tolerance >= 0 ? tolerance / (1.0 - tolerance) : u;
	double zmax, rmin, dphi;
	b->prec = prec;
	b->tolerance = tolerance;
	/* a pole's band also holds the n.z beyond the pole (cert_in_region),
	   which only a tolerance admits: n.z = (1 + t) u.z, |t| <= T, lies in
	   the box's values of n.z (u.z in [z_lo, z_hi] below) whatever the
	   band says, so the band is left open there */
	b->nz_lo = r->nz_lo <= -1.0 && tolerance >= 0 ? -INFINITY : r->nz_lo;
	b->nz_hi = r->nz_hi >= 1.0 && tolerance >= 0 ? INFINITY : r->nz_hi;
	b->has_zpoint = 0;
	b->zpoint = b->dz_lo = b->dz_hi = 0.0;
	b->z_lo = fmax(-1.0, r->nz_lo - w * fabs(r->nz_lo) * 1.01 - eta);
	b->z_hi = fmin(1.0, r->nz_hi + w * fabs(r->nz_hi) * 1.01 + eta);
	if (prec == PREC_HALF && tolerance < 0)
		half_band(r, b);
	zmax = fmax(fabs(b->z_lo), fabs(b->z_hi));   /* r = sqrt(1 - z^2) is least there */
	rmin = sqrt(fmax(0.0, (1.0 - zmax) * (1.0 + zmax)));
	/* the azimuth of n differs from u's by at most 2u + 2 eta / r radians
	   (n = (1 + t) u with a tolerance: the same azimuth); and membership
	   is decided on cert_phi_deg's phi, which atan2 (within an ulp of pi),
	   the conversion to degrees and the wrap to [0, 360) (each within half
	   an ulp of 360 degrees) put within 1.7e-15 rad of n's azimuth: PHI_SLACK
	   covers that, so every input a region claims lies in its box */
	dphi = rmin > 0.0 ? 2.01 * (u + 2.0 * eta / rmin) : INFINITY;
	if (tolerance >= 0)
		dphi = 0.0;
	dphi += PHI_SLACK;
	/* binary16's 2u alone is 1e-3 rad: a sector of 8 or fewer keeps its
	   azimuths there up to 0.02 rad */
	if (!(dphi < (prec == PREC_HALF ? 0.02 : 1e-3))) {
		b->phi_lo = 0.0;
		b->phi_hi = 360.0 * DEG;
	} else {
		b->phi_lo = r->phi_lo * DEG - dphi;
		b->phi_hi = r->phi_hi * DEG + dphi;
	}
}

int region_meets_singular(const study_kernel *k, const cert_region *r)
{
	return k->m && k->fam->meets_singular(k->m, r->nz_lo, r->nz_hi, r->phi_lo, r->phi_hi);
}

/* The reals that round (to nearest) to the format value v have |u| in
   [a - down/2, a + up/2], a = |v|, down and up its gaps to the next values
   towards 0 and away from 0 (for a = 0: [0, up/2]).  Set exactly in t. */
static void rounding_end(double v, int prec, int upper, mpfr_t t)
{
	double a = fabs(v), up, down;
	if (prec == PREC_FLOAT) {
		float f = (float)a;
		up = (double)nextafterf(f, INFINITY) - a;
		down = a > 0.0 ? a - (double)nextafterf(f, 0.0f) : 0.0;
	} else {
		up = nextafter(a, INFINITY) - a;
		down = a > 0.0 ? a - nextafter(a, 0.0) : 0.0;
	}
	mpfr_set_d(t, a, MPFR_RNDN);
	if (upper)
		mpfr_add_d(t, t, up / 2, MPFR_RNDN);   /* exact at 4400 bits */
	else
		mpfr_sub_d(t, t, down / 2, MPFR_RNDN);
}

int cert_in_domain(const double n[3], int prec, double tolerance)
{
	mpfr_t s_lo, s_hi, t;
	int i, in = 1;
	mpfr_inits2(4400, s_lo, s_hi, t, (mpfr_ptr)0);
	mpfr_set_zero(s_lo, 1);
	mpfr_set_zero(s_hi, 1);
	for (i = 0; i < 3 && in; i++) {
		if (!isfinite(n[i]) || (prec == PREC_FLOAT && (double)(float)n[i] != n[i])) {
			in = 0;
			break;
		}
		if (tolerance >= 0)
			mpfr_set_d(t, fabs(n[i]), MPFR_RNDN);
		else
			rounding_end(n[i], prec, 0, t);
		mpfr_sqr(t, t, MPFR_RNDN);
		mpfr_add(s_lo, s_lo, t, MPFR_RNDN);
		if (tolerance < 0)
			rounding_end(n[i], prec, 1, t);
		else
			mpfr_set_d(t, fabs(n[i]), MPFR_RNDN);
		mpfr_sqr(t, t, MPFR_RNDN);
		mpfr_add(s_hi, s_hi, t, MPFR_RNDN);
	}
	if (in && tolerance >= 0) {   /* (1 - T)^2 <= |n|^2 <= (1 + T)^2 */
		mpfr_set_d(t, 1.0, MPFR_RNDN);
		mpfr_sub_d(t, t, tolerance, MPFR_RNDN);
		mpfr_sqr(t, t, MPFR_RNDN);
		in = mpfr_cmp(t, s_lo) <= 0;
		mpfr_set_d(t, 1.0, MPFR_RNDN);
		mpfr_add_d(t, t, tolerance, MPFR_RNDN);
		mpfr_sqr(t, t, MPFR_RNDN);
		in = in && mpfr_cmp(s_hi, t) <= 0;
	} else if (in) {              /* min |u|^2 < 1 < max |u|^2 over the open box */
		in = mpfr_cmp_ui(s_lo, 1) < 0 && mpfr_cmp_ui(s_hi, 1) > 0;
	}
	mpfr_clears(s_lo, s_hi, t, (mpfr_ptr)0);
	return in;
}
