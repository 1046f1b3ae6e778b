/*
 * checkpoint.c - certify's checkpoint and keys files (checkpoint.h).
 *
 * The checkpoint: text lines (magic, settings, engine, sizes, one line per
 * group with its key), "data", then the flags, the base and the refined
 * results of every task as the machine holds them (the same binary reads
 * them back: sizes and a byte-order mark are checked), and an FNV-1a hash
 * of everything before it (a truncated or altered file is refused).
 */
#include <dirent.h>
#include <errno.h>
#include <inttypes.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "checkpoint.h"
#include "keys.h"
#include "common/output.h"
#include "common/options.h"
#include "common/prec.h"

#define CK_MAGIC "onbstudy certify checkpoint 1"
#define CK_BOM UINT64_C(0x0102030405060708)

/* The text head of s, into f, hashed into *h. */
static void put_text(FILE *f, uint64_t *h, const char *fmt, const char *a, long b, long c)
{
	char line[8192];
	snprintf(line, sizeof line, fmt, a, b, c);
	fputs(line, f);
	*h = cert_hash_bytes(*h, line, strlen(line));
}

static void put_bin(FILE *f, uint64_t *h, const void *p, size_t n)
{
	if (n)
		fwrite(p, 1, n, f);
	*h = cert_hash_bytes(*h, p, n);
}

int ck_write(const char *dir, const ck_state *s)
{
	study_out o;
	uint64_t h = CERT_FNV0, bom = CK_BOM;
	char gl[256];
	int g;
	if (study_out_open(&o, dir, CK_NAME))
		return -1;
	put_text(o.f, &h, CK_MAGIC "\nsettings %s\n", s->settings, 0, 0);
	put_text(o.f, &h, "engine %s\n", s->engine, 0, 0);
	put_text(o.f, &h, "sizes%s %ld %ld", "", (long)sizeof(cert_result), (long)s->nt);
	put_text(o.f, &h, "%s %ld\n", "", (long)s->ng, 0);
	for (g = 0; g < s->ng; g++) {
		snprintf(gl, sizeof gl, "group %s %s %016" PRIx64 "\n", s->g[g].name, prec_name(s->g[g].prec), s->g[g].key);
		put_text(o.f, &h, "%s", gl, 0, 0);
	}
	put_text(o.f, &h, "data\n%s", "", 0, 0);
	put_bin(o.f, &h, &bom, sizeof bom);
	put_bin(o.f, &h, s->flag, (size_t)s->nt);
	put_bin(o.f, &h, s->base, (size_t)s->nt * sizeof *s->base);
	put_bin(o.f, &h, s->ref, (size_t)s->nt * sizeof *s->ref);
	fwrite(&h, sizeof h, 1, o.f);
	if (ferror(o.f) || study_out_commit(&o)) {
		study_out_abort(&o);
		study_error("%s/%s: the checkpoint could not be written (disk full?); the last complete checkpoint is "
		            "kept: run again with --resume %s when there is room", dir, CK_NAME, dir);
		return -1;
	}
	return 0;
}

/* One text line of f into line (its newline dropped), hashed; -1 at the end. */
static int get_line(FILE *f, uint64_t *h, char *line, size_t cap)
{
	size_t n;
	if (!fgets(line, (int)cap, f))
		return -1;
	n = strlen(line);
	*h = cert_hash_bytes(*h, line, n);
	if (n && line[n - 1] == '\n')
		line[n - 1] = '\0';
	return 0;
}

/* The first word of a and b where they differ, as "X there, Y here". */
static void first_difference(const char *a, const char *b, char *out, size_t cap)
{
	char wa[512], wb[512];
	while (*a || *b) {
		size_t la = strcspn(a, " "), lb = strcspn(b, " ");
		if (la != lb || strncmp(a, b, la) != 0) {
			snprintf(wa, sizeof wa, "%.*s", (int)(la < 500 ? la : 500), a);
			snprintf(wb, sizeof wb, "%.*s", (int)(lb < 500 ? lb : 500), b);
			snprintf(out, cap, "%s there, %s here", *wa ? wa : "(nothing)", *wb ? wb : "(nothing)");
			return;
		}
		a += la + (a[la] == ' ');
		b += lb + (b[lb] == ' ');
	}
	snprintf(out, cap, "(no difference)");
}

/* A settings line of certify --precision half (certify_half.c), whose
   tasks are binary16 regions: never to be resumed as float or double's. */
static int is_half(const char *settings)
{
	return strncmp(settings, "precision=half ", 15) == 0;
}

/* The head of the checkpoint against s: 0, or -1 after a message. */
static int check_head(FILE *f, uint64_t *h, const char *path, const ck_state *s)
{
	char line[8192], want[8192], d[1200];
	long sz, nt, ng;
	int g;
	if (get_line(f, h, line, sizeof line) || strcmp(line, CK_MAGIC) != 0) {
		study_error("--resume: %s is no certify checkpoint (corrupted?)", path);
		return -1;
	}
	if (get_line(f, h, line, sizeof line) || strncmp(line, "settings ", 9) != 0) {
		study_error("--resume: %s: corrupted (no settings line)", path);
		return -1;
	}
	if (is_half(line + 9) != is_half(s->settings)) {
		study_error("--resume: %s is a checkpoint of certify --precision %s, and this run is --precision %s: "
		            "resume it with its own precision, or give this run another directory", path,
		            is_half(line + 9) ? "half" : "float, double or both", is_half(s->settings) ? "half" : "float, double or both");
		return -1;
	}
	if (strcmp(line + 9, s->settings) != 0) {
		first_difference(line + 9, s->settings, d, sizeof d);
		study_error("--resume: %s is from another command line: %s", path, d);
		return -1;
	}
	if (get_line(f, h, line, sizeof line) || strncmp(line, "engine ", 7) != 0 || strcmp(line + 7, s->engine) != 0) {
		study_error("--resume: %s is from another certify engine (source, compiler or MPFR): '%s' there, '%s' here",
		            path, strncmp(line, "engine ", 7) == 0 ? line + 7 : "?", s->engine);
		return -1;
	}
	if (get_line(f, h, line, sizeof line) || sscanf(line, "sizes %ld %ld %ld", &sz, &nt, &ng) != 3 ||
	    sz != (long)sizeof(cert_result)) {
		study_error("--resume: %s: corrupted, or written by another build (sizes '%s')", path, line);
		return -1;
	}
	if (ng != s->ng) {
		study_error("--resume: %s is from another command line: its methods differ (%ld methods and precisions "
		            "there, %d here)", path, ng, s->ng);
		return -1;
	}
	for (g = 0; g < s->ng; g++) {
		snprintf(want, sizeof want, "group %s %s %016" PRIx64, s->g[g].name, prec_name(s->g[g].prec), s->g[g].key);
		if (get_line(f, h, line, sizeof line) || strncmp(line, "group ", 6) != 0) {
			study_error("--resume: %s: corrupted (group %d)", path, g);
			return -1;
		}
		if (strcmp(line, want) != 0) {
			if (strncmp(line, want, strlen(want) - 16) == 0)
				study_error("--resume: %s is from another revision of %s %s's model or kernel (key %s there, "
				            "%016" PRIx64 " here)", path, s->g[g].name, prec_name(s->g[g].prec),
				            line + strlen(want) - 16, s->g[g].key);
			else
				study_error("--resume: %s is from another command line: its methods differ (%s there, %s %s here)",
				            path, line + 6, s->g[g].name, prec_name(s->g[g].prec));
			return -1;
		}
	}
	if (nt != s->nt || get_line(f, h, line, sizeof line) || strcmp(line, "data") != 0) {
		study_error("--resume: %s: corrupted (no data)", path);
		return -1;
	}
	return 0;
}

static int get_bin(FILE *f, uint64_t *h, void *p, size_t n)
{
	if (n && fread(p, 1, n, f) != n)
		return -1;
	*h = cert_hash_bytes(*h, p, n);
	return 0;
}

/* The partial checkpoints in dir (study_out's ".NAME.partial.PID") of a
   writer that is gone: one killed while it wrote (onbstudy-mpi's rank 0,
   SIGKILLed by mpirun in the middle of a write) left its partial file
   beside the last complete checkpoint; removed.  A live writer's is
   left alone. */
static void clean_partials(const char *dir)
{
	static const char head[] = "." CK_NAME ".partial.";
	char path[4096], *end;
	struct dirent *e;
	DIR *d = opendir(dir);
	while (d && (e = readdir(d)) != NULL) {
		long pid;
		if (strncmp(e->d_name, head, sizeof head - 1) != 0)
			continue;
		pid = strtol(e->d_name + sizeof head - 1, &end, 10);
		if (*end || pid <= 0 || kill((pid_t)pid, 0) == 0 || errno != ESRCH)
			continue;
		if (snprintf(path, sizeof path, "%s/%s", dir, e->d_name) < (int)sizeof path)
			remove(path);
	}
	if (d)
		closedir(d);
}

int ck_read(const char *dir, ck_state *s)
{
	char path[4096];
	uint64_t h = CERT_FNV0, bom = 0, sum = 0;
	FILE *f;
	int bad;
	if (snprintf(path, sizeof path, "%s/%s", dir, CK_NAME) >= (int)sizeof path)
		return -1;
	clean_partials(dir);
	if (!(f = fopen(path, "rb"))) {
		if (errno == ENOENT)
			return 1;
		study_error("--resume: cannot read %s: %s", path, strerror(errno));
		return -1;
	}
	if (check_head(f, &h, path, s)) {
		fclose(f);
		return -1;
	}
	bad = get_bin(f, &h, &bom, sizeof bom) || bom != CK_BOM || get_bin(f, &h, s->flag, (size_t)s->nt) ||
	      get_bin(f, &h, s->base, (size_t)s->nt * sizeof *s->base) ||
	      get_bin(f, &h, s->ref, (size_t)s->nt * sizeof *s->ref) || fread(&sum, sizeof sum, 1, f) != 1 ||
	      sum != h || fgetc(f) != EOF;
	fclose(f);
	if (bad) {
		study_error("--resume: %s is corrupted (truncated, or its checksum does not match)", path);
		return -1;
	}
	return 0;
}

int keys_write(const char *dir, const ck_state *s, const char *cmd)
{
	study_out o;
	int g;
	if (study_out_open(&o, dir, KEYS_NAME))
		return -1;
	fprintf(o.f, "# onbstudy certify keys: what determined each method and precision's results in certify.csv "
	        "(src/certify/keys.h)\n# command: %s\n# settings %s\n# engine %s\nmethod,precision,key\n", cmd,
	        s->settings, s->engine);
	for (g = 0; g < s->ng; g++)
		fprintf(o.f, "%s,%s,%016" PRIx64 "\n", s->g[g].name, prec_name(s->g[g].prec), s->g[g].key);
	if (ferror(o.f) || study_out_commit(&o)) {
		study_out_abort(&o);
		study_error("%s/%s: write failed", dir, KEYS_NAME);
		return -1;
	}
	return 0;
}

/* Group g's line in the keys file's rows (method,precision,key). */
static int key_of(char (*rows)[128], int nr, const ck_group *g, uint64_t *key)
{
	char head[100];
	int i, n = snprintf(head, sizeof head, "%s,%s,", g->name, prec_name(g->prec));
	for (i = 0; i < nr; i++)
		if (strncmp(rows[i], head, (size_t)n) == 0 && sscanf(rows[i] + n, "%" SCNx64, key) == 1)
			return 1;
	return 0;
}

int keys_compare(const char *dir, const ck_state *s, int *cur, int quiet)
{
	char path[4096], line[8192], d[1200], (*rows)[128] = NULL;
	int nr = 0, g, rc = 0;
	FILE *f;
	if (snprintf(path, sizeof path, "%s/%s", dir, KEYS_NAME) >= (int)sizeof path || !(f = fopen(path, "r")))
		return -1;
	rows = malloc((size_t)(s->ng + 1024) * sizeof *rows);
	while (rows && fgets(line, sizeof line, f)) {
		line[strcspn(line, "\n")] = '\0';
		if (strncmp(line, "# settings ", 11) == 0 && strcmp(line + 11, s->settings) != 0) {
			first_difference(line + 11, s->settings, d, sizeof d);
			if (!quiet)
				study_error("%s is from another command line: %s", path, d);
			rc = 1;
		} else if (strncmp(line, "# engine ", 9) == 0 && strcmp(line + 9, s->engine) != 0) {
			if (!quiet)
				study_error("%s is from another certify engine: '%s' there, '%s' here", path, line + 9, s->engine);
			rc = 1;
		} else if (line[0] != '#' && nr < s->ng + 1024) {
			snprintf(rows[nr++], sizeof *rows, "%.120s", line);
		}
	}
	fclose(f);
	for (g = 0; g < s->ng; g++) {
		uint64_t k;
		cur[g] = rows && key_of(rows, nr, &s->g[g], &k) && k == s->g[g].key;
	}
	free(rows);
	return rows ? rc : -1;
}
