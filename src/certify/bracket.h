/*
 * bracket.h - what one region's bracket is asked (cert_opts, with the
 * inputs its found side starts from) and what it answers (cert_result):
 * shared by the branch and bound (search.c) and the found side (found.c).
 */
#ifndef ONB_CERTIFY_BRACKET_H
#define ONB_CERTIFY_BRACKET_H

#include <stdint.h>
#include "model/mvf.h"

enum { CERT_PROVEN = 0, CERT_SINGULAR, CERT_BUDGET,
       CERT_UNBOUNDED /* --arith: an operation's allowance gives no bound (cert_result.unb_op) */ };

/* The found side's best inputs a region keeps for the images pass
   (found_images.c). */
#define CERT_KEEP 8

/* An input the found side starts a walk from (--starts): another run's
   worst input of a method, for one precision (-1: either). */
typedef struct {
	char method[48];
	int prec;
	double n[3];
	int has_loc;        /* frisvad_rotate's found local direction, when given */
	double loc[3];
} cert_start;

typedef struct {
	long budget;        /* boxes bounded per region at most                    */
	long samples;       /* kernel inputs sampled per region before the boxes   */
	double target;      /* proven when bound <= target * found (1.25)          */
	double tolerance;   /* < 0: the default domain                             */
	uint64_t seed;
	/* Called with every leaf of the branch and bound and its bound, when
	   set (tests: every input of the region lies in some leaf). */
	void (*leaf_fn)(void *arg, const mvf_box *b, double bound);
	void *leaf_arg;
	const cert_start *starts;   /* walks also start from these (those of the */
	long nstarts;               /* kernel, precision and region)            */
	/* The arithmetic profile (src/model/arith.h; NULL: ieee): the bound
	   holds for every result it allows at every operation, and the found
	   side also takes the adversarial emulation's worst at the region's
	   best inputs (src/certify/emulate.c). */
	const arith_profile *arith;
} cert_opts;

/* The phases of a region's bracket whose CPU time is kept (certify's
   profile: stderr and certify-times.csv, never certify.csv's rows). */
enum { CERT_T_SAMPLE = 0, CERT_T_WALKS, CERT_T_BOXES, CERT_T_PROBES, CERT_T_IMAGES, CERT_T_REFINE, CERT_NT };

typedef struct {
	double bound;       /* certified: no input of the region exceeds it (+inf: none) */
	double found;       /* the largest defect measured on an input of the region */
	double found_n[3];  /* that input (in the format)                          */
	double found_loc[3]; /* frisvad_rotate: its local direction (x, y, z)     */
	int status;         /* CERT_*                                              */
	int nonfinite;      /* a sampled input gave a non-finite output            */
	long boxes;
	long probes;        /* inputs of the region the found side evaluated      */
	double keep_n[CERT_KEEP][3];   /* its best inputs by screened defect, largest first */
	int nkeep;
	double cpu[CERT_NT]; /* CPU seconds per phase: sampling, walks, bounding boxes,
	                        the probes of the branch and bound, images, refinement */
	int unb_op;         /* --arith: the operation (AR_*) that left it unbounded, -1 */
} cert_result;

/* An input of the images pass's pool; sure: known to be in the domain. */
typedef struct {
	double n[3];
	int sure;
} cert_pool_in;

#endif
