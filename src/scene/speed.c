/*
 * speed.c - the speed source of `onbstudy scene` (see speed.h).
 */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "common/csv.h"
#include "common/options.h"
#include "common/output.h"
#include "bench/bench_core.h"
#include "scene/speed.h"
#include "common/prec.h"

#define SPEED_N 14336 /* bases per pass: bench's L2-resident size */

void speed_free(speed_table *t)
{
	free(t->rows);
	t->rows = NULL;
	t->n = 0;
}

const speed_row *speed_find(const speed_table *t, const char *name)
{
	size_t i;
	for (i = 0; i < t->n; i++)
		if (!strcmp(t->rows[i].method, name))
			return &t->rows[i];
	return NULL;
}

int speed_ci_rank(int n)
{
	/* largest k with P(Binomial(n, 1/2) <= k - 1) <= 0.025: then
	   [x_(k), x_(n+1-k)] covers the median with probability >= 95% */
	double p = pow(0.5, n), c = 1.0, cum = 0.0;
	int k;
	for (k = 0; k < n; k++) {
		cum += c * p;             /* P(B <= k) */
		if (cum > 0.025)
			break;
		c = c * (double)(n - k) / (double)(k + 1);
	}
	return k < 1 ? 1 : k;
}

static uint64_t fnv1a(uint64_t h, const char *s)
{
	for (; *s; s++) {
		h ^= (unsigned char)*s;
		h *= 1099511628211ULL;
	}
	return h;
}

int speed_cache_path(int prec, char *buf, size_t n)
{
	const char *x = getenv("XDG_CACHE_HOME"), *home = getenv("HOME");
	uint64_t h = 14695981039346656037ULL;
	int w;
	h = fnv1a(h, study_cpu_model());
	h = fnv1a(h, "|" ONB_GIT_REV "|" ONB_CFLAGS "|");
	h = fnv1a(h, onb_batch_isa());
	h = fnv1a(h, prec == PREC_DOUBLE ? "|double" : prec == PREC_HALF ? "|half" : "|float");
	if (x && x[0] == '/')
		w = snprintf(buf, n, "%s/onbstudy/speed-%016llx.csv", x, (unsigned long long)h);
	else if (home && home[0])
		w = snprintf(buf, n, "%s/.cache/onbstudy/speed-%016llx.csv", home, (unsigned long long)h);
	else
		return -1;
	return w < 0 || (size_t)w >= n ? -1 : 0;
}

static int add_row(speed_table *t, const char *m, double med, double lo, double hi)
{
	speed_row *r;
	if (speed_find(t, m))
		return 0; /* the first row of a method counts */
	r = realloc(t->rows, (t->n + 1) * sizeof *r);
	if (!r)
		return -1;
	t->rows = r;
	r = &t->rows[t->n++];
	memset(r, 0, sizeof *r);
	snprintf(r->method, sizeof r->method, "%s", m);
	r->med = med;
	r->lo = lo;
	r->hi = hi;
	return 0;
}

/* A bench.csv (kind SPEED_FILE or SPEED_REFERENCE) or a cache file. */
static int read_csv(const char *path, int prec, speed_table *t)
{
	FILE *f = fopen(path, "r");
	char line[4096], *fl[64], desc[3][256] = { "", "", "" };
	int n, hdr = 0, c[10], bad = 0, k0;
	for (k0 = 0; k0 < 10; k0++)
		c[k0] = -1;
	if (!f)
		return -1;
	while (fgets(line, sizeof line, f)) {
		if (line[0] == '#') {
			char *v = line + 1;
			int k = !strncmp(v, " revision:", 10) ? 0 : !strncmp(v, " cpu:", 5) ? 1 : !strncmp(v, " date:", 6) ? 2 : -1;
			if (k >= 0) {
				v[strcspn(v, "\r\n")] = '\0';
				snprintf(desc[k], sizeof desc[k], "%.160s", v + 1);
			}
			continue;
		}
		n = csv_split(line, fl, 64, 0);   /* no quoting in these files */
		if (!hdr) {
			const char *names[10] = { "method", "precision", "mode", "threads", "size_class",
			                          "mbases_per_s", "mbases_per_s_best", "lo", "hi", "reps" };
			int k;
			for (k = 0; k < 10; k++)
				c[k] = csv_col(fl, n, names[k]);
			hdr = 1;
			if (c[0] < 0 || c[1] < 0 || c[5] < 0 || (c[6] < 0 && (c[7] < 0 || c[8] < 0)))
				bad = 1;
			continue;
		}
		if (bad)
			break;
		{
			int k, mx = 0;
			double med, lo, hi;
			for (k = 0; k < 10; k++)
				if (c[k] > mx) mx = c[k];
			if (n <= mx || strcmp(fl[c[1]], prec_name(prec)))
				continue;
			if ((c[2] >= 0 && strcmp(fl[c[2]], "batch")) || (c[3] >= 0 && strcmp(fl[c[3]], "1"))
			    || (c[4] >= 0 && strcmp(fl[c[4]], "l2")))
				continue;
			med = strtod(fl[c[5]], NULL);
			if (c[7] >= 0 && c[8] >= 0) {
				lo = strtod(fl[c[7]], NULL);
				hi = strtod(fl[c[8]], NULL);
			} else {
				hi = strtod(fl[c[6]], NULL);
				lo = med - (hi - med);
			}
			if (!(med > 0) || !isfinite(med) || !(lo <= med) || !(hi >= med) || !isfinite(hi))
				continue;
			if (c[9] >= 0 && t->reps == 0)
				t->reps = atoi(fl[c[9]]);
			if (add_row(t, fl[c[0]], med, lo, hi) != 0)
				bad = 1;
		}
	}
	fclose(f);
	snprintf(t->path, sizeof t->path, "%s", path);
	snprintf(t->desc, sizeof t->desc, "%.160s; %.160s; %.160s", desc[0][0] ? desc[0] : "revision: ?",
	         desc[1][0] ? desc[1] : "cpu: ?", desc[2][0] ? desc[2] : "date: ?");
	if (bad || !hdr || t->n == 0) {
		speed_free(t);
		return -2;
	}
	return 0;
}

/* results/reference/bench.csv beside the executable, else in the working
   directory; in half, results/half/bench/bench.csv (the reference run has
   no half rows). */
static int reference_path(int prec, char *buf, size_t n)
{
	const char *rel = prec == PREC_HALF ? "results/half/bench/bench.csv" : "results/reference/bench.csv";
	char exe[4096];
	ssize_t l = readlink("/proc/self/exe", exe, sizeof exe - 1);
	if (l > 0) {
		char *s;
		exe[l] = '\0';
		s = strrchr(exe, '/');
		if (s) {
			*s = '\0';
			if ((size_t)snprintf(buf, n, "%s/%s", exe, rel) < n && access(buf, R_OK) == 0)
				return 0;
		}
	}
	snprintf(buf, n, "%s", rel);
	return access(buf, R_OK) == 0 ? 0 : -1;
}

static int cmp_d(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* Times every registry method's batch kernel on 1 thread, SPEED_N uniform
   directions, reps repetitions taken round-robin over the methods (so a
   change of machine load falls on all of them alike). */
static int measure(int prec, int reps, speed_table *t)
{
	size_t nm, i, j;
	const onb_method *ms = onb_methods(&nm);
	double *gx = malloc(SPEED_N * sizeof *gx), *gy = malloc(SPEED_N * sizeof *gy), *gz = malloc(SPEED_N * sizeof *gz);
	double *mb = calloc(nm * (size_t)reps, sizeof *mb);
	size_t *inner = calloc(nm, sizeof *inner);
	bench_soa s;
	int r, rc = -1, k = speed_ci_rank(reps);
	memset(&s, 0, sizeof s);
	if (!gx || !gy || !gz || !mb || !inner || bench_soa_alloc(&s, SPEED_N, prec) != 0) {
		study_error("scene: out of memory measuring speeds");
		goto out;
	}
	bench_fill_uniform(SPEED_N, 1, gx, gy, gz);
	for (i = 0; i < SPEED_N; i++) {
		if (prec == PREC_DOUBLE) {
			((double *)s.in[0])[i] = gx[i]; ((double *)s.in[1])[i] = gy[i]; ((double *)s.in[2])[i] = gz[i];
		} else if (prec == PREC_HALF) {   /* rounded once to binary16, as bench --precision half's */
			((uint16_t *)s.in[0])[i] = prec_half_bits(prec_half_round(gx[i]));
			((uint16_t *)s.in[1])[i] = prec_half_bits(prec_half_round(gy[i]));
			((uint16_t *)s.in[2])[i] = prec_half_bits(prec_half_round(gz[i]));
		} else {
			((float *)s.in[0])[i] = (float)gx[i]; ((float *)s.in[1])[i] = (float)gy[i]; ((float *)s.in[2])[i] = (float)gz[i];
		}
	}
	for (i = 0; i < nm; i++) {
		if (prec == PREC_DOUBLE ? !ms[i].batch : prec == PREC_HALF ? !ms[i].arrayh : !ms[i].batchf)
			continue; /* float-only methods in double, methods without a binary16 entry in half */
		s.batch = ms[i].batch;
		s.batchf = ms[i].batchf;
		s.arrayh = ms[i].arrayh;
		inner[i] = bench_calibrate(bench_soa_kernel, &s, SPEED_N, 1, 0.02, 100000);
	}
	for (r = 0; r < reps; r++)
		for (i = 0; i < nm; i++) {
			bench_cfg cfg;
			bench_result br;
			if (!inner[i])
				continue;
			cfg.threads = 1; cfg.warmup = 1; cfg.reps = 1; cfg.inner = inner[i];
			s.batch = ms[i].batch;
			s.batchf = ms[i].batchf;
			s.arrayh = ms[i].arrayh;
			if (bench_run(bench_soa_kernel, &s, SPEED_N, &cfg, &br) != 0 || !(br.median_s > 0)) {
				study_error("scene: timing %s failed", ms[i].name);
				goto out;
			}
			mb[i * (size_t)reps + (size_t)r] = (double)SPEED_N / br.median_s / 1e6;
		}
	for (i = 0; i < nm; i++) {
		double *v = mb + i * (size_t)reps;
		if (!inner[i])
			continue;
		qsort(v, (size_t)reps, sizeof *v, cmp_d);
		j = (size_t)reps / 2;
		if (add_row(t, ms[i].name, reps % 2 ? v[j] : 0.5 * (v[j - 1] + v[j]), v[k - 1], v[reps - k]) != 0) {
			study_error("scene: out of memory");
			goto out;
		}
	}
	rc = 0;
out:
	free(gx); free(gy); free(gz); free(mb); free(inner);
	bench_soa_free(&s);
	return rc;
}

static int write_cache(const char *path, int prec, int reps, const speed_table *t)
{
	char dir[4096], *s;
	study_out o;
	size_t i;
	snprintf(dir, sizeof dir, "%s", path);
	s = strrchr(dir, '/');
	if (!s)
		return -1;
	*s = '\0';
	if (study_mkdir_p(dir) != 0 || study_out_open(&o, dir, s + 1) != 0)
		return -1;
	study_provenance(o.f, "scene --refresh-speed", 1, 1);
	fprintf(o.f, "# what: batch kernel throughput, %s, 1 thread, %d uniform directions (L2-resident), M bases/s\n",
	        prec_name(prec), SPEED_N);
	fprintf(o.f, "# repetitions: %d (round-robin over the methods, each >= 20 ms after a warm-up pass)\n", reps);
	fprintf(o.f, "# interval: lo, hi = order statistics %d and %d of %d: a distribution-free confidence interval of the median (>= 95%% for 6 or more repetitions)\n",
	        speed_ci_rank(reps), reps + 1 - speed_ci_rank(reps), reps);
	fprintf(o.f, "method,precision,mode,threads,size_class,reps,mbases_per_s,lo,hi\n");
	for (i = 0; i < t->n; i++)
		fprintf(o.f, "%s,%s,batch,1,l2,%d,%.6g,%.6g,%.6g\n", t->rows[i].method, prec_name(prec),
		        reps, t->rows[i].med, t->rows[i].lo, t->rows[i].hi);
	return study_out_commit(&o);
}

int speed_load(int prec, const char *file, int refresh, int reps, speed_table *t)
{
	char cache[4096], ref[4096];
	int rc;
	memset(t, 0, sizeof *t);
	if (file) {
		rc = read_csv(file, prec, t);
		if (rc != 0) {
			study_error("scene: --speed %s: %s", file, rc == -1 ? strerror(errno)
			            : "no batch, 1-thread, l2 rows for this precision (expected a bench.csv of 'onbstudy bench')");
			return -1;
		}
		t->kind = SPEED_FILE;
		return 0;
	}
	if (speed_cache_path(prec, cache, sizeof cache) != 0) {
		cache[0] = '\0';
		if (refresh) {
			study_error("scene: --refresh-speed: no cache directory (set XDG_CACHE_HOME or HOME)");
			return -1;
		}
	}
	if (refresh) {
		if (measure(prec, reps, t) != 0)
			return -1;
		if (write_cache(cache, prec, reps, t) != 0) {
			speed_free(t);
			return -1;
		}
		speed_free(t);
		memset(t, 0, sizeof *t);
	}
	if (cache[0] && read_csv(cache, prec, t) == 0) {
		t->kind = SPEED_CACHE;
		return 0;
	}
	if (reference_path(prec, ref, sizeof ref) == 0 && read_csv(ref, prec, t) == 0) {
		t->kind = SPEED_REFERENCE;
		return 0;
	}
	study_error("scene: no speed figures: no cache (%s) and no readable %s; "
	            "run 'onbstudy scene --refresh-speed FILE' or give --speed BENCH_CSV", cache[0] ? cache : "no cache directory",
	            prec == PREC_HALF ? "results/half/bench/bench.csv" : "results/reference/bench.csv");
	return -1;
}
