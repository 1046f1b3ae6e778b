/*
 * family.h - what the study knows about one formula family: everything
 * but the kernel (include/libonb/onb.h) and the method's parameters (its
 * registry row, src/lib/registry.c).  One file per family in
 * src/families/ fills one study_family (or more: stark.c has two);
 * families.c lists them all, from the files (scripts/family-list.sh).
 *
 * A family file is compiled four times (the Makefile, FAMILY_PASS):
 *   0  the study's build: the branch rule, the MPFR formula, the rounding
 *      model, the singular set, branch names, and the struct;
 *   1  the branch rule again with FMA contraction, for the --fma copies
 *      (rtow's branch depends on rounded intermediates);
 *   2  the fast reference's formula in pairs of doubles (float inputs);
 *   3  the same formula in pairs of long doubles (double inputs).
 * Passes 2 and 3 are built with the fast reference's flags (-mfma on
 * x86-64), so the formula's bits are the fast reference's.
 *
 * The families import the kits below them (the MPFR kit, the pair kit,
 * the model kit) and libonb; nothing in the kits imports a family.
 * Method parameters (thresholds, normalizations) are read from the
 * registry row m, never copied here.
 */
#ifndef ONB_FAMILIES_FAMILY_H
#define ONB_FAMILIES_FAMILY_H

#include <stddef.h>
#include <mpfr.h>
#include "libonb/onb.h"
#include "common/prec.h"
#include "arith/mpfr_kit.h"
#include "arith/pair.h"

typedef int (*family_branch_fn)(const onb_method *m, int prec, const double n[3]);
/* The exact formula along branch br on n, into b1 and b2 (for
   frisvad_rotate, m = NULL: the direction loc, rotated, into b1). */
typedef void (*family_mpfr_fn)(mpfr_kit *c, const onb_method *m, int br, const double loc[3],
                               mpfr_t *n, mpfr_t *b1, mpfr_t *b2);
/* The same formula in the fast reference's pairs; *bad set when a bound
   cannot be kept (then MPFR decides). */
typedef void (*family_pair_d_fn)(const onb_method *m, int br, const double loc[3], const xv_pd *n,
                                 xv_pd *b1, xv_pd *b2, int *bad);
typedef void (*family_pair_l_fn)(const onb_method *m, int br, const double loc[3], const xv_pl *n,
                                 xv_pl *b1, xv_pl *b2, int *bad);
/* The kernel's operations as a rounding model (src/model/model.h: the
   context cm, value handles cv, which are ints): b1 into out[0..2], b2
   into out[3..5], in precision P (PREC_FLOAT, PREC_DOUBLE).  Spelled without the
   model's names, which the rooms that only evaluate need not see. */
struct cm;
typedef void (*family_model_fn)(struct cm *c, int P, const onb_method *m, const int n[3], int out[6]);

typedef struct study_family {
	const char *name;            /* onb_method.family of its methods            */
	family_branch_fn branch;     /* the branch the kernel takes on n (>= 0)     */
	family_branch_fn branch_fma; /* the same, compiled with FMA contraction     */
	/* What branch b means, in words (onbstudy eval); buf may be used. */
	const char *(*branch_name)(const onb_method *m, int b, char *buf, size_t n);
	family_mpfr_fn mpfr;
	family_pair_d_fn pair_d;
	family_pair_l_fn pair_l;
	/* The parameter of m the formula's value depends on (beside the branch):
	   two methods with the same family, branch and variant share the
	   fast reference's evaluation of it on an input. */
	int (*variant)(const onb_method *m);
	/* The output component (0..5) identically zero in exact arithmetic
	   on branch br, for any n, where the MPFR formula leaves a rounding
	   residue; -1 for none. */
	int (*exact_zero)(const onb_method *m, int br);
	family_model_fn model;       /* frisvad_rotate's: the basis it forms    */
	int model_branches;          /* branch points of the model: 2^k paths       */
	/* The defect quantities (CQ_ bits) that stay 0 in exact arithmetic for
	   every n, unit or not (see model_kit.h). */
	unsigned (*zero_any_n)(const onb_method *m);
	/* The unit inputs where the kernel can return NaN or inf (certify does
	   not bound them), in words, and whether a region of n.z in
	   [nz_lo, nz_hi], azimuth in [phi_lo, phi_hi] degrees, meets them. */
	const char *(*singular)(const onb_method *m);
	int (*meets_singular)(const onb_method *m, double nz_lo, double nz_hi, double phi_lo, double phi_hi);
	/* Whether the model of m is also its --fma copy's (the kernel compiled
	   with -mfma -ffp-contract=fast, where GCC fuses some a*b + c): 1 where
	   MADD, ADDM, SUBM and MSUB under c->contract mark exactly the products
	   GCC fuses (or the kernel has none), so certify --fma bounds the copy
	   and tests/test_certify.c checks the model against it bit for bit;
	   0 where no contracted model is written (certify --fma then writes no
	   METHOD+fma rows).  Every family says which (family_fma_model,
	   family_no_fma_model or its own rule); NULL counts as 1, so a family
	   that forgets is checked, not skipped. */
	int (*fma_model)(const onb_method *m);
} study_family;

/* The family of registry method m (its `family` field), or NULL when no
   family file knows it; family_rotate() is frisvad_rotate's. */
const study_family *family_of(const onb_method *m);
const study_family *family_rotate(void);
/* Every family, in the order of scripts/family-list.sh's list. */
const study_family *const *family_all(size_t *count);

/* ---- what a family file uses ---- */
#ifndef FAMILY_PASS
#define FAMILY_PASS 0
#endif
#define FAMILY_MAIN_PASS (FAMILY_PASS == 0)
#define FAMILY_RULE_PASS (FAMILY_PASS <= 1)
#define FAMILY_PAIR_PASS (FAMILY_PASS >= 2)
#if FAMILY_PASS == 1
#define FAMILY_BRANCH(f) f##_branch_fma
#else
#define FAMILY_BRANCH(f) f##_branch
#endif
#if FAMILY_PASS == 2
#define REFFAST_PAIR_DOUBLE 1
#define FAMILY_PAIR(f) f##_pair_d
#else
#define FAMILY_PAIR(f) f##_pair_l
#endif
#if FAMILY_PAIR_PASS
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wunused-function" /* the kit's helpers this formula does not need */
#endif
#include "arith/pair_kit.h"
#endif

/* The functions of family f the other passes define, for its struct. */
#define FAMILY_DECLARE(f) \
	int f##_branch(const onb_method *m, int prec, const double n[3]); \
	int f##_branch_fma(const onb_method *m, int prec, const double n[3]); \
	void f##_pair_d(const onb_method *m, int br, const double loc[3], const xv_pd *n, xv_pd *b1, xv_pd *b2, int *bad); \
	void f##_pair_l(const onb_method *m, int br, const double loc[3], const xv_pl *n, xv_pl *b1, xv_pl *b2, int *bad)
#define FAMILY_PASSES(f) f##_branch, f##_branch_fma
#define FAMILY_PAIRS(f) f##_pair_d, f##_pair_l

/* The common answers. */
int family_no_variant(const onb_method *m);
int family_no_exact_zero(const onb_method *m, int br);
const char *family_no_singular(const onb_method *m);
int family_meets_none(const onb_method *m, double nz_lo, double nz_hi, double phi_lo, double phi_hi);
int family_fma_model(const onb_method *m);
int family_no_fma_model(const onb_method *m);

#endif
