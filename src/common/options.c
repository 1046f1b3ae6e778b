/*
 * options.c - argument parsing helpers shared by the subcommands.
 */
#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "common/options.h"

const char *study_cmdline = "";

void study_set_cmdline(int argc, char **argv)
{
	static char buf[4096];
	size_t len = 0;
	int k;
	for (k = 0; k < argc && len + 2 < sizeof buf; k++) {
		const int w = snprintf(buf + len, sizeof buf - len, "%s%s", k ? " " : "", argv[k]);
		if (w < 0)
			break;
		len += (size_t)w;
		if (len >= sizeof buf)
			len = sizeof buf - 1;
	}
	study_cmdline = buf;
}

void study_error(const char *fmt, ...)
{
	va_list ap;
	fflush(stdout); /* whatever stdout holds comes first: no message inside a table row */
	fputs("onbstudy: ", stderr);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
}

/* The digits of s (after one '-' when neg_ok) as a magnitude; a digit
   must come first (strtoull would skip blanks and accept " -1" as
   2^64-1).  0, or -1 after "OPT: expected WHAT, got 'S'" (WHAT: "an
   integer", "a positive integer", ...). */
static int parse_whole(const char *opt, const char *s, int neg_ok, const char *what, unsigned long long *mag, int *neg)
{
	char *end;
	*neg = neg_ok && s && *s == '-';
	if (!s || !(s[*neg] >= '0' && s[*neg] <= '9')) {
		study_error("%s: expected %s, got '%s'", opt, what, s ? s : "");
		return -1;
	}
	errno = 0;
	*mag = strtoull(s + *neg, &end, 10);
	if (errno || *end || (neg_ok && *mag > (unsigned long long)LONG_MAX + *neg)) {
		study_error("%s: expected %s, got '%s'", opt, what, s);
		return -1;
	}
	return 0;
}

int parse_u64(const char *opt, const char *s, unsigned long long lo, unsigned long long hi, unsigned long long *out)
{
	unsigned long long v;
	int neg;
	const char *what = lo == 1 ? "a positive integer" : "a non-negative integer";
	if (parse_whole(opt, s, 0, what, &v, &neg) != 0)
		return -1;
	if (v == 0 && lo == 1) {   /* 0 where the count must be positive */
		study_error("%s: expected %s, got '%s'", opt, what, s);
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
	unsigned long long mag;
	long v;
	int neg;
	if (parse_whole(opt, s, 1, "an integer", &mag, &neg) != 0)
		return -1;
	/* -(LONG_MAX + 1) without overflow: negate the magnitude less one */
	v = !neg ? (long)mag : mag == 0 ? 0 : -(long)(mag - 1) - 1;
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

/* ---- getopt_long for every command -------------------------------------- */

int cli_begin(cli_args *c, const char *cmd, int argc, char **argv)
{
	int i;
	memset(c, 0, sizeof *c);
	c->cmd = cmd;
	c->av = malloc(((size_t)argc + 2) * sizeof *c->av);
	if (!c->av) {
		study_error("out of memory");
		return -1;
	}
	snprintf(c->name, sizeof c->name, "onbstudy %s", cmd);
	c->av[0] = c->name;
	for (i = 0; i < argc; i++)
		c->av[i + 1] = argv[i];
	c->av[argc + 1] = NULL;
	c->ac = argc + 1;
	optind = 0; /* glibc: a full re-initialisation, so commands can parse twice */
	opterr = 0;
	return 0;
}

void cli_end(cli_args *c)
{
	free(c->av);
	c->av = NULL;
}

/* The long name of an option by its value, for messages. */
static const char *long_name(const struct option *lo, int val)
{
	for (; lo && lo->name; lo++)
		if (lo->val == val && !lo->flag)
			return lo->name;
	return NULL;
}

int cli_next(cli_args *c, const struct option *lo)
{
	int v;
	c->arg = NULL;
	v = getopt_long(c->ac, c->av, ":h", lo, NULL);
	if (v == -1 || v == 'h' || (v > 0 && v != '?' && v != ':')) {
		c->arg = optarg;
		return v == 'h' ? CLI_HELP : v;
	}
	{
		const char *bad = optind > 0 && optind <= c->ac ? c->av[optind - 1] : "?";
		const char *ln = long_name(lo, optopt);
		if (v == ':') {
			if (ln)
				study_error("--%s needs a value", ln);
			else
				study_error("%s needs a value", bad);
		} else if (optopt && ln && strchr(bad, '=')) {
			study_error("--%s takes no value, not '%s'", ln, bad);
		} else if (optopt > 0 && optopt < 128 && !ln) {
			study_error("%s: unknown option '-%c' (try 'onbstudy %s --help')", c->cmd, optopt, c->cmd);
		} else {
			study_error("%s: unknown option '%s' (try 'onbstudy %s --help')", c->cmd, bad, c->cmd);
		}
	}
	return CLI_ERROR;
}

int cli_option_arity(const struct option *lo, const char *a, int exact)
{
	const char *eq;
	size_t len;
	int hits = 0, value = 0;
	if (a[0] != '-' || a[1] != '-' || !a[2])
		return -1;
	a += 2;
	eq = strchr(a, '=');
	len = eq ? (size_t)(eq - a) : strlen(a);
	for (; lo->name; lo++)
		if (!strncmp(lo->name, a, len)) {
			if (strlen(lo->name) == len)
				return !eq && lo->has_arg == required_argument;
			hits++;
			value = lo->has_arg == required_argument;
		}
	return exact || hits != 1 ? -1 : !eq && value;
}

char **cli_rest(cli_args *c, int *n)
{
	*n = c->ac - optind;
	return c->av + optind;
}

int cli_no_rest(cli_args *c)
{
	if (optind < c->ac) {
		study_error("%s: unexpected argument '%s' (try 'onbstudy %s --help')", c->cmd, c->av[optind], c->cmd);
		return -1;
	}
	return 0;
}

static void names_joined(char *buf, size_t n, const char *const *names, int count)
{
	int i;
	size_t len = 0;
	buf[0] = '\0';
	for (i = 0; i < count && len + 1 < n; i++) {
		const int w = snprintf(buf + len, n - len, "%s%s", i ? (i + 1 == count ? " or " : ", ") : "", names[i]);
		if (w < 0)
			break;
		len += (size_t)w;
	}
}

int cli_choice(const char *opt, const char *arg, const char *const *names, int count)
{
	char all[512];
	int i;
	for (i = 0; i < count; i++)
		if (!strcmp(arg, names[i]))
			return i;
	names_joined(all, sizeof all, names, count);
	study_error("%s: expected %s, not '%s'", opt, all, arg);
	return -1;
}

int cli_name_order(const char *opt, const char *arg, int *idx, const char *const *names, int count)
{
	char buf[2048], *tok, *save = NULL, all[2048];
	int i, j, n = 0;
	if (strlen(arg) >= sizeof buf) {
		study_error("%s: list too long", opt);
		return -1;
	}
	if (arg[0] == ',' || (arg[0] && arg[strlen(arg) - 1] == ',') || strstr(arg, ",,")) {
		study_error("%s: empty name in the list '%s'", opt, arg);
		return -1;
	}
	strcpy(buf, arg);
	for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
		for (i = 0; i < count && strcmp(tok, names[i]); i++)
			;
		if (i == count) {
			names_joined(all, sizeof all, names, count);
			study_error("%s: unknown name '%s' (valid: %s)", opt, tok, all);
			return -1;
		}
		for (j = 0; j < n && idx[j] != i; j++)
			;
		if (j == n)
			idx[n++] = i;
	}
	if (n == 0)
		study_error("%s: empty list", opt);
	return n ? n : -1;
}

int cli_name_list(const char *opt, const char *arg, int *on, const char *const *names, int count)
{
	int idx[256], i, n;
	if (count > 256) {
		study_error("%s: too many names", opt);
		return -1;
	}
	n = cli_name_order(opt, arg, idx, names, count);
	if (n < 0)
		return -1;
	for (i = 0; i < count; i++)
		on[i] = 0;
	for (i = 0; i < n; i++)
		on[idx[i]] = 1;
	return 0;
}

/* The names every --precision takes; each command says which it measures. */
static const char *const prec_names[] = { "float", "double", "both", "half", "all" };

int cli_precision(const char *opt, const char *arg, int on[2])
{
	const int i = cli_choice(opt, arg, prec_names, 5);
	if (i < 0)
		return -1;
	if (i >= 3) {
		study_error("%s %s: this command does not measure binary16 yet "
		            "(sweep, eval, threshold and list --axes take --precision half)", opt, arg);
		return -1;
	}
	on[0] = i != 1;
	on[1] = i != 0;
	return 0;
}

int cli_precision_half(const char *opt, const char *arg, int on[PREC_COUNT])
{
	const int i = cli_choice(opt, arg, prec_names, 5);
	if (i < 0)
		return -1;
	on[PREC_FLOAT] = i == 0 || i == 2 || i == 4;
	on[PREC_DOUBLE] = i == 1 || i == 2 || i == 4;
	on[PREC_HALF] = i >= 3;
	if (on[PREC_HALF] && !ONB_HAVE_HALF) {
		study_error("%s %s: this build has no binary16 kernels: its compiler lacks _Float16 "
		            "(GCC >= 12, or clang >= 15, on x86-64 or arm64); rebuild with one (make CC=gcc-12)", opt, arg);
		return -1;
	}
	return 0;
}

int cli_shard(const char *opt, const char *arg, int *k, int *n)
{
	char tail;
	if (sscanf(arg, "%d/%d%c", k, n, &tail) != 2 || *n < 1 || *n > 1000000 || *k < 0 || *k >= *n) {
		study_error("%s: expected K/N, the 0-based slice K of N slices (0 <= K < N <= 1000000; "
		            "for Slurm: $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT with --array=0-(N-1)), not '%s'", opt, arg);
		return -1;
	}
	return 0;
}

int cli_format(const char *opt, const char *arg, int with_json)
{
	static const char *const names[] = { "table", "csv", "json" };
	return cli_choice(opt, arg, names, with_json ? 3 : 2);
}

void study_missing_shards(const unsigned char *seen, int n, char *buf, size_t len)
{
	int i, listed = 0;
	size_t used = 0;
	buf[0] = '\0';
	for (i = 0; i < n && used + 16 < len; i++)
		if (!seen[i]) {
			if (listed == 20) {
				snprintf(buf + used, len - used, ", ...");
				break;
			}
			used += (size_t)snprintf(buf + used, len - used, "%s%d", listed ? ", " : "", i);
			listed++;
		}
}
