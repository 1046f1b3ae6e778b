/*
 * sweep.c - `onbstudy sweep` (the main job) and `onbstudy merge`.
 *
 * cmd_sweep is parse -> plan -> run -> write: plan.c builds the plan from
 * the options, engine.c runs its chunks into accumulators (threads take
 * chunks dynamically; every accumulation is order-independent, so the data
 * are the same for any thread count), engine_walk runs the worst-case walk, and writers.c writes
 * the files from the const state.
 * `--shard K/N` keeps the chunks c with c % N == K and saves the
 * accumulators (state.c); `merge` adds the shards' accumulators and
 * writes what the whole run would have written.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <signal.h>
#include <unistd.h>
#include "sweep/sweep.h"
#include "sweep/engine.h"
#include "sweep/state.h"
#include "common/options.h"
#include "common/output.h"
#include "sweep/threshold.h"
#include "sweep/writers.h"
#include "sweep/emusweep.h"

static void on_signal(int sig) { (void)sig; engine_stop = 1; }

static const char *const fmt_names[] = { "table", "csv", "json" };

/* Refuse an unusable output directory before hours of work (and only once
   every option has been checked, so a refused run creates nothing). */
int sweep_outdir(const char *out)
{
	if (study_mkdir_p(out) != 0)
		return -1;
	if (access(out, W_OK) != 0) {
		study_error("%s: output directory is not writable", out);
		return -1;
	}
	return 0;
}

/* --dry-run: the plan, with a time estimated from a few chunks of it. */
static int sweep_dry_run(const sweep_plan *pl)
{
	unsigned long long ev = 0;
	double rate = 0.0;
	engine *e = engine_new(pl);
	if (!e)
		return 1;
	if (pl->evals > 0)
		rate = engine_calibrate(e, 8, &ev);
	engine_free(e);
	plan_print(pl, stdout, rate, ev);
	return 0;
}

/* Run every chunk of the plan into st.  0, or the exit status after a message. */
static int sweep_run(const sweep_plan *pl, sweep_state *st, double *seconds)
{
	study_progress pr;
	engine *e;
	int rc;
	if (pl->evals > 1000000000ull)
		fprintf(stderr, "onbstudy: %llu referenced evaluations ahead (hours at about a million per second per core);"
		        " inputs are generated %d at a time, so memory stays flat; SIGINT keeps partial figures\n",
		        pl->evals, PLAN_CHUNK);
	e = engine_new(pl);
	if (!e)
		return 1;
	memset(&pr, 0, sizeof pr);
	pr.bar = !pl->quiet && isatty(2);
	pr.total = pl->evals;
	signal(SIGINT, on_signal);
	signal(SIGTERM, on_signal);
	pr.t0 = study_now();
	rc = engine_run(e, st, 0, pl->chunks, &pr);
	*seconds = study_now() - pr.t0;
	if (pr.bar)
		fprintf(stderr, "\r%70s\r", "");
	if (rc == ENGINE_DISAGREE)
		study_error("the MPFR reference at %d bits disagrees with %d bits: %s; rerun with a larger --ref-bits",
		            pl->cfg.ref_bits, pl->cfg.ref_bits + 64, engine_why(e));
	else if (rc == ENGINE_NOMEM)
		study_error("out of memory during the sweep");
	engine_free(e);
	return rc == ENGINE_DISAGREE ? 3 : rc == ENGINE_NOMEM ? 1 : 0;
}

static int sweep_plots(const char *out)
{
	char cmd[8300];
	if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
		fprintf(stderr, "onbstudy: --plots: gnuplot is not installed (scripts/install-deps.sh --plots installs it); skipped\n");
		return 0;
	}
	snprintf(cmd, sizeof cmd, "sh scripts/plots.sh '%s'", out);
	if (system(cmd) != 0) {
		study_error("--plots: scripts/plots.sh failed");
		return 1;
	}
	return 0;
}

/* The files: a shard's state, or (after the worst-case walk) the whole
   run's CSV files. */
int sweep_write(const sweep_plan *pl, sweep_state *st, double seconds)
{
	const sweep_cfg *cfg = &st->cfg;
	if (cfg->shard_n > 1) {
		char name[64];
		snprintf(name, sizeof name, "sweep-state-%d-of-%d.bin", cfg->shard_k, cfg->shard_n);
		if (sweep_save_state(st, pl->out, name) != 0)
			return 1;
		fprintf(stderr, "onbstudy: shard %d of %d (0-based) saved to %s/%s; combine the shards with 'onbstudy merge'\n",
		        cfg->shard_k, cfg->shard_n, pl->out, name);
		return 0;
	}
	if (engine_walk(st, pl->threads) != 0 || sweep_finish(st, pl->out, pl->threads, fmt_names[pl->fmt], seconds, 0) != 0)
		return 1;
	if (!pl->out_given)
		study_point_latest(pl->out);
	fprintf(stderr, "onbstudy: wrote %s/summary.csv, by_nz.csv, worst.csv%s\n", pl->out,
	        cfg->dist_on[DIST_GRID] ? ", grid.csv" : "");
	return pl->plots ? sweep_plots(pl->out) : 0;
}

int cmd_sweep(int argc, char **argv)
{
	static sweep_plan pl;
	static sweep_state st;
	double seconds = 0.0;
	int rc = plan_parse(&pl, argc, argv);
	if (rc != 0)
		return rc == 1 ? 0 : rc;
	if ((rc = plan_build(&pl)) != 0)
		return rc;
	if (pl.arith)
		return sweep_outdir(pl.out) != 0 ? ONB_EXIT_USAGE : emusweep_run(&pl);
	if (pl.dry_run)
		return sweep_dry_run(&pl);
	if (sweep_outdir(pl.out) != 0)
		return ONB_EXIT_USAGE;
	if (engine_state_init(&pl, &st) != 0)
		return 1;
	rc = sweep_run(&pl, &st, &seconds);
	if (rc == 0 && engine_stop) {
		fprintf(stderr, "onbstudy: interrupted; earlier results are untouched, partial figures go to %s/*.partial.csv\n", pl.out);
		sweep_finish(&st, pl.out, pl.threads, fmt_names[pl.fmt], seconds, 1);
		rc = 130;
	} else if (rc == 0) {
		fprintf(stderr, "onbstudy: %llu referenced evaluations in %.2f s: %.0f per second, %.0f per thread (%d threads); MPFR %d bits, %llu inputs re-checked at %d bits\n",
		        (unsigned long long)st.cfg.evals, seconds, (double)st.cfg.evals / seconds,
		        (double)st.cfg.evals / seconds / pl.threads, pl.threads, st.cfg.ref_bits,
		        (unsigned long long)st.cfg.checked, st.cfg.ref_bits + 64);
		sweep_print_reference(stderr, &st, "onbstudy: ", 0);
		rc = sweep_write(&pl, &st, seconds);
	}
	sweep_free(&st);
	return rc;
}

static void merge_usage(FILE *f)
{
	fprintf(f, "usage: onbstudy merge [--out DIR] [--threads T] [--format F] STATE...\n"
	           "Combine the sweep-state-K-of-N.bin files of 'sweep --shard K/N' runs (or the\n"
	           "threshold-state files of 'threshold --shard K/N') into the files one unsharded\n"
	           "run would have written.  Every shard 0 .. N-1 must be given once; missing ones\n"
	           "are named.\n"
	           "  --out DIR      output directory (default results/run-<UTC date>)\n"
	           "  --threads T    threads for the worst-case walk, 0 = all cores (default 0)\n"
	           "  --format F     stdout: table, csv or json (default table)\n");
}

/* Load and add every state file into acc; 0, or the exit status. */
static int merge_states(sweep_state *acc, int nfiles, char **files)
{
	static sweep_state one;
	unsigned char *seen = NULL;
	int i, nmiss = 0;
	char miss[256];
	for (i = 0; i < nfiles; i++) {
		sweep_state *dst = i == 0 ? acc : &one;
		if (sweep_load_state(dst, files[i]) != 0)
			break;
		if (i == 0 && !(seen = calloc((size_t)acc->cfg.shard_n, 1))) {
			study_error("out of memory");
			break;
		}
		if (i > 0 && (one.cfg.shard_n != acc->cfg.shard_n || seen[one.cfg.shard_k])) {
			study_error("%s: shard %d of %d repeats or does not belong with the first file's %d shards", files[i],
			            one.cfg.shard_k, one.cfg.shard_n, acc->cfg.shard_n);
			break;
		}
		seen[dst->cfg.shard_k] = 1;
		if (i > 0 && sweep_merge_into(acc, &one) != 0)
			break;
		if (i > 0)
			sweep_free(&one);
	}
	if (i == nfiles)
		for (i = 0; i < acc->cfg.shard_n; i++)
			nmiss += !seen[i];
	else
		nmiss = -1;
	if (nmiss > 0) {
		study_missing_shards(seen, acc->cfg.shard_n, miss, sizeof miss);
		study_error("%d of %d shards missing (0-based K of --shard K/%d): %s", nmiss, acc->cfg.shard_n,
		            acc->cfg.shard_n, miss);
	}
	free(seen);
	sweep_free(&one);
	if (nmiss != 0) {
		sweep_free(acc);
		return ONB_EXIT_USAGE;
	}
	return 0;
}

int cmd_merge(int argc, char **argv)
{
	static sweep_state acc;
	static char buf[4096];
	static const struct option lo[] = {
		{ "out", required_argument, NULL, 'o' }, { "threads", required_argument, NULL, 't' },
		{ "format", required_argument, NULL, 'f' }, CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
	};
	const char *out = NULL;
	int v, nfiles = 0, threads = 0, fmt = 0, rc = 0;
	char **files;
	cli_args c;
	long l;
	if (cli_begin(&c, "merge", argc, argv))
		return 1;
	while (rc == 0 && (v = cli_next(&c, lo)) != -1) {
		if (v == CLI_HELP) { merge_usage(stdout); cli_end(&c); return 0; }
		else if (v == 'o') out = c.arg;
		else if (v == 't') { if (parse_int("--threads", c.arg, 0, 1024, &l)) rc = ONB_EXIT_USAGE; threads = (int)l; }
		else if (v == 'f') { if ((fmt = cli_format("--format", c.arg, 1)) < 0) rc = ONB_EXIT_USAGE; }
		else rc = ONB_EXIT_USAGE;
	}
	files = cli_rest(&c, &nfiles);
	if (rc == 0 && nfiles == 0) {
		study_error("merge: no state files given (usage: onbstudy merge [--out DIR] STATE...)");
		rc = ONB_EXIT_USAGE;
	}
	if (rc == 0 && !out) {
		study_default_run_dir(buf, sizeof buf);
		out = buf;
	}
	threads = threads ? threads : plan_all_cores();
	if (rc == 0 && threshold_is_state(files[0]))
		rc = threshold_merge(nfiles, files, out, threads);
	else if (rc == 0 && (rc = merge_states(&acc, nfiles, files)) == 0) {
		acc.cfg.shard_k = 0;
		acc.cfg.shard_n = 1;
		rc = engine_walk(&acc, threads) || sweep_finish(&acc, out, threads, fmt_names[fmt], 0.0, 0) ? 1 : 0;
		sweep_free(&acc);
		if (rc == 0)
			fprintf(stderr, "onbstudy: merged %d shards into %s\n", nfiles, out);
	}
	cli_end(&c);
	return rc;
}
