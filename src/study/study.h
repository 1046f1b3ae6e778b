/*
 * study.h - shared declarations of the onbstudy CLI (not part of libonb).
 */
#ifndef ONB_STUDY_H
#define ONB_STUDY_H

#include <stdio.h>
#include <stddef.h>
#include "onb.h"

#ifndef ONB_GIT_REV
#define ONB_GIT_REV "unknown"
#endif
#ifndef ONB_CC
#define ONB_CC "unknown"
#endif
#ifndef ONB_CFLAGS
#define ONB_CFLAGS "unknown"
#endif

/* Exit status for bad usage or input: one line on stderr, then 2. */
#define ONB_EXIT_USAGE 2

/* Subcommands: each takes the arguments after its own name. */
int cmd_list(int argc, char **argv);
int cmd_sweep(int argc, char **argv);
int cmd_merge(int argc, char **argv);
int cmd_eval(int argc, char **argv);
int cmd_threshold(int argc, char **argv);
/* threshold.c: merge support for threshold shards */
int threshold_is_state(const char *path);
int threshold_merge(int nfiles, char **files, const char *out, int threads);
int cmd_scene(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_table(int argc, char **argv);
int cmd_reproduce(int argc, char **argv);
int cmd_certify(int argc, char **argv);   /* src/certify/certify.c */

/* cli.c: argument helpers.  Each prints one clear line and returns -1 on
   bad input; callers then exit with ONB_EXIT_USAGE. */
void study_error(const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 1, 2)))
#endif
	;
int parse_u64(const char *opt, const char *s, unsigned long long lo, unsigned long long hi, unsigned long long *out);
int parse_double(const char *opt, const char *s, double *out);
int parse_int(const char *opt, const char *s, long lo, long hi, long *out);

/* cli.c: getopt_long for every command, with the same messages for the same
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
int  cli_shard(const char *opt, const char *arg, int *k, int *n);  /* K/N, 0-based */
/* "1, 3, 4" (the first 20, then "...") of the shards 0 .. n-1 not seen, for merge's messages. */
void study_missing_shards(const unsigned char *seen, int n, char *buf, size_t len);
int  cli_format(const char *opt, const char *arg, int with_json);  /* 0 table, 1 csv, 2 json; -1 */

/* The command line as one string, for provenance lines; set once by
   study_set_cmdline (argv joined by spaces, cut at 4095 bytes). */
extern const char *study_cmdline;
void study_set_cmdline(int argc, char **argv);

/* output.c: atomic result files and provenance.
   A result file is written to a temporary name beside its final name and
   renamed over it only when complete, so an interrupted run never leaves a
   truncated file in place of an earlier good one. */
typedef struct {
	FILE *f;
	char tmp[4096];
	char path[4096];
} study_out;
int  study_mkdir_p(const char *dir);                       /* 0, or -1 with a message */
int  study_out_open(study_out *o, const char *dir, const char *name); /* 0, or -1 with a message */
int  study_out_commit(study_out *o);                      /* flush, fsync, rename; 0 or -1 */
void study_out_abort(study_out *o);                       /* close and remove the temporary */
/* Lines starting with '#': tool, version, git revision, compiler, flags,
   CPU, date, seed, threads, command line.  Callers add their own '#' lines
   (MPFR precision, ISA, ...) after it. */
void study_provenance(FILE *f, const char *what, unsigned long long seed, int threads);
const char *study_cpu_model(void);
/* An extra provenance line (without '#'), e.g. the MPI driver's ranks and threads; NULL: none. */
extern const char *study_provenance_note;
/* A new run directory name under results/: results/run-YYYYmmdd-HHMMSS. */
void study_default_run_dir(char *buf, size_t n);
/* The current run, where threshold and bench write by default: the
   directory results/latest names, or (none yet) a new results/run-DATE,
   created, which results/latest then names. */
void study_current_run_dir(char *buf, size_t n);
/* results/latest -> DIR (only for a directory directly under results/). */
void study_point_latest(const char *dir);

#endif
