/*
 * gpu.c - onbstudy-gpu: libonb's shader kernels (include/libonb/onb.glsl,
 * onb.hlsl) and the shader engines' own lines on a real Vulkan driver,
 * Mesa's lavapipe by default, compared bit for bit with libonb's C float
 * kernels.  Built by `make gpu` (libvulkan, glslang); not part of
 * ./onbstudy, whose build needs no Vulkan.  lavapipe runs on the CPU:
 * nothing here times anything.
 *
 *   onbstudy-gpu info       the device, driver (Mesa, LLVM) and float controls
 *   onbstudy-gpu ops        how the driver rounds each GLSL operation
 *   onbstudy-gpu compare    every method in four shader variants against C
 *   onbstudy-gpu wild       the engines' own lines (src/gpu/wild/) against their C rows
 *   onbstudy-gpu half       binary16 kernels (float16_t, half.comp) against the C half kernels
 *   onbstudy-gpu report     all four, with provenance, into --out FILE
 * Exit: 0 when every difference is explained and every result lies in its
 * envelope, 1 when not, 2 on bad usage, 3 when the device cannot be made.
 */
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "common/options.h"
#include "gpu/gpu.h"
#include "gpu/compare.h"

/* half's bounds: certify --quick --arith vulkan --precision half (results/gpu/README.md) */
#define GPU_HALF_BOUNDS "results/gpu/half/vulkan/certify-half.csv"


typedef struct {
	const char *device, *spv, *bounds, *methods, *out;
	unsigned long long seed, per, count;
	int bounds_given;  /* --bounds: no fallback to the wild runs' CSVs */
} gpu_opts;

static void usage(FILE *f)
{
	fprintf(f, "usage: onbstudy-gpu COMMAND [options]\n\n"
	           "libonb's GLSL and HLSL kernels and the shader engines' own lines on a Vulkan\n"
	           "driver (Mesa's lavapipe by default), bit for bit against libonb's C float\n"
	           "kernels.  lavapipe runs on the CPU: no timings.\n\n"
	           "commands:\n"
	           "  info      the device, its driver (Mesa and LLVM versions) and float controls\n"
	           "  ops       how the driver rounds each GLSL operation the methods use\n"
	           "  compare   every method of onb.glsl/onb.hlsl (as written and all precise) against C,\n"
	           "            and every result on a rounded unit input against its proven bound\n"
	           "  wild      the shader engines of docs/wild.md (src/gpu/wild/) in their own lines\n"
	           "            against their C rows\n"
	           "  half      binary16 kernels in explicit float16_t arithmetic (src/gpu/half.comp,\n"
	           "            shaderFloat16) against libonb's C half kernels, and every result on a\n"
	           "            rounded unit input against certify --arith vulkan --precision half\n"
	           "  report    info, ops, compare and wild with provenance, written to --out FILE\n\n"
	           "options:\n"
	           "  --device NAME   the first Vulkan device whose name contains NAME (default llvmpipe)\n"
	           "  --spv DIR       the compiled kernels (default build/gpu, made by make gpu)\n"
	           "  --bounds CSV    certify's bounds (default results/certify/certify.csv, and for\n"
	           "                  wild's rows absent there results/wild/add/*/certify.csv; a\n"
	           "                  certify --arith CSV for a profile's); half: its binary16 rows\n"
	           "                  (default results/gpu/half/vulkan/certify-half.csv)\n"
	           "  --methods LIST  compare, half: these methods only (comma-separated); broken_duff_sign\n"
	           "                  (both) and broken_frisvad_f32 (half) are deliberately broken kernels\n"
	           "                  that the checks must catch\n"
	           "  --seed S        inputs' seed (default 1)\n"
	           "  --per N         inputs per distribution of the sweep (default 20000)\n"
	           "  --count N       ops: operand triples (default 200000)\n"
	           "  --out FILE      report (required), half: the file to write, with provenance\n"
	           "Exit status: 0 all explained and inside, 1 not, 2 bad usage, 3 no device.\n");
}

static int parse(gpu_opts *o, const char *cmd, int argc, char **argv)
{
	static const struct option lo[] = {
		{ "device", required_argument, NULL, 'd' }, { "spv", required_argument, NULL, 's' },
		{ "bounds", required_argument, NULL, 'b' }, { "methods", required_argument, NULL, 'm' },
		{ "seed", required_argument, NULL, 'S' }, { "per", required_argument, NULL, 'p' },
		{ "count", required_argument, NULL, 'c' }, { "out", required_argument, NULL, 'o' },
		CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
	};
	cli_args c;
	int v, rc = 0;
	if (cli_begin(&c, cmd, argc, argv))
		return -1;
	while (rc == 0 && (v = cli_next(&c, lo)) != -1) {
		switch (v) {
		case CLI_HELP: usage(stdout); cli_end(&c); exit(0);
		case 'd': o->device = c.arg; break;
		case 's': o->spv = c.arg; break;
		case 'b': o->bounds = c.arg; o->bounds_given = 1; break;
		case 'm': o->methods = c.arg; break;
		case 'o': o->out = c.arg; break;
		case 'S': rc = parse_u64("--seed", c.arg, 0, ~0ull, &o->seed); break;
		case 'p': rc = parse_u64("--per", c.arg, 1, 1u << 24, &o->per); break;
		case 'c': rc = parse_u64("--count", c.arg, 1, 1u << 24, &o->count); break;
		default: rc = -1; break;
		}
	}
	if (rc == 0)
		rc = cli_no_rest(&c);
	cli_end(&c);
	return rc;
}

static void info(FILE *f, gpu_dev *d)
{
	const uint32_t a = gpu_api(d);
	fprintf(f, "- device: %s; driver: %s; Vulkan %u.%u.%u; shaderFloat64 %s; shaderFloat16 %s\n", gpu_name(d), gpu_driver(d),
	        a >> 22, (a >> 12) & 0x3ffu, a & 0xfffu, gpu_float64(d) ? "on" : "off", gpu_float16(d) ? "on" : "off");
	fprintf(f, "- float controls reported: %s\n", gpu_float_controls(d));
}

/* Is the driver's fma() fused?  Run on a product whose rounding shows. */
static int fma_fused(gpu_dev *d, const char *spvdir)
{
	const float in[3] = { 0x1.000002p+0f, 0x1.000002p+0f, -0x1.000004p+0f };
	uint32_t out[1];
	char spv[4096];
	float r;
	snprintf(spv, sizeof spv, "%s/ops.spv", spvdir);
	if (gpu_run(d, spv, 7, (const uint32_t *)(const void *)in, 3, out, 1, 1) != 0)
		return -1;
	memcpy(&r, out, sizeof r);
	return r != 0.0f;  /* fused: 2^-46; twice rounded: 0 */
}

static int run(gpu_dev *d, const char *cmd, const gpu_opts *o, FILE *f)
{
	gpu_inputs in;
	int rc = 0, fused;
	if (strcmp(cmd, "info") == 0 || strcmp(cmd, "report") == 0)
		info(f, d);
	if (strcmp(cmd, "ops") == 0 || strcmp(cmd, "report") == 0) {
		fprintf(f, "\n### Operations (%llu operand triples, seed %llu)\n\n", o->count, o->seed);
		if (gpu_ops(d, o->spv, f, o->seed, (size_t)o->count) < 0)
			return -1;
	}
	if (strcmp(cmd, "half") == 0) {
		int h;
		info(f, d);
		h = gpu_half(d, o->spv, f, o->seed, o->per, o->bounds, o->methods);
		if (h >= 0 && !o->methods && gpu_relaxed(d, o->spv, f, o->seed, o->per) != 0)
			h = -1;   /* the mediump table runs with the whole list only */
		return h;
	}
	if (strcmp(cmd, "compare") != 0 && strcmp(cmd, "wild") != 0 && strcmp(cmd, "report") != 0)
		return 0;
	if ((fused = fma_fused(d, o->spv)) < 0 || gpu_inputs_make(&in, o->seed, o->per) != 0)
		return -1;
	if (strcmp(cmd, "compare") == 0 || strcmp(cmd, "report") == 0) {
		char prof[64];
		gpu_bounds_profile(o->bounds, prof, sizeof prof);
		fprintf(f, "\n### Methods (%zu inputs, seed %llu; fma() %s on this driver; bounds of profile %s)\n\n",
		        in.count, o->seed, fused ? "fused" : "rounded twice", prof);
		rc = gpu_compare_all(d, o->spv, f, &in, fused, o->bounds, o->methods);
	}
	if (rc >= 0 && (strcmp(cmd, "wild") == 0 || strcmp(cmd, "report") == 0)) {
		int w;
		fprintf(f, "\n### Shader engines in their own lines (%zu inputs, seed %llu)\n\n", in.count, o->seed);
		w = gpu_wild(d, o->spv, f, &in, o->bounds, !o->bounds_given);
		rc = w < 0 ? -1 : rc + w;
	}

	gpu_inputs_free(&in);
	return rc;
}

static void provenance(FILE *f, const gpu_opts *o)
{
	char date[32];
	const time_t t = time(NULL);
	strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", gmtime(&t));
	fprintf(f, "# onbstudy-gpu report\n\n- revision: %s\n- compiler: %s\n- flags: %s\n- shaders: %s (build/gpu, make gpu)\n"
	           "- date: %s\n- seed: %llu, inputs per distribution: %llu, operand triples: %llu\n- bounds: %s\n- command: %s\n",
	        ONB_GIT_REV, ONB_CC, ONB_CFLAGS, ONB_GLSLANG, date, o->seed, o->per, o->count, o->bounds, study_cmdline);
}

int main(int argc, char **argv)
{
	gpu_opts o = { "llvmpipe", "build/gpu", "results/certify/certify.csv", NULL, NULL, 1, 20000, 200000, 0 };
	const char *cmd;
	FILE *f = stdout;
	gpu_dev *d;
	char tmp[4096];
	int rc;
	study_set_cmdline(argc, argv);
	if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
		usage(argc < 2 ? stderr : stdout);
		return argc < 2 ? ONB_EXIT_USAGE : 0;
	}
	cmd = argv[1];
	if (strcmp(cmd, "info") && strcmp(cmd, "ops") && strcmp(cmd, "compare") && strcmp(cmd, "wild") && strcmp(cmd, "half") &&
	    strcmp(cmd, "report")) {
		study_error("onbstudy-gpu: unknown command '%s' (info, ops, compare, wild, half or report)", cmd);
		return ONB_EXIT_USAGE;
	}
	if (parse(&o, cmd, argc - 2, argv + 2) != 0)
		return ONB_EXIT_USAGE;
	if ((strcmp(cmd, "report") == 0 && !o.out) || (o.out && strcmp(cmd, "report") != 0 && strcmp(cmd, "half") != 0)) {
		study_error("onbstudy-gpu: --out FILE goes with report (required) and half, and only with them");
		return ONB_EXIT_USAGE;
	}
	if (strcmp(cmd, "half") == 0 && !o.bounds_given)
		o.bounds = GPU_HALF_BOUNDS;
	if (strcmp(cmd, "half") == 0 ? gpu_half_check(o.methods) != 0 : gpu_methods_check(o.methods) != 0)
		return ONB_EXIT_USAGE;
	if (!(d = gpu_open(o.device)))
		return 3;
	if (o.out) {
		snprintf(tmp, sizeof tmp, "%s.tmp", o.out);
		if (!(f = fopen(tmp, "w"))) {
			study_error("onbstudy-gpu: cannot write %s", tmp);
			gpu_close(d);
			return 1;
		}
		provenance(f, &o);
	}
	rc = run(d, cmd, &o, f);
	gpu_close(d);
	if (o.out && (fclose(f) != 0 || rc < 0 || rename(tmp, o.out) != 0)) {
		remove(tmp);
		return 1;
	}
	return rc == 0 ? 0 : 1;
}
