/*
 * output.c - atomic result files and the provenance header of every data
 * file.
 */
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include <gmp.h>
#include <mpfr.h>
#include "common/output.h"
#include "common/options.h"

int study_mkdir_p(const char *dir)
{
	char buf[4096];
	size_t i, n = strlen(dir);
	if (n == 0 || n >= sizeof buf) {
		study_error("output directory name '%s' is empty or too long", dir);
		return -1;
	}
	memcpy(buf, dir, n + 1);
	for (i = 1; i <= n; i++) {
		if (buf[i] == '/' || buf[i] == '\0') {
			char c = buf[i];
			buf[i] = '\0';
			if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
				study_error("cannot create directory '%s': %s", buf, strerror(errno));
				return -1;
			}
			buf[i] = c;
		}
	}
	{
		struct stat st;
		if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
			study_error("'%s' is not a directory", dir);
			return -1;
		}
		if (access(dir, W_OK) != 0) {
			study_error("output directory '%s' is not writable: %s", dir, strerror(errno));
			return -1;
		}
	}
	return 0;
}

int study_out_open(study_out *o, const char *dir, const char *name)
{
	int w1, w2;
	memset(o, 0, sizeof *o);
	w1 = snprintf(o->path, sizeof o->path, "%s/%s", dir, name);
	w2 = snprintf(o->tmp, sizeof o->tmp, "%s/.%s.partial.%ld", dir, name, (long)getpid());
	if (w1 < 0 || w2 < 0 || (size_t)w1 >= sizeof o->path || (size_t)w2 >= sizeof o->tmp) {
		study_error("output path too long: '%s/%s'", dir, name);
		return -1;
	}
	o->f = fopen(o->tmp, "w");
	if (!o->f) {
		study_error("cannot write '%s': %s", o->tmp, strerror(errno));
		return -1;
	}
	return 0;
}

int study_out_commit(study_out *o)
{
	int bad = 0;
	if (!o->f)
		return -1;
	if (fflush(o->f) != 0 || ferror(o->f))
		bad = 1;
	if (!bad && fsync(fileno(o->f)) != 0)
		bad = 1;
	if (fclose(o->f) != 0)
		bad = 1;
	o->f = NULL;
	if (bad) {
		study_error("error writing '%s': %s (the earlier '%s' is untouched)", o->tmp, strerror(errno), o->path);
		unlink(o->tmp);
		return -1;
	}
	if (rename(o->tmp, o->path) != 0) {
		study_error("cannot rename '%s' to '%s': %s", o->tmp, o->path, strerror(errno));
		unlink(o->tmp);
		return -1;
	}
	return 0;
}

void study_out_abort(study_out *o)
{
	if (o->f) {
		fclose(o->f);
		o->f = NULL;
	}
	if (o->tmp[0])
		unlink(o->tmp);
}

const char *study_cpu_model(void)
{
	static char model[256];
	if (!model[0]) {
		FILE *f = fopen("/proc/cpuinfo", "r");
		char line[512];
		strcpy(model, "unknown");
		if (f) {
			while (fgets(line, sizeof line, f)) {
				if (strncmp(line, "model name", 10) == 0) {
					char *p = strchr(line, ':');
					if (p) {
						p++;
						while (*p == ' ' || *p == '\t')
							p++;
						p[strcspn(p, "\n")] = '\0';
						snprintf(model, sizeof model, "%s", p);
					}
					break;
				}
			}
			fclose(f);
		}
	}
	return model;
}

void study_default_run_dir(char *buf, size_t n)
{
	time_t t = time(NULL);
	struct tm tmv;
	char stamp[32];
	gmtime_r(&t, &tmv);
	strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tmv);
	snprintf(buf, n, "results/run-%s", stamp);
}

const char *study_provenance_note;

/* results/latest -> dir (a directory under results/), replaced atomically. */
void study_point_latest(const char *dir)
{
	const char *base = strrchr(dir, '/');
	if (!base || strncmp(dir, "results/", 8) != 0 || strchr(dir + 8, '/'))
		return;
	unlink("results/latest.tmp");
	if (symlink(base + 1, "results/latest.tmp") == 0)
		rename("results/latest.tmp", "results/latest");
}

void study_current_run_dir(char *buf, size_t n)
{
	char target[512];
	struct stat st;
	ssize_t len = readlink("results/latest", target, sizeof target - 1);
	if (len > 0 && stat("results/latest", &st) == 0 && S_ISDIR(st.st_mode)) {
		target[len] = '\0';
		if (target[0] == '/' || strncmp(target, "results/", 8) == 0)
			snprintf(buf, n, "%s", target);
		else
			snprintf(buf, n, "results/%s", target);
		return;
	}
	study_default_run_dir(buf, n);
	if (study_mkdir_p(buf) == 0)
		study_point_latest(buf);
}

void study_provenance(FILE *f, const char *what, unsigned long long seed, int threads)
{
	time_t t = time(NULL);
	struct tm tmv;
	char date[64];
	gmtime_r(&t, &tmv);
	strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &tmv);
	fprintf(f, "# onbstudy %s %s\n", ONB_VERSION, what);
	fprintf(f, "# revision: %s\n", ONB_GIT_REV);
	fprintf(f, "# compiler: %s\n", ONB_CC);
	fprintf(f, "# flags: %s\n", ONB_CFLAGS);
	fprintf(f, "# mpfr: %s (gmp %s)\n", mpfr_get_version(), gmp_version);
	fprintf(f, "# cpu: %s; batch isa: %s\n", study_cpu_model(), onb_batch_isa());
	fprintf(f, "# date: %s\n", date);
	fprintf(f, "# seed: %llu\n", seed);
	fprintf(f, "# threads: %d\n", threads);
	fprintf(f, "# command: %s\n", study_cmdline);
	if (study_provenance_note)
		fprintf(f, "# %s\n", study_provenance_note);
}

void study_csv_num(FILE *f, double v)
{
	if (isnan(v))
		fputs(",nan", f);
	else
		fprintf(f, ",%.6g", v);
}

double study_duration(double s, const char **unit)
{
	if (s < 120) {
		*unit = "s";
		return s;
	}
	if (s < 7200) {
		*unit = "min";
		return s / 60;
	}
	if (s < 172800) {
		*unit = "h";
		return s / 3600;
	}
	*unit = "days";
	return s / 86400;
}
