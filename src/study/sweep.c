/*
 * sweep.c - `onbstudy sweep` (the main job) and `onbstudy merge`.
 *
 * For each precision and distribution, the inputs are cut into chunks of
 * CHUNK indices; threads take chunks dynamically, each with its own MPFR
 * contexts and accumulators, and fold them into the run's cells at the
 * end.  Every accumulation is order-independent (sweep_state.c), so the
 * data written are the same for any thread count.  `--shard K/N` keeps the
 * chunks c with c % N == K and saves the accumulators; `merge` adds the
 * shards' accumulators and writes what the whole run would have written.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>
#include <errno.h>
#include <sys/stat.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "sweep.h"
#include "study.h"

#define CHUNK 256

static volatile sig_atomic_t interrupted;
static void on_signal(int sig) { (void)sig; interrupted = 1; }

static double now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int all_cores(void)
{
#ifdef _OPENMP
	return omp_get_num_procs();
#else
	return 1;
#endif
}

static void sweep_usage(FILE *f)
{
	fprintf(f,
	"usage: onbstudy sweep [options]\n"
	"Every method, both precisions, every distribution, against an MPFR reference.\n"
	"  --methods a,b,...     methods (default all; 'onbstudy list'; frisvad_rotate too)\n"
	"  --precision P         float, double or both (default both)\n"
	"  --dists a,b,...       uniform,north,south,threshold,exhaustive,nonunit,grid (default all)\n"
	"  --samples N           inputs per random distribution (default 32768; nonunit and\n"
	"                        south get N, north N/2)\n"
	"  --exhaustive-from Z   first n.z of the exhaustive range (default -1)\n"
	"  --exhaustive-count C  consecutive representable n.z values (default 65536)\n"
	"  --exhaustive-range LO:HI  every representable n.z in [LO, HI] (instead of the two above)\n"
	"  --azimuths A          azimuths per exhaustive n.z (default 4)\n"
	"  --grid RxC            equal-area grid rows x columns (default 24x48)\n"
	"  --seed S              seed (default 1)\n"
	"  --threads T           OpenMP threads, 0 = all cores (default 0)\n"
	"  --ref-bits B          MPFR precision of the reference (default 127, the widest with\n"
	"                        MPFR's two-limb fast paths; re-checked at B+64)\n"
	"  --check-every K       re-evaluate every K-th input at B+64 bits (default 509)\n"
	"  --fma                 also run a copy of the kernels built with -mfma -ffp-contract=fast\n"
	"  --shard K/N           run the K-th of N slices and save sweep-state.bin for 'merge'\n"
	"  --out DIR             output directory (default results/run-<UTC date>; results/latest\n"
	"                        then points at it)\n"
	"  --format F            stdout: table, csv or json (default table)\n"
	"  --plots               run scripts/plots.sh on the output when gnuplot is present\n"
	"  --quiet               no progress bar\n");
}

typedef struct {
	const char *methods, *out, *fmt;
	int threads, plots, quiet;
} sweep_opts;

static int parse_list(const char *opt, const char *arg, int *on, int n, int (*find)(const char *))
{
	char buf[512], *tok, *save = NULL;
	int i;
	if (strlen(arg) >= sizeof buf) {
		study_error("%s: list too long", opt);
		return -1;
	}
	for (i = 0; i < n; i++)
		on[i] = 0;
	strcpy(buf, arg);
	for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
		const int d = find(tok);
		if (d < 0) {
			study_error("%s: unknown name '%s'", opt, tok);
			return -1;
		}
		on[d] = 1;
	}
	for (i = 0; i < n; i++)
		if (on[i])
			return 0;
	study_error("%s: empty list", opt);
	return -1;
}

static int parse_prec(const char *arg, int on[2])
{
	on[0] = on[1] = 0;
	if (!strcmp(arg, "float")) on[PREC_FLOAT] = 1;
	else if (!strcmp(arg, "double")) on[PREC_DOUBLE] = 1;
	else if (!strcmp(arg, "both")) on[0] = on[1] = 1;
	else {
		study_error("--precision: expected float, double or both, not '%s'", arg);
		return -1;
	}
	return 0;
}

static int parse_shard(const char *arg, int *k, int *n)
{
	char tail;
	if (sscanf(arg, "%d/%d%c", k, n, &tail) != 2 || *n < 1 || *n > 1000000 || *k < 0 || *k >= *n) {
		study_error("--shard: expected K/N with 0 <= K < N, not '%s'", arg);
		return -1;
	}
	return 0;
}

/* The ordinal of x among the format's values (consecutive values have
   consecutive ordinals). */
static int64_t ord_of(double x, int prec)
{
	if (prec == PREC_FLOAT) {
		const float f = (float)x;
		int32_t i;
		memcpy(&i, &f, 4);
		return i < 0 ? -(int64_t)(i & 0x7fffffff) : (int64_t)i;
	} else {
		int64_t i;
		memcpy(&i, &x, 8);
		return i < 0 ? -(i & INT64_MAX) : i;
	}
}

/* How many representable values lie in [lo, hi]. */
static int count_values(double lo, double hi, int prec, uint64_t *count)
{
	double x, y;
	int64_t a, b;
	if (!(lo <= hi) || !isfinite(lo) || !isfinite(hi)) {
		study_error("--exhaustive-range: need finite LO <= HI");
		return -1;
	}
	x = fmt_round(lo, prec);
	if (x < lo)
		x = fmt_step(x, 1, prec);
	y = fmt_round(hi, prec);
	if (y > hi)
		y = fmt_step(y, -1, prec);
	a = ord_of(x, prec);
	b = ord_of(y, prec);
	if (b < a) {
		study_error("--exhaustive-range: no representable value in the range");
		return -1;
	}
	*count = (uint64_t)(b - a) + 1;
	return 0;
}

int cmd_sweep(int argc, char **argv)
{
	static sweep_state st;
	sweep_cfg *cfg = &st.cfg;
	sweep_opts o = { NULL, NULL, "table", 0, 0, 0 };
	const char *range = NULL;
	char outbuf[4096];
	int i, p, d, rc = 0, threads, nk;
	double t0, seconds;
	unsigned long long total = 0;
	memset(&st, 0, sizeof st);
	cfg->seed = 1; cfg->samples = 32768; cfg->ex_from = -1.0; cfg->ex_values = 65536;
	cfg->ex_azimuths = 4; cfg->grid_rows = 24; cfg->grid_cols = 48; cfg->ref_bits = 127;
	cfg->check_every = 509; cfg->shard_k = 0; cfg->shard_n = 1;
	cfg->prec_on[0] = cfg->prec_on[1] = 1;
	for (d = 0; d < NDIST; d++)
		cfg->dist_on[d] = 1;

	for (i = 0; i < argc; i++) {
		const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
		unsigned long long u;
		long l;
#define NEED() do { if (!v) { study_error("%s needs a value", a); return ONB_EXIT_USAGE; } i++; } while (0)
		if (!strcmp(a, "--help") || !strcmp(a, "-h")) { sweep_usage(stdout); return 0; }
		else if (!strcmp(a, "--methods")) { NEED(); o.methods = v; }
		else if (!strcmp(a, "--precision")) { NEED(); if (parse_prec(v, cfg->prec_on)) return ONB_EXIT_USAGE; }
		else if (!strcmp(a, "--dists") || !strcmp(a, "--distributions")) { NEED(); if (parse_list(a, v, cfg->dist_on, NDIST, dist_find)) return ONB_EXIT_USAGE; }
		else if (!strcmp(a, "--samples")) { NEED(); if (parse_u64(a, v, 1, 1ull << 36, &u)) return ONB_EXIT_USAGE; cfg->samples = u; }
		else if (!strcmp(a, "--exhaustive-from")) { NEED(); if (parse_double(a, v, &cfg->ex_from)) return ONB_EXIT_USAGE;
			if (!(cfg->ex_from >= -1.0 && cfg->ex_from <= 1.0)) { study_error("%s: must lie in [-1, 1]", a); return ONB_EXIT_USAGE; } }
		else if (!strcmp(a, "--exhaustive-count")) { NEED(); if (parse_u64(a, v, 1, 1ull << 32, &u)) return ONB_EXIT_USAGE; cfg->ex_values = u; }
		else if (!strcmp(a, "--exhaustive-range")) { NEED(); range = v; }
		else if (!strcmp(a, "--azimuths")) { NEED(); if (parse_int(a, v, 1, 4096, &l)) return ONB_EXIT_USAGE; cfg->ex_azimuths = (int)l; }
		else if (!strcmp(a, "--grid")) {
			int r, c; char tail;
			NEED();
			if (sscanf(v, "%dx%d%c", &r, &c, &tail) != 2 || r < 2 || c < 2 || r > 4096 || c > 8192 ||
			    (uint64_t)r * (uint64_t)c > SWEEP_MAX_GRID_CELLS) {
				study_error("--grid: expected RxC with 2 <= R <= 4096, 2 <= C <= 8192, R*C <= %u, not '%s'", SWEEP_MAX_GRID_CELLS, v);
				return ONB_EXIT_USAGE;
			}
			cfg->grid_rows = r; cfg->grid_cols = c;
		}
		else if (!strcmp(a, "--seed")) { NEED(); if (parse_u64(a, v, 0, UINT64_MAX, &u)) return ONB_EXIT_USAGE; cfg->seed = u; }
		else if (!strcmp(a, "--threads")) { NEED(); if (parse_int(a, v, 0, 1024, &l)) return ONB_EXIT_USAGE; o.threads = (int)l; }
		else if (!strcmp(a, "--ref-bits")) { NEED(); if (parse_int(a, v, 64, 4096, &l)) return ONB_EXIT_USAGE; cfg->ref_bits = (int)l; }
		else if (!strcmp(a, "--check-every")) { NEED(); if (parse_int(a, v, 1, 1000000000, &l)) return ONB_EXIT_USAGE; cfg->check_every = (int)l; }
		else if (!strcmp(a, "--fma")) { cfg->fma = 1; }
		else if (!strcmp(a, "--shard")) { NEED(); if (parse_shard(v, &cfg->shard_k, &cfg->shard_n)) return ONB_EXIT_USAGE; }
		else if (!strcmp(a, "--out")) { NEED(); o.out = v; }
		else if (!strcmp(a, "--format")) { NEED(); o.fmt = v;
			if (strcmp(v, "table") && strcmp(v, "csv") && strcmp(v, "json")) { study_error("--format: expected table, csv or json, not '%s'", v); return ONB_EXIT_USAGE; } }
		else if (!strcmp(a, "--plots")) { o.plots = 1; }
		else if (!strcmp(a, "--quiet")) { o.quiet = 1; }
		else { study_error("sweep: unknown option '%s' (try 'onbstudy sweep --help')", a); return ONB_EXIT_USAGE; }
#undef NEED
	}
	if (cfg->fma && !fma_available()) {
		study_error("--fma: this CPU (or this build) has no FMA instructions");
		return ONB_EXIT_USAGE;
	}
	nk = kernels_select(o.methods, cfg->fma, st.kernels, SWEEP_MAX_KERNELS);
	if (nk < 0)
		return ONB_EXIT_USAGE;
	for (i = 0; i < nk; i++) {
		int j;
		for (j = 0; j < i; j++)
			if (!strcmp(st.kernels[i].name, st.kernels[j].name)) {
				study_error("--methods: '%s' given twice", st.kernels[i].name);
				return ONB_EXIT_USAGE;
			}
		snprintf(cfg->names[i], sizeof cfg->names[i], "%s", st.kernels[i].name);
	}
	cfg->nk = nk;
	threads = o.threads ? o.threads : all_cores();
	if (o.out) {
		snprintf(outbuf, sizeof outbuf, "%s", o.out);
	} else {
		study_default_run_dir(outbuf, sizeof outbuf);
	}

	/* Inputs per distribution. */
	for (p = 0; p < 2; p++) {
		for (d = 0; d < NDIST; d++) {
			dist_spec ds;
			if (!cfg->prec_on[p] || !cfg->dist_on[d])
				continue;
			memset(&ds, 0, sizeof ds);
			ds.dist = d; ds.prec = p; ds.seed = cfg->seed;
			ds.count = d == DIST_NORTH ? (cfg->samples + 1) / 2 : cfg->samples;
			ds.ex_from = fmt_round(cfg->ex_from, p);
			ds.ex_values = cfg->ex_values;
			ds.ex_azimuths = cfg->ex_azimuths;
			ds.grid_rows = cfg->grid_rows; ds.grid_cols = cfg->grid_cols;
			if (d == DIST_EXHAUSTIVE && range) {
				double lo, hi;
				char *colon = strchr(range, ':');
				char lbuf[128];
				if (!colon || (size_t)(colon - range) >= sizeof lbuf) {
					study_error("--exhaustive-range: expected LO:HI, not '%s'", range);
					return ONB_EXIT_USAGE;
				}
				memcpy(lbuf, range, (size_t)(colon - range));
				lbuf[colon - range] = '\0';
				if (parse_double("--exhaustive-range", lbuf, &lo) || parse_double("--exhaustive-range", colon + 1, &hi) ||
				    count_values(lo, hi, p, &ds.ex_values))
					return ONB_EXIT_USAGE;
				if (lo < -1.0 || hi > 1.0) {
					study_error("--exhaustive-range: must lie in [-1, 1]");
					return ONB_EXIT_USAGE;
				}
				ds.ex_from = fmt_round(lo, p) < lo ? fmt_step(fmt_round(lo, p), 1, p) : fmt_round(lo, p);
				if (ds.ex_values > (1ull << 32)) {
					study_error("--exhaustive-range: %llu values; at most 2^32 per run (split it with --shard or a narrower range)",
					            (unsigned long long)ds.ex_values);
					return ONB_EXIT_USAGE;
				}
				if (p == PREC_FLOAT || !cfg->prec_on[PREC_FLOAT]) {
					cfg->ex_from = ds.ex_from;
					cfg->ex_values = ds.ex_values;
				}
			}
			if (dist_prepare(&ds) != 0)
				return 1;
			cfg->counts[p][d] = ds.count;
			total += ds.count * (unsigned long long)nk;
			dist_free(&ds);
		}
	}
	/* Refuse an unusable output directory before hours of work (and only
	   once every option has been checked, so a refused run creates nothing). */
	if (study_mkdir_p(outbuf) != 0)
		return ONB_EXIT_USAGE;
	if (access(outbuf, W_OK) != 0) {
		study_error("%s: output directory is not writable", outbuf);
		return ONB_EXIT_USAGE;
	}
	if (sweep_alloc(&st) != 0)
		return 1;
	if (total > 1000000000ull)
		fprintf(stderr, "onbstudy: %llu referenced evaluations ahead (hours at about a million per second per core);"
		        " inputs are generated %d at a time, so memory stays flat; SIGINT keeps partial figures\n",
		        total, CHUNK);

	signal(SIGINT, on_signal);
	signal(SIGTERM, on_signal);
	t0 = now();
	{
		unsigned long long done = 0;
		int fail = 0;
		char why[512] = "";
		const int bar = !o.quiet && isatty(2);
		for (p = 0; p < 2 && !fail; p++) {
			for (d = 0; d < NDIST && !fail; d++) {
				dist_spec ds;
				uint64_t nchunks;
				long long c;
				const size_t GG = (size_t)cfg->grid_rows * (size_t)cfg->grid_cols;
				if (!cfg->prec_on[p] || !cfg->dist_on[d])
					continue;
				memset(&ds, 0, sizeof ds);
				ds.dist = d; ds.prec = p; ds.seed = cfg->seed;
				ds.count = cfg->counts[p][d];
				ds.ex_from = fmt_round(cfg->ex_from, p);
				ds.ex_values = cfg->ex_values;
				ds.ex_azimuths = cfg->ex_azimuths;
				ds.grid_rows = cfg->grid_rows; ds.grid_cols = cfg->grid_cols;
				if (dist_prepare(&ds) != 0) { fail = 1; break; }
				ds.count = cfg->counts[p][d];
				nchunks = (ds.count + CHUNK - 1) / CHUNK;
#pragma omp parallel num_threads(threads) reduction(|:fail)
				{
					ref_ctx *rc1 = ref_new(cfg->ref_bits), *rc2 = ref_new(cfg->ref_bits + 64);
					cell_t *loc = malloc((size_t)nk * sizeof *loc);
					unsigned long long my_evals = 0, my_checked = 0;
					int k;
					if (!rc1 || !rc2 || !loc) {
						fail = 1;
					} else {
						for (k = 0; k < nk; k++)
							cell_init(&loc[k]);
					}
#pragma omp for schedule(dynamic, 1)
					for (c = 0; c < (long long)nchunks; c++) {
						uint64_t i0 = (uint64_t)c * CHUNK, i1 = i0 + CHUNK, idx;
						if (fail || interrupted || (uint64_t)c % (uint64_t)cfg->shard_n != (uint64_t)cfg->shard_k)
							continue;
						if (i1 > ds.count)
							i1 = ds.count;
						for (idx = i0; idx < i1; idx++) {
							double n[3], lv[3], aux;
							dist_sample(&ds, idx, n, lv, &aux);
							for (k = 0; k < nk; k++) {
								sample_metrics m;
								ref_eval(rc1, &st.kernels[k], p, n, lv, d == DIST_NONUNIT, &m);
								my_evals++;
								if (idx % (uint64_t)cfg->check_every == 0) {
									sample_metrics m2;
									char w[256];
									ref_eval(rc2, &st.kernels[k], p, n, lv, d == DIST_NONUNIT, &m2);
									my_checked++;
									if (!ref_agree(&m, &m2, w, sizeof w)) {
#pragma omp critical(sweep_why)
										snprintf(why, sizeof why, "%s %s %s input %llu (%a, %a, %a): %s",
										         st.kernels[k].name, p ? "double" : "float", dist_name(d),
										         (unsigned long long)idx, n[0], n[1], n[2], w);
										fail = 2;
									}
								}
								cell_add(&loc[k], idx, &m, n, 0);
								if (d == DIST_GRID) {
									const size_t j = ((size_t)p * (size_t)nk + (size_t)k) * GG + (size_t)aux;
									st.g_err[j] = m.nonfinite ? INFINITY : st.kernels[k].m ? m.defect : fmax(m.dir_norm, m.dir_cos);
									st.g_bits[j] = m.nbits ? m.bits_sum / m.nbits : 0.0;
									memcpy(&st.g_b1[3 * j], m.out, 3 * sizeof(double));
									st.g_done[(size_t)p * GG + (size_t)aux] = 1;
								}
							}
						}
#pragma omp atomic
						done += (unsigned long long)(i1 - i0) * (unsigned long long)nk;
						if (bar
#ifdef _OPENMP
						    && omp_get_thread_num() == 0
#endif
						) {
							unsigned long long dn;
#pragma omp atomic read
							dn = done;
							fprintf(stderr, "\rsweep %-6s %-10s %5.1f%%", p ? "double" : "float", dist_name(d),
							        100.0 * (double)dn / (double)(total ? total : 1));
						}
					}
#pragma omp critical(sweep_fold)
					{
						if (loc && !fail)
							for (k = 0; k < nk; k++)
								cell_merge(sweep_cell(&st, p, d, k), &loc[k]);
						cfg->evals += my_evals;
						cfg->checked += my_checked;
					}
					free(loc);
					ref_free(rc1);
					ref_free(rc2);
				}
				dist_free(&ds);
			}
		}
		if (bar)
			fprintf(stderr, "\r%60s\r", "");
		if (fail == 2 || (fail & 2)) {
			study_error("the MPFR reference at %d bits disagrees with %d bits: %s; rerun with a larger --ref-bits",
			            cfg->ref_bits, cfg->ref_bits + 64, why);
			sweep_free(&st);
			return 3;
		}
		if (fail) {
			study_error("out of memory during the sweep");
			sweep_free(&st);
			return 1;
		}
	}
	seconds = now() - t0;
	if (interrupted) {
		fprintf(stderr, "onbstudy: interrupted; earlier results are untouched, partial figures go to %s/*.partial.csv\n", outbuf);
		sweep_finish(&st, outbuf, threads, o.fmt, seconds, 1);
		sweep_free(&st);
		return 130;
	}
	fprintf(stderr, "onbstudy: %llu referenced evaluations in %.2f s: %.0f per second, %.0f per thread (%d threads); MPFR %d bits, %llu inputs re-checked at %d bits\n",
	        (unsigned long long)cfg->evals, seconds, (double)cfg->evals / seconds,
	        (double)cfg->evals / seconds / threads, threads, cfg->ref_bits,
	        (unsigned long long)cfg->checked, cfg->ref_bits + 64);
	if (cfg->shard_n > 1) {
		char name[64];
		snprintf(name, sizeof name, "sweep-state-%d-of-%d.bin", cfg->shard_k, cfg->shard_n);
		rc = sweep_save_state(&st, outbuf, name);
		if (rc == 0)
			fprintf(stderr, "onbstudy: shard %d of %d saved to %s/%s; combine the shards with 'onbstudy merge'\n",
			        cfg->shard_k, cfg->shard_n, outbuf, name);
		sweep_free(&st);
		return rc ? 1 : 0;
	}
	rc = sweep_finish(&st, outbuf, threads, o.fmt, seconds, 0);
	sweep_free(&st);
	if (rc)
		return 1;
	if (!o.out) {
		study_point_latest(outbuf); /* results/latest -> the new run */
	}
	fprintf(stderr, "onbstudy: wrote %s/summary.csv, by_nz.csv, worst.csv%s\n", outbuf, cfg->dist_on[DIST_GRID] ? ", grid.csv" : "");
	if (o.plots) {
		char cmd[8300];
		if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
			fprintf(stderr, "onbstudy: --plots: gnuplot is not installed (scripts/install-deps.sh installs it); skipped\n");
		} else {
			snprintf(cmd, sizeof cmd, "sh scripts/plots.sh '%s'", outbuf);
			if (system(cmd) != 0) {
				study_error("--plots: scripts/plots.sh failed");
				return 1;
			}
		}
	}
	return 0;
}

static void merge_usage(FILE *f)
{
	fprintf(f, "usage: onbstudy merge [--out DIR] [--threads T] [--format F] STATE...\n"
	           "Combine the sweep-state-K-of-N.bin files of 'sweep --shard K/N' runs into the\n"
	           "files one unsharded run would have written.\n");
}

int cmd_merge(int argc, char **argv)
{
	static sweep_state acc, one;
	const char *out = NULL, *fmt = "table";
	int i, nfiles = 0, threads = 0, rc;
	unsigned char *seen = NULL;
	for (i = 0; i < argc; i++) {
		const char *a = argv[i];
		long l;
		if (!strcmp(a, "--help") || !strcmp(a, "-h")) { merge_usage(stdout); return 0; }
		if (!strcmp(a, "--out") || !strcmp(a, "--threads") || !strcmp(a, "--format")) {
			if (i + 1 >= argc) { study_error("%s needs a value", a); return ONB_EXIT_USAGE; }
			if (!strcmp(a, "--out")) out = argv[++i];
			else if (!strcmp(a, "--format")) {
				fmt = argv[++i];
				if (strcmp(fmt, "table") && strcmp(fmt, "csv") && strcmp(fmt, "json")) {
					study_error("--format: expected table, csv or json, not '%s'", fmt);
					return ONB_EXIT_USAGE;
				}
			} else { if (parse_int(a, argv[++i], 0, 1024, &l)) return ONB_EXIT_USAGE; threads = (int)l; }
			continue;
		}
		if (a[0] == '-') { study_error("merge: unknown option '%s'", a); return ONB_EXIT_USAGE; }
		if (nfiles == 0 && threshold_is_state(a)) {
			/* threshold shards: every remaining argument is one */
			static char buf[4096];
			char **files = malloc((size_t)argc * sizeof *files);
			int nf = 0, j;
			if (!files) { study_error("out of memory"); return 1; }
			for (j = i; j < argc; j++) {
				if (!strcmp(argv[j], "--out") || !strcmp(argv[j], "--threads") || !strcmp(argv[j], "--format")) {
					if (j + 1 < argc && !strcmp(argv[j], "--out")) out = argv[j + 1];
					j++;
					continue;
				}
				files[nf++] = argv[j];
			}
			if (!out) { study_default_run_dir(buf, sizeof buf); out = buf; }
			j = threshold_merge(nf, files, out, threads ? threads : all_cores());
			free(files);
			return j;
		}
		if (nfiles == 0) {
			if (sweep_load_state(&acc, a) != 0) return ONB_EXIT_USAGE;
			seen = calloc((size_t)acc.cfg.shard_n, 1);
			if (!seen) { study_error("out of memory"); return 1; }
			seen[acc.cfg.shard_k] = 1;
		} else {
			if (sweep_load_state(&one, a) != 0) { free(seen); sweep_free(&acc); return ONB_EXIT_USAGE; }
			if (one.cfg.shard_n != acc.cfg.shard_n || seen[one.cfg.shard_k]) {
				study_error("%s: shard %d of %d repeats or does not belong with the first file's %d shards", a,
				            one.cfg.shard_k, one.cfg.shard_n, acc.cfg.shard_n);
				free(seen); sweep_free(&acc); sweep_free(&one);
				return ONB_EXIT_USAGE;
			}
			seen[one.cfg.shard_k] = 1;
			if (sweep_merge_into(&acc, &one) != 0) { free(seen); sweep_free(&acc); sweep_free(&one); return ONB_EXIT_USAGE; }
			sweep_free(&one);
		}
		nfiles++;
	}
	if (nfiles == 0) { study_error("merge: no state files given (usage: onbstudy merge [--out DIR] STATE...)"); return ONB_EXIT_USAGE; }
	for (i = 0; i < acc.cfg.shard_n; i++)
		if (!seen[i]) {
			study_error("shard %d of %d is missing", i, acc.cfg.shard_n);
			free(seen); sweep_free(&acc);
			return ONB_EXIT_USAGE;
		}
	free(seen);
	acc.cfg.shard_k = 0;
	acc.cfg.shard_n = 1;
	if (!out) {
		static char buf[4096];
		study_default_run_dir(buf, sizeof buf);
		out = buf;
	}
	rc = sweep_finish(&acc, out, threads ? threads : all_cores(), fmt, 0.0, 0);
	sweep_free(&acc);
	if (rc == 0)
		fprintf(stderr, "onbstudy: merged %d shards into %s\n", nfiles, out);
	return rc ? 1 : 0;
}
