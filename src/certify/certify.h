/*
 * src/certify/ - proven extremes.  For every method, precision
 * and region of the sphere, `onbstudy certify` brackets the largest
 * orthonormality defect between an input found (search.c) and a bound no
 * input can exceed: each kernel's operations written once more as a model
 * (its family's model, src/families/, bit-exact to the kernel:
 * tests/test_certify.c), evaluated in a mean value form over MPFI
 * intervals (src/model/mvf.c, bound.c), by branch and
 * bound over boxes of the sphere (search.c, regions.c).  seeds.c bounds the
 * approximate reciprocal square roots; scene_cert.c answers for a scene.
 *
 * certify.h - the command.
 */
#ifndef ONB_CERTIFY_CERTIFY_H
#define ONB_CERTIFY_CERTIFY_H

#include "bracket.h"
#include "probe.h"

int cmd_certify(int argc, char **argv);

/* The distribution of certify's passes over processes: `onbstudy-mpi
   certify` (src/mpi/certify_mpi.c) sets cert_distribute before it calls
   cmd_certify on every rank; NULL (onbstudy) runs every task here.

   Every rank runs cmd_certify in step: the same tasks, the same passes
   (the first pass, the images pass, the refinement's rounds).  In a pass,
   dist->run hands each task j that is not done (flags[i] & flag, i =
   pick[j] or j) to some rank's thread, which calls fn(x, j, arg) there
   (its result lands in res[i]); rank 0 gets every result and commits it
   (commit: the results, the checkpoint, as onbstudy does), and at the
   end of the pass every rank gets rank 0's res, flags and *failed, so
   that the next pass starts from the same state everywhere.  Rank 0
   alone writes files and speaks. */
typedef struct {
	int n;                       /* the pass's tasks j = 0..n-1           */
	const int *pick;             /* task j's region task: pick[j] (NULL: j) */
	int flag;                    /* CK_RUN, CK_IMAGES, CK_REFINED          */
	void (*fn)(cert_ctx *x, int j, void *arg);
	void *arg;
	void (*commit)(void *arg, int i, const cert_result *r);   /* rank 0 */
	cert_result *res;            /* every region task's result [nres]     */
	unsigned char *flags;        /* every region task's CK_* [nres]       */
	int nres;
	int *failed;                 /* rank 0: a checkpoint failed, stop     */
} cert_pass;

typedef struct {
	int rank;                    /* 0: writes the files and speaks        */
	int (*run)(const cert_pass *p);          /* 0, or -1 (every rank)   */
	void (*share)(void *p, size_t n);        /* rank 0's bytes to all   */
	int (*agree)(int rc);                    /* the largest rc of all   */
	const char *note;            /* provenance: "mpi: N ranks x T threads" */
} cert_dist;

extern const cert_dist *cert_distribute;

/* onbstudy-mpi's rank 0, when the job is being ended (a rank died, mpirun
   was stopped).  cert_stop: no result is committed after it; into v the
   directory of the checkpoint (the --resume DIR, or else the run's
   output directory, which --resume DIR then continues) and the region
   tasks with a result of each pass; 0, or 1 when no run is under way.
   cert_stop_save then writes the checkpoint of every result committed
   (no write when the last checkpoint already holds them all, as with
   --checkpoint-every 0: nothing for mpirun's SIGKILL to cut short):
   0 written or current, -1 not (a message said why; the last one, if
   any, is intact), 1 no run under way. */
typedef struct {
	char dir[4096];
	int nt, run, images, refined;
	int resume;                  /* the run has --resume DIR */
} cert_saved;
int cert_stop(cert_saved *v);
int cert_stop_save(void);
/* Region task i of the run under way, named: its method, precision,
   region number and bounds ("" when no run is under way). */
void cert_task_name(int i, char *buf, size_t cap);

#endif
