/*
 * models.c - each registry method's rounding model: its family's model
 * (src/families/), with the method's parameters from its registry row.
 */
#include <stddef.h>
#include "certify/models.h"

#define CM_ONE(m) + 1
enum { CM_NMETHODS = 0 ONB_METHOD_LIST(CM_ONE) ONB_FLOAT_METHOD_LIST(CM_ONE) };
#undef CM_ONE

/* Filled on the first call (callers may be threads: under a lock). */
static cm_method table[CM_NMETHODS];
static size_t ntable;
static int filled;

static void fill(void)
{
	size_t i, n;
	const onb_method *ms = onb_methods(&n);
	for (i = 0; i < n && ntable < CM_NMETHODS; i++) {
		const study_family *f = family_of(&ms[i]);
		if (!f || !f->model)
			continue;
		table[ntable].m = &ms[i];
		table[ntable].fam = f;
		table[ntable].nbranch = f->model_branches;
		table[ntable].zero_any_n = f->zero_any_n(&ms[i]);
		ntable++;
	}
	filled = 1;
}

const cm_method *cm_find(const char *name)
{
	const onb_method *m = onb_find(name);
	const cm_method *r = NULL;
	size_t i;
	if (!m)
		return NULL;
#pragma omp critical(cm_find)
	{
		if (!filled)
			fill();
		for (i = 0; i < ntable; i++)
			if (table[i].m == m)
				r = &table[i];
	}
	return r;
}

void cm_run(cm *c, const cm_method *m, int P, const cv n[3], cv out[6])
{
	m->fam->model(c, P, m->m, n, out);
}
