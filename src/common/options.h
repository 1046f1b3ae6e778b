/*
 * common/options.h - the command line of onbstudy (not part of libonb):
 * study_error, the one getopt_long wrapper every command and the MPI driver
 * parse their options with, the value parsers and their messages, and the
 * command line kept for provenance lines.  src/common/ is the ground floor:
 * these helpers, the result files and their provenance (output.h), the
 * progress line (progress.h) and the precisions (prec.h), which every room
 * may import and which import nothing of the study.  src/cli/ holds main
 * (the command table) and the thin commands (list, eval); each other
 * command lives in the folder of its concern and is declared in that
 * folder's header named after its file.
 */
#ifndef ONB_COMMON_OPTIONS_H
#define ONB_COMMON_OPTIONS_H

#include <stdio.h>
#include <stddef.h>
#include "libonb/onb.h"
#include "common/prec.h"

/* Exit status for bad usage or input: one line on stderr, then 2. */
#define ONB_EXIT_USAGE 2

/* options.c: argument helpers.  Each prints one clear line and returns -1 on
   bad input; callers then exit with ONB_EXIT_USAGE. */
void study_error(const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 1, 2)))
#endif
	;
int parse_u64(const char *opt, const char *s, unsigned long long lo, unsigned long long hi, unsigned long long *out);
int parse_double(const char *opt, const char *s, double *out);
int parse_int(const char *opt, const char *s, long lo, long hi, long *out);

/* options.c: getopt_long for every command, with the same messages for the same
   mistakes.  Usage:
	static const struct option lo[] = { { "samples", required_argument, NULL, 'n' }, ..., { 0, 0, 0, 0 } };
	cli_args c; int v;
	if (cli_begin(&c, "sweep", argc, argv)) return 1;
	while ((v = cli_next(&c, lo)) != -1) switch (v) { case CLI_HELP: ...; case CLI_ERROR: ...; case 'n': c.arg ... }
	then cli_rest() or cli_no_rest(), and cli_end().
   Both '--opt value' and '--opt=value' work (getopt_long), '-h' and '--help' give
   CLI_HELP when the table has "help" with val 'h'. */
#include <getopt.h>
#define CLI_HELP  (-'h')
#define CLI_ERROR (-'?')
#define CLI_HELP_OPTION { "help", no_argument, NULL, 'h' }
typedef struct {
	const char *cmd;      /* "sweep" */
	char name[64];        /* "onbstudy sweep", argv[0] for getopt */
	char **av;
	int ac;
	const char *arg;      /* the current option's value, or NULL */
} cli_args;
int  cli_begin(cli_args *c, const char *cmd, int argc, char **argv); /* 0, or -1 after a message */
int  cli_next(cli_args *c, const struct option *lo); /* val, CLI_HELP, CLI_ERROR (message printed) or -1 at the end */
/* For pre-scans that split argv before getopt_long sees it (eval's
   operands, the MPI driver's own options): whether a is "--name" or
   "--name=value" of the table (a unique prefix of a name too, as
   getopt_long allows, unless exact), and then 1 when it takes the next
   argument as its value, else 0; -1 when it is not one of the table's. */
int  cli_option_arity(const struct option *lo, const char *a, int exact);
char **cli_rest(cli_args *c, int *n);                 /* the operands, after the options */
int  cli_no_rest(cli_args *c);                        /* -1 with a message if there are operands */
void cli_end(cli_args *c);
/* One of names[count]: its index, or -1 after "OPT: expected a, b or c, not 'x'". */
int  cli_choice(const char *opt, const char *arg, const char *const *names, int count);
/* A comma-separated list of names into on[count]; unknown names get the list of valid ones. */
/* The same, keeping the order given: idx[] (room for count) gets each name's
   index once; returns how many, or -1 after a message. */
int  cli_name_order(const char *opt, const char *arg, int *idx, const char *const *names, int count);
int  cli_name_list(const char *opt, const char *arg, int *on, const char *const *names, int count);
int  cli_precision(const char *opt, const char *arg, int on[2]);   /* float, double or both */
/* float, double, both (float and double), half or all three, into
   on[PREC_*]; half on a build without _Float16 (ONB_HAVE_HALF 0) is
   refused with a message (-1: the caller exits 2). */
int  cli_precision_half(const char *opt, const char *arg, int on[PREC_COUNT]);
int  cli_shard(const char *opt, const char *arg, int *k, int *n);  /* K/N, 0-based */
/* "1, 3, 4" (the first 20, then "...") of the shards 0 .. n-1 not seen, for merge's messages. */
void study_missing_shards(const unsigned char *seen, int n, char *buf, size_t len);
int  cli_format(const char *opt, const char *arg, int with_json);  /* 0 table, 1 csv, 2 json; -1 */

/* The command line as one string, for provenance lines; set once by
   study_set_cmdline (argv joined by spaces, cut at 4095 bytes). */
extern const char *study_cmdline;
void study_set_cmdline(int argc, char **argv);

#endif
