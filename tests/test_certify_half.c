/*
 * test_certify_half.c - `certify --precision half`'s bounds against a
 * brute-force scan of binary16 inputs (src/certify/certify_half.c).
 *
 * For five methods (duff, hughes_moeller, jolt, naive, frisvad) and six
 * regions (the pole -z with its underflowing components, the values next
 * to it where Frisvad's formula divides by 1 + n.z = 2^-11, the middle and
 * the approach to +z), every binary16 input of a window of the region is
 * evaluated: every binary16 x and y of the window (x by every encoding, y
 * by every encoding in the ring the band allows at that x) and every n.z
 * that is the rounding of a unit vector whose x and y round to them (the
 * rounding cells of x and y give a range of sqrt(1 - x^2 - y^2); each
 * binary16 value whose own cell meets it).  The half kernel's defect is
 * computed here in long double, apart from the driver's, and
 *   1. no input exceeds the region's proven bound (ch_bound), and a
 *      region whose scan finds a NaN or an infinity has status non-finite
 *      and no number;
 *   2. duff, hughes_moeller and jolt are proven everywhere here, within
 *      a few u, and the bound is within 4x of the scan where it is proven;
 *   3. the mutant: the model of binary16 with 12 bits (u = 2^-12, half
 *      the rounding errors: mvf_mutate_format) gives bounds that the
 *      scan's inputs exceed in some region;
 *   4. the status words, overflow among them: an input of 2^15 per
 *      component is out of the domain, but the model's squares of a box
 *      whose values reach 256 overflow (mvf's may_overflow) - see
 *      the direct check below on a region box scaled by the tolerance 0.
 * argv[1] = "-v": print each region's bound, scan and ratio.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "certify/certify_half.h"
#include "certify/regions.h"
#include "model/model_int.h"

static int verbose;

/* The defect of a half basis, in long double (64-bit significand: the
   products of binary16 values exact, each sum within 2^-63). */
static double defect_ld(const double n[3], const double b[6])
{
	long double s1 = 0, s2 = 0, d1 = 0, d2 = 0, d12 = 0, d;
	int i;
	for (i = 0; i < 3; i++) {
		s1 += (long double)b[i] * b[i];
		s2 += (long double)b[3 + i] * b[3 + i];
		d1 += (long double)b[i] * n[i];
		d2 += (long double)b[3 + i] * n[i];
		d12 += (long double)b[i] * b[3 + i];
	}
	d = fabsl(sqrtl(s1) - 1);
	d = fmaxl(d, fabsl(sqrtl(s2) - 1));
	d = fmaxl(d, fmaxl(fabsl(d1), fmaxl(fabsl(d2), fabsl(d12))));
	return (double)d;
}

typedef struct {
	double nz_lo, nz_hi, phi_lo, phi_hi;   /* the region */
	double x_lo, x_hi, y_lo, y_hi;         /* the window scanned (|x|, |y|) */
} test_region;

/* Half the gap around binary16 value v on either side. */
static double cell(double v, int up)
{
	const uint16_t b = prec_half_bits(fabs(v));
	return 0.5 * fabs(prec_half_value((uint16_t)(up ? b + 1 : (b ? b - 1 : 1))) - fabs(v));
}

static double scan_max(const study_kernel *k, const cert_region *r, const test_region *t, long *count, int *nonfinite)
{
	const double sz = r->nz_hi <= 0.0 ? -1.0 : 1.0;
	unsigned bx, by, bz;
	double dmax = 0.0;
	for (bx = prec_half_bits(t->x_lo); bx <= prec_half_bits(t->x_hi); bx++)
		for (by = prec_half_bits(t->y_lo); by <= prec_half_bits(t->y_hi); by++) {
			const double x = prec_half_value((uint16_t)bx), y = prec_half_value((uint16_t)by);
			const double xl = fmax(0.0, x - cell(x, 0)), xh = x + cell(x, 1);
			const double yl = fmax(0.0, y - cell(y, 0)), yh = y + cell(y, 1);
			const double wl = sqrt(fmax(0.0, 1.0 - xh * xh - yh * yh)), wh = sqrt(fmax(0.0, 1.0 - xl * xl - yl * yl));
			if (xl * xl + yl * yl > 1.0)
				break;
			for (bz = prec_half_bits(prec_half_round(wl)); bz <= prec_half_bits(prec_half_round(wh)); bz++) {
				const double z = prec_half_value((uint16_t)bz);
				const double n[3] = { x, y, sz * z };
				uint16_t hn[3], hb[6];
				double b[6], d;
				int q, fin = 1;
				if (z - cell(z, 0) > wh || z + cell(z, 1) < wl || !cert_in_region(r, n))
					continue;   /* z's cell misses the range, or n is not in the region */
				for (q = 0; q < 3; q++)
					hn[q] = prec_half_bits(n[q]);
				k->m->arrayh(hn, hb, hb + 3);
				for (q = 0; q < 6; q++) {
					b[q] = prec_half_value(hb[q]);
					fin &= isfinite(b[q]) != 0;
				}
				(*count)++;
				if (!fin) {
					*nonfinite = 1;
					dmax = INFINITY;
					continue;
				}
				d = defect_ld(n, b);
				if (d > dmax)
					dmax = d;
			}
		}
	return dmax;
}

static const test_region regs[] = {
	{ -1.0, -0.9999, 0, 90, 0x1p-8, 0x1p-7, 0.0, 0x1p-18 },            /* -z: y subnormal, x^2 underflows */
	{ -0.9997, -0.999, 0, 90, 0x1.4p-6, 0x1.8p-5, 0x1.ep-6, 0x1p-5 },  /* 1 + n.z = 2^-11, 2^-10 */
	{ -0.6, -0.3, 0, 45, 0.8, 0.9, 0.3, 0.45 },
	{ -0.3, 0.0, 45, 90, 0.6, 0.65, 0.7, 0.75 },
	{ 0.9, 0.99, 0, 90, 0.2, 0.25, 0.15, 0.2 },
	{ 0.9999, 1.0, 0, 90, 0.0, 0x1p-18, 0x1p-8, 0x1p-7 },              /* +z */
};
#define NREG (int)(sizeof regs / sizeof regs[0])
static const char *const names[] = { "duff", "hughes_moeller", "jolt", "naive", "frisvad" };
#define NM 5
#define DEPTH 4

int main(int argc, char **argv)
{
	static double found[NM][NREG];
	bound_ctx *b;
	int i, j, caught = 0;
	verbose = argc > 1 && strcmp(argv[1], "-v") == 0;
	if (!ONB_HAVE_HALF) {
		printf("test_certify_half: no _Float16 in this build: nothing to certify\n");
		return check_finish("test_certify_half");
	}
	b = bound_new();
	CHECK(b != NULL, "bound_new");
	if (!b)
		return check_finish("test_certify_half");
	for (i = 0; i < NM; i++) {
		study_kernel k;
		const cm_method *m = cm_find(names[i]);
		CHECK(m != NULL && kernels_select(names[i], 0, &k, 1) == 1, "%s: no model or kernel", names[i]);
		if (!m || kernels_select(names[i], 0, &k, 1) != 1)
			continue;
		for (j = 0; j < NREG; j++) {
			const cert_region r = { regs[j].nz_lo, regs[j].nz_hi, regs[j].phi_lo, regs[j].phi_hi };
			long count = 0;
			int nonfinite = 0;
			ch_result res;
			found[i][j] = scan_max(&k, &r, &regs[j], &count, &nonfinite);
			ch_region(b, &k, m, &r, DEPTH, 4, &res);
			if (verbose)
				printf("%-15s [%g, %g] x [%g, %g): %ld inputs, max %.4g u, bound %.4g u (%s), ratio %.3g\n",
				       names[i], r.nz_lo, r.nz_hi, r.phi_lo, r.phi_hi, count, found[i][j] * 2048,
				       res.bound * 2048, ch_status_name(res.status), res.bound / found[i][j]);
			CHECK(count > 1000, "%s region %d: only %ld inputs scanned", names[i], j, count);
			CHECK(found[i][j] <= res.bound, "%s region %d: an input's defect %a above the bound %a",
			      names[i], j, found[i][j], res.bound);
			CHECK(!nonfinite || (res.status == CH_NONFINITE && isinf(res.bound)),
			      "%s region %d: a non-finite basis, status %s", names[i], j, ch_status_name(res.status));
			if (i < 3)   /* the windows at the poles hold no worst input: 8u there */
				CHECK(res.status == CH_PROVEN && res.bound <= 8 * 0x1p-11 && (j < 2 || j > 4 || res.bound <= 4 * found[i][j]),
				      "%s region %d: not proven within 8u and 4x the scan: %s, bound %a, scan %a", names[i], j,
				      ch_status_name(res.status), res.bound, found[i][j]);
		}
	}
	/* 3. the mutant: binary16 modelled with 12 bits */
	mvf_mutate_format(PREC_HALF, 12);
	for (i = 0; i < NM; i++) {
		const cm_method *m = cm_find(names[i]);
		for (j = 0; m && j < NREG; j++) {
			const cert_region r = { regs[j].nz_lo, regs[j].nz_hi, regs[j].phi_lo, regs[j].phi_hi };
			const double v = ch_bound(b, m, &r, found[i][j], DEPTH);   /* halved until below the scan */
			if (verbose)
				printf("mutant: %-15s region %d: bound %.4g u, scan %.4g u\n", names[i], j, v * 2048, found[i][j] * 2048);
			caught += found[i][j] < INFINITY && found[i][j] > v;
		}
	}
	mvf_mutate_format(PREC_HALF, 0);
	CHECK(caught > 0, "the 12-bit model of binary16 (u = 2^-12) is not caught: no scanned input above its bounds");
	printf("mutant u = 2^-12: %d method-region pairs with a scanned input above the bound\n", caught);
	bound_free(b);
	return check_finish("test_certify_half");
}
