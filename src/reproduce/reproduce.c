/*
 * reproduce.c - `onbstudy reproduce`: every published figure the study can
 * check, beside a fresh measurement with the same definitions, and the
 * ratio.  The published figures are constants below, each with its
 * citation; the measurements are made on every run.
 *
 *   frisvad2012  Table 1: RMSE of the 11 rows (float).  Protocol as far as
 *                stated: "root mean square error with respect to length and
 *                orthogonality of the vectors".  Assumed: inputs uniform on
 *                the sphere, computed in double and rounded to float; the
 *                error of one input is the mean of the squares of |b1|-1,
 *                |b2|-1, b1.n, b2.n, b1.b2 (the study's `rmse`), evaluated
 *                in double from the float outputs (products of floats are
 *                exact in double).  The expectation is estimated by
 *                stratified sampling in 1 + n.z (geometric strata down to
 *                2^-38, exact weights), with a 95% interval from the strata
 *                variances, so that Frisvad's heavy tail near -z is
 *                measured, not sampled by luck.  For frisvad, the median
 *                over 15 plain draws of 32768 inputs is shown as well.
 *   duff2017     Duff et al. 2017, Section 2: Frisvad's method on their two
 *                failing vectors, with their footnote-1 error (RMS of
 *                |n|-1, |b1|-1, |b2|-1, n.b1, b1.b2, b2.n) and the sign of
 *                det(b1, b2, n); their Listing 2 and 3 on the same vectors
 *                beside pbrt-v4's test bound (mean square < 1e-10).
 *   max2017      Max 2017: the minimax threshold of Listing 2 in float for
 *                the combined error, and for orthogonality and normality
 *                with the definitions we could try (see README).
 * Writes reproduce.csv (atomically) to --out when given, and a table (or
 * the CSV) on stdout.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "reproduce/reproduce.h"
#include "common/options.h"
#include "common/output.h"
#include "inputs/rng.h"

typedef void (*fnf)(onb_vec3f, onb_vec3f *, onb_vec3f *);

typedef struct {
	const char *paper, *item, *source; /* source: where the published figure is */
	double published, measured, lo, hi; /* lo, hi: 95% interval, or NAN */
	const char *note;
} rp_row;

#define RP_MAX 64
typedef struct { rp_row r[RP_MAX]; int n; uint64_t seed; int nh; } rp_set;

static void rp_add(rp_set *s, const char *paper, const char *item, const char *src, double pub, double meas,
                   double lo, double hi, const char *note)
{
	rp_row *r;
	if (s->n >= RP_MAX)
		return;
	r = &s->r[s->n++];
	r->paper = paper; r->item = item; r->source = src; r->published = pub; r->measured = meas;
	r->lo = lo; r->hi = hi; r->note = note;
}

/* SplitMix64's finalizer on a counter: sample k of stream s is the same on
   every run (its own keying, kept so that the committed figures stay). */
static double rp_u01(uint64_t seed, uint64_t k)
{
	return (double)(rng_fmix64(seed * RNG_GOLDEN + (k + 1) * RNG_FMIX_M1) >> 11) * 0x1p-53;
}

/* A float unit vector with 1 + n.z = u (computed in double, then rounded) */
static onb_vec3f rp_dir(double u, double phi)
{
	const double z = -1.0 + u, r = sqrt(fmax(0.0, u * (2.0 - u)));
	onb_vec3f n;
	n.x = (float)(r * cos(phi)); n.y = (float)(r * sin(phi)); n.z = (float)z;
	return n;
}

static double rp_dot(onb_vec3f a, onb_vec3f b) { return (double)a.x * b.x + (double)a.y * b.y + (double)a.z * b.z; }
/* |a| - 1 without cancellation: (|a|^2 - 1)/(|a| + 1) */
static double rp_len1(onb_vec3f a) { const double s = rp_dot(a, a); return (s - 1.0) / (sqrt(s) + 1.0); }

/* Frisvad's Table 1 error of one input: the mean square of the five */
static double rp_table1_sq(fnf f, onb_vec3f n)
{
	onb_vec3f b1, b2;
	double d[5], s = 0.0;
	int k;
	f(n, &b1, &b2);
	d[0] = rp_len1(b1); d[1] = rp_len1(b2); d[2] = rp_dot(b1, n); d[3] = rp_dot(b2, n); d[4] = rp_dot(b1, b2);
	for (k = 0; k < 5; k++) s += d[k] * d[k];
	return s / 5.0;
}

/* ---- Frisvad 2012, Table 1 ---- */
#define RP_STRATA 40
static const struct { const char *name; fnf f; double pub; } rp_t1[] = {
	{ "naive, rsqrt", onb_naivef, 5.6e-8 },
	{ "naive, InvSqrt", onb_naive_invsqrtf, 7.3e-4 },
	{ "naive, SSE_rsqrt", onb_naive_rsqrtf, 6.6e-5 },
	{ "naive, SSE_rsqrt_1N", onb_naive_rsqrt_nrf, 6.2e-8 },
	{ "naive, no normalization", onb_naive_nonormf, 1.5e-1 },
	{ "hughes_moeller, rsqrt", onb_hughes_moellerf, 3.2e-8 },
	{ "hughes_moeller, InvSqrt", onb_hughes_moeller_invsqrtf, 7.9e-4 },
	{ "hughes_moeller, SSE_rsqrt", onb_hughes_moeller_rsqrtf, 6.7e-5 },
	{ "hughes_moeller, SSE_rsqrt_1N", onb_hughes_moeller_rsqrt_nrf, 4.0e-8 },
	{ "hughes_moeller, no normalization", onb_hughes_moeller_nonormf, 5.5e-2 },
	{ "frisvad", onb_frisvadf, 7.2e-7 },
};
#define RP_T1_SRC "Frisvad 2012, JGT 16(3), Table 1 (author's version), RMSE"

/* Stratified in u = 1 + n.z: stratum j is [2^(j-S+1), 2^(j-S+2)) for
   j >= 1 and [0, 2^(2-S)) for j = 0, weight (its width)/2, nh inputs
   each.  Returns the mean square; *se its standard error. */
static double rp_stratified(fnf f, uint64_t seed, int nh, double *se)
{
	double est = 0.0, var = 0.0;
	int j, i;
	for (j = 0; j < RP_STRATA; j++) {
		const double lo = j ? ldexp(1.0, j - RP_STRATA + 1) : 0.0, hi = ldexp(1.0, j - RP_STRATA + 2);
		const double w = (hi - lo) / 2.0;
		double sum = 0.0, sq = 0.0, mean, v;
		for (i = 0; i < nh; i++) {
			const uint64_t k = (uint64_t)j * (uint64_t)nh + (uint64_t)i;
			const double u = lo + (hi - lo) * rp_u01(seed, 2 * k), ph = 6.283185307179586 * rp_u01(seed, 2 * k + 1);
			const double e = rp_table1_sq(f, rp_dir(u, ph));
			sum += e; sq += e * e;
		}
		mean = sum / nh;
		v = nh > 1 ? fmax(0.0, sq / nh - mean * mean) * nh / (nh - 1.0) : 0.0;
		est += w * mean;
		var += w * w * v / nh;
	}
	*se = sqrt(var);
	return est;
}

static int rp_cmp(const void *a, const void *b)
{
	const double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* The RMSE one plain uniform draw of n inputs gives: median of `draws` */
static double rp_plain_median(fnf f, uint64_t seed, int n, int draws)
{
	double r[32];
	int d, i;
	for (d = 0; d < draws && d < 32; d++) {
		double s = 0.0;
		for (i = 0; i < n; i++) {
			const uint64_t k = (uint64_t)d * (uint64_t)n + (uint64_t)i;
			s += rp_table1_sq(f, rp_dir(2.0 * rp_u01(seed ^ 0x706c61696eULL, 2 * k),
			                            6.283185307179586 * rp_u01(seed ^ 0x706c61696eULL, 2 * k + 1)));
		}
		r[d] = sqrt(s / n);
	}
	qsort(r, (size_t)d, sizeof r[0], rp_cmp);
	return r[d / 2];
}

static void rp_frisvad2012(rp_set *s)
{
	size_t i;
	for (i = 0; i < sizeof rp_t1 / sizeof rp_t1[0]; i++) {
		double se, ms = rp_stratified(rp_t1[i].f, s->seed, s->nh, &se);
		rp_add(s, "frisvad2012", rp_t1[i].name, RP_T1_SRC, rp_t1[i].pub, sqrt(ms),
		       sqrt(fmax(0.0, ms - 1.96 * se)), sqrt(ms + 1.96 * se),
		       "expectation over uniform float inputs (stratified in 1+n.z)");
	}
	rp_add(s, "frisvad2012", "frisvad, one draw of 32768", RP_T1_SRC, 7.2e-7,
	       rp_plain_median(onb_frisvadf, s->seed, 32768, 15), NAN, NAN,
	       "median RMSE of 15 plain uniform draws of 32768 inputs: the heavy tail near -z makes one draw small");
}

/* ---- Duff et al. 2017 ---- */
/* Footnote 1's error of the frame {n, b1, b2}: the mean of the squares of
   |n|-1, |b1|-1, |b2|-1, n.b1, b1.b2, b2.n (pbrt-v4 writes it so, without
   the root); Section 2 quotes its root (RMS).  Also the study's
   `duff_rms` metric (reference.c). */
static double rp_duff_ms(onb_vec3f n, onb_vec3f b1, onb_vec3f b2)
{
	const double d[6] = { rp_len1(n), rp_len1(b1), rp_len1(b2), rp_dot(n, b1), rp_dot(b1, b2), rp_dot(b2, n) };
	double s = 0.0;
	int k;
	for (k = 0; k < 6; k++) s += d[k] * d[k];
	return s / 6.0;
}
static double rp_det(onb_vec3f a, onb_vec3f b, onb_vec3f c)
{
	return (double)a.x * ((double)b.y * c.z - (double)b.z * c.y) - (double)a.y * ((double)b.x * c.z - (double)b.z * c.x)
	     + (double)a.z * ((double)b.x * c.y - (double)b.y * c.x);
}

#define RP_DUFF_SRC "Duff et al. 2017, JCGT 6(1), Sect. 2 and footnote 1 (RMS 0.29 and 0.16, one frame flipped; as quoted in a public test of these vectors, the paper's text was not in our sources)"
#define RP_PBRT4_SRC "pbrt-v4 src/pbrt/util/vecmath_test.cpp, TEST(Vector, CoordinateSystem): footnote-1 mean square < 1e-10 on Duff's vectors"

static void rp_duff2017(rp_set *s)
{
	/* pbrt-v4's test writes them as double literals converted to float */
	const double v[2][3] = { { 0.00038527316, 0.00038460016, -0.99999988079 },
	                         { -0.00019813581, -0.00008946839, -0.99999988079 } };
	static const char *const it_rms[2] = { "frisvad, vector 1: RMS error", "frisvad, vector 2: RMS error" };
	static const char *const it_ms[2][2] = { { "duff, vector 1: mean square", "duff, vector 2: mean square" },
	                                         { "duff_branchless, vector 1: mean square", "duff_branchless, vector 2: mean square" } };
	const double pub_rms[2] = { 0.29, 0.16 };
	int i, flipped = 0;
	for (i = 0; i < 2; i++) {
		onb_vec3f n, b1, b2;
		n.x = (float)v[i][0]; n.y = (float)v[i][1]; n.z = (float)v[i][2];
		onb_frisvadf(n, &b1, &b2);
		rp_add(s, "duff2017", it_rms[i], RP_DUFF_SRC, pub_rms[i], sqrt(rp_duff_ms(n, b1, b2)), NAN, NAN,
		       "footnote 1 metric, float");
		flipped += rp_det(b1, b2, n) < 0.0;
		onb_dufff(n, &b1, &b2);
		rp_add(s, "duff2017", it_ms[0][i], RP_PBRT4_SRC, 1e-10, rp_duff_ms(n, b1, b2), NAN, NAN,
		       rp_det(b1, b2, n) > 0.0 ? "a bound: ratio < 1 passes; det(b1,b2,n) > 0" : "a bound; det(b1,b2,n) <= 0!");
		onb_duff_branchlessf(n, &b1, &b2);
		rp_add(s, "duff2017", it_ms[1][i], RP_PBRT4_SRC, 1e-10, rp_duff_ms(n, b1, b2), NAN, NAN,
		       rp_det(b1, b2, n) > 0.0 ? "a bound: ratio < 1 passes; det(b1,b2,n) > 0" : "a bound; det(b1,b2,n) <= 0!");
	}
	rp_add(s, "duff2017", "frisvad: frames with det(b1,b2,n) < 0", RP_DUFF_SRC, 1.0, (double)flipped, NAN, NAN,
	       "count over the two vectors");
}

/* ---- Max 2017 ---- */
/* Eigenvalues' largest |sqrt(1 + e) - 1| for the symmetric E = G - I,
   G the Gram matrix of the frame [b1 b2 n]: max over unit v of ||Mv| - 1|
   (trigonometric solution of the 3x3 symmetric eigenproblem). */
static double rp_frame_norm(const double e[6]) /* e11 e22 e33 e12 e13 e23 */
{
	const double p1 = e[3] * e[3] + e[4] * e[4] + e[5] * e[5], q = (e[0] + e[1] + e[2]) / 3.0;
	double l[3], worst = 0.0;
	int k;
	if (p1 == 0.0) {
		l[0] = e[0]; l[1] = e[1]; l[2] = e[2];
	} else {
		const double a = e[0] - q, b = e[1] - q, c = e[2] - q;
		const double p = sqrt((a * a + b * b + c * c + 2.0 * p1) / 6.0);
		const double r = (a * (b * c - e[5] * e[5]) - e[3] * (e[3] * c - e[5] * e[4]) + e[4] * (e[3] * e[5] - b * e[4]))
		                 / (2.0 * p * p * p);
		const double ph = acos(fmax(-1.0, fmin(1.0, r))) / 3.0;
		l[0] = q + 2.0 * p * cos(ph);
		l[2] = q + 2.0 * p * cos(ph + 2.0943951023931957);
		l[1] = 3.0 * q - l[0] - l[2];
	}
	for (k = 0; k < 3; k++)
		worst = fmax(worst, fabs(l[k] / (sqrt(fmax(0.0, 1.0 + l[k])) + 1.0)));
	return worst;
}

/* the three criteria of one frame: [0] normality max| |b_i|-1 |,
   [1] orthogonality max(|b1.n|, |b2.n|, |b1.b2|), [2] frame normality */
static void rp_max_errs(onb_vec3f n, onb_vec3f b1, onb_vec3f b2, double out[3])
{
	const double s1 = rp_dot(b1, b1), s2 = rp_dot(b2, b2), sn = rp_dot(n, n);
	const double e[6] = { s1 - 1.0, s2 - 1.0, sn - 1.0, rp_dot(b1, b2), rp_dot(b1, n), rp_dot(b2, n) };
	out[0] = fmax(fabs(rp_len1(b1)), fabs(rp_len1(b2)));
	out[1] = fmax(fabs(e[4]), fmax(fabs(e[5]), fabs(e[3])));
	out[2] = rp_frame_norm(e);
}

#define RP_MAXZ 2048
#define RP_MAX_SRC "Max 2017, JCGT 6(1): t = -0.99998796 (the study's ONB_FRISVAD_MAX_TF)"
typedef struct { double z[RP_MAXZ], f[RP_MAXZ][4], g[RP_MAXZ][4]; int m; } rp_maxdata;

/* f: the formula's worst errors at each n.z (over 64 azimuths), g: the
   fallback's; criteria 0..2 as rp_max_errs, 3 = max(0, 1) (both). */
static void rp_max_measure(rp_maxdata *d, uint64_t seed)
{
	int j, a, c;
	d->m = 0;
	for (j = 0; j < RP_MAXZ; j++) {
		const double u = j < 1024 ? ldexp((double)(j + 1), -24) : 1025.0 * 0x1p-24 * pow(0.1 / (1025.0 * 0x1p-24), (j - 1024) / 1023.0);
		const float z = (float)(-1.0 + u);
		if (d->m && z <= d->z[d->m - 1])
			continue;
		d->z[d->m] = z;
		for (c = 0; c < 4; c++) d->f[d->m][c] = d->g[d->m][c] = 0.0;
		for (a = 0; a < 64; a++) {
			/* as `onbstudy threshold`: an exact unit vector whose n.z is
			   within half an ulp of z, rounded (n.z exactly z with x, y
			   fitted to it would be unit to eps (1 + n.z), hiding the
			   formula's failure); then n.z is set to z itself */
			const uint64_t k = (uint64_t)j * 64u + (uint64_t)a;
			const double up = (double)nextafterf(z, 0.0f) - (double)z;
			onb_vec3f n = rp_dir(1.0 + (double)z + (rp_u01(seed, 2 * k) - 0.5) * up, 6.283185307179586 * rp_u01(seed, 2 * k + 1));
			onb_vec3f b1, b2;
			double e[3];
			n.z = z;
			onb_frisvad_thresholdf(n, -2.0f, &b1, &b2);
			rp_max_errs(n, b1, b2, e);
			for (c = 0; c < 3; c++) d->f[d->m][c] = fmax(d->f[d->m][c], e[c]);
			onb_frisvad_thresholdf(n, 2.0f, &b1, &b2);
			rp_max_errs(n, b1, b2, e);
			for (c = 0; c < 3; c++) d->g[d->m][c] = fmax(d->g[d->m][c], e[c]);
		}
		d->f[d->m][3] = fmax(d->f[d->m][0], d->f[d->m][1]);
		d->g[d->m][3] = fmax(d->g[d->m][0], d->g[d->m][1]);
		d->m++;
	}
}

/* minimax t for criterion c: t = z[j] sends z[0..j-1] to the fallback */
static double rp_minimax(const rp_maxdata *d, int c, double *err)
{
	static double suf[RP_MAXZ + 1];
	double pre = 0.0, best = INFINITY, bt = NAN;
	int j;
	suf[d->m] = 0.0;
	for (j = d->m - 1; j >= 0; j--) suf[j] = fmax(suf[j + 1], d->f[j][c]);
	for (j = 0; j < d->m; j++) {
		const double e = fmax(pre, suf[j]);
		if (e < best) { best = e; bt = d->z[j]; }
		pre = fmax(pre, d->g[j][c]);
	}
	*err = best;
	return bt;
}

static void rp_max2017(rp_set *s)
{
	static rp_maxdata d;
	static const char *const what[4] = { "normality, max of abs(len(b_i) - 1)", "orthogonality", "frame normality, max over unit v of abs(len(Mv) - 1)", "both (normality and orthogonality)" };
	static char items[8][96];
	const double pub_1pt = 1.0 + (double)ONB_FRISVAD_MAX_TF;
	int c;
	rp_max_measure(&d, s->seed ^ 0x6d6178ULL);
	for (c = 0; c < 4; c++) {
		double err, t = rp_minimax(&d, c, &err);
		snprintf(items[2 * c], sizeof items[0], "minimax %s: 1 + t", what[c]);
		snprintf(items[2 * c + 1], sizeof items[0], "minimax %s: max error", what[c]);
		if (c == 3) {
			rp_add(s, "max2017", items[2 * c], RP_MAX_SRC, pub_1pt, 1.0 + t, NAN, NAN, "float; 2048 n.z near -1 x 64 azimuths");
			rp_add(s, "max2017", items[2 * c + 1], RP_MAX_SRC, NAN, err, NAN, NAN, "published error not recovered");
		} else {
			rp_add(s, "max2017", items[2 * c], "Max 2017 (not recovered)", NAN, 1.0 + t, NAN, NAN,
			       c == 0 ? "degenerate: the fallback's lengths are exact, so this measure sends everything to it" :
			       c == 1 ? "published value not recovered" : "a definition tried for Max's normality");
			rp_add(s, "max2017", items[2 * c + 1], "Max 2017 (not recovered)", NAN, err, NAN, NAN, "");
		}
	}
}

/* ---- output ---- */
static double rp_ratio(const rp_row *r) { return (isnan(r->published) || r->published == 0.0) ? NAN : r->measured / r->published; }

static void rp_csv(FILE *f, const rp_set *s)
{
	int i;
	fprintf(f, "paper,item,published,measured,ratio,ci95_lo,ci95_hi,source,note\n");
	for (i = 0; i < s->n; i++) {
		const rp_row *r = &s->r[i];
		fprintf(f, "%s,\"%s\",%.6g,%.6g,%.4g,%.6g,%.6g,\"%s\",\"%s\"\n", r->paper, r->item, r->published, r->measured,
		        rp_ratio(r), r->lo, r->hi, r->source, r->note);
	}
}

static void rp_table(const rp_set *s)
{
	int i;
	printf("%-11s %-50s %11s %11s %8s  %s\n", "paper", "item", "published", "measured", "ratio", "95% interval");
	for (i = 0; i < s->n; i++) {
		const rp_row *r = &s->r[i];
		printf("%-11s %-50s %11.4g %11.4g %8.3g", r->paper, r->item, r->published, r->measured, rp_ratio(r));
		if (!isnan(r->lo))
			printf("  [%.4g, %.4g]", r->lo, r->hi);
		printf("\n");
	}
}

static const char *const rp_papers[3] = { "frisvad2012", "duff2017", "max2017" };

static int rp_parse(int argc, char **argv, int on[3], rp_set *s, const char **out, int *csv)
{
	static const struct option lo[] = {
		{ "paper", required_argument, NULL, 'p' }, { "strata-samples", required_argument, NULL, 'n' },
		{ "seed", required_argument, NULL, 's' }, { "out", required_argument, NULL, 'o' },
		{ "format", required_argument, NULL, 'f' }, CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
	};
	cli_args c;
	unsigned long long u;
	int v, rc = 0;
	if (cli_begin(&c, "reproduce", argc, argv))
		return ONB_EXIT_USAGE;
	while (rc == 0 && (v = cli_next(&c, lo)) != -1) {
		if (v == CLI_HELP) {
			printf("usage: onbstudy reproduce [--paper frisvad2012,duff2017,max2017] [--strata-samples N]\n"
			       "                          [--seed S] [--out DIR] [--format table|csv]\n"
			       "  Each published figure beside a fresh measurement with the same definitions, and\n"
			       "  the ratio.  --strata-samples: inputs per stratum of 1 + n.z for Table 1 (40 strata,\n"
			       "  default 4096).  --out DIR writes DIR/reproduce.csv.\n");
			rc = -1;
		} else if (v == 'p') {
			if (cli_name_list("--paper", c.arg, on, rp_papers, 3) != 0) rc = ONB_EXIT_USAGE;
		} else if (v == 'n') {
			if (parse_u64("--strata-samples", c.arg, 2, 1u << 20, &u) != 0) rc = ONB_EXIT_USAGE; else s->nh = (int)u;
		} else if (v == 's') {
			if (parse_u64("--seed", c.arg, 0, ~0ULL, &u) != 0) rc = ONB_EXIT_USAGE; else s->seed = u;
		} else if (v == 'o') {
			*out = c.arg;
		} else if (v == 'f') {
			if ((*csv = cli_format("--format", c.arg, 0)) < 0) rc = ONB_EXIT_USAGE;
		} else {
			rc = ONB_EXIT_USAGE;
		}
	}
	if (rc == 0 && cli_no_rest(&c) != 0)
		rc = ONB_EXIT_USAGE;
	cli_end(&c);
	return rc;
}

int cmd_reproduce(int argc, char **argv)
{
	static rp_set s;
	int on[3] = { 1, 1, 1 }, csv = 0, rc;
	const char *out = NULL;
	study_out o;
	memset(&s, 0, sizeof s);
	s.seed = 1; s.nh = 4096;
	rc = rp_parse(argc, argv, on, &s, &out, &csv);
	if (rc)
		return rc < 0 ? 0 : rc;
	if (out && (study_mkdir_p(out) != 0 || study_out_open(&o, out, "reproduce.csv") != 0))
		return 1;
	if (on[0]) rp_frisvad2012(&s);
	if (on[1]) rp_duff2017(&s);
	if (on[2]) rp_max2017(&s);
	if (csv) rp_csv(stdout, &s); else rp_table(&s);
	if (out) {
		study_provenance(o.f, "reproduce", s.seed, 1);
		fprintf(o.f, "# Table 1: %d strata of 1 + n.z x %d inputs per row; errors in double from the float outputs\n",
		        RP_STRATA, s.nh);
		rp_csv(o.f, &s);
		if (study_out_commit(&o) != 0)
			return 1;
		fprintf(stderr, "onbstudy: wrote %s/reproduce.csv\n", out);
	}
	return 0;
}
