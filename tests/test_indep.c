/*
 * test_indep.c - every method of libonb against a second implementation
 * written separately from include/libonb/onb.h (tests/indep.h, transliterated
 * from each source), bit for bit, in float and double, for the inline
 * function, the out-of-line copy and the batch kernel.
 *
 * Inputs, per precision (each a unit vector rounded to the format):
 *   uniform    N directions uniform on the sphere (default 1,000,000;
 *              --quick: 16,384, and a quarter of the repetitions below)
 *   poles      n.z = +-1 exactly and k ulps from it (k = 1..64), and 1 -+ n.z
 *              log-uniform from eps to 0.1, with random azimuths
 *   threshold  every branch threshold of every method, +-8 ulps: n.x =
 *              +-0.9 (naive, rtow), n.z = Frisvad's and Max's t, n.z = +-0
 *              and subnormals (duff, duff_branchless), |a| = |b| for the
 *              pairs (x,y), (x,z), (y,z) (hughes_moeller, pbrt_v3, stark),
 *              with random signs and azimuths; and the six axes.
 * Exit 1 on any differing bit (NaN included: the bits must match too).
 *
 * -DINDEP_INLINE_ONLY builds the test against the header alone (no
 * libonb.a): scripts/mutate.sh uses it to judge each mutant in seconds,
 * with INDEP_STOP_EARLY set in the environment (exit 1 at the first
 * method that differs) and INDEP_FIRST=NAME (the rows whose name and NAME
 * share a prefix, NAME's trailing f or not, run first: mutate.sh passes the
 * mutated function's name, so a caught mutant stops after its own method;
 * the order changes no verdict, and the hash is the same in any order).
 * INDEP_PARTIAL: the table is a subset (mutate.sh's first try builds the
 * mutated function's rows alone): no coverage or alias checks.
 */
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "libonb/onb.h"
/* scripts/mutate.sh (INDEP_SPLIT): the table comes from tests/indep_lib.c,
   built against the mutated header, and this file is compiled once */
#ifndef INDEP_SPLIT
#define INDEP_TABLE_DEFINE
#endif
#include "indep.h"

#define IND_PI 3.14159265358979323846
#ifdef INDEP_SPLIT
const indep_row *indep_rows(size_t *n);
static const indep_row *T;
static size_t NT;
#endif

/* ---- inputs ---- */
typedef struct { double *x, *y, *z; size_t n, cap; int fl; } inset;
static uint64_t rng_s = 0x696e646570ULL;
static int reps_div = 1; /* --quick divides the repetitions below by 4 */
static double urand(void)
{
	uint64_t z = (rng_s += 0x9e3779b97f4a7c15ULL);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	return (double)((z ^ (z >> 31)) >> 11) * 0x1p-53;
}
static double rnd(const inset *s, double v) { return s->fl ? (double)(float)v : v; }
static double step(const inset *s, double v, int k)
{
	for (; k > 0; k--) v = s->fl ? (double)nextafterf((float)v, 2.0f) : nextafter(v, 2.0);
	for (; k < 0; k++) v = s->fl ? (double)nextafterf((float)v, -2.0f) : nextafter(v, -2.0);
	return v;
}
static void push(inset *s, double x, double y, double z)
{
	if (s->n == s->cap) {
		s->cap = s->cap ? 2 * s->cap : 4096;
		s->x = realloc(s->x, s->cap * sizeof *s->x);
		s->y = realloc(s->y, s->cap * sizeof *s->y);
		s->z = realloc(s->z, s->cap * sizeof *s->z);
		if (!s->x || !s->y || !s->z) { fprintf(stderr, "test_indep: out of memory\n"); exit(2); }
	}
	s->x[s->n] = rnd(s, x); s->y[s->n] = rnd(s, y); s->z[s->n] = rnd(s, z);
	s->n++;
}
/* Component `c` fixed to v (already in the format), the other two on the
   circle of radius sqrt(1 - v^2) at a random azimuth. */
static void push_fixed(inset *s, int c, double v)
{
	double r = sqrt(fmax(0.0, 1.0 - v * v)), ph = 2.0 * IND_PI * urand();
	double a = r * cos(ph), b = r * sin(ph), o[3];
	o[c] = v; o[(c + 1) % 3] = a; o[(c + 2) % 3] = b;
	push(s, o[0], o[1], o[2]);
}
static void gen_uniform(inset *s, size_t n)
{
	size_t i;
	for (i = 0; i < n; i++) {
		double z = 2.0 * urand() - 1.0, ph = 2.0 * IND_PI * urand(), r = sqrt(1.0 - z * z);
		push(s, r * cos(ph), r * sin(ph), z);
	}
}
static void gen_poles(inset *s)
{
	const double eps = s->fl ? FLT_EPSILON : DBL_EPSILON;
	int sg, k, j;
	for (sg = -1; sg <= 1; sg += 2) {
		for (k = 0; k <= 64; k++)
			for (j = 0; j < (k ? 16 : 1); j++)
				push_fixed(s, 2, step(s, (double)sg, -sg * k));
		push(s, 0.0, 0.0, (double)sg); push(s, -0.0, 0.0, (double)sg); push(s, 0.0, -0.0, (double)sg);
		for (k = 0; k < 8192 / reps_div; k++)
			push_fixed(s, 2, rnd(s, sg * (1.0 - eps * pow(0.1 / eps, urand()))));
	}
}
/* |a| = |b| (components ca, cb) at magnitude v, b stepped k ulps. */
static void gen_pair(inset *s, int ca, int cb, int reps)
{
	int r, k;
	for (r = 0; r < reps; r++) {
		const double v = rnd(s, urand() * 0.70710678118654752440);
		for (k = -8; k <= 8; k++) {
			double o[3], w = step(s, v, k);
			int cc = 3 - ca - cb;
			o[ca] = urand() < 0.5 ? -v : v;
			o[cb] = urand() < 0.5 ? -w : w;
			o[cc] = sqrt(fmax(0.0, 1.0 - v * v - w * w)) * (urand() < 0.5 ? -1.0 : 1.0);
			push(s, o[0], o[1], o[2]);
		}
	}
}
/* The engines' thresholds: q2rtx's n.z = -0.999805696f and filament's
   n.y = -1 + FLT_EPSILON (+-8 ulps), luxcore's sqrt(n.x^2 + n.y^2) = 1e-5
   (n.z = +-1 with a small transverse part in float, n.z stepped in double),
   and cycles_cross111's diagonal n.x = n.y = n.z (+-4 ulps per component). */
static void gen_engines(inset *s)
{
	int k, r, j;
	for (k = -8; k <= 8; k++)
		for (r = 0; r < 64 / reps_div; r++) {
			push_fixed(s, 2, step(s, rnd(s, (double)-0.999805696f), k));
			push_fixed(s, 1, step(s, rnd(s, (double)(-1.0f + FLT_EPSILON)), k));
		}
	for (r = 0; r < 512 / reps_div; r++) {
		const double len = 1e-5 * pow(2.0, 4.0 * urand() - 2.0), ph = 2.0 * IND_PI * urand();
		const double sg = urand() < 0.5 ? -1.0 : 1.0;
		if (s->fl)
			push(s, len * cos(ph), len * sin(ph), sg);
		else
			push_fixed(s, 2, sg * sqrt(1.0 - len * len));
	}
	for (r = 0; r < 2; r++) {
		const double d = (r ? -1.0 : 1.0) / sqrt(3.0);
		double o[3];
		for (k = 0; k < 729; k++) { /* each component -4..4 ulps from the diagonal */
			int q = k;
			for (j = 0; j < 3; j++, q /= 9)
				o[j] = step(s, rnd(s, d), q % 9 - 4);
			push(s, o[0], o[1], o[2]);
		}
	}
}

static void gen_thresholds(inset *s)
{
	const double vals[] = { 0.9, -0.9, -0.9999999, -0.99998796 };
	const int comp[] = { 0, 0, 2, 2 };
	int i, k, r;
	for (i = 0; i < 4; i++)
		for (k = -8; k <= 8; k++)
			for (r = 0; r < 64 / reps_div; r++) {
				/* rtow compares |unit(w).x|: the same inputs serve */
				push_fixed(s, comp[i], step(s, rnd(s, vals[i]), k));
			}
	for (k = 0; k <= 8; k++)
		for (r = 0; r < 64; r++) {
			const double tiny = s->fl ? 0x1p-149 : 0x1p-1074; /* the smallest subnormals */
			const double nrm = s->fl ? (double)FLT_MIN : DBL_MIN;
			push_fixed(s, 2, k * tiny); push_fixed(s, 2, -k * tiny);
			push_fixed(s, 2, step(s, nrm, k)); push_fixed(s, 2, -step(s, nrm, k));
			push_fixed(s, 2, step(s, s->fl ? FLT_EPSILON : DBL_EPSILON, k - 4));
			push_fixed(s, 2, -step(s, s->fl ? FLT_EPSILON : DBL_EPSILON, k - 4));
		}
	gen_pair(s, 0, 1, 2048 / reps_div); gen_pair(s, 0, 2, 2048 / reps_div); gen_pair(s, 1, 2, 2048 / reps_div);
	gen_engines(s);
	for (i = 0; i < 3; i++) {
		double o[3] = { 0.0, 0.0, 0.0 };
		o[i] = 1.0; push(s, o[0], o[1], o[2]);
		o[i] = -1.0; push(s, o[0], o[1], o[2]);
	}
}

/* ---- comparison ---- */
/* FNV-1a over every output bit of the inline versions: scripts/mutate.sh
   compares it with the unmutated header's to tell whether a mutant changed
   any output on these inputs, apart from whether the test caught it. */
static uint64_t out_hash = 0xcbf29ce484222325ULL; /* HASH_SEED */
static void hash_bytes(const void *p, size_t n)
{
	const unsigned char *b = p;
	size_t i;
	for (i = 0; i < n; i++) { out_hash ^= b[i]; out_hash *= 0x100000001b3ULL; }
}
#define HASH_SEED 0xcbf29ce484222325ULL

/* INDEP_FIRST: is one of a and b a prefix of the other (a's final f
   dropped or not)?  "dufff" and "duff_compf" -> duff, duff_comp. */
static int prefix_either(const char *a, size_t na, const char *b)
{
	size_t nb = strlen(b), m = na < nb ? na : nb;
	return m > 0 && strncmp(a, b, m) == 0;
}
static int first_row(const char *key, const char *name)
{
	size_t n = key ? strlen(key) : 0;
	if (n == 0)
		return 0;
	return prefix_either(key, n, name) || (n > 1 && key[n - 1] == 'f' && prefix_either(key, n - 1, name));
}
static int same_d(double a, double b) { uint64_t x, y; memcpy(&x, &a, 8); memcpy(&y, &b, 8); return x == y; }
static int same_f(float a, float b)   { uint32_t x, y; memcpy(&x, &a, 4); memcpy(&y, &b, 4); return x == y; }
static int same6_d(const double *a, const double *b)
{
	int i;
	for (i = 0; i < 6; i++) if (!same_d(a[i], b[i])) return 0;
	return 1;
}
static int same6_f(const float *a, const float *b)
{
	int i;
	for (i = 0; i < 6; i++) if (!same_f(a[i], b[i])) return 0;
	return 1;
}
static long report(const char *name, const char *prec, const char *what, long bad, const double *n, const double *a, const double *b)
{
	if (bad <= 3)
		printf("  %s/%s %s differs at n = (%a, %a, %a):\n    lib   %a %a %a | %a %a %a\n    indep %a %a %a | %a %a %a\n",
		       name, prec, what, n[0], n[1], n[2], a[0], a[1], a[2], a[3], a[4], a[5], b[0], b[1], b[2], b[3], b[4], b[5]);
	return bad;
}

/* One method in double: indep vs inline (and out-of-line, batch).  The
   transliteration is `id` (with normalization k): T[t]'s own, or an
   alias's, then reported under `label`. */
static long check_d(size_t t, int id, int k, const char *label, const inset *s, double *bo)
{
	long bad = 0;
	size_t i;
#ifndef INDEP_INLINE_ONLY
	const onb_method *m = onb_find(T[t].name);
	m->batch(s->n, s->x, s->y, s->z, bo, bo + s->n, bo + 2 * s->n, bo + 3 * s->n, bo + 4 * s->n, bo + 5 * s->n);
#else
	(void)bo;
#endif
	for (i = 0; i < s->n; i++) {
		onb_vec3 n, b1, b2;
		Vec3d in = vd(s->x[i], s->y[i], s->z[i]), r1, r2;
		double ref[6], got[6], nn[3] = { s->x[i], s->y[i], s->z[i] };
		const char *what = NULL;
		int j;
		n.x = s->x[i]; n.y = s->y[i]; n.z = s->z[i];
		indep_d(id, k, in, &r1, &r2);
		ref[0] = r1.x; ref[1] = r1.y; ref[2] = r1.z; ref[3] = r2.x; ref[4] = r2.y; ref[5] = r2.z;
		T[t].d(n, &b1, &b2);
		got[0] = b1.x; got[1] = b1.y; got[2] = b1.z; got[3] = b2.x; got[4] = b2.y; got[5] = b2.z;
		hash_bytes(got, sizeof got);
		if (!same6_d(got, ref)) what = "inline";
#ifndef INDEP_INLINE_ONLY
		if (!what) {
			m->basis(n, &b1, &b2);
			got[0] = b1.x; got[1] = b1.y; got[2] = b1.z; got[3] = b2.x; got[4] = b2.y; got[5] = b2.z;
			if (!same6_d(got, ref)) what = "out-of-line";
		}
		if (!what) {
			for (j = 0; j < 6; j++) got[j] = bo[(size_t)j * s->n + i];
			if (!same6_d(got, ref)) what = "batch";
		}
#endif
		(void)j;
		if (what)
			report(label, "double", what, ++bad, nn, got, ref);
	}
	return bad;
}

/* The same in float; fx, fy, fz hold the inputs, bo the batch outputs. */
static long check_f(size_t t, int id, int k, const char *label, const inset *s, const float *fx, const float *fy,
                    const float *fz, float *bo)
{
	long bad = 0;
	size_t i;
#ifndef INDEP_INLINE_ONLY
	const onb_method *m = onb_find(T[t].name);
	m->batchf(s->n, fx, fy, fz, bo, bo + s->n, bo + 2 * s->n, bo + 3 * s->n, bo + 4 * s->n, bo + 5 * s->n);
#else
	(void)bo;
#endif
	for (i = 0; i < s->n; i++) {
		onb_vec3f n, b1, b2;
		Vec3f in = vf(fx[i], fy[i], fz[i]), r1, r2;
		float ref[6], got[6];
		const char *what = NULL;
		int j;
		n.x = fx[i]; n.y = fy[i]; n.z = fz[i];
		indep_f(id, k, in, &r1, &r2);
		ref[0] = r1.x; ref[1] = r1.y; ref[2] = r1.z; ref[3] = r2.x; ref[4] = r2.y; ref[5] = r2.z;
		T[t].f(n, &b1, &b2);
		got[0] = b1.x; got[1] = b1.y; got[2] = b1.z; got[3] = b2.x; got[4] = b2.y; got[5] = b2.z;
		hash_bytes(got, sizeof got);
		if (!same6_f(got, ref)) what = "inline";
#ifndef INDEP_INLINE_ONLY
		if (!what) {
			m->basisf(n, &b1, &b2);
			got[0] = b1.x; got[1] = b1.y; got[2] = b1.z; got[3] = b2.x; got[4] = b2.y; got[5] = b2.z;
			if (!same6_f(got, ref)) what = "out-of-line";
		}
		if (!what) {
			for (j = 0; j < 6; j++) got[j] = bo[(size_t)j * s->n + i];
			if (!same6_f(got, ref)) what = "batch";
		}
#endif
		(void)j;
		if (what) {
			double nn[3] = { fx[i], fy[i], fz[i] }, g[6], r[6];
			for (j = 0; j < 6; j++) { g[j] = got[j]; r[j] = ref[j]; }
			report(label, "float", what, ++bad, nn, g, r);
		}
	}
	return bad;
}

static void build(inset *s, int fl, size_t nuni)
{
	memset(s, 0, sizeof *s);
	s->fl = fl;
	gen_uniform(s, nuni);
	gen_poles(s);
	gen_thresholds(s);
}

/* Every method of the header's list (and of the registry) has a row. */
static int coverage(void)
{
#define ONE(m) + 1
	const size_t listed = 0 ONB_METHOD_LIST(ONE) ONB_FLOAT_METHOD_LIST(ONE);
#undef ONE
	size_t i, j;
	if (listed != NT) {
		printf("FAIL: %zu methods in ONB_METHOD_LIST and ONB_FLOAT_METHOD_LIST, %zu in this test\n", listed, (size_t)NT);
		return 1;
	}
	for (i = 0; i < NT; i++)
		for (j = 0; j < i; j++)
			if (strcmp(T[i].name, T[j].name) == 0) { printf("FAIL: %s twice\n", T[i].name); return 1; }
#ifndef INDEP_INLINE_ONLY
	{
		size_t nm;
		const onb_method *m = onb_methods(&nm);
		if (nm != NT) { printf("FAIL: registry has %zu methods, test %zu\n", nm, (size_t)NT); return 1; }
		for (i = 0; i < nm; i++)
			if (!onb_find(m[i].name)) return 1;
		for (i = 0; i < NT; i++)
			if (!onb_find(T[i].name)) { printf("FAIL: %s not in the registry\n", T[i].name); return 1; }
	}
#endif
	return 0;
}

/* The aliases: each claimed precision of each alias's transliteration
   against its target's inline, out-of-line and batch code, on the same
   inputs; the registry's alias table and this test's must agree. */
static int alias_coverage(void)
{
	size_t i, j, n = 0;
#ifndef INDEP_INLINE_ONLY
	const onb_alias *a = onb_aliases(&n);
	if (n != NIA) { printf("FAIL: registry has %zu aliases, test %zu\n", n, (size_t)NIA); return 1; }
	for (i = 0; i < n; i++) {
		const int both = strcmp(a[i].precisions, "float and double") == 0;
		for (j = 0; j < NIA && strcmp(IA[j].name, a[i].name) != 0; j++)
			;
		if (j == NIA || strcmp(IA[j].target, a[i].target) != 0 || IA[j].dbl != both || !IA[j].fl ||
		    (!both && strcmp(a[i].precisions, "float") != 0)) {
			printf("FAIL: alias %s: registry and test disagree (target, precisions)\n", a[i].name);
			return 1;
		}
		if (onb_find(a[i].name) || !onb_find(a[i].target) || onb_find_alias(a[i].name) != &a[i]) {
			printf("FAIL: alias %s: a method of that name, or no target method\n", a[i].name);
			return 1;
		}
	}
#endif
	(void)j;
	for (i = 0; i < NIA; i++) {
		for (j = 0; j < NT && strcmp(T[j].name, IA[i].target) != 0; j++)
			;
		if (j == NT) { printf("FAIL: alias %s: target %s has no row\n", IA[i].name, IA[i].target); return 1; }
	}
	return 0;
}
static size_t alias_row(size_t i)
{
	size_t j;
	for (j = 0; j < NT && strcmp(T[j].name, IA[i].target) != 0; j++)
		;
	return j;
}
/* Non-finite inputs (NaN, +-inf, +-0, 1/2 in every component), NaN
   compared as a class (which NaN propagates is the compiler's operand order):
   the count of inputs where alias i and its target's inline float code differ. */
static long alias_nonfinite(size_t i)
{
	static const float v[6] = { NAN, -NAN, INFINITY, -INFINITY, -0.0f, 0.5f };
	long bad = 0;
	int a, b, c, j;
	for (a = 0; a < 6; a++) for (b = 0; b < 6; b++) for (c = 0; c < 6; c++) {
		onb_vec3f n, l1, l2;
		Vec3f r1, r2;
		float g[6], r[6];
		n.x = v[a]; n.y = v[b]; n.z = v[c];
		T[alias_row(i)].f(n, &l1, &l2);
		indep_f(IA[i].id, 0, vf(n.x, n.y, n.z), &r1, &r2);
		g[0] = l1.x; g[1] = l1.y; g[2] = l1.z; g[3] = l2.x; g[4] = l2.y; g[5] = l2.z;
		r[0] = r1.x; r[1] = r1.y; r[2] = r1.z; r[3] = r2.x; r[4] = r2.y; r[5] = r2.z;
		for (j = 0; j < 6; j++)
			if (!(g[j] != g[j] && r[j] != r[j]) && !same_f(g[j], r[j])) { bad++; break; }
	}
	return bad;
}
/* the aliases whose registry note excepts NaN z (sign = z >= 0 ? 1 : -1) */
static int nan_z_alias(const char *name)
{
	return strcmp(name, "falcor") == 0 || strcmp(name, "rtxdi") == 0;
}
static long check_aliases(const inset *sd, const inset *sf, const float *fx, const float *fy, const float *fz,
                          float *bof, double *bod)
{
	long fails = 0;
	size_t i;
	for (i = 0; i < NIA; i++) {
		const size_t t = alias_row(i);
		long bd = IA[i].dbl ? check_d(t, IA[i].id, 0, IA[i].name, sd, bod) : 0;
		long bf = check_f(t, IA[i].id, 0, IA[i].name, sf, fx, fy, fz, bof);
		long nf = alias_nonfinite(i);
		printf("  alias %-18s = %-16s double %s, float %ld differ; non-finite inputs: %ld of 216 differ%s\n",
		       IA[i].name, IA[i].target, IA[i].dbl ? (bd ? "DIFFERS" : "0 differ") : "(float only)", bf, nf,
		       nan_z_alias(IA[i].name) ? " (the NaN-z exception of the registry's note: expected > 0)" : "");
		fails += bd + bf;
		/* the registry notes falcor's and rtxdi's NaN-z exception alone */
		if (nan_z_alias(IA[i].name) != (nf > 0)) {
			printf("FAIL: alias %s: non-finite behaviour not as its registry note says\n", IA[i].name);
			fails++;
		}
	}
	return fails;
}

int main(int argc, char **argv)
{
	const int quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
	const size_t nuni = quick ? 16384 : 1000000;
	const int stop_early = getenv("INDEP_STOP_EARLY") != NULL;
	const char *first = getenv("INDEP_FIRST");
	const int partial = getenv("INDEP_PARTIAL") != NULL;
	uint64_t *row_hash;
	int pass;
	inset sd, sf;
	float *fx, *fy, *fz, *bof;
	double *bod;
	long fails = 0;
	size_t t, i;
#ifdef INDEP_SPLIT
	T = indep_rows(&NT);
#endif
	/* INDEP_PARTIAL (mutate.sh's first try): a table of a few rows, so
	   neither the coverage of the lists nor the aliases are checked */
	if (!partial && (coverage() || alias_coverage()))
		return 1;
	if (quick)
		reps_div = 4;
	build(&sd, 0, nuni);
	build(&sf, 1, nuni);
	fx = malloc(sf.n * sizeof *fx); fy = malloc(sf.n * sizeof *fy); fz = malloc(sf.n * sizeof *fz);
	bof = malloc(6 * sf.n * sizeof *bof); bod = malloc(6 * sd.n * sizeof *bod);
	row_hash = calloc(NT, sizeof *row_hash);
	if (!fx || !fy || !fz || !bof || !bod || !row_hash) { fprintf(stderr, "test_indep: out of memory\n"); return 2; }
	for (i = 0; i < sf.n; i++) { fx[i] = (float)sf.x[i]; fy[i] = (float)sf.y[i]; fz[i] = (float)sf.z[i]; }
	printf("test_indep: %zu double and %zu float inputs (%zu uniform each, poles, thresholds +-8 ulps)\n", sd.n, sf.n, nuni);
	/* pass 0: INDEP_FIRST's rows; pass 1: the others.  Each row's outputs
	   hash on their own, and the rows' hashes in table order make the
	   outputs-hash, whatever order they ran in. */
	for (pass = 0; pass < 2; pass++) for (t = 0; t < NT; t++) {
		long bd, bf;
		if (first_row(first, T[t].name) != (pass == 0))
			continue;
		out_hash = HASH_SEED;
		bd = T[t].d ? check_d(t, T[t].id, T[t].k, T[t].name, &sd, bod) : 0;
		bf = check_f(t, T[t].id, T[t].k, T[t].name, &sf, fx, fy, fz, bof);
		row_hash[t] = out_hash;
		printf("  %-24s double %ld differ, float %ld differ%s\n", T[t].name, bd, bf,
#ifdef INDEP_INLINE_ONLY
		       " (inline only)"
#else
		       " (inline, out-of-line, batch)"
#endif
		       );
		fails += bd + bf;
		/* scripts/mutate.sh only needs the verdict: a mutant that fails
		   here is caught, and the rest of the run would not change that */
		if (fails && stop_early) {
			printf("test_indep: FAILED (stopped at the first failing method: INDEP_STOP_EARLY)\n");
			return 1;
		}
	}
	out_hash = HASH_SEED;
	hash_bytes(row_hash, NT * sizeof *row_hash);
	free(row_hash);
	if (!partial)
		fails += check_aliases(&sd, &sf, fx, fy, fz, bof, bod);
	free(sd.x); free(sd.y); free(sd.z); free(sf.x); free(sf.y); free(sf.z);
	free(fx); free(fy); free(fz); free(bof); free(bod);
	printf("outputs-hash %016llx\n", (unsigned long long)out_hash);
	printf("test_indep: %s\n", fails ? "FAILED" : "all methods and aliases agree bit for bit");
	return fails ? 1 : 0;
}
