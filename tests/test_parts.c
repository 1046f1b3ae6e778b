/*
 * test_parts.c - adding a method is one checked path: every
 * method of ONB_METHOD_LIST and ONB_FLOAT_METHOD_LIST (include/libonb/onb.h),
 * and frisvad_rotate, has each part the study needs, and this test names
 * the part that is missing:
 *   registry   onb_find(name), with the out-of-line, array and batch kernels
 *              of its precisions (src/lib/registry.c, batch.c)
 *   kernel     the study's kernel, which needs the family to be known: a
 *              family file in src/families/ named in families.c's list
 *   branch     the family's branch rule gives a branch (>= 0)
 *   mpfr       the family's MPFR formula is finite on generic inputs
 *   reffast    the family's fast-reference formula decides some inputs
 *              (where it cannot, every input falls back to MPFR)
 *   family     the kernel IS its family's formula: on NFAMILY random unit
 *              inputs, nine in ten of its errors against the family's MPFR
 *              formula are under 1e3 ulps (0.01 absolute for the approximate
 *              normalizations, whose error includes the approximation); a
 *              method registered under the wrong family is off by O(1)
 *   names      eval's words for each branch the rule gives, distinct for
 *              distinct branches (the family's branch_name)
 *   axes       its six rows in tests/data/axes.csv (list --axes)
 *   man        its name in man/onb.3
 *   index      its line in the method index atop include/libonb/onb.h
 *   bench      the inline call loops (src/bench/bench_calls.c, from the lists)
 *   indep      the independent transliteration (tests/indep.h: its code, id
 *              and row in the table at its end)
 *   model      a rounding model for `onbstudy certify` (the family's;
 *              frisvad_rotate's is the basis it forms on the way);
 *              tests/test_certify.c checks it is bit-exact
 *              (tests/test_certify_dir.c for frisvad_rotate's)
 * The yardstick (src/bench/yardstick.c) re-implements four methods on
 * purpose, not every one: each of its entries must name a registry method.
 * docs/adding-a-method.md is written from this test.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "libonb/onb.h"
#include "methods/kernels.h"
#include "reference/reference.h"
#include "reference/reffast.h"
#include "bench/bench_calls.h"
#include "bench/yardstick.h"
#include "certify/models.h"
#include "inputs/rng.h"
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wunused-function" /* indep.h: only its table is used here */
#endif
#define INDEP_TABLE_DEFINE
#include "indep.h"

#define NAME(m) #m,
static const char *const listed[] = { ONB_METHOD_LIST(NAME) ONB_FLOAT_METHOD_LIST(NAME) "frisvad_rotate" };
#undef NAME
#define NLISTED (sizeof listed / sizeof listed[0])

/* Unit inputs in double (float inputs are these rounded): both poles and
   the axes (where some methods are singular: the branch rule only), then
   generic directions from NGENERIC on (every formula finite there). */
static const double inputs[][3] = {
	{ 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 }, { 0, -1, 0 },
	{ 0.48, 0.6, 0.64 }, { -0.6, 0.48, -0.64 }, { 0.36, -0.48, 0.8 }, { 0.8, 0.36, -0.48 },
	{ -0.28, -0.96, 0 }, { 0, 0.6, -0.8 },
};
#define NIN (sizeof inputs / sizeof inputs[0])
#define NGENERIC 6

#include "check.h"   /* passed, failed: part() counts in them */

static void part(int ok, const char *method, const char *what, const char *where)
{
	if (ok) {
		passed++;
		return;
	}
	failed++;
	printf("FAIL: %s: %s (%s)\n", method, what, where);
}

static void check_registry(const char *name)
{
	const onb_method *m = onb_find(name);
	int has_double;
	part(m != NULL, name, "not in the registry", "src/lib/registry.c");
	if (!m)
		return;
	has_double = !(m->flags & ONB_FLOAT_ONLY);
	part(m->basisf && m->batchf, name, "no float out-of-line or batch kernel", "src/lib/batch.c");
	part(!has_double || (m->basis && m->batch), name, "no double out-of-line or batch kernel", "src/lib/batch.c");
	part(m->arrayf && (has_double ? m->array != NULL : m->array == NULL), name,
	     "no array entry for onb_basis_array[f] (ONB__PTRS)", "src/lib/registry.c");
	part(bench_call_find(name) != NULL, name, "no inline call loops", "src/bench/bench_calls.c");
}

static void check_indep(const char *name)
{
	size_t i;
	int found = 0;
	for (i = 0; i < NT; i++)
		found |= strcmp(T[i].name, name) == 0;
	part(found, name, "no independent transliteration", "tests/indep.h");
}

/* ---- the text files that must name a method ---- */

/* The whole file, or NULL (then every check against it fails). */
static char *slurp(const char *path)
{
	FILE *f = fopen(path, "rb");
	char *b = NULL;
	long n;
	if (!f)
		return NULL;
	if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0 &&
	    (b = malloc((size_t)n + 1)) != NULL) {
		if (fread(b, 1, (size_t)n, f) != (size_t)n) {
			free(b);
			b = NULL;
		} else {
			b[n] = '\0';
		}
	}
	fclose(f);
	return b;
}

static int word_char(char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; }

/* Does `name` occur as a whole word in the text [t, end)? */
static int has_word(const char *t, const char *end, const char *name)
{
	const size_t l = strlen(name);
	const char *q;
	for (q = t; q && q + l <= end && (q = strstr(q, name)) != NULL && q + l <= end; q++)
		if ((q == t || !word_char(q[-1])) && !word_char(q[l]))
			return 1;
	return 0;
}

/* Rows of tests/data/axes.csv whose first field is name. */
static int axes_rows(const char *csv, const char *name)
{
	const size_t l = strlen(name);
	const char *q;
	int n = 0;
	for (q = csv; q && *q; q = strchr(q, '\n'), q = q ? q + 1 : NULL)
		n += strncmp(q, name, l) == 0 && q[l] == ',';
	return n;
}

/* Is name in man/onb.3 on a .B or .BR line? */
static int man_names(const char *man, const char *name)
{
	const char *q;
	for (q = man; q && *q; q = strchr(q, '\n'), q = q ? q + 1 : NULL) {
		const char *e = strchr(q, '\n');
		if (!e)
			e = q + strlen(q);
		if ((strncmp(q, ".B ", 3) == 0 || strncmp(q, ".BR ", 4) == 0) && has_word(q, e, name))
			return 1;
	}
	return 0;
}

/* Is onb_NAME (or onb_NAMEf, or a prefix of NAME followed by '*') in the
   method index, the header's first comment? */
static int index_names(const char *hdr, const char *name)
{
	const char *end = strstr(hdr, "*/"), *q;
	char w[96];
	if (!end)
		return 0;
	snprintf(w, sizeof w, "onb_%s", name);
	if (has_word(hdr, end, w) || (strcat(w, "f"), has_word(hdr, end, w)))
		return 1;
	for (q = hdr; (q = strstr(q, "onb_")) != NULL && q < end; q += 4) {
		size_t l = 0;
		while (word_char(q[4 + l]))
			l++;
		if (q[4 + l] == '*' && l > 0 && strncmp(q + 4, name, l) == 0)
			return 1;
	}
	return 0;
}

static char *axes_csv, *man_page, *header;

static void check_texts(const char *name)
{
	part(axes_csv && axes_rows(axes_csv, name) == 6, name, "not six rows of frames at the axes",
	     "tests/data/axes.csv: sh scripts/axes-golden.sh on x86-64 adds them");
	part(man_page && man_names(man_page, name), name, "not in the man page", "man/onb.3, METHODS");
	part(header && index_names(header, name), name, "not in the method index", "include/libonb/onb.h, Index");
}

/* ---- the kernel is its family's formula ---- */

#define NFAMILY 2000

static int cmp_double(const void *a, const void *b)
{
	const double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* Unit input i of the family check: uniform on the sphere. */
static void family_input(uint64_t i, double n[3])
{
	const double z = 2.0 * rng_u01(29, 1, i) - 1.0, phi = 6.283185307179586 * rng_u01(29, 2, i);
	const double r = sqrt(fmax(0.0, 1.0 - z * z));
	n[0] = r * cos(phi);
	n[1] = r * sin(phi);
	n[2] = z;
}

static double worst_q90;            /* the largest 0.9 quantile in ulps, reported */
static char worst_name[80];

/* The errors of kernel k in precision p against its own family's MPFR
   formula (in ulps; absolute for an approximate normalization) must be
   small on nine inputs in ten: a kernel registered under another family's
   formula is off by O(1) wherever the formulas differ (a hemisphere, for
   Frisvad's formula against Duff's).  Not the maximum, since near a
   singular or threshold direction a right family's error grows too. */
static void check_family(const study_kernel *k, int p, ref_ctx *rc)
{
	static const double loc[3] = { 0.6, 0.0, 0.8 };
	static double e[NFAMILY];
	const int approx = k->m && (k->m->flags & ONB_APPROX_NORM) && k->m->norm != ONB__NORM_NONE;
	const double eps = p == PREC_FLOAT ? 0x1p-23 : 0x1p-52;
	int i, m = 0;
	double q;
	for (i = 0; i < NFAMILY; i++) {
		double n[3];
		sample_metrics s;
		family_input((uint64_t)i, n);
		ref_eval(rc, k, p, n, loc, 0, &s);
		if (!s.nonfinite)
			e[m++] = approx ? s.abs_eps_max * eps : s.ulp_max;
	}
	qsort(e, (size_t)m, sizeof e[0], cmp_double);
	q = m ? e[m - 1 - m / 10] : INFINITY;
	if (!approx && q > worst_q90) {
		worst_q90 = q;
		snprintf(worst_name, sizeof worst_name, "%s %s", k->name, prec_name(p));
	}
	if (!(approx ? q < 1e-2 : q < 1e3)) {
		char why[160];
		snprintf(why, sizeof why, "not its family's formula: one input in ten %.3g %s or more from it (%d inputs)",
		         q, approx ? "absolute" : "ulps", m);
		part(0, k->name, why, k->fam->name);
	} else {
		part(1, k->name, "", "");
	}
}

/* eval's words for branch br of k: present, and other than those of the
   branches seen before (seen[b] holds branch b's words, or ""). */
static int names_ok(const study_kernel *k, int br, char seen[][96], int nseen)
{
	char buf[96];
	const char *w = k->fam->branch_name(k->m, br, buf, sizeof buf);
	int b;
	if (!w || !*w || br >= nseen)
		return 0;
	if (!seen[br][0])
		snprintf(seen[br], 96, "%s", w);
	for (b = 0; b < nseen; b++)
		if (b != br && seen[b][0] && strcmp(seen[b], w) == 0)
			return 0;
	return 1;
}

/* The branch rule, the MPFR formula and the fast reference of kernel k in
   precision p, on every input; reffast must decide at least one. */
static void check_reference(const study_kernel *k, int p, ref_ctx *rc, reffast_ctx *fc)
{
	static const double loc[3] = { 0.6, 0.0, 0.8 };
	int branch_ok = 1, mpfr_ok = 1, decided = 0, named = 1;
	char seen[8][96] = { "" };
	size_t i, j;
	for (i = 0; i < NIN; i++) {
		double n[3];
		sample_metrics s;
		int br;
		for (j = 0; j < 3; j++)
			n[j] = p == PREC_FLOAT ? (double)(float)inputs[i][j] : inputs[i][j];
		br = k->branch(k, p, n);
		branch_ok &= br >= 0;
		named &= br < 0 || names_ok(k, br, seen, 8);
		ref_eval(rc, k, p, n, loc, 0, &s);
		for (j = 0; i >= NGENERIC && j < (k->m ? 6u : 3u); j++)
			mpfr_ok &= !isnan(s.ref[j]);
		if (fc)
			decided += reffast_eval(fc, k, p, n, loc, 0, &s) != REFFAST_MPFR;
	}
	part(branch_ok, k->name, "no branch rule for its family", k->fam->name);
	part(mpfr_ok, k->name, "no MPFR formula for its family", k->fam->name);
	part(named, k->name, "eval has no words (or the same words) for its branches", k->fam->name);
	if (fc)
		part(decided > 0, k->name, "no fast-reference formula (every input fell back to MPFR)", k->fam->name);
}

static void check_study(const char *name, ref_ctx *rc, reffast_ctx *fc)
{
	study_kernel k;
	int p;
	part(kernels_select(name, 0, &k, 1) == 1, name, "no study kernel (family unknown to the study)",
	     "src/families/: a family file, and its name in families.c's list");
	if (kernels_select(name, 0, &k, 1) != 1)
		return;
	for (p = 0; p < 2; p++)
		if (kernel_runs(&k, p)) {
			check_reference(&k, p, rc, fc);
			check_family(&k, p, rc);
		}
}

/* argv[1], when given: that method alone (make check-method M=NAME). */
int main(int argc, char **argv)
{
	ref_ctx *rc = ref_new(127);
	const char *why = "";
	reffast_ctx *fc = reffast_usable(127, &why) ? reffast_new(127) : NULL;
	size_t i, ny, nchecked = 0;
	const bench_yardstick *y = bench_yardsticks(&ny);
	if (!rc) {
		printf("test_parts: out of memory\n");
		return 2;
	}
	if (!fc)
		printf("test_parts: note: the fast reference is not usable here (%s): its part is not checked\n", why);
	axes_csv = slurp("tests/data/axes.csv");
	man_page = slurp("man/onb.3");
	header = slurp("include/libonb/onb.h");
	for (i = 0; i < NLISTED; i++) {
		if (argc > 1 && strcmp(argv[1], listed[i]) != 0)
			continue;
		nchecked++;
		if (strcmp(listed[i], "frisvad_rotate") != 0) {
			check_registry(listed[i]);
			check_indep(listed[i]);
			check_texts(listed[i]);
		}
		part(cm_find(listed[i]) != NULL, listed[i], "no rounding model (certify skips it)", "its family file's model");
		check_study(listed[i], rc, fc);
	}
	for (i = 0; i < ny; i++)
		part(onb_find(y[i].name) != NULL, y[i].name, "a yardstick of no registry method", "src/bench/yardstick.c");
	if (argc > 1 && !onb_find(argv[1]) && strcmp(argv[1], "frisvad_rotate") != 0)
		part(0, argv[1], "not a listed method", "include/libonb/onb.h, ONB_METHOD_LIST");
	ref_free(rc);
	reffast_free(fc);
	free(axes_csv);
	free(man_page);
	free(header);
	printf("test_parts: the kernels against their families' MPFR formulas on %d inputs each: largest 0.9 "
	       "quantile %.3g ulps (%s)\n", NFAMILY, worst_q90, worst_name);
	printf("test_parts: %zu methods; %d passed, %d failed\n", nchecked, passed, failed);
	return failed ? 1 : 0;
}
