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

/* The methods whose models follow GCC's contraction of their kernels
   (MADD and ADDM in the family's model, where the --fma copy fuses):
   tests/test_certify.c checks each against that copy bit for bit.  The
   others have none (docs/certify.md says why). */
const char *const cm_fma_names[] = { "duff_branchless", "duff", "frisvad", "frisvad_max", "pbrt_v3", "hughes_moeller", "stark", "stark_fixed", "rtow",
	"naive", "naive_invsqrt", "naive_rsqrt", "naive_rsqrt_nr", "naive_nonorm", "hughes_moeller_invsqrt", "hughes_moeller_rsqrt",
	"hughes_moeller_rsqrt_nr", "hughes_moeller_nonorm", "q2rtx", "filament", "jolt_fma", "duff_wide", "duff_comp", "bullet", "eigen", "rp3d", "jolt", "luxcore", "physx", "physx_fixed", "mujoco", "embree", "cycles_cross111", "cycles_cross111_avx2", "tangent_cross_z", "open3d", "open3d_fixed", "mitsuba3", "filament_fixed", "luxcore_fixed", NULL };

static int fma_modelled(const char *name)
{
	int i;
	for (i = 0; cm_fma_names[i]; i++)
		if (strcmp(cm_fma_names[i], name) == 0)
			return 1;
	return 0;
}

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
		table_fma[ntable].contract = fma_modelled(ms[i].name);
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

void cm_run(cm *c, const cm_method *m, int P, const cv n[3], cv out[6])
{
	c->contract = m->contract;
	if (P == PREC_HALF && c->backend == CM_MVF) {  /* no proof model of binary16 yet (model.h) */
		c->failed = 1;
		return;
	}
	m->fam->model(c, P, m->m, n, out);
}
