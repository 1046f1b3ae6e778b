/*
 * families.c - the one list of the study's formula families (family.h),
 * and the lookups through it.  The list, STUDY_FAMILY_LIST(X), is given on
 * the compiler's command line by scripts/family-list.sh (the Makefile,
 * scripts/fuzz.sh): X(NAME) for each `const study_family family_NAME`
 * that a file in src/families/ defines.  A new family is its definition,
 * with no entry to add here.
 */
#include <string.h>
#include "families/family.h"

#ifndef STUDY_FAMILY_LIST
#error "families.c: compile with -DSTUDY_FAMILY_LIST(X)=\"$(sh scripts/family-list.sh)\" (the Makefile does)"
#endif

#define FAMILY_EXTERN(f) extern const study_family family_##f;
STUDY_FAMILY_LIST(FAMILY_EXTERN)
#undef FAMILY_EXTERN

static const study_family *const families[] = {
#define FAMILY_ENTRY(f) &family_##f,
	STUDY_FAMILY_LIST(FAMILY_ENTRY)
#undef FAMILY_ENTRY
};

const study_family *const *family_all(size_t *count)
{
	*count = sizeof families / sizeof families[0];
	return families;
}

/* The registry row names its family; the list is searched for it, so a
   family is known by being listed, and nowhere else by its name. */
const study_family *family_of(const onb_method *m)
{
	size_t i;
	if (!m)
		return &family_frisvad_rotate;
	for (i = 0; i < sizeof families / sizeof families[0]; i++)
		if (strcmp(families[i]->name, m->family) == 0)
			return families[i];
	return NULL;
}

const study_family *family_rotate(void) { return &family_frisvad_rotate; }

int family_no_variant(const onb_method *m) { (void)m; return 0; }
int family_no_exact_zero(const onb_method *m, int br) { (void)m; (void)br; return -1; }
const char *family_no_singular(const onb_method *m) { (void)m; return "none"; }
int family_meets_none(const onb_method *m, double nz_lo, double nz_hi, double phi_lo, double phi_hi)
{
	(void)m; (void)nz_lo; (void)nz_hi; (void)phi_lo; (void)phi_hi;
	return 0;
}
int family_fma_model(const onb_method *m) { (void)m; return 1; }
int family_no_fma_model(const onb_method *m) { (void)m; return 0; }
