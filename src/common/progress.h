/*
 * common/progress.h - the progress line of long commands (sweep, certify,
 * the MPI driver): "\r<label> <pct> ETA ..." on stderr (progress.c).
 */
#ifndef ONB_COMMON_PROGRESS_H
#define ONB_COMMON_PROGRESS_H

/* The work done so far; whoever runs adds to done (the sweep's engine, one
   thread of it printing), and prints when bar is set. */
typedef struct {
	int bar;                       /* print the progress line */
	double t0;                     /* study_now() at the start */
	unsigned long long done;       /* units of work completed */
	unsigned long long total;      /* of the whole run */
	unsigned long long skipped;    /* done before t0 (resumed chunks): not in the rate */
} study_progress;

double study_now(void);                              /* monotonic seconds */
/* CPU seconds of the calling thread (its own work, whatever the load of
   the machine); study_now() where the system has no thread clock. */
double study_thread_cpu(void);
/* "\r<label> 42.0%  ETA 3.2 min" on stderr. */
void   study_progress_line(const char *label, const study_progress *pr);

#endif
