/*
 * test_coverage.c - every input a region claims lies in some leaf of that
 * region's branch and bound (certify's soundness in double, where the
 * edges of cells and sectors are not doubles).
 *
 * Inputs are made as the rounding to double of a known real unit vector
 * u = (sqrt(1 - z^2) cos phi, sqrt(1 - z^2) sin phi, z), z and phi exact
 * (MPFR, 256 bits):
 *   - next to both poles: u.z in the rounding cell of n.z = -+1, -+(1 -
 *     k 2^-53) for k = 1..6 (odd and even mantissas), at its middle and
 *     within 1e-4 of a cell's width from either edge, at several azimuths
 *     (phi = 0 gives n.y = 0, as in (0x1.6a09e667f3bccp-27, 0, 1));
 *   - at every sector edge of the band n.z in [-0.3, 0]: phi = k 45 degrees
 *     plus 0, +-1e-16 and +-4e-16 rad;
 *   - the input (0x1.595d2b0e703afp-1, -0x1.595d2b0e703b4p-1,
 *     -0x1.3330c465b584p-2) with u = n/|n|, which atan2 put in the sector
 *     [315, 360) while the box of that sector missed it.
 *   - the tolerance domain (--tolerance 1e-3) beyond the poles: n = the
 *     rounding of s u for u next to +-z and s = 1 + 0.999 T, 1 + T / 2,
 *     1 + T / 8, so that |n.z| > 1, which no band held before the bands
 *     at the poles were opened beyond them; u = n/|n| (MPFR).
 * Every input must be claimed by some region.  For each input and each
 * region that claims it (cert_in_region), the region is run
 * (cert_region_run, budget 150) and FAIL unless some leaf holds u exactly:
 * u.z in [z_lo, z_hi] (in zpoint + [dz_lo, dz_hi] when n.z is given, with
 * n.z = zpoint) and phi in [phi_lo, phi_hi] modulo 2 pi, compared in MPFR,
 * with n.z in the leaf's band [nz_lo, nz_hi] (which branch decisions use).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <mpfr.h>
#include "check.h"
#include "methods/kernels.h"
#include "certify/models.h"
#include "certify/regions.h"
#include "certify/search.h"

#define PREC 256
#define MAXLEAF 4096

typedef struct {
	mvf_box b[MAXLEAF];
	int n, over;
} leaves;

static void keep_leaf(void *arg, const mvf_box *b, double bound)
{
	leaves *l = arg;
	(void)bound;
	if (l->n < MAXLEAF)
		l->b[l->n++] = *b;
	else
		l->over = 1;
}

/* phi (radians, exact in p) within [lo, hi] modulo 2 pi. */
static int phi_within(mpfr_srcptr p, double lo, double hi)
{
	mpfr_t t, tau;
	int k, in = 0;
	mpfr_inits2(PREC, t, tau, (mpfr_ptr)0);
	mpfr_const_pi(tau, MPFR_RNDN);
	mpfr_mul_2ui(tau, tau, 1, MPFR_RNDN);
	for (k = -1; k <= 1 && !in; k++) {
		mpfr_mul_si(t, tau, k, MPFR_RNDN);
		mpfr_add(t, t, p, MPFR_RNDN);
		in = mpfr_cmp_d(t, lo) >= 0 && mpfr_cmp_d(t, hi) <= 0;
	}
	mpfr_clears(t, tau, (mpfr_ptr)0);
	return in;
}

/* Some leaf holds the real unit vector (z, phi) whose rounding is n. */
static int in_some_leaf(const leaves *l, mpfr_srcptr z, mpfr_srcptr phi, const double n[3])
{
	mpfr_t d;
	int i, in = 0;
	mpfr_init2(d, PREC);
	for (i = 0; i < l->n && !in; i++) {
		const mvf_box *b = &l->b[i];
		if (!(n[2] >= b->nz_lo && n[2] <= b->nz_hi))
			continue;
		if (b->has_zpoint) {
			if (b->zpoint != n[2])
				continue;
			mpfr_sub_d(d, z, b->zpoint, MPFR_RNDN);   /* exact */
			if (mpfr_cmp_d(d, b->dz_lo) < 0 || mpfr_cmp_d(d, b->dz_hi) > 0)
				continue;
		} else if (mpfr_cmp_d(z, b->z_lo) < 0 || mpfr_cmp_d(z, b->z_hi) > 0) {
			continue;
		}
		in = phi_within(phi, b->phi_lo, b->phi_hi);
	}
	mpfr_clear(d);
	return in;
}

typedef struct {
	cert_ctx *x;
	const study_kernel *k;
	const cm_method *m;
	cert_region reg[1024];   /* regions_band writes the default regions first */
	leaves *lv[1024];
	int nreg;
	double tol;   /* the domain's tolerance (< 0: roundings of unit vectors) */
	long inputs, claims, missed;
} env;

/* Check input n, the rounding of (z, phi), against every region of e. */
static void check_input(env *e, mpfr_srcptr z, mpfr_srcptr phi, const double n[3])
{
	int i, claimed = 0;
	if (!cert_in_domain(n, PREC_DOUBLE, e->tol)) {
		CHECK(0, "(%a, %a, %a): not in the domain", n[0], n[1], n[2]);
		return;
	}
	e->inputs++;
	for (i = 0; i < e->nreg; i++) {
		if (!cert_in_region(&e->reg[i], n))
			continue;
		e->claims++;
		claimed = 1;
		if (!e->lv[i]) {
			cert_opts o = { 150, 50, 1.25, -1.0, 31, keep_leaf, NULL, NULL, 0, NULL };
			o.tolerance = e->tol;
			cert_result res;
			e->lv[i] = calloc(1, sizeof *e->lv[i]);
			if (!e->lv[i])
				abort();
			o.leaf_arg = e->lv[i];
			cert_region_run(e->x, e->k, e->m, PREC_DOUBLE, &e->reg[i], &o, &res);
			CHECK(!e->lv[i]->over && e->lv[i]->n > 0, "%s: %d leaves", e->k->name, e->lv[i]->n);
		}
		if (!in_some_leaf(e->lv[i], z, phi, n)) {
			e->missed++;
			CHECK(0, "%s: (%a, %a, %a) claimed by n.z [%.17g, %.17g] x [%g, %g) lies in none of its %d leaves",
			      e->k->name, n[0], n[1], n[2], e->reg[i].nz_lo, e->reg[i].nz_hi, e->reg[i].phi_lo,
			      e->reg[i].phi_hi, e->lv[i]->n);
		}
	}
	CHECK(claimed, "(%a, %a, %a): claimed by no region", n[0], n[1], n[2]);
}

/* The rounding to double of the unit vector (z, phi). */
static void round_u(mpfr_srcptr z, mpfr_srcptr phi, double n[3])
{
	mpfr_t r, t;
	mpfr_inits2(PREC, r, t, (mpfr_ptr)0);
	mpfr_sqr(r, z, MPFR_RNDN);
	mpfr_ui_sub(r, 1, r, MPFR_RNDN);
	mpfr_sqrt(r, r, MPFR_RNDN);
	mpfr_cos(t, phi, MPFR_RNDN);
	mpfr_mul(t, t, r, MPFR_RNDN);
	n[0] = mpfr_get_d(t, MPFR_RNDN);
	mpfr_sin(t, phi, MPFR_RNDN);
	mpfr_mul(t, t, r, MPFR_RNDN);
	n[1] = mpfr_get_d(t, MPFR_RNDN);
	n[2] = mpfr_get_d(z, MPFR_RNDN);
	mpfr_clears(r, t, (mpfr_ptr)0);
}

static void env_regions(env *e, double lo, double hi)
{
	int i;
	for (i = 0; i < e->nreg; i++)
		free(e->lv[i]);
	memset(e->lv, 0, sizeof e->lv);
	e->nreg = (int)regions_band(PREC_DOUBLE, 8, lo, hi, e->reg, 1024);
}

/* Next to the pole sg (+1 or -1): n.z = sg (1 - k 2^-53), k = 0..6. */
static void pole_inputs(env *e, int sg)
{
	static const double frac[] = { -0.4999, -0.25, 0.0, 0.25, 0.4999 };
	static const double phis[] = { 0.0, 0.3, 2.0, 3.9, 5.5 };
	mpfr_t z, phi, g;
	int k, f, p;
	mpfr_inits2(PREC, z, phi, g, (mpfr_ptr)0);
	env_regions(e, sg > 0 ? 1.0 - 0x1p-49 : -1.0, sg > 0 ? 1.0 : -1.0 + 0x1p-49);
	for (k = 0; k <= 6; k++)
		for (f = 0; f < 5; f++)
			for (p = 0; p < 5; p++) {
				double zc = sg * (1.0 - k * 0x1p-53), n[3];
				/* the gap towards 0 is 2^-53; away from 0 (k > 0) the same */
				mpfr_set_d(g, 0x1p-53 * frac[f], MPFR_RNDN);
				if (k == 0 && frac[f] > 0.0)
					continue;   /* beyond the pole */
				mpfr_set_d(z, zc, MPFR_RNDN);
				if (sg > 0)
					mpfr_add(z, z, g, MPFR_RNDN);
				else
					mpfr_sub(z, z, g, MPFR_RNDN);
				mpfr_set_d(phi, phis[p], MPFR_RNDN);
				round_u(z, phi, n);
				CHECK(n[2] == zc, "pole input: n.z %a, want %a", n[2], zc);
				check_input(e, z, phi, n);
			}
	mpfr_clears(z, phi, g, (mpfr_ptr)0);
}

/* At every sector edge of the band [-0.3, 0], and the input atan2 put
   in the wrong box. */
static void sector_inputs(env *e)
{
	static const double zs[] = { -0.2999, -0.15, -0.0001 };
	static const double dphi[] = { 0.0, 1e-16, -1e-16, 4e-16, -4e-16 };
	const double b[3] = { 0x1.595d2b0e703afp-1, -0x1.595d2b0e703b4p-1, -0x1.3330c465b584p-2 };
	mpfr_t z, phi, t;
	int s, i, j;
	double n[3];
	mpfr_inits2(PREC, z, phi, t, (mpfr_ptr)0);
	env_regions(e, -0.3, 0.0);
	for (s = 0; s < 8; s++)
		for (i = 0; i < 3; i++)
			for (j = 0; j < 5; j++) {
				mpfr_set_d(z, zs[i], MPFR_RNDN);
				mpfr_const_pi(phi, MPFR_RNDN);
				mpfr_mul_ui(phi, phi, (unsigned long)s, MPFR_RNDN);
				mpfr_div_ui(phi, phi, 4, MPFR_RNDN);
				mpfr_add_d(phi, phi, dphi[j], MPFR_RNDN);
				round_u(z, phi, n);
				check_input(e, z, phi, n);
			}
	/* u = b/|b|: z = b.z/|b|, phi = atan2(b.y, b.x) */
	mpfr_set_d(t, b[0], MPFR_RNDN);
	mpfr_sqr(t, t, MPFR_RNDN);
	mpfr_set_d(z, b[1], MPFR_RNDN);
	mpfr_fma(t, z, z, t, MPFR_RNDN);
	mpfr_set_d(z, b[2], MPFR_RNDN);
	mpfr_fma(t, z, z, t, MPFR_RNDN);
	mpfr_sqrt(t, t, MPFR_RNDN);
	mpfr_div(z, z, t, MPFR_RNDN);
	mpfr_set_d(phi, b[1], MPFR_RNDN);
	mpfr_set_d(t, b[0], MPFR_RNDN);
	mpfr_atan2(phi, phi, t, MPFR_RNDN);
	round_u(z, phi, n);
	CHECK(memcmp(n, b, sizeof n) == 0, "b/|b| rounds to (%a, %a, %a), not b", n[0], n[1], n[2]);
	check_input(e, z, phi, n);
	mpfr_clears(z, phi, t, (mpfr_ptr)0);
}

/* u = n/|n| of a double vector n, as (z, phi), exact to PREC bits. */
static void unit_of(const double n[3], mpfr_t z, mpfr_t phi)
{
	mpfr_t t, c;
	int i;
	mpfr_inits2(PREC, t, c, (mpfr_ptr)0);
	mpfr_set_zero(t, 1);
	for (i = 0; i < 3; i++) {
		mpfr_set_d(c, n[i], MPFR_RNDN);
		mpfr_fma(t, c, c, t, MPFR_RNDN);
	}
	mpfr_sqrt(t, t, MPFR_RNDN);
	mpfr_set_d(z, n[2], MPFR_RNDN);
	mpfr_div(z, z, t, MPFR_RNDN);
	mpfr_set_d(t, n[1], MPFR_RNDN);
	mpfr_set_d(c, n[0], MPFR_RNDN);
	mpfr_atan2(phi, t, c, MPFR_RNDN);
	if (n[0] == 0.0 && n[1] == 0.0)   /* a pole: every azimuth is u, take 0 */
		mpfr_set_zero(phi, 1);
	mpfr_clears(t, c, (mpfr_ptr)0);
}

/* The tolerance domain beyond the pole sg: n = RN(s u), |n.z| > 1. */
static void tolerance_inputs(env *e, int sg)
{
	static const double zs[] = { 1.0, 1.0 - 1e-12, 1.0 - 1e-7, 1.0 - 1e-5 };
	static const double ss[] = { 0.999, 0.5, 0.125 };
	static const double phis[] = { 0.0, 1.0, 2.5, 4.0, 5.9 };
	const double T = 1e-3;
	mpfr_t z, phi;
	int i, j, p;
	mpfr_inits2(PREC, z, phi, (mpfr_ptr)0);
	e->tol = T;
	env_regions(e, sg > 0 ? 1.0 - 1e-16 : -1.0, sg > 0 ? 1.0 : -1.0 + 1e-16);
	for (i = 0; i < 4; i++)
		for (j = 0; j < 3; j++)
			for (p = 0; p < 5; p++) {
				double r = sqrt((1.0 - zs[i]) * (1.0 + zs[i])), s = 1.0 + ss[j] * T, n[3];
				n[0] = s * r * cos(phis[p]);
				n[1] = s * r * sin(phis[p]);
				n[2] = sg * s * zs[i];
				CHECK(fabs(n[2]) > 1.0, "tolerance input: n.z %a", n[2]);
				unit_of(n, z, phi);
				check_input(e, z, phi, n);
			}
	e->tol = -1.0;
	mpfr_clears(z, phi, (mpfr_ptr)0);
}

int main(void)
{
	static const char *names[] = { "hughes_moeller", "frisvad", "rtow" };
	static study_kernel ks[STUDY_MAX_KERNELS];
	static env e;
	int nk = kernels_select(NULL, 0, ks, STUDY_MAX_KERNELS), i, j;
	e.x = cert_ctx_new();
	CHECK(nk > 0 && e.x != NULL, "setup");
	if (nk <= 0 || !e.x)
		return check_finish("test_coverage");
	for (j = 0; j < 3; j++) {
		for (i = 0; i < nk && strcmp(ks[i].name, names[j]) != 0; i++)
			;
		if (i == nk || !(e.m = cm_find(names[j]))) {
			CHECK(0, "%s: no kernel or model", names[j]);
			continue;
		}
		e.k = &ks[i];
		e.inputs = e.claims = e.missed = 0;
		e.tol = -1.0;
		pole_inputs(&e, 1);
		pole_inputs(&e, -1);
		sector_inputs(&e);
		tolerance_inputs(&e, 1);
		tolerance_inputs(&e, -1);
		env_regions(&e, 0.0, 0.0);
		printf("%-16s %ld double inputs (%d beyond +-1 with a tolerance), %ld region claims, %ld outside every leaf\n", names[j], e.inputs, 2 * 60,
		       e.claims, e.missed);
	}
	cert_ctx_free(e.x);
	return check_finish("test_coverage");
}
