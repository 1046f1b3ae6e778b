/*
 * models.h - the rounding model of each registry method (models.c): its
 * family's model (src/families/), run with the method's registry row.
 */
#ifndef ONB_CERTIFY_MODELS_H
#define ONB_CERTIFY_MODELS_H

#include "libonb/onb.h"
#include "model/model.h"
#include "families/family.h"

typedef struct {
	const onb_method *m;       /* the registry row: the model's parameters   */
	const study_family *fam;   /* its family, whose model it runs            */
	int nbranch;               /* branch points: paths are 2^nbranch         */
	/* The defect quantities (CQ_ bits of model_int.h) that stay 0 in exact
	   arithmetic for every n, unit or not (b2 = n x b1 is orthogonal to n
	   and b1 whatever |n| is): where n is not unit at e = 0 (n.z given,
	   mvf_box.has_zpoint) only the others need their centre Q(U, 0). */
	unsigned zero_any_n;
	int contract;              /* the model of the --fma copy (cm_find_fma)  */
	/* frisvad_rotate: the model is the basis its kernel forms on the way
	   (m is NULL), and what is bounded is the direction error of
	   w = x b1 + y b2 + z n, not the basis's defect (bound.c). */
	int direction;
} cm_method;

/* The model of registry method `name` or of frisvad_rotate, or NULL. */
const cm_method *cm_find(const char *name);
/* The model of the method's --fma copy (its kernel compiled with -mfma
   -ffp-contract=fast: GCC fuses some a*b + c into one rounding), or NULL
   where no contracted model has been written and checked bit for bit
   against that copy: its family's fma_model, family.h). */
const cm_method *cm_find_fma(const char *name);
/* The i-th registry method (in the registry's order) that has a contracted
   model, or NULL past the last. */
const char *cm_fma_name(size_t i);
/* The kernel's operations on n, writing b1 (out[0..2]) and b2 (out[3..5])
   in precision P (PREC_FLOAT, PREC_DOUBLE or PREC_HALF). */
void cm_run(cm *c, const cm_method *m, int P, const cv n[3], cv out[6]);

#endif
