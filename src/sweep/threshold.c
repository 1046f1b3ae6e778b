/*
 * threshold.c - `onbstudy threshold`: Nelson Max's (2017) analysis of
 * Frisvad's threshold.  Listing 2 uses Frisvad's formula for n.z >= t
 * and the fixed fallback b1 = (0,-1,0), b2 = (-1,0,0) for n.z < t.  Near
 * the south pole the formula's error grows like eps/(1 + n.z) while the
 * fallback's grows like sqrt(2(1 + n.z)); the best t balances them.
 *
 * For every n.z in a dense set near -1 (the first C representable values
 * above -1, then M log-spaced values of 1 + n.z up to 0.1), at A azimuths,
 * we measure in MPFR (ref_defects) the normality error max| |b_i| - 1 |
 * and the orthogonality error max(|b1.n|, |b2.n|, |b1.b2|) of the formula
 * and of the fallback, keeping the maximum over azimuths.  Each input is an
 * exact unit vector whose n.z lies within half an ulp of the value, rounded
 * to the format: unit to rounding, as a renderer's normalized normal is.  A threshold
 * t = V_j sends V_i < t to the fallback, so
 *   max_normality(t) = max(max_{i<j} fallback_N(i), max_{i>=j} formula_N(i))
 * and likewise for orthogonality and for both together.  We report the t
 * minimizing each, and the published thresholds beside them.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <errno.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "sweep/threshold.h"
#include "sweep/state.h"  /* its state-file helpers */
#include "common/options.h"
#include "common/output.h"
#include "methods/kernels.h"
#include "reference/reference.h"
#include "inputs/inputs.h"
#include "inputs/rng.h"

#define TH_MAGIC "onbthresh-state2"   /* 2: three precisions */

typedef struct {
	char magic[24];
	uint64_t seed;
	int prec_on[PREC_COUNT], consecutive, logspaced, azimuths, ref_bits, shard_k, shard_n;
	int count[PREC_COUNT];        /* number of n.z values per precision */
} th_cfg;

typedef struct {
	th_cfg cfg;
	double *v[PREC_COUNT];        /* n.z values, increasing            */
	double *fn[PREC_COUNT], *fo[PREC_COUNT], *bn[PREC_COUNT], *bo[PREC_COUNT];
	unsigned char *done[PREC_COUNT];
} th_state;

static void th_free(th_state *s)
{
	int p;
	for (p = 0; p < PREC_COUNT; p++) {
		free(s->v[p]); free(s->fn[p]); free(s->fo[p]); free(s->bn[p]); free(s->bo[p]); free(s->done[p]);
		s->v[p] = s->fn[p] = s->fo[p] = s->bn[p] = s->bo[p] = NULL;
		s->done[p] = NULL;
	}
}

static int th_alloc(th_state *s, int p, int n)
{
	s->v[p] = calloc((size_t)n, sizeof(double));
	s->fn[p] = calloc((size_t)n, sizeof(double));
	s->fo[p] = calloc((size_t)n, sizeof(double));
	s->bn[p] = calloc((size_t)n, sizeof(double));
	s->bo[p] = calloc((size_t)n, sizeof(double));
	s->done[p] = calloc((size_t)n, 1);
	if (!s->v[p] || !s->fn[p] || !s->fo[p] || !s->bn[p] || !s->bo[p] || !s->done[p]) {
		study_error("out of memory for %d threshold inputs", n);
		return -1;
	}
	return 0;
}

/* The n.z values: C consecutive from -1, then M log-spaced 1 + n.z up to 0.1. */
static int build_values(th_state *s, int p)
{
	const int C = s->cfg.consecutive, M = s->cfg.logspaced;
	int j, n = 0;
	double last;
	if (th_alloc(s, p, C + M) != 0)
		return -1;
	for (j = 0; j < C; j++)
		s->v[p][n++] = fmt_step(-1.0, j, p);
	last = s->v[p][n - 1];
	for (j = 0; j < M; j++) {
		const double h0 = 1.0 + last, lo = log10(h0), hi = -1.0;
		const double z = fmt_round(-1.0 + pow(10.0, lo + (hi - lo) * (j + 1) / M), p);
		if (z > s->v[p][n - 1])
			s->v[p][n++] = z;
	}
	s->cfg.count[p] = n;
	return 0;
}

static double nmax(double a, double b) { return b > a || isnan(b) ? b : a; }

/* Listing 2's formula in binary16 (never the fallback: t = -2), each
   operation rounded to binary16 (libonb's onb_frisvad_thresholdh); the
   caller refused half where the build has none. */
static void frisvad_formula_half(const double n[3], double b[6])
{
#if ONB_HAVE_HALF
	const onb_vec3h nh = { (onb_half)n[0], (onb_half)n[1], (onb_half)n[2] };
	onb_vec3h b1, b2;
	onb_frisvad_thresholdh(nh, (onb_half)-2.0, &b1, &b2);
	b[0] = (double)b1.x; b[1] = (double)b1.y; b[2] = (double)b1.z;
	b[3] = (double)b2.x; b[4] = (double)b2.y; b[5] = (double)b2.z;
#else
	int k;
	(void)n;
	for (k = 0; k < 6; k++)
		b[k] = NAN;
#endif
}

static void measure(th_state *s, ref_ctx *rc, int p, int j)
{
	const double z = s->v[p][j];
	const long double up = (long double)fmt_step(z, 1, p) - z;
	int a, k;
	double fN = 0, fO = 0, bN = 0, bO = 0;
	for (a = 0; a < s->cfg.azimuths; a++) {
		const long double phi = 6.283185307179586476925L * rng_u01(s->cfg.seed, 77, (uint64_t)j * 4096u + (uint64_t)a);
		/* An exact unit vector whose n.z lies within half an ulp of z, rounded:
		   unit to the format's rounding, as a normalized normal is (n.z exact
		   with x, y fitted to it would be unit to eps * (1 + n.z) and hide the
		   formula's failure). */
		const long double jit = rng_u01(s->cfg.seed, 78, (uint64_t)j * 4096u + (uint64_t)a) - (z == -1.0 ? 0.0L : 0.5L);
		const long double h = 1.0L + z + jit * up;
		const long double r = sqrtl(fmaxl(0.0L, h * (2.0L - h)));
		double n[3], b[6], d[NDEF];
		n[0] = fmt_round((double)(r * cosl(phi)), p);
		n[1] = fmt_round((double)(r * sinl(phi)), p);
		n[2] = z;
		if (p == PREC_HALF) {
			frisvad_formula_half(n, b);
		} else if (p == PREC_FLOAT) {
			const onb_vec3f nf = { (float)n[0], (float)n[1], (float)n[2] };
			onb_vec3f b1, b2;
			onb_frisvad_thresholdf(nf, -2.0f, &b1, &b2); /* the formula, never the fallback */
			b[0] = b1.x; b[1] = b1.y; b[2] = b1.z; b[3] = b2.x; b[4] = b2.y; b[5] = b2.z;
		} else {
			const onb_vec3 nd = { n[0], n[1], n[2] };
			onb_vec3 b1, b2;
			onb_frisvad_threshold(nd, -2.0, &b1, &b2);
			b[0] = b1.x; b[1] = b1.y; b[2] = b1.z; b[3] = b2.x; b[4] = b2.y; b[5] = b2.z;
		}
		ref_defects(rc, n, b, d);
		for (k = 0; k < NDEF; k++)
			if (isnan(d[k]))
				d[k] = INFINITY; /* a non-finite basis is infinitely wrong */
		fN = nmax(fN, nmax(fabs(d[DEF_N1]), fabs(d[DEF_N2])));
		fO = nmax(fO, nmax(fabs(d[DEF_D1N]), nmax(fabs(d[DEF_D2N]), fabs(d[DEF_D12]))));
		b[0] = 0.0; b[1] = -1.0; b[2] = 0.0; b[3] = -1.0; b[4] = 0.0; b[5] = 0.0;
		ref_defects(rc, n, b, d);
		bN = nmax(bN, nmax(fabs(d[DEF_N1]), fabs(d[DEF_N2])));
		bO = nmax(bO, nmax(fabs(d[DEF_D1N]), nmax(fabs(d[DEF_D2N]), fabs(d[DEF_D12]))));
	}
	s->fn[p][j] = fN; s->fo[p][j] = fO; s->bn[p][j] = bN; s->bo[p][j] = bO;
	s->done[p][j] = 1;
}

/* max errors for t = V_j, for each j, into mN, mO, mB (arrays of count) */
static void curves(const th_state *s, int p, double *mN, double *mO, double *mB)
{
	const int n = s->cfg.count[p];
	int j;
	double pre_N = 0, pre_O = 0, suf_N = 0, suf_O = 0;
	double *sN = malloc((size_t)n * sizeof *sN), *sO = malloc((size_t)n * sizeof *sO);
	if (!sN || !sO) {
		free(sN); free(sO);
		for (j = 0; j < n; j++) mN[j] = mO[j] = mB[j] = NAN;
		return;
	}
	for (j = n - 1; j >= 0; j--) {
		suf_N = nmax(suf_N, s->fn[p][j]);
		suf_O = nmax(suf_O, s->fo[p][j]);
		sN[j] = suf_N;
		sO[j] = suf_O;
	}
	for (j = 0; j < n; j++) {
		mN[j] = nmax(pre_N, sN[j]);
		mO[j] = nmax(pre_O, sO[j]);
		mB[j] = nmax(mN[j], mO[j]);
		pre_N = nmax(pre_N, s->bn[p][j]);
		pre_O = nmax(pre_O, s->bo[p][j]);
	}
	free(sN); free(sO);
}

static int index_of_t(const th_state *s, int p, double t)
{
	/* the first value >= t: inputs below it take the fallback, as n.z < t does */
	int j;
	for (j = 0; j < s->cfg.count[p]; j++)
		if (s->v[p][j] >= t)
			return j;
	return s->cfg.count[p] - 1;
}

static int th_write(th_state *s, const char *out, int threads)
{
	study_out o;
	int p, j;
	if (study_mkdir_p(out) != 0 || study_out_open(&o, out, "threshold.csv") != 0)
		return -1;
	study_provenance(o.f, "threshold", s->cfg.seed, threads);
	fprintf(o.f, "# Max 2017 threshold analysis of Frisvad 2012 Listing 2: n.z < t takes the fallback b1=(0,-1,0), b2=(-1,0,0)\n");
	fprintf(o.f, "# inputs: the first %d representable n.z above -1, then up to %d log-spaced 1+n.z to 0.1; %d azimuths each; MPFR %d bits\n",
	        s->cfg.consecutive, s->cfg.logspaced, s->cfg.azimuths, s->cfg.ref_bits);
	fprintf(o.f, "# max_normality: max | |b_i| - 1 |; max_orthogonality: max(|b1.n|, |b2.n|, |b1.b2|); over all inputs, for threshold t\n");
	fprintf(o.f, "precision,t_hex,t,one_plus_t,max_normality,max_orthogonality,max_both\n");
	printf("%-7s %-10s %-26s %-14s %-12s %-12s %-12s\n", "prec", "criterion", "t", "1+t", "max normal.", "max orthog.", "max both");
	for (p = 0; p < PREC_COUNT; p++) {
		const int n = s->cfg.count[p];
		double *mN, *mO, *mB;
		const char *pn = prec_name(p);
		int best[3] = { 0, 0, 0 }, c;
		const char *crit[3] = { "normality", "orthog.", "both" };
		if (!s->cfg.prec_on[p])
			continue;
		mN = malloc((size_t)n * sizeof *mN);
		mO = malloc((size_t)n * sizeof *mO);
		mB = malloc((size_t)n * sizeof *mB);
		if (!mN || !mO || !mB) {
			free(mN); free(mO); free(mB);
			study_out_abort(&o);
			study_error("out of memory");
			return -1;
		}
		curves(s, p, mN, mO, mB);
		for (j = 0; j < n; j++) {
			fprintf(o.f, "%s,%a,%.9g,%.6g,%.6g,%.6g,%.6g\n", pn, s->v[p][j], s->v[p][j], 1.0 + s->v[p][j], mN[j], mO[j], mB[j]);
			if (mN[j] < mN[best[0]]) best[0] = j;
			if (mO[j] < mO[best[1]]) best[1] = j;
			if (mB[j] < mB[best[2]]) best[2] = j;
		}
		for (c = 0; c < 3; c++) {
			const int b = best[c];
			printf("%-7s %-10s %-26a %-14.6g %-12.4g %-12.4g %-12.4g  minimax of %s\n", pn, crit[c], s->v[p][b],
			       1.0 + s->v[p][b], mN[b], mO[b], mB[b], crit[c]);
			fprintf(o.f, "# minimax %s: t = %a (%.9g), one_plus_t %.6g, max_normality %.6g, max_orthogonality %.6g, max_both %.6g\n",
			        crit[c], s->v[p][b], s->v[p][b], 1.0 + s->v[p][b], mN[b], mO[b], mB[b]);
		}
		{
			const double pub[2] = { fmt_round(p != PREC_DOUBLE ? (double)ONB_FRISVAD_TF : ONB_FRISVAD_T, p),
			                        fmt_round(p != PREC_DOUBLE ? (double)ONB_FRISVAD_MAX_TF : ONB_FRISVAD_MAX_T, p) };
			const char *who[2] = { "Frisvad 2012", "Max 2017" };
			int q;
			for (q = 0; q < 2; q++) {
				const int b = index_of_t(s, p, pub[q]);
				printf("%-7s %-10s %-26a %-14.6g %-12.4g %-12.4g %-12.4g  published (%s)\n", pn, "published", pub[q],
				       1.0 + pub[q], mN[b], mO[b], mB[b], who[q]);
				fprintf(o.f, "# published %s: t = %a (%.9g), one_plus_t %.6g, max_normality %.6g, max_orthogonality %.6g, max_both %.6g\n",
				        who[q], pub[q], pub[q], 1.0 + pub[q], mN[b], mO[b], mB[b]);
			}
		}
		free(mN); free(mO); free(mB);
	}
	printf("normality alone is minimized by sending every input to the fallback (exact unit vectors), so its minimax\n"
	       "is the largest t tried; orthogonality, and both together, balance eps/(1+n.z) against sqrt(2(1+n.z)).\n");
	if (study_out_commit(&o) != 0)
		return -1;
	fprintf(stderr, "onbstudy: wrote %s/threshold.csv\n", out);
	return 0;
}

/* The parts of precision p in a state file, in file order (state.h). */
static int th_parts(const th_state *s, int p, state_part *parts)
{
	const size_t n = (size_t)s->cfg.count[p];
	void *const a[6] = { s->v[p], s->fn[p], s->fo[p], s->bn[p], s->bo[p], s->done[p] };
	int i;
	for (i = 0; i < 6; i++) {
		parts[i].p = a[i];
		parts[i].bytes = i < 5 ? n * sizeof(double) : n;
	}
	return 6;
}

static int th_save(const th_state *s, const char *out)
{
	study_out o;
	char name[64];
	state_part parts[6];
	int p, bad = 0;
	snprintf(name, sizeof name, "threshold-state-%d-of-%d.bin", s->cfg.shard_k, s->cfg.shard_n);
	if (study_mkdir_p(out) != 0 || study_out_open(&o, out, name) != 0)
		return -1;
	bad |= fwrite(&s->cfg, sizeof s->cfg, 1, o.f) != 1;
	for (p = 0; p < PREC_COUNT; p++)
		if (s->cfg.prec_on[p])
			bad |= state_file_parts(o.f, parts, th_parts(s, p, parts), 1) != 0;
	if (bad) {
		study_error("%s: write failed", o.path);
		study_out_abort(&o);
		return -1;
	}
	if (study_out_commit(&o) != 0)
		return -1;
	fprintf(stderr, "onbstudy: shard %d of %d saved to %s/%s; combine with 'onbstudy merge'\n",
	        s->cfg.shard_k, s->cfg.shard_n, out, name);
	return 0;
}

static int th_load(th_state *s, const char *path)
{
	FILE *f;
	state_part parts[6];
	int p, bad = 0;
	memset(s, 0, sizeof *s);
	if (!(f = state_file_open(path, &s->cfg, sizeof s->cfg, TH_MAGIC, "threshold state file")))
		return -1;
	bad = s->cfg.shard_n < 1 || s->cfg.shard_n > 1000000 || s->cfg.shard_k < 0 || s->cfg.shard_k >= s->cfg.shard_n;
	for (p = 0; p < PREC_COUNT && !bad; p++) {
		if (!s->cfg.prec_on[p])
			continue;
		if (s->cfg.count[p] < 1 || s->cfg.count[p] > (1 << 26)) { bad = 1; break; }
		if (th_alloc(s, p, s->cfg.count[p]) != 0) { bad = 1; break; }
		bad |= state_file_parts(f, parts, th_parts(s, p, parts), 0) != 0;
	}
	if (state_file_end(f, path, bad, "truncated or corrupt threshold state") != 0) {
		th_free(s);
		return -1;
	}
	return 0;
}

int threshold_is_state(const char *path)
{
	char m[24] = { 0 };
	FILE *f = fopen(path, "rb");
	int r;
	if (!f)
		return 0;
	r = fread(m, 1, sizeof m, f) == sizeof m && strncmp(m, TH_MAGIC, sizeof m) == 0;
	fclose(f);
	return r;
}

int threshold_merge(int nfiles, char **files, const char *out, int threads)
{
	th_state acc, one;
	int i, p, j, rc, nmiss = 0;
	unsigned char *seen;
	char miss[256];
	if (th_load(&acc, files[0]) != 0)
		return ONB_EXIT_USAGE;
	if (!(seen = calloc((size_t)acc.cfg.shard_n, 1))) {
		study_error("out of memory");
		th_free(&acc);
		return 1;
	}
	seen[acc.cfg.shard_k] = 1;
	for (i = 1; i < nfiles; i++) {
		th_cfg a, b;
		if (th_load(&one, files[i]) != 0) { th_free(&acc); return ONB_EXIT_USAGE; }
		a = acc.cfg; b = one.cfg;
		a.shard_k = b.shard_k = 0;
		if (memcmp(&a, &b, sizeof a) != 0) {
			study_error("%s: from a different threshold run", files[i]);
			th_free(&acc); th_free(&one); free(seen);
			return ONB_EXIT_USAGE;
		}
		seen[one.cfg.shard_k] = 1;
		for (p = 0; p < PREC_COUNT; p++)
			if (acc.cfg.prec_on[p])
				for (j = 0; j < acc.cfg.count[p]; j++)
					if (one.done[p][j]) {
						if (acc.done[p][j]) {
							study_error("%s: overlaps another shard", files[i]);
							th_free(&acc); th_free(&one); free(seen);
							return ONB_EXIT_USAGE;
						}
						acc.done[p][j] = 1;
						acc.fn[p][j] = one.fn[p][j]; acc.fo[p][j] = one.fo[p][j];
						acc.bn[p][j] = one.bn[p][j]; acc.bo[p][j] = one.bo[p][j];
					}
		th_free(&one);
	}
	for (i = 0; i < acc.cfg.shard_n; i++)
		nmiss += !seen[i];
	study_missing_shards(seen, acc.cfg.shard_n, miss, sizeof miss);
	free(seen);
	for (p = 0; p < PREC_COUNT; p++)
		if (acc.cfg.prec_on[p])
			for (j = 0; j < acc.cfg.count[p]; j++)
				if (!acc.done[p][j]) {
					if (nmiss)
						study_error("%d of %d threshold shards missing (0-based K of --shard K/%d): %s", nmiss,
						            acc.cfg.shard_n, acc.cfg.shard_n, miss);
					else
						study_error("shards missing: input %d of %s was computed by none", j, prec_name(p));
					th_free(&acc);
					return ONB_EXIT_USAGE;
				}
	acc.cfg.shard_k = 0;
	acc.cfg.shard_n = 1;
	rc = th_write(&acc, out, threads);
	th_free(&acc);
	return rc ? 1 : 0;
}

static void usage(FILE *f)
{
	fprintf(f, "usage: onbstudy threshold [--precision float|double|both|half|all] [--consecutive C]\n"
	           "        [--logspaced M] [--azimuths A] [--seed S] [--threads T] [--out DIR] [--shard K/N]\n"
	           "Nelson Max's analysis of Frisvad's threshold: for each t near -1, the largest\n"
	           "normality and orthogonality error of Listing 2 with that t over inputs near -z;\n"
	           "the minimax t of each criterion, the published thresholds beside them, and\n"
	           "threshold.csv for plotting (default C = 4096, M = 8192, A = 64), written into\n"
	           "the current run (results/latest) unless --out DIR names another.\n"
	           "--shard K/N runs slice K of N (0-based, 0 <= K < N) and saves a state for\n"
	           "'onbstudy merge'.  Options take '--opt value' or '--opt=value'.\n"
	           "--precision half (or all) adds binary16: libonb's onb_frisvad_thresholdh, each\n"
	           "operation rounded to binary16 (a build whose compiler has _Float16).\n");
}

/* One option into the plan; 0 or -1 after a message. */
static int th_option(th_state *s, int v, const char *a, int *threads, const char **out)
{
	long l;
	unsigned long long u;
	switch (v) {
	case 'p': return cli_precision_half("--precision", a, s->cfg.prec_on);
	case 'c': if (parse_int("--consecutive", a, 2, 1 << 24, &l)) return -1; s->cfg.consecutive = (int)l; return 0;
	case 'l': if (parse_int("--logspaced", a, 0, 1 << 24, &l)) return -1; s->cfg.logspaced = (int)l; return 0;
	case 'a': if (parse_int("--azimuths", a, 1, 4096, &l)) return -1; s->cfg.azimuths = (int)l; return 0;
	case 's': if (parse_u64("--seed", a, 0, UINT64_MAX, &u)) return -1; s->cfg.seed = u; return 0;
	case 't': if (parse_int("--threads", a, 0, 1024, &l)) return -1; *threads = (int)l; return 0;
	case 'o': *out = a; return 0;
	case 'k': return cli_shard("--shard", a, &s->cfg.shard_k, &s->cfg.shard_n);
	}
	return -1;
}

/* Options -> the plan (s->cfg), threads and output directory.  0; 1 after
   --help; or ONB_EXIT_USAGE after a message. */
static int th_parse(th_state *s, int argc, char **argv, int *threads, char *outbuf, size_t outlen)
{
	static const struct option lo[] = {
		{ "precision", required_argument, NULL, 'p' }, { "consecutive", required_argument, NULL, 'c' },
		{ "logspaced", required_argument, NULL, 'l' }, { "azimuths", required_argument, NULL, 'a' },
		{ "seed", required_argument, NULL, 's' }, { "threads", required_argument, NULL, 't' },
		{ "out", required_argument, NULL, 'o' }, { "shard", required_argument, NULL, 'k' },
		CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
	};
	const char *out = NULL;
	cli_args c;
	int v, rc = 0;
	memset(s, 0, sizeof *s);
	snprintf(s->cfg.magic, sizeof s->cfg.magic, "%s", TH_MAGIC);
	s->cfg.seed = 1; s->cfg.prec_on[0] = s->cfg.prec_on[1] = 1;
	s->cfg.consecutive = 4096; s->cfg.logspaced = 8192; s->cfg.azimuths = 64; s->cfg.ref_bits = 127;
	s->cfg.shard_k = 0; s->cfg.shard_n = 1;
	*threads = 0;
	if (cli_begin(&c, "threshold", argc, argv))
		return 1;
	while (rc == 0 && (v = cli_next(&c, lo)) != -1) {
		if (v == CLI_HELP) { usage(stdout); rc = 1; }
		else if (v == CLI_ERROR || th_option(s, v, c.arg, threads, &out) != 0) rc = ONB_EXIT_USAGE;
	}
	if (rc == 0 && cli_no_rest(&c) != 0)
		rc = ONB_EXIT_USAGE;
	cli_end(&c);
#ifdef _OPENMP
	if (!*threads) *threads = omp_get_num_procs();
#else
	*threads = 1;
#endif
	if (out) snprintf(outbuf, outlen, "%s", out);
	else if (rc == 0) study_current_run_dir(outbuf, outlen); /* the run of results/latest */
	return rc;
}

/* Run every value of this shard; 0, or -1 (out of memory, after a message). */
static int th_run(th_state *s, int threads)
{
	int p, fail = 0;
	for (p = 0; p < PREC_COUNT; p++) {
		int j;
		if (!s->cfg.prec_on[p])
			continue;
		if (build_values(s, p) != 0)
			return -1;
#pragma omp parallel num_threads(threads) reduction(|:fail)
		{
			ref_ctx *rc = ref_new(s->cfg.ref_bits);
			if (!rc) fail = 1;
#pragma omp for schedule(dynamic, 16)
			for (j = 0; j < s->cfg.count[p]; j++)
				if (rc && j % s->cfg.shard_n == s->cfg.shard_k)
					measure(s, rc, p, j);
			ref_free(rc);
		}
	}
	if (fail)
		study_error("out of memory");
	return fail ? -1 : 0;
}

int cmd_threshold(int argc, char **argv)
{
	th_state s;
	char outbuf[4096];
	int threads, rc = th_parse(&s, argc, argv, &threads, outbuf, sizeof outbuf);
	if (rc != 0)
		return rc == 1 ? 0 : rc;
	if (study_mkdir_p(outbuf) != 0)
		return ONB_EXIT_USAGE;
	if (th_run(&s, threads) != 0) {
		th_free(&s);
		return 1;
	}
	if (s.cfg.shard_n > 1)
		rc = th_save(&s, outbuf);
	else
		rc = th_write(&s, outbuf, threads);
	th_free(&s);
	return rc ? 1 : 0;
}
