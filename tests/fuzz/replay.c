/*
 * replay.c - a plain main() for the libFuzzer harnesses, so the seed
 * corpus and every kept crash input (tests/fuzz/regressions/) run under
 * `make test` with gcc, no clang needed.  Arguments are files or
 * directories (every regular file in them, in name order); each file is
 * passed once to LLVMFuzzerTestOneInput.  A finding aborts the process
 * (the harness calls abort(), or a sanitizer stops it), so the exit status
 * says it all; the file being run is printed first with -v.
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int verbose;
static unsigned long ran;

static int run_file(const char *path)
{
	FILE *f = fopen(path, "rb");
	unsigned char *buf = NULL;
	size_t len = 0, cap = 0, r;
	if (!f) {
		fprintf(stderr, "replay: cannot open '%s'\n", path);
		return -1;
	}
	for (;;) {
		if (len == cap) {
			unsigned char *q;
			cap = cap ? 2 * cap : 4096;
			q = realloc(buf, cap);
			if (!q) {
				free(buf);
				fclose(f);
				fprintf(stderr, "replay: out of memory reading '%s'\n", path);
				return -1;
			}
			buf = q;
		}
		r = fread(buf + len, 1, cap - len, f);
		len += r;
		if (r == 0)
			break;
	}
	fclose(f);
	if (verbose)
		fprintf(stderr, "replay: %s (%zu bytes)\n", path, len);
	LLVMFuzzerTestOneInput(buf, len);
	free(buf);
	ran++;
	return 0;
}

static int cmp_str(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

static int run_path(const char *path)
{
	struct stat st;
	DIR *d;
	struct dirent *e;
	char **names = NULL;
	size_t n = 0, i;
	int rc = 0;
	if (stat(path, &st) != 0) {
		fprintf(stderr, "replay: cannot stat '%s'\n", path);
		return -1;
	}
	if (!S_ISDIR(st.st_mode))
		return run_file(path);
	d = opendir(path);
	if (!d) {
		fprintf(stderr, "replay: cannot open directory '%s'\n", path);
		return -1;
	}
	while ((e = readdir(d)) != NULL) {
		char full[4096], **q;
		struct stat fs;
		if (e->d_name[0] == '.')
			continue;
		snprintf(full, sizeof full, "%s/%s", path, e->d_name);
		if (stat(full, &fs) != 0 || !S_ISREG(fs.st_mode))
			continue;
		q = realloc(names, (n + 1) * sizeof *names);
		if (!q || !(q[n] = strdup(full))) {
			free(q ? q : names);
			closedir(d);
			return -1;
		}
		names = q;
		n++;
	}
	closedir(d);
	if (n)
		qsort(names, n, sizeof *names, cmp_str);
	for (i = 0; i < n; i++) {
		if (run_file(names[i]) != 0)
			rc = -1;
		free(names[i]);
	}
	free(names);
	return rc;
}

int main(int argc, char **argv)
{
	int k, rc = 0;
	for (k = 1; k < argc; k++) {
		if (!strcmp(argv[k], "-v")) {
			verbose = 1;
			continue;
		}
		if (run_path(argv[k]) != 0)
			rc = 1;
	}
	printf("replay: %lu inputs, no finding\n", ran);
	return rc;
}
