/*
 * plan.c - the sweep's plan (see plan.h): options -> plan, and its
 * printed form for --dry-run.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "reference/reffast.h"
#include "sweep/plan.h"
#include "common/options.h"
#include "common/output.h"

int plan_all_cores(void)
{
#ifdef _OPENMP
	return omp_get_num_procs();
#else
	return 1;
#endif
}

void plan_usage(FILE *f)
{
	fprintf(f,
	"usage: onbstudy sweep [options]\n"
	"Every method, both precisions, every distribution, against an MPFR reference.\n"
	"Options take their value as '--opt value' or '--opt=value'.\n"
	"  --methods a,b,...     methods (default all; 'onbstudy list'; frisvad_rotate too)\n"
	"  --precision P         float, double, both, half or all (default both: binary16 is\n"
	"                        opt-in; half runs libonb's binary16 kernels on unit vectors\n"
	"                        rounded to binary16, against MPFR alone)\n"
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
	"  --ref R               fast (default): a certified reference in pairs of doubles or\n"
	"                        long doubles that writes MPFR's bytes and asks MPFR where it\n"
	"                        cannot decide (fallback rates in reference.csv); mpfr: MPFR\n"
	"                        alone (the same data)\n"
	"  --fma                 also run a copy of the kernels built with -mfma -ffp-contract=fast\n"
	"  --shard K/N           run slice K of N, 0-based (0 <= K < N), and save\n"
	"                        sweep-state-K-of-N.bin for 'merge'; with Slurm job arrays:\n"
	"                        --array=0-(N-1) and --shard $SLURM_ARRAY_TASK_ID/N\n"
	"  --out DIR             output directory (default results/run-<UTC date>; results/latest\n"
	"                        then points at it)\n"
	"  --format F            stdout: table, csv or json (default table)\n"
	"  --plots               run scripts/plots.sh on the output when gnuplot is present\n"
	"  --dry-run             print the plan (inputs, evaluations, estimated time) and stop;\n"
	"                        the estimate times a few chunks of the real work on this machine\n"
	"  --quiet               no progress line\n"
	"  --arith PROFILE       the emulated conforming implementations of an arithmetic\n"
	"                        profile (onbstudy list --arith; docs/gpu.md) in place of the\n"
	"                        kernels: per input the nearest, R random and the adversarial\n"
	"                        one; the worst defect held to the proven bound at the input\n"
	"                        and to the method's whole-sphere bound; DIR/arith-sweep.csv;\n"
	"                        exit 1 when a defect exceeds a bound.  --samples and\n"
	"                        --exhaustive-count default to 512 here; --fma, --shard, --ref,\n"
	"                        --ref-bits, --check-every, --plots, --dry-run do not apply;\n"
	"                        --precision half where the profile has a binary16 row\n"
	"                        (vulkan's): measured, not checked (no binary16 proof model)\n"
	"  --emu-random R        with --arith: random implementations per input (default 4)\n"
	"  --bounds CSV          with --arith: a certify --arith CSV of the same profile for the\n"
	"                        whole-sphere bounds (default results/gpu/PROFILE/certify.csv)\n"
	"  --widen K             with --arith, for tests: every ulp or relative allowance of the\n"
	"                        emulation K times the profile's (a NONCONFORMING implementation:\n"
	"                        the bounds must not hold for it; K >= 1)\n");
}

static void plan_defaults(sweep_plan *pl)
{
	sweep_cfg *cfg = &pl->cfg;
	int d;
	memset(pl, 0, sizeof *pl);
	cfg->seed = 1; cfg->samples = 32768; cfg->ex_from = -1.0; cfg->ex_values = 65536;
	cfg->ex_azimuths = 4; cfg->grid_rows = 24; cfg->grid_cols = 48; cfg->ref_bits = 127;
	cfg->check_every = 509; cfg->shard_k = 0; cfg->shard_n = 1;
	cfg->prec_on[0] = cfg->prec_on[1] = 1;
	pl->emu_random = 4;
	pl->widen = 1.0;
	for (d = 0; d < NDIST; d++)
		cfg->dist_on[d] = 1;
}

static int parse_grid(const char *v, sweep_cfg *cfg)
{
	int r, c;
	char tail;
	if (sscanf(v, "%dx%d%c", &r, &c, &tail) != 2 || r < 2 || c < 2 || r > 4096 || c > 8192 ||
	    (uint64_t)r * (uint64_t)c > SWEEP_MAX_GRID_CELLS) {
		study_error("--grid: expected RxC with 2 <= R <= 4096, 2 <= C <= 8192, R*C <= %u, not '%s'", SWEEP_MAX_GRID_CELLS, v);
		return -1;
	}
	cfg->grid_rows = r;
	cfg->grid_cols = c;
	return 0;
}

enum { O_METHODS = 256, O_PREC, O_DISTS, O_SAMPLES, O_EXFROM, O_EXCOUNT, O_EXRANGE, O_AZ, O_GRID, O_SEED,
       O_THREADS, O_REFBITS, O_CHECK, O_REF, O_FMA, O_SHARD, O_OUT, O_FORMAT, O_PLOTS, O_QUIET, O_DRY,
       O_ARITH, O_EMURANDOM, O_BOUNDS, O_WIDEN };

static const struct option sweep_options[] = {
	{ "methods", required_argument, NULL, O_METHODS }, { "precision", required_argument, NULL, O_PREC },
	{ "dists", required_argument, NULL, O_DISTS }, { "distributions", required_argument, NULL, O_DISTS },
	{ "samples", required_argument, NULL, O_SAMPLES }, { "exhaustive-from", required_argument, NULL, O_EXFROM },
	{ "exhaustive-count", required_argument, NULL, O_EXCOUNT }, { "exhaustive-range", required_argument, NULL, O_EXRANGE },
	{ "azimuths", required_argument, NULL, O_AZ }, { "grid", required_argument, NULL, O_GRID },
	{ "seed", required_argument, NULL, O_SEED }, { "threads", required_argument, NULL, O_THREADS },
	{ "ref-bits", required_argument, NULL, O_REFBITS }, { "check-every", required_argument, NULL, O_CHECK },
	{ "ref", required_argument, NULL, O_REF },
	{ "fma", no_argument, NULL, O_FMA }, { "shard", required_argument, NULL, O_SHARD },
	{ "out", required_argument, NULL, O_OUT }, { "format", required_argument, NULL, O_FORMAT },
	{ "plots", no_argument, NULL, O_PLOTS }, { "quiet", no_argument, NULL, O_QUIET },
	{ "dry-run", no_argument, NULL, O_DRY }, { "arith", required_argument, NULL, O_ARITH },
	{ "emu-random", required_argument, NULL, O_EMURANDOM }, { "bounds", required_argument, NULL, O_BOUNDS },
	{ "widen", required_argument, NULL, O_WIDEN }, CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
};

static int plan_arith(sweep_plan *pl, const char *a)
{
	char names[256];
	if ((pl->arith = arith_find(a)))
		return 0;
	arith_names(names, sizeof names);
	study_error("--arith: unknown profile '%s' (one of: %s)", a, names);
	return -1;
}

/* --arith's own defaults and the options it refuses (and theirs without
   it); 0 or -1 after a message. */
static int plan_arith_check(sweep_plan *pl)
{
	static const char *const plain[] = { "--ref-bits", "--check-every", "--ref", "--fma", "--shard", "--format", "--plots",
	                                     "--dry-run" };
	static const int code[] = { O_REFBITS, O_CHECK, O_REF, O_FMA, O_SHARD, O_FORMAT, O_PLOTS, O_DRY };
	size_t i;
	if (!pl->arith) {
		if (pl->emu_random != 4 || pl->bounds || pl->widen != 1.0) {
			study_error("sweep: --emu-random, --bounds and --widen go with --arith");
			return -1;
		}
		return 0;
	}
	for (i = 0; i < sizeof code / sizeof code[0]; i++)
		if (pl->plain_only == code[i]) {
			study_error("sweep --arith: %s does not apply (the emulated implementations are measured in MPFR at 127 bits, in one run)", plain[i]);
			return -1;
		}
	if (pl->cfg.prec_on[PREC_HALF] && !arith_has_format(pl->arith, PREC_HALF)) {
		study_error("sweep --arith %s: the profile gives binary16 no precision (docs/gpu.md; ieee, vulkan, vulkan-precise, opencl, cuda-fast and contract-any have a half row)",
		            pl->arith->name);
		return -1;
	}
	if (!pl->samples_given)
		pl->cfg.samples = 512;
	if (!pl->excount_given)
		pl->cfg.ex_values = 512;
	return 0;
}

/* One option; 0 or -1 after a message. */
static int plan_option(sweep_plan *pl, int v, const char *a)
{
	sweep_cfg *cfg = &pl->cfg;
	unsigned long long u;
	long l;
	if (v == O_REFBITS || v == O_CHECK || v == O_REF || v == O_FMA || v == O_SHARD || v == O_PLOTS || v == O_DRY ||
	    v == O_FORMAT)
		pl->plain_only = v;
	switch (v) {
	case O_METHODS: pl->methods = a; return 0;
	case O_PREC: return cli_precision_half("--precision", a, cfg->prec_on);
	case O_DISTS: return cli_name_list("--dists", a, cfg->dist_on, dist_names(), NDIST);
	case O_SAMPLES: if (parse_u64("--samples", a, 1, 1ull << 36, &u)) return -1; cfg->samples = u; pl->samples_given = 1; return 0;
	case O_EXFROM:
		if (parse_double("--exhaustive-from", a, &cfg->ex_from)) return -1;
		if (!(cfg->ex_from >= -1.0 && cfg->ex_from <= 1.0)) { study_error("--exhaustive-from: must lie in [-1, 1]"); return -1; }
		return 0;
	case O_EXCOUNT: if (parse_u64("--exhaustive-count", a, 1, 1ull << 32, &u)) return -1; cfg->ex_values = u; pl->excount_given = 1; return 0;
	case O_EXRANGE: pl->range = a; return 0;
	case O_AZ: if (parse_int("--azimuths", a, 1, 4096, &l)) return -1; cfg->ex_azimuths = (int)l; return 0;
	case O_GRID: return parse_grid(a, cfg);
	case O_SEED: if (parse_u64("--seed", a, 0, UINT64_MAX, &u)) return -1; cfg->seed = u; return 0;
	case O_THREADS: if (parse_int("--threads", a, 0, 1024, &l)) return -1; pl->threads = (int)l; return 0;
	case O_REFBITS: if (parse_int("--ref-bits", a, 64, 4096, &l)) return -1; cfg->ref_bits = (int)l; return 0;
	case O_CHECK: if (parse_int("--check-every", a, 1, 1000000000, &l)) return -1; cfg->check_every = (int)l; return 0;
	case O_REF:
		pl->ref_given = 1;
		if (!strcmp(a, "fast")) cfg->ref_mpfr = 0;
		else if (!strcmp(a, "mpfr")) cfg->ref_mpfr = 1;
		else { study_error("--ref: expected fast or mpfr, not '%s'", a); return -1; }
		return 0;
	case O_FMA: cfg->fma = 1; return 0;
	case O_SHARD: return cli_shard("--shard", a, &cfg->shard_k, &cfg->shard_n);
	case O_OUT: pl->out_given = 1; snprintf(pl->out, sizeof pl->out, "%s", a); return 0;
	case O_FORMAT: return (pl->fmt = cli_format("--format", a, 1)) < 0 ? -1 : 0;
	case O_PLOTS: pl->plots = 1; return 0;
	case O_QUIET: pl->quiet = 1; return 0;
	case O_DRY: pl->dry_run = 1; return 0;
	case O_ARITH: return plan_arith(pl, a);
	case O_EMURANDOM: if (parse_int("--emu-random", a, 0, 100000, &l)) return -1; pl->emu_random = (int)l; return 0;
	case O_BOUNDS: pl->bounds = a; return 0;
	case O_WIDEN:
		if (parse_double("--widen", a, &pl->widen)) return -1;
		if (!(pl->widen >= 1.0 && pl->widen <= 1e6)) { study_error("--widen: must lie in [1, 1e6]"); return -1; }
		return 0;
	}
	return -1;
}

int plan_parse(sweep_plan *pl, int argc, char **argv)
{
	cli_args c;
	int v, rc = 0;
	plan_defaults(pl);
	if (cli_begin(&c, "sweep", argc, argv))
		return 1;
	while (rc == 0 && (v = cli_next(&c, sweep_options)) != -1) {
		if (v == CLI_HELP) {
			plan_usage(stdout);
			rc = 1;
		} else if (v == CLI_ERROR || plan_option(pl, v, c.arg) != 0) {
			rc = ONB_EXIT_USAGE;
		}
	}
	if (rc == 0 && cli_no_rest(&c) != 0)
		rc = ONB_EXIT_USAGE;
	if (rc == 0 && plan_arith_check(pl) != 0)
		rc = ONB_EXIT_USAGE;
	cli_end(&c);
	if (rc == 1)
		return 1;
	return rc ? ONB_EXIT_USAGE : 0;
}

/* The ordinal of x among the format's values (consecutive values have
   consecutive ordinals). */
static int64_t ord_of(double x, int prec)
{
	if (prec == PREC_HALF) {
		const uint16_t b = prec_half_bits(x);
		return (b >> 15) ? -(int64_t)(b & 0x7fffu) : (int64_t)b;
	}
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

/* --exhaustive-range LO:HI for precision p: ds->ex_from and ds->ex_values. */
static int plan_range(sweep_plan *pl, int p, dist_spec *ds)
{
	const char *range = pl->range, *colon = strchr(range, ':');
	double lo, hi;
	char lbuf[128];
	if (!colon || (size_t)(colon - range) >= sizeof lbuf) {
		study_error("--exhaustive-range: expected LO:HI, not '%s'", range);
		return -1;
	}
	memcpy(lbuf, range, (size_t)(colon - range));
	lbuf[colon - range] = '\0';
	if (parse_double("--exhaustive-range", lbuf, &lo) || parse_double("--exhaustive-range", colon + 1, &hi) ||
	    count_values(lo, hi, p, &ds->ex_values))
		return -1;
	if (lo < -1.0 || hi > 1.0) {
		study_error("--exhaustive-range: must lie in [-1, 1]");
		return -1;
	}
	ds->ex_from = fmt_round(lo, p) < lo ? fmt_step(fmt_round(lo, p), 1, p) : fmt_round(lo, p);
	if (ds->ex_values > (1ull << 32)) {
		study_error("--exhaustive-range: %llu values; at most 2^32 per run (split it with --shard or a narrower range)",
		            (unsigned long long)ds->ex_values);
		return -1;
	}
	if (p == PREC_FLOAT || !pl->cfg.prec_on[PREC_FLOAT]) {
		pl->cfg.ex_from = ds->ex_from;
		pl->cfg.ex_values = ds->ex_values;
	}
	return 0;
}

void plan_dist_spec(const sweep_plan *pl, int p, int d, dist_spec *ds)
{
	const sweep_cfg *cfg = &pl->cfg;
	memset(ds, 0, sizeof *ds);
	ds->dist = d; ds->prec = p; ds->seed = cfg->seed;
	ds->count = cfg->counts[p][d] ? cfg->counts[p][d] : d == DIST_NORTH ? (cfg->samples + 1) / 2 : cfg->samples;
	ds->ex_from = fmt_round(cfg->ex_from, p);
	ds->ex_values = cfg->ex_values;
	ds->ex_azimuths = cfg->ex_azimuths;
	ds->grid_rows = cfg->grid_rows; ds->grid_cols = cfg->grid_cols;
}

/* The kernels of --methods (each once). */
static int plan_kernels(sweep_plan *pl)
{
	sweep_cfg *cfg = &pl->cfg;
	int i, j, nk;
	if (cfg->fma && !fma_available()) {
		study_error("--fma: this CPU (or this build) has no FMA instructions");
		return -1;
	}
	nk = kernels_select(pl->methods, cfg->fma, pl->kernels, SWEEP_MAX_KERNELS);
	if (nk < 0)
		return -1;
	for (i = 0; i < nk; i++) {
		for (j = 0; j < i; j++)
			if (!strcmp(pl->kernels[i].name, pl->kernels[j].name)) {
				study_error("--methods: '%s' given twice", pl->kernels[i].name);
				return -1;
			}
		snprintf(cfg->names[i], sizeof cfg->names[i], "%s", pl->kernels[i].name);
	}
	cfg->nk = nk;
	return 0;
}

/* Inputs of this shard's chunks of (p, d). */
static uint64_t shard_inputs(const sweep_plan *pl, int p, int d)
{
	const uint64_t n = pl->nchunks[p][d], K = (uint64_t)pl->cfg.shard_k, N = (uint64_t)pl->cfg.shard_n;
	uint64_t mine, in;
	if (K >= n)
		return 0;
	mine = (n - K + N - 1) / N;
	in = mine * PLAN_CHUNK;
	if ((n - 1) % N == K) /* this shard has the last, short chunk */
		in -= n * PLAN_CHUNK - pl->cfg.counts[p][d];
	return in;
}

int plan_build(sweep_plan *pl)
{
	sweep_cfg *cfg = &pl->cfg;
	int p, d;
	if (plan_kernels(pl) != 0)
		return ONB_EXIT_USAGE;
	if (!cfg->ref_mpfr) {
		const char *why;
		if (!reffast_usable(cfg->ref_bits, &why)) {
			/* said when --ref fast was asked for; the default falls back quietly */
			if (pl->ref_given)
				fprintf(stderr, "onbstudy: %s: the reference is MPFR only (as --ref mpfr)\n", why);
			cfg->ref_mpfr = 1;
		}
	}
	pl->threads = pl->threads ? pl->threads : plan_all_cores();
	if (!pl->out_given)
		study_default_run_dir(pl->out, sizeof pl->out);
	pl->chunks = 0;
	pl->evals = 0;
	for (p = 0; p < SWEEP_NPREC; p++)
		for (d = 0; d < NDIST; d++) {
			dist_spec ds;
			pl->first[p][d] = pl->chunks;
			pl->nchunks[p][d] = 0;
			if (!cfg->prec_on[p] || !cfg->dist_on[d])
				continue;
			plan_dist_spec(pl, p, d, &ds);
			if (d == DIST_EXHAUSTIVE && pl->range && plan_range(pl, p, &ds) != 0)
				return ONB_EXIT_USAGE;
			if (dist_prepare(&ds) != 0)
				return 1;
			cfg->counts[p][d] = ds.count;
			dist_free(&ds);
			pl->nchunks[p][d] = (ds.count + PLAN_CHUNK - 1) / PLAN_CHUNK;
			pl->chunks += pl->nchunks[p][d];
			pl->evals += shard_inputs(pl, p, d) * (unsigned long long)kernels_running(pl->kernels, cfg->nk, p);
		}
	return 0;
}

int plan_locate(const sweep_plan *pl, uint64_t g, int *p, int *d, uint64_t *c)
{
	int pp, dd;
	for (pp = 0; pp < SWEEP_NPREC; pp++)
		for (dd = 0; dd < NDIST; dd++)
			if (g >= pl->first[pp][dd] && g < pl->first[pp][dd] + pl->nchunks[pp][dd]) {
				*p = pp;
				*d = dd;
				*c = g - pl->first[pp][dd];
				return 0;
			}
	return -1;
}

int plan_in_shard(const sweep_plan *pl, uint64_t g)
{
	int p, d;
	uint64_t c;
	if (plan_locate(pl, g, &p, &d, &c) != 0)
		return 0;
	return c % (uint64_t)pl->cfg.shard_n == (uint64_t)pl->cfg.shard_k;
}

static void print_duration(FILE *f, double s)
{
	const char *unit;
	const double v = study_duration(s, &unit);
	fprintf(f, "%.1f %s", v, unit);
}

void plan_print(const sweep_plan *pl, FILE *f, double per_thread_rate, unsigned long long calib_evals)
{
	const sweep_cfg *cfg = &pl->cfg;
	int p, d, k;
	fprintf(f, "plan: %d methods:", cfg->nk);
	for (k = 0; k < cfg->nk; k++)
		fprintf(f, " %s", cfg->names[k]);
	fprintf(f, "\nplan: seed %llu, MPFR %d bits (every %d-th input re-checked at %d), chunks of %d inputs\n",
	        (unsigned long long)cfg->seed, cfg->ref_bits, cfg->check_every, cfg->ref_bits + 64, PLAN_CHUNK);
	fprintf(f, "plan: reference %s\n", cfg->ref_mpfr ? "MPFR only (--ref mpfr)" : "fast, MPFR where it cannot decide (--ref fast)");
	for (p = 0; p < SWEEP_NPREC; p++)
		for (d = 0; d < NDIST; d++)
			if (cfg->prec_on[p] && cfg->dist_on[d])
				fprintf(f, "plan: %-6s %-10s %12llu inputs %9llu chunks\n", prec_name(p), dist_name(d),
				        (unsigned long long)cfg->counts[p][d], (unsigned long long)pl->nchunks[p][d]);
	if (cfg->dist_on[DIST_EXHAUSTIVE])
		fprintf(f, "plan: exhaustive: %llu consecutive n.z from %a, %d azimuths\n",
		        (unsigned long long)cfg->ex_values, cfg->ex_from, cfg->ex_azimuths);
	if (cfg->shard_n > 1)
		fprintf(f, "plan: shard %d of %d (0-based): every chunk c with c %% %d == %d\n", cfg->shard_k, cfg->shard_n,
		        cfg->shard_n, cfg->shard_k);
	fprintf(f, "plan: %llu referenced evaluations (before the worst-case walk), %llu chunks in all\n", pl->evals,
	        (unsigned long long)pl->chunks);
	fprintf(f, "plan: %d threads, output to %s\n", pl->threads, pl->out);
	if (per_thread_rate > 0) {
		fprintf(f, "plan: estimated time ");
		print_duration(f, (double)pl->evals / (per_thread_rate * pl->threads));
		fprintf(f, " on %d threads (%.0f evaluations per second per thread, timed on %llu evaluations of this plan)\n",
		        pl->threads, per_thread_rate, calib_evals);
	}
}
