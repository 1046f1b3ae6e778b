/*
 * writers.c - the sweep's output files, from a const state (the
 * worst-case walk that comes before them is the engine's): summary.csv,
 * by_nz.csv, worst.csv, grid.csv, reference.csv, and the table on stdout.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <errno.h>
#include <unistd.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "sweep/writers.h"
#include "sweep/state.h"
#include "common/options.h"
#include "common/output.h"


/* Precision p was run, and kernel k has code in it (not a float-only
   method in double): the (p, k) pairs every file and table lists. */
static int on(const sweep_state *s, int p, int k)
{
	return s->cfg.prec_on[p] && kernel_runs(&s->kernels[k], p);
}

/* fn on every cell that ran, in the order of every file's rows:
   precision, then method, then distribution. */
typedef void (*cell_fn)(FILE *f, const sweep_state *s, int p, int k, int d, void *arg);
static void each_cell(FILE *f, const sweep_state *s, cell_fn fn, void *arg)
{
	int p, k, d;
	for (p = 0; p < SWEEP_NPREC; p++)
		for (k = 0; k < s->cfg.nk; k++)
			for (d = 0; d < NDIST; d++)
				if (on(s, p, k) && s->cfg.dist_on[d])
					fn(f, s, p, k, d, arg);
}

static double grid_jump(const sweep_state *s, int p, int k, size_t cell)
{
	const size_t rows = (size_t)s->cfg.grid_rows, cols = (size_t)s->cfg.grid_cols;
	const size_t r = cell / cols, c = cell % cols;
	const double *a = &s->g_b1[3 * sweep_grid_index(s, p, k, cell)];
	size_t nb[2];
	int i, m = 0;
	double jump = 0.0;
	nb[m++] = r * cols + (c + 1) % cols;
	if (r + 1 < rows)
		nb[m++] = (r + 1) * cols + c;
	for (i = 0; i < m; i++) {
		const double *b = &s->g_b1[3 * sweep_grid_index(s, p, k, nb[i])];
		const double d = sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
		if (isnan(d))
			return NAN;
		if (d > jump)
			jump = d;
	}
	return jump;
}

static double max_grid_jump(const sweep_state *s, int p, int k)
{
	size_t i;
	double m = 0.0;
	if (!s->kernels[k].m)
		return NAN;
	for (i = 0; i < sweep_grid_cells(s); i++) {
		const double j = grid_jump(s, p, k, i);
		if (isnan(j))
			return NAN;
		if (j > m)
			m = j;
	}
	return m;
}

/* ---- files ---------------------------------------------------------------- */

void sweep_print_reference(FILE *f, const sweep_state *s, const char *prefix, int per_method)
{
	unsigned long long ev = 0, fb = 0, wr = 0;
	int p, k;
	for (p = 0; p < SWEEP_NPREC; p++)
		for (k = 0; k < s->cfg.nk; k++) {
			ev += s->cfg.ref_evals[p][k];
			fb += s->cfg.ref_fallback[p][k];
			wr += s->cfg.ref_worst[p][k];
		}
	if (s->cfg.ref_mpfr) {
		fprintf(f, "%sreference: MPFR only (--ref mpfr) for the sampled inputs\n", prefix);
		return;
	}
	fprintf(f, "%sreference: fast (reffast.c, certified double-long-double, byte-identical to --ref mpfr); "
	        "fell back to MPFR on %llu of %llu evaluations (%.4f%%)%s\n",
	        prefix, fb, ev, ev ? 100.0 * (double)fb / (double)ev : 0.0,
	        per_method ? "" : "; per method and precision in reference.csv");
	/* only in the log: the count depends on thread scheduling (see write_reference) */
	if (f == stderr)
		fprintf(f, "%sMPFR filled ref[] of %llu samples kept among the worst (a count that depends on thread scheduling)\n",
		        prefix, wr);
	if (!per_method)
		return;
	for (p = 0; p < SWEEP_NPREC; p++)
		for (k = 0; k < s->cfg.nk; k++)
			if (s->cfg.ref_evals[p][k])
				fprintf(f, "%s  %-28s %-6s %12llu evaluations, fallback %.4f%%\n", prefix, s->kernels[k].name,
				        prec_name(p), (unsigned long long)s->cfg.ref_evals[p][k],
				        100.0 * (double)s->cfg.ref_fallback[p][k] / (double)s->cfg.ref_evals[p][k]);
}

static void header(FILE *f, const sweep_state *s, int threads, double seconds, int partial)
{
	int p, d;
	study_provenance(f, "sweep", s->cfg.seed, threads);
	fprintf(f, "# mpfr precision: %d bits (never the default); reference re-evaluated at %d bits on %llu inputs, all agreeing to 2^-40\n",
	        s->cfg.ref_bits, s->cfg.ref_bits + 64, (unsigned long long)s->cfg.checked);
	fprintf(f, "# inputs:");
	for (p = 0; p < SWEEP_NPREC; p++)
		for (d = 0; d < NDIST; d++)
			if (s->cfg.prec_on[p] && s->cfg.dist_on[d])
				fprintf(f, " %s/%s=%llu", prec_name(p), dist_name(d), (unsigned long long)s->cfg.counts[p][d]);
	fprintf(f, "\n# exhaustive: %llu consecutive n.z from %a, %d azimuths; grid: %dx%d equal-area cells\n",
	        (unsigned long long)s->cfg.ex_values, s->cfg.ex_from, s->cfg.ex_azimuths, s->cfg.grid_rows, s->cfg.grid_cols);
	if (seconds > 0)
		fprintf(f, "# rate: %llu referenced evaluations in %.2f s = %.0f per second on %d threads (%.0f per thread)\n",
		        (unsigned long long)s->cfg.evals, seconds, (double)s->cfg.evals / seconds, threads,
		        (double)s->cfg.evals / seconds / threads);
	sweep_print_reference(f, s, "# ", 0);
	if (s->cfg.shard_n > 1)
		fprintf(f, "# shard: %d of %d\n", s->cfg.shard_k, s->cfg.shard_n);
	if (partial)
		fprintf(f, "# PARTIAL: the run was interrupted; these figures cover only the inputs done before the signal\n");
}

/* The stratified estimate of the mean of quantity q (Q_*) over the cell's
   finite inputs, each stratum with its exact weight (inputs.h), and the
   half-width of its 95% interval (normal, from the strata variances:
   var = sum w_h^2 s_h^2 / n_h).  Strata with no input are left out and the
   weights renormalized.  One stratum of weight 1 gives the plain mean. */
static double st_mean(const cell_t *c, int d, int q, double *hw)
{
	double W = 0.0, m = 0.0, v = 0.0;
	int h;
	for (h = 0; h < NSTRAT; h++) {
		const stratum_t *t = &c->st[h];
		const double w = dist_stratum_weight(d, h), n = (double)t->n;
		double mh, vh;
		if (!t->n || w == 0.0)
			continue;
		mh = fx_value(&t->s[q]) / n;
		vh = t->n > 1 ? fmax(0.0, fx_value(&t->s2[q]) / n - mh * mh) * n / (n - 1.0) : 0.0;
		W += w; m += w * mh; v += w * w * vh / n;
	}
	*hw = W > 0.0 ? 1.96 * sqrt(v) / W : NAN;
	return W > 0.0 ? m / W : NAN;
}
/* The same for mean_bits = bits / components, a ratio per stratum
   (variance of x - R y, the delta method) */
static double st_bits(const cell_t *c, int d, double *hw)
{
	double W = 0.0, m = 0.0, v = 0.0;
	int h;
	for (h = 0; h < NSTRAT; h++) {
		const stratum_t *t = &c->st[h];
		const double w = dist_stratum_weight(d, h), n = (double)t->n, y = (double)t->by;
		double r, vh;
		if (!t->n || !t->by || w == 0.0)
			continue;
		r = fx_value(&t->bx) / y;
		vh = fmax(0.0, fx_value(&t->bx2) - 2.0 * r * fx_value(&t->bxy) + r * r * (double)t->by2);
		vh = t->n > 1 ? vh / (n - 1.0) / ((y / n) * (y / n)) : 0.0;
		W += w; m += w * r; v += w * w * vh / n;
	}
	*hw = W > 0.0 ? 1.96 * sqrt(v) / W : NAN;
	return W > 0.0 ? m / W : NAN;
}
/* root of a stratified mean, with the interval's ends as roots too */
static double st_root(const cell_t *c, int d, int q, double *lo, double *hi)
{
	double hw, m = st_mean(c, d, q, &hw);
	*lo = sqrt(fmax(0.0, m - hw));
	*hi = sqrt(m + hw);
	return sqrt(m);
}

static double st_rmse(const cell_t *c, int d)
{
	double lo, hi;
	return st_root(c, d, Q_SQ, &lo, &hi);
}

/* The floor's columns of a summary row: the floor's max and
   RMS, its direction error's max, and the ratio of the method's per-input
   error to it (reference.c floor_eval): max, RMS, the share of inputs at
   or below the floor (ratio <= 1), and the input of the largest ratio as
   hex floats.  The RMS and the share are stratified like st_mean: each
   over its own inputs per stratum, strata with none left out and the
   weights renormalized (one stratum of weight 1: the plain mean). */
enum { F_FLOOR2, F_RATIO2, F_AT };
static double fl_mean(const cell_t *c, int d, int q)
{
	double W = 0.0, m = 0.0;
	int h;
	for (h = 0; h < NSTRAT; h++) {
		const fstrat_t *t = &c->fst[h];
		const uint64_t n = q == F_FLOOR2 ? t->fn : t->rn;
		const double w = dist_stratum_weight(d, h);
		const double x = q == F_FLOOR2 ? fx_value(&t->f2) : q == F_RATIO2 ? fx_value(&t->r2) : (double)t->rat;
		if (!n || w == 0.0)
			continue;
		W += w; m += w * (x / (double)n);
	}
	return W > 0.0 ? m / W : NAN;
}

static void floor_cols(FILE *f, const cell_t *c, int d)
{
	const int some = c->ratio_idx != UINT64_MAX;
	fprintf(f, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,", c->floor_n ? c->max_floor : NAN, sqrt(fl_mean(c, d, F_FLOOR2)),
	        c->floor_n ? c->max_floor_dir : NAN, some ? c->max_ratio : NAN,
	        sqrt(fl_mean(c, d, F_RATIO2)), fl_mean(c, d, F_AT));
	if (some)
		fprintf(f, "%a,%a,%a,", c->ratio_in[0], c->ratio_in[1], c->ratio_in[2]);
	else
		fprintf(f, "nan,nan,nan,");
}

static void summary_row(FILE *f, const sweep_state *s, int p, int d, int k, double jump)
{
	const cell_t *c = sweep_cell_at(s, p, d, k);
	const int basis = s->kernels[k].m != NULL;
	const double nan = NAN;
	double r[4], lo[4], hi[4], bits, bhw;
	int q;
	for (q = 0; q < 4; q++)
		r[q] = st_root(c, d, q == 0 ? Q_SQ : q == 1 ? Q_DEF2 : q == 2 ? Q_DIRC2 : Q_DUFF, &lo[q], &hi[q]);
	if (!basis)
		r[0] = lo[0] = hi[0] = r[1] = lo[1] = hi[1] = r[3] = lo[3] = hi[3] = nan;
	bits = st_bits(c, d, &bhw);
	fprintf(f, "%s,%s,%s,%llu,%.6g,%.6g,%.6g,%.6g,%llu,%llu,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,",
	        s->kernels[k].name, prec_name(p), dist_name(d), (unsigned long long)c->count,
	        r[0], basis ? (c->finite ? c->max_defect : nan) : nan,
	        c->finite ? c->max_ulp : nan, bits,
	        (unsigned long long)c->wrong, (unsigned long long)c->nonfinite, r[1],
	        c->finite ? c->max_abs_eps : nan, c->finite ? c->max_bits : nan, c->max_in_norm,
	        c->finite ? c->max_dir_norm : nan, c->finite ? c->max_dir_cos : nan,
	        r[2], jump, r[3], basis && c->finite ? c->max_duff_rms : nan);
	floor_cols(f, c, d);
	fprintf(f, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n",
	        lo[0], hi[0], lo[1], hi[1], bits - bhw, bits + bhw, lo[2], hi[2], lo[3], hi[3]);
}

/* reference.csv: the fast reference's fallback rate per method and precision. */
static void reference_body(FILE *f, const sweep_state *s, int partial)
{
	int p, k;
	(void)partial; /* the writers' common signature */
	/* The count of worst rows whose ref[] MPFR filled in is not written here:
	   it depends on which chunks each thread saw first (thread scheduling),
	   and a data file holds only figures that identical runs reproduce.  The
	   log line (sweep_print_reference) gives it, marked as such. */
	fprintf(f, "# per method and precision: referenced evaluations of the sampled inputs, and those the fast reference could not decide (MPFR computed them)\n");
	fprintf(f, "method,precision,evaluations,mpfr_fallback,fallback_rate\n");
	for (p = 0; p < SWEEP_NPREC; p++)
		for (k = 0; k < s->cfg.nk; k++)
			if (s->cfg.ref_evals[p][k])
				fprintf(f, "%s,%s,%llu,%llu,%.6g\n", s->kernels[k].name, prec_name(p),
				        (unsigned long long)s->cfg.ref_evals[p][k], (unsigned long long)s->cfg.ref_fallback[p][k],
				        (double)s->cfg.ref_fallback[p][k] / (double)s->cfg.ref_evals[p][k]);
}

#define SUMMARY_COLUMNS "method,precision,distribution,samples,rmse,max_defect,max_ulp,mean_bits,wrong_handed,nonfinite," \
	"rms_defect,max_abs_eps,max_bits,max_input_norm,max_dir_norm,max_dir_cos,rms_dir_cos,max_b1_jump,duff_rms,max_duff_rms," \
	"max_floor,rms_floor,max_floor_dir,max_floor_ratio,rms_floor_ratio,at_floor,floor_ratio_nx,floor_ratio_ny,floor_ratio_nz," \
	"rmse_lo,rmse_hi,rms_defect_lo,rms_defect_hi,mean_bits_lo,mean_bits_hi,rms_dir_cos_lo,rms_dir_cos_hi,duff_rms_lo,duff_rms_hi"

/* arg: the writer's partial flag (a partial state's grid has no jumps yet) */
static void summary_cell(FILE *f, const sweep_state *s, int p, int k, int d, void *arg)
{
	const int partial = *(const int *)arg;
	summary_row(f, s, p, d, k, d == DIST_GRID && !partial ? max_grid_jump(s, p, k) : NAN);
}

static void summary_body(FILE *f, const sweep_state *s, int partial)
{
	fprintf(f, "# rmse: Frisvad 2012 Table 1, over |b1|-1, |b2|-1, b1.n, b2.n, b1.b2; rms_defect and max_defect: the per-input error max_k |.|; duff_rms, max_duff_rms: Duff et al. 2017 footnote 1, the per-input RMS of |n|-1, |b1|-1, |b2|-1, n.b1, b1.b2, b2.n (root of the mean over inputs; largest)\n");
	fprintf(f, "# max_ulp: forward error in ulps of the exact value of the method's own formula, components with |exact| >= eps; max_abs_eps: absolute forward error / eps; bits: Herbie's log2(distance in floats + 1)\n");
	fprintf(f, "# max_dir_norm, max_dir_cos: | |w|-1 | and | w.n - z | for w = x b1 + y b2 + z n (frisvad_rotate: Frisvad 2012 Eq. 3); max_b1_jump: largest |b1 - b1'| between neighbouring grid cells\n");
	fprintf(f, "# max_floor, rms_floor: the accuracy floor, the per-input error (defect; frisvad_rotate: direction error) of the method's exact formula on its branch rounded once to the format; max_floor_dir: its direction error; max_floor_ratio, rms_floor_ratio: the per-input ratio max(error, u^2) / max(floor, u^2), u = 2^-24 or 2^-53; at_floor: the share of inputs with ratio <= 1; floor_ratio_n*: the input of the largest ratio\n");
	fprintf(f, "# rmse, rms_defect, mean_bits, rms_dir_cos, duff_rms: estimates over the inputs; uniform is stratified in 1 + n.z (%d strata, finer towards -z, input i in stratum i mod %d) and combined with each stratum's exact probability; *_lo, *_hi: 95%% interval from the strata variances (normal; roots of the interval of the mean square for the RMS columns); rms_floor, rms_floor_ratio, at_floor: estimated the same way (stratified, each over its own inputs: floor finite; for the ratio, the method's output finite too)\n", NSTRAT, NSTRAT);
	fprintf(f, "%s\n", SUMMARY_COLUMNS);
	each_cell(f, s, summary_cell, &partial);
}

static void by_nz_cell(FILE *f, const sweep_state *s, int p, int k, int d, void *arg)
{
	const cell_t *c = sweep_cell_at(s, p, d, k);
	int b;
	(void)arg;
	/* threshold and grid are lists, not distributions over n.z: their
	   errors are in worst.csv and grid.csv */
	if (d == DIST_THRESHOLD || d == DIST_GRID)
		return;
	for (b = 0; b < NBINS; b++) {
		const bin_t *x = &c->bins[b];
		const char *axis;
		double lo, hi;
		if (!x->count)
			continue;
		if (b < NB_NZ) {
			axis = "nz"; lo = -1.0 + 2.0 * b / NB_NZ; hi = -1.0 + 2.0 * (b + 1) / NB_NZ;
		} else if (b < NB_NZ + NB_LOG) {
			axis = "log10_1pnz"; lo = -17.0 + 0.25 * (b - NB_NZ); hi = lo + 0.25;
		} else if (b < NB_NZ + NB_LOG + NB_NORM) {
			axis = "log10_absnorm"; lo = -9.0 + 0.25 * (b - NB_NZ - NB_LOG); hi = lo + 0.25;
		} else {
			axis = "log10_1mnz"; lo = -17.0 + 0.25 * (b - NB_NZ - NB_LOG - NB_NORM); hi = lo + 0.25;
		}
		fprintf(f, "%s,%s,%s,%s,%.6g,%.6g,%llu,%.4g,%.4g,%.4g,%.4g\n", s->kernels[k].name, prec_name(p),
		        dist_name(d), axis, lo, hi, (unsigned long long)x->count,
		        sqrt(fx_value(&x->sumsq) / (double)x->count), x->max,
		        x->fcount ? sqrt(fx_value(&x->fsumsq) / (double)x->fcount) : NAN, x->fcount ? x->fmax : NAN);
	}
}

static void by_nz_body(FILE *f, const sweep_state *s, int partial)
{
	(void)partial; /* the writers' common signature */
	fprintf(f, "# the per-input error (max_defect's, or | |w|-1 |, | w.n-z | for frisvad_rotate) binned by n.z, by log10(1 + n.z) for n.z <= 0, by log10| |n| - 1 |, and by log10(1 - n.z) for n.z >= 0 (axis log10_1mnz); empty bins omitted; lo and hi bound the bin; threshold and grid (lists, not distributions) are in worst.csv and grid.csv\n");
	fprintf(f, "# floor_rms, floor_max: the accuracy floor of the same inputs (the method's exact formula rounded once)\n");
	fprintf(f, "method,precision,distribution,axis,lo,hi,count,rms,max,floor_rms,floor_max\n");
	each_cell(f, s, by_nz_cell, NULL);
}

static void worst_cell(FILE *f, const sweep_state *s, int p, int k, int d, void *arg)
{
	const cell_t *c = sweep_cell_at(s, p, d, k);
	int i, j;
	(void)arg;
	for (i = 0; i < NWORST; i++) {
		const worst_t *w = &c->worst[i];
		if (w->index == UINT64_MAX)
			continue;
		fprintf(f, "%s,%s,%s,%d,%s,%llu,%d,%.6g,%.6g,%.6g", s->kernels[k].name, prec_name(p),
		        dist_name(d), i + 1, w->source ? "walk" : "sample", (unsigned long long)w->index,
		        w->branch, w->key, w->ulp, w->bits_max);
		for (j = 0; j < 3; j++)
			fprintf(f, ",%a", w->n[j]);
		for (j = 0; j < 6; j++)
			fprintf(f, ",%a", w->out[j]);
		for (j = 0; j < 6; j++)
			fprintf(f, ",%a", w->ref[j]);
		fputc('\n', f);
	}
}

static void worst_body(FILE *f, const sweep_state *s, int partial)
{
	(void)partial; /* the writers' common signature */
	fprintf(f, "# the %d worst inputs per method, precision and distribution; source: sample, or walk (found by walking neighbouring floats from the worst sampled threshold inputs); index: the input's index (for walk: the start's)\n", NWORST);
	fprintf(f, "# error: the per-input defect (frisvad_rotate: max(| |w|-1 |, | w.n-z |)); inputs and outputs as C99 hex floats; ref: the method's exact formula on the same branch, rounded to double\n");
	fprintf(f, "method,precision,distribution,rank,source,index,branch,error,max_ulp,max_bits,nx,ny,nz,b1x,b1y,b1z,b2x,b2y,b2z,ref_b1x,ref_b1y,ref_b1z,ref_b2x,ref_b2y,ref_b2z\n");
	each_cell(f, s, worst_cell, NULL);
}

static void grid_body(FILE *f, const sweep_state *s, int partial)
{
	int p, k;
	size_t i;
	fprintf(f, "# equal-area grid: row r has n.z in [-1 + 2r/rows, -1 + 2(r+1)/rows], col c has azimuth in [2 pi c/cols, 2 pi (c+1)/cols]; inputs at cell centres\n");
	fprintf(f, "# error: the per-input defect (frisvad_rotate: direction error); b1_jump: max |b1 - b1'| to the next cell in azimuth and in n.z\n");
	fprintf(f, "method,precision,row,col,nz,phi,error,mean_bits,b1_jump\n");
	for (p = 0; p < SWEEP_NPREC; p++)
		for (k = 0; k < s->cfg.nk; k++) {
			if (!on(s, p, k))
				continue;
			for (i = 0; i < sweep_grid_cells(s); i++) {
				const size_t j = sweep_grid_index(s, p, k, i);
				const size_t r = i / (size_t)s->cfg.grid_cols, c = i % (size_t)s->cfg.grid_cols;
				if (!sweep_grid_done(s, p, i))
					continue;
				fprintf(f, "%s,%s,%zu,%zu,%.4g,%.4g,%.3g,%.3g,%.3g\n", s->kernels[k].name, prec_name(p), r, c,
				        -1.0 + 2.0 * ((double)r + 0.5) / s->cfg.grid_rows,
				        6.283185307179586 * ((double)c + 0.5) / s->cfg.grid_cols,
				        s->g_err[j], s->g_bits[j], s->kernels[k].m && !partial ? grid_jump(s, p, k, i) : NAN);
			}
		}
}

/* ---- stdout ---------------------------------------------------------------- */

static void print_table(const sweep_state *s)
{
	int p, k, d;
	printf("%-28s %-6s %10s", "method", "prec", "rmse(uni)");
	for (d = 0; d < NDIST; d++)
		if (s->cfg.dist_on[d])
			printf(" %11.11s", dist_name(d));
	printf(" %9s %7s %6s\n", "ulp(uni)", "nonfin", "wrong");
	printf("%-28s %-6s %10s", "", "", "");
	for (d = 0; d < NDIST; d++)
		if (s->cfg.dist_on[d])
			printf(" %11s", "max err");
	printf("\n");
	for (p = 0; p < SWEEP_NPREC; p++) {
		if (!s->cfg.prec_on[p])
			continue;
		for (k = 0; k < s->cfg.nk; k++) {
			const cell_t *u = sweep_cell_at(s, p, DIST_UNIFORM, k);
			uint64_t nf = 0, wr = 0;
			const int basis = s->kernels[k].m != NULL;
			if (!on(s, p, k))
				continue;
			printf("%-28s %-6s", s->kernels[k].name, prec_name(p));
			if (basis && s->cfg.dist_on[DIST_UNIFORM])
				printf(" %10.3g", st_rmse(u, DIST_UNIFORM));
			else
				printf(" %10s", "n/a"); /* no basis (frisvad_rotate), or no uniform run */
			for (d = 0; d < NDIST; d++) {
				const cell_t *c = sweep_cell_at(s, p, d, k);
				if (!s->cfg.dist_on[d])
					continue;
				nf += c->nonfinite;
				wr += c->wrong;
				if (c->nonfinite)
					printf(" %11s", "NaN/Inf");
				else
					printf(" %11.3g", basis ? c->max_defect : fmax(c->max_dir_norm, c->max_dir_cos));
			}
			printf(" %9.3g %7llu %6llu\n", s->cfg.dist_on[DIST_UNIFORM] ? u->max_ulp : NAN,
			       (unsigned long long)nf, (unsigned long long)wr);
		}
	}
	printf("max err: the largest per-input orthonormality defect (frisvad_rotate: direction error); NaN/Inf: some output was not finite\n");
}

/* arg: 1 until the first object is out (the separator goes before the rest) */
static void json_cell(FILE *f, const sweep_state *s, int p, int k, int d, void *arg)
{
	const cell_t *c = sweep_cell_at(s, p, d, k);
	int *first = arg;
	const int basis = s->kernels[k].m != NULL;
	const double rmse = basis ? st_rmse(c, d) : NAN;
	const double mx = basis ? c->max_defect : NAN;
	fprintf(f, "%s  {\"method\": \"%s\", \"precision\": \"%s\", \"distribution\": \"%s\", \"samples\": %llu, ",
	        *first ? "" : ",\n", s->kernels[k].name, prec_name(p), dist_name(d), (unsigned long long)c->count);
	if (isfinite(rmse)) fprintf(f, "\"rmse\": %.6g, ", rmse); else fprintf(f, "\"rmse\": null, ");
	if (isfinite(mx) && c->finite) fprintf(f, "\"max_defect\": %.6g, ", mx); else fprintf(f, "\"max_defect\": null, ");
	fprintf(f, "\"max_ulp\": %.6g, \"mean_bits\": %.6g, \"wrong_handed\": %llu, \"nonfinite\": %llu}",
	        c->finite ? c->max_ulp : 0.0, c->comps ? fx_value(&c->bits) / (double)c->comps : 0.0,
	        (unsigned long long)c->wrong, (unsigned long long)c->nonfinite);
	*first = 0;
}

static void print_csv(const sweep_state *s, int json)
{
	int first = 1, partial = 1;   /* no grid jumps on stdout */
	if (json) {
		printf("[\n");
		each_cell(stdout, s, json_cell, &first);
		printf("\n]\n");
	} else {
		printf("%s\n", SUMMARY_COLUMNS);
		each_cell(stdout, s, summary_cell, &partial);
	}
}

/* The files: each a header (provenance), then its body; the .partial.csv
   name for an interrupted run.  In this order; grid.csv only with the grid
   distribution, reference.csv only with the fast reference. */
typedef struct {
	const char *base;
	int (*wanted)(const sweep_state *s);                      /* NULL: always */
	void (*body)(FILE *f, const sweep_state *s, int partial);
} writer;

static int has_grid(const sweep_state *s) { return s->cfg.dist_on[DIST_GRID]; }
static int has_fast_ref(const sweep_state *s) { return !s->cfg.ref_mpfr; }

static const writer writers[] = {
	{ "summary", NULL, summary_body }, { "by_nz", NULL, by_nz_body }, { "worst", NULL, worst_body },
	{ "grid", has_grid, grid_body }, { "reference", has_fast_ref, reference_body },
};

static int write_one(const writer *w, const sweep_state *s, const char *dir, int threads, double sec, int partial)
{
	char name[64];
	study_out o;
	snprintf(name, sizeof name, "%s%s.csv", w->base, partial ? ".partial" : "");
	if (study_out_open(&o, dir, name) != 0)
		return -1;
	header(o.f, s, threads, sec, partial);
	w->body(o.f, s, partial);
	return study_out_commit(&o);
}

int sweep_finish(const sweep_state *s, const char *outdir, int threads, const char *fmt, double seconds, int partial)
{
	size_t i;
	int rc = 0;
	if (study_mkdir_p(outdir) != 0)
		return -1;
	for (i = 0; i < sizeof writers / sizeof writers[0]; i++)
		if (!writers[i].wanted || writers[i].wanted(s))
			rc |= write_one(&writers[i], s, outdir, threads, seconds, partial);
	if (rc)
		return -1;
	if (partial)
		return 0; /* the partial files say what was done; no table of half a run on stdout */
	if (!fmt || !strcmp(fmt, "table"))
		print_table(s);
	else
		print_csv(s, !strcmp(fmt, "json"));
	return 0;
}
