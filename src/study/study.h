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

/* The command line as one string, for provenance lines. */
extern const char *study_cmdline;

#endif
