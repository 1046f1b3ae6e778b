/*
 * onbstudy_mpi.c - `mpirun -n N onbstudy-mpi sweep [the options of sweep]`
 * (and `certify`: certify_mpi.c):
 * the sweep of src/sweep/sweep.c over MPI ranks, with OpenMP threads in
 * each rank, checkpoints and --resume.  Built by `make mpi` (mpicc); the
 * default build does not need MPI.
 *
 * The run's global chunks (plan.h) are cut into batches of B chunks.  Rank
 * 0 is the master: its main thread hands batches out on request, one at a
 * time, so a slower rank takes fewer; a second thread of rank 0 works
 * through batches too.  Every worker runs its batch with the same engine
 * as `onbstudy sweep` (engine_run, OpenMP inside) into an empty state and
 * sends that state's slice (the cells the batch touched, the grid cells it
 * computed) to rank 0, which adds it to the run's accumulators
 * (cell_merge: exact fixed-point sums, maxima, ordered worst lists).  The
 * total is independent of the order and the grouping, so the files rank 0
 * writes are byte-identical to the single-process sweep's.
 *
 * Checkpoints: rank 0 writes DIR/sweep-checkpoint.bin (the accumulators and
 * the list of done batches, atomically renamed) after each batch it adds,
 * at most every --checkpoint-every S seconds (default 0: every batch).  A
 * run that loses a rank (the whole MPI job ends) or is cancelled restarts
 * with `--resume DIR` and redoes only the batches that were in flight (and,
 * with S > 0, those added since the last checkpoint).  With no checkpoint
 * in DIR yet, --resume DIR starts from the beginning (and says so), so a
 * scheduler can requeue the same command line however early the job died.
 */
#include <mpi.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>
#include <fcntl.h>
#include <errno.h>
#include <sys/resource.h>
#include "sweep/engine.h"
#include "common/options.h"
#include "common/output.h"
#include "sweep/sweep.h"
#include "certify_mpi.h"

#define CKPT_NAME "sweep-checkpoint.bin"
#define CKPT_MAGIC "onbckpt1"
enum { TAG_RESULT = 11, TAG_WORK = 12 };

typedef struct {
	const char *resume;            /* --resume DIR */
	double ckpt_every;             /* --checkpoint-every S */
	long batch;                    /* --batch C (0: automatic) */
} mpi_opts;

/* What a worker sends after a batch (then the cells, then the grid). */
typedef struct {
	int64_t batch;                 /* -1: no batch (ready for the first) */
	uint64_t lo, hi;               /* cells [lo, hi) of the state */
	int64_t grid;                  /* 1: the grid arrays follow */
	sweep_cfg cfg;                 /* the batch's counters (evals, checked, reference path) */
} delta_hdr;

typedef struct {
	char magic[16];
	uint64_t batch, nbatches;
} ckpt_hdr;

typedef struct {
	sweep_plan pl;
	mpi_opts mo;
	engine *e;
	sweep_state acc;               /* rank 0: every batch added so far */
	uint64_t B, nbatches, next;
	unsigned char *done;           /* rank 0: [nbatches] */
	pthread_mutex_t mu;
	int local_active, fail, dirty;
	unsigned long long evals_done, evals_resumed;
	double t0, t_ckpt, t_progress;
	double cpu0, cpu;              /* this process's CPU seconds at t0; all ranks' (rank 0) */
} run_t;

static int rank, nranks;
static char prov_note[256];

static double cpu_seconds(void)
{
	struct rusage u;
	if (getrusage(RUSAGE_SELF, &u) != 0)
		return 0.0;
	return (double)u.ru_utime.tv_sec + 1e-6 * (double)u.ru_utime.tv_usec +
	       (double)u.ru_stime.tv_sec + 1e-6 * (double)u.ru_stime.tv_usec;
}

/* Every rank's CPU seconds since t0, summed on rank 0 (collective). */
static void sum_cpu(run_t *r)
{
	double mine = cpu_seconds() - r->cpu0;
	MPI_Reduce(&mine, &r->cpu, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
}

static void on_signal(int sig) { (void)sig; engine_stop = 1; }

static void die_all(int code) { MPI_Abort(MPI_COMM_WORLD, code); exit(code); }

/* ---- identity: the same binary and command line on every rank ---------- */

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
	const unsigned char *c = p;
	size_t i;
	for (i = 0; i < n; i++)
		h = (h ^ c[i]) * 1099511628211ull;
	return h;
}

static uint64_t binary_hash(void)
{
	unsigned char buf[65536];
	uint64_t h = 14695981039346656037ull;
	ssize_t r;
	int fd = open("/proc/self/exe", O_RDONLY);
	if (fd < 0)
		return fnv(h, ONB_GIT_REV, strlen(ONB_GIT_REV));
	while ((r = read(fd, buf, sizeof buf)) > 0)
		h = fnv(h, buf, (size_t)r);
	close(fd);
	return h;
}

/* 0 if every rank has the same binary and arguments; else every rank
   returns 2 and rank 0 says which rank differs and how. */
static int check_identity(int argc, char **argv)
{
	uint64_t mine[2], *all = malloc(2 * (size_t)nranks * sizeof *all);
	int i, bad = -1, what = 0;
	mine[0] = binary_hash();
	mine[1] = 14695981039346656037ull;
	for (i = 1; i < argc; i++) /* not argv[0]: the same binary may be reached by other paths */
		mine[1] = fnv(mine[1], argv[i], strlen(argv[i]) + 1);
	if (!all)
		die_all(1);
	MPI_Allgather(mine, 2, MPI_UINT64_T, all, 2, MPI_UINT64_T, MPI_COMM_WORLD);
	for (i = 1; i < nranks && bad < 0; i++)
		if (all[2 * i] != all[0] || all[2 * i + 1] != all[1]) {
			bad = i;
			what = all[2 * i] != all[0] ? 0 : 1;
		}
	if (bad >= 0 && rank == 0)
		study_error("rank %d runs %s than rank 0 (hash %016llx, rank 0 %016llx); every rank must run the same "
		            "build with the same options", bad, what ? "other options" : "a different binary",
		            (unsigned long long)all[2 * bad + what], (unsigned long long)all[what]);
	free(all);
	return bad >= 0 ? ONB_EXIT_USAGE : 0;
}

/* ---- options ------------------------------------------------------------ */

static void mpi_usage(void)
{
	printf("usage: mpirun -n N onbstudy-mpi sweep [options of 'onbstudy sweep'] [MPI options]\n"
	       "       mpirun -n N onbstudy-mpi certify [options of 'onbstudy certify']\n"
	       "certify: the regions over MPI ranks from a work queue on rank 0, OpenMP threads in each\n"
	       "(OMP_NUM_THREADS per rank); certify.csv's rows are those of 'onbstudy certify', and\n"
	       "--resume DIR takes either driver's checkpoint.  'onbstudy certify --help' lists its options.\n"
	       "sweep:\n"
	       "The sweep over MPI ranks, OpenMP threads in each (--threads T per rank); the files are\n"
	       "byte-identical to 'onbstudy sweep' with the same options.  MPI options:\n"
	       "  --resume DIR           continue the run whose checkpoint is DIR/" CKPT_NAME "\n"
	       "                         (same options; the output goes to DIR); with no checkpoint\n"
	       "                         there yet, start the run from the beginning, so one command\n"
	       "                         line serves the first start and every restart\n"
	       "  --checkpoint-every S   write the checkpoint at most every S seconds (default 0: after\n"
	       "                         every batch, so a lost run redoes only the batches in flight)\n"
	       "  --batch C              chunks of %d inputs per batch handed to a rank (default: about\n"
	       "                         a second of work per thread, from the plan)\n"
	       "'onbstudy-mpi sweep --help' lists the sweep's options after these.\n", PLAN_CHUNK);
}

static int mpi_option(int v, const char *a, mpi_opts *o)
{
	if (v == 'r') {
		o->resume = a;
		return 0;
	}
	if (v == 'c') {
		if (parse_double("--checkpoint-every", a, &o->ckpt_every))
			return -1;
		if (o->ckpt_every < 0) {
			study_error("--checkpoint-every: must be >= 0");
			return -1;
		}
		return 0;
	}
	return parse_int("--batch", a, 1, 1L << 30, &o->batch);
}

/* Take the MPI options (exact names: a prefix may be one of the sweep's)
   out of argv, the rest to plan_parse, and parse them with the study's
   getopt_long wrapper. */
static int mpi_options(int *argc, char **argv, mpi_opts *o)
{
	static const struct option lo[] = {
		{ "resume", required_argument, NULL, 'r' }, { "checkpoint-every", required_argument, NULL, 'c' },
		{ "batch", required_argument, NULL, 'b' }, { NULL, 0, NULL, 0 }
	};
	char **mine = malloc(((size_t)*argc + 1) * sizeof *mine);
	int i, n = 0, m = 0, v, rc = 0;
	cli_args c;
	if (!mine) {
		study_error("out of memory");
		return -1;
	}
	for (i = 0; i < *argc; i++) {
		const int ar = cli_option_arity(lo, argv[i], 1);
		if (ar < 0) {
			argv[n++] = argv[i];
			continue;
		}
		mine[m++] = argv[i];
		if (ar == 1 && i + 1 < *argc)
			mine[m++] = argv[++i];
	}
	*argc = n;
	if (cli_begin(&c, "sweep", m, mine) != 0) {
		free(mine);
		return -1;
	}
	memset(o, 0, sizeof *o);
	while (rc == 0 && (v = cli_next(&c, lo)) != -1)
		rc = v == CLI_ERROR || mpi_option(v, c.arg, o) != 0 ? -1 : 0;
	cli_end(&c);
	free(mine);
	return rc;
}

/* Parse and build the plan on every rank; only rank 0 speaks.  0, or the
   exit status every rank returns. */
static int mpi_plan(run_t *r, int argc, char **argv)
{
	int rc, all, saved_err = -1, saved_out = -1;
	if (rank != 0) { /* one message, from rank 0 */
		int nul = open("/dev/null", O_WRONLY);
		fflush(stdout);
		saved_err = dup(2); saved_out = dup(1);
		dup2(nul, 2); dup2(nul, 1);
		close(nul);
	}
	rc = mpi_options(&argc, argv, &r->mo) ? ONB_EXIT_USAGE : 0;
	if (rc == 0 && (rc = plan_parse(&r->pl, argc - 1, argv + 1)) == 1)
		mpi_usage(); /* after the sweep's own options */
	if (rc == 0) {
		if (r->mo.resume) {
			if (r->pl.out_given && strcmp(r->pl.out, r->mo.resume) != 0) {
				study_error("--resume %s: the output goes to the checkpoint's directory; drop --out %s", r->mo.resume, r->pl.out);
				rc = ONB_EXIT_USAGE;
			}
			snprintf(r->pl.out, sizeof r->pl.out, "%s", r->mo.resume);
			r->pl.out_given = 1;
		}
		if (rc == 0)
			rc = plan_build(&r->pl);
	}
	if (rank != 0) {
		fflush(stdout); fflush(stderr);
		dup2(saved_err, 2); dup2(saved_out, 1);
		close(saved_err); close(saved_out);
	}
	MPI_Allreduce(&rc, &all, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
	return all;
}

/* ---- batches and the deltas workers send --------------------------------- */

static void batch_range(const run_t *r, uint64_t b, uint64_t *g0, uint64_t *g1)
{
	*g0 = b * r->B;
	*g1 = *g0 + r->B < r->pl.chunks ? *g0 + r->B : r->pl.chunks;
}

/* The cells [lo, hi) that chunks [g0, g1) touch, and whether they touch the grid. */
static void batch_cells(const run_t *r, uint64_t g0, uint64_t g1, uint64_t *lo, uint64_t *hi, int *grid)
{
	int p0, d0, p1, d1, p, d;
	uint64_t c;
	const uint64_t nk = (uint64_t)r->pl.cfg.nk;
	plan_locate(&r->pl, g0, &p0, &d0, &c);
	plan_locate(&r->pl, g1 - 1, &p1, &d1, &c);
	*lo = ((uint64_t)p0 * NDIST + (uint64_t)d0) * nk;
	*hi = ((uint64_t)p1 * NDIST + (uint64_t)d1 + 1) * nk;
	*grid = 0;
	for (p = 0; p < SWEEP_NPREC; p++)
		for (d = 0; d < NDIST; d++)
			if (d == DIST_GRID && r->pl.nchunks[p][d] && r->pl.first[p][d] < g1 &&
			    r->pl.first[p][d] + r->pl.nchunks[p][d] > g0)
				*grid = 1;
}

/* The batch's delta (state st after running only batch b) into *buf:
   a header, then the state's slice (state.c packs it). */
static size_t pack(const run_t *r, const sweep_state *st, int64_t b, unsigned char **buf, size_t *cap)
{
	delta_hdr h;
	uint64_t g0, g1;
	int grid;
	size_t n;
	memset(&h, 0, sizeof h);
	h.batch = b;
	if (b >= 0) {
		batch_range(r, (uint64_t)b, &g0, &g1);
		batch_cells(r, g0, g1, &h.lo, &h.hi, &grid);
		h.grid = grid;
		h.cfg = st->cfg;
	}
	n = sizeof h + sweep_slice_bytes(st, (size_t)h.lo, (size_t)h.hi, h.grid != 0);
	if (n > *cap) {
		unsigned char *t = realloc(*buf, n);
		if (!t)
			die_all(1);
		*buf = t;
		*cap = n;
	}
	memcpy(*buf, &h, sizeof h);
	sweep_slice_pack(st, (size_t)h.lo, (size_t)h.hi, h.grid != 0, *buf + sizeof h);
	return n;
}

/* Add a delta to the run's accumulators (rank 0, under r->mu).  The
   batch number, or -1 for "ready" or a malformed message. */
static int64_t unpack_add(run_t *r, const unsigned char *buf, size_t n)
{
	sweep_state *a = &r->acc;
	delta_hdr h;
	if (n < sizeof h)
		return -1;
	memcpy(&h, buf, sizeof h);
	if (h.batch < 0 || (uint64_t)h.batch >= r->nbatches ||
	    sweep_slice_merge(a, (size_t)h.lo, (size_t)h.hi, h.grid != 0, buf + sizeof h, n - sizeof h) != 0)
		return -1;
	sweep_cfg_add_counters(&a->cfg, &h.cfg);
	r->evals_done += h.cfg.evals;
	r->done[h.batch] = 1;
	r->dirty = 1;
	return h.batch;
}

/* Run batch b into st (emptied first).  ENGINE_* code. */
static int run_batch(run_t *r, sweep_state *st, int64_t b)
{
	uint64_t g0, g1;
	int rc;
	sweep_clear(st);
	st->cfg = r->pl.cfg; /* counters at zero */
	batch_range(r, (uint64_t)b, &g0, &g1);
	rc = engine_run(r->e, st, g0, g1, NULL);
	if (rc == ENGINE_DISAGREE)
		study_error("rank %d: the MPFR reference at %d bits disagrees with %d bits: %s; rerun with a larger --ref-bits",
		            rank, r->pl.cfg.ref_bits, r->pl.cfg.ref_bits + 64, engine_why(r->e));
	else if (rc == ENGINE_NOMEM)
		study_error("rank %d: out of memory during the sweep", rank);
	return rc;
}

/* ---- rank 0: checkpoints, hand-out, progress ----------------------------- */

static int write_checkpoint(run_t *r);

/* After an add (under r->mu): the checkpoint, when due. */
static void maybe_checkpoint(run_t *r)
{
	if (r->dirty && study_now() - r->t_ckpt >= r->mo.ckpt_every && write_checkpoint(r) != 0)
		r->fail = 1;
}

static int write_checkpoint(run_t *r)
{
	const size_t n = sizeof(ckpt_hdr) + r->nbatches;
	unsigned char *x = malloc(n);
	ckpt_hdr h;
	int rc;
	if (!x)
		return -1;
	memset(&h, 0, sizeof h);
	snprintf(h.magic, sizeof h.magic, "%s", CKPT_MAGIC);
	h.batch = r->B;
	h.nbatches = r->nbatches;
	memcpy(x, &h, sizeof h);
	memcpy(x + sizeof h, r->done, r->nbatches);
	rc = sweep_save_state_x(&r->acc, r->pl.out, CKPT_NAME, x, n);
	free(x);
	r->dirty = 0;
	r->t_ckpt = study_now();
	return rc;
}

/* --resume: the checkpoint's accumulators and done list (rank 0).  0, or -1 after a message. */
static int load_checkpoint(run_t *r)
{
	static sweep_state ck;
	char path[4200];
	unsigned char *x = NULL;
	size_t n = 0;
	ckpt_hdr h;
	snprintf(path, sizeof path, "%s/%s", r->mo.resume, CKPT_NAME);
	if (sweep_load_state_x(&ck, path, &x, &n) != 0)
		return -1;
	if (n >= sizeof h)
		memcpy(&h, x, sizeof h);
	if (!sweep_cfg_same(&ck.cfg, &r->acc.cfg) || ck.cfg.shard_k != r->acc.cfg.shard_k) {
		study_error("%s: the checkpoint is from a sweep with other options (methods, sizes, seed or shard); "
		            "resume with the options of the interrupted run", path);
	} else if (n < sizeof h || strcmp(h.magic, CKPT_MAGIC) != 0 || n != sizeof h + h.nbatches || h.batch < 1 ||
	           h.nbatches != (r->pl.chunks + h.batch - 1) / h.batch) {
		study_error("%s: not a checkpoint of onbstudy-mpi (no done list, or a damaged one)", path);
	} else {
		r->B = h.batch;
		r->nbatches = h.nbatches;
		r->done = calloc(r->nbatches + 1, 1);
		if (r->done) {
			memcpy(r->done, x + sizeof h, r->nbatches);
			sweep_merge_into(&r->acc, &ck);
			r->evals_resumed = r->evals_done = r->acc.cfg.evals;
		}
	}
	free(x);
	sweep_free(&ck);
	return r->done ? 0 : -1;
}

/* --resume DIR before the run wrote a checkpoint there (a job killed early
   and requeued with the same command line): a first start, said once.
   0 then; 1 when DIR/CKPT_NAME exists or cannot be looked at (the load
   names the problem). */
static int checkpoint_present(const run_t *r)
{
	char path[4200];
	snprintf(path, sizeof path, "%s/%s", r->mo.resume, CKPT_NAME);
	if (access(path, F_OK) == 0 || errno != ENOENT)
		return 1;
	fprintf(stderr, "onbstudy-mpi: --resume %s: no checkpoint there yet (%s): starting from the beginning\n",
	        r->mo.resume, path);
	return 0;
}

/* The next batch not done, or -1 (under r->mu). */
static int64_t take_batch(run_t *r)
{
	if (r->fail || engine_stop)
		return -1;
	while (r->next < r->nbatches && r->done[r->next])
		r->next++;
	return r->next < r->nbatches ? (int64_t)r->next++ : -1;
}

/* Rank 0's own worker thread. */
static void *local_worker(void *arg)
{
	static sweep_state st;
	static unsigned char *buf;
	static size_t cap;
	run_t *r = arg;
	int64_t b;
	if (engine_state_init(&r->pl, &st) != 0) {
		pthread_mutex_lock(&r->mu); r->fail = 1; r->local_active = 0; pthread_mutex_unlock(&r->mu);
		return NULL;
	}
	for (;;) {
		int rc;
		size_t n;
		pthread_mutex_lock(&r->mu);
		b = take_batch(r);
		pthread_mutex_unlock(&r->mu);
		if (b < 0)
			break;
		rc = run_batch(r, &st, b);
		n = rc == ENGINE_OK ? pack(r, &st, b, &buf, &cap) : 0;
		pthread_mutex_lock(&r->mu);
		if (rc != ENGINE_OK)
			r->fail = rc == ENGINE_STOPPED ? 0 : 1;
		else if (unpack_add(r, buf, n) >= 0)
			maybe_checkpoint(r);
		pthread_mutex_unlock(&r->mu);
		if (rc != ENGINE_OK)
			break;
	}
	sweep_free(&st);
	pthread_mutex_lock(&r->mu); r->local_active = 0; pthread_mutex_unlock(&r->mu);
	return NULL;
}

static void progress(run_t *r, int final)
{
	const int tty = isatty(2);
	const double now = study_now();
	study_progress pr;
	char label[64];
	if (r->pl.quiet || (!final && now - r->t_progress < (tty ? 1.0 : 10.0)))
		return;
	r->t_progress = now;
	memset(&pr, 0, sizeof pr);
	pr.t0 = r->t0;
	pr.done = r->evals_done;
	pr.skipped = r->evals_resumed;
	pr.total = r->pl.evals;
	snprintf(label, sizeof label, "sweep: %d ranks x %d thr", nranks, r->pl.threads);
	study_progress_line(label, &pr);
	if (!tty || final)
		fputc('\n', stderr);
}

/* One message from a worker: add its delta, send it the next batch. */
static void serve(run_t *r, MPI_Status *s, unsigned char **buf, size_t *cap, int *active)
{
	int n;
	int64_t b;
	MPI_Get_count(s, MPI_BYTE, &n);
	if ((size_t)n > *cap) {
		unsigned char *t = realloc(*buf, (size_t)n);
		if (!t)
			die_all(1);
		*buf = t;
		*cap = (size_t)n;
	}
	MPI_Recv(*buf, n, MPI_BYTE, s->MPI_SOURCE, TAG_RESULT, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
	pthread_mutex_lock(&r->mu);
	if ((size_t)n > sizeof(delta_hdr) && unpack_add(r, *buf, (size_t)n) < 0) {
		study_error("rank %d sent a malformed result", s->MPI_SOURCE);
		r->fail = 1;
	}
	maybe_checkpoint(r);
	b = take_batch(r);
	pthread_mutex_unlock(&r->mu);
	MPI_Send(&b, 1, MPI_INT64_T, s->MPI_SOURCE, TAG_WORK, MPI_COMM_WORLD);
	if (b < 0)
		(*active)--;
}

/* Rank 0's main thread until every batch is done.  0, or the exit status. */
static int master(run_t *r)
{
	static unsigned char *buf;
	static size_t cap;
	pthread_t th;
	int active = nranks - 1, local, fail;
	const struct timespec nap = { 0, 1000000 };
	r->local_active = 1;
	if (pthread_create(&th, NULL, local_worker, r) != 0)
		r->local_active = 0;
	for (;;) {
		MPI_Status s;
		int flag;
		MPI_Iprobe(MPI_ANY_SOURCE, TAG_RESULT, MPI_COMM_WORLD, &flag, &s);
		if (flag) {
			serve(r, &s, &buf, &cap, &active);
			continue;
		}
		pthread_mutex_lock(&r->mu);
		maybe_checkpoint(r);
		local = r->local_active;
		fail = r->fail;
		progress(r, 0);
		pthread_mutex_unlock(&r->mu);
		if (fail || engine_stop) {
			pthread_mutex_lock(&r->mu); /* the local worker may be adding a batch */
			if (r->dirty)
				write_checkpoint(r);
			fprintf(stderr, "onbstudy-mpi: %s; the checkpoint in %s keeps every batch finished so far (%llu of %llu "
			        "evaluations): rerun with --resume %s\n", fail ? "stopped after an error" : "interrupted",
			        r->pl.out, r->evals_done, r->pl.evals, r->pl.out);
			die_all(fail ? 1 : 130);
		}
		if (!local && active == 0)
			break;
		nanosleep(&nap, NULL);
	}
	pthread_join(th, NULL);
	return 0;
}

/* ---- workers ------------------------------------------------------------- */

static void worker(run_t *r)
{
	static sweep_state st;
	unsigned char *buf = NULL;
	size_t cap = 0, n;
	int64_t b = -1;
	if (engine_state_init(&r->pl, &st) != 0)
		die_all(1);
	n = pack(r, &st, -1, &buf, &cap);
	for (;;) {
		int rc;
		MPI_Send(buf, (int)n, MPI_BYTE, 0, TAG_RESULT, MPI_COMM_WORLD);
		MPI_Recv(&b, 1, MPI_INT64_T, 0, TAG_WORK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
		if (b < 0)
			break;
		rc = run_batch(r, &st, b);
		if (rc != ENGINE_OK)
			die_all(rc == ENGINE_STOPPED ? 130 : rc == ENGINE_DISAGREE ? 3 : 1);
		n = pack(r, &st, b, &buf, &cap);
	}
	free(buf);
	sweep_free(&st);
}

/* ---- the run ------------------------------------------------------------- */

/* Batch size, the accumulators, and --resume (rank 0).  0, or the status. */
static int setup(run_t *r)
{
	const uint64_t per_chunk = (uint64_t)PLAN_CHUNK * (uint64_t)r->pl.cfg.nk;
	/* about a second of work per thread (at roughly 6e5 evaluations per
	   second per thread), but at least 4 batches per rank when it fits */
	uint64_t B = r->mo.batch ? (uint64_t)r->mo.batch : (uint64_t)r->pl.threads * (600000 / per_chunk + 1);
	if (!r->mo.batch && B * 4 * (uint64_t)nranks > r->pl.chunks)
		B = r->pl.chunks / (4 * (uint64_t)nranks);
	r->B = B ? B : 1;
	r->nbatches = (r->pl.chunks + r->B - 1) / r->B;
	pthread_mutex_init(&r->mu, NULL);
	if (rank != 0)
		return 0;
	if (sweep_outdir(r->pl.out) != 0)
		return ONB_EXIT_USAGE;
	if (engine_state_init(&r->pl, &r->acc) != 0)
		return 1;
	if (r->mo.resume && !checkpoint_present(r))
		r->mo.resume = NULL;
	if (r->mo.resume)
		return load_checkpoint(r) ? ONB_EXIT_USAGE : 0;
	r->done = calloc(r->nbatches + 1, 1);
	return r->done ? 0 : 1;
}

static int finish(run_t *r)
{
	const double sec = study_now() - r->t0;
	char path[4200];
	progress(r, 1);
	fprintf(stderr, "onbstudy-mpi: %llu referenced evaluations in %.2f s on %d ranks x %d threads (%llu from the checkpoint): "
	        "%.0f per second per thread; %.2f CPU seconds in all ranks, %.0f evaluations per CPU second\n",
	        (unsigned long long)r->acc.cfg.evals, sec, nranks, r->pl.threads, r->evals_resumed,
	        (double)(r->evals_done - r->evals_resumed) / sec / (nranks * r->pl.threads), r->cpu,
	        r->cpu > 0 ? (double)(r->evals_done - r->evals_resumed) / r->cpu : 0.0);
	snprintf(prov_note, sizeof prov_note, "mpi: %d ranks x %d threads, batches of %llu chunks of %d inputs%s",
	         nranks, r->pl.threads, (unsigned long long)r->B, PLAN_CHUNK, r->mo.resume ? ", resumed from a checkpoint" : "");
	study_provenance_note = prov_note;
	if (sweep_write(&r->pl, &r->acc, sec) != 0)
		return 1;
	snprintf(path, sizeof path, "%s/%s", r->pl.out, CKPT_NAME);
	unlink(path);
	return 0;
}

static int run(run_t *r, int argc, char **argv)
{
	int rc = mpi_plan(r, argc, argv), all;
	if (rc)
		return rc == 1 ? 0 : rc;
	if (r->pl.dry_run) {
		if (rank == 0) {
			unsigned long long ev = 0;
			double rate = 0;
			r->e = engine_new(&r->pl);
			if (r->e) rate = engine_calibrate(r->e, 8, &ev);
			plan_print(&r->pl, stdout, rate, ev);
			printf("plan: %d MPI ranks\n", nranks);
		}
		return 0;
	}
	rc = setup(r);
	if (rc == 0 && !(r->e = engine_new(&r->pl)))
		rc = 1;
	MPI_Allreduce(&rc, &all, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
	if (all)
		return all;
	/* the batch size is rank 0's (a resumed run keeps the checkpoint's) */
	MPI_Bcast(&r->B, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
	r->nbatches = (r->pl.chunks + r->B - 1) / r->B;
	signal(SIGINT, on_signal);
	signal(SIGTERM, on_signal);
	r->t0 = r->t_progress = study_now();
	r->cpu0 = cpu_seconds();
	if (rank == 0) {
		rc = master(r);
		sum_cpu(r);
		if (rc == 0)
			rc = finish(r);
	} else {
		worker(r);
		sum_cpu(r);
	}
	engine_free(r->e);
	return rc;
}

int main(int argc, char **argv)
{
	static run_t r;
	int provided, rc;
	study_set_cmdline(argc, argv);
	/* serialized: certify's threads on ranks > 0 each ask rank 0 for work */
	MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
	MPI_Comm_rank(MPI_COMM_WORLD, &rank);
	MPI_Comm_size(MPI_COMM_WORLD, &nranks);
	rc = check_identity(argc, argv);
	if (rc == 0 && argc >= 2 && strcmp(argv[1], "certify") == 0) {
		rc = certify_mpi(argc - 2, argv + 2, rank, nranks, provided);
		MPI_Finalize();
		return rc;
	}
	if (rc == 0 && (argc < 2 || strcmp(argv[1], "sweep") != 0)) {
		if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
			if (rank == 0) mpi_usage();
			rc = -1;
		} else {
			if (rank == 0)
				study_error("onbstudy-mpi runs 'sweep' and 'certify' (usage: mpirun -n N onbstudy-mpi sweep|certify [options])");
			rc = ONB_EXIT_USAGE;
		}
	}
	if (rc == 0)
		rc = run(&r, argc - 1, argv + 1);
	MPI_Finalize();
	return rc < 0 ? 0 : rc;
}
