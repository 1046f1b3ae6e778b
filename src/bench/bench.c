/*
 * bench.c - `onbstudy bench`: batch throughput, per-call throughput and
 * latency of every registry method, beside a copy roofline and a
 * hand-written -march=native yardstick.  Writes bench.csv.
 *
 * Every measurement: the same pre-generated uniform inputs for every
 * method, a calibration pass, a warm-up repetition, then `reps` timed
 * repetitions of `inner` passes each (each repetition lasts at least
 * `target` seconds), timed between OpenMP barriers; median and minimum
 * over repetitions.  Results stay live through checksums of the outputs,
 * written to the CSV.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <omp.h>
#include "bench/bench.h"
#include "common/options.h"
#include "common/output.h"
#include "bench/bench_core.h"
#include "bench/bench_calls.h"
#include "bench/yardstick.h"
#include "bench/bench_ref.h"
#include "common/prec.h"

typedef struct {
	const char *method;   /* registry name, or "copy" for the roofline */
	int prec;
	const char *mode;     /* batch, yardstick, roofline, call_throughput, call_latency */
	const char *size_class; /* l2 or stream */
	size_t bytes;
	bench_result r;
	double chain_ns, frac_roof, vs_yard, checksum;
	char isa[32];
	const char *vec;
} bench_row;

typedef struct {
	bench_row *v;
	size_t n, cap;
} bench_rows;

static volatile double bench_sink;

static bench_row *rows_add(bench_rows *rs)
{
	if (rs->n == rs->cap) {
		size_t cap = rs->cap ? 2 * rs->cap : 256;
		bench_row *t = realloc(rs->v, cap * sizeof *t);
		if (!t)
			return NULL;
		rs->v = t;
		rs->cap = cap;
	}
	memset(&rs->v[rs->n], 0, sizeof rs->v[rs->n]);
	rs->v[rs->n].chain_ns = NAN;
	rs->v[rs->n].frac_roof = NAN;
	rs->v[rs->n].vs_yard = NAN;
	rs->v[rs->n].checksum = NAN;
	return &rs->v[rs->n++];
}

/* Room for every registry method: bench_main refuses a registry larger
   than this (it once held 64, and methods past the 64th were silently
   not measured). */
#define BENCH_MAX_METHODS 256

typedef struct {
	int quick, threads, csv, nmeth, prec_on[PREC_COUNT];
	int reference;                              /* --reference: that mode only */
	const onb_method *meth[BENCH_MAX_METHODS];
	const char *out;
	double stream_mib;
	unsigned long long seed;
	int reps, warmup;
	double target;
} bench_opts;

static const char usage_text[] =
	"usage: onbstudy bench [options]   (options take '--opt value' or '--opt=value')\n"
	"  --methods a,b,...      registry methods to measure (default: all; see onbstudy list)\n"
	"  --precision P          float, double, both, half or all (default both).  half: libonb's\n"
	"                         binary16 kernels (onb_NAME_arrayh over SoA bit patterns, onb_NAMEh\n"
	"                         per call), their arithmetic emulated in float with each result\n"
	"                         rounded to binary16: 'emulated' in the isa column, never a\n"
	"                         hardware half speed; no yardstick\n"
	"  --threads N            threads of the all-threads runs (default 0: OpenMP's maximum)\n"
	"  --out DIR              output directory (default: the current run, results/latest)\n"
	"  --quick                a check, not a measurement: 3 short repetitions and a 16 MiB\n"
	"                         'stream' set (under 15 s); the default run takes about a minute\n"
	"  --stream-mib M         smallest float working set of the stream size (default 64)\n"
	"  --seed S               input seed (default 1)\n"
	"  --format table|csv     what to print on stdout (bench.csv is written either way)\n"
	"  --reference            the reference mode only: referenced evaluations per second per\n"
	"                         core, fast reference and MPFR alone, on the default sweep's\n"
	"                         inputs (bench-reference.csv; about a minute, --quick seconds)\n";

/* A name of the list v that is not a registry method, in the words of the
   other commands' --methods (methods/kernels.c): 0, or -1 after the message. */
static int bench_unknown(const char *v, const char *const *names, size_t nm)
{
	char buf[2048], all[2048], *tok, *save = NULL;
	size_t i, len = 0;
	if (strlen(v) >= sizeof buf || v[0] == ',' || (v[0] && v[strlen(v) - 1] == ',') || strstr(v, ",,"))
		return 0;   /* cli_name_order says "list too long" or "empty name" */
	strcpy(buf, v);
	for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
		if (onb_find(tok))
			continue;
		all[0] = '\0';
		for (i = 0; i < nm && len + 64 < sizeof all; i++)
			len += (size_t)snprintf(all + len, sizeof all - len, "%s%s", i ? ", " : "", names[i]);
		study_error("unknown method '%s' (valid: %s)", tok, all);
		return -1;
	}
	return 0;
}

/* --methods a,b,...: registry methods, each once, in the order given. */
static int bench_methods(const char *v, bench_opts *o)
{
	size_t nm, i;
	int idx[BENCH_MAX_METHODS], k, n;
	const onb_method *all = onb_methods(&nm);
	const char *names[BENCH_MAX_METHODS];
	if (nm > BENCH_MAX_METHODS) {
		study_error("bench: the registry has %zu methods, more than the %d it has room for", nm, BENCH_MAX_METHODS);
		return -1;
	}
	for (i = 0; i < nm; i++)
		names[i] = all[i].name;
	if (bench_unknown(v, names, nm) != 0 || (n = cli_name_order("--methods", v, idx, names, (int)nm)) < 0)
		return -1;
	o->nmeth = n;
	for (k = 0; k < n; k++)
		o->meth[k] = &all[idx[k]];
	return 0;
}

static int bench_option(int v, const char *a, bench_opts *o)
{
	long t;
	switch (v) {
	case 'q': o->quick = 1; return 0;
	case 'R': o->reference = 1; return 0;
	case 'm': return bench_methods(a, o);
	case 'p': return cli_precision_half("--precision", a, o->prec_on);
	case 't': /* 0: OpenMP's maximum, as the default */
		if (parse_int("--threads", a, 0, 1024, &t) != 0) return -1;
		o->threads = t ? (int)t : omp_get_max_threads();
		return 0;
	case 'o':
		if (!*a) {
			study_error("--out: empty directory name");
			return -1;
		}
		o->out = a;
		return 0;
	case 'f': return (o->csv = cli_format("--format", a, 0)) < 0 ? -1 : 0;
	case 'S':
		if (parse_double("--stream-mib", a, &o->stream_mib) != 0)
			return -1;
		if (!(o->stream_mib >= 1.0 && o->stream_mib <= 65536.0)) {
			study_error("--stream-mib: %s is out of range [1, 65536]", a);
			return -1;
		}
		return 0;
	case 's': return parse_u64("--seed", a, 0, ~0ULL, &o->seed) != 0 ? -1 : 0;
	}
	return -1;
}

static int parse_opts(int argc, char **argv, bench_opts *o)
{
	static const struct option lo[] = {
		{ "quick", no_argument, NULL, 'q' }, { "methods", required_argument, NULL, 'm' },
		{ "precision", required_argument, NULL, 'p' }, { "threads", required_argument, NULL, 't' },
		{ "out", required_argument, NULL, 'o' }, { "format", required_argument, NULL, 'f' },
		{ "stream-mib", required_argument, NULL, 'S' }, { "seed", required_argument, NULL, 's' },
		{ "reference", no_argument, NULL, 'R' },
		CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
	};
	size_t nm, i;
	const onb_method *all = onb_methods(&nm);
	cli_args c;
	int v, rc = 0;
	memset(o, 0, sizeof *o);
	o->prec_on[PREC_FLOAT] = o->prec_on[PREC_DOUBLE] = 1;
	o->threads = omp_get_max_threads();
	o->stream_mib = -1.0;
	o->seed = 1;
	if (cli_begin(&c, "bench", argc, argv))
		return -1;
	while (rc == 0 && (v = cli_next(&c, lo)) != -1) {
		if (v == CLI_HELP) { fputs(usage_text, stdout); rc = 1; }
		else if (v == CLI_ERROR || bench_option(v, c.arg, o) != 0) rc = -1;
	}
	if (rc == 0 && cli_no_rest(&c) != 0)
		rc = -1;
	cli_end(&c);
	if (rc)
		return rc;
	if (o->nmeth == 0 && nm > BENCH_MAX_METHODS) {
		study_error("bench: the registry has %zu methods, more than the %d it has room for", nm, BENCH_MAX_METHODS);
		return -1;
	}
	if (o->nmeth == 0)
		for (i = 0; i < nm; i++)
			o->meth[o->nmeth++] = &all[i];
	if (o->stream_mib < 0.0)
		o->stream_mib = o->quick ? 16.0 : 64.0;
	o->reps = o->quick ? 3 : 11;
	o->warmup = 1;
	o->target = o->quick ? 0.5e-3 : 10e-3;
	return 0;
}

/* ---- kernels for the runner -------------------------------------------- */

typedef struct {
	const bench_call *c;
	int prec;
	const void *in;
	void *out;
	double sum;
} call_ctx;

/* Bytes of one component in precision prec. */
static size_t elem_size(int prec)
{
	return prec == PREC_DOUBLE ? sizeof(double) : prec == PREC_HALF ? sizeof(uint16_t) : sizeof(float);
}

/* The isa column of a half row: the arithmetic is always emulated in float
   (libonb's half kernels use no native half instruction), the conversions
   are onb_half_isa()'s. */
static const char *half_conv(void)
{
#if ONB_HAVE_HALF
	return onb_half_isa();
#else
	return "none";
#endif
}
static const char *half_isa(void)
{
	static char buf[32];
	snprintf(buf, sizeof buf, "emulated-%s", half_conv());
	return buf;
}

static void call_tp_kernel(void *ctx, size_t lo, size_t hi)
{
	call_ctx *c = ctx;
	if (c->prec == PREC_HALF)
		c->c->tph(hi - lo, (const char *)c->in + lo * 3 * sizeof(uint16_t),
		          (char *)c->out + lo * 6 * sizeof(uint16_t));
	else if (c->prec == PREC_DOUBLE)
		c->c->tp(hi - lo, (const onb_vec3 *)c->in + lo, (bench_pair *)c->out + lo);
	else
		c->c->tpf(hi - lo, (const onb_vec3f *)c->in + lo, (bench_pairf *)c->out + lo);
}

static void call_lat_kernel(void *ctx, size_t lo, size_t hi)
{
	call_ctx *c = ctx;
	if (c->prec == PREC_HALF)
		c->sum += c->c->lath(hi - lo, (const char *)c->in + lo * 3 * sizeof(uint16_t));
	else if (c->prec == PREC_DOUBLE)
		c->sum += c->c->lat(hi - lo, (const onb_vec3 *)c->in + lo);
	else
		c->sum += c->c->latf(hi - lo, (const onb_vec3f *)c->in + lo);
}

static int measure(bench_kernel k, void *ctx, size_t n, int threads, const bench_opts *o, bench_result *r)
{
	bench_cfg cfg;
	cfg.threads = threads;
	cfg.warmup = o->warmup;
	cfg.reps = o->reps;
	cfg.inner = bench_calibrate(k, ctx, n, threads, o->target, 100000);
	return bench_run(k, ctx, n, &cfg, r);
}

static const char *clone_name(void)
{
	const char *isa = onb_batch_isa();
	return strcmp(isa, "sse2") == 0 ? "default" : isa;
}

/* The vector width of the batch clone that ran. */
static const char *batch_vec(const char *method, int prec)
{
	char sym[128];
	const char *w;
	if (prec == PREC_HALF) { /* the kernel the ifunc picked (half.c), else the plain name */
		snprintf(sym, sizeof sym, "onb__%sh_%s", method, half_conv());
		w = bench_vector_width(sym);
		if (strcmp(w, "unknown") == 0) {
			snprintf(sym, sizeof sym, "onb_%sh", method);
			w = bench_vector_width(sym);
		}
		return w;
	}
	snprintf(sym, sizeof sym, "onb_%s_batch%s.%s", method, prec == PREC_DOUBLE ? "" : "f", clone_name());
	w = bench_vector_width(sym);
	if (strcmp(w, "unknown") == 0) { /* hand-dispatched kernels (batch.c) */
		snprintf(sym, sizeof sym, "onb__%s_batch%s_%s", method, prec == PREC_DOUBLE ? "" : "f", clone_name());
		w = bench_vector_width(sym);
	}
	if (strcmp(w, "unknown") == 0) {
		snprintf(sym, sizeof sym, "onb_%s_batch%s", method, prec == PREC_DOUBLE ? "" : "f");
		w = bench_vector_width(sym);
	}
	return w;
}

static const char *sym_vec(const char *prefix, const char *method, int prec)
{
	char sym[128];
	const char *w;
	snprintf(sym, sizeof sym, "%s%s%s", prefix, method, prec == PREC_DOUBLE ? "" : prec == PREC_HALF ? "h" : "f");
	w = bench_vector_width(sym);
	if (prec == PREC_HALF && strcmp(w, "unknown") == 0) { /* the half call loops' clones (bench_calls.c) */
		snprintf(sym, sizeof sym, "%s%sh_%s", prefix, method, strcmp(half_conv(), "f16c") == 0 ? "f16c" : "plain");
		w = bench_vector_width(sym);
	}
	return w;
}

/* The generated directions into both SoA sets and the n_l2 AoS inputs. */
static void fill_inputs(int prec, const double *gx, const double *gy, const double *gz, bench_soa soa[2], void *aos_in,
                        size_t n_l2)
{
	size_t i;
	int s;
	for (s = 0; s < 2; s++)
		for (i = 0; i < soa[s].n; i++) {
			if (prec == PREC_DOUBLE) {
				((double *)soa[s].in[0])[i] = gx[i];
				((double *)soa[s].in[1])[i] = gy[i];
				((double *)soa[s].in[2])[i] = gz[i];
			} else if (prec == PREC_HALF) { /* the same directions rounded once to binary16 */
				((uint16_t *)soa[s].in[0])[i] = prec_half_bits(prec_half_round(gx[i]));
				((uint16_t *)soa[s].in[1])[i] = prec_half_bits(prec_half_round(gy[i]));
				((uint16_t *)soa[s].in[2])[i] = prec_half_bits(prec_half_round(gz[i]));
			} else {
				((float *)soa[s].in[0])[i] = (float)gx[i];
				((float *)soa[s].in[1])[i] = (float)gy[i];
				((float *)soa[s].in[2])[i] = (float)gz[i];
			}
		}
	for (i = 0; i < n_l2; i++) {
		if (prec == PREC_HALF) {
#if ONB_HAVE_HALF
			onb_vec3h *v = (onb_vec3h *)aos_in + i;
			v->x = (onb_half)prec_half_round(gx[i]);
			v->y = (onb_half)prec_half_round(gy[i]);
			v->z = (onb_half)prec_half_round(gz[i]);
#endif
		} else if (prec == PREC_DOUBLE) {
			onb_vec3 *v = (onb_vec3 *)aos_in + i;
			v->x = gx[i]; v->y = gy[i]; v->z = gz[i];
		} else {
			onb_vec3f *v = (onb_vec3f *)aos_in + i;
			v->x = (float)gx[i]; v->y = (float)gy[i]; v->z = (float)gz[i];
		}
	}
}

/* The yardstick of method mi (the last of that name), or NULL; NULL for the roofline (mi < 0). */
static const bench_yardstick *find_yardstick(const bench_opts *o, int mi, int prec)
{
	size_t ny, i;
	const bench_yardstick *yd = bench_yardsticks(&ny), *y = NULL;
	if (mi >= 0 && prec != PREC_HALF) /* no half yardstick */
		for (i = 0; i < ny; i++)
			if (strcmp(yd[i].name, o->meth[mi]->name) == 0)
				y = &yd[i];
	return y;
}

/* Point b's kernel and r's labels at the copy roofline (mi < 0), the batch
   kernel of method mi (v == 0) or its yardstick y (v == 1). */
static void set_soa_kind(bench_row *r, bench_soa *b, const bench_opts *o, int mi, int v, const bench_yardstick *y,
                         int prec)
{
	if (mi < 0) {
		r->method = "copy";
		r->mode = "roofline";
		b->batch = bench_copy;
		b->batchf = bench_copyf;
		b->batchh = bench_copyh;
		snprintf(r->isa, sizeof r->isa, "native-%s", bench_yardstick_isa());
		r->vec = sym_vec("bench_copy", "", prec);
	} else if (v == 0) {
		r->method = o->meth[mi]->name;
		r->mode = "batch";
		b->batch = o->meth[mi]->batch;
		b->batchf = o->meth[mi]->batchf;
		b->batchh = NULL;
		b->arrayh = o->meth[mi]->arrayh;
		snprintf(r->isa, sizeof r->isa, "%s", prec == PREC_HALF ? half_isa() : onb_batch_isa());
		r->vec = batch_vec(r->method, prec);
	} else {
		r->method = y->name;
		r->mode = "yardstick";
		b->batch = y->batch;
		b->batchf = y->batchf;
		snprintf(r->isa, sizeof r->isa, "native-%s", bench_yardstick_isa());
		r->vec = sym_vec("bench_yard_", y->name, prec);
	}
}

/* One SoA row: n items of size class cls on nthreads threads.  0 or -1. */
static int soa_row(const bench_opts *o, int prec, bench_soa *b, const char *cls, size_t n, int nthreads, int mi, int v,
                   const bench_yardstick *y, bench_rows *rs)
{
	bench_row *r = rows_add(rs);
	if (!r)
		return -1;
	r->prec = prec;
	r->size_class = cls;
	r->bytes = n * 9 * elem_size(prec);
	set_soa_kind(r, b, o, mi, v, y, prec);
	if (measure(bench_soa_kernel, b, n, nthreads, o, &r->r) != 0)
		return -1;
	/* the outputs of this run, over the items it wrote */
	{
		size_t keep = b->n;
		b->n = n;
		r->checksum = bench_soa_checksum(b);
		b->n = keep;
	}
	bench_sink = r->checksum;
	return 0;
}

/* Roofline, batch and yardstick: the same SoA arrays, same sizes; a
   method's yardstick runs right after it at each size and thread
   count, so that both see the same machine load.  0 or -1. */
static int soa_rows(const bench_opts *o, int prec, bench_soa soa[2], const size_t sz[2][2], bench_rows *rs)
{
	const int nthr = o->threads > 1 ? 2 : 1;
	const int thr[2] = { 1, o->threads };
	const char *cls[2] = { "l2", "stream" };
	int mi, s, t, v;

	for (mi = -1; mi < o->nmeth; mi++) {
		const bench_yardstick *y;
		if (mi >= 0 && prec == PREC_DOUBLE && !o->meth[mi]->batch)
			continue; /* float only (ONB_FLOAT_ONLY) */
		if (mi >= 0 && prec == PREC_HALF && !o->meth[mi]->arrayh)
			continue;
		y = find_yardstick(o, mi, prec);
		for (s = 0; s < 2; s++)
			for (t = 0; t < nthr; t++)
				for (v = 0; v < (y ? 2 : 1); v++)
					if (soa_row(o, prec, &soa[s], cls[s], sz[s][t], thr[t], mi, v, y, rs) != 0)
						return -1;
	}
	return 0;
}

/* Fractions of the roofline, ratios to the yardstick, over rows roof0.. */
static void link_ratios(bench_rows *rs, size_t roof0)
{
	size_t i, j;
	for (i = roof0; i < rs->n; i++) {
		bench_row *r = &rs->v[i];
		for (j = roof0; j < rs->n; j++) {
			const bench_row *q = &rs->v[j];
			if (q->r.n != r->r.n || q->r.threads != r->r.threads || strcmp(q->size_class, r->size_class))
				continue;
			if (strcmp(q->mode, "roofline") == 0)
				r->frac_roof = q->r.min_s / r->r.min_s;
			if (strcmp(r->mode, "batch") == 0 && strcmp(q->mode, "yardstick") == 0 && strcmp(q->method, r->method) == 0)
				r->vs_yard = q->r.min_s / r->r.min_s;
		}
	}
}

/* The call_throughput (t == 0) or call_latency (t == 1) row of cc->c.  0 or -1. */
static int call_row(call_ctx *cc, int t, size_t n_l2, double chain_ns, const bench_opts *o, bench_rows *rs)
{
	const bench_call *c = cc->c;
	const int prec = cc->prec;
	bench_row *r = rows_add(rs);
	if (!r)
		return -1;
	r->method = c->name;
	r->prec = prec;
	r->mode = t ? "call_latency" : "call_throughput";
	r->size_class = "l2";
	r->bytes = n_l2 * 9 * elem_size(prec);
	snprintf(r->isa, sizeof r->isa, "%s", prec == PREC_HALF ? half_isa() : bench_calls_isa());
	cc->sum = 0.0;
	if (measure(t ? call_lat_kernel : call_tp_kernel, cc, n_l2, 1, o, &r->r) != 0)
		return -1;
	if (t) {
		/* one more pass, alone, for the checksum */
		cc->sum = 0.0;
		call_lat_kernel(cc, 0, n_l2);
		r->checksum = cc->sum;
		r->chain_ns = chain_ns;
		r->vec = sym_vec("bench_lat_", c->name, prec);
	} else {
		r->checksum = prec == PREC_DOUBLE ? bench_pair_checksum(n_l2, cc->out) :
		              prec == PREC_HALF ? bench_pair_checksumh(n_l2, cc->out) : bench_pair_checksumf(n_l2, cc->out);
		r->vec = sym_vec("bench_tp_", c->name, prec);
	}
	bench_sink = r->checksum;
	return 0;
}

/* Per call: the inline function over an array of structs, 1 thread.
   0, -1 (out of memory or bad run) or -2 (reported). */
static int call_rows(const bench_opts *o, int prec, size_t n_l2, const void *aos_in, void *aos_out, bench_rows *rs)
{
	call_ctx cc;
	bench_result cr;
	double chain_ns;
	int mi, t;

	cc.prec = prec;
	cc.in = aos_in;
	cc.out = aos_out;
	cc.c = bench_call_find("chain");
	cc.sum = 0.0;
	if (measure(call_lat_kernel, &cc, n_l2, 1, o, &cr) != 0)
		return -1;
	chain_ns = cr.median_s / (double)n_l2 * 1e9;
	bench_sink = cc.sum;
	for (mi = 0; mi < o->nmeth; mi++) {
		const bench_call *c = bench_call_find(o->meth[mi]->name);
		if (prec == PREC_DOUBLE && !o->meth[mi]->basis)
			continue; /* float only */
		if (prec == PREC_HALF && !o->meth[mi]->arrayh)
			continue;
		if (!c || (prec == PREC_HALF && !c->tph)) {
			study_error("bench: no inline call loop for '%s' (add it to ONB_METHOD_LIST)", o->meth[mi]->name);
			return -2;
		}
		cc.c = c;
		for (t = 0; t < 2; t++)
			if (call_row(&cc, t, n_l2, chain_ns, o, rs) != 0)
				return -1;
	}
	return 0;
}

/* One precision: every measurement, appended to rs.  0 or -1. */
static int bench_precision(const bench_opts *o, int prec, size_t n_l2, size_t n_stream, bench_rows *rs)
{
	const size_t n_l2_all = n_l2 * (size_t)o->threads;
	const size_t n_gen = n_stream > n_l2_all ? n_stream : n_l2_all;
	const size_t sz[2][2] = { { n_l2, n_l2_all }, { n_stream, n_stream } };
	const size_t roof0 = rs->n;
	double *gx = malloc(n_gen * sizeof *gx), *gy = malloc(n_gen * sizeof *gy), *gz = malloc(n_gen * sizeof *gz);
	bench_soa soa[2];
	void *aos_in = NULL, *aos_out = NULL;
	int rc = -1, e;

	memset(soa, 0, sizeof soa);
	if (!gx || !gy || !gz || bench_soa_alloc(&soa[0], n_l2_all, prec) || bench_soa_alloc(&soa[1], n_stream, prec))
		goto oom;
	aos_in = malloc(n_l2 * 3 * elem_size(prec));   /* onb_vec3, onb_vec3f, onb_vec3h */
	aos_out = malloc(n_l2 * 6 * elem_size(prec));  /* bench_pair, bench_pairf, bench_pairh */
	if (!aos_in || !aos_out)
		goto oom;
	bench_fill_uniform(n_gen, o->seed, gx, gy, gz);
	fill_inputs(prec, gx, gy, gz, soa, aos_in, n_l2);
	if (soa_rows(o, prec, soa, sz, rs) != 0)
		goto oom;
	link_ratios(rs, roof0);
	e = call_rows(o, prec, n_l2, aos_in, aos_out, rs);
	if (e == -1)
		goto oom;
	if (e != 0)
		goto fail;
	rc = 0;
	goto done;
oom:
	study_error("bench: out of memory or bad run configuration");
fail:
	rc = -1;
done:
	free(gx);
	free(gy);
	free(gz);
	free(aos_in);
	free(aos_out);
	bench_soa_free(&soa[0]);
	bench_soa_free(&soa[1]);
	return rc;
}

#define BENCH_COLUMNS "method,precision,mode,threads,size_class,size,bytes,reps,passes," \
	"mbases_per_s,mbases_per_s_best,ns_per_call,ns_per_call_best,cycles_per_call,cycles_per_call_best," \
	"chain_ns,frac_roofline,vs_yardstick,isa,vectorized,checksum,flag"

/* A figure not to take at face value (the "flag" column): "load" for an
   all-threads row begun at a 1-minute load average of BENCH_BUSY_LOAD or
   more (other processes took CPU time from the threads); "spread" when the
   median time exceeds the minimum by more than BENCH_WIDE_SPREAD. */
#define BENCH_BUSY_LOAD   0.5
#define BENCH_WIDE_SPREAD 1.2
static int bench_busy; /* the load average at the start was BENCH_BUSY_LOAD or more */
static const char *row_flag(const bench_row *r)
{
	const int load = bench_busy && r->r.threads > 1;
	const int spread = r->r.median_s > BENCH_WIDE_SPREAD * r->r.min_s;
	return load ? (spread ? "load+spread" : "load") : spread ? "spread" : "ok";
}

static void write_row(FILE *f, const bench_row *r, int tsc)
{
	const double n = (double)r->r.n;
	fprintf(f, "%s,%s,%s,%d,%s,%zu,%zu,%zu,%zu", r->method, prec_name(r->prec), r->mode, r->r.threads,
	        r->size_class, r->r.n, r->bytes, (size_t)r->r.reps, r->r.passes);
	study_csv_num(f, n / r->r.median_s * 1e-6);
	study_csv_num(f, n / r->r.min_s * 1e-6);
	study_csv_num(f, r->r.median_s / n * 1e9);
	study_csv_num(f, r->r.min_s / n * 1e9);
	study_csv_num(f, tsc ? r->r.median_ticks / n : NAN);
	study_csv_num(f, tsc ? r->r.min_ticks / n : NAN);
	study_csv_num(f, r->chain_ns);
	study_csv_num(f, r->frac_roof);
	study_csv_num(f, r->vs_yard);
	fprintf(f, ",%s,%s,%.17g,%s\n", r->isa, r->vec ? r->vec : "unknown", r->checksum, row_flag(r));
}

static const bench_row *find_row(const bench_rows *rs, const char *method, int prec, const char *mode,
                                 const char *cls, int many)
{
	size_t i;
	for (i = 0; i < rs->n; i++) {
		const bench_row *r = &rs->v[i];
		if (r->prec == prec && strcmp(r->method, method) == 0 && strcmp(r->mode, mode) == 0 &&
		    strcmp(r->size_class, cls) == 0 && (r->r.threads > 1) == many)
			return r;
	}
	return NULL;
}

static double mbs(const bench_row *r)
{
	return r ? (double)r->r.n / r->r.median_s * 1e-6 : NAN;
}
/* '*' after a flagged figure (see row_flag) */
static char star(const bench_row *r)
{
	return r && strcmp(row_flag(r), "ok") != 0 ? '*' : ' ';
}

/* After the table: what the '*' marks mean, and --quick's caveat. */
static void flag_notes(const bench_opts *o, const bench_rows *rs, const char *load0)
{
	size_t i, nload = 0, nspread = 0;
	for (i = 0; i < rs->n; i++) {
		const char *fl = row_flag(&rs->v[i]);
		nload += strstr(fl, "load") != NULL;
		nspread += strstr(fl, "spread") != NULL;
	}
	if (nload)
		printf("\n* %zu all-threads figures were taken under load (load average %s at the start, >= %g): "
		       "other processes shared the CPUs, so read them as lower bounds\n", nload, load0, BENCH_BUSY_LOAD);
	if (nspread)
		printf("%s* %zu figures have a wide spread (median > %g x the best of %d repetitions): noisy\n",
		       nload ? "" : "\n", nspread, BENCH_WIDE_SPREAD, o->reps);
	if (o->quick)
		printf("--quick: a check, not a measurement (%d short repetitions)\n", o->reps);
}

static void print_table(const bench_opts *o, const bench_rows *rs)
{
	int p, mi;
	for (p = 0; p < PREC_COUNT; p++) {
		if (!o->prec_on[p])
			continue;
		if (p == PREC_HALF)
			printf("\nhalf: binary16 EMULATED (%s): libonb's half kernels do each operation in float and round it to "
			       "binary16; batch = onb_NAME_arrayh per basis over SoA arrays; no yardstick; not hardware half speed\n",
			       half_isa());
		printf("\n%s: batch M bases/s (median), L2-resident and stream, 1 and %d threads; per call ns (%s, 1 thread)\n",
		       prec_name(p), o->threads, p == PREC_HALF ? "out-of-line onb_NAMEh" : "inline");
		printf("  roof%% = stream, 1 thread, vs the copy; vsYard = L2, 1 thread, vs the yardstick (both from best times);\n"
		       "  vec = widest packed register of the kernel that ran; call ns = inline, independent calls; lat ns = dependent\n"
		       "  chain; lat-ch = lat ns minus the chain alone (%.2f ns)\n",
		       find_row(rs, o->meth[0]->name, p, "call_latency", "l2", 0) ?
		       find_row(rs, o->meth[0]->name, p, "call_latency", "l2", 0)->chain_ns : NAN);
		printf("%-24s %8s %8s %8s %8s %6s %6s %6s %7s %7s %7s\n", "method", "L2 1t", "L2 all", "strm 1t", "strm all",
		       "roof%", "vsYard", "vec", "call ns", "lat ns", "lat-ch");
		for (mi = -1; mi < o->nmeth; mi++) {
			const char *name = mi < 0 ? "copy" : o->meth[mi]->name;
			if (mi >= 0 && p == PREC_DOUBLE && !o->meth[mi]->batch)
				continue; /* float only */
			if (mi >= 0 && p == PREC_HALF && !o->meth[mi]->arrayh)
				continue;
			const char *mode = mi < 0 ? "roofline" : "batch";
			const bench_row *a = find_row(rs, name, p, mode, "l2", 0);
			const bench_row *b = find_row(rs, name, p, mode, "l2", 1);
			const bench_row *c = find_row(rs, name, p, mode, "stream", 0);
			const bench_row *d = find_row(rs, name, p, mode, "stream", 1);
			const bench_row *tp = find_row(rs, name, p, "call_throughput", "l2", 0);
			const bench_row *lat = find_row(rs, name, p, "call_latency", "l2", 0);
			printf("%-24s %7.0f%c %7.0f%c %7.0f%c %7.0f%c %5.0f%% %6.2f %6s %7.2f %7.2f %7.2f\n", mi < 0 ? "(copy roofline)" : name,
			       mbs(a), star(a), mbs(b), star(b), mbs(c), star(c), mbs(d), star(d),
			       c ? 100.0 * c->frac_roof : NAN, a ? a->vs_yard : NAN,
			       a && a->vec ? a->vec : "-", tp ? tp->r.median_s / (double)tp->r.n * 1e9 : NAN,
			       lat ? lat->r.median_s / (double)lat->r.n * 1e9 : NAN,
			       lat ? lat->r.median_s / (double)lat->r.n * 1e9 - lat->chain_ns : NAN);
		}
		for (mi = 0; mi < o->nmeth; mi++) {
			const bench_row *y = find_row(rs, o->meth[mi]->name, p, "yardstick", "l2", 0);
			if (y)
				printf("  yardstick %-20s %8.0f M/s (L2, 1 thread, -march=native %s, %s)\n", y->method, mbs(y),
				       bench_yardstick_isa(), y->vec);
		}
	}
}

/* The L2 size per core in bytes (1 MiB when unknown); the L2-resident and
   stream sizes in bases. */
static long bench_sizes(const bench_opts *o, size_t *n_l2_out, size_t *n_stream_out)
{
	long l2 = -1;
	size_t n_l2, n_stream;
#ifdef _SC_LEVEL2_CACHE_SIZE
	l2 = sysconf(_SC_LEVEL2_CACHE_SIZE);
#endif
	if (l2 <= 0)
		l2 = 1L << 20;
	/* L2-resident: the nine double arrays fill half of one core's L2 */
	n_l2 = ((size_t)l2 / 2 / (9 * sizeof(double))) / 256 * 256;
	if (n_l2 < 1024)
		n_l2 = 1024;
	/* stream: a power of two of bases, float working set >= stream_mib */
	n_stream = 1024;
	while ((double)(n_stream * 9 * sizeof(float)) < o->stream_mib * 1048576.0)
		n_stream *= 2;
	*n_l2_out = n_l2;
	*n_stream_out = n_stream;
	return l2;
}

/* 1 when the CPU has AVX512-FP16 (native binary16 arithmetic). */
static int cpu_has_fp16(void)
{
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && __GNUC__ >= 12
	__builtin_cpu_init();
	return __builtin_cpu_supports("avx512fp16") != 0;
#else
	return 0;
#endif
}

/* The provenance and '#' lines of bench.csv, before the header. */
static void write_header(FILE *f, const bench_opts *o, int tsc, double ghz, const char *load0, const char *load1,
                         long l2, size_t n_l2, size_t n_stream)
{
	study_provenance(f, "bench", o->seed, o->threads);
	fprintf(f, "# timer: clock_gettime(CLOCK_MONOTONIC) between OpenMP barriers; %s\n",
	        tsc ? "cycles from the TSC (constant_tsc nonstop_tsc): ticks at the nominal frequency, not core cycles" :
	              "no constant TSC: cycle columns are nan");
	fprintf(f, "# load: /proc/loadavg %s at the start, %s at the end (%ld CPUs online); other load slows the "
	           "all-threads runs most\n", load0, load1, sysconf(_SC_NPROCESSORS_ONLN));
	fprintf(f, "# flag: load = an all-threads row begun at a 1-minute load average >= %g (other processes took CPU "
	           "time: a lower bound)%s; spread = median time > %g x the minimum over the repetitions; ok otherwise\n",
	        BENCH_BUSY_LOAD, bench_busy ? ", as in this run" : "", BENCH_WIDE_SPREAD);
	if (tsc)
		fprintf(f, "# tsc: %.4f GHz (calibrated against CLOCK_MONOTONIC)\n", ghz);
	fprintf(f, "# isa: batch kernels %s (libonb run-time dispatch, clone '%s'); yardstick and roofline native-%s "
	           "(src/bench/yardstick.c: the flags above + -march=native -fno-tree-loop-distribute-patterns; the copy "
	           "at full vector width); call loops %s (the flags above)\n",
	        onb_batch_isa(), clone_name(), bench_yardstick_isa(), bench_calls_isa());
	if (o->prec_on[PREC_HALF])
		fprintf(f, "# half: binary16 arithmetic EMULATED (isa emulated-%s): libonb's half kernels (src/lib/half.c) do "
		           "each operation in float and round it to binary16, with %s conversions; batch = onb_NAME_arrayh once "
		           "per basis over SoA bit-pattern arrays (libonb has no half batch kernel), calls = onb_NAMEh out of "
		           "line; no yardstick; inputs = the same directions rounded once to binary16; this CPU %s AVX512-FP16 "
		           "(native half arithmetic), which these kernels do not use: no half figure is a hardware half speed\n",
		           half_conv(), strcmp(half_conv(), "f16c") == 0 ? "F16C (vcvtph2ps, vcvtps2ph)" :
		           strcmp(half_conv(), "soft") == 0 ? "libgcc soft-float" : "instruction",
		           cpu_has_fp16() ? "has" : "lacks");
	fprintf(f, "# vectorized: widest register of packed FP arithmetic in the function that ran (objdump of the "
	           "executable): zmm, ymm, xmm, scalar, or unknown\n");
	fprintf(f, "# sizes: l2 = %zu bases per thread (L2 %ld B per core; working set %zu B float, %zu B double); "
	           "stream = %zu bases (%zu B float, %zu B double)\n",
	        n_l2, l2, n_l2 * 36, n_l2 * 72, n_stream, n_stream * 36, n_stream * 72);
	if (o->prec_on[PREC_HALF])
		fprintf(f, "# sizes, half: the same numbers of bases, %zu B (l2) and %zu B (stream)\n", n_l2 * 18, n_stream * 18);
	fprintf(f, "# repetitions: 1 calibration pass, %d warm-up and %d timed repetitions of >= %g s each; "
	           "median (mbases_per_s, ns_per_call, cycles_per_call) and minimum time (_best)%s\n",
	        o->warmup, o->reps, o->target, o->quick ? "; --quick: a check, not a measurement" : "");
	fprintf(f, "# modes: batch = libonb SoA kernel; yardstick = hand-written loop of the same formula; roofline = "
	           "copy 3 arrays to 6; call_throughput = inline function over an array of structs; call_latency = "
	           "dependent chain (input + (b1.x + b2.x) * 0), chain_ns = the chain alone, included in ns_per_call\n");
	fprintf(f, "# ns_per_call and cycles_per_call: wall time per basis (all threads together for threads > 1); "
	           "frac_roofline and vs_yardstick: ratios of best throughput (minimum time, the least disturbed by other load) at "
	           "the same size and threads; each yardstick runs right after its method\n");
}

int cmd_bench(int argc, char **argv)
{
	bench_opts o;
	bench_rows rs = { NULL, 0, 0 };
	char outbuf[4096];
	const char *out;
	study_out f;
	long l2;
	size_t n_l2, n_stream, i;
	int rc, tsc, p;
	double ghz, t0 = bench_now();
	char load0[64], load1[64];

	rc = parse_opts(argc, argv, &o);
	if (rc)
		return rc > 0 ? 0 : ONB_EXIT_USAGE;
	if (o.out)
		out = o.out;
	else {
		study_current_run_dir(outbuf, sizeof outbuf); /* the run of results/latest */
		out = outbuf;
	}
	if (study_mkdir_p(out) != 0)
		return ONB_EXIT_USAGE;
	if (o.reference)
		return bench_reference(out, o.quick, o.seed);
	l2 = bench_sizes(&o, &n_l2, &n_stream);

	bench_loadavg(load0, sizeof load0);
	bench_busy = atof(load0) >= BENCH_BUSY_LOAD;
	tsc = bench_tsc_constant();
	ghz = bench_tsc_ghz(o.quick ? 0.01 : 0.05);
	for (p = 0; p < PREC_COUNT; p++)
		if (o.prec_on[p])
			if (bench_precision(&o, p, n_l2, n_stream, &rs) != 0) {
				free(rs.v);
				return 1;
			}

	bench_loadavg(load1, sizeof load1);
	if (study_out_open(&f, out, "bench.csv") != 0) {
		free(rs.v);
		return 1;
	}
	write_header(f.f, &o, tsc, ghz, load0, load1, l2, n_l2, n_stream);
	fprintf(f.f, "%s\n", BENCH_COLUMNS);
	for (i = 0; i < rs.n; i++)
		write_row(f.f, &rs.v[i], tsc);
	if (study_out_commit(&f) != 0) {
		free(rs.v);
		return 1;
	}
	if (o.csv) {
		printf("%s\n", BENCH_COLUMNS);
		for (i = 0; i < rs.n; i++)
			write_row(stdout, &rs.v[i], tsc);
	} else {
		printf("# onbstudy bench: batch isa %s, yardstick native-%s, call loops %s, %d threads; TSC %s; load %s -> %s\n",
		       onb_batch_isa(), bench_yardstick_isa(), bench_calls_isa(), o.threads,
		       tsc ? "constant" : "not constant (no cycles)", load0, load1);
		print_table(&o, &rs);
		flag_notes(&o, &rs, load0);
	}
	fprintf(stderr, "onbstudy: wrote %s/bench.csv (%zu rows, %.1f s)\n", out, rs.n, bench_now() - t0);
	free(rs.v);
	return 0;
}
