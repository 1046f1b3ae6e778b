/*
 * gpu_wild.c - onbstudy-gpu wild: the shader engines of docs/wild.md in
 * their own GLSL lines (wild.comp) on the driver, against their C rows
 * (the method or alias target of docs/wild.md) bit for bit, with the
 * envelope check of gpu_compare.c against that row's bound.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "gpu/gpu.h"
#include "gpu/compare.h"

typedef struct {
	int id;                  /* wild.comp's ENGINE           */
	const char *engine, *row; /* docs/wild.md's row, its C method */
	const char *lines;       /* where the lines are          */
} wild_row;

static const wild_row rows[] = {
	{ 1, "q2rtx", "q2rtx", "NVIDIA/Q2RTX f2526e9a src/refresh/vkpt/shader/utils.glsl:241-257 (GLSL)" },
	{ 2, "nvpro", "frisvad_max", "nvpro-samples/nvpro_core ba24b73e nvvkhl/shaders/func.h:102-114 (GLSL)" },
	{ 3, "pasvulkan", "duff", "BeRo1985/pasvulkan bc6681f3 src/assets/shaders/scene3d/tangentspacebasis.glsl:4-11 (GLSL)" },
	{ 4, "falcor", "duff", "NVIDIAGameWorks/Falcor eb540f67 Source/Falcor/Utils/Math/MathHelpers.slang:559-567 (Slang, read as GLSL)" },
};
#define NROWS (sizeof rows / sizeof rows[0])

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

static int one(gpu_dev *d, FILE *f, const char *spv, const gpu_inputs *in, const wild_row *r,
               const char *bounds, float *ref, float *got, int *bad)
{
	size_t i, same = 0, zero = 0, nonfin = 0, value = 0, value_bad_in = 0, first = in->count, above = 0;
	double dmax = 0.0, bound = gpu_bound(bounds, r->row);
	if (bound < 0.0 || gpu_c_outputs(r->row, in, ref) != 0)
		return -1;
	if (gpu_run(d, spv, r->id, (const uint32_t *)(const void *)in->n, 3 * in->count,
	            (uint32_t *)(void *)got, 6 * in->count, (uint32_t)((in->count + 63) / 64)) != 0)
		return -1;
	for (i = 0; i < in->count; i++) {
		const int k = gpu_class(ref + 6 * i, got + 6 * i);
		same += k <= GPU_NAN;
		zero += k == GPU_ZERO;
		nonfin += k == GPU_NONFINITE;
		value += k == GPU_VALUE;
		value_bad_in += k == GPU_VALUE && !(isfinite(in->n[3 * i]) && isfinite(in->n[3 * i + 1]) && isfinite(in->n[3 * i + 2]));
		if (k >= GPU_ZERO && first == in->count)
			first = i;
		if (in->unit[i]) {
			const double dd = gpu_defect(in->n + 3 * i, got + 6 * i);
			if (dd > dmax) dmax = dd;
			if (!(dd <= bound)) above++;
		}
	}
	fprintf(f, "| `%s` | %s | `%s` | %zu | %zu | %zu | %s%zu%s (%zu at a NaN/inf input) | %.3g | %.3g | %s | ", r->engine, r->lines,
	        r->row, same, zero, nonfin, value ? "**" : "", value, value ? "**" : "", value_bad_in, dmax, bound,
	        above ? "**outside**" : "inside");
	if (first < in->count)
		first_diff(f, in, ref, got, first);
	else
		fprintf(f, "-");
	fprintf(f, " |\n");
	/* The engines' lines are their own (no precise but q2rtx's): a finite
	   difference is shown, not failed, as contraction may make one; a
	   result outside the envelope fails. */
	*bad += above > 0;
	return 0;
}

int gpu_wild(gpu_dev *d, const char *spvdir, FILE *f, const gpu_inputs *in, const char *bounds)
{
	float *ref = malloc(6 * in->count * sizeof *ref), *got = malloc(6 * in->count * sizeof *got);
	char spv[4096];
	size_t k;
	int bad = 0, rc = 0;
	if (!ref || !got) {
		fprintf(stderr, "onbstudy-gpu: out of memory\n");
		free(ref); free(got);
		return -1;
	}
	snprintf(spv, sizeof spv, "%s/wild.spv", spvdir);
	fprintf(f, "| engine | its lines | C row | same bits (NaN payloads aside) | +-0 | NaN/inf | value | largest D on unit inputs | bound (C row) | envelope | first differing input: driver b1 b2, C b1 b2 |\n"
	           "|---|---|---|---|---|---|---|---|---|---|---|\n");
	for (k = 0; k < NROWS && rc == 0; k++)
		rc = one(d, f, spv, in, &rows[k], bounds, ref, got, &bad);
	free(ref); free(got);
	return rc ? -1 : bad;
}
