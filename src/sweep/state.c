/*
 * state.c - the sweep's accumulators, the grid layout, slices, merging and
 * the state files (sweep's and, through state_file_*, threshold's).
 *
 * Every accumulation here is exact or order-independent (integer counts,
 * fx sums, maxima, worst lists ordered by error then index), so the data
 * are the same bits for any thread count, and a merge of shards equals
 * the unsharded run.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include "sweep/state.h"
#include "common/options.h"
#include "common/output.h"

#define STATE_MAGIC "onbsweep-state5" /* 5: three precisions (binary16) */

/* The cells' layout, [prec][dist][kernel] (the slices' lo and hi count in it). */
static size_t cell_index(const sweep_state *s, int prec, int dist, int k)
{
	return ((size_t)prec * NDIST + (size_t)dist) * (size_t)s->cfg.nk + (size_t)k;
}

const cell_t *sweep_cell_at(const sweep_state *s, int prec, int dist, int k) { return &s->cells[cell_index(s, prec, dist, k)]; }
cell_t *sweep_cell(sweep_state *s, int prec, int dist, int k) { return &s->cells[cell_index(s, prec, dist, k)]; }

void cell_init(cell_t *c)
{
	int i;
	memset(c, 0, sizeof *c);
	for (i = 0; i < NWORST; i++) {
		c->worst[i].key = -1.0;
		c->worst[i].index = UINT64_MAX;
	}
	c->ratio_idx = UINT64_MAX;
	c->max_ratio = -1.0;
}

/* The largest ratio to the floor, ties to the smaller index, then the
   sampled input before the walked one: a total order, so merges agree. */
static int ratio_wins(double r, uint64_t idx, int src, const cell_t *c)
{
	if (c->ratio_idx == UINT64_MAX || r != c->max_ratio)
		return c->ratio_idx == UINT64_MAX || r > c->max_ratio;
	if (idx != c->ratio_idx)
		return idx < c->ratio_idx;
	return src < c->ratio_src;
}

/* a ranks before b: larger error first, then the smaller index, then
   sampled before walked (a total order, so merges are deterministic). */
static int worse(const worst_t *a, const worst_t *b)
{
	if (a->key != b->key)
		return a->key > b->key;
	if (a->index != b->index)
		return a->index < b->index;
	return a->source < b->source;
}

static void worst_insert(cell_t *c, const worst_t *w)
{
	int i;
	if (!worse(w, &c->worst[NWORST - 1]))
		return;
	for (i = 0; i < NWORST; i++)
		if (c->worst[i].index == w->index && c->worst[i].source == w->source && c->worst[i].key == w->key)
			return; /* already there */
	i = NWORST - 1;
	while (i > 0 && worse(w, &c->worst[i - 1])) {
		c->worst[i] = c->worst[i - 1];
		i--;
	}
	c->worst[i] = *w;
}

static double dmax(double a, double b) { return b > a ? b : a; }

static void stratum_merge(stratum_t *d, const stratum_t *s)
{
	int q;
	d->n += s->n; d->by += s->by; d->by2 += s->by2;
	for (q = 0; q < NQ; q++) { fx_add(&d->s[q], &s->s[q]); fx_add(&d->s2[q], &s->s2[q]); }
	fx_add(&d->bx, &s->bx); fx_add(&d->bx2, &s->bx2); fx_add(&d->bxy, &s->bxy);
}

/* One finite input into its stratum: the estimates' per-input quantities */
static void stratum_add(stratum_t *t, const sample_metrics *m)
{
	double q[NQ];
	int k;
	t->n++;
	q[Q_SQ] = m->has_basis ? m->sumsq / 5.0 : 0.0;
	q[Q_DEF2] = m->has_basis ? m->defect * m->defect : 0.0;
	q[Q_DIRC2] = m->dir_cos * m->dir_cos;
	q[Q_DUFF] = m->has_basis ? (m->in_norm * m->in_norm + m->sumsq) / 6.0 : 0.0;
	for (k = 0; k < NQ; k++) {
		fx_add_double(&t->s[k], q[k]);
		fx_add_double(&t->s2[k], q[k] * q[k]);
	}
	t->by += (uint64_t)m->nbits;
	t->by2 += (uint64_t)m->nbits * (uint64_t)m->nbits;
	fx_add_double(&t->bx, m->bits_sum);
	fx_add_double(&t->bx2, m->bits_sum * m->bits_sum);
	fx_add_double(&t->bxy, m->bits_sum * m->nbits);
}

static void fstrat_merge(fstrat_t *d, const fstrat_t *s)
{
	d->fn += s->fn; d->rn += s->rn; d->rat += s->rat;
	fx_add(&d->f2, &s->f2); fx_add(&d->r2, &s->r2);
}

void cell_merge(cell_t *d, const cell_t *s)
{
	int i;
	d->count += s->count; d->finite += s->finite; d->nonfinite += s->nonfinite;
	d->wrong += s->wrong; d->comps += s->comps;
	fx_add(&d->sumsq, &s->sumsq); fx_add(&d->sumdef2, &s->sumdef2); fx_add(&d->bits, &s->bits);
	fx_add(&d->dirn2, &s->dirn2); fx_add(&d->dirc2, &s->dirc2);
	d->max_defect = dmax(d->max_defect, s->max_defect);
	d->max_ulp = dmax(d->max_ulp, s->max_ulp);
	d->max_abs_eps = dmax(d->max_abs_eps, s->max_abs_eps);
	d->max_bits = dmax(d->max_bits, s->max_bits);
	d->max_in_norm = dmax(d->max_in_norm, s->max_in_norm);
	d->max_dir_norm = dmax(d->max_dir_norm, s->max_dir_norm);
	d->max_dir_cos = dmax(d->max_dir_cos, s->max_dir_cos);
	fx_add(&d->duffms, &s->duffms);
	d->max_duff_rms = dmax(d->max_duff_rms, s->max_duff_rms);
	for (i = 0; i < NSTRAT; i++) {
		stratum_merge(&d->st[i], &s->st[i]);
		fstrat_merge(&d->fst[i], &s->fst[i]);
	}
	for (i = 0; i < NWORST; i++)
		if (s->worst[i].index != UINT64_MAX)
			worst_insert(d, &s->worst[i]);
	for (i = 0; i < NBINS; i++) {
		d->bins[i].count += s->bins[i].count;
		fx_add(&d->bins[i].sumsq, &s->bins[i].sumsq);
		d->bins[i].max = dmax(d->bins[i].max, s->bins[i].max);
		d->bins[i].fcount += s->bins[i].fcount;
		fx_add(&d->bins[i].fsumsq, &s->bins[i].fsumsq);
		d->bins[i].fmax = dmax(d->bins[i].fmax, s->bins[i].fmax);
	}
	d->floor_n += s->floor_n; d->ratio_n += s->ratio_n; d->ratio_at += s->ratio_at;
	fx_add(&d->floor2, &s->floor2); fx_add(&d->ratio2, &s->ratio2);
	d->max_floor = dmax(d->max_floor, s->max_floor);
	d->max_floor_dir = dmax(d->max_floor_dir, s->max_floor_dir);
	if (s->ratio_idx != UINT64_MAX && ratio_wins(s->max_ratio, s->ratio_idx, s->ratio_src, d)) {
		d->max_ratio = s->max_ratio;
		d->ratio_idx = s->ratio_idx;
		d->ratio_src = s->ratio_src;
		memcpy(d->ratio_in, s->ratio_in, sizeof d->ratio_in);
	}
}

/* The floor's share of cell_add: its own statistics, and the ratio. */
static void floor_add(cell_t *c, uint64_t index, const sample_metrics *m, const double n[3], int source,
                      bin_t *b[4], int lazy)
{
	const double f = m->has_basis ? m->floor : dmax(m->floor_dir_norm, m->floor_dir_cos);
	const double r = m->floor_ratio;
	fstrat_t *t = m->stratum >= 0 && m->stratum < NSTRAT ? &c->fst[m->stratum] : NULL;
	int i;
	if (isnan(f))
		return;
	c->floor_n++;
	if (!lazy)
		fx_add_double(&c->floor2, f * f);
	if (t) {
		t->fn++;
		fx_add_double(&t->f2, f * f);
	}
	c->max_floor = dmax(c->max_floor, f);
	c->max_floor_dir = dmax(c->max_floor_dir, dmax(m->floor_dir_norm, m->floor_dir_cos));
	for (i = 0; i < 4; i++)
		if (b[i]) {
			b[i]->fcount++;
			fx_add_double(&b[i]->fsumsq, f * f);
			b[i]->fmax = dmax(b[i]->fmax, f);
		}
	if (m->nonfinite || isnan(r))
		return;
	c->ratio_n++;
	c->ratio_at += r <= 1.0;
	if (!lazy)
		fx_add_double(&c->ratio2, r * r);
	if (t) {
		t->rn++;
		t->rat += r <= 1.0;
		fx_add_double(&t->r2, r * r);
	}
	if (ratio_wins(r, index, source, c)) {
		c->max_ratio = r;
		c->ratio_idx = index;
		c->ratio_src = source;
		memcpy(c->ratio_in, n, sizeof c->ratio_in);
	}
}

static void bin_add(bin_t *b, double e)
{
	b->count++;
	fx_add_double(&b->sumsq, e * e);
	if (e > b->max)
		b->max = e;
}

static int clampi(int v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : v; }

/* 10^-k, k = 0 .. 68: the by_nz bins' edges, as the nearest doubles. */
static const double p10[69] = {
	1e-0, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14,
	1e-15, 1e-16, 1e-17, 1e-18, 1e-19, 1e-20, 1e-21, 1e-22, 1e-23, 1e-24, 1e-25, 1e-26, 1e-27, 1e-28,
	1e-29, 1e-30, 1e-31, 1e-32, 1e-33, 1e-34, 1e-35, 1e-36, 1e-37, 1e-38, 1e-39, 1e-40, 1e-41, 1e-42,
	1e-43, 1e-44, 1e-45, 1e-46, 1e-47, 1e-48, 1e-49, 1e-50, 1e-51, 1e-52, 1e-53, 1e-54, 1e-55, 1e-56,
	1e-57, 1e-58, 1e-59, 1e-60, 1e-61, 1e-62, 1e-63, 1e-64, 1e-65, 1e-66, 1e-67, 1e-68
};

/* The by_nz bin of h > 0 in quarter decades: the figure the files were
   first written with, clampi((int)floor((log10(h) + off4 / 4) * 4), 0,
   nb - 1), for off4 = 68 or 36 and nb <= off4, without log10 (three calls
   per input were a sixth of cell_add).  That expression is floor(log10
   y) + off4 for y = h^4, clamped: the number of edges t_j = 10^(j - off4),
   j = 1 .. nb-1, that y reaches.  y and the t_j here are rounded (y to
   3 ulps, t_j to half an ulp), so an edge within a relative 2^-30 of y
   is left to the expression itself; farther out both agree: 2^-30
   relative in h^4 moves log10(h) by 2^-33.2, and the expression's own
   error (log10 within 2 ulps of a value below 32, the sum with off4 / 4
   half an ulp) stays below 2^-46 after the factor 4. */
static inline int log_bin(double h, int off4, int nb)
{
	const double y = (h * h) * (h * h);
	uint64_t u;
	int e, j;
	if (!(h > 0.0))
		return 0;
	if (!(y >= 0x1p-1000 && y < 0x1p1000))
		return clampi((int)floor((log10(h) + off4 / 4.0) * 4.0), 0, nb - 1);
	/* y = 2^e (1 + f): log2(1 + f) - f lies in [0, 0.0861], so log10 y
	   is (e + f) log10 2 or at most 0.026 above it: the bin is j below or
	   the next one */
	memcpy(&u, &y, sizeof u);
	e = (int)(u >> 52) - 1023;
	j = clampi((int)floor((e + (double)(u & 0xfffffffffffffull) * 0x1p-52) * 0.30102999566398120) + off4, 0, nb - 1);
	if (j + 1 < nb && y >= p10[off4 - j - 1])
		j++;
	/* t_j (1 + 2^-30) <= y < t_(j+1) (1 - 2^-30): bin j however j was found */
	if ((j > 0 && y < p10[off4 - j] * (1.0 + 0x1p-30)) || (j + 1 < nb && y >= p10[off4 - j - 1] * (1.0 - 0x1p-30)))
		return clampi((int)floor((log10(h) + off4 / 4.0) * 4.0), 0, nb - 1);
	return j;
}

int sweep_log_bin(double h, int off4, int nb) { return log_bin(h, off4, nb); }

/* cell_add, and with lazy (cell_add_lazy) the sums a stratum holds too
   left to cell_settle. */
static void cell_add_to(cell_t *c, uint64_t index, const sample_metrics *m, const double n[3], int source, int lazy)
{
	worst_t w;
	double key;
	bin_t *fb[4] = { NULL, NULL, NULL, NULL }; /* the bins of this input, for the floor */
	lazy = lazy && m->stratum >= 0 && m->stratum < NSTRAT;
	c->count++;
	if (m->nonfinite) {
		c->nonfinite++;
		key = INFINITY;
	} else {
		c->finite++;
		if (m->has_basis) {
			fx_add_double(&c->sumsq, m->sumsq);
			if (!lazy)
				fx_add_double(&c->sumdef2, m->defect * m->defect);
			c->max_defect = dmax(c->max_defect, m->defect);
			{	/* footnote 1: |n|-1 with the five defects, mean square */
				const double ms = (m->in_norm * m->in_norm + m->sumsq) / 6.0;
				if (!lazy)
					fx_add_double(&c->duffms, ms);
				c->max_duff_rms = dmax(c->max_duff_rms, sqrt(ms));
			}
			c->wrong += (uint64_t)m->wrong_hand;
			key = m->defect;
		} else {
			key = dmax(m->dir_norm, m->dir_cos);
		}
		c->comps += (uint64_t)m->nbits;
		if (!lazy)
			fx_add_double(&c->bits, m->bits_sum);
		if (m->stratum >= 0 && m->stratum < NSTRAT)
			stratum_add(&c->st[m->stratum], m);
		c->max_ulp = dmax(c->max_ulp, m->ulp_max);
		c->max_abs_eps = dmax(c->max_abs_eps, m->abs_eps_max);
		c->max_bits = dmax(c->max_bits, m->bits_max);
		c->max_dir_norm = dmax(c->max_dir_norm, m->dir_norm);
		c->max_dir_cos = dmax(c->max_dir_cos, m->dir_cos);
		fx_add_double(&c->dirn2, m->dir_norm * m->dir_norm);
		if (!lazy)
			fx_add_double(&c->dirc2, m->dir_cos * m->dir_cos);
		/* bins of the per-input error */
		fb[0] = &c->bins[clampi((int)floor((n[2] + 1.0) * 0.5 * NB_NZ), 0, NB_NZ - 1)];
		bin_add(fb[0], key);
		if (n[2] <= 0.0) {
			fb[1] = &c->bins[NB_NZ + log_bin(1.0 + n[2], 68, NB_LOG)];
			bin_add(fb[1], key);
		}
		fb[2] = &c->bins[NB_NZ + NB_LOG + log_bin(fabs(m->in_norm), 36, NB_NORM)];
		bin_add(fb[2], key);
		if (n[2] >= 0.0) { /* the north pole's cancellation, 1 - n.z */
			fb[3] = &c->bins[NB_NZ + NB_LOG + NB_NORM + log_bin(1.0 - n[2], 68, NB_LOG)];
			bin_add(fb[3], key);
		}
	}
	floor_add(c, index, m, n, source, fb, lazy);
	c->max_in_norm = dmax(c->max_in_norm, fabs(m->in_norm));
	w.key = key;
	w.index = index;
	w.source = source;
	if (!worse(&w, &c->worst[NWORST - 1]))
		return; /* the common case: not among the worst */
	w.branch = m->branch;
	memcpy(w.n, n, sizeof w.n);
	memcpy(w.out, m->out, sizeof w.out);
	memcpy(w.ref, m->ref, sizeof w.ref);
	w.defect = m->defect;
	w.ulp = m->ulp_max;
	w.bits_max = m->bits_max;
	w.dir_norm = m->dir_norm;
	w.dir_cos = m->dir_cos;
	worst_insert(c, &w);
}

void cell_add(cell_t *c, uint64_t index, const sample_metrics *m, const double n[3], int source)
{
	cell_add_to(c, index, m, n, source, 0);
}

void cell_add_lazy(cell_t *c, uint64_t index, const sample_metrics *m, const double n[3], int source)
{
	cell_add_to(c, index, m, n, source, 1);
}

/* The stratum sums (stratum_add, floor_add) hold the same terms as these
   six cell sums, whenever the input's stratum is one of the NSTRAT: the
   sum over the strata is the same integer. */
void cell_settle(cell_t *c)
{
	int h;
	for (h = 0; h < NSTRAT; h++) {
		fx_add(&c->sumdef2, &c->st[h].s[Q_DEF2]);
		fx_add(&c->duffms, &c->st[h].s[Q_DUFF]);
		fx_add(&c->dirc2, &c->st[h].s[Q_DIRC2]);
		fx_add(&c->bits, &c->st[h].bx);
		fx_add(&c->floor2, &c->fst[h].f2);
		fx_add(&c->ratio2, &c->fst[h].r2);
	}
}

int sweep_alloc(sweep_state *s)
{
	size_t i, nc = SWEEP_NPREC * NDIST * (size_t)s->cfg.nk, g = sweep_grid_cells(s) * SWEEP_NPREC * (size_t)s->cfg.nk;
	s->cells = malloc(nc * sizeof *s->cells);
	s->g_err = malloc(g * sizeof *s->g_err);
	s->g_bits = malloc(g * sizeof *s->g_bits);
	s->g_b1 = malloc(3 * g * sizeof *s->g_b1);
	s->g_done = calloc(SWEEP_NPREC * sweep_grid_cells(s) + 1, 1);
	if (!s->cells || !s->g_err || !s->g_bits || !s->g_b1 || !s->g_done) {
		study_error("out of memory for the sweep's accumulators (grid %dx%d, %d methods)",
		            s->cfg.grid_rows, s->cfg.grid_cols, s->cfg.nk);
		sweep_free(s);
		return -1;
	}
	for (i = 0; i < nc; i++)
		cell_init(&s->cells[i]);
	for (i = 0; i < g; i++)
		s->g_err[i] = s->g_bits[i] = s->g_b1[3 * i] = s->g_b1[3 * i + 1] = s->g_b1[3 * i + 2] = NAN;
	return 0;
}

void sweep_free(sweep_state *s)
{
	free(s->cells); free(s->g_err); free(s->g_bits); free(s->g_b1); free(s->g_done);
	s->cells = NULL; s->g_err = s->g_bits = s->g_b1 = NULL; s->g_done = NULL;
}

int sweep_kernels_from_names(sweep_state *s)
{
	int i;
	for (i = 0; i < s->cfg.nk; i++) {
		char name[64];
		const size_t len = strlen(s->cfg.names[i]);
		const int fma = len > 4 && strcmp(s->cfg.names[i] + len - 4, "+fma") == 0;
		snprintf(name, sizeof name, "%.*s", (int)(fma ? len - 4 : len), s->cfg.names[i]);
		if (fma && !fma_available()) {
			study_error("state has FMA kernels, but this CPU or build has no FMA");
			return -1;
		}
		if (fma) { /* kernels_select with fma adds the plain copy, then the FMA one */
			study_kernel tmp[2];
			if (kernels_select(name, 1, tmp, 2) != 2)
				return -1;
			s->kernels[i] = tmp[1];
		} else if (kernels_select(name, 0, &s->kernels[i], 1) != 1) {
			return -1;
		}
	}
	return 0;
}

static int wr(FILE *f, const void *p, size_t n) { return fwrite(p, 1, n, f) == n ? 0 : -1; }
static int rd(FILE *f, void *p, size_t n) { return fread(p, 1, n, f) == n ? 0 : -1; }

/* ---- state files: a header that starts with its magic, then parts --------- */

FILE *state_file_open(const char *path, void *hdr, size_t len, const char *magic, const char *not_one)
{
	FILE *f = fopen(path, "rb");
	if (!f) {
		study_error("%s: %s", path, strerror(errno));
		return NULL;
	}
	if (rd(f, hdr, len) || memcmp(hdr, magic, strlen(magic) + 1) != 0) {
		study_error("%s: not a %s", path, not_one);
		fclose(f);
		return NULL;
	}
	return f;
}

int state_file_parts(FILE *f, const state_part *parts, int n, int write)
{
	int i;
	for (i = 0; i < n; i++)
		if (write ? wr(f, parts[i].p, parts[i].bytes) : rd(f, parts[i].p, parts[i].bytes))
			return -1;
	return 0;
}

int state_file_end(FILE *f, const char *path, int bad, const char *what)
{
	if (!bad && fgetc(f) != EOF)
		bad = 1;
	fclose(f);
	if (bad)
		study_error("%s: %s", path, what);
	return bad ? -1 : 0;
}

/* The parts of a sweep state after its cfg, in file order. */
static int state_parts(const sweep_state *s, state_part *parts)
{
	const size_t nc = SWEEP_NPREC * NDIST * (size_t)s->cfg.nk, g = sweep_grid_cells(s) * SWEEP_NPREC * (size_t)s->cfg.nk;
	parts[0].p = s->cells; parts[0].bytes = nc * sizeof *s->cells;
	parts[1].p = s->g_err; parts[1].bytes = g * sizeof *s->g_err;
	parts[2].p = s->g_bits; parts[2].bytes = g * sizeof *s->g_bits;
	parts[3].p = s->g_b1; parts[3].bytes = 3 * g * sizeof *s->g_b1;
	parts[4].p = s->g_done; parts[4].bytes = SWEEP_NPREC * sweep_grid_cells(s);
	return 5;
}

int sweep_save_state(const sweep_state *s, const char *dir, const char *name)
{
	return sweep_save_state_x(s, dir, name, NULL, 0);
}

int sweep_save_state_x(const sweep_state *s, const char *dir, const char *name, const void *extra, size_t len)
{
	study_out o;
	state_part parts[5];
	const int np = state_parts(s, parts);
	sweep_cfg cfg = s->cfg;
	snprintf(cfg.magic, sizeof cfg.magic, "%s", STATE_MAGIC);
	if (study_out_open(&o, dir, name) != 0)
		return -1;
	if (wr(o.f, &cfg, sizeof cfg) || state_file_parts(o.f, parts, np, 1) || (len && wr(o.f, extra, len))) {
		study_error("%s: write failed: %s", o.path, strerror(errno));
		study_out_abort(&o);
		return -1;
	}
	return study_out_commit(&o);
}

int sweep_load_state(sweep_state *s, const char *path)
{
	return sweep_load_state_x(s, path, NULL, NULL);
}

/* The bytes after the state, up to EOF: 0, or -1 (out of memory, read error). */
static int read_rest(FILE *f, unsigned char **extra, size_t *len)
{
	size_t cap = 4096, n = 0, r;
	unsigned char *b = malloc(cap), *t;
	if (!b)
		return -1;
	while ((r = fread(b + n, 1, cap - n, f)) > 0) {
		n += r;
		if (n == cap) {
			if (!(t = realloc(b, 2 * cap))) { free(b); return -1; }
			b = t;
			cap *= 2;
		}
	}
	if (ferror(f)) { free(b); return -1; }
	*extra = b;
	*len = n;
	return 0;
}

int sweep_load_state_x(sweep_state *s, const char *path, unsigned char **extra, size_t *len)
{
	FILE *f;
	state_part parts[5];
	int c, np;
	memset(s, 0, sizeof *s);
	if (!(f = state_file_open(path, &s->cfg, sizeof s->cfg, STATE_MAGIC,
	                          "sweep state file of this version (write one with 'sweep --shard K/N')")))
		return -1;
	if (s->cfg.nk < 1 || s->cfg.nk > SWEEP_MAX_KERNELS || s->cfg.grid_rows < 2 || s->cfg.grid_cols < 2 ||
	    (uint64_t)s->cfg.grid_rows * (uint64_t)s->cfg.grid_cols > SWEEP_MAX_GRID_CELLS ||
	    s->cfg.shard_n < 1 || s->cfg.shard_n > 1000000 || s->cfg.shard_k < 0 || s->cfg.shard_k >= s->cfg.shard_n ||
	    s->cfg.ref_bits < 64 || s->cfg.ref_bits > 4096 || s->cfg.check_every < 1 ||
	    (s->cfg.prec_on[0] & ~1) || (s->cfg.prec_on[1] & ~1)) {
		study_error("%s: corrupt state header", path);
		fclose(f);
		return -1;
	}
	for (c = 0; c < s->cfg.nk; c++)
		s->cfg.names[c][63] = '\0';
	if (sweep_kernels_from_names(s) != 0 || sweep_alloc(s) != 0) {
		fclose(f);
		return -1;
	}
	np = state_parts(s, parts);
	if (state_file_end(f, path, state_file_parts(f, parts, np, 0) || (extra && read_rest(f, extra, len) != 0),
	                   "truncated or oversized state file") != 0) {
		sweep_free(s);
		return -1;
	}
	return 0;
}

int sweep_cfg_same(const sweep_cfg *x, const sweep_cfg *y)
{
	sweep_cfg a = *x, b = *y;
	/* everything but the shard index and the counters must agree */
	a.shard_k = b.shard_k = 0;
	a.evals = b.evals = a.checked = b.checked = 0;
	/* nor the reference path (both give the same bytes) and its counters */
	a.ref_mpfr = b.ref_mpfr = 0;
	memset(a.ref_evals, 0, sizeof a.ref_evals); memset(b.ref_evals, 0, sizeof b.ref_evals);
	memset(a.ref_fallback, 0, sizeof a.ref_fallback); memset(b.ref_fallback, 0, sizeof b.ref_fallback);
	memset(a.ref_worst, 0, sizeof a.ref_worst); memset(b.ref_worst, 0, sizeof b.ref_worst);
	memset(a.magic, 0, sizeof a.magic);
	memset(b.magic, 0, sizeof b.magic);
	return memcmp(&a, &b, sizeof a) == 0;
}

void sweep_cfg_add_counters(sweep_cfg *d, const sweep_cfg *s)
{
	int p, k;
	d->evals += s->evals;
	d->checked += s->checked;
	for (p = 0; p < SWEEP_NPREC; p++)
		for (k = 0; k < d->nk; k++) {
			d->ref_evals[p][k] += s->ref_evals[p][k];
			d->ref_fallback[p][k] += s->ref_fallback[p][k];
			d->ref_worst[p][k] += s->ref_worst[p][k];
		}
	d->ref_mpfr |= s->ref_mpfr; /* mixed shards: say MPFR took part */
}

/* ---- the grid layout: the one place that spells it out ------------------- */

size_t sweep_grid_cells(const sweep_state *s)
{
	return (size_t)s->cfg.grid_rows * (size_t)s->cfg.grid_cols;
}

size_t sweep_grid_index(const sweep_state *s, int p, int k, size_t cell)
{
	return ((size_t)p * (size_t)s->cfg.nk + (size_t)k) * sweep_grid_cells(s) + cell;
}

void sweep_grid_put(sweep_state *s, int p, int k, size_t cell, double err, double bits, const double b1[3])
{
	const size_t j = sweep_grid_index(s, p, k, cell);
	s->g_err[j] = err;
	s->g_bits[j] = bits;
	memcpy(&s->g_b1[3 * j], b1, 3 * sizeof(double));
	s->g_done[(size_t)p * sweep_grid_cells(s) + cell] = 1;
}

int sweep_grid_done(const sweep_state *s, int p, size_t cell)
{
	return s->g_done[(size_t)p * sweep_grid_cells(s) + cell] != 0;
}

/* The cells another state computed (done[p][cell] set) into d. */
static void grid_merge(sweep_state *d, const double *err, const double *bits, const double *b1, const unsigned char *done)
{
	const size_t G = sweep_grid_cells(d);
	size_t i;
	int p, k;
	for (p = 0; p < SWEEP_NPREC; p++)
		for (i = 0; i < G; i++)
			if (done[(size_t)p * G + i])
				for (k = 0; k < d->cfg.nk; k++) {
					const size_t j = sweep_grid_index(d, p, k, i);
					sweep_grid_put(d, p, k, i, err[j], bits[j], &b1[3 * j]);
				}
}

int sweep_merge_into(sweep_state *d, const sweep_state *s)
{
	size_t i, nc = SWEEP_NPREC * NDIST * (size_t)d->cfg.nk;
	if (!sweep_cfg_same(&d->cfg, &s->cfg)) {
		study_error("shards come from different sweeps (seed, methods, sizes or shard count differ)");
		return -1;
	}
	for (i = 0; i < nc; i++)
		cell_merge(&d->cells[i], &s->cells[i]);
	grid_merge(d, s->g_err, s->g_bits, s->g_b1, s->g_done);
	sweep_cfg_add_counters(&d->cfg, &s->cfg);
	return 0;
}

/* ---- slices: a run's part of a state, as bytes (the MPI driver's deltas) -- */

static size_t grid_bytes(const sweep_state *s)
{
	const size_t g = sweep_grid_cells(s) * SWEEP_NPREC * (size_t)s->cfg.nk;
	return g * sizeof(double) * 5 + SWEEP_NPREC * sweep_grid_cells(s);
}

size_t sweep_slice_bytes(const sweep_state *s, size_t lo, size_t hi, int grid)
{
	return (hi - lo) * sizeof(cell_t) + (grid ? grid_bytes(s) : 0);
}

void sweep_slice_pack(const sweep_state *s, size_t lo, size_t hi, int grid, unsigned char *out)
{
	const size_t g = sweep_grid_cells(s) * SWEEP_NPREC * (size_t)s->cfg.nk;
	memcpy(out, s->cells + lo, (hi - lo) * sizeof(cell_t));
	if (grid) {
		unsigned char *q = out + (hi - lo) * sizeof(cell_t);
		memcpy(q, s->g_err, g * sizeof(double)); q += g * sizeof(double);
		memcpy(q, s->g_bits, g * sizeof(double)); q += g * sizeof(double);
		memcpy(q, s->g_b1, 3 * g * sizeof(double)); q += 3 * g * sizeof(double);
		memcpy(q, s->g_done, SWEEP_NPREC * sweep_grid_cells(s));
	}
}

int sweep_slice_merge(sweep_state *d, size_t lo, size_t hi, int grid, const unsigned char *in, size_t n)
{
	const size_t g = sweep_grid_cells(d) * SWEEP_NPREC * (size_t)d->cfg.nk;
	size_t i;
	if (lo > hi || hi > SWEEP_NPREC * NDIST * (size_t)d->cfg.nk || n != sweep_slice_bytes(d, lo, hi, grid))
		return -1;
	for (i = 0; i < hi - lo; i++) {
		cell_t c;
		memcpy(&c, in + i * sizeof c, sizeof c);
		cell_merge(&d->cells[lo + i], &c);
	}
	if (grid) {
		const double *err = (const double *)(const void *)(in + (hi - lo) * sizeof(cell_t));
		const double *bits = err + g, *b1 = bits + g;
		grid_merge(d, err, bits, b1, (const unsigned char *)(b1 + 3 * g));
	}
	return 0;
}

void sweep_clear(sweep_state *s)
{
	size_t i;
	for (i = 0; i < SWEEP_NPREC * NDIST * (size_t)s->cfg.nk; i++)
		cell_init(&s->cells[i]);
	memset(s->g_done, 0, SWEEP_NPREC * sweep_grid_cells(s));
}
