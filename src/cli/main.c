/*
 * main.c - onbstudy: subcommand dispatch.  main stands above every
 * command's folder: its includes of sweep/, scene/, bench/ and reproduce/
 * are the only imports from cli/ upward, and the reason cli/ is drawn
 * above them.  A new command (certify/, say) is one #include of its
 * header below and one row of commands[].
 */
#include <stdlib.h>
#include <string.h>
#include "common/options.h"
#include "common/output.h"
#include "cli/list.h"
#include "cli/eval.h"
/* up: the commands of the other folders */
#include "sweep/sweep.h"
#include "sweep/threshold.h"
#include "sweep/halfscan.h"
#include "certify/certify.h"
#include "scene/scene.h"
#include "bench/bench.h"
#include "bench/table.h"
#include "reproduce/reproduce.h"

typedef int (*cmd_fn)(int argc, char **argv);

static const struct {
	const char *name;
	cmd_fn fn;
	const char *help;
} commands[] = {
	{ "list", cmd_list, "the methods in the registry: source, handedness, singular set" },
	{ "sweep", cmd_sweep, "MPFR-referenced error of every method over every input distribution" },
	{ "eval", cmd_eval, "one input: every method's outputs (hex) and every metric" },
	{ "threshold", cmd_threshold, "Nelson Max's analysis of Frisvad's threshold t near -1" },
	{ "halfscan", cmd_halfscan, "every method in binary16 near each axis: largest defect in u = 2^-11, non-finite bases" },
	{ "merge", cmd_merge, "combine 'sweep --shard K/N' outputs into one run's files" },
	{ "scene", cmd_scene, "a scene's own normals (OBJ, PLY, glTF 2.0): every method, and the one to use" },
	{ "bench", cmd_bench, "batch and per-call speed of every method, beside a copy roofline and a yardstick" },
	{ "reproduce", cmd_reproduce, "each published figure (Frisvad 2012, Duff et al. 2017, Max 2017) beside a fresh measurement" },
	{ "certify", cmd_certify, "proven extremes: per region of the sphere, the worst input found beside a bound no input exceeds" },
	{ "table", cmd_table, "the speed-accuracy trade table (bench.csv joined with a sweep's summary.csv)" },
};

#define NCOMMANDS (sizeof commands / sizeof commands[0])

static void usage(FILE *f)
{
	size_t i;
	fprintf(f, "usage: onbstudy COMMAND [options]\n\n"
	           "A precision and robustness study of orthonormal-basis methods (libonb %s).\n\n"
	           "commands:\n", ONB_VERSION);
	for (i = 0; i < NCOMMANDS; i++)
		fprintf(f, "  %-10s %s\n", commands[i].name, commands[i].help);
	fprintf(f, "\n'onbstudy COMMAND --help' describes a command's options.\n");
}

/* Top-level options (stop at the command: "+"), then the command. */
static int dispatch(int argc, char **argv)
{
	static const struct option lo[] = {
		{ "help", no_argument, NULL, 'h' }, { "version", no_argument, NULL, 'V' }, { NULL, 0, NULL, 0 }
	};
	size_t i;
	int v;
	opterr = 0;
	while ((v = getopt_long(argc, argv, "+h", lo, NULL)) != -1) {
		if (v == 'h') {
			usage(stdout);
			return 0;
		}
		if (v == 'V') {
			printf("onbstudy %s (%s)\n", ONB_VERSION, ONB_GIT_REV);
			return 0;
		}
		study_error("unknown option '%s' (try 'onbstudy --help')", argv[optind - 1]);
		return ONB_EXIT_USAGE;
	}
	if (optind >= argc) {
		usage(stderr);
		return ONB_EXIT_USAGE;
	}
	if (strcmp(argv[optind], "help") == 0) {
		usage(stdout);
		return 0;
	}
	for (i = 0; i < NCOMMANDS; i++)
		if (strcmp(argv[optind], commands[i].name) == 0)
			return commands[i].fn(argc - optind - 1, argv + optind + 1);
	study_error("unknown command '%s' (try 'onbstudy --help')", argv[optind]);
	return ONB_EXIT_USAGE;
}

int main(int argc, char **argv)
{
	/* stdout line by line, even into a file or a pipe: a stderr message
	   (progress, summary, warning) then never lands inside a table row,
	   and study_error flushes stdout before it writes. */
	setvbuf(stdout, NULL, _IOLBF, 0);
	study_set_cmdline(argc, argv);
	return dispatch(argc, argv);
}
