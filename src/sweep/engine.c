/*
 * engine.c - the sweep engine (see engine.h): chunks of a plan into
 * accumulators.
 *
 * Threads take global chunks dynamically.  Each thread has its own MPFR
 * contexts and accumulators for the (precision, distribution) it is in,
 * and folds them into the state when it moves on and at the end.  Where
 * things go:
 *   - a new per-input metric: computed by the reference (sample_metrics,
 *     reference/reference.h), accumulated by cell_add (state.c, a field of
 *     cell_t in state.h, merged by cell_merge), written by writers.c;
 *   - an alternative reference path: eval_one() below is the one place
 *     an input is evaluated against the reference.
 * The worst-case walk (engine_walk, at the end of this file) is the
 * engine's last stage: it runs once on the finished, merged state, before
 * the writers, which only read it.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "sweep/engine.h"
#include "common/options.h"
#include "common/output.h"
#include "reference/reffast.h"

volatile sig_atomic_t engine_stop;

struct engine {
	const sweep_plan *pl;
	dist_spec ds[SWEEP_NPREC][NDIST];
	int fail;                      /* ENGINE_NOMEM or ENGINE_DISAGREE, shared */
	char why[512];
};

/* What one thread holds. */
typedef struct {
	ref_ctx *rc1, *rc2;            /* the reference at B and B+64 bits */
	reffast_ctx *fc;               /* the fast reference (NULL: MPFR only) */
	/* per precision and kernel: evaluations, MPFR fallbacks, ref[] filled for the worst rows */
	unsigned long long revals[SWEEP_NPREC][SWEEP_MAX_KERNELS], rfall[SWEEP_NPREC][SWEEP_MAX_KERNELS],
	                   rworst[SWEEP_NPREC][SWEEP_MAX_KERNELS];
	cell_t *loc;                   /* [kernel] of (p, d) */
	int p, d;                      /* -1: loc is empty */
	unsigned long long evals, checked;
} worker;

engine *engine_new(const sweep_plan *pl)
{
	engine *e = calloc(1, sizeof *e);
	int p, d;
	if (!e) {
		study_error("out of memory");
		return NULL;
	}
	e->pl = pl;
	for (p = 0; p < SWEEP_NPREC; p++)
		for (d = 0; d < NDIST; d++) {
			if (!pl->cfg.prec_on[p] || !pl->cfg.dist_on[d])
				continue;
			plan_dist_spec(pl, p, d, &e->ds[p][d]);
			if (dist_prepare(&e->ds[p][d]) != 0) {
				engine_free(e);
				return NULL;
			}
			/* the plan's count (exhaustive: --exhaustive-range's, per precision) */
			e->ds[p][d].count = pl->cfg.counts[p][d];
		}
	return e;
}

void engine_free(engine *e)
{
	int p, d;
	if (!e)
		return;
	for (p = 0; p < SWEEP_NPREC; p++)
		for (d = 0; d < NDIST; d++)
			dist_free(&e->ds[p][d]);
	free(e);
}

const char *engine_why(const engine *e) { return e->why; }

int engine_state_init(const sweep_plan *pl, sweep_state *st)
{
	memset(st, 0, sizeof *st);
	st->cfg = pl->cfg;
	memcpy(st->kernels, pl->kernels, sizeof st->kernels);
	return sweep_alloc(st);
}

static int worker_init(worker *w, const sweep_plan *pl)
{
	memset(w, 0, sizeof *w);
	w->p = w->d = -1;
	w->rc1 = ref_new(pl->cfg.ref_bits);
	w->rc2 = ref_new(pl->cfg.ref_bits + 64);
	w->loc = malloc((size_t)pl->cfg.nk * sizeof *w->loc);
	if (!pl->cfg.ref_mpfr) {
		w->fc = reffast_new(pl->cfg.ref_bits);
		if (!w->fc)
			return -1;
	}
	return w->rc1 && w->rc2 && w->loc ? 0 : -1;
}

/* The worst rows of the thread's cells whose ref[] the fast reference
   left to MPFR (REFFAST_NOREF: NaN where undetermined): the input again,
   and ref[] from ref_eval, the bytes the MPFR path would have stored
   (every other field of the row is already MPFR's).  A row of a finite
   key with a NaN that MPFR wrote itself is evaluated again to the same
   bytes.  Only the rows kept at the end pay: filling each one as it
   entered the list cost an MPFR evaluation for every new worst input
   (half a million in the default sweep). */
static void worker_fill_refs(engine *e, worker *w, sweep_state *st)
{
	int k, i, j;
	for (k = 0; k < st->cfg.nk; k++)
		for (i = 0; i < NWORST; i++) {
			worst_t *r = &w->loc[k].worst[i];
			double n[3], lv[3], aux;
			sample_metrics m;
			if (r->index == UINT64_MAX || r->source != 0 || !isfinite(r->key))
				continue;
			for (j = 0; j < 6 && !isnan(r->ref[j]); j++)
				;
			if (j == 6)
				continue;
			dist_sample(&e->ds[w->p][w->d], r->index, n, lv, &aux);
			ref_eval(w->rc1, &st->kernels[k], w->p, n, lv, w->d == DIST_NONUNIT, &m);
			memcpy(r->ref, m.ref, sizeof r->ref);
			w->rworst[w->p][k]++;
		}
}

/* Fold the thread's cells into the state, and start (p, d) afresh. */
static void worker_fold(engine *e, worker *w, sweep_state *st, int p, int d)
{
	int k;
	if (w->p >= 0 && w->fc)
		worker_fill_refs(e, w, st);
	if (w->p >= 0) {
		for (k = 0; k < st->cfg.nk; k++)
			cell_settle(&w->loc[k]); /* filled by cell_add_lazy since cell_init */
#pragma omp critical(engine_fold)
		for (k = 0; k < st->cfg.nk; k++)
			cell_merge(sweep_cell(st, w->p, w->d, k), &w->loc[k]);
	}
	w->p = p;
	w->d = d;
	if (p >= 0)
		for (k = 0; k < st->cfg.nk; k++)
			cell_init(&w->loc[k]);
}

static void worker_free(worker *w)
{
	free(w->loc);
	reffast_free(w->fc);
	ref_free(w->rc1);
	ref_free(w->rc2);
}

/* Input idx of (p, d) through every kernel, against the reference. */
static void eval_one(engine *e, worker *w, sweep_state *st, int p, int d, uint64_t idx)
{
	const sweep_cfg *cfg = &st->cfg;
	double n[3], lv[3], aux;
	int k;
	const int check = idx % (uint64_t)cfg->check_every == 0, stratum = dist_stratum(&e->ds[p][d], idx);
	dist_sample(&e->ds[p][d], idx, n, lv, &aux);
	for (k = 0; k < cfg->nk; k++) {
		sample_metrics m;
		if (!kernel_runs(&st->kernels[k], p))
			continue; /* a float-only method, in double */
		w->evals++;
		w->revals[p][k]++;
		if (!w->fc || p == PREC_HALF) {
			ref_eval(w->rc1, &st->kernels[k], p, n, lv, d == DIST_NONUNIT, &m);
			if (w->fc)   /* the fast reference has no binary16: MPFR on every half input */
				w->rfall[p][k]++;
		} else {
			const int f = reffast_eval(w->fc, &st->kernels[k], p, n, lv, d == DIST_NONUNIT, &m);
			if (f == REFFAST_MPFR) {
				ref_eval(w->rc1, &st->kernels[k], p, n, lv, d == DIST_NONUNIT, &m);
				w->rfall[p][k]++;
			}
			/* REFFAST_NOREF: ref[] (worst rows only) holds NaN where MPFR
			   must fill it in; worker_fill_refs does, for the rows still
			   kept when the thread folds its cells */
		}
		if (check) {
			sample_metrics m2;
			char why[256];
			ref_eval(w->rc2, &st->kernels[k], p, n, lv, d == DIST_NONUNIT, &m2);
			w->checked++;
			if (!ref_agree(&m, &m2, why, sizeof why)) {
#pragma omp critical(engine_why)
				snprintf(e->why, sizeof e->why, "%s %s %s input %llu (%a, %a, %a): %s", st->kernels[k].name,
				         prec_name(p), dist_name(d), (unsigned long long)idx, n[0], n[1], n[2], why);
#pragma omp atomic write
				e->fail = ENGINE_DISAGREE;
			}
		}
		m.stratum = stratum;
		cell_add_lazy(&w->loc[k], idx, &m, n, 0);
		if (d == DIST_GRID) {
			sweep_grid_put(st, p, k, (size_t)aux, m.nonfinite ? INFINITY : st->kernels[k].m ? m.defect : fmax(m.dir_norm, m.dir_cos),
			               m.nbits ? m.bits_sum / m.nbits : 0.0, m.out);
		}
	}
}

/* Global chunk g; returns the evaluations done. */
static unsigned long long run_chunk(engine *e, worker *w, sweep_state *st, uint64_t g)
{
	int p, d;
	uint64_t c, i0, i1, idx;
	if (plan_locate(e->pl, g, &p, &d, &c) != 0)
		return 0;
	if (p != w->p || d != w->d)
		worker_fold(e, w, st, p, d);
	i0 = c * PLAN_CHUNK;
	i1 = i0 + PLAN_CHUNK;
	if (i1 > e->ds[p][d].count)
		i1 = e->ds[p][d].count;
	for (idx = i0; idx < i1; idx++)
		eval_one(e, w, st, p, d, idx);
	return (unsigned long long)(i1 - i0) * (unsigned long long)kernels_running(st->kernels, st->cfg.nk, p);
}

static void report(engine *e, study_progress *pr, unsigned long long n, uint64_t g)
{
	int p, d;
	uint64_t c;
	char label[64];
	study_progress snap;
#pragma omp atomic
	pr->done += n;
	if (!pr->bar)
		return;
#ifdef _OPENMP
	if (omp_get_thread_num() != 0)
		return;
#endif
	snap.bar = pr->bar;
	snap.t0 = pr->t0;
	snap.total = pr->total;
	snap.skipped = pr->skipped;
#pragma omp atomic read
	snap.done = pr->done;
	if (plan_locate(e->pl, g, &p, &d, &c) != 0)
		return;
	snprintf(label, sizeof label, "sweep %-6s %-10s", prec_name(p), dist_name(d));
	study_progress_line(label, &snap);
}

int engine_run(engine *e, sweep_state *st, uint64_t g0, uint64_t g1, study_progress *pr)
{
	long long g;
	e->fail = 0;
#pragma omp parallel num_threads(e->pl->threads)
	{
		worker w;
		if (worker_init(&w, e->pl) != 0) {
#pragma omp atomic write
			e->fail = ENGINE_NOMEM;
		}
#pragma omp for schedule(dynamic, 1)
		for (g = (long long)g0; g < (long long)g1; g++) {
			int f;
#pragma omp atomic read
			f = e->fail;
			if (f || engine_stop || !plan_in_shard(e->pl, (uint64_t)g))
				continue;
			{
				const unsigned long long n = run_chunk(e, &w, st, (uint64_t)g);
				if (pr)
					report(e, pr, n, (uint64_t)g);
			}
		}
		if (w.loc && !e->fail)
			worker_fold(e, &w, st, -1, -1);
#pragma omp critical(engine_fold)
		{
			int p, k;
			st->cfg.evals += w.evals;
			st->cfg.checked += w.checked;
			for (p = 0; p < SWEEP_NPREC; p++)
				for (k = 0; k < st->cfg.nk; k++) {
					st->cfg.ref_evals[p][k] += w.revals[p][k];
					st->cfg.ref_fallback[p][k] += w.rfall[p][k];
					st->cfg.ref_worst[p][k] += w.rworst[p][k];
				}
		}
		worker_free(&w);
	}
	if (e->fail)
		return e->fail;
	return engine_stop ? ENGINE_STOPPED : ENGINE_OK;
}

double engine_calibrate(engine *e, int chunks, unsigned long long *evals)
{
	static sweep_state scratch;
	const sweep_plan *pl = e->pl;
	double t0, t;
	int i;
	*evals = 0;
	if (pl->chunks == 0 || engine_state_init(pl, &scratch) != 0)
		return 0.0;
	t0 = study_now();
	for (i = 0; i < chunks; i++) {
		uint64_t g = (uint64_t)((double)pl->chunks * i / chunks);
		while (g < pl->chunks && !plan_in_shard(pl, g))
			g++;
		if (g >= pl->chunks || engine_run(e, &scratch, g, g + 1, NULL) != ENGINE_OK)
			break;
	}
	t = study_now() - t0;
	*evals = scratch.cfg.evals;
	sweep_free(&scratch);
	return t > 0 ? (double)*evals / t : 0.0;
}

/* ---- the worst-case walk ------------------------------------------------ */
/* From the worst threshold inputs, move to the neighbouring input (x, y
   and z each changed by -1, 0 or +1 steps of 1 or 8 representable values)
   with the largest error while it grows, staying unit to within two
   rounding errors.  Each accepted step joins the threshold distribution
   and its worst list (source "walk"). */

#define WALK_STARTS 3
#define WALK_STEPS 24

static void walk_one(sweep_state *s, ref_ctx *rc, int p, int k)
{
	cell_t *c = sweep_cell(s, p, DIST_THRESHOLD, k);
	const study_kernel *K = &s->kernels[k];
	worst_t starts[WALK_STARTS];
	const double loc[3] = { fmt_round(0.6, p), 0.0, fmt_round(0.8, p) };
	int ns = 0, i;
	for (i = 0; i < NWORST && ns < WALK_STARTS; i++)
		if (c->worst[i].index != UINT64_MAX && isfinite(c->worst[i].key))
			starts[ns++] = c->worst[i];
	for (i = 0; i < ns; i++) {
		double cur[3], key = starts[i].key;
		int step;
		memcpy(cur, starts[i].n, sizeof cur);
		for (step = 0; step < WALK_STEPS; step++) {
			double best[3], best_key = key;
			sample_metrics bm, m;
			int dx, dy, dz, sc, moved = 0;
			for (sc = 1; sc <= 8; sc *= 8)
				for (dx = -1; dx <= 1; dx++)
					for (dy = -1; dy <= 1; dy++)
						for (dz = -1; dz <= 1; dz++) {
							double nn[3];
							double kk;
							if (!dx && !dy && !dz)
								continue;
							nn[0] = fmt_step(cur[0], dx * sc, p);
							nn[1] = fmt_step(cur[1], dy * sc, p);
							nn[2] = fmt_step(cur[2], dz * sc, p);
							if (!isfinite(nn[0]) || !isfinite(nn[1]) || !isfinite(nn[2]))
								continue;
							/* stay on the sphere, to the format's rounding: a walk that
							   drifts off it measures non-unit input, not the method */
							{
								const long double len = sqrtl((long double)nn[0] * nn[0] + (long double)nn[1] * nn[1] +
								                              (long double)nn[2] * nn[2]);
								if (fabsl(len - 1.0L) > 2.0L * (long double)prec_fmt(p)->u)
									continue;
							}
							ref_eval(rc, K, p, nn, loc, 0, &m);
							kk = m.nonfinite ? INFINITY : K->m ? m.defect : fmax(m.dir_norm, m.dir_cos);
							if (kk > best_key) {
								best_key = kk;
								memcpy(best, nn, sizeof best);
								bm = m;
								moved = 1;
							}
						}
			if (!moved)
				break;
			memcpy(cur, best, sizeof cur);
			key = best_key;
			cell_add(c, starts[i].index, &bm, cur, 1);
			if (isinf(key))
				break;
		}
	}
}

int engine_walk(sweep_state *s, int threads)
{
	int p, fail = 0;
	for (p = 0; p < SWEEP_NPREC; p++) {
		int k;
		if (!s->cfg.prec_on[p] || !s->cfg.dist_on[DIST_THRESHOLD])
			continue;
#pragma omp parallel num_threads(threads) reduction(|:fail)
		{
			ref_ctx *rc = ref_new(s->cfg.ref_bits);
			if (!rc)
				fail = 1;
#pragma omp for schedule(dynamic, 1)
			for (k = 0; k < s->cfg.nk; k++)
				if (rc && s->cfg.prec_on[p] && kernel_runs(&s->kernels[k], p))
					walk_one(s, rc, p, k);
			ref_free(rc);
		}
	}
	if (fail)
		study_error("out of memory in the worst-case walk");
	return fail ? -1 : 0;
}
