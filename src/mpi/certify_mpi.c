/*
 * certify_mpi.c - `mpirun -n N onbstudy-mpi certify [the options of
 * certify]`: `onbstudy certify` (src/certify/certify.c) with its regions
 * spread over MPI ranks, OpenMP threads in each.
 *
 * Every rank runs cmd_certify in step (certify.h: cert_dist).  In each
 * pass (the regions' first pass, the images pass, each round of the
 * refinement) rank 0's main thread is a work queue: it hands the pass's
 * tasks out one at a time, in the single-process order, to whichever
 * thread asks (every thread of every other rank asks for its next task
 * when it sends its last result), so a rank that draws the costly polar
 * regions takes fewer; rank 0's own threads take from the same queue.
 * Rank 0 commits every result as onbstudy does (the results, the
 * checkpoint of --resume DIR: the same file, so a run of either driver
 * resumes with the other), and at the end of a pass every rank gets rank
 * 0's results, so the next pass (the images pool, the refinement's
 * picks) starts from the same state everywhere.  A region's result does
 * not depend on the thread, rank or order that computed it, so
 * certify.csv's rows are those of `onbstudy certify` for any number of
 * ranks and threads (tests/certify_mpi.sh).
 *
 * A rank that dies ends the job (Open MPI's mpirun names it); the regions
 * it had in flight were never committed, so the same command line with
 * --resume DIR redoes them.  Ranks other than 0 print nothing.
 */
#include <mpi.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <fcntl.h>
#include <sys/resource.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "certify/certify.h"
#include "common/output.h"
#include "common/options.h"
#include "common/progress.h"
#include "certify_mpi.h"

enum { TAG_DONE = 21, TAG_TASK = 22 };

/* A worker thread's message: its team size, and the result of task j
   (j = -1: ready for a first task, no result). */
typedef struct {
	int32_t j, team;
	cert_result r;
} msg_t;

static int rank, nranks, threads_ok;   /* threads_ok: MPI_THREAD_SERIALIZED: every thread may ask */
static char note[160];
static long *ran;   /* rank 0: the tasks each rank computed, over every pass */

/* Rank 0's queue of a pass: the tasks already done (run here: no work,
   or the copy of a refined result) and those to hand out. */
typedef struct {
	const cert_pass *p;
	int *skip, *todo;
	int nskip, ntodo, nexts, nextt;
	pthread_mutex_t mu;
	int local_done, fail;
} queue;

static int task_of(const cert_pass *p, int j) { return p->pick ? p->pick[j] : j; }

/* The next task: a done one first for rank 0's threads (local), then the
   next to do; -1 when none is left or the run stops. */
static int take(queue *q, int local)
{
	int j = -1;
	pthread_mutex_lock(&q->mu);
	if (local && q->nexts < q->nskip)
		j = q->skip[q->nexts++];
	else if (q->nextt < q->ntodo && !*q->p->failed)
		j = q->todo[q->nextt++];
	pthread_mutex_unlock(&q->mu);
	return j;
}

static void *local_threads(void *arg)
{
	queue *q = arg;
	int fail = 0;
#pragma omp parallel
	{
		cert_ctx *x = cert_ctx_new();
		int j;
		if (!x) {
#pragma omp atomic write
			fail = 1;
		}
		while (x && (j = take(q, 1)) >= 0) {
			const int work = !(q->p->flags[task_of(q->p, j)] & q->p->flag);
			q->p->fn(x, j, q->p->arg);
			if (work)
#pragma omp atomic
				ran[0]++;
		}
		cert_ctx_free(x);
	}
	pthread_mutex_lock(&q->mu);
	q->fail = fail;
	q->local_done = 1;
	pthread_mutex_unlock(&q->mu);
	return NULL;
}

/* Rank 0: serve the other ranks' threads until every task is committed
   and every thread has been told the pass is over. */
static void serve(queue *q, int *team, int *ended)
{
	const struct timespec nap = { 0, 500000 };
	msg_t m;
	for (;;) {
		MPI_Status s;
		int flag, r, over;
		int32_t j;
		MPI_Iprobe(MPI_ANY_SOURCE, TAG_DONE, MPI_COMM_WORLD, &flag, &s);
		if (flag) {
			MPI_Recv(&m, (int)sizeof m, MPI_BYTE, s.MPI_SOURCE, TAG_DONE, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
			if (m.j >= 0 && m.j < q->p->n) {
				q->p->commit(q->p->arg, task_of(q->p, m.j), &m.r);
				ran[s.MPI_SOURCE]++;
			}
			team[s.MPI_SOURCE] = m.team;
			j = take(q, 0);
			MPI_Send(&j, 1, MPI_INT32_T, s.MPI_SOURCE, TAG_TASK, MPI_COMM_WORLD);
			ended[s.MPI_SOURCE] += j < 0;
			continue;
		}
		pthread_mutex_lock(&q->mu);
		over = q->local_done;
		pthread_mutex_unlock(&q->mu);
		for (r = 1; r < nranks && over; r++)
			over = team[r] > 0 && ended[r] == team[r];
		if (over)
			return;
		nanosleep(&nap, NULL);
	}
}

static int run_rank0(const cert_pass *p)
{
	queue q;
	pthread_t th;
	int *team = calloc((size_t)nranks, sizeof *team), *ended = calloc((size_t)nranks, sizeof *ended), j;
	memset(&q, 0, sizeof q);
	q.p = p;
	q.skip = malloc(((size_t)p->n + 1) * sizeof *q.skip);
	q.todo = malloc(((size_t)p->n + 1) * sizeof *q.todo);
	if (!team || !ended || !q.skip || !q.todo) {
		study_error("out of memory");
		MPI_Abort(MPI_COMM_WORLD, 1);
	}
	for (j = 0; j < p->n; j++) {
		if (p->flags[task_of(p, j)] & p->flag)
			q.skip[q.nskip++] = j;
		else
			q.todo[q.ntodo++] = j;
	}
	pthread_mutex_init(&q.mu, NULL);
	if (pthread_create(&th, NULL, local_threads, &q) != 0) {
		study_error("cannot start rank 0's threads");
		MPI_Abort(MPI_COMM_WORLD, 1);
	}
	serve(&q, team, ended);
	pthread_join(th, NULL);
	pthread_mutex_destroy(&q.mu);
	free(team); free(ended); free(q.skip); free(q.todo);
	return q.fail;
}

/* Another rank: each thread asks rank 0 for a task with its last result
   (MPI_THREAD_SERIALIZED: one thread at a time talks to rank 0). */
static int run_worker(const cert_pass *p)
{
	int fail = 0, nt = 1;
#ifdef _OPENMP
	nt = threads_ok ? omp_get_max_threads() : 1;
#endif
#pragma omp parallel num_threads(nt)
	{
		cert_ctx *x = cert_ctx_new();
		msg_t *m = calloc(1, sizeof *m);
		int32_t j = 0;
		if (!x || !m) {
			fprintf(stderr, "onbstudy-mpi: rank %d: out of memory\n", rank);
			MPI_Abort(MPI_COMM_WORLD, 1);
		}
		m->j = -1;
#ifdef _OPENMP
		m->team = omp_get_num_threads();
#else
		m->team = 1;
#endif
		while (j >= 0) {
#pragma omp critical(cert_mpi)
			{
				MPI_Send(m, (int)sizeof *m, MPI_BYTE, 0, TAG_DONE, MPI_COMM_WORLD);
				MPI_Recv(&j, 1, MPI_INT32_T, 0, TAG_TASK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
			}
			if (j >= 0) {
				p->fn(x, j, p->arg);
				m->j = j;
				m->r = p->res[task_of(p, j)];
			}
		}
		free(m);
		cert_ctx_free(x);
	}
	return fail;
}

static void share(void *p, size_t n)
{
	unsigned char *c = p;
	while (n > 0) {
		const int k = n > (1u << 30) ? 1 << 30 : (int)n;
		MPI_Bcast(c, k, MPI_BYTE, 0, MPI_COMM_WORLD);
		c += k;
		n -= (size_t)k;
	}
}

static int agree(int rc)
{
	int all = rc;
	MPI_Allreduce(&rc, &all, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
	return all;
}

/* A pass over every rank; then rank 0's results, flags and stop to all. */
static int run_pass(const cert_pass *p)
{
	int fail = rank == 0 ? run_rank0(p) : run_worker(p);
	share(p->res, (size_t)p->nres * sizeof *p->res);
	share(p->flags, (size_t)p->nres);
	share(p->failed, sizeof *p->failed);
	return agree(fail) ? -1 : 0;
}

static double cpu_seconds(void)
{
	struct rusage u;
	if (getrusage(RUSAGE_SELF, &u) != 0)
		return 0.0;
	return (double)u.ru_utime.tv_sec + 1e-6 * (double)u.ru_utime.tv_usec +
	       (double)u.ru_stime.tv_sec + 1e-6 * (double)u.ru_stime.tv_usec;
}

/* Rank 0, at the end: the wall and CPU seconds of the run and the regions
   each rank computed (the measured scaling: scripts/certify-mpi-scaling.sh). */
static void report(double wall, double cpu, int t)
{
	int r;
	fprintf(stderr, "onbstudy-mpi: certify on %d ranks x %d threads: %.2f s wall, %.2f CPU seconds in all ranks; "
	        "regions computed per rank (every pass):", nranks, t, wall, cpu);
	for (r = 0; r < nranks; r++)
		fprintf(stderr, " %ld", ran[r]);
	fprintf(stderr, "\n");
}

int certify_mpi(int argc, char **argv, int rank_, int nranks_, int provided)
{
	static cert_dist d;
	int t = 1, rc, saved = -1;
	double t0, cpu, wall;
	rank = rank_;
	nranks = nranks_;
	threads_ok = provided >= MPI_THREAD_SERIALIZED;
#ifdef _OPENMP
	t = omp_get_max_threads();
#endif
	snprintf(note, sizeof note, "mpi: %d ranks x %d threads (certify: a work queue of regions on rank 0)", nranks,
	         t);
	d.rank = rank;
	d.run = run_pass;
	d.share = share;
	d.agree = agree;
	d.note = note;
	cert_distribute = &d;
	study_provenance_note = note;
	if (rank != 0) {   /* one voice: rank 0's */
		int nul = open("/dev/null", O_WRONLY);
		fflush(stdout);
		fflush(stderr);
		saved = dup(2);
		dup2(nul, 1);
		dup2(nul, 2);
		close(nul);
	}
	ran = calloc((size_t)nranks, sizeof *ran);
	if (!ran) {
		study_error("out of memory");
		return 1;
	}
	t0 = study_now();
	cpu = cpu_seconds();
	rc = cmd_certify(argc, argv);
	wall = study_now() - t0;
	cpu = cpu_seconds() - cpu;
	MPI_Allreduce(MPI_IN_PLACE, &cpu, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
	if (rank == 0 && rc == 0)
		report(wall, cpu, t);
	free(ran);
	if (saved >= 0) {
		fflush(stdout);
		fflush(stderr);
		dup2(saved, 2);
		close(saved);
	}
	return agree(rc);
}
