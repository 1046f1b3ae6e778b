/*
 * table.c - `onbstudy table`: the successor of Frisvad 2012, Table 1, for
 * this machine.  Joins a bench.csv (speed) with a sweep's summary.csv
 * (accuracy), marks the Pareto front and writes tradeoff.csv.
 *
 * Speed: batch M bases/s at the L2-resident size, 1 thread and all
 * threads, and the inline call_throughput ns per call.  Accuracy: RMSE on
 * `uniform`, max_defect on `south` and on `threshold`.
 *
 * Pareto front, per precision: a method is on it when no other method is
 * at least as fast (batch, 1 thread, L2) and at least as accurate, and
 * strictly better in one of the two.  Speeds within a tolerance (default
 * 5%, --speed-tol) count as equal: at the L2 size the cheap methods all
 * run at the copy roofline, and their order there is timing noise.  So B
 * beats A when speed_B >= (1 - tol) speed_A and err_B <= err_A, and
 * err_B < err_A or speed_B > (1 + tol) speed_A.  Accuracy here is the worst
 * max_defect over uniform, south and threshold together; a method with
 * any non-finite output on those inputs counts as infinitely inaccurate.
 * Methods without both speed and accuracy are left off the front ("na").
 */
#include <errno.h>
#include <glob.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "bench/table.h"
#include "common/csv.h"
#include "common/options.h"
#include "common/output.h"
#include "common/prec.h"

#define CSV_MAXF 64

static double num(const char *s)
{
	char *end;
	double v;
	if (!s || !*s)
		return NAN;
	v = strtod(s, &end);
	return *end ? NAN : v;
}

typedef struct {
	FILE *f;
	const char *path;
	char hline[4096], line[4096];
	char *hdr[CSV_MAXF], *fld[CSV_MAXF];
	int nh;
	long lineno;
} csv_file;

static int csv_open(csv_file *c, const char *path)
{
	memset(c, 0, sizeof *c);
	c->path = path;
	c->f = fopen(path, "r");
	if (!c->f) {
		study_error("table: cannot read '%s': %s", path, strerror(errno));
		return -1;
	}
	while (fgets(c->hline, sizeof c->hline, c->f)) {
		c->lineno++;
		if (c->hline[0] == '#' || c->hline[0] == '\n')
			continue;
		c->nh = csv_split(c->hline, c->hdr, CSV_MAXF, 1);
		return 0;
	}
	study_error("table: '%s' has no header line", path);
	fclose(c->f);
	return -1;
}

/* The next data row: its number of fields, 0 at the end. */
static int csv_next(csv_file *c)
{
	while (fgets(c->line, sizeof c->line, c->f)) {
		c->lineno++;
		if (c->line[0] == '#' || c->line[0] == '\n')
			continue;
		return csv_split(c->line, c->fld, CSV_MAXF, 1);
	}
	return 0;
}

static int find_row(const tradeoff_row *rows, int n, const char *method, int prec)
{
	int i;
	for (i = 0; i < n; i++)
		if (rows[i].prec == prec && strcmp(rows[i].method, method) == 0)
			return i;
	return -1;
}

static int parse_prec(const char *s)
{
	return strcmp(s, "double") == 0 ? PREC_DOUBLE : strcmp(s, "float") == 0 ? PREC_FLOAT :
	       strcmp(s, "half") == 0 ? PREC_HALF : -1;
}

typedef struct {
	tradeoff_row *v;
	int n, cap;
} row_set;

/* The row of method at precision prec, appended (every figure NaN) when new.
   Its index, or -1 (reported). */
static int row_of(row_set *s, const char *method, int prec)
{
	int r = find_row(s->v, s->n, method, prec);
	if (r >= 0)
		return r;
	if (s->n == s->cap) {
		tradeoff_row *t;
		s->cap = s->cap ? 2 * s->cap : 64;
		t = realloc(s->v, (size_t)s->cap * sizeof *t);
		if (!t) {
			study_error("table: out of memory");
			return -1;
		}
		s->v = t;
	}
	r = s->n++;
	memset(&s->v[r], 0, sizeof s->v[r]);
	snprintf(s->v[r].method, sizeof s->v[r].method, "%s", method);
	s->v[r].prec = prec;
	s->v[r].batch1 = s->v[r].batchn = s->v[r].call_ns = NAN;
	s->v[r].rmse_uniform = s->v[r].max_south = s->v[r].max_threshold = s->v[r].max_worst = NAN;
	s->v[r].max_uniform = s->v[r].max_floor_uniform = s->v[r].x_floor = NAN;
	s->v[r].rms_ratio_uniform = s->v[r].max_ratio_uniform = NAN;
	return r;
}

/* The speeds of bench.csv's L2 batch and call_throughput rows into s.  0, or -1 (reported). */
static int load_speeds(const char *bench_csv, row_set *s)
{
	csv_file c;
	int nf, i, cm, cp, cmode, ct, ccls, cmbs, cns;

	if (csv_open(&c, bench_csv) != 0)
		return -1;
	cm = csv_col(c.hdr, c.nh, "method");
	cp = csv_col(c.hdr, c.nh, "precision");
	cmode = csv_col(c.hdr, c.nh, "mode");
	ct = csv_col(c.hdr, c.nh, "threads");
	ccls = csv_col(c.hdr, c.nh, "size_class");
	cmbs = csv_col(c.hdr, c.nh, "mbases_per_s");
	cns = csv_col(c.hdr, c.nh, "ns_per_call");
	if (cm < 0 || cp < 0 || cmode < 0 || ct < 0 || cmbs < 0 || cns < 0) {
		study_error("table: '%s' lacks one of the columns method,precision,mode,threads,mbases_per_s,ns_per_call", bench_csv);
		fclose(c.f);
		return -1;
	}
	while ((nf = csv_next(&c)) > 0) {
		const char *mode;
		int prec, r, thr;
		if (nf != c.nh) {
			study_error("table: %s:%ld: %d fields, the header has %d", bench_csv, c.lineno, nf, c.nh);
			goto fail;
		}
		mode = c.fld[cmode];
		prec = parse_prec(c.fld[cp]);
		if (prec < 0) {
			study_error("table: %s:%ld: precision '%s' is not float, double or half", bench_csv, c.lineno, c.fld[cp]);
			goto fail;
		}
		if (strcmp(mode, "batch") && strcmp(mode, "call_throughput"))
			continue;
		if (ccls >= 0 && strcmp(c.fld[ccls], "l2") != 0)
			continue;
		r = row_of(s, c.fld[cm], prec);
		if (r < 0)
			goto fail;
		thr = atoi(c.fld[ct]);
		if (strcmp(mode, "batch") == 0) {
			if (thr <= 1)
				s->v[r].batch1 = num(c.fld[cmbs]);
			else {
				s->v[r].batchn = num(c.fld[cmbs]);
				s->v[r].threads = thr;
			}
		} else
			s->v[r].call_ns = num(c.fld[cns]);
	}
	fclose(c.f);
	for (i = 0; i < s->n; i++)
		s->v[i].has_speed = !isnan(s->v[i].batch1);
	return 0;
fail:
	fclose(c.f);
	return -1;
}

/* The columns of summary.csv; the last four optional (-1 when absent). */
typedef struct {
	int m, p, dist, rmse, max, nf, fl, rr, mr;
} sum_cols;

/* One summary row of distribution bit (1 uniform, 2 south, 4 threshold) into
   row r; seen holds the bits seen so far. */
static void set_accuracy(tradeoff_row *r, char **fld, const sum_cols *k, int bit, int *seen)
{
	double mx = num(fld[k->max]);
	if (bit == 1) {
		r->rmse_uniform = num(fld[k->rmse]);
		r->max_uniform = mx;
		if (k->fl >= 0)
			r->max_floor_uniform = num(fld[k->fl]);
		if (k->rr >= 0)
			r->rms_ratio_uniform = num(fld[k->rr]);
		if (k->mr >= 0)
			r->max_ratio_uniform = num(fld[k->mr]);
		r->x_floor = r->max_floor_uniform > 0.0 ? mx / r->max_floor_uniform : NAN;
	} else if (bit == 2)
		r->max_south = mx;
	else
		r->max_threshold = mx;
	if (isnan(mx))
		mx = INFINITY;
	if (!(*seen & 7) || mx > r->max_worst)
		r->max_worst = mx;
	if (k->nf >= 0)
		r->nonfinite += atol(fld[k->nf]);
	*seen |= bit;
}

/* The rows of csv c, open at its data, into rows[0..n-1]; seen[i]: bit 0
   uniform, 1 south, 2 threshold seen.  0, or -1 (reported). */
static int read_accuracy(csv_file *c, const char *summary_csv, const sum_cols *k, tradeoff_row *rows, int n, int *seen)
{
	int nf;
	while ((nf = csv_next(c)) > 0) {
		const char *d;
		int prec, r, bit;
		if (nf != c->nh) {
			study_error("table: %s:%ld: %d fields, the header has %d", summary_csv, c->lineno, nf, c->nh);
			return -1;
		}
		prec = parse_prec(c->fld[k->p]);
		r = prec < 0 ? -1 : find_row(rows, n, c->fld[k->m], prec);
		if (r < 0)
			continue;
		d = c->fld[k->dist];
		bit = strcmp(d, "uniform") == 0 ? 1 : strcmp(d, "south") == 0 ? 2 : strcmp(d, "threshold") == 0 ? 4 : 0;
		if (!bit)
			continue;
		set_accuracy(&rows[r], c->fld, k, bit, &seen[r]);
	}
	return 0;
}

/* The accuracy of summary.csv's uniform, south and threshold rows into the
   rows found in bench.csv.  0, or -1 (reported). */
static int load_accuracy(const char *summary_csv, tradeoff_row *rows, int n)
{
	csv_file c;
	sum_cols k;
	int *seen, i, rc;

	if (csv_open(&c, summary_csv) != 0)
		return -1;
	k.m = csv_col(c.hdr, c.nh, "method");
	k.p = csv_col(c.hdr, c.nh, "precision");
	k.dist = csv_col(c.hdr, c.nh, "distribution");
	k.rmse = csv_col(c.hdr, c.nh, "rmse");
	k.max = csv_col(c.hdr, c.nh, "max_defect");
	k.nf = csv_col(c.hdr, c.nh, "nonfinite");
	k.fl = csv_col(c.hdr, c.nh, "max_floor");       /* the floor: optional (older runs lack it) */
	k.rr = csv_col(c.hdr, c.nh, "rms_floor_ratio");
	k.mr = csv_col(c.hdr, c.nh, "max_floor_ratio");
	if (k.m < 0 || k.p < 0 || k.dist < 0 || k.rmse < 0 || k.max < 0) {
		study_error("table: '%s' lacks one of the columns method,precision,distribution,rmse,max_defect", summary_csv);
		fclose(c.f);
		return -1;
	}
	seen = calloc((size_t)(n ? n : 1), sizeof *seen);
	if (!seen) {
		study_error("table: out of memory");
		fclose(c.f);
		return -1;
	}
	rc = read_accuracy(&c, summary_csv, &k, rows, n, seen);
	if (rc == 0)
		for (i = 0; i < n; i++)
			rows[i].has_accuracy = seen[i] == 7;
	free(seen);
	fclose(c.f);
	return rc;
}

/* A row (accuracy only) for every binary16 method of summary.csv that
   bench.csv has no speed for (a bench run without --precision half).
   0, or -1 (reported). */
static int add_half_rows(const char *summary_csv, row_set *s)
{
	csv_file c;
	int km, kp, nf, rc = 0;
	if (csv_open(&c, summary_csv) != 0)
		return -1;
	km = csv_col(c.hdr, c.nh, "method");
	kp = csv_col(c.hdr, c.nh, "precision");
	while (rc == 0 && km >= 0 && kp >= 0 && (nf = csv_next(&c)) > 0)
		if (nf > km && nf > kp && strcmp(c.fld[kp], "half") == 0 && row_of(s, c.fld[km], PREC_HALF) < 0)
			rc = -1;
	fclose(c.f);
	return rc;
}

int tradeoff_load(const char *bench_csv, const char *summary_csv, double tol, tradeoff_row **rows_out)
{
	row_set s = { NULL, 0, 0 };
	*rows_out = NULL;
	if (load_speeds(bench_csv, &s) != 0 || add_half_rows(summary_csv, &s) != 0 ||
	    load_accuracy(summary_csv, s.v, s.n) != 0) {
		free(s.v);
		return -1;
	}
	tradeoff_pareto(s.v, s.n, tol);
	*rows_out = s.v;
	return s.n;
}

static double err_of(const tradeoff_row *r)
{
	return r->nonfinite > 0 || isnan(r->max_worst) ? INFINITY : r->max_worst;
}

void tradeoff_pareto(tradeoff_row *rows, int n, double tol)
{
	int i, j;
	for (i = 0; i < n; i++) {
		const double si = rows[i].batch1, ei = err_of(&rows[i]);
		rows[i].pareto = 0;
		if (!rows[i].has_speed || !rows[i].has_accuracy)
			continue;
		rows[i].pareto = 1;
		for (j = 0; j < n; j++) {
			double sj, ej;
			if (j == i || rows[j].prec != rows[i].prec || !rows[j].has_speed || !rows[j].has_accuracy)
				continue;
			sj = rows[j].batch1;
			ej = err_of(&rows[j]);
			if (sj >= (1.0 - tol) * si && ej <= ei && (ej < ei || sj > (1.0 + tol) * si)) {
				rows[i].pareto = 0;
				break;
			}
		}
	}
}

/* results/latest/<name> if it exists, else the newest results/run-* that has it */
static int default_path(const char *name, char *buf, size_t n)
{
	struct stat st;
	char pat[256];
	glob_t g;
	snprintf(buf, n, "results/latest/%s", name);
	if (stat(buf, &st) == 0)
		return 0;
	snprintf(pat, sizeof pat, "results/run-*/%s", name);
	if (glob(pat, 0, NULL, &g) == 0 && g.gl_pathc > 0) {
		snprintf(buf, n, "%s", g.gl_pathv[g.gl_pathc - 1]);
		fflush(stdout);
		fprintf(stderr, "onbstudy: table: results/latest has no %s; using %s\n", name, buf);
		globfree(&g);
		return 0;
	}
	study_error("table: no %s in results/latest/ or results/run-*/ (run onbstudy %s, or pass --%s FILE)", name,
	            strcmp(name, "bench.csv") == 0 ? "bench" : "sweep", strcmp(name, "bench.csv") == 0 ? "bench" : "summary");
	return -1;
}

#define TRADEOFF_COLUMNS "method,precision,batch_mbases_1t,batch_mbases_all,threads_all,call_ns," \
	"rmse_uniform,max_defect_south,max_defect_threshold,max_defect_worst,nonfinite,pareto," \
	"max_defect_uniform,max_floor_uniform,x_floor,rms_floor_ratio_uniform,max_floor_ratio_uniform"

static void print_cell(double v, const char *fmt, int w)
{
	if (isnan(v))
		printf(" %*s", w, "-");
	else
		printf(fmt, w, v);
}

static void table_usage(void)
{
	printf("usage: onbstudy table [--bench FILE] [--summary FILE] [--out DIR] [--speed-tol T] [--format table|csv]\n"
	       "                     [--precision P]\n"
	       "  --bench FILE     a bench.csv (default results/latest/bench.csv, else the newest results/run-*/bench.csv)\n"
	       "  --summary FILE   a sweep's summary.csv (default: found the same way)\n"
	       "  --out DIR        where tradeoff.csv goes (default: the directory of the bench.csv)\n"
	       "  --speed-tol T    speeds within this fraction count as equal on the Pareto front (default 0.05)\n"
	       "  --format F       table (default) or csv on stdout\n"
	       "  --precision P    float, double, both, half or all: the rows kept (default: every precision of\n"
	       "                   the two files).  half: bench --precision half's speeds (binary16 emulated in\n"
	       "                   float: not hardware half speed) beside sweep --precision half's accuracy\n");
}

typedef struct {
	const char *bench, *summary, *out;
	int csv, prec_given, prec_on[PREC_COUNT];
	double tol;
} table_opts;

static int table_option(int v, const char *a, table_opts *o)
{
	if (!*a) {
		study_error("--%s needs a value", v == 'b' ? "bench" : v == 's' ? "summary" : v == 'o' ? "out" :
		            v == 't' ? "speed-tol" : v == 'p' ? "precision" : "format");
		return -1;
	}
	switch (v) {
	case 'b': o->bench = a; return 0;
	case 's': o->summary = a; return 0;
	case 'o': o->out = a; return 0;
	case 't':
		if (parse_double("--speed-tol", a, &o->tol) != 0)
			return -1;
		if (!(o->tol >= 0.0 && o->tol < 1.0)) {
			study_error("--speed-tol: %s is out of range [0, 1)", a);
			return -1;
		}
		return 0;
	case 'f': return (o->csv = cli_format("--format", a, 0)) < 0 ? -1 : 0;
	case 'p': o->prec_given = 1; return cli_precision_half("--precision", a, o->prec_on);
	}
	return -1;
}

/* 0; 1 after --help; ONB_EXIT_USAGE after a message. */
static int table_parse(int argc, char **argv, table_opts *o)
{
	static const struct option lo[] = {
		{ "bench", required_argument, NULL, 'b' }, { "summary", required_argument, NULL, 's' },
		{ "out", required_argument, NULL, 'o' }, { "speed-tol", required_argument, NULL, 't' },
		{ "format", required_argument, NULL, 'f' }, { "precision", required_argument, NULL, 'p' },
		CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
	};
	cli_args c;
	int v, rc = 0;
	memset(o, 0, sizeof *o);
	o->tol = 0.05;
	if (cli_begin(&c, "table", argc, argv))
		return ONB_EXIT_USAGE;
	while (rc == 0 && (v = cli_next(&c, lo)) != -1) {
		if (v == CLI_HELP) { table_usage(); rc = 1; }
		else if (v == CLI_ERROR || table_option(v, c.arg, o) != 0) rc = ONB_EXIT_USAGE;
	}
	if (rc == 0 && cli_no_rest(&c) != 0)
		rc = ONB_EXIT_USAGE;
	cli_end(&c);
	return rc;
}

/* The default inputs (results/latest, else the newest run) and output
   (the bench.csv's directory).  0, or -1 after a message. */
static int table_paths(table_opts *o, char *bbuf, char *sbuf, char *obuf, size_t len)
{
	if (!o->bench) {
		if (default_path("bench.csv", bbuf, len) != 0)
			return -1;
		o->bench = bbuf;
	}
	if (!o->summary) {
		if (default_path("summary.csv", sbuf, len) != 0)
			return -1;
		o->summary = sbuf;
	}
	if (!o->out) {
		const char *sl = strrchr(o->bench, '/');
		if (sl) {
			snprintf(obuf, len, "%.*s", (int)(sl - o->bench), o->bench);
			o->out = sl == o->bench ? "/" : obuf;
		} else
			o->out = ".";
	}
	return 0;
}

/* tradeoff.csv; 0, or -1 after a message. */
static int table_write(const table_opts *o, const tradeoff_row *rows, int n, study_out *f)
{
	int i, p;
	if (study_mkdir_p(o->out) != 0 || study_out_open(f, o->out, "tradeoff.csv") != 0)
		return -1;
	study_provenance(f->f, "table", 0, 0);
	fprintf(f->f, "# bench: %s\n# summary: %s\n", o->bench, o->summary);
	fprintf(f->f, "# speed: batch at the L2-resident size (1 thread, all threads), call_ns = inline call_throughput; "
	              "accuracy: rmse on uniform, max_defect on south and threshold\n");
	fprintf(f->f, "# pareto: per precision, 1 when no other method is at least as fast (batch_mbases_1t, speeds within "
	              "%g%% counted equal) and at least as accurate (max_defect_worst = max over uniform, south, threshold; "
	              "any nonfinite output = infinite) and better in one; na without speed or accuracy\n", 100.0 * o->tol);
	fprintf(f->f, "# floor (uniform): max_floor_uniform = the largest defect of the method's exact formula rounded once to the format; "
	              "x_floor = max_defect_uniform / max_floor_uniform; *_floor_ratio_uniform: the per-input ratio's RMS and max (summary.csv)\n");
	for (i = 0; i < n && !(rows[i].prec == PREC_HALF && rows[i].has_speed); i++)
		;
	if (i < n)
		fprintf(f->f, "# half: speeds from bench --precision half, binary16 arithmetic EMULATED in float (libonb's half "
		              "kernels, each operation rounded to binary16): not hardware half speed\n");
	fprintf(f->f, "%s\n", TRADEOFF_COLUMNS);
	for (p = 0; p < PREC_COUNT; p++)
		for (i = 0; i < n; i++) {
			const tradeoff_row *r = &rows[i];
			if (r->prec != p)
				continue;
			fprintf(f->f, "%s,%s", r->method, prec_name(r->prec));
			study_csv_num(f->f, r->batch1);
			study_csv_num(f->f, r->batchn);
			fprintf(f->f, ",%d", r->threads);
			study_csv_num(f->f, r->call_ns);
			study_csv_num(f->f, r->rmse_uniform);
			study_csv_num(f->f, r->max_south);
			study_csv_num(f->f, r->max_threshold);
			study_csv_num(f->f, r->has_accuracy ? r->max_worst : NAN);
			fprintf(f->f, ",%ld,%s", r->nonfinite, r->has_speed && r->has_accuracy ? (r->pareto ? "1" : "0") : "na");
			study_csv_num(f->f, r->max_uniform);
			study_csv_num(f->f, r->max_floor_uniform);
			study_csv_num(f->f, r->x_floor);
			study_csv_num(f->f, r->rms_ratio_uniform);
			study_csv_num(f->f, r->max_ratio_uniform);
			fputc('\n', f->f);
		}
	return study_out_commit(f);
}

static void table_print_half(const tradeoff_row *rows, int n);

/* The table on stdout: a float and a double block per method; then the
   binary16 rows, if any. */
static void table_print(const table_opts *o, const tradeoff_row *rows, int n)
{
	int i, j, p;
	printf("# speed from %s, accuracy from %s; * = Pareto front of its precision (speeds within %g%% equal)\n",
	       o->bench, o->summary, 100.0 * o->tol);
	printf("# xfloor = max defect on uniform / the floor's (the method's exact formula rounded once to the format)\n");
	for (i = 0; i < n && rows[i].prec == PREC_HALF; i++)
		;
	if (i == n) { /* binary16 alone */
		table_print_half(rows, n);
		return;
	}
	printf("%-24s |%51s |%51s\n", "", "float", "double");
	printf("%-24s |", "method");
	for (p = 0; p < 2; p++)
		printf(" %7s %7s %5s %8s %8s %8s %6s%s", "M/s 1t", "M/s all", "ns", "rmse uni", "max sth", "max thr", "xfloor",
		       p ? "\n" : " |");
	for (i = 0; i < n; i++) {
		if (rows[i].prec == PREC_HALF || (rows[i].prec != 0 && find_row(rows, n, rows[i].method, 0) >= 0))
			continue; /* printed with its float row; binary16 below */
		printf("%-24s |", rows[i].method);
		for (p = 0; p < 2; p++) {
			j = find_row(rows, n, rows[i].method, p);
			if (j < 0) {
				printf(" %50s%s", "-", p ? "\n" : " |");
				continue;
			}
			print_cell(rows[j].batch1, " %*.0f", 7);
			print_cell(rows[j].batchn, " %*.0f", 7);
			print_cell(rows[j].call_ns, " %*.2f", 5);
			print_cell(rows[j].rmse_uniform, " %*.1e", 8);
			print_cell(rows[j].max_south, " %*.1e", 8);
			print_cell(rows[j].max_threshold, " %*.1e", 8);
			print_cell(rows[j].x_floor, " %*.2f", 6);
			printf("%s%s", rows[j].pareto ? "*" : " ", p ? "\n" : "|");
		}
	}
	table_print_half(rows, n);
}

/* The binary16 rows: accuracy from sweep --precision half, speeds (where
   the bench.csv has half rows) from bench --precision half, whose
   arithmetic is emulated in float. */
static void table_print_half(const tradeoff_row *rows, int n)
{
	int i, any = 0, speeds = 0;
	for (i = 0; i < n; i++)
		speeds |= rows[i].prec == PREC_HALF && rows[i].has_speed;
	for (i = 0; i < n; i++) {
		if (rows[i].prec != PREC_HALF)
			continue;
		if (!any++)
			printf("\n# binary16 (sweep --precision half), u = 2^-11; %s\n"
			       "%-24s | %7s %7s %6s %8s %8s %8s %6s %8s\n",
			       speeds ? "speeds from bench --precision half: EMULATED in float (libonb's half kernels), "
			                "not hardware half speed; * = Pareto front of the half rows" :
			                "no speeds: the bench.csv has no half rows (bench --precision half)",
			       "method", "M/s 1t", "M/s all", "ns", "rmse uni", "max sth", "max thr", "xfloor", "max uni/u");
		printf("%-24s |", rows[i].method);
		print_cell(rows[i].batch1, " %*.1f", 7);
		print_cell(rows[i].batchn, " %*.1f", 7);
		print_cell(rows[i].call_ns, " %*.1f", 6);
		print_cell(rows[i].rmse_uniform, " %*.1e", 8);
		print_cell(rows[i].max_south, " %*.1e", 8);
		print_cell(rows[i].max_threshold, " %*.1e", 8);
		print_cell(rows[i].x_floor, " %*.2f", 6);
		print_cell(rows[i].max_uniform * 2048.0, " %*.3g", 8);
		printf("%s\n", rows[i].pareto ? "*" : "");
	}
}

/* Warnings about the bench.csv being joined: a --quick run (a check, not
   a measurement), or rows that bench flagged (under load, wide spread).
   Returns the number of warnings. */
static int bench_caveats(const char *path)
{
	char line[4096];
	int quick = 0, flagged = 0, cflag = -1, cmode = -1, header = 0, nw = 0;
	FILE *fp = fopen(path, "r");
	if (!fp)
		return 0;
	while (fgets(line, sizeof line, fp)) {
		char *fld[64];
		int nf;
		line[strcspn(line, "\r\n")] = '\0';
		if (line[0] == '#') {
			quick |= strstr(line, "--quick") != NULL;
			continue;
		}
		if (!line[0])
			continue;
		nf = csv_split(line, fld, 64, 1);
		if (!header) {
			header = 1;
			cflag = csv_col(fld, nf, "flag");
			cmode = csv_col(fld, nf, "mode");
		} else if (cflag >= 0 && cmode >= 0 && nf > cflag && nf > cmode && strcmp(fld[cflag], "ok") != 0 &&
		           (!strcmp(fld[cmode], "batch") || !strcmp(fld[cmode], "call_throughput")))
			flagged++;
	}
	fclose(fp);
	fflush(stdout);
	if (quick) {
		fprintf(stderr, "onbstudy: table: warning: %s comes from 'bench --quick', a check, not a measurement: "
		        "its speeds (and so the Pareto front) are rough\n", path);
		nw++;
	}
	if (flagged) {
		fprintf(stderr, "onbstudy: table: warning: %d of the rows joined from %s are flagged (under load or wide "
		        "spread; see its 'flag' column): treat those speeds with care\n", flagged, path);
		nw++;
	}
	return nw;
}

int cmd_table(int argc, char **argv)
{
	char bbuf[4096], sbuf[4096], obuf[4096];
	tradeoff_row *rows;
	int n, rc;
	study_out f;
	table_opts o;
	if ((rc = table_parse(argc, argv, &o)) != 0)
		return rc == 1 ? 0 : rc;
	if (table_paths(&o, bbuf, sbuf, obuf, sizeof bbuf) != 0)
		return ONB_EXIT_USAGE;
	n = tradeoff_load(o.bench, o.summary, o.tol, &rows);
	if (n < 0)
		return ONB_EXIT_USAGE;
	bench_caveats(o.bench);
	if (o.prec_given) { /* the precisions asked for alone (the front is per precision: unchanged) */
		int i, m = 0;
		for (i = 0; i < n; i++)
			if (o.prec_on[rows[i].prec])
				rows[m++] = rows[i];
		if (m == 0 && n > 0) {
			study_error("table: --precision: '%s' and '%s' have no rows of that precision (bench --precision half "
			            "and sweep --precision half make the half ones)", o.bench, o.summary);
			free(rows);
			return ONB_EXIT_USAGE;
		}
		n = m;
	}
	if (n == 0) {
		study_error("table: '%s' has no batch or call_throughput rows", o.bench);
		free(rows);
		return ONB_EXIT_USAGE;
	}
	if (table_write(&o, rows, n, &f) != 0) {
		free(rows);
		return 1;
	}
	if (o.csv) {
		FILE *in = fopen(f.path, "r");
		char line[4096];
		if (in) {
			while (fgets(line, sizeof line, in))
				if (line[0] != '#')
					fputs(line, stdout);
			fclose(in);
		}
	} else {
		table_print(&o, rows, n);
	}
	fprintf(stderr, "onbstudy: wrote %s\n", f.path);
	free(rows);
	return 0;
}
