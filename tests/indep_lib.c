/*
 * indep_lib.c - the method table of tests/test_indep.c in a file of its
 * own, for scripts/mutate.sh: each mutant of include/libonb/onb.h rebuilds only
 * this file and links it with the test's driver, compiled once
 * (-DINDEP_SPLIT).  Not part of `make test`, which builds test_indep.c whole.
 */
#include "libonb/onb.h"
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wunused-function" /* indep.h: only its table is used here */
#endif
#define INDEP_TABLE_DEFINE
#include "indep.h"

const indep_row *indep_rows(size_t *n);
const indep_row *indep_rows(size_t *n)
{
	*n = NT;
	return T;
}
