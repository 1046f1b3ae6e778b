/*
 * gpu_wild.c - onbstudy-gpu wild: the shader engines of docs/wild.md in
 * their own lines on the driver, against their C rows bit for bit, with
 * the envelope check of gpu_compare.c against that row's bound.  The
 * engines are the registry's rows (methods and aliases) whose language is
 * GLSL, HLSL or Slang; each runs from build/gpu/wild/NAME.spv, which the
 * Makefile makes from src/gpu/wild/NAME.glsl and the harness wild.comp.
 * A shader row without its file, or without a bound, fails the run.
 */
#include <glob.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "gpu/gpu.h"
#include "gpu/compare.h"
#include "libonb/onb.h"

typedef struct {
	const char *engine, *row;    /* docs/wild.md's row, its C method */
	const onb_provenance *prov;  /* where its lines are              */
} wild_row;

/* the certify CSVs of the registry's new rows (scripts/wild-run.sh's runs):
   where a shader row's bound is looked up when the default --bounds
   (results/certify/certify.csv, the full run) does not hold its C row */
#define WILD_ADD_CSV "results/wild/add/*/certify.csv"

static int shader_language(const onb_provenance *p)
{
	return p && p->language && (strstr(p->language, "GLSL") || strstr(p->language, "HLSL") || strstr(p->language, "Slang"));
}

static int by_engine(const void *a, const void *b)
{
	return strcmp(((const wild_row *)a)->engine, ((const wild_row *)b)->engine);
}

/* The registry's shader rows, by name; their number (at most max). */
static size_t wild_rows(wild_row *r, size_t max)
{
	size_t nm, na, i, n = 0;
	const onb_method *m = onb_methods(&nm);
	const onb_alias *a = onb_aliases(&na);
	for (i = 0; i < nm && n < max; i++)
		if (shader_language(m[i].prov)) {
			r[n].engine = r[n].row = m[i].name;
			r[n++].prov = m[i].prov;
		}
	for (i = 0; i < na && n < max; i++)
		if (shader_language(&a[i].prov)) {
			r[n].engine = a[i].name;
			r[n].row = a[i].target;
			r[n++].prov = &a[i].prov;
		}
	qsort(r, n, sizeof *r, by_engine);
	return n;
}

/* The whole-sphere float bound of C row `row` in `bounds`, or with
   `fallback` in the first of WILD_ADD_CSV that holds it; *from names the
   CSV.  -1: none holds it (or the CSV cannot be read: a message). */
static double row_bound(const char *bounds, int fallback, const char *row, char *from, size_t len)
{
	glob_t g;
	size_t i;
	double b;
	snprintf(from, len, "%s", bounds);
	if ((b = gpu_bound(bounds, row)) >= 0.0 || !fallback || access(bounds, R_OK) != 0)
		return b;
	if (glob(WILD_ADD_CSV, 0, NULL, &g) != 0)
		return -1.0;
	for (i = 0; i < g.gl_pathc && b < 0.0; i++)
		if ((b = gpu_bound(g.gl_pathv[i], row)) >= 0.0)
			snprintf(from, len, "%s", g.gl_pathv[i]);
	globfree(&g);
	return b;
}

static void first_diff(FILE *f, const gpu_inputs *in, const float *ref, const float *got, size_t i)
{
	int k;
	fprintf(f, "(%a, %a, %a): driver", (double)in->n[3 * i], (double)in->n[3 * i + 1], (double)in->n[3 * i + 2]);
	for (k = 0; k < 6; k++)
		fprintf(f, " %a", (double)got[6 * i + k]);
	fprintf(f, ", C");
	for (k = 0; k < 6; k++)
		fprintf(f, " %a", (double)ref[6 * i + k]);
}

/* Its lines, as the engines table shows them: repository commit path (language). */
static void lines(FILE *f, const onb_provenance *p)
{
	const char *repo = strncmp(p->repository, "github.com/", 11) == 0 ? p->repository + 11 : p->repository;
	fprintf(f, "%s %.8s %s (%s)", repo, p->commit, p->path, p->language);
}

/* A row that cannot run: no engine file, or no bound for its C row. */
static void missing(FILE *f, const wild_row *r, const char *why)
{
	fprintf(f, "| `%s` | ", r->engine);
	lines(f, r->prov);
	fprintf(f, " | `%s` | - | - | - | - | - | - | **%s** | - |\n", r->row, why);
}

/* The classes of the driver's outputs against C's, and the envelope:
   each unit input's D against the bound at that input (its regions'). */
typedef struct {
	size_t same, zero, nonfin, value, value_bad_in, first, above, regional;
	double dmax, ratio;   /* largest D; largest D / bound at the input where the bound is finite */
} wild_scan;

static void scan(const gpu_inputs *in, const float *ref, const float *got, const gpu_regions *rg, wild_scan *w)
{
	size_t i;
	memset(w, 0, sizeof *w);
	w->first = in->count;
	for (i = 0; i < in->count; i++) {
		const int k = gpu_class(ref + 6 * i, got + 6 * i);
		w->same += k <= GPU_NAN;
		w->zero += k == GPU_ZERO;
		w->nonfin += k == GPU_NONFINITE;
		w->value += k == GPU_VALUE;
		w->value_bad_in += k == GPU_VALUE && !(isfinite(in->n[3 * i]) && isfinite(in->n[3 * i + 1]) && isfinite(in->n[3 * i + 2]));
		if (k >= GPU_ZERO && w->first == in->count)
			w->first = i;
		if (in->unit[i]) {
			const double dd = gpu_defect(in->n + 3 * i, got + 6 * i), b = gpu_regions_bound(rg, in->n + 3 * i);
			if (dd > w->dmax) w->dmax = dd;
			if (!(dd <= b)) w->above++;
			w->regional += b < rg->whole;
			if (b < INFINITY && b > 0.0 && dd / b > w->ratio) w->ratio = dd / b;
		}
	}
}

static int one(gpu_dev *d, FILE *f, const char *spvdir, const gpu_inputs *in, const wild_row *r,
               const char *bounds, int fallback, float *ref, float *got, int *bad)
{
	char spv[4096], from[4096];
	gpu_regions rg;
	wild_scan w;
	double bound;
	snprintf(spv, sizeof spv, "%s/wild/%s.spv", spvdir, r->engine);
	if (access(spv, R_OK) != 0) {
		missing(f, r, "not run: no src/gpu/wild/ENGINE.glsl (docs/adding-a-method.md)");
		return ++*bad, 0;
	}
	if ((bound = row_bound(bounds, fallback, r->row, from, sizeof from)) < 0.0) {
		if (access(bounds, R_OK) != 0)
			return -1;
		missing(f, r, "no bound: its C row is in no certify CSV read");
		return ++*bad, 0;
	}
	if (gpu_c_outputs(r->row, in, ref) != 0 || gpu_regions_load(from, r->row, &rg) != 0)
		return -1;
	if (gpu_run(d, spv, 0, (const uint32_t *)(const void *)in->n, 3 * in->count,
	            (uint32_t *)(void *)got, 6 * in->count, (uint32_t)((in->count + 63) / 64)) != 0) {
		gpu_regions_free(&rg);
		return -1;
	}
	scan(in, ref, got, &rg, &w);
	fprintf(f, "| `%s` | ", r->engine);
	lines(f, r->prov);
	fprintf(f, " | `%s` | %zu | %zu | %zu | %s%zu%s (%zu at a NaN/inf input) | %.3g | %.3g%s%s; at each input its regions' (%zu tighter): largest D/bound %.3g | %s | ",
	        r->row, w.same, w.zero, w.nonfin, w.value ? "**" : "", w.value, w.value ? "**" : "", w.value_bad_in, w.dmax, bound,
	        strcmp(from, bounds) ? " from " : "", strcmp(from, bounds) ? from : "", w.regional, w.ratio,
	        w.above ? "**outside**" : "inside");
	if (w.first < in->count)
		first_diff(f, in, ref, got, w.first);
	else
		fprintf(f, "-");
	fprintf(f, " |\n");
	gpu_regions_free(&rg);
	/* The engines' lines are their own (no precise but q2rtx's): a finite
	   difference is shown, not failed, as contraction may make one; a
	   result outside the envelope fails. */
	*bad += w.above > 0;
	return 0;
}

int gpu_wild(gpu_dev *d, const char *spvdir, FILE *f, const gpu_inputs *in, const char *bounds, int fallback)
{
	float *ref = malloc(6 * in->count * sizeof *ref), *got = malloc(6 * in->count * sizeof *got);
	wild_row r[64];
	const size_t n = wild_rows(r, sizeof r / sizeof r[0]);
	size_t k;
	int bad = 0, rc = 0;
	if (!ref || !got) {
		fprintf(stderr, "onbstudy-gpu: out of memory\n");
		free(ref); free(got);
		return -1;
	}
	fprintf(f, "| engine | its lines | C row | same bits (NaN payloads aside) | +-0 | NaN/inf | value | largest D on unit inputs | bound (C row): whole sphere; at each input | envelope | first differing input: driver b1 b2, C b1 b2 |\n"
	           "|---|---|---|---|---|---|---|---|---|---|---|\n");
	for (k = 0; k < n && rc == 0; k++)
		rc = one(d, f, spvdir, in, &r[k], bounds, fallback, ref, got, &bad);
	free(ref); free(got);
	return rc ? -1 : bad;
}
