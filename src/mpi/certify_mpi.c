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
 * A rank that dies ends the job: mpirun names it and sends SIGTERM to the
 * others, SIGKILL a second later (odls_base_sigkill_timeout).  Rank 0
 * then (stop_report, on a thread of its own, whatever the main thread
 * waits for) stops committing, names the rank that is gone (on its own
 * node) and every region in flight, lost, writes the checkpoint of
 * every result committed so far (to --resume DIR, or else to the run's
 * directory: certify.h's cert_stop_save), says how to continue, and exits
 * 1; certify.csv is written at the end only, whole or not at all.  The
 * other ranks end a second after mpirun's SIGTERM (SIGALRM), so that the
 * rank that died is the one gone.  Ranks other than 0 print nothing.
 */
#include <mpi.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <errno.h>
#include <fcntl.h>
#include <semaphore.h>
#include <signal.h>
#include <sys/resource.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "certify/certify.h"
#include "certify/checkpoint.h"
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
	int *holder;        /* per task j: the rank computing it, or -1 */
	int nskip, ntodo, nexts, nextt;
	pthread_mutex_t mu;
	int local_done, fail;
} queue;

static int task_of(const cert_pass *p, int j) { return p->pick ? p->pick[j] : j; }

/* Rank 0: the pass under way (stop_report reads its holders). */
static pthread_mutex_t live_mu = PTHREAD_MUTEX_INITIALIZER;
static queue *live_q;

/* The next task for rank who: a done one first for rank 0's threads,
   then the next to do; -1 when none is left or the run stops. */
static int take(queue *q, int who)
{
	int j = -1;
	pthread_mutex_lock(&q->mu);
	if (who == 0 && q->nexts < q->nskip)
		j = q->skip[q->nexts++];
	else if (q->nextt < q->ntodo && !*q->p->failed) {
		j = q->todo[q->nextt++];
		q->holder[j] = who;
	}
	pthread_mutex_unlock(&q->mu);
	return j;
}

/* Task j is no longer in flight (committed, or done already). */
static void release(queue *q, int j)
{
	pthread_mutex_lock(&q->mu);
	q->holder[j] = -1;
	pthread_mutex_unlock(&q->mu);
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
		while (x && (j = take(q, 0)) >= 0) {
			const int work = !(q->p->flags[task_of(q->p, j)] & q->p->flag);
			q->p->fn(x, j, q->p->arg);
			release(q, j);
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
				release(q, m.j);
				ran[s.MPI_SOURCE]++;
			}
			team[s.MPI_SOURCE] = m.team;
			j = take(q, s.MPI_SOURCE);
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
	q.holder = malloc(((size_t)p->n + 1) * sizeof *q.holder);
	if (!team || !ended || !q.skip || !q.todo || !q.holder) {
		study_error("out of memory");
		MPI_Abort(MPI_COMM_WORLD, 1);
	}
	for (j = 0; j < p->n; j++) {
		q.holder[j] = -1;
		if (p->flags[task_of(p, j)] & p->flag)
			q.skip[q.nskip++] = j;
		else
			q.todo[q.ntodo++] = j;
	}
	pthread_mutex_init(&q.mu, NULL);
	pthread_mutex_lock(&live_mu);
	live_q = &q;
	pthread_mutex_unlock(&live_mu);
	if (pthread_create(&th, NULL, local_threads, &q) != 0) {
		study_error("cannot start rank 0's threads");
		MPI_Abort(MPI_COMM_WORLD, 1);
	}
	serve(&q, team, ended);
	pthread_join(th, NULL);
	pthread_mutex_lock(&live_mu);
	live_q = NULL;
	pthread_mutex_unlock(&live_mu);
	pthread_mutex_destroy(&q.mu);
	free(team); free(ended); free(q.skip); free(q.todo); free(q.holder);
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

/* The job being ended (SIGTERM, SIGINT): rank 0's report. */
static volatile sig_atomic_t stop_sig, stop_from;
static sem_t stop_sem;
static int watching, reporting, watch_over;   /* under live_mu */
typedef struct {
	int32_t pid;
	char host[64];
} where_t;
static where_t *where;   /* rank 0: every rank's pid and host */

static void on_stop(int sig, siginfo_t *si, void *ctx)
{
	(void)ctx;
	if (rank != 0) {
		if (si && si->si_pid == getppid()) {
			alarm(1);   /* mpirun ends the job: ended by SIGALRM a second later, so that the rank that died is the one gone */
			return;
		}
		signal(sig, SIG_DFL);
		raise(sig);
		return;
	}
	stop_sig = sig;
	stop_from = si ? (sig_atomic_t)si->si_pid : 0;
	sem_post(&stop_sem);
}

/* Process pid (on this node) has ended: no such process, or a zombie. */
static int gone(long pid)
{
	char path[64], buf[512], *p;
	FILE *f;
	size_t n;
	if (kill((pid_t)pid, 0) != 0)
		return errno == ESRCH;
	snprintf(path, sizeof path, "/proc/%ld/stat", pid);
	if (!(f = fopen(path, "r")))
		return 0;
	n = fread(buf, 1, sizeof buf - 1, f);
	fclose(f);
	buf[n] = 0;
	p = strrchr(buf, ')');
	return p && p[1] == ' ' && (p[2] == 'Z' || p[2] == 'X');
}

static const char *pass_name(int flag)
{
	return flag == CK_RUN ? "the first pass" : flag == CK_IMAGES ? "the images pass" : "the refinement";
}

/* The regions in flight in the pass under way, lost (after
   cert_stop_save: no more commits); how many. */
static int report_lost(void)
{
	char name[320];
	int j, n = 0;
	pthread_mutex_lock(&live_mu);
	if (live_q) {
		queue *q = live_q;
		pthread_mutex_lock(&q->mu);
		for (j = 0; j < q->p->n; j++)
			if (q->holder[j] >= 0 && !(q->p->flags[task_of(q->p, j)] & q->p->flag)) {
				cert_task_name(task_of(q->p, j), name, sizeof name);
				fprintf(stderr, "onbstudy-mpi: lost, in flight on rank %d in %s: %s\n", q->holder[j],
				        pass_name(q->p->flag), name);
				n++;
			}
		pthread_mutex_unlock(&q->mu);
	}
	pthread_mutex_unlock(&live_mu);
	return n;
}

/* Rank 0, the job being ended: who is gone, what is lost, what is kept,
   how to continue; then exit 1. */
static void stop_report(void)
{
	char host[64] = "";
	cert_saved v;
	int r, rc;
	fprintf(stderr, "onbstudy-mpi: signal %d from pid %ld: the job is being ended (a rank died, or mpirun was "
	        "stopped)\n", (int)stop_sig, (long)stop_from);
	gethostname(host, sizeof host - 1);
	for (r = 1; where && r < nranks; r++)
		if (strcmp(where[r].host, host) == 0 && gone(where[r].pid))
			fprintf(stderr, "onbstudy-mpi: rank %d (pid %ld, this node) has died\n", r, (long)where[r].pid);
	rc = cert_stop(&v);   /* no more commits: what is in flight now is lost */
	if (report_lost() == 0)
		fprintf(stderr, "onbstudy-mpi: no region was in flight\n");
	if (rc == 1) {
		fprintf(stderr, "onbstudy-mpi: no pass of regions was under way; certify.csv not written\n");
		return;
	}
	if (v.resume)
		fprintf(stderr, "onbstudy-mpi: to continue: the same command line (--resume %s redoes only what its "
		        "checkpoint lacks)\n", v.dir);
	else
		fprintf(stderr, "onbstudy-mpi: to continue: the same command line with --resume %s in place of --out "
		        "(it redoes only what the checkpoint lacks)\n", v.dir);
	fflush(stderr);
	if (cert_stop_save() == 0)
		fprintf(stderr, "onbstudy-mpi: kept in %s/%s: every result committed so far (first pass: %d of %d "
		        "regions, images pass: %d, refined: %d); certify.csv not written\n", v.dir, CK_NAME, v.run, v.nt,
		        v.images, v.refined);
	else
		fprintf(stderr, "onbstudy-mpi: the checkpoint could not be written; the last complete one in %s, if "
		        "any, is intact; certify.csv not written\n", v.dir);
}

static void *watch(void *arg)
{
	int go;
	(void)arg;
	while (sem_wait(&stop_sem) != 0 && errno == EINTR)
		;
	pthread_mutex_lock(&live_mu);
	go = !watch_over;
	reporting = go;
	pthread_mutex_unlock(&live_mu);
	if (!go)
		return NULL;
	stop_report();
	fflush(stderr);
	_exit(1);
}

/* Every rank's pid and host to rank 0; the handlers; rank 0's watcher. */
static void watch_start(void)
{
	struct sigaction sa;
	where_t me;
	pthread_t th;
	memset(&me, 0, sizeof me);
	me.pid = (int32_t)getpid();
	gethostname(me.host, sizeof me.host - 1);
	where = rank == 0 ? calloc((size_t)nranks, sizeof *where) : NULL;
	MPI_Gather(&me, (int)sizeof me, MPI_BYTE, where, (int)sizeof me, MPI_BYTE, 0, MPI_COMM_WORLD);
	if (rank == 0 && (sem_init(&stop_sem, 0, 0) != 0 || pthread_create(&th, NULL, watch, NULL) != 0 ||
	                  pthread_detach(th) != 0))
		return;   /* no report: the job ends as before, by the signal */
	memset(&sa, 0, sizeof sa);
	sa.sa_sigaction = on_stop;
	sa.sa_flags = SA_SIGINFO | SA_RESTART;
	sigemptyset(&sa.sa_mask);
	sigaction(SIGTERM, &sa, NULL);
	sigaction(SIGINT, &sa, NULL);
	watching = rank == 0;
}

/* The end of a run: the watcher told to go, unless it is reporting (then
   it ends the process). */
static void watch_end(void)
{
	int wait_report;
	if (!watching)
		return;
	pthread_mutex_lock(&live_mu);
	wait_report = reporting;
	watch_over = 1;
	pthread_mutex_unlock(&live_mu);
	if (wait_report)
		for (;;)
			pause();
	sem_post(&stop_sem);
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
	watch_start();
	t0 = study_now();
	cpu = cpu_seconds();
	rc = cmd_certify(argc, argv);
	watch_end();
	wall = study_now() - t0;
	cpu = cpu_seconds() - cpu;
	MPI_Allreduce(MPI_IN_PLACE, &cpu, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
	if (rank == 0 && rc == 0)
		report(wall, cpu, t);
	free(ran);
	free(where);
	if (saved >= 0) {
		fflush(stdout);
		fflush(stderr);
		dup2(saved, 2);
		close(saved);
	}
	return agree(rc);
}
