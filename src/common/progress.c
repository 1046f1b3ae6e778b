/*
 * progress.c - the progress line (see progress.h).
 */
#include <stdio.h>
#include <time.h>
#include "common/progress.h"
#include "common/output.h"

double study_now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double study_thread_cpu(void)
{
#ifdef CLOCK_THREAD_CPUTIME_ID
	struct timespec ts;
	if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) == 0)
		return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
#endif
	return study_now();
}

/* Fixed width: "  42 s  ", " 3.2 min", " 1.5 h  ", " 2.0 days". */
static void print_eta(double s)
{
	const char *unit;
	const double v = study_duration(s, &unit);
	fprintf(stderr, v == s ? "%4.0f %-3s" : "%4.1f %-3s", v, unit);
}

void study_progress_line(const char *label, const study_progress *pr)
{
	const double el = study_now() - pr->t0;
	const unsigned long long fresh = pr->done > pr->skipped ? pr->done - pr->skipped : 0;
	fprintf(stderr, "\r%-24s %5.1f%%  ETA ", label, 100.0 * (double)pr->done / (double)(pr->total ? pr->total : 1));
	if (fresh > 0 && el > 0.5)
		print_eta(el * (double)(pr->total > pr->done ? pr->total - pr->done : 0) / (double)fresh);
	else
		fprintf(stderr, "   ?     ");
}
