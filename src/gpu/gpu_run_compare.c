/*
 * gpu_run_compare.c - onbstudy-gpu compare: each method of methods.inc in
 * the four shader variants (GLSL and HLSL, each as written and with
 * ONB_PRECISE = precise) on the inputs, against its C kernel, with the
 * envelope check (gpu_compare.c describes both).  One markdown row per
 * method.  A method fails when a precise variant gives another finite
 * value than C on some input (a difference the driver's fma explains
 * excepted), or when a result on a rounded unit input lies above its
 * bound.  Differences in the sign of a zero, or where C or the driver
 * gives NaN or inf, are counted and shown, not failed: Vulkan allows both
 * without SignedZeroInfNanPreserve (docs/gpu.md).  In the variants as
 * written, a finite difference is what contraction may do: shown.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "gpu/gpu.h"
#include "gpu/compare.h"

static const gpu_variant variants[GPU_NVAR] = {
	{ "GLSL", "onb_glsl.spv" }, { "GLSL precise", "onb_glsl_precise.spv" },
	{ "HLSL", "onb_hlsl.spv" }, { "HLSL precise", "onb_hlsl_precise.spv" },
};
#define PRECISE(v) ((v) == 1 || (v) == 3)
#define HLSL(v) ((v) >= 2)

static void tally(gpu_cmp *c, int v, const gpu_inputs *in, const float *ref, const float *got)
{
	size_t i;
	for (i = 0; i < in->count; i++) {
		const int k = gpu_class(ref + 6 * i, got + 6 * i);
		c->n[v][k]++;
		if (k >= GPU_ZERO && (k > c->first_cls || (k == c->first_cls && i < c->first))) {
			c->first = i;
			c->first_cls = k;
			c->first_var = v;
			memcpy(c->first_out, got + 6 * i, sizeof c->first_out);
			memcpy(c->first_ref, ref + 6 * i, sizeof c->first_ref);
		}
		if (in->unit[i]) {
			const double d = gpu_defect(in->n + 3 * i, got + 6 * i);
			if (v == 0)
				c->domain++;
			if (v == 1)
				c->un[k]++;
			if (d > c->dmax) {
				c->dmax = d;
				c->dmax_at = i;
			}
			if (c->bound >= 0.0 && !(d <= c->bound) && c->above++ == 0)
				c->above_at = i;
		}
	}
}

/* The C kernel the shader must match, and the bound that applies. */
static void expectation(gpu_cmp *c, int fma_fused, const char *bounds)
{
	const gpu_method *m = c->m;
	const int broken = strcmp(m->name, "broken_duff_sign") == 0;
	const int none = strcmp(m->twin, "none") == 0;
	char prof[64];
	c->expect = broken || (!fma_fused && !none) ? m->twin : m->name;
	c->bound_of = !fma_fused && none ? NULL : c->expect;
	gpu_bounds_profile(bounds, prof, sizeof prof);
	if (strcmp(prof, "ieee") != 0)  /* a profile's bound covers every conforming result */
		c->bound_of = broken ? m->twin : m->name;
	c->bound = c->bound_of ? gpu_bound(bounds, c->bound_of) : -1.0;
}

int gpu_compare_one(gpu_dev *d, const char *spvdir, const gpu_inputs *in, const gpu_method *m,
                    int fma_fused, const char *bounds, float *ref, float *got, gpu_cmp *c)
{
	char spv[4096];
	int v;
	memset(c, 0, sizeof *c);
	c->m = m;
	c->first = in->count;
	c->first_cls = -1;
	expectation(c, fma_fused, bounds);
	if (c->bound_of && c->bound < 0.0) {
		fprintf(stderr, "onbstudy-gpu: no whole-sphere float bound of %s in %s\n", c->bound_of, bounds);
		return -1;
	}
	if (gpu_c_outputs(c->expect, in, ref) != 0)
		return -1;
	for (v = 0; v < GPU_NVAR; v++) {
		if (HLSL(v) && m->f64 == 2)
			continue;  /* HLSL has no double sqrt */
		snprintf(spv, sizeof spv, "%s/%s", spvdir, variants[v].spv);
		if (gpu_run(d, spv, m->id, (const uint32_t *)(const void *)in->n, 3 * in->count,
		            (uint32_t *)(void *)got, 6 * in->count, (uint32_t)((in->count + 63) / 64)) != 0)
			return -1;
		c->ran[v] = 1;
		tally(c, v, in, ref, got);
	}
	return 0;
}

static void cell(FILE *f, const gpu_cmp *c, int v)
{
	const size_t *n = c->n[v];
	if (!c->ran[v]) {
		fprintf(f, " - (no double sqrt in HLSL) |");
		return;
	}
	if (n[GPU_ZERO] + n[GPU_NONFINITE] + n[GPU_VALUE] == 0) {
		fprintf(f, " all %zu%s |", n[GPU_SAME] + n[GPU_NAN], n[GPU_NAN] ? " (NaN payloads aside)" : "");
		return;
	}
	fprintf(f, " %zu", n[GPU_SAME] + n[GPU_NAN]);
	if (n[GPU_ZERO])
		fprintf(f, "; +-0: %zu", n[GPU_ZERO]);
	if (n[GPU_NONFINITE])
		fprintf(f, "; NaN/inf: %zu", n[GPU_NONFINITE]);
	if (n[GPU_VALUE])
		fprintf(f, "; **value: %zu**", n[GPU_VALUE]);
	fprintf(f, " |");
}

static void row(FILE *f, const gpu_inputs *in, const gpu_cmp *c, int explained)
{
	static const char *const what[GPU_NCLASS] = { "", "", "+-0", "NaN/inf", "value" };
	int v, k;
	fprintf(f, "| `%s` | `%s` |", c->m->name, c->expect);
	for (v = 0; v < GPU_NVAR; v++)
		cell(f, c, v);
	if (c->first < in->count) {
		const size_t i = c->first;
		fprintf(f, " %s, %s: (%a, %a, %a): C", variants[c->first_var].label, what[c->first_cls],
		        (double)in->n[3 * i], (double)in->n[3 * i + 1], (double)in->n[3 * i + 2]);
		for (k = 0; k < 6; k++)
			fprintf(f, " %a", (double)c->first_ref[k]);
		fprintf(f, ", driver");
		for (k = 0; k < 6; k++)
			fprintf(f, " %a", (double)c->first_out[k]);
		fprintf(f, "%s |", explained ? " (fma rounded twice)" : "");
	} else {
		fprintf(f, " - |");
	}
	fprintf(f, " %zu | %zu / %zu / %zu | %.3g |", c->domain, c->un[GPU_ZERO], c->un[GPU_NONFINITE], c->un[GPU_VALUE], c->dmax);
	if (!c->bound_of)
		fprintf(f, " none: its IEEE bound needs a fused fma | - |\n");
	else if (c->bound == INFINITY)
		fprintf(f, " inf (%s: no finite bound) | no bound |\n", c->bound_of);
	else
		fprintf(f, " %.3g (%s) | %s |\n", c->bound, c->bound_of, c->above ? "**outside**" : "inside");
	if (c->above) {
		const size_t i = c->above_at;
		fprintf(f, "\n  %s: %zu unit inputs above the bound, the first (%a, %a, %a)\n\n", c->m->name, c->above,
		        (double)in->n[3 * i], (double)in->n[3 * i + 1], (double)in->n[3 * i + 2]);
	}
}

static int wanted(const char *list, const char *name)
{
	const size_t n = strlen(name);
	const char *p = list;
	if (!list)
		return strcmp(name, "broken_duff_sign") != 0;
	while ((p = strstr(p, name)) != NULL) {
		if ((p == list || p[-1] == ',') && (p[n] == ',' || p[n] == '\0'))
			return 1;
		p += n;
	}
	return 0;
}

/* -1 with a message when the list names a method that is not ours. */
int gpu_methods_check(const char *list)
{
	size_t nm, k, found = 0, names = 1;
	const gpu_method *ms = gpu_methods(&nm);
	const char *p;
	if (!list)
		return 0;
	for (p = list; *p; p++)
		names += *p == ',';
	for (k = 0; k < nm; k++)
		found += (size_t)wanted(list, ms[k].name);
	if (found == names)
		return 0;
	fprintf(stderr, "onbstudy-gpu: --methods: unknown method in '%s'; valid:", list);
	for (k = 0; k < nm; k++)
		fprintf(stderr, " %s", ms[k].name);
	fprintf(stderr, "\n");
	return -1;
}

int gpu_compare_all(gpu_dev *d, const char *spvdir, FILE *f, const gpu_inputs *in, int fused,
                    const char *bounds, const char *methods)
{
	size_t nm, k;
	const gpu_method *ms = gpu_methods(&nm);
	float *ref = malloc(6 * in->count * sizeof *ref), *got = malloc(6 * in->count * sizeof *got);
	int bad = 0, rc = 0;
	if (!ref || !got) {
		fprintf(stderr, "onbstudy-gpu: out of memory\n");
		free(ref); free(got);
		return -1;
	}
	fprintf(f, "| method | C kernel | GLSL | GLSL precise | HLSL | HLSL precise | first input that differs most | unit inputs | of which differ in GLSL precise: +-0 / NaN-inf / value | largest D there | bound | envelope |\n"
	           "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
	for (k = 0; k < nm && rc == 0; k++) {
		gpu_cmp c;
		int explained, value;
		if (!wanted(methods, ms[k].name))
			continue;
		if (ms[k].f64 && !gpu_float64(d)) {
			fprintf(f, "| `%s` | - | needs shaderFloat64, which the device lacks | | | | | | | | | |\n", ms[k].name);
			continue;
		}
		if ((rc = gpu_compare_one(d, spvdir, in, &ms[k], fused, bounds, ref, got, &c)) != 0)
			break;
		value = c.n[1][GPU_VALUE] + c.n[3][GPU_VALUE] != 0;
		explained = !fused && strcmp(ms[k].twin, "none") == 0;
		row(f, in, &c, explained && c.first_cls == GPU_VALUE);
		bad += (value && !explained) || c.above;
	}
	free(ref); free(got);
	return rc ? -1 : bad;
}
