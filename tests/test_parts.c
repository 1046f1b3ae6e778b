/*
 * test_parts.c - adding a method is one checked path (issue 23): every
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
 *   bench      the inline call loops (src/bench/bench_calls.c, from the lists)
 *   indep      the independent transliteration (tests/indep.h and its row in
 *              tests/indep_table.h)
 *   model      a rounding model for `onbstudy certify` (the family's;
 *              frisvad_rotate's direction error has none, said in
 *              docs/certify.md); tests/test_certify.c checks it is bit-exact
 * The yardstick (src/bench/yardstick.c) re-implements four methods on
 * purpose, not every one: each of its entries must name a registry method.
 * docs/adding-a-method.md is written from this test.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "libonb/onb.h"
#include "methods/kernels.h"
#include "reference/reference.h"
#include "reference/reffast.h"
#include "bench/bench_calls.h"
#include "bench/yardstick.h"
#include "certify/models.h"
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wunused-function" /* indep.h: only its table is used here */
#endif
#include "indep.h"
#define INDEP_TABLE_DEFINE
#include "indep_table.h"

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
	int dbl;
	part(m != NULL, name, "not in the registry", "src/lib/registry.c");
	if (!m)
		return;
	dbl = !(m->flags & ONB_FLOAT_ONLY);
	part(m->basisf && m->batchf, name, "no float out-of-line or batch kernel", "src/lib/batch.c");
	part(!dbl || (m->basis && m->batch), name, "no double out-of-line or batch kernel", "src/lib/batch.c");
	part(m->arrayf && (dbl ? m->array != NULL : m->array == NULL), name,
	     "no array entry for onb_basis_array[f] (ONB__PTRS)", "src/lib/registry.c");
	part(bench_call_find(name) != NULL, name, "no inline call loops", "src/bench/bench_calls.c");
}

static void check_indep(const char *name)
{
	size_t i;
	int found = 0;
	for (i = 0; i < NT; i++)
		found |= strcmp(T[i].name, name) == 0;
	part(found, name, "no independent transliteration", "tests/indep.h, tests/indep_table.h");
}

/* The branch rule, the MPFR formula and the fast reference of kernel k in
   precision p, on every input; reffast must decide at least one. */
static void check_reference(const study_kernel *k, int p, ref_ctx *rc, reffast_ctx *fc)
{
	static const double loc[3] = { 0.6, 0.0, 0.8 };
	int branch_ok = 1, mpfr_ok = 1, decided = 0;
	size_t i, j;
	for (i = 0; i < NIN; i++) {
		double n[3];
		sample_metrics s;
		for (j = 0; j < 3; j++)
			n[j] = p == PREC_FLOAT ? (double)(float)inputs[i][j] : inputs[i][j];
		branch_ok &= k->branch(k, p, n) >= 0;
		ref_eval(rc, k, p, n, loc, 0, &s);
		for (j = 0; i >= NGENERIC && j < (k->m ? 6u : 3u); j++)
			mpfr_ok &= !isnan(s.ref[j]);
		if (fc)
			decided += reffast_eval(fc, k, p, n, loc, 0, &s) != REFFAST_MPFR;
	}
	part(branch_ok, k->name, "no branch rule for its family", k->fam->name);
	part(mpfr_ok, k->name, "no MPFR formula for its family", k->fam->name);
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
		if (kernel_runs(&k, p))
			check_reference(&k, p, rc, fc);
}

int main(void)
{
	ref_ctx *rc = ref_new(127);
	const char *why = "";
	reffast_ctx *fc = reffast_usable(127, &why) ? reffast_new(127) : NULL;
	size_t i, ny;
	const bench_yardstick *y = bench_yardsticks(&ny);
	if (!rc) {
		printf("test_parts: out of memory\n");
		return 2;
	}
	if (!fc)
		printf("test_parts: note: the fast reference is not usable here (%s): its part is not checked\n", why);
	for (i = 0; i < NLISTED; i++) {
		if (strcmp(listed[i], "frisvad_rotate") != 0) {
			check_registry(listed[i]);
			check_indep(listed[i]);
			part(cm_find(listed[i]) != NULL, listed[i], "no rounding model (certify skips it)", "its family file's model");
		}
		check_study(listed[i], rc, fc);
	}
	for (i = 0; i < ny; i++)
		part(onb_find(y[i].name) != NULL, y[i].name, "a yardstick of no registry method", "src/bench/yardstick.c");
	ref_free(rc);
	reffast_free(fc);
	printf("test_parts: %zu methods; %d passed, %d failed\n", NLISTED, passed, failed);
	return failed ? 1 : 0;
}
