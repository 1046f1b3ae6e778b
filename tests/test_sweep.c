/*
 * test_sweep.c - the MPFR reference and the metrics: hand-derived exact
 * cases, deliberately broken methods caught by the expected amounts, the
 * exact accumulator, the distributions' reproducibility.
 */
#include <stdio.h>
#include <string.h>
#include <math.h>
#include <float.h>
#include "reference/reference.h"
#include "inputs/inputs.h"
#include "sweep/fx.h"
#include "sweep/state.h"

#include "check.h"

static study_kernel kernel(const char *name)
{
	study_kernel k[2];
	memset(k, 0, sizeof k);
	if (kernels_select(name, 0, k, 1) != 1)
		printf("no kernel %s\n", name);
	return k[0];
}

/* Deliberately broken variants of duff (test-only methods). */
static void duff_sign_error(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_duff(n, b1, b2);
	b2->x = -b2->x; b2->y = -b2->y; b2->z = -b2->z;   /* b2 -> -b2: wrong hand */
}
static void duff_lost_ulp(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_duff(n, b1, b2);
	b1->x = nextafter(b1->x, 2.0);                   /* one ulp off */
}
static void duff_lost_ulpf(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_dufff(n, b1, b2);
	b1->x = nextafterf(b1->x, 2.0f);
}

/* The by_nz bin as first written (sweep/state.c). */
static int clampi_log(double h, int off4, int nb)
{
	int b;
	if (!(h > 0.0))
		return 0;
	b = (int)floor((log10(h) + off4 / 4.0) * 4.0);
	return b < 0 ? 0 : b > nb - 1 ? nb - 1 : b;
}

/* fx_add_double as first written (frexp and ldexp): the bit reading in
   fx.h must add the same integer for every double. */
static void fx_add_double_frexp(fx *a, double v)
{
	int e, s;
	uint64_t m;
	if (!(v > 0.0))
		return;
	if (!(v < 0x1p80)) {
		a->saturated = 1;
		return;
	}
	m = (uint64_t)ldexp(frexp(v, &e), 53);
	s = e - 53 + FX_SHIFT;
	if (s < 0) {
		if (s <= -64)
			return;
		m >>= -s;
		s = 0;
	}
	fx_add_limbs(a, s / 64, m << (s % 64));
	if (s % 64)
		fx_add_limbs(a, s / 64 + 1, m >> (64 - s % 64));
}

/* Random mantissas at every exponent from subnormal to 2^70 (short of
   saturating the sum, which reaches the top limb), the
   edges of the resolution (2^-300, 2^-364) and long carry chains (many
   terms with all mantissa bits set on one limb boundary). */
static int fx_bits_agree(void)
{
	fx a, b;
	uint64_t x = 0x9e3779b97f4a7c15ull;
	int i, bad = 0;
	const double edge[] = { 0x1p-300, 0x1.fffffffffffffp-301, 0x1p-363, 0x1.fffffffffffffp-364, 0x1p-364,
	                        0x1p-1074, 0x1p-1022, 0x1.fffffffffffffp70, 0x1p-236, 0x1.fffffffffffffp-237 };
	memset(&a, 0, sizeof a);
	memset(&b, 0, sizeof b);
	for (i = 0; i < 400000; i++) {
		uint64_t u;
		double v;
		x ^= x << 13; x ^= x >> 7; x ^= x << 17;
		u = (x & 0xfffffffffffffull) | ((uint64_t)(i % 1094) << 52);
		if (i % 7 == 0)
			u |= 0xfffffffffffffull; /* all ones: carries */
		memcpy(&v, &u, sizeof v);
		if (i % 1000 == 0)
			v = edge[(i / 1000) % (int)(sizeof edge / sizeof edge[0])];
		fx_add_double(&a, v);
		fx_add_double_frexp(&b, v);
		bad += memcmp(&a, &b, sizeof a) != 0;
	}
	return bad == 0 && a.l[FX_LIMBS - 1] != 0 && !a.saturated;
}

/* 1. Exact cases of the reference. */
static void test_exact(ref_ctx *c)
{
	const double loc[3] = { 0.0, 0.0, 1.0 };
	sample_metrics m;
	int p;
	const study_kernel duff = kernel("duff"), naive = kernel("naive"), fris = kernel("frisvad"),
	                   hm = kernel("hughes_moeller"), rtow = kernel("rtow");
	const double up[3] = { 0, 0, 1 }, down[3] = { 0, 0, -1 }, ey[3] = { 0, 1, 0 };
	const double half[3] = { 0.5, 0.5, 0.5 };
	for (p = 0; p < 2; p++) {
		ref_eval(c, &duff, p, up, loc, 0, &m);
		CHECK(m.ref[0] == 1 && m.ref[1] == 0 && m.ref[2] == 0 && m.ref[3] == 0 && m.ref[4] == 1 && m.ref[5] == 0,
		      "duff at +z: exact (1,0,0),(0,1,0), got (%a,%a,%a),(%a,%a,%a)", m.ref[0], m.ref[1], m.ref[2], m.ref[3], m.ref[4], m.ref[5]);
		CHECK(m.defect == 0.0 && m.ulp_max == 0.0 && m.abs_eps_max == 0.0 && !m.wrong_hand, "duff at +z: no error");
		ref_eval(c, &duff, p, down, loc, 0, &m);
		CHECK(m.branch == 1 && m.ref[0] == 1 && m.ref[4] == -1 && m.defect == 0.0,
		      "duff at -z: lower branch, b1 = (1,0,0), b2 = (0,-1,0)");
		ref_eval(c, &naive, p, ey, loc, 0, &m);
		CHECK(m.ref[0] == 1 && m.ref[5] == -1 && m.defect == 0.0, "naive at +y: b1 = x, b2 = n x b1 = -z");
		ref_eval(c, &hm, p, up, loc, 0, &m);
		CHECK(m.branch == 0 && m.ref[4] == -1 && m.ref[0] == -1, "hughes_moeller at +z: b2 = (0,-1,0), b1 = b2 x n = (-1,0,0), got b1.x %a", m.ref[0]);
	}
	/* Frisvad's formula on (1/2, 1/2, 1/2) (not unit, exact in binary):
	   a = 2/3, b1 = (1 - 1/6, -1/6, -1/2), b2 = (-1/6, 5/6, -1/2). */
	ref_eval(c, &fris, PREC_DOUBLE, half, loc, 0, &m);
	CHECK(m.ref[0] == 5.0 / 6.0 && m.ref[1] == -1.0 / 6.0 && m.ref[2] == -0.5 && m.ref[3] == -1.0 / 6.0 &&
	      m.ref[4] == 5.0 / 6.0 && m.ref[5] == -0.5, "frisvad on (1/2,1/2,1/2): exact sixths, got %a %a", m.ref[0], m.ref[1]);
	/* |n| - 1 of that input: sqrt(3)/2 - 1 */
	CHECK(fabs(m.in_norm - (sqrt(3.0) / 2.0 - 1.0)) < 1e-16, "|n|-1 of (1/2,1/2,1/2): %.17g", m.in_norm);
	/* its defects: b1.n = (5/6 - 1/6 - 1/2)/2 = 1/12, up to the outputs' rounding */
	CHECK(fabs(m.d[DEF_D1N] - 1.0 / 12.0) < 1e-16, "frisvad (1/2,1/2,1/2): b1.n = 1/12, got %.17g", m.d[DEF_D1N]);
	/* rtow normalizes its input: the exact frame of 2z is the frame of z */
	{
		const double twoz[3] = { 0, 0, 2 };
		ref_eval(c, &rtow, PREC_DOUBLE, twoz, loc, 0, &m);
		CHECK(m.ulp_max == 0.0 && m.abs_eps_max == 0.0, "rtow on (0,0,2): exact");
	}
}

/* 2. Broken methods are flagged by the expected amounts. */
static void test_broken(ref_ctx *c)
{
	const double loc[3] = { 0.0, 0.0, 1.0 };
	sample_metrics m;
	int i;
	study_kernel bad = kernel("duff");
	const double up[3] = { 0, 0, 1 };
	bad.basis = duff_sign_error;
	ref_eval(c, &bad, PREC_DOUBLE, up, loc, 0, &m);
	CHECK(m.wrong_hand == 1 && m.det == -1.0, "sign error: wrong hand, det -1 (got %d, %g)", m.wrong_hand, m.det);
	CHECK(m.defect == 0.0, "sign error: still orthonormal (defect %g)", m.defect);
	CHECK(m.abs_eps_max == 2.0 / DBL_EPSILON, "sign error: forward error 2 = %g eps, got %g", 2.0 / DBL_EPSILON, m.abs_eps_max);
	bad.basis = duff_lost_ulp;
	ref_eval(c, &bad, PREC_DOUBLE, up, loc, 0, &m);
	CHECK(m.ulp_max == 1.0, "lost ulp: exactly 1 ulp forward, got %.17g", m.ulp_max);
	CHECK(m.bits_max == 1.0, "lost ulp: 1 bit of error (Herbie), got %.17g", m.bits_max);
	CHECK(fabs(m.d[DEF_N1] - DBL_EPSILON) < 1e-30, "lost ulp: |b1|-1 = 2^-52, got %a", m.d[DEF_N1]);
	CHECK(!m.wrong_hand, "lost ulp: right hand");
	bad.basisf = duff_lost_ulpf;
	ref_eval(c, &bad, PREC_FLOAT, up, loc, 0, &m);
	CHECK(m.ulp_max == 1.0 && fabs(m.d[DEF_N1] - FLT_EPSILON) < 1e-20, "lost ulp in float: 1 ulp, |b1|-1 = 2^-23 (got %g, %a)", m.ulp_max, m.d[DEF_N1]);
	/* a lost ulp on a generic input: forward error grows by about one ulp */
	{
		const double n[3] = { 0x1.3p-2, -0x1.7p-1, 0x1.9p-1 };
		sample_metrics good;
		const study_kernel duff = kernel("duff");
		double nn[3];
		const double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		for (i = 0; i < 3; i++) nn[i] = n[i] / len;
		ref_eval(c, &duff, PREC_DOUBLE, nn, loc, 0, &good);
		ref_eval(c, &bad, PREC_DOUBLE, nn, loc, 0, &m);
		CHECK(m.ulp_max >= 0.5 && m.ulp_max <= good.ulp_max + 1.5, "lost ulp (generic n): %g ulp, method alone %g", m.ulp_max, good.ulp_max);
	}
}

/* 3. Known failures: frisvad in float just above its threshold fails,
      duff does not; tangent_cross_z at -z is not finite. */
static void test_known_failures(ref_ctx *c)
{
	const double loc[3] = { 0.0, 0.0, 1.0 };
	sample_metrics m;
	const study_kernel fris = kernel("frisvad"), duff = kernel("duff"), tcz = kernel("tangent_cross_z");
	double worst_f = 0, worst_d = 0;
	dist_spec d;
	uint64_t k;
	memset(&d, 0, sizeof d);
	d.dist = DIST_SOUTH; d.prec = PREC_FLOAT; d.seed = 7; d.count = 4096;
	for (k = 0; k < d.count; k++) {
		double n[3], lv[3], aux;
		dist_sample(&d, k, n, lv, &aux);
		ref_eval(c, &fris, PREC_FLOAT, n, lv, 0, &m);
		if (m.defect > worst_f) worst_f = m.defect;
		ref_eval(c, &duff, PREC_FLOAT, n, lv, 0, &m);
		if (m.defect > worst_d) worst_d = m.defect;
	}
	CHECK(worst_f > 0.1, "frisvad float near -z: published failure, max defect %g > 0.1", worst_f);
	CHECK(worst_d < 4.0 * FLT_EPSILON, "duff float near -z: max defect %g < 4 eps", worst_d);
	{
		const double down[3] = { 0, 0, -1 };
		ref_eval(c, &tcz, PREC_FLOAT, down, loc, 0, &m);
		CHECK(m.nonfinite == 1, "tangent_cross_z at -z: non-finite");
	}
}

/* 4. The two-precision check agrees on ordinary inputs and the MPFR
      reference does not depend on the context's history. */
static void test_two_precisions(ref_ctx *c, ref_ctx *c2)
{
	sample_metrics m, m2;
	int i;
	char why[256];
	const study_kernel all[3] = { kernel("naive"), kernel("frisvad_rotate"), kernel("rtow") };
	dist_spec d;
	uint64_t k;
	int bad = 0;
	memset(&d, 0, sizeof d);
	d.dist = DIST_UNIFORM; d.prec = PREC_DOUBLE; d.seed = 3; d.count = 2000;
	for (k = 0; k < d.count; k++) {
		double n[3], lv[3], aux;
		dist_sample(&d, k, n, lv, &aux);
		for (i = 0; i < 3; i++) {
			ref_eval(c, &all[i], PREC_DOUBLE, n, lv, 0, &m);
			ref_eval(c2, &all[i], PREC_DOUBLE, n, lv, 0, &m2);
			if (!ref_agree(&m, &m2, why, sizeof why)) {
				if (!bad) printf("disagreement: %s\n", why);
				bad++;
			}
		}
	}
	CHECK(bad == 0, "127 and 191 bits agree on 6000 uniform evaluations (%d disagree)", bad);
	/* the change must be real: a defect of 0 scaled is still 0 */
	m2 = m;
	m2.d[DEF_D12] = m.d[DEF_D12] != 0.0 ? m.d[DEF_D12] * (1.0 + 0x1p-30) : 0x1p-60;
	CHECK(m2.d[DEF_D12] != m.d[DEF_D12] && !ref_agree(&m, &m2, why, sizeof why), "ref_agree notices a 2^-30 relative change");
	m2 = m;
	m2.ulp_max = m.ulp_max + 0.5;
	CHECK(!ref_agree(&m, &m2, why, sizeof why), "ref_agree notices half an ulp more");
	CHECK(ref_agree(&m, &m, why, sizeof why), "ref_agree accepts identical metrics");
}

/* 5. The exact accumulator: order-independent, exact on dyadic terms. */
static void test_fx(void)
{
	int i;
	fx a, b;
	memset(&a, 0, sizeof a);
	memset(&b, 0, sizeof b);
	fx_add_double(&a, 1.0); fx_add_double(&a, 0x1p-200); fx_add_double(&a, 3.0);
	fx_add_double(&b, 3.0); fx_add_double(&b, 0x1p-200); fx_add_double(&b, 1.0);
	CHECK(memcmp(&a, &b, sizeof a) == 0, "fx: sums are order-independent");
	CHECK(fx_value(&a) == 4.0, "fx: 1 + 3 + 2^-200 reads 4 in double, got %a", fx_value(&a));
	fx_add_double(&a, 0x1p90);
	CHECK(isinf(fx_value(&a)), "fx: saturates to +inf beyond 2^80");
	memset(&a, 0, sizeof a);
	for (i = 0; i < 1000; i++) fx_add_double(&a, 0.1);
	CHECK(fabs(fx_value(&a) - 100.0) < 1e-12, "fx: 1000 x 0.1 = 100 (got %.17g)", fx_value(&a));
	CHECK(fx_bits_agree(), "fx: fx_add_double (bits) adds what frexp/ldexp's reading adds, carries and edges included");
}

/* 5b. by_nz's log bins without log10: the same bin as the expression,
   at the edges (every double within 64 steps of each 10^(j/4 - off)),
   and for random doubles over the whole range. */
static void test_log_bins(void)
{
	int i;
	int bad = 0, off4, j, tested = 0;
	uint64_t x = 12345;
	for (off4 = 36; off4 <= 68; off4 += 32) {
		const int nb = off4 == 68 ? NB_LOG : NB_NORM;
		for (j = -2; j <= nb + 2; j++) {
			const double t = pow(10.0, j / 4.0 - off4 / 4.0);
			double h = t;
			for (i = 0; i < 64; i++)
				h = nextafter(h, 0.0);
			for (i = 0; i < 128; i++, h = nextafter(h, INFINITY), tested++)
				bad += sweep_log_bin(h, off4, nb) != clampi_log(h, off4, nb);
		}
		for (i = 0; i < 200000; i++, tested++) {
			double h;
			uint64_t u;
			x ^= x << 13; x ^= x >> 7; x ^= x << 17;
			u = x >> 1; /* every positive double, and NaN, inf */
			memcpy(&h, &u, sizeof h);
			if (i % 2)
				h = pow(10.0, -20.0 * (double)(x >> 11) * 0x1p-53); /* where the bins are */
			bad += sweep_log_bin(h, off4, nb) != clampi_log(h, off4, nb);
		}
	}
	CHECK(bad == 0 && sweep_log_bin(0.0, 68, NB_LOG) == 0 && sweep_log_bin(-1.0, 68, NB_LOG) == 0,
	      "by_nz log bins: %d of %d doubles binned differently from the log10 expression", bad, tested);
}

/* 6. Distributions: pure functions of (seed, index), in the format. */
static void test_distributions(void)
{
	int i, p;
	int dd, bad = 0;
	for (p = 0; p < 2; p++)
		for (dd = 0; dd < NDIST; dd++) {
			dist_spec d;
			uint64_t k;
			memset(&d, 0, sizeof d);
			d.dist = dd; d.prec = p; d.seed = 11; d.count = 500;
			d.ex_from = -1.0; d.ex_values = 100; d.ex_azimuths = 5; d.grid_rows = 10; d.grid_cols = 20;
			if (dist_prepare(&d) != 0) { bad++; continue; }
			for (k = 0; k < d.count && k < 500; k++) {
				double n1[3], n2[3], l1[3], l2[3], a1, a2;
				dist_sample(&d, k, n1, l1, &a1);
				dist_sample(&d, k, n2, l2, &a2);
				int b0 = bad;
				if (memcmp(n1, n2, sizeof n1) || memcmp(l1, l2, sizeof l1)) bad++;
				for (i = 0; i < 3; i++)
					if (fmt_round(n1[i], p) != n1[i] || !isfinite(n1[i])) bad++;
				if (dd != DIST_NONUNIT && dd != DIST_THRESHOLD) {
					const long double len = sqrtl((long double)n1[0] * n1[0] + (long double)n1[1] * n1[1] + (long double)n1[2] * n1[2]);
					if (fabsl(len - 1.0L) > 2.0 * (p ? DBL_EPSILON : FLT_EPSILON)) bad++;
				}
				if (dd == DIST_SOUTH && !(n1[2] <= -0.9 + 1e-7)) bad++;
				if (dd == DIST_NORTH && !(n1[2] >= 0.9 - 1e-7)) bad++;
				if (dd == DIST_EXHAUSTIVE && n1[2] != fmt_step(-1.0, (int64_t)(k / 5), p)) bad++;
				if (bad != b0 && bad < 5)
					printf("  %s %s input %llu: (%a, %a, %a)\n", dist_name(dd), prec_name(p),
					       (unsigned long long)k, n1[0], n1[1], n1[2]);
			}
			dist_free(&d);
		}
	CHECK(bad == 0, "distributions: reproducible, representable, unit to rounding, in range (%d bad)", bad);
}

int main(void)
{
	ref_ctx *c = ref_new(127), *c2 = ref_new(191);

	test_exact(c);
	test_broken(c);
	test_known_failures(c);
	test_two_precisions(c, c2);
	test_fx();
	test_log_bins();
	test_distributions();
	ref_free(c);
	ref_free(c2);
	return check_finish("test_sweep");
}
