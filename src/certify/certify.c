/*
 * certify.c - `onbstudy certify`: for every method, precision and region
 * of the sphere, the largest defect found on a real input beside a bound
 * that no input of the region can exceed.  Writes certify.csv.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "common/options.h"
#include "common/output.h"
#include "common/progress.h"
#include "certify.h"
#include "search.h"
#include "model/seeds.h"
#include "found.h"
#include "keys.h"
#include "checkpoint.h"
#include "certify_half.h"
#include <inttypes.h>
#include <signal.h>

#define MAXREG 1024
#define MAXK STUDY_MAX_KERNELS

typedef struct {
	const char *methods;
	int prec_on[2];
	const char *out;
	cert_opts o;
	int sectors;
	int band;               /* --band given: only lo <= n.z <= hi */
	long refined;           /* regions refine_top bounded again ...    */
	double refine_s;        /* ... in this many seconds                */
	long pool;              /* inputs the images pass pooled ...       */
	double images_s;        /* ... in this many seconds                */
	double run_s;           /* the regions' first pass, wall seconds   */
	double band_lo, band_hi;
	int quick;
	int quiet;
	int fma;                /* --fma: also the contracted kernels */
	const char *starts;     /* --starts FILE[,FILE...] */
	int arith_given;        /* --arith P other than ieee: its rows and header */
	const char *resume;     /* --resume DIR */
	const char *reuse;      /* --reuse DIR */
	const char *check_keys; /* --check-keys DIR */
	const char *write_keys; /* --write-keys DIR */
	double ck_every;        /* --checkpoint-every S */
	const unsigned char *frozen;   /* per group: re-used whole (--reuse), not refined */
	int nreused;            /* groups re-used */
	int half;               /* --precision half: certify_half.c */
	int set_other;          /* an option that --precision half does not take */
	long depth, az;         /* --depth, --azimuths (half only; -1: default) */
} cert_cli;

/* What the tasks commit to: the results, and the checkpoint. */
typedef struct {
	ck_state ck;            /* flags, base and refined results, keys */
	const char *dir;        /* --resume: where the checkpoint goes; NULL none */
	double every, last;
	int failed;             /* a checkpoint could not be written: stop */
	int stopped;            /* cert_stop_save: nothing more is committed */
	int current;            /* the checkpoint in dir holds every commit */
	int kill_phase;         /* ONB_CERT_KILL=PHASE:N (tests): SIGKILL after */
	long kill_at, commits;  /* the N-th commit of that phase */
} run_ctl;

typedef struct {
	int k, prec, reg;   /* kernel, precision, region index */
} task;

static int group_of(const task *t) { return 2 * t->k + t->prec; }

const cert_dist *cert_distribute;

/* Rank 0 of onbstudy-mpi, or onbstudy: the process that writes and speaks. */
static int writer(void) { return !cert_distribute || cert_distribute->rank == 0; }

static void usage(FILE *f)
{
	fprintf(f,
	"usage: onbstudy certify [--methods LIST] [--precision float|double|both|half] [--out DIR]\n"
	"                        [--budget N] [--samples N] [--sectors N] [--tolerance T]\n"
	"                        [--band LO,HI] [--starts FILE[,FILE...]] [--seed S]\n"
	"                        [--fma] [--arith PROFILE] [--quick] [--quiet] [--resume DIR]\n"
	"                        [--checkpoint-every S] [--reuse DIR] [--check-keys DIR]\n\n"
	"For each method, precision and region of the sphere (bands of n.z, log-spaced\n"
	"near the poles, times azimuth sectors), a bracket  found <= true max <= bound  of\n"
	"the orthonormality defect max(| |b1|-1 |, | |b2|-1 |, |b1.n|, |b2.n|, |b1.b2|)\n"
	"(frisvad_rotate: the direction error max(| |w|-1 |, |w.n - z|) of its output w\n"
	"on every local direction (x, y, z) that is a rounding of a unit vector):\n"
	"  found  the largest defect of the real kernel on a real input of the region\n"
	"         (sampled, then ulp walks from many starts, then every region's best\n"
	"         inputs under the 48 signed permutations of (x, y, z) where they fall\n"
	"         in the region; replay it with `onbstudy eval`);\n"
	"  bound  proven for every input of the region: the kernel's own operations,\n"
	"         each rounded once, in a mean value form over MPFI intervals, by\n"
	"         branch and bound until bound <= 1.25 found, the budget runs out or\n"
	"         250 more boxes take less than 2%% off the bound.\n"
	"The domain: every rounding of a real unit vector (default), or with\n"
	"--tolerance T every n with | |n| - 1 | <= T.  status: proven, singular (the\n"
	"method can return NaN or inf there: not bounded) or budget (bound holds, not\n"
	"yet within 1.25x).  Writes DIR/certify.csv (default: the current run) and\n"
	"DIR/certify-times.csv (the profile: each region's CPU seconds in sampling,\n"
	"walks, boxes, box probes, images and refinement; the totals on stderr and\n"
	"in certify.csv's '# profile' line).\n\n"
	"  --methods LIST    comma-separated registry names, or all (default)\n"
	"  --precision P     float, double or both (default both); half: binary16 alone\n"
	"                    (certify_half.c): per region, the bound beside a scan of every\n"
	"                    binary16 n.z of the band at --azimuths A per sector (default\n"
	"                    16, --quick 4), halving a region up to --depth D times\n"
	"                    (default 6, --quick 3) while the bound is above twice what\n"
	"                    the scan found; status proven, non-finite (a half basis\n"
	"                    with a NaN or an infinity: no bound), overflow (a value may\n"
	"                    exceed 65504) or unbounded (no enclosure: an underflowing\n"
	"                    length near a pole); writes DIR/certify-half.csv.  Takes\n"
	"                    --methods, --sectors, --band, --quick, --quiet, --out,\n"
	"                    --depth, --azimuths, --resume, --checkpoint-every and --arith\n"
	"                    (the profile's binary16 row; the found side is the IEEE half\n"
	"                    kernel's scan; an unbounded row names the operation where the\n"
	"                    profile gives no bound); onbstudy-mpi certify --precision half\n"
	"                    spreads its regions over the ranks\n");
	fprintf(f,
	"  --budget N        boxes bounded per region at most (default 6000)\n"
	"  --samples N       inputs sampled per region before the boxes (default 1000)\n"
	"  --sectors N       azimuth sectors (default 8)\n"
	"  --tolerance T     the non-unit domain | |n| - 1 | <= T (T in [0, 0.01])\n"
	"  --band LO,HI      only the inputs with LO <= n.z <= HI (-1 <= LO <= HI <= 1):\n"
	"                    the default bands cut to it; the summary row is that band\n"
	"  --starts FILES    CSV files of earlier worst inputs (columns method, precision,\n"
	"                    nx,ny,nz or found_nx,found_ny,found_nz: a certify.csv or a\n"
	"                    sweep's worst.csv; frisvad_rotate's rows also lx,ly,lz or\n"
	"                    found_lx,found_ly,found_lz): the found side also walks from\n"
	"                    those of each method, precision and region, and tries\n"
	"                    their signed permutations\n"
	"  --fma             also the methods' --fma copies (compiled with -mfma\n"
	"                    -ffp-contract=fast), as METHOD+fma rows, where a contracted\n"
	"                    rounding model exists (docs/certify.md lists which)\n"
	"  --arith PROFILE   the bound for every implementation the profile allows\n"
	"                    (`onbstudy list --arith`: ieee, vulkan, vulkan-precise,\n"
	"                    d3d11, opencl, cuda-fast, contract-any; docs/gpu.md); the\n"
	"                    found side also takes an adversarial emulation's worst;\n"
	"                    status unbounded names the operation whose allowance gives\n"
	"                    no bound (ieee: the default, byte for byte)\n"
	"  --quick           budget 40, samples 150 (walks a quarter as long), 2 sectors:\n"
	"                    a run of under a minute\n");
	fprintf(f,
	"  --resume DIR      write to DIR and keep a checkpoint there (certify-checkpoint.bin,\n"
	"                    removed at the end): run again with the same command line to\n"
	"                    continue a run that was stopped; before the first checkpoint it\n"
	"                    starts from the beginning, after the end it says the work is\n"
	"                    done.  A checkpoint of other options, another revision of a\n"
	"                    model or kernel, of the other format (half against float,\n"
	"                    double or both), or a corrupted one is refused\n"
	"  --checkpoint-every S  with --resume: at most every S seconds (default 60; 0:\n"
	"                    after every region)\n"
	"  --reuse DIR       take the results of every method and precision whose key (its\n"
	"                    model's operations, kernel, format, settings and the certify\n"
	"                    engine: DIR/certify-keys.csv, which every run writes) is\n"
	"                    unchanged from DIR's certify.csv; compute the others\n"
	"  --check-keys DIR  prove nothing: exit 0 when every key of this command line is\n"
	"                    DIR's (DIR/certify.csv is current), else 1 naming the stale\n"
	"  --write-keys DIR  prove nothing: write DIR/certify-keys.csv, the keys of this\n"
	"                    command line, for a DIR/certify.csv that holds its methods,\n"
	"                    precisions and regions and whose rows this code gives (made\n"
	"                    before the keys, or by an engine engines.txt declares the\n"
	"                    same: that claim is the caller's, with its evidence)\n");
}

/* Split line s at commas into f (at most max fields); returns the count. */
static int split_fields(char *s, char **f, int max)
{
	int n = 0;
	s[strcspn(s, "\r\n")] = '\0';
	while (n < max) {
		f[n++] = s;
		if (!(s = strchr(s, ',')))
			break;
		*s++ = '\0';
	}
	return n;
}

static int col_of(char **h, int nh, const char *a, const char *b)
{
	int i;
	for (i = 0; i < nh; i++)
		if (strcmp(h[i], a) == 0 || (b && strcmp(h[i], b) == 0))
			return i;
	return -1;
}

/* The rows of one --starts file appended to *v (count *n, capacity *cap). */
static int load_start_file(const char *path, cert_start **v, long *n, long *cap)
{
	char line[8192], head[8192], *h[64], *f[64];
	int nh = 0, cmeth = -1, cp = -1, cx = -1, cy = -1, cz = -1, lx = -1, ly = -1, lz = -1;
	FILE *in = fopen(path, "r");
	if (!in) {
		study_error("--starts: %s: cannot open", path);
		return -1;
	}
	while (fgets(line, sizeof line, in)) {
		cert_start *s;
		char *end[3];
		if (line[0] == '#')
			continue;
		if (!nh) {
			memcpy(head, line, sizeof head);
			nh = split_fields(head, h, 64);
			cmeth = col_of(h, nh, "method", NULL); cp = col_of(h, nh, "precision", NULL);
			cx = col_of(h, nh, "found_nx", "nx"); cy = col_of(h, nh, "found_ny", "ny"); cz = col_of(h, nh, "found_nz", "nz");
			lx = col_of(h, nh, "found_lx", "lx"); ly = col_of(h, nh, "found_ly", "ly"); lz = col_of(h, nh, "found_lz", "lz");
			if (cmeth < 0 || cx < 0 || cy < 0 || cz < 0) {
				study_error("--starts: %s: no method and nx,ny,nz (or found_nx,found_ny,found_nz) columns", path);
				fclose(in);
				return -1;
			}
			continue;
		}
		if (split_fields(line, f, 64) < nh || !*f[cx])
			continue;
		if (*n == *cap) {
			cert_start *t = realloc(*v, (size_t)(*cap = *cap * 2 + 1024) * sizeof *t);
			if (!t) {
				study_error("out of memory");
				fclose(in);
				return -1;
			}
			*v = t;
		}
		s = &(*v)[*n];
		snprintf(s->method, sizeof s->method, "%s", f[cmeth]);
		s->prec = cp < 0 ? -1 : strcmp(f[cp], "double") == 0 ? PREC_DOUBLE : strcmp(f[cp], "float") == 0 ? PREC_FLOAT : -2;
		s->n[0] = strtod(f[cx], &end[0]); s->n[1] = strtod(f[cy], &end[1]); s->n[2] = strtod(f[cz], &end[2]);
		s->has_loc = 0;
		if (lx >= 0 && ly >= 0 && lz >= 0 && *f[lx] && *f[ly] && *f[lz]) {   /* frisvad_rotate's loc */
			char *le[3];
			s->loc[0] = strtod(f[lx], &le[0]); s->loc[1] = strtod(f[ly], &le[1]); s->loc[2] = strtod(f[lz], &le[2]);
			s->has_loc = !*le[0] && !*le[1] && !*le[2] && isfinite(s->loc[0] + s->loc[1] + s->loc[2]);
		}
		if (s->prec > -2 && !*end[0] && !*end[1] && !*end[2] && isfinite(s->n[0] + s->n[1] + s->n[2]))
			(*n)++;
	}
	fclose(in);
	return 0;
}

/* --starts FILE[,FILE...]: every row into c->o.starts (free it). */
static int load_starts(cert_cli *c)
{
	char path[4096];
	const char *p = c->starts;
	cert_start *v = NULL;
	long n = 0, cap = 0;
	while (p && *p) {
		size_t len = strcspn(p, ",");
		if (len == 0 || len >= sizeof path) {
			study_error("--starts: expected FILE[,FILE...], not '%s'", c->starts);
			free(v);
			return -1;
		}
		memcpy(path, p, len);
		path[len] = '\0';
		if (load_start_file(path, &v, &n, &cap)) {
			free(v);
			return -1;
		}
		p += len + (p[len] == ',');
	}
	c->o.starts = v;
	c->o.nstarts = n;
	return 0;
}

/* --band LO,HI: two numbers, -1 <= LO <= HI <= 1. */
static int parse_band(const char *s, cert_cli *c)
{
	char lo[64];
	const char *comma = strchr(s, ',');
	size_t n = comma ? (size_t)(comma - s) : 0;
	if (!comma || n == 0 || n >= sizeof lo) {
		study_error("--band: expected LO,HI (two numbers in [-1, 1]), not '%s'", s);
		return -1;
	}
	memcpy(lo, s, n);
	lo[n] = '\0';
	if (parse_double("--band", lo, &c->band_lo) || parse_double("--band", comma + 1, &c->band_hi))
		return -1;
	if (!(c->band_lo >= -1.0 && c->band_lo <= c->band_hi && c->band_hi <= 1.0)) {
		study_error("--band: expected -1 <= LO <= HI <= 1, not '%s'", s);
		return -1;
	}
	c->band = 1;
	return 0;
}

/* --precision: float, double or both (certify.c), or half (certify_half.c) */
static int parse_precision(const char *arg, cert_cli *c)
{
	int on[PREC_COUNT];
	c->half = strcmp(arg, "half") == 0;
	return c->half ? cli_precision_half("--precision", arg, on) : cli_precision("--precision", arg, c->prec_on);
}

/* --precision half takes its own options alone, and they go with it alone. */
static int half_options_bad(const cert_cli *c)
{
	if (c->half ? !c->set_other : c->depth < 0 && c->az < 0)
		return 0;
	study_error(c->half ? "--precision half takes --methods, --sectors, --band, --depth, --azimuths, --arith, "
	                      "--quick, --quiet, --out, --resume and --checkpoint-every alone" :
	                      "--depth and --azimuths go with --precision half");
	return 1;
}

/* --check-keys and --write-keys prove nothing: no output to go with them. */
static int keys_options_bad(const cert_cli *c)
{
	if (!c->write_keys || !(c->check_keys || c->reuse || c->resume || c->out))
		return 0;
	study_error("--write-keys proves nothing and writes only its keys: drop --out, --resume, --reuse and "
	            "--check-keys");
	return 1;
}

/* --arith NAME: the profile, and whether it differs from ieee. */
static int parse_arith(const char *arg, cert_cli *c)
{
	char names[256];
	if ((c->o.arith = arith_find(arg)) != NULL) {
		c->arith_given = !arith_is_ieee(c->o.arith);
		return 0;
	}
	arith_names(names, sizeof names);
	study_error("--arith: unknown profile '%s' (one of: %s)", arg, names);
	return 1;
}

/* --checkpoint-every SECONDS, >= 0. */
static int parse_every(const char *arg, cert_cli *c)
{
	if (parse_double("--checkpoint-every", arg, &c->ck_every))
		return 1;
	if (c->ck_every >= 0.0)
		return 0;
	study_error("--checkpoint-every: expected seconds >= 0, not '%s'", arg);
	return 1;
}

static int parse(int argc, char **argv, cert_cli *c)
{
	static const struct option lo[] = {
		{ "methods", required_argument, NULL, 'm' }, { "precision", required_argument, NULL, 'p' },
		{ "out", required_argument, NULL, 'o' }, { "budget", required_argument, NULL, 'b' },
		{ "samples", required_argument, NULL, 'n' }, { "sectors", required_argument, NULL, 's' },
		{ "tolerance", required_argument, NULL, 't' }, { "seed", required_argument, NULL, 'S' },
		{ "quick", no_argument, NULL, 'q' }, { "quiet", no_argument, NULL, 'Q' },
		{ "band", required_argument, NULL, 'B' }, { "starts", required_argument, NULL, 'T' },
		{ "fma", no_argument, NULL, 'F' }, { "arith", required_argument, NULL, 'A' },
		{ "resume", required_argument, NULL, 'R' },
		{ "reuse", required_argument, NULL, 'U' }, { "check-keys", required_argument, NULL, 'K' },
		{ "write-keys", required_argument, NULL, 'W' },
		{ "checkpoint-every", required_argument, NULL, 'E' },
		{ "depth", required_argument, NULL, 'D' }, { "azimuths", required_argument, NULL, 'Z' },
		CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
	};
	cli_args a;
	long l;
	unsigned long long u;
	int v, budget_set = 0, samples_set = 0, sectors_set = 0;
	memset(c, 0, sizeof *c);
	c->depth = c->az = -1;
	c->methods = "all";
	c->prec_on[0] = c->prec_on[1] = 1;
	c->o.budget = 6000; c->o.samples = 1000; c->o.target = 1.25; c->o.tolerance = -1.0; c->o.seed = 1;
	c->sectors = 8;
	c->ck_every = 60.0;
	if (cli_begin(&a, "certify", argc, argv))
		return ONB_EXIT_USAGE;
	while ((v = cli_next(&a, lo)) != -1) {
		switch (v) {
		case CLI_HELP: usage(stdout); cli_end(&a); return -1;
		case 'm': c->methods = a.arg; break;
		case 'p': if (parse_precision(a.arg, c)) goto bad; break;
		case 'D': if (parse_int("--depth", a.arg, 0, 20, &c->depth)) goto bad; break;
		case 'Z': if (parse_int("--azimuths", a.arg, 1, 4096, &c->az)) goto bad; break;
		case 'o': c->out = a.arg; break;
		case 'b': if (parse_int("--budget", a.arg, 1, 1000000, &l)) goto bad; c->o.budget = l; budget_set = 1; break;
		case 'n': if (parse_int("--samples", a.arg, 0, 100000000, &l)) goto bad; c->o.samples = l; samples_set = 1; break;
		case 's': if (parse_int("--sectors", a.arg, 1, 64, &l)) goto bad; c->sectors = (int)l; sectors_set = 1; break;
		case 't':
			if (parse_double("--tolerance", a.arg, &c->o.tolerance)) goto bad;
			if (!(c->o.tolerance >= 0.0 && c->o.tolerance <= 0.01)) {
				study_error("--tolerance: expected a number in [0, 0.01], not '%s'", a.arg);
				goto bad;
			}
			break;
		case 'S': if (parse_u64("--seed", a.arg, 0, ~0ull, &u)) goto bad; c->o.seed = u; break;
		case 'q': c->quick = 1; break;
		case 'Q': c->quiet = 1; break;
		case 'B': if (parse_band(a.arg, c)) goto bad; break;
		case 'T': c->starts = a.arg; break;
		case 'F': c->fma = 1; break;
		case 'A': if (parse_arith(a.arg, c)) goto bad; break;
		case 'R': c->resume = a.arg; break;
		case 'U': c->reuse = a.arg; break;
		case 'K': c->check_keys = a.arg; break;
		case 'W': c->write_keys = a.arg; break;
		case 'E': if (parse_every(a.arg, c)) goto bad; break;
		default: goto bad;
		}
		c->set_other |= v > 0 && strchr("bntSTFUKW", v) != NULL;
	}
	if (cli_no_rest(&a))
		goto bad;
	if (half_options_bad(c) || keys_options_bad(c))
		goto bad;
	if (c->arith_given && c->fma) {
		study_error("--arith and --fma exclude each other (a profile's contraction covers the +fma copies)");
		goto bad;
	}
	cli_end(&a);
	if (c->resume && c->out && strcmp(c->resume, c->out) != 0) {
		study_error("--resume %s: the output goes to the checkpoint's directory; drop --out %s", c->resume, c->out);
		return ONB_EXIT_USAGE;
	}
	if (c->resume)
		c->out = c->resume;
	if (c->quick) {
		if (!budget_set) c->o.budget = 40;
		if (!samples_set) c->o.samples = 150;
		if (!sectors_set) c->sectors = 2;
	}
	return 0;
bad:
	cli_end(&a);
	return ONB_EXIT_USAGE;
}

/* The threads the regions ran on, for the provenance. */
static int cert_threads(void)
{
#ifdef _OPENMP
	return omp_get_max_threads();
#else
	return 1;
#endif
}

static const char *status_name(int s)
{
	return s == CERT_PROVEN ? "proven" : s == CERT_SINGULAR ? "singular" : s == CERT_UNBOUNDED ? "unbounded" : "budget";
}

/* The operation an unbounded row names (AR_NOPS: frisvad_rotate's
   direction rule, proven for round to nearest alone). */
static const char *unb_name(int op) { return op == AR_NOPS ? "direction-rule" : arith_op_name(op); }

/* --arith: why a row's bound is +inf (arith.h's causes; the status
   unbounded: the operation the profile gives no bound), "" when it has a
   bound or is singular. */
static const char *inf_cause(const cert_result *x)
{
	if (x->status == CERT_UNBOUNDED)
		return unb_name(x->unb_op);
	if (x->status == CERT_SINGULAR || x->bound < INFINITY)
		return "";
	return x->unb_op == AR_NOPS ? "direction-rule" : arith_cause_name(x->unb_op);
}

/* The cause a CSV's unbounded_by names (inf_cause), -1 for none. */
static int parse_cause(const char *s)
{
	static const int why[3] = { 0, AR_AT_POLE, AR_OVERFLOW };
	int j, w;
	for (w = 0; w < 3; w++)
		for (j = 0; j < AR_NOPS; j++)
			if (strcmp(s, arith_cause_name(j | why[w])) == 0)
				return j | why[w];
	return strcmp(s, "direction-rule") == 0 ? AR_NOPS : strcmp(s, "overflow") == 0 ? (AR_NOPS | AR_OVERFLOW)
	     : strcmp(s, "enclosure") == 0 ? AR_LOST : -1;
}

static double unit_of(int prec) { return prec == PREC_FLOAT ? 0x1p-24 : 0x1p-53; }

/* The whole-sphere row of kernel k in precision p, from its regions. */
static void whole_sphere(const cert_result *res, const task *t, int nt, int k, int p, cert_result *w)
{
	int i, any = 0, cause = -1;
	memset(w, 0, sizeof *w);
	w->status = CERT_PROVEN;
	for (i = 0; i < nt; i++) {
		const cert_result *r = &res[i];
		if (t[i].k != k || t[i].prec != p)
			continue;
		any = 1;
		if (!(r->bound <= w->bound))
			w->bound = r->bound;
		if (r->found > w->found) {
			w->found = r->found;
			memcpy(w->found_n, r->found_n, sizeof w->found_n);
			memcpy(w->found_loc, r->found_loc, sizeof w->found_loc);
		}
		if (r->status == CERT_SINGULAR)
			w->status = CERT_SINGULAR;
		if (r->status == CERT_UNBOUNDED) {   /* the op also beside singular (stdout's count) */
			if (w->status != CERT_SINGULAR)
				w->status = CERT_UNBOUNDED;
			w->unb_op = r->unb_op;
		}
		if (r->status == CERT_BUDGET && !(r->bound < INFINITY) && cause < 0)
			cause = r->unb_op;   /* the first region without a bound says why */
		w->boxes += r->boxes;
		w->probes += r->probes;
	}
	if (!any)
		w->status = -1;
	else if (w->status != CERT_SINGULAR && w->status != CERT_UNBOUNDED) {
		w->status = w->bound <= 1.25 * w->found ? CERT_PROVEN : CERT_BUDGET;
		w->unb_op = cause;
	}
	if (w->status == CERT_SINGULAR)
		w->bound = INFINITY;
}

static void csv_row(FILE *f, const char *name, int dir, int p, const cert_region *r, const cert_result *x, int arith)
{
	fprintf(f, "%s,%s,%.17g,%.17g,%g,%g,", name, prec_name(p),
	        r->nz_lo, r->nz_hi, r->phi_lo, r->phi_hi);
	if (isinf(x->bound))
		fprintf(f, "inf,");
	else
		fprintf(f, "%.17g,", x->bound);   /* exact: the bound was rounded up once, never again */
	if (x->found > 0.0)
		fprintf(f, "%.17g,%a,%a,%a,%s,", x->found, x->found_n[0], x->found_n[1], x->found_n[2], status_name(x->status));
	else
		fprintf(f, "0,,,,%s,", status_name(x->status));
	fprintf(f, "%ld", x->probes);   /* inputs the found side evaluated */
	if (dir && x->found > 0.0)     /* frisvad_rotate: the found input's loc */
		fprintf(f, ",%a,%a,%a", x->found_loc[0], x->found_loc[1], x->found_loc[2]);
	else
		fprintf(f, ",,,");
	if (arith)   /* --arith: the operation an unbounded row owes it to, or why the bound is +inf */
		fprintf(f, ",%s", inf_cause(x));
	fprintf(f, "\n");
}

/* fn(x, j, arg) for j = 0..n-1 in parallel, each thread with its own
   cert_ctx x; pr (or NULL) counts them and draws the bar.  Returns -1
   when a thread could not make its context (its tasks were not run). */
typedef void (*cert_task_fn)(cert_ctx *x, int j, void *arg);

static int run_tasks(int n, cert_task_fn fn, void *arg, study_progress *pr)
{
	int fail = 0;
#pragma omp parallel
	{
		cert_ctx *x = cert_ctx_new();
		int j;
		if (!x) {
#pragma omp atomic write
			fail = 1;
		}
#pragma omp for schedule(dynamic, 1)
		for (j = 0; j < n; j++) {
			if (!x)
				continue;
			fn(x, j, arg);
			if (!pr)
				continue;
#pragma omp atomic
			pr->done++;
#ifdef _OPENMP
			if (omp_get_thread_num() == 0 && pr->bar)
#else
			if (pr->bar)
#endif
				study_progress_line("certify", pr);
		}
		cert_ctx_free(x);
	}
	return fail ? -1 : 0;
}

/* What the tasks of run_all and refine_top read. */
typedef struct {
	const study_kernel *ks;
	const cm_method **ms;
	const cert_region *reg;
	const task *t;
	const cert_cli *c;
	cert_result *res;
	const int *pick;   /* refine_top: the regions of the round */
	const struct image_pool_s *pool;   /* images_all: the pooled inputs */
	run_ctl *ctl;
	int flag;          /* the pass's CK_*: what its tasks commit */
} task_set;

/* ONB_CERT_KILL=PHASE:N (the tests of --resume): the process kills itself
   after the N-th task of phase run, images or refine that it committed
   (onbstudy-mpi: rank 0 commits every rank's results; with
   ONB_CERT_KILL_RANK=R rank R kills itself after the N-th it finished). */
static void kill_hook(run_ctl *c)
{
	const char *e = getenv("ONB_CERT_KILL"), *kr = getenv("ONB_CERT_KILL_RANK");
	static const char *const names[] = { "run", "images", "refine" };
	int p;
	c->kill_phase = 0;
	if ((cert_distribute ? cert_distribute->rank : 0) != (kr ? atoi(kr) : 0))
		return;
	for (p = 0; e && p < 3; p++)
		if (strncmp(e, names[p], strlen(names[p])) == 0 && e[strlen(names[p])] == ':') {
			c->kill_phase = 1 << p;
			c->kill_at = atol(e + strlen(names[p]) + 1);
		}
}

/* Task i's result r for phase flag (CK_*): into the results and the
   checkpoint's state, the checkpoint written when due. */
static void commit(const task_set *s, int i, const cert_result *r, int flag)
{
	run_ctl *c = s->ctl;
#pragma omp critical(cert_commit)
	if (!c->stopped) {
		s->res[i] = *r;
		if (flag == CK_REFINED)
			c->ck.ref[i] = *r;
		else
			c->ck.base[i] = *r;
		c->ck.flag[i] |= (unsigned char)flag;
		c->current = 0;
		if (c->dir && !c->failed && study_now() - c->last >= c->every) {
			c->failed = ck_write(c->dir, &c->ck) != 0;
			c->current = !c->failed;
			c->last = study_now();
		}
		if (flag == c->kill_phase && ++c->commits == c->kill_at)
			raise(SIGKILL);
	}
}

static void run_one(cert_ctx *x, int i, void *arg)
{
	const task_set *s = arg;
	const task *t = &s->t[i];
	cert_result r;
	if ((s->ctl->ck.flag[i] & CK_RUN) || s->ctl->failed)
		return;
	cert_region_run(x, &s->ks[t->k], s->ms[t->k], t->prec, &s->reg[t->prec * MAXREG + t->reg], &s->c->o, &r);
	commit(s, i, &r, CK_RUN);
}

static void refine_one(cert_ctx *x, int j, void *arg)
{
	const task_set *s = arg;
	const int i = s->pick[j];
	const task *t = &s->t[i];
	cert_result r = s->res[i];
	if (s->ctl->ck.flag[i] & CK_REFINED) {   /* refined before the run was stopped */
		s->res[i] = s->ctl->ck.ref[i];
		return;
	}
	if (s->ctl->failed)
		return;
	cert_region_refine(x, &s->ks[t->k], s->ms[t->k], t->prec, &s->reg[t->prec * MAXREG + t->reg], &s->c->o, &r);
	commit(s, i, &r, CK_REFINED);
}

/* onbstudy-mpi: another rank's result of task i, on rank 0. */
static void commit_remote(void *arg, int i, const cert_result *r)
{
	const task_set *s = arg;
	commit(s, i, r, s->flag);
}

/* The pass's n tasks (task j is region task pick[j], or j), here or over
   the ranks of onbstudy-mpi (cert_distribute). */
static int run_pass(int n, const int *pick, cert_task_fn fn, task_set *s, study_progress *pr)
{
	cert_pass p;
	if (!cert_distribute)
		return run_tasks(n, fn, s, pr);
	memset(&p, 0, sizeof p);
	p.n = n;
	p.pick = pick;
	p.flag = s->flag;
	p.fn = fn;
	p.arg = s;
	p.commit = commit_remote;
	p.res = s->res;
	p.flags = s->ctl->ck.flag;
	p.nres = s->ctl->ck.nt;
	p.failed = &s->ctl->failed;
	return cert_distribute->run(&p);
}

/* Every region of every kernel and precision, in parallel. */
static int run_all(const study_kernel *ks, const cm_method **ms, const cert_region *reg, const task *t, int nt,
                   cert_cli *c, cert_result *res, run_ctl *ctl)
{
	task_set s = { ks, ms, reg, t, c, res, NULL, NULL, ctl, CK_RUN };
	study_progress pr;
	int fail;
	memset(&pr, 0, sizeof pr);
	pr.bar = !c->quiet && isatty(2) && writer();
	pr.t0 = study_now();
	pr.total = (unsigned long long)nt;
	fail = run_pass(nt, NULL, run_one, &s, &pr);
	c->run_s = study_now() - pr.t0;
	if (pr.bar)
		fprintf(stderr, "\n");
	if (fail)
		study_error("out of memory: some regions were not run; nothing written");
	return fail;
}

/* The images pass (found_images.c), after every region has run: per
   kernel and precision a pool of every region's best inputs (known
   members of the domain) and the --starts inputs that fit, each region
   trying the images of its pool that fall in it.  pool[off[g]..off[g+1])
   is group g's. */
typedef struct image_pool_s {
	cert_pool_in *in;
	long *off;
} image_pool;

static void pool_add(image_pool *p, long *fill, int g, const double n[3], int sure, int write)
{
	if (write) {
		memcpy(p->in[fill[g]].n, n, sizeof p->in->n);
		p->in[fill[g]].sure = sure;
	}
	fill[g]++;
}

/* Counts the pool (write 0) into fill, or fills it (write 1). */
static void pool_pass(const study_kernel *ks, int nk, const task *t, int nt, const cert_result *res,
                      const cert_opts *o, image_pool *p, long *fill, int write)
{
	long s;
	int i, j, k;
	for (i = 0; i < nt; i++)
		for (j = 0; j < res[i].nkeep; j++)
			pool_add(p, fill, group_of(&t[i]), res[i].keep_n[j], 1, write);
	for (s = 0; s < o->nstarts; s++)
		for (k = 0; k < nk; k++)
			for (j = PREC_FLOAT; j <= PREC_DOUBLE; j++)
				if (found_start_fits(&o->starts[s], ks[k].name, j))
					pool_add(p, fill, 2 * k + j, o->starts[s].n, 0, write);
}

static void images_one(cert_ctx *x, int i, void *arg)
{
	const task_set *s = arg;
	const task *t = &s->t[i];
	const image_pool *p = s->pool;
	const int g = group_of(t);
	cert_result r = s->res[i];
	if ((s->ctl->ck.flag[i] & CK_IMAGES) || s->ctl->failed)
		return;
	cert_region_images(x, &s->ks[t->k], t->prec, &s->reg[t->prec * MAXREG + t->reg], &s->c->o,
	                   p->in + p->off[g], p->off[g + 1] - p->off[g], &r);
	commit(s, i, &r, CK_IMAGES);
}

static int images_all(const study_kernel *ks, int nk, const cm_method **ms, const cert_region *reg, const task *t,
                      int nt, cert_cli *c, cert_result *res, run_ctl *ctl)
{
	const double t0 = study_now();
	const int ng = 2 * nk;
	image_pool p;
	long *fill = calloc((size_t)ng + 1, sizeof *fill);
	int g, fail = -1;
	p.off = calloc((size_t)ng + 1, sizeof *p.off);
	p.in = NULL;
	if (fill && p.off) {
		pool_pass(ks, nk, t, nt, res, &c->o, &p, fill, 0);
		for (g = 0; g < ng; g++)
			p.off[g + 1] = p.off[g] + fill[g];
		p.in = malloc((size_t)(p.off[ng] > 0 ? p.off[ng] : 1) * sizeof *p.in);
	}
	if (p.in) {
		task_set s = { ks, ms, reg, t, c, res, NULL, NULL, ctl, CK_IMAGES };
		s.pool = &p;
		memcpy(fill, p.off, (size_t)ng * sizeof *fill);
		pool_pass(ks, nk, t, nt, res, &c->o, &p, fill, 1);
		fail = run_pass(nt, NULL, images_one, &s, NULL);
		c->pool = p.off[ng];
	}
	c->images_s = study_now() - t0;
	free(fill);
	free(p.off);
	free(p.in);
	if (fail)
		study_error("out of memory: the images pass was not run; nothing written");
	return fail ? -1 : 0;
}

/* The regions that set a whole-sphere bound, refined.  For each kernel
   and precision whose whole-sphere bracket is wider than REFINE_ABOVE
   (the target), the regions left at their budget whose bound is within
   REFINE_NEAR of the largest, and above every bound a refined region
   kept, are bounded again without the stall stop (cert_region_refine);
   again while some are, while each round takes at least REFINE_GAIN off
   its regions' largest bound, and for REFINE_MAX regions at most.  The stall stop keeps
   the run short where splitting pays little; there it would decide the
   whole-sphere bracket.  A region below a refined one's bound cannot lower
   the whole-sphere bound: it is left. */
#define REFINE_ABOVE 2.0
#define REFINE_NEAR 0.98
#define REFINE_GAIN 0.05
#define REFINE_MAX 64

typedef struct {
	double top, kept, found;   /* the largest bound, a refined region's, the largest found */
	double before;             /* the largest bound of the round's regions before it */
	int stop, count;
	int frozen;                /* re-used whole (--reuse): its results are final */
} refine_group;

static void refine_tops(const task *t, int nt, const cert_result *res, const unsigned char *done, refine_group *g, int ng)
{
	int i;
	for (i = 0; i < ng; i++)
		g[i].top = g[i].kept = g[i].found = 0.0;
	for (i = 0; i < nt; i++) {
		refine_group *r = &g[group_of(&t[i])];
		if (res[i].status == CERT_SINGULAR)
			continue;
		if (res[i].bound > r->top)
			r->top = res[i].bound;
		if (done[i] && res[i].bound > r->kept)
			r->kept = res[i].bound;
		if (res[i].found > r->found)
			r->found = res[i].found;
	}
}

/* The next round's regions into pick; their number. */
static int refine_pick(const task *t, int nt, const cert_result *res, const unsigned char *done, refine_group *g,
                       int ng, int *pick)
{
	int i, np = 0;
	refine_tops(t, nt, res, done, g, ng);
	for (i = 0; i < ng; i++)
		if ((g[i].count == 0 && !(g[i].top > REFINE_ABOVE * g[i].found)) || g[i].frozen)
			g[i].stop = 1;   /* within the target already, or re-used whole */
	for (i = 0; i < nt; i++) {
		refine_group *r = &g[group_of(&t[i])];
		if (!r->stop && r->count < REFINE_MAX && !done[i] && res[i].status == CERT_BUDGET &&
		    res[i].bound >= REFINE_NEAR * r->top && res[i].bound > r->kept) {
			pick[np++] = i;
			r->count++;
			if (res[i].bound > r->before)
				r->before = res[i].bound;
		}
	}
	return np;
}

/* After a round: a kernel and precision whose refined regions' largest
   bound fell by less than REFINE_GAIN is refined no more. */
static void refine_gain(const task *t, const cert_result *res, const int *pick, int np, refine_group *g, int ng)
{
	double *after = calloc((size_t)ng, sizeof *after);
	int j;
	if (!after) {
		for (j = 0; j < ng; j++)
			g[j].stop = 1;
		return;
	}
	for (j = 0; j < np; j++)
		if (res[pick[j]].bound > after[group_of(&t[pick[j]])])
			after[group_of(&t[pick[j]])] = res[pick[j]].bound;
	for (j = 0; j < ng; j++) {
		if (g[j].before > 0.0 && !(after[j] <= (1.0 - REFINE_GAIN) * g[j].before))
			g[j].stop = 1;
		g[j].before = 0.0;
	}
	free(after);
}

static int refine_top(const study_kernel *ks, const cm_method **ms, const cert_region *reg, const task *t, int nt,
                      cert_cli *c, cert_result *res, run_ctl *ctl)
{
	const double t0 = study_now();
	unsigned char *done = calloc((size_t)nt, 1);
	int *pick = malloc((size_t)nt * sizeof *pick), np, fail = 0, ng = 0, i;
	refine_group *g;
	for (i = 0; i < nt; i++)
		if (group_of(&t[i]) >= ng)
			ng = group_of(&t[i]) + 1;
	g = calloc((size_t)ng + 1, sizeof *g);
	for (i = 0; g && c->frozen && i < ng; i++)
		g[i].frozen = c->frozen[i];
	if (!done || !pick || !g) {
		free(done);
		free(pick);
		free(g);
		study_error("out of memory");
		return -1;
	}
	while (!fail && (np = refine_pick(t, nt, res, done, g, ng, pick)) > 0) {
		task_set s = { ks, ms, reg, t, c, res, pick, NULL, ctl, CK_REFINED };
		fail = run_pass(np, pick, refine_one, &s, NULL);
		for (i = 0; i < np; i++)
			done[pick[i]] = 1;
		refine_gain(t, res, pick, np, g, ng);
	}
	for (i = 0; i < nt; i++)
		c->refined += done[i];
	c->refine_s = study_now() - t0;
	free(done);
	free(pick);
	free(g);
	if (fail)
		study_error("out of memory: some regions were not refined; nothing written");
	return fail ? -1 : 0;
}

/* Does any selected method use an approximate reciprocal square root (a
   normalization of its registry row that starts from a seed)? */
static int uses_seeds(const study_kernel *ks, int nk)
{
	int k;
	for (k = 0; k < nk; k++)
		if (ks[k].m && (ks[k].m->norm == ONB__NORM_INVSQRT || ks[k].m->norm == ONB__NORM_RSQRT ||
		                ks[k].m->norm == ONB__NORM_RSQRT_NR))
			return 1;
	return 0;
}

/* The seed bounds the run used, with the CPU (rsqrtss is CPU-specific). */
static void seeds_provenance(FILE *f, const study_kernel *ks, int nk)
{
	int s;
	if (!uses_seeds(ks, nk))
		return;
	fprintf(f, "# seeds: cpu %s\n", seed_cpu());
	for (s = 0; s < NSEED; s++) {
		seed_bound b;
		if (seed_bound_get((seed_kind)s, &b) == 0)
			fprintf(f, "# seed %s: |s sqrt(x) - 1| <= %a (%.6g), worst x %a; %s\n", seed_name((seed_kind)s),
			        b.bound, b.bound, b.worst_x, b.how);
	}
}

static const char *const phase_names[CERT_NT] = { "sampling", "walks", "boxes", "box probes", "images", "refinement" };

/* The CPU seconds of every phase over all regions into sum (CERT_NT). */
static void phase_sums(const cert_result *res, int nt, double *sum)
{
	int i, j;
	for (j = 0; j < CERT_NT; j++)
		sum[j] = 0.0;
	for (i = 0; i < nt; i++)
		for (j = 0; j < CERT_NT; j++)
			sum[j] += res[i].cpu[j];
}

/* "sampling 1.2 s, walks ..." of the CPU seconds in sum. */
static void phase_line(FILE *f, const double *sum)
{
	int j;
	double all = 0.0;
	for (j = 0; j < CERT_NT; j++)
		all += sum[j];
	for (j = 0; j < CERT_NT; j++)
		fprintf(f, "%s%s %.1f s (%.0f%%)", j ? ", " : "", phase_names[j], sum[j], all > 0 ? 100.0 * sum[j] / all : 0.0);
	fprintf(f, "; %.1f s in all", all);
}

static double region_cpu(const cert_result *r)
{
	double s = 0.0;
	int j;
	for (j = 0; j < CERT_NT; j++)
		s += r->cpu[j];
	return s;
}

/* The profile on stderr: CPU seconds per phase, wall seconds per pass, and
   the methods that took longest. */
static void print_profile(const study_kernel *ks, int nk, const task *t, int nt, const cert_result *res,
                          const cert_cli *c)
{
	double sum[CERT_NT], *per = calloc((size_t)(2 * nk) + 1, sizeof *per);
	int i, shown;
	phase_sums(res, nt, sum);
	fprintf(stderr, "certify: CPU per phase: ");
	phase_line(stderr, sum);
	fprintf(stderr, "\ncertify: wall: regions %.1f s, images %.1f s, refinement %.1f s on %d threads\n", c->run_s,
	        c->images_s, c->refine_s, cert_threads());
	if (!per)
		return;
	for (i = 0; i < nt; i++)
		per[group_of(&t[i])] += region_cpu(&res[i]);
	fprintf(stderr, "certify: CPU per method (the longest):");
	for (shown = 0; shown < 5; shown++) {
		int g, top = -1;
		for (g = 0; g < 2 * nk; g++)
			if (per[g] > 0.0 && (top < 0 || per[g] > per[top]))
				top = g;
		if (top < 0)
			break;
		fprintf(stderr, "%s %s %s %.1f s", shown ? "," : "", ks[top / 2].name, prec_name(top % 2), per[top]);
		per[top] = 0.0;
	}
	fprintf(stderr, "; every region's in certify-times.csv\n");
	free(per);
}

/* certify-times.csv: every region's CPU seconds per phase (the profile
   and the per-region cost the MPI scaling figures come from). */
static int write_times(FILE *f, const study_kernel *ks, const cert_region *reg, const task *t, int nt,
                       const cert_result *res, const cert_cli *c)
{
	int i, j;
	study_provenance(f, "certify", (unsigned long long)c->o.seed, cert_threads());
	fprintf(f, "# CPU seconds of each region's phases (thread CPU time); wall: regions %.1f s, images %.1f s, "
	        "refinement %.1f s\n", c->run_s, c->images_s, c->refine_s);
	fprintf(f, "method,precision,nz_lo,nz_hi,phi_lo,phi_hi,sampling_s,walks_s,boxes_s,box_probes_s,images_s,refine_s,boxes\n");
	for (i = 0; i < nt; i++) {
		const cert_region *r = &reg[t[i].prec * MAXREG + t[i].reg];
		fprintf(f, "%s,%s,%.17g,%.17g,%g,%g", ks[t[i].k].name, prec_name(t[i].prec), r->nz_lo, r->nz_hi, r->phi_lo,
		        r->phi_hi);
		for (j = 0; j < CERT_NT; j++)
			fprintf(f, ",%.6f", res[i].cpu[j]);
		fprintf(f, ",%ld\n", res[i].boxes);
	}
	return ferror(f) ? -1 : 0;
}

static int write_csv(FILE *f, const study_kernel *ks, int nk, const cert_region *reg, const task *t, int nt,
                     const cert_result *res, const cert_cli *c)
{
	int k, p, i;
	study_provenance(f, "certify", (unsigned long long)c->o.seed, cert_threads());
	fprintf(f, "# domain: %s\n", c->o.tolerance < 0 ? "every rounding to nearest of a real unit vector"
	                                                : "every n with | |n| - 1 | <= tolerance");
	if (c->o.tolerance >= 0)
		fprintf(f, "# tolerance: %.17g\n", c->o.tolerance);
	fprintf(f, "# images: every region also tried the images under the 48 signed permutations of %ld inputs (each "
	        "region's best and the --starts of its method and precision) that fall in it (%.0f s)\n", c->pool, c->images_s);
	fprintf(f, "# refine: %ld regions that set a whole-sphere bound wider than %.0fx found bounded again without the "
	        "stall stop (%.0f s)\n", c->refined, REFINE_ABOVE, c->refine_s);
	{
		double sum[CERT_NT];
		phase_sums(res, nt, sum);
		fprintf(f, "# profile: CPU per phase: ");
		phase_line(f, sum);
		fprintf(f, "; every region's in certify-times.csv\n");
	}
	fprintf(f, "# budget: %ld boxes per region, %ld samples, target bound <= %.2f found, %d sectors\n",
	        c->o.budget, c->o.samples, c->o.target, c->sectors);
	if (c->fma) {
		int j;
		fprintf(f, "# fma: METHOD+fma rows are the kernels compiled with -mfma -ffp-contract=fast, bounded with contracted models (");
		for (j = 0; cm_fma_name((size_t)j); j++)
			fprintf(f, "%s%s", j ? " " : "", cm_fma_name((size_t)j));
		fprintf(f, "); the other methods' +fma copies have none and no rows\n");
	}
	if (c->band)
		fprintf(f, "# band: %.17g <= n.z <= %.17g (the first row of each method is this band, not the sphere)\n",
		        c->band_lo, c->band_hi);
	if (c->arith_given) {
		char d[2048];
		arith_describe(c->o.arith, d, sizeof d);
		fprintf(f, "# arith: %s (%s; %s)\n", c->o.arith->name, c->o.arith->title, c->o.arith->spec);
		fprintf(f, "# model: the IEEE model's operations, each widened to the profile's allowance (src/model/arith.c): %s\n", d);
		fprintf(f, "# found: the largest of the IEEE kernel's defect and an adversarial emulation's (src/certify/emulate.c, 1 greedy pass) at each region's 4 best inputs\n");
	} else {
		fprintf(f, "# model: IEEE binary32/binary64, round to nearest, no contraction, correctly rounded sqrt, subnormals kept (no FTZ/DAZ)\n");
	}
	seeds_provenance(f, ks, nk);
	if (c->reuse)
		fprintf(f, "# reuse: %d methods and precisions taken from %s/certify.csv, their keys unchanged (%s)\n",
		        c->nreused, c->reuse, KEYS_NAME);
	if (c->starts)
		fprintf(f, "# starts: the found side also walked from the %ld inputs of %s\n", c->o.nstarts, c->starts);
	for (i = 0; i < nt && ks[t[i].k].m; i++)
		;
	if (i < nt)
		fprintf(f, "# frisvad_rotate: bound and found are its direction error max(| |w| - 1 |, |w.n - z|) for w the kernel's output on the local direction loc = (x, y, z), over every loc that is a rounding of a unit vector; found_lx,found_ly,found_lz: the found input's loc (empty on the other methods' rows)\n");
	fprintf(f, "method,precision,nz_lo,nz_hi,phi_lo,phi_hi,bound,found,found_nx,found_ny,found_nz,status,evaluated,found_lx,found_ly,found_lz%s\n",
	        c->arith_given ? ",unbounded_by" : "");
	for (k = 0; k < nk; k++)
		for (p = 0; p < 2; p++) {
			cert_result w;
			cert_region all = { -1.0, 1.0, 0.0, 360.0 };
			if (c->band) {
				all.nz_lo = c->band_lo;
				all.nz_hi = c->band_hi;
			}
			whole_sphere(res, t, nt, k, p, &w);
			if (w.status < 0)
				continue;
			csv_row(f, ks[k].name, !ks[k].m, p, &all, &w, c->arith_given);
			for (i = 0; i < nt; i++)
				if (t[i].k == k && t[i].prec == p)
					csv_row(f, ks[k].name, !ks[k].m, p, &reg[p * MAXREG + t[i].reg], &res[i], c->arith_given);
		}
	return ferror(f) ? -1 : 0;
}

static void print_summary(const study_kernel *ks, int nk, const task *t, int nt, const cert_result *res, int arith)
{
	int k, p;
	printf("%-24s %-6s %12s %12s %7s  %s\n", "method", "prec", "bound/u", "found/u", "ratio", "status (regions proven/singular/budget)");
	for (k = 0; k < nk; k++)
		for (p = 0; p < 2; p++) {
			cert_result w;
			int i, cnt[4] = { 0, 0, 0, 0 };
			whole_sphere(res, t, nt, k, p, &w);
			if (w.status < 0)
				continue;
			for (i = 0; i < nt; i++)
				if (t[i].k == k && t[i].prec == p)
					cnt[res[i].status]++;
			printf("%-24s %-6s %12.4g %12.4g %7.3g  %s (%d/%d/%d)", ks[k].name, prec_name(p),
			       w.bound / unit_of(p), w.found / unit_of(p), w.found > 0 ? w.bound / w.found : NAN,
			       status_name(w.status), cnt[0], cnt[1], cnt[2]);
			if (cnt[3])
				printf(" %d unbounded (%s)", cnt[3], unb_name(w.unb_op));
			else if (arith && w.status == CERT_BUDGET && !(w.bound < INFINITY))
				printf(" inf by %s", inf_cause(&w));
			printf("\n");
		}
}

/* The run's settings that enter every region's result, one line (the
   checkpoint's and the keys file's; the methods are the groups). */
static void settings_line(const cert_cli *c, char *buf, size_t cap)
{
	uint64_t h = CERT_FNV0, hp;
	long i;
	for (i = 0; i < c->o.nstarts; i++) {
		const cert_start *st = &c->o.starts[i];
		h = cert_hash_str(h, st->method);
		h = cert_hash_bytes(h, &st->prec, sizeof st->prec);
		h = cert_hash_bytes(h, st->n, sizeof st->n);
		h = cert_hash_bytes(h, &st->has_loc, sizeof st->has_loc);
		if (st->has_loc)
			h = cert_hash_bytes(h, st->loc, sizeof st->loc);
	}
	{   /* the arithmetic profile: its name and every allowance (arith.h) */
		char d[4096];
		arith_describe(c->o.arith ? c->o.arith : arith_ieee(), d, sizeof d);
		hp = cert_hash_str(CERT_FNV0, d);
	}
	snprintf(buf, cap, "budget=%ld samples=%ld sectors=%d target=%a tolerance=%a seed=%llu band=%s%a,%a starts=%ld:%016" PRIx64
	         " arith=%s:%016" PRIx64, c->o.budget, c->o.samples, c->sectors, c->o.target, c->o.tolerance,
	         (unsigned long long)c->o.seed, c->band ? "" : "none:", c->band ? c->band_lo : 0.0, c->band ? c->band_hi : 0.0,
	         c->o.nstarts, h, (c->o.arith ? c->o.arith : arith_ieee())->name, hp);
}

/* Group (k, p)'s key: its method's (keys.c), the settings, the engine,
   its regions and the --starts of its method and precision. */
static uint64_t group_key(cert_ctx *x, const study_kernel *k, const cm_method *m, int p, const char *settings,
                          const cert_region *reg, size_t nreg, const cert_opts *o)
{
	uint64_t h = cert_hash_str(CERT_FNV0, settings), mk = cert_method_key(x, k, m, p);
	long s;
	h = cert_hash_str(h, cert_engine());
	h = cert_hash_bytes(h, &mk, sizeof mk);
	h = cert_hash_bytes(h, reg, nreg * sizeof *reg);
	for (s = 0; s < o->nstarts; s++)
		if (found_start_fits(&o->starts[s], k->name, p))
			h = cert_hash_bytes(h, &o->starts[s], sizeof o->starts[s]);
	return h;
}

/* The run's groups (the methods and precisions with regions) and their
   keys into ctl->ck; gi[2 k + p] the index of group (k, p), or -1. */
static int make_groups(const study_kernel *ks, int nk, const cm_method **ms, const cert_region *reg,
                       const size_t *nreg, const task *t, int nt, const cert_cli *c, run_ctl *ctl, int *gi)
{
	static char settings[1024];
	ck_group *g = calloc((size_t)(2 * nk) + 1, sizeof *g);
	cert_ctx *x = cert_ctx_new();
	int i, ng = 0;
	if (!g || !x) {
		free(g);
		cert_ctx_free(x);
		study_error("out of memory");
		return -1;
	}
	settings_line(c, settings, sizeof settings);
	for (i = 0; i < 2 * nk; i++)
		gi[i] = -1;
	for (i = 0; i < nt; i++) {
		const int k = t[i].k, p = t[i].prec;
		if (gi[group_of(&t[i])] >= 0)
			continue;
		gi[group_of(&t[i])] = ng;
		snprintf(g[ng].name, sizeof g[ng].name, "%s", ks[k].name);
		g[ng].prec = p;
		g[ng].key = group_key(x, &ks[k], ms[k], p, settings, reg + p * MAXREG, nreg[p], &c->o);
		ng++;
	}
	cert_ctx_free(x);
	ctl->ck.settings = settings;
	ctl->ck.engine = cert_engine();
	ctl->ck.ng = ng;
	ctl->ck.nt = nt;
	ctl->ck.g = g;
	ctl->ck.flag = calloc((size_t)nt + 1, 1);
	ctl->ck.base = calloc((size_t)nt + 1, sizeof *ctl->ck.base);
	ctl->ck.ref = calloc((size_t)nt + 1, sizeof *ctl->ck.ref);
	if (!ctl->ck.flag || !ctl->ck.base || !ctl->ck.ref) {
		study_error("out of memory");
		return -1;
	}
	return 0;
}

static void free_ctl(run_ctl *ctl)
{
	free((void *)ctl->ck.g);
	free(ctl->ck.flag);
	free(ctl->ck.base);
	free(ctl->ck.ref);
}

/* Row s of a certify.csv (its fields split at commas) into *r. */
static int parse_row(char **f, int nf, cert_result *r)
{
	char *e;
	int j;
	memset(r, 0, sizeof *r);
	if (nf < 16)
		return -1;
	r->bound = strtod(f[6], &e);
	r->found = strtod(f[7], &e);
	for (j = 0; j < 3 && r->found > 0.0; j++) {
		r->found_n[j] = strtod(f[8 + j], &e);
		r->found_loc[j] = *f[13 + j] ? strtod(f[13 + j], &e) : 0.0;
	}
	r->status = strcmp(f[11], "proven") == 0 ? CERT_PROVEN : strcmp(f[11], "singular") == 0 ? CERT_SINGULAR
	          : strcmp(f[11], "unbounded") == 0 ? CERT_UNBOUNDED : CERT_BUDGET;
	r->probes = strtol(f[12], &e, 10);
	r->unb_op = -1;
	for (j = 0; r->status == CERT_UNBOUNDED && nf > 16 && j <= AR_NOPS; j++)
		if (strcmp(f[16], unb_name(j)) == 0)
			r->unb_op = j;
	if (r->status == CERT_BUDGET && !(r->bound < INFINITY) && nf > 16)
		r->unb_op = parse_cause(f[16]);
	return 0;
}

/* Group gr's rows of DIR/certify.csv (its first, the whole sphere's,
   left out) into res for its tasks, matched by region; the number taken
   or -1. */
static int reuse_group(FILE *in, const ck_group *gr, const cert_region *reg, const task *t, int nt, int gidx,
                       const int *gi, cert_result *res, unsigned char *flag)
{
	char line[8192], want[512], *f[24];
	int i = 0, first = 1, took = 0;
	rewind(in);
	while (fgets(line, sizeof line, in)) {
		cert_result r;
		int nf;
		if (line[0] == '#')
			continue;
		nf = split_fields(line, f, 24);
		if (nf < 16 || strcmp(f[0], gr->name) != 0 || strcmp(f[1], prec_name(gr->prec)) != 0)
			continue;
		if (first) {   /* the whole sphere (or --band) */
			first = 0;
			continue;
		}
		while (i < nt && gi[group_of(&t[i])] != gidx)
			i++;
		if (i == nt)
			return -1;
		snprintf(want, sizeof want, "%.17g,%.17g,%g,%g", reg[t[i].prec * MAXREG + t[i].reg].nz_lo,
		         reg[t[i].prec * MAXREG + t[i].reg].nz_hi, reg[t[i].prec * MAXREG + t[i].reg].phi_lo,
		         reg[t[i].prec * MAXREG + t[i].reg].phi_hi);
		snprintf(line, sizeof line, "%s,%s,%s,%s", f[2], f[3], f[4], f[5]);
		if (strcmp(line, want) != 0 || parse_row(f, nf, &r))
			return -1;
		res[i] = r;
		flag[i] = CK_RUN | CK_IMAGES;
		took++;
		i++;
	}
	return took;
}

/* --reuse DIR: every group whose key DIR/certify-keys.csv holds, from
   DIR/certify.csv, frozen (no images pass, no refinement). */
static int reuse_dir(cert_cli *c, const cert_region *reg, const task *t, int nt, const int *gi, int ngi,
                     run_ctl *ctl, cert_result *res, unsigned char *frozen)
{
	char path[4096];
	int *cur = calloc((size_t)ctl->ck.ng + 1, sizeof *cur), g, i, rc;
	FILE *in;
	if (!cur || snprintf(path, sizeof path, "%s/certify.csv", c->reuse) >= (int)sizeof path || (rc = keys_compare(c->reuse, &ctl->ck, cur, 0)) < 0 || !(in = fopen(path, "r"))) {
		study_error("--reuse %s: no certify.csv and %s there", c->reuse, KEYS_NAME);
		free(cur);
		return -1;
	}
	for (g = 0; g < ctl->ck.ng && rc == 0; g++) {
		int want = 0;
		for (i = 0; i < nt; i++)
			want += gi[group_of(&t[i])] == g;
		if (!cur[g] || reuse_group(in, &ctl->ck.g[g], reg, t, nt, g, gi, res, ctl->ck.flag) != want) {
			for (i = 0; i < nt; i++)   /* not re-used: computed from scratch */
				if (gi[group_of(&t[i])] == g)
					ctl->ck.flag[i] = 0;
			continue;
		}
		for (i = 0; i < ngi; i++)
			if (gi[i] == g)
				frozen[i] = 1;
		c->nreused++;
	}
	fclose(in);
	free(cur);
	for (i = 0; i < nt; i++)
		if (ctl->ck.flag[i])
			ctl->ck.base[i] = res[i];
	fprintf(stderr, "certify: --reuse %s: %d of %d methods and precisions re-used (their keys unchanged), %d to "
	        "compute\n", c->reuse, c->nreused, ctl->ck.ng, ctl->ck.ng - c->nreused);
	return 0;
}

/* --check-keys DIR: 0 when every group's key is DIR's, else 1 (the
   stale named), 2 with no keys there. */
static int check_keys(const cert_cli *c, run_ctl *ctl)
{
	int *cur = calloc((size_t)ctl->ck.ng + 1, sizeof *cur), g, stale = 0, rc;
	if (!cur)
		return 1;
	rc = keys_compare(c->check_keys, &ctl->ck, cur, 0);
	if (rc < 0) {
		study_error("--check-keys %s: no %s there", c->check_keys, KEYS_NAME);
		free(cur);
		return 2;
	}
	for (g = 0; g < ctl->ck.ng; g++)
		if (!cur[g]) {
			printf("stale: %s %s (key %016" PRIx64 " now)\n", ctl->ck.g[g].name, prec_name(ctl->ck.g[g].prec),
			       ctl->ck.g[g].key);
			stale++;
		}
	printf("%s: %d of %d keys current%s\n", c->check_keys, ctl->ck.ng - stale, ctl->ck.ng,
	       rc ? "; the settings or the engine differ" : "");
	free(cur);
	return stale || rc ? 1 : 0;
}

/* --write-keys DIR: the keys of this command line into DIR's keys file,
   once DIR/certify.csv holds a row of every one of its regions and no
   other method and precision; 0, or 1 refused. */
static int write_keys(const cert_cli *c, const cert_region *reg, const task *t, int nt, const int *gi,
                      run_ctl *ctl)
{
	char path[4096], line[8192], *f[24];
	cert_result *res = calloc((size_t)nt + 1, sizeof *res);
	unsigned char *flag = calloc((size_t)nt + 1, 1);
	int g, i, bad = 0, rows = 0;
	FILE *in = NULL;
	if (!res || !flag || snprintf(path, sizeof path, "%s/certify.csv", c->write_keys) >= (int)sizeof path ||
	    !(in = fopen(path, "r"))) {
		study_error("--write-keys %s: no certify.csv there", c->write_keys);
		bad = 1;
	}
	for (g = 0; !bad && g < ctl->ck.ng; g++) {
		int want = 0;
		for (i = 0; i < nt; i++)
			want += gi[group_of(&t[i])] == g;
		if (reuse_group(in, &ctl->ck.g[g], reg, t, nt, g, gi, res, flag) != want) {
			study_error("--write-keys %s: its certify.csv does not hold the %d regions of %s %s of this "
			            "command line", c->write_keys, want, ctl->ck.g[g].name, prec_name(ctl->ck.g[g].prec));
			bad = 1;
		}
		rows += want + 1;
	}
	if (!bad) {   /* no rows of other methods, precisions or regions */
		rewind(in);
		while (fgets(line, sizeof line, in))
			rows -= line[0] != '#' && split_fields(line, f, 24) >= 16 && strcmp(f[0], "method") != 0;
		if ((bad = rows != 0) != 0)
			study_error("--write-keys %s: its certify.csv holds rows of methods, precisions or regions not on "
			            "this command line", c->write_keys);
	}
	if (in)
		fclose(in);
	free(res);
	free(flag);
	if (bad || keys_write(c->write_keys, &ctl->ck, study_cmdline))
		return 1;
	printf("%s: %d keys written (no proof run)\n", c->write_keys, ctl->ck.ng);
	return 0;
}

/* --resume DIR: the checkpoint's state into res; 0 to run, 1 when the
   work is done already, -1 refused. */
static int resume_dir(const cert_cli *c, run_ctl *ctl, cert_result *res)
{
	char path[4096];
	int i, n = 0, r = ck_read(c->resume, &ctl->ck), *cur;
	FILE *f;
	if (r < 0)
		return -1;
	if (r == 0) {
		for (i = 0; i < ctl->ck.nt; i++)
			if (ctl->ck.flag[i]) {
				res[i] = ctl->ck.base[i];
				n++;
			}
		fprintf(stderr, "certify: --resume %s: continuing from its checkpoint (%d of %d regions run)\n", c->resume,
		        n, ctl->ck.nt);
		return 0;
	}
	if (snprintf(path, sizeof path, "%s/certify.csv", c->resume) >= (int)sizeof path)
		return -1;
	if (!(cur = calloc((size_t)ctl->ck.ng + 1, sizeof *cur)))
		return -1;
	r = keys_compare(c->resume, &ctl->ck, cur, 0);
	for (i = 0; i < ctl->ck.ng && r == 0; i++)
		if (!cur[i]) {
			study_error("--resume %s: its finished run is of another revision of %s %s's model or kernel "
			            "(--reuse %s recomputes only what changed)", c->resume, ctl->ck.g[i].name,
			            prec_name(ctl->ck.g[i].prec), c->resume);
			r = 1;
		}
	free(cur);
	if (r > 0)
		return -1;
	if (r == 0 && (f = fopen(path, "r"))) {
		fclose(f);
		fprintf(stderr, "certify: --resume %s: the work is done (its certify.csv is of this command line and "
		        "every key is current); nothing to do\n", c->resume);
		return 1;
	}
	fprintf(stderr, "certify: --resume %s: no checkpoint there yet: starting from the beginning\n", c->resume);
	return 0;
}

/* A checkpoint now (the end of a pass), with --resume; -1 when one
   could not be written (the run stops: its last one is intact). */
static int ck_now(run_ctl *ctl)
{
	if (!ctl->failed && ctl->dir) {
		ctl->failed = ck_write(ctl->dir, &ctl->ck) != 0;
		ctl->current = !ctl->failed;
		ctl->last = study_now();
	}
	if (ctl->failed)
		study_error("the run stopped: the checkpoint in %s could not be written", ctl->dir);
	return ctl->failed ? -1 : 0;
}

/* The keys, --check-keys, --reuse, --resume: 0 to run; else 1 + the exit
   status (done or checked), or -1 refused. */
static int prepare_state(cert_cli *c, const study_kernel *ks, int nk, const cm_method **ms, const cert_region *reg,
                         const size_t *nreg, const task *t, int nt, cert_result *res, run_ctl *ctl, int *gi,
                         unsigned char *frozen, const char *dir)
{
	int r;
	if (make_groups(ks, nk, ms, reg, nreg, t, nt, c, ctl, gi))
		return 2;
	if (!writer()) {   /* onbstudy-mpi's other ranks: rank 0 decides the rest (share_state) */
		kill_hook(ctl);
		return 0;
	}
	if (c->check_keys)
		return 1 + check_keys(c, ctl);
	if (c->write_keys)
		return 1 + write_keys(c, reg, t, nt, gi, ctl);
	if (study_mkdir_p(dir))
		return 2;
	kill_hook(ctl);
	ctl->every = c->ck_every;
	ctl->last = study_now();
	if (c->reuse && reuse_dir(c, reg, t, nt, gi, 2 * nk, ctl, res, frozen))
		return -1;
	c->frozen = frozen;
	if (c->resume) {
		if ((r = resume_dir(c, ctl, res)) != 0)
			return r > 0 ? 1 : -1;
		ctl->dir = c->resume;
	}
	return 0;
}

/* onbstudy-mpi: rank 0's outcome of prepare_state (r) and the state it
   loaded (--resume, --reuse) to every rank; prepare_state's value. */
static int share_state(cert_cli *c, run_ctl *ctl, cert_result *res, unsigned char *frozen, int nf, int r)
{
	const cert_dist *d = cert_distribute;
	const int mine = r;
	d->share(&r, sizeof r);
	if (d->agree(mine == 2) && r == 0)   /* a rank could not make its groups */
		r = 2;
	if (r != 0)
		return r;
	d->share(res, (size_t)ctl->ck.nt * sizeof *res);
	d->share(ctl->ck.flag, (size_t)ctl->ck.nt);
	d->share(frozen, (size_t)nf);
	d->share(&c->nreused, sizeof c->nreused);
	c->frozen = frozen;
	return 0;
}

/* The files of a finished run: certify.csv, certify-times.csv, the keys;
   the checkpoint removed. */
static int write_outputs(const char *dir, const study_kernel *ks, int nk, const cert_region *reg, const task *t,
                         int nt, const cert_result *res, const cert_cli *c, const run_ctl *ctl)
{
	study_out out;
	char path[4096];
	if (study_out_open(&out, dir, "certify.csv"))
		return -1;
	if (write_csv(out.f, ks, nk, reg, t, nt, res, c) || study_out_commit(&out)) {
		study_out_abort(&out);
		study_error("%s/certify.csv: write failed; nothing written", dir);
		return -1;
	}
	if (study_out_open(&out, dir, "certify-times.csv"))
		return -1;
	if (write_times(out.f, ks, reg, t, nt, res, c) || study_out_commit(&out)) {
		study_out_abort(&out);
		study_error("%s/certify-times.csv: write failed", dir);
		return -1;
	}
	if (keys_write(dir, &ctl->ck, study_cmdline))
		return -1;
	if (snprintf(path, sizeof path, "%s/%s", dir, CK_NAME) < (int)sizeof path)
		remove(path);
	return 0;
}

/* The rounding model of each selected kernel into ms[] (NULL: left out,
   said for a --fma copy without one); 0, or a usage error for a method
   named on --methods that cannot be certified. */
static int select_models(const cert_cli *c, const study_kernel *ks, int nk, const cm_method **ms)
{
	int k;
	for (k = 0; k < nk; k++) {
		if (ks[k].fma) {   /* no contracted model: said, and left out */
			if (!(ms[k] = ks[k].m ? cm_find_fma(ks[k].m->name) : NULL) && !c->quiet && strcmp(c->methods, "all") != 0)
				fprintf(stderr, "certify: %s: no contracted rounding model, not certified\n", ks[k].name);
			continue;
		}
		if (!(ms[k] = cm_find(ks[k].name)) && strcmp(c->methods, "all") != 0) {
			study_error("--methods: %s has no rounding model", ks[k].name);
			return ONB_EXIT_USAGE;
		}
		if (ms[k] && ms[k]->direction && c->o.tolerance >= 0) {   /* its model assumes n.z >= -1 */
			if (strcmp(c->methods, "all") != 0) {
				study_error("--tolerance: %s is certified in the default domain only (n.z < -1 takes another path)", ks[k].name);
				return ONB_EXIT_USAGE;
			}
			ms[k] = NULL;
		}
	}
	return 0;
}

/* onbstudy-mpi's rank 0: the run under way, for cert_stop_save and
   cert_task_name (set and cleared under critical(cert_commit)). */
static struct {
	run_ctl *ctl;
	const study_kernel *ks;
	const cert_region *reg;
	const task *t;
	const char *dir;        /* where the checkpoint goes */
} live;

static void set_live(run_ctl *ctl, const study_kernel *ks, const cert_region *reg, const task *t, const char *dir)
{
#pragma omp critical(cert_commit)
	{
		live.ctl = ctl;
		live.ks = ks;
		live.reg = reg;
		live.t = t;
		live.dir = dir;
	}
}

int cert_stop(cert_saved *v)
{
	int rc = 1, i;
	memset(v, 0, sizeof *v);
#pragma omp critical(cert_commit)
	if (live.ctl) {
		run_ctl *c = live.ctl;
		c->stopped = 1;
		v->nt = c->ck.nt;
		v->resume = c->dir != NULL;
		snprintf(v->dir, sizeof v->dir, "%s", live.dir);
		for (i = 0; i < c->ck.nt; i++) {
			v->run += (c->ck.flag[i] & CK_RUN) != 0;
			v->images += (c->ck.flag[i] & CK_IMAGES) != 0;
			v->refined += (c->ck.flag[i] & CK_REFINED) != 0;
		}
		rc = 0;
	}
	return rc;
}

int cert_stop_save(void)
{
	int rc = 1;
#pragma omp critical(cert_commit)
	if (live.ctl)   /* nothing new since the last checkpoint: no write to be cut short by mpirun's SIGKILL */
		rc = live.ctl->current ? 0 : ck_write(live.dir, &live.ctl->ck) != 0 ? -1 : 0;
	return rc;
}

void cert_task_name(int i, char *buf, size_t cap)
{
	if (cap)
		buf[0] = 0;
#pragma omp critical(cert_commit)
	if (live.ctl && i >= 0 && i < live.ctl->ck.nt) {
		const task *t = &live.t[i];
		const cert_region *r = &live.reg[t->prec * MAXREG + t->reg];
		snprintf(buf, cap, "%s %s region %d (n.z in [%.9g, %.9g], azimuth [%g, %g) degrees)", live.ks[t->k].name,
		         prec_name(t->prec), t->reg + 1, r->nz_lo, r->nz_hi, r->phi_lo, r->phi_hi);
	}
}

/* --precision half: certify_half.c, with the profile's binary16 row. */
static int run_half(const cert_cli *c)
{
	ch_opts h;
	if (c->arith_given && !arith_has_format(c->o.arith, PREC_HALF)) {
		study_error("certify: --arith %s gives binary16 no precision (docs/gpu.md; ieee, vulkan, vulkan-precise, opencl, "
		            "cuda-fast and contract-any have a half row)", c->o.arith->name);
		return ONB_EXIT_USAGE;
	}
	memset(&h, 0, sizeof h);
	h.methods = c->methods; h.out = c->out; h.sectors = c->sectors; h.quiet = c->quiet;
	h.band = c->band; h.band_lo = c->band_lo; h.band_hi = c->band_hi;
	h.arith = c->arith_given ? c->o.arith : NULL;
	h.depth = c->depth >= 0 ? (int)c->depth : c->quick ? 3 : 6;
	h.az = c->az >= 0 ? (int)c->az : c->quick ? 4 : 16;
	h.resume = c->resume;
	h.every = c->ck_every;
	return cert_half_run(&h);
}

int cmd_certify(int argc, char **argv)
{
	cert_cli c;
	study_kernel ks[MAXK];
	const cm_method *ms[MAXK];
	static cert_region reg[2 * MAXREG];
	size_t nreg[2];
	task *t;
	cert_result *res;
	int nk, k, p, nt = 0, rc = 1, r, gi[2 * MAXK];
	static unsigned char frozen[2 * MAXK];
	char dir[4096];
	run_ctl ctl;
	memset(&ctl, 0, sizeof ctl);
	if ((r = parse(argc, argv, &c)) != 0)
		return r < 0 ? 0 : r;
	if (c.half)
		return run_half(&c);
	if (c.fma && !fma_available()) {
		study_error("--fma: this CPU or build has no FMA");
		return ONB_EXIT_USAGE;
	}
	if ((nk = kernels_select(c.methods, c.fma, ks, MAXK)) < 0)
		return ONB_EXIT_USAGE;
	if (select_models(&c, ks, nk, ms))
		return ONB_EXIT_USAGE;
	if (c.starts && load_starts(&c))
		return ONB_EXIT_USAGE;
	for (p = 0; p < 2; p++)
		nreg[p] = c.band ? regions_band(p, c.sectors, c.band_lo, c.band_hi,
		                                reg + p * MAXREG, MAXREG)
		                 : regions_default(p, c.sectors, reg + p * MAXREG, MAXREG);
	t = malloc((size_t)nk * (nreg[0] + nreg[1]) * sizeof *t);
	res = calloc((size_t)nk * (nreg[0] + nreg[1]), sizeof *res);
	if (!t || !res) {
		study_error("out of memory");
		goto done;
	}
	for (k = 0; k < nk; k++)
		for (p = 0; p < 2; p++) {
			size_t i;
			if (!ms[k] || !c.prec_on[p] || !kernel_runs(&ks[k], p))
				continue;
			for (i = 0; i < nreg[p]; i++) {
				t[nt].k = k; t[nt].prec = p; t[nt].reg = (int)i;
				nt++;
			}
		}
	if (c.out)
		snprintf(dir, sizeof dir, "%s", c.out);
	else
		study_current_run_dir(dir, sizeof dir);
	if (uses_seeds(ks, nk)) {   /* computed once, outside the parallel regions */
		int sk;
		for (sk = 0; sk < NSEED; sk++) {
			seed_bound sb;
			if (seed_bound_get((seed_kind)sk, &sb) != 0) {
				study_error("the seed bound of %s could not be computed", seed_name((seed_kind)sk));
				goto done;
			}
		}
	}
	r = prepare_state(&c, ks, nk, ms, reg, nreg, t, nt, res, &ctl, gi, frozen, dir);
	if (cert_distribute)
		r = share_state(&c, &ctl, res, frozen, 2 * nk, r);
	if (r != 0) {
		rc = r > 0 ? r - 1 : ONB_EXIT_USAGE;
		goto done;
	}
	if (cert_distribute && writer())
		set_live(&ctl, ks, reg, t, dir);
	if (run_all(ks, ms, reg, t, nt, &c, res, &ctl) || ck_now(&ctl) ||
	    images_all(ks, nk, ms, reg, t, nt, &c, res, &ctl) || ck_now(&ctl) ||
	    refine_top(ks, ms, reg, t, nt, &c, res, &ctl) || ck_now(&ctl) ||
	    (writer() && write_outputs(dir, ks, nk, reg, t, nt, res, &c, &ctl)))
		goto done;
	if (writer()) {
		print_summary(ks, nk, t, nt, res, c.arith_given);
		print_profile(ks, nk, t, nt, res, &c);
		fprintf(stderr, "certify: wrote %s/certify.csv\n", dir);
	}
	rc = 0;
done:
	set_live(NULL, NULL, NULL, NULL, NULL);
	free(t);
	free(res);
	free_ctl(&ctl);
	free((void *)c.o.starts);
	return rc;
}
