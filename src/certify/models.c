/*
 * models.c - each registry method's rounding model: its family's model
 * (src/families/), with the method's parameters from its registry row.
 */
#include <stddef.h>
#include <string.h>
#include "certify/models.h"
#include "model/model_int.h"
#include "methods/kernels.h"

#define CM_ONE(m) + 1
enum { CM_NMETHODS = 0 ONB_METHOD_LIST(CM_ONE) ONB_FLOAT_METHOD_LIST(CM_ONE) };
#undef CM_ONE

/* Filled on the first call (callers may be threads: under a lock). */
static cm_method table[CM_NMETHODS], table_fma[CM_NMETHODS];
static size_t ntable;
/* frisvad_rotate: no registry row, its family's model, the direction. */
static cm_method rotate;
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
		table_fma[ntable] = table[ntable];
		table_fma[ntable].contract = !f->fma_model || f->fma_model(&ms[i]);
		ntable++;
	}
	rotate.fam = family_rotate();
	rotate.nbranch = rotate.fam->model_branches;
	rotate.direction = 1;
	filled = 1;
}

const cm_method *cm_find(const char *name)
{
	const onb_method *m = onb_find(name);
	const cm_method *r = NULL;
	size_t i;
	const int rot = !m && kernels_direction(name) != NULL;
	if (!m && !rot)
		return NULL;
#pragma omp critical(cm_find)
	{
		if (!filled)
			fill();
		for (i = 0; i < ntable; i++)
			if (table[i].m == m)
				r = &table[i];
		if (rot)
			r = &rotate;
	}
	return r;
}

const cm_method *cm_find_fma(const char *name)
{
	const cm_method *m = cm_find(name);
	/* frisvad_rotate's model lies outside the tables, and has no contracted twin */
	return m && !m->direction && table_fma[m - table].contract ? &table_fma[m - table] : NULL;
}

const char *cm_fma_name(size_t i)
{
	const char *r = NULL;
	size_t k;
#pragma omp critical(cm_find)
	{
		if (!filled)
			fill();
		for (k = 0; k < ntable && !r; k++)
			if (table_fma[k].contract && i-- == 0)
				r = table_fma[k].m->name;
	}
	return r;
}

void cm_run(cm *c, const cm_method *m, int P, const cv n[3], cv out[6])
{
	c->contract = m->contract;
	m->fam->model(c, P, m->m, n, out);
}
