/*
 * cli.c - argument parsing helpers shared by the subcommands.
 */
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "study.h"

const char *study_cmdline = "";

void study_error(const char *fmt, ...)
{
	va_list ap;
	fputs("onbstudy: ", stderr);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
}

int parse_u64(const char *opt, const char *s, unsigned long long lo, unsigned long long hi, unsigned long long *out)
{
	char *end;
	unsigned long long v;
	/* a digit first: strtoull would skip blanks and accept " -1" as 2^64-1 */
	if (!s || !(*s >= '0' && *s <= '9')) {
		study_error("%s: expected a non-negative integer, got '%s'", opt, s ? s : "");
		return -1;
	}
	errno = 0;
	v = strtoull(s, &end, 10);
	if (errno || *end) {
		study_error("%s: expected a non-negative integer, got '%s'", opt, s);
		return -1;
	}
	if (v < lo || v > hi) {
		study_error("%s: %llu is out of range [%llu, %llu]", opt, v, lo, hi);
		return -1;
	}
	*out = v;
	return 0;
}

int parse_int(const char *opt, const char *s, long lo, long hi, long *out)
{
	char *end;
	long v;
	if (!s || !((*s >= '0' && *s <= '9') || (*s == '-' && s[1] >= '0' && s[1] <= '9'))) {
		study_error("%s: expected an integer, got '%s'", opt, s ? s : "");
		return -1;
	}
	errno = 0;
	v = strtol(s, &end, 10);
	if (errno || *end) {
		study_error("%s: expected an integer, got '%s'", opt, s);
		return -1;
	}
	if (v < lo || v > hi) {
		study_error("%s: %ld is out of range [%ld, %ld]", opt, v, lo, hi);
		return -1;
	}
	*out = v;
	return 0;
}

int parse_double(const char *opt, const char *s, double *out)
{
	char *end;
	double v;
	/* no leading blanks (strtod skips them), and nan/inf are refused */
	if (!s || !*s || *s == ' ' || *s == '\t' || *s == '\n') {
		study_error("%s: expected a number, got '%s'", opt, s ? s : "");
		return -1;
	}
	errno = 0;
	v = strtod(s, &end);
	if (*end || v != v || v == HUGE_VAL || v == -HUGE_VAL) {
		study_error("%s: expected a finite number, got '%s'", opt, s);
		return -1;
	}
	*out = v;
	return 0;
}
