/*
 * kernels.h - what the study evaluates: every registry method as built
 * with the library's flags, optionally a second copy compiled with FMA
 * contraction (--fma), and Frisvad's Equation 3 (frisvad_rotate), which
 * rotates a direction instead of returning a basis.
 *
 * src/methods/ holds the study's side of each method: this kernel table
 * (kernels.c) and the FMA copy (fma_kernels.c); each kernel carries its
 * family (src/families/), whose branch rule the references follow.  Every
 * command that evaluates a method (sweep, eval, threshold, bench
 * --reference) goes through it; it imports libonb and the families (and
 * cli.h for its messages).
 */
#ifndef ONB_KERNELS_H
#define ONB_KERNELS_H

#include "libonb/onb.h"
#include "common/prec.h"
#include "families/family.h"

struct study_kernel;

typedef onb_vec3  (*rotate_fn) (onb_vec3  n, double x, double y, double z);
typedef onb_vec3f (*rotatef_fn)(onb_vec3f n, float x, float y, float z);

typedef struct study_kernel {
	char name[64];          /* registry name, "+fma" appended for FMA copies */
	const onb_method *m;    /* registry entry; NULL for frisvad_rotate       */
	const study_family *fam; /* family_of(m): frisvad_rotate's without m     */
	int fma;                /* compiled with -mfma -ffp-contract=fast        */
	onb_basis_fn  basis;    /* NULL for frisvad_rotate                       */
	onb_basisf_fn basisf;
	rotate_fn  rot;         /* frisvad_rotate only                           */
	rotatef_fn rotf;
	/* The branch the kernel takes on n (the family's rule).  For the FMA
	   copies it is the rule compiled with contraction, since rtow's
	   branch depends on rounded intermediates. */
	int (*branch)(const struct study_kernel *k, int prec, const double n[3]);
} study_kernel;

/* The study's kernels that rotate a direction instead of returning a
   basis: they have no libonb registry row (their study_kernel's m is
   NULL), so this list is their registry, named once here; kernels.c and
   fma_kernels.c make their rows from it (onb_NAME and onb_NAMEf, plain and
   contracted).  A kernel is a direction kernel by having a row here, and
   nowhere by its name. */
#define STUDY_DIRECTION_LIST(X) X(frisvad_rotate)

typedef struct {
	const char *name;
	rotate_fn   rot;        /* plain, with the library's flags */
	rotatef_fn  rotf;
} study_direction;

/* Every direction row (*count of them), and the one called name or NULL. */
const study_direction *kernels_directions(size_t *count);
const study_direction *kernels_direction(const char *name);

/* The most kernels a command selects at once (every registry method,
   frisvad_rotate and their FMA copies fit): the capacity of its tables. */
#define STUDY_MAX_KERNELS 256

/* Fill out[] (capacity cap) with the kernels named in the comma-separated
   list `names` (NULL or "all": every registry method and frisvad_rotate),
   plus FMA copies when fma != 0.  Returns the count, or -1 after a
   message naming the unknown method. */
int kernels_select(const char *names, int fma, study_kernel *out, int cap);

/* 0 when the kernel has no code in that precision: the float-only
   registry methods (ONB_FLOAT_ONLY, NULL basis) in double; in binary16
   every registry method with a half entry (onb_NAME_arrayh; none on a
   build without _Float16), not frisvad_rotate and not the FMA copies.
   Every loop over kernels and precisions skips those pairs. */
static inline int kernel_runs(const study_kernel *k, int prec)
{
	if (prec == PREC_HALF)
		return k->m && k->m->arrayh && !k->fma;
	return prec == PREC_FLOAT || !k->m || k->basis != NULL;
}
/* How many of the nk kernels run in precision prec. */
static inline int kernels_running(const study_kernel *k, int nk, int prec)
{
	int i, n = 0;
	for (i = 0; i < nk; i++)
		n += kernel_runs(&k[i], prec);
	return n;
}

/* Branch ids, plain arithmetic. */
int kernels_branch(const study_kernel *k, int prec, const double n[3]);

/* fma_kernels.c: 1 when the CPU can run the FMA copies. */
int fma_available(void);
/* The contracted copy of the method or direction kernel called name: its
   basis pointers, or its rotate pointers; -1 when there is none. */
int fma_lookup(const char *name, onb_basis_fn *basis, onb_basisf_fn *basisf, rotate_fn *rot, rotatef_fn *rotf);
int fma_branch(const study_kernel *k, int prec, const double n[3]);

#endif
