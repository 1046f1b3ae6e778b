/*
 * test_table.c - `onbstudy table` on a small hand-made bench.csv and
 * summary.csv: the join picks the right rows and columns, '#' lines and
 * extra columns are skipped, the Pareto front is the one worked out by
 * hand below, and tradeoff.csv is written.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "common/options.h"
#include "bench/table.h"
#include "bench/table.h"

#include "check.h"

static char dir[] = "/tmp/onb_test_table_XXXXXX";

static void write_file(const char *name, const char *text)
{
	char path[256];
	FILE *f;
	snprintf(path, sizeof path, "%s/%s", dir, name);
	f = fopen(path, "w");
	if (!f) {
		printf("cannot write %s\n", path);
		exit(1);
	}
	fputs(text, f);
	fclose(f);
}

/* Speeds (batch, 1 thread, l2) and worst max_defect over uniform, south,
   threshold:
     float:  fast     3000  inf (a nonfinite on threshold)  -> front (nothing faster)
             acc      1000  1e-8                            -> front (most accurate)
             mid      2000  1e-7                            -> front
             twin     2000  1e-7 (ties mid)                 -> front (ties dominate nothing)
             slow      500  1e-6                            -> dominated by mid
             nosum    2500  (no summary rows)               -> na
     double: mid       900  1e-16                           -> front
             slow      400  1e-15                           -> dominated
   Stream rows, yardstick rows and the north distribution must be ignored:
   they carry figures that would change the answer. */
static const char bench_csv[] =
	"# onbstudy bench (fixture)\n"
	"# threads: 2\n"
	"method,precision,mode,threads,size_class,size,mbases_per_s,ns_per_call,extra\n"
	"copy,float,roofline,1,l2,100,5000,0.2,x\n"
	"fast,float,batch,1,l2,100,3000,0.33,x\n"
	"fast,float,batch,2,l2,200,5900,0.17,x\n"
	"fast,float,batch,1,stream,999,1,1000,x\n"
	"fast,float,call_throughput,1,l2,100,400,2.5,x\n"
	"acc,float,batch,1,l2,100,1000,1,x\n"
	"acc,float,batch,2,l2,200,1990,0.5,x\n"
	"acc,float,call_latency,1,l2,100,50,20,x\n"
	"mid,float,batch,1,l2,100,2000,0.5,x\n"
	"mid,float,yardstick,1,l2,100,9999,0.1,x\n"
	"twin,float,batch,1,l2,100,2000,0.5,x\n"
	"slow,float,batch,1,l2,100,500,2,x\n"
	"nosum,float,batch,1,l2,100,2500,0.4,x\n"
	"mid,double,batch,1,l2,100,900,1.1,x\n"
	"slow,double,batch,1,l2,100,400,2.5,x\n"
	"slow,double,call_throughput,1,l2,100,300,3.25,x\n";

static const char summary_csv[] =
	"# onbstudy sweep (fixture)\n"
	"method,precision,distribution,samples,rmse,max_defect,max_ulp,mean_bits,wrong_handed,nonfinite\n"
	"fast,float,uniform,10,1e-9,1e-9,1,0,0,0\n"
	"fast,float,south,10,1e-9,1e-9,1,0,0,0\n"
	"fast,float,threshold,10,1e-9,1e-9,1,0,0,3\n"
	"acc,float,uniform,10,2e-9,5e-9,1,0,0,0\n"
	"acc,float,south,10,2e-9,1e-8,1,0,0,0\n"
	"acc,float,threshold,10,2e-9,7e-9,1,0,0,0\n"
	"acc,float,north,10,2e-9,1e+3,1,0,0,0\n"
	"mid,float,uniform,10,3e-8,1e-8,1,0,0,0\n"
	"mid,float,south,10,3e-8,1e-7,1,0,0,0\n"
	"mid,float,threshold,10,3e-8,2e-8,1,0,0,0\n"
	"twin,float,uniform,10,3e-8,1e-8,1,0,0,0\n"
	"twin,float,south,10,3e-8,2e-8,1,0,0,0\n"
	"twin,float,threshold,10,3e-8,1e-7,1,0,0,0\n"
	"slow,float,uniform,10,4e-8,1e-6,1,0,0,0\n"
	"slow,float,south,10,4e-8,1e-7,1,0,0,0\n"
	"slow,float,threshold,10,4e-8,1e-7,1,0,0,0\n"
	"mid,double,uniform,10,1e-17,1e-16,1,0,0,0\n"
	"mid,double,south,10,1e-17,1e-16,1,0,0,0\n"
	"mid,double,threshold,10,1e-17,1e-16,1,0,0,0\n"
	"slow,double,uniform,10,1e-17,1e-15,1,0,0,0\n"
	"slow,double,south,10,1e-17,1e-16,1,0,0,0\n"
	"slow,double,threshold,10,1e-17,1e-16,1,0,0,0\n"
	"unknown_method,double,uniform,10,1,1,1,0,0,0\n";

static const tradeoff_row *get(const tradeoff_row *r, int n, const char *m, int prec)
{
	int i;
	for (i = 0; i < n; i++)
		if (r[i].prec == prec && strcmp(r[i].method, m) == 0)
			return &r[i];
	return NULL;
}

/* the join: rows, speed and accuracy columns, the front */
static void test_load(const char *b, const char *s)
{
	tradeoff_row *rows;
	const tradeoff_row *r;
	int n;

	n = tradeoff_load(b, s, 0.05, &rows);
	CHECK(n == 8, "rows: %d, want 8 (6 float, 2 double; copy's roofline row is not a method row)", n);
	if (n > 0) {
		r = get(rows, n, "fast", 0);
		CHECK(r && r->batch1 == 3000 && r->batchn == 5900 && r->threads == 2 && r->call_ns == 2.5,
		      "fast speed columns (stream row ignored)");
		CHECK(r && r->nonfinite == 3 && r->pareto == 1 && isinf(r->max_worst) == 0 && r->max_worst == 1e-9,
		      "fast: nonfinite 3, still on the front (nothing is faster)");
		r = get(rows, n, "acc", 0);
		CHECK(r && r->rmse_uniform == 2e-9 && r->max_south == 1e-8 && r->max_threshold == 7e-9 && r->max_worst == 1e-8,
		      "acc accuracy columns (north ignored)");
		CHECK(r && isnan(r->call_ns), "acc: call_latency is not call_throughput");
		CHECK(r && r->pareto == 1, "acc on the front");
		r = get(rows, n, "mid", 0);
		CHECK(r && r->batch1 == 2000 && r->max_worst == 1e-7 && r->pareto == 1, "mid on the front (yardstick ignored)");
		r = get(rows, n, "twin", 0);
		CHECK(r && r->pareto == 1, "twin ties mid: both on the front");
		r = get(rows, n, "slow", 0);
		CHECK(r && r->has_accuracy && r->pareto == 0, "slow float dominated");
		r = get(rows, n, "nosum", 0);
		CHECK(r && r->has_speed && !r->has_accuracy && r->pareto == 0, "nosum has no accuracy");
		r = get(rows, n, "mid", 1);
		CHECK(r && r->batch1 == 900 && r->pareto == 1, "mid double on the front");
		r = get(rows, n, "slow", 1);
		CHECK(r && r->pareto == 0 && r->call_ns == 3.25 && r->max_worst == 1e-15, "slow double dominated");
		CHECK(get(rows, n, "unknown_method", 1) == NULL, "summary-only methods are not rows");
	}
	free(rows);
}

/* the accuracy floor: optional columns, found by name;
   x_floor = max_defect on uniform / max_floor there */
static void test_floor(const char *b)
{
	char s[256];
	tradeoff_row *rows;
	const tradeoff_row *r;
	int n;

	write_file("summary2.csv",
	           "method,precision,distribution,samples,rmse,max_defect,max_ulp,mean_bits,wrong_handed,nonfinite,"
	           "max_floor,rms_floor,max_floor_dir,max_floor_ratio,rms_floor_ratio,at_floor\n"
	           "fast,float,uniform,10,1e-9,1.6e-7,1,0,0,0,8e-8,2e-8,1e-7,30,2,0.5\n"
	           "fast,float,south,10,1e-9,1e-9,1,0,0,0,1e-9,1e-9,1e-9,1,1,1\n");
	snprintf(s, sizeof s, "%s/summary2.csv", dir);
	n = tradeoff_load(b, s, 0.05, &rows);
	r = n > 0 ? get(rows, n, "fast", 0) : NULL;
	CHECK(r && r->max_floor_uniform == 8e-8 && r->x_floor == 1.6e-7 / 8e-8 && r->rms_ratio_uniform == 2 &&
	      r->max_ratio_uniform == 30, "floor columns: x_floor %g, want 2", r ? r->x_floor : NAN);
	r = n > 0 ? get(rows, n, "acc", 0) : NULL;
	CHECK(r && isnan(r->x_floor), "no floor row: x_floor is nan");
	if (n > 0)
		free(rows);
}

/* front by hand: a faster method with a NaN error counts as infinite */
static void test_front_nan(void)
{
	tradeoff_row x[2];
	memset(x, 0, sizeof x);
	strcpy(x[0].method, "a");
	strcpy(x[1].method, "b");
	x[0].has_speed = x[0].has_accuracy = x[1].has_speed = x[1].has_accuracy = 1;
	x[0].batch1 = 10; x[0].max_worst = NAN;
	x[1].batch1 = 5; x[1].max_worst = 1.0;
	tradeoff_pareto(x, 2, 0.05);
	CHECK(x[0].pareto == 1 && x[1].pareto == 1, "NaN error: both on the front");
	x[1].batch1 = 10;
	tradeoff_pareto(x, 2, 0.05);
	CHECK(x[0].pareto == 0 && x[1].pareto == 1, "as fast and finite beats NaN");
}

/* the speed tolerance: speeds within 5% are equal, beyond it faster */
static void test_tolerance(void)
{
	tradeoff_row x[3];
	int i;
	memset(x, 0, sizeof x);
	for (i = 0; i < 3; i++) {
		snprintf(x[i].method, sizeof x[i].method, "m%d", i);
		x[i].has_speed = x[i].has_accuracy = 1;
	}
	x[0].batch1 = 2000; x[0].max_worst = 1e-6;
	x[1].batch1 = 1950; x[1].max_worst = 1e-7;
	x[2].batch1 = 100;  x[2].max_worst = 1e-6;
	tradeoff_pareto(x, 3, 0.05);
	CHECK(x[0].pareto == 0 && x[1].pareto == 1 && x[2].pareto == 0, "2.5%% slower but more accurate wins at tol 5%%");
	tradeoff_pareto(x, 3, 0.0);
	CHECK(x[0].pareto == 1 && x[1].pareto == 1 && x[2].pareto == 0, "tol 0: the faster one stays on the front");
	x[1].max_worst = 1e-6;
	x[2].batch1 = 2040;
	tradeoff_pareto(x, 3, 0.05);
	CHECK(x[0].pareto == 1 && x[1].pareto == 1 && x[2].pareto == 1, "equal errors, speeds within 5%%: all ties");
	x[2].batch1 = 2101;
	tradeoff_pareto(x, 3, 0.05);
	CHECK(x[0].pareto == 0 && x[1].pareto == 0 && x[2].pareto == 1, "equal errors, more than 5%% faster wins");
}

/* the command: tradeoff.csv written, one line per row, the pareto column */
static void test_command(char *b, char *s, const char *t)
{
	char line[1024];
	char *argv[] = { "--bench", b, "--summary", s, "--out", dir, "--format", "csv", NULL };
	FILE *f;
	int rows_seen = 0, front = 0, na = 0, hdr = 0, rc;
	rc = cmd_table(8, argv); /* prints the CSV too */
	CHECK(rc == 0, "cmd_table returned %d", rc);
	f = fopen(t, "r");
	CHECK(f != NULL, "tradeoff.csv written");
	if (f) {
		while (fgets(line, sizeof line, f)) {
			size_t l = strlen(line);
			if (line[0] == '#')
				continue;
			if (!hdr) {
				hdr = strncmp(line, "method,precision,", 17) == 0;
				continue;
			}
			rows_seen++;
			{ /* pareto is the 12th column (the floor's columns follow it) */
				const char *q = line;
				int k;
				for (k = 1; k < 12 && q; k++) {
					q = strchr(q, ',');
					if (q)
						q++;
				}
				front += q && strncmp(q, "1,", 2) == 0;
				na += q && strncmp(q, "na,", 3) == 0;
			}
			(void)l;
		}
		fclose(f);
	}
	CHECK(hdr && rows_seen == 8 && front == 5 && na == 1, "tradeoff.csv: header %d, %d rows, %d on the front, %d na",
	      hdr, rows_seen, front, na);
}

/* bad input: missing file, bad option, a bench.csv without the columns */
static void test_bad_input(char *s)
{
	char missing[300];
	char *a1[] = { "--bench", missing, "--summary", s, NULL };
	char *a2[] = { "--frobnicate", NULL };
	char *a3[] = { "--bench", s, "--summary", s, "--out", dir, NULL };
	snprintf(missing, sizeof missing, "%s/nope.csv", dir);
	CHECK(cmd_table(4, a1) == ONB_EXIT_USAGE, "missing bench.csv: exit 2");
	CHECK(cmd_table(1, a2) == ONB_EXIT_USAGE, "unknown option: exit 2");
	CHECK(cmd_table(6, a3) == ONB_EXIT_USAGE, "summary passed as bench: exit 2");
}

int main(void)
{
	char b[256], s[256], t[256];
	if (!mkdtemp(dir)) {
		printf("mkdtemp failed\n");
		return 1;
	}
	write_file("bench.csv", bench_csv);
	write_file("summary.csv", summary_csv);
	snprintf(b, sizeof b, "%s/bench.csv", dir);
	snprintf(s, sizeof s, "%s/summary.csv", dir);
	snprintf(t, sizeof t, "%s/tradeoff.csv", dir);

	test_load(b, s);
	test_floor(b);
	test_front_nan();
	test_tolerance();
	test_command(b, s, t);
	test_bad_input(s);
	unlink(b);
	unlink(s);
	unlink(t);
	snprintf(s, sizeof s, "%s/summary2.csv", dir);
	unlink(s);
	rmdir(dir);
	return check_finish(NULL);
}
