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
} cert_cli;

typedef struct {
	int k, prec, reg;   /* kernel, precision, region index */
} task;

static int group_of(const task *t) { return 2 * t->k + t->prec; }

static void usage(FILE *f)
{
	fprintf(f,
	"usage: onbstudy certify [--methods LIST] [--precision float|double|both] [--out DIR]\n"
	"                        [--budget N] [--samples N] [--sectors N] [--tolerance T]\n"
	"                        [--band LO,HI] [--starts FILE[,FILE...]] [--seed S]\n"
	"                        [--fma] [--arith PROFILE] [--quick] [--quiet]\n\n"
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
	"  --precision P     float, double or both (default both)\n"
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
		CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
	};
	cli_args a;
	long l;
	unsigned long long u;
	int v, budget_set = 0, samples_set = 0, sectors_set = 0;
	memset(c, 0, sizeof *c);
	c->methods = "all";
	c->prec_on[0] = c->prec_on[1] = 1;
	c->o.budget = 6000; c->o.samples = 1000; c->o.target = 1.25; c->o.tolerance = -1.0; c->o.seed = 1;
	c->sectors = 8;
	if (cli_begin(&a, "certify", argc, argv))
		return ONB_EXIT_USAGE;
	while ((v = cli_next(&a, lo)) != -1) {
		switch (v) {
		case CLI_HELP: usage(stdout); cli_end(&a); return -1;
		case 'm': c->methods = a.arg; break;
		case 'p': if (cli_precision("--precision", a.arg, c->prec_on)) goto bad; break;
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
		case 'A':
			if (!(c->o.arith = arith_find(a.arg))) {
				char names[256];
				arith_names(names, sizeof names);
				study_error("--arith: unknown profile '%s' (one of: %s)", a.arg, names);
				goto bad;
			}
			c->arith_given = !arith_is_ieee(c->o.arith);
			break;
		default: goto bad;
		}
	}
	if (cli_no_rest(&a))
		goto bad;
	if (c->arith_given && c->fma) {
		study_error("--arith and --fma exclude each other (a profile's contraction covers the +fma copies)");
		goto bad;
	}
	cli_end(&a);
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

static double unit_of(int prec) { return prec == PREC_FLOAT ? 0x1p-24 : 0x1p-53; }

/* The whole-sphere row of kernel k in precision p, from its regions. */
static void whole_sphere(const cert_result *res, const task *t, int nt, int k, int p, cert_result *w)
{
	int i, any = 0;
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
		if (r->status == CERT_UNBOUNDED && w->status != CERT_SINGULAR) {
			w->status = CERT_UNBOUNDED;
			w->unb_op = r->unb_op;
		}
		w->boxes += r->boxes;
		w->probes += r->probes;
	}
	if (!any)
		w->status = -1;
	else if (w->status != CERT_SINGULAR && w->status != CERT_UNBOUNDED)
		w->status = w->bound <= 1.25 * w->found ? CERT_PROVEN : CERT_BUDGET;
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
	if (arith)   /* --arith: the operation an unbounded row owes it to */
		fprintf(f, ",%s", x->status == CERT_UNBOUNDED ? unb_name(x->unb_op) : "");
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
} task_set;

static void run_one(cert_ctx *x, int i, void *arg)
{
	const task_set *s = arg;
	const task *t = &s->t[i];
	cert_region_run(x, &s->ks[t->k], s->ms[t->k], t->prec, &s->reg[t->prec * MAXREG + t->reg], &s->c->o, &s->res[i]);
}

static void refine_one(cert_ctx *x, int j, void *arg)
{
	const task_set *s = arg;
	const int r = s->pick[j];
	const task *t = &s->t[r];
	cert_region_refine(x, &s->ks[t->k], s->ms[t->k], t->prec, &s->reg[t->prec * MAXREG + t->reg], &s->c->o,
	                   &s->res[r]);
}

/* Every region of every kernel and precision, in parallel. */
static int run_all(const study_kernel *ks, const cm_method **ms, const cert_region *reg, const task *t, int nt,
                   cert_cli *c, cert_result *res)
{
	const task_set s = { ks, ms, reg, t, c, res, NULL, NULL };
	study_progress pr;
	int fail;
	memset(&pr, 0, sizeof pr);
	pr.bar = !c->quiet && isatty(2);
	pr.t0 = study_now();
	pr.total = (unsigned long long)nt;
	fail = run_tasks(nt, run_one, (void *)&s, &pr);
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
	cert_region_images(x, &s->ks[t->k], t->prec, &s->reg[t->prec * MAXREG + t->reg], &s->c->o,
	                   p->in + p->off[g], p->off[g + 1] - p->off[g], &s->res[i]);
}

static int images_all(const study_kernel *ks, int nk, const cm_method **ms, const cert_region *reg, const task *t,
                      int nt, cert_cli *c, cert_result *res)
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
		task_set s = { ks, ms, reg, t, c, res, NULL, NULL };
		s.pool = &p;
		memcpy(fill, p.off, (size_t)ng * sizeof *fill);
		pool_pass(ks, nk, t, nt, res, &c->o, &p, fill, 1);
		fail = run_tasks(nt, images_one, (void *)&s, NULL);
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
		if (g[i].count == 0 && !(g[i].top > REFINE_ABOVE * g[i].found))
			g[i].stop = 1;   /* within the target already */
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
                      cert_cli *c, cert_result *res)
{
	const double t0 = study_now();
	unsigned char *done = calloc((size_t)nt, 1);
	int *pick = malloc((size_t)nt * sizeof *pick), np, fail = 0, ng = 0, i;
	refine_group *g;
	for (i = 0; i < nt; i++)
		if (group_of(&t[i]) >= ng)
			ng = group_of(&t[i]) + 1;
	g = calloc((size_t)ng + 1, sizeof *g);
	if (!done || !pick || !g) {
		free(done);
		free(pick);
		free(g);
		study_error("out of memory");
		return -1;
	}
	while (!fail && (np = refine_pick(t, nt, res, done, g, ng, pick)) > 0) {
		const task_set s = { ks, ms, reg, t, c, res, pick, NULL };
		fail = run_tasks(np, refine_one, (void *)&s, NULL);
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
		for (j = 0; cm_fma_names[j]; j++)
			fprintf(f, "%s%s", j ? " " : "", cm_fma_names[j]);
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

static void print_summary(const study_kernel *ks, int nk, const task *t, int nt, const cert_result *res)
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
			printf("\n");
		}
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
	int nk, k, p, nt = 0, rc = 1, r;
	char dir[4096];
	study_out out;
	if ((r = parse(argc, argv, &c)) != 0)
		return r < 0 ? 0 : r;
	if (c.fma && !fma_available()) {
		study_error("--fma: this CPU or build has no FMA");
		return ONB_EXIT_USAGE;
	}
	if ((nk = kernels_select(c.methods, c.fma, ks, MAXK)) < 0)
		return ONB_EXIT_USAGE;
	for (k = 0; k < nk; k++) {
		if (ks[k].fma) {   /* no contracted model: said, and left out */
			if (!(ms[k] = ks[k].m ? cm_find_fma(ks[k].m->name) : NULL) && !c.quiet && strcmp(c.methods, "all") != 0)
				fprintf(stderr, "certify: %s: no contracted rounding model, not certified\n", ks[k].name);
			continue;
		}
		if (!(ms[k] = cm_find(ks[k].name)) && strcmp(c.methods, "all") != 0) {
			study_error("--methods: %s has no rounding model", ks[k].name);
			return ONB_EXIT_USAGE;
		}
		if (ms[k] && ms[k]->direction && c.o.tolerance >= 0) {   /* its model assumes n.z >= -1 */
			if (strcmp(c.methods, "all") != 0) {
				study_error("--tolerance: %s is certified in the default domain only (n.z < -1 takes another path)", ks[k].name);
				return ONB_EXIT_USAGE;
			}
			ms[k] = NULL;
		}
	}
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
	if (study_mkdir_p(dir) || run_all(ks, ms, reg, t, nt, &c, res) ||
	    images_all(ks, nk, ms, reg, t, nt, &c, res) || refine_top(ks, ms, reg, t, nt, &c, res))
		goto done;
	if (study_out_open(&out, dir, "certify.csv"))
		goto done;
	if (write_csv(out.f, ks, nk, reg, t, nt, res, &c) || study_out_commit(&out)) {
		study_out_abort(&out);
		study_error("%s/certify.csv: write failed; nothing written", dir);
		goto done;
	}
	if (study_out_open(&out, dir, "certify-times.csv"))
		goto done;
	if (write_times(out.f, ks, reg, t, nt, res, &c) || study_out_commit(&out)) {
		study_out_abort(&out);
		study_error("%s/certify-times.csv: write failed", dir);
		goto done;
	}
	print_summary(ks, nk, t, nt, res);
	print_profile(ks, nk, t, nt, res, &c);
	fprintf(stderr, "certify: wrote %s/certify.csv\n", dir);
	rc = 0;
done:
	free(t);
	free(res);
	free((void *)c.o.starts);
	return rc;
}
