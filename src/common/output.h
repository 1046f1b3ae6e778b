/*
 * common/output.h - atomic result files, run directories and the provenance
 * header of every data file (output.c).
 */
#ifndef ONB_COMMON_OUTPUT_H
#define ONB_COMMON_OUTPUT_H

#include <stdio.h>
#include <stddef.h>

#ifndef ONB_GIT_REV
#define ONB_GIT_REV "unknown"
#endif
#ifndef ONB_CC
#define ONB_CC "unknown"
#endif
#ifndef ONB_CFLAGS
#define ONB_CFLAGS "unknown"
#endif

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
/* One CSV cell: ",%.6g" of v, or ",nan". */
void study_csv_num(FILE *f, double v);
/* A duration for people: s in seconds (under 120), minutes (under 2 h),
   hours (under 2 days) or days; returns the value, *unit its unit. */
double study_duration(double s, const char **unit);
/* results/latest -> DIR (only for a directory directly under results/). */
void study_point_latest(const char *dir);

#endif
