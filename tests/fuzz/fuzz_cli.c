/*
 * fuzz_cli.c - libFuzzer harness for the command-line parsers.
 *
 * The first byte picks a target, the rest is split at NUL and newline
 * bytes into arguments (at most 32):
 *   0 cmd_list      the whole command (it only prints the registry)
 *   1 cmd_sweep     option parsing only, see below
 *   2 cmd_merge     option parsing only
 *   3 cmd_scene     option parsing only
 *   4 parse_u64, parse_int and parse_double on every argument, with
 *     bounds taken from the next bytes
 *
 * How a real sweep, merge or scene run is avoided without a parse-only
 * entry point: every argument vector gets two extra arguments,
 * "--onbfuzz-stop --onbfuzz-stop".  Each option of these commands takes at
 * most one value, so one of the two is always read as an option, and
 * being unknown it ends the command with exit 2 before any work (the
 * option loops have no side effects: no file is opened, no directory made).
 * The only exceptions are --help (prints usage, returns 0) and merge's
 * STATE arguments, which merge reads while parsing; to keep those reads
 * harmless every '/' in an argument is replaced by '_', so only names in
 * the current directory can be reached, and scripts/fuzz.sh and the replay
 * runner run in an empty scratch directory.
 * The harness checks that a command returns 0 (help), 2 (usage error).
 * Anything else (a crash, a sanitizer report, another status) is a finding.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "common/options.h"
#include "cli/list.h"
#include "sweep/sweep.h"
#include "scene/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAXARGS 32
#define STOP "--onbfuzz-stop"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *buf, *argv[MAXARGS + 3];
	int argc = 0, target, rc = 0;
	size_t i, start;
	if (size < 1 || size > 4096)
		return 0;
	target = data[0] % 5;
	buf = malloc(size); /* size - 1 bytes of arguments plus a final NUL */
	if (!buf)
		return 0;
	memcpy(buf, data + 1, size - 1);
	buf[size - 1] = '\0';
	for (i = 0, start = 0; i < size; i++) {
		if (i == size - 1 || buf[i] == '\0' || buf[i] == '\n') {
			buf[i] = '\0';
			if (argc < MAXARGS)
				argv[argc++] = buf + start;
			start = i + 1;
		} else if (buf[i] == '/') {
			buf[i] = '_';
		}
	}
	/* a trailing empty argument from the final NUL is dropped */
	if (argc > 0 && argv[argc - 1][0] == '\0' && (size == 1 || data[size - 1] == '\0' || data[size - 1] == '\n'))
		argc--;
	if (target == 4) {
		unsigned long long u, lo = 0, hi = ~0ull;
		long l, llo = -1000000000L, lhi = 1000000000L;
		double d;
		int k;
		if (size > 3) {
			lo = data[1] & 0x7f;
			hi = lo + ((unsigned long long)data[2] << (data[3] & 0x1f));
			llo = -(long)data[2];
			lhi = (long)data[3];
		}
		for (k = 0; k < argc; k++) {
			if (parse_u64("--fuzz", argv[k], lo, hi, &u) == 0 && (u < lo || u > hi))
				abort();
			if (parse_int("--fuzz", argv[k], llo, lhi, &l) == 0 && (l < llo || l > lhi))
				abort();
			(void)parse_double("--fuzz", argv[k], &d);
		}
		free(buf);
		return 0;
	}
	if (target != 0) {
		argv[argc++] = (char *)STOP;
		argv[argc++] = (char *)STOP;
	}
	argv[argc] = NULL;
	switch (target) {
	case 0: rc = cmd_list(argc, argv); break;
	case 1: rc = cmd_sweep(argc, argv); break;
	case 2: rc = cmd_merge(argc, argv); break;
	case 3: rc = cmd_scene(argc, argv); break;
	}
	if (rc != 0 && rc != ONB_EXIT_USAGE)
		abort();
	free(buf);
	return 0;
}
