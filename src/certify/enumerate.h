/*
 * enumerate.h - soundness data for certify: every float input
 * of the default domain (region.h) inside a small box, and each method's
 * largest defect over them, measured by cert_probe (search.h) as
 * `onbstudy eval` measures it.  A certified bound for a region holding a
 * box must never be below the box's maximum (tests/test_enumerate.c).
 *
 * A box fixes float ranges of two components and completes the third
 * (`axis`) with every float that makes n a domain member: for each pair,
 * the runs of domain values of either sign (cert_f32_run, domain32.h), kept when
 * within [lo, hi] of that axis (a filter: a hemisphere, say).  The ranges
 * of the two fixed components are of consecutive floats; a range that
 * holds 0 holds both -0 and +0.
 */
#ifndef ONB_CERTIFY_ENUMERATE_H
#define ONB_CERTIFY_ENUMERATE_H

#include "methods/kernels.h"
#include "probe.h"
#include "domain32.h"
#include "regions.h"

typedef struct {
	const char *name;
	const char *why;      /* what the box is there to test                  */
	int axis;             /* the component completed into the domain        */
	double c[3];          /* centre of the two fixed ranges (floats)        */
	int half;             /* each fixed range: c -+ half floats             */
	double lo, hi;        /* filter on the completed axis                   */
} cert_box;

/* The built-in boxes (near -z: on frisvad's float threshold, the float
   below it, on frisvad_max's threshold, deeper in the band where frisvad
   fails; near +z; on hughes_moeller's |x| = |z|; at the n.z = 0 seam;
   near -x for naive; -x itself); their count in *count. */
const cert_box *cert_boxes(int *count);

/* Every domain input of box b, 3 doubles each, into a new array *out
   (free it); returns the count, or -1 after a message (out of memory,
   more than CERT_ENUM_MAX inputs, or an input that cert_in_domain does
   not confirm: each member is checked, and so is each run's first
   non-member on either end). */
#define CERT_ENUM_MAX 1000000LL
long long cert_box_inputs(const cert_box *b, double **out);

/* The region the inputs span: their n.z range and azimuth range (phi_hi
   just above the largest azimuth).  0, or -1 when the azimuths straddle 0. */
int cert_inputs_region(const double *in, long long count, cert_region *r);

typedef struct {
	double max;           /* the largest finite defect (-1 if none)       */
	double n[3];          /* its input                                    */
	long long inputs;     /* inputs evaluated                             */
	long long nonfinite;  /* of them, with a non-finite output            */
} cert_enum;

/* Kernel k (float) on the count inputs of in, each defect by cert_probe;
   d (NULL: not kept) receives each input's defect (+inf if non-finite).
   0, or -1 after a message (the kernel has no float code). */
int cert_enumerate(cert_ctx *x, const study_kernel *k, const double *in, long long count, double *d,
                   cert_enum *out);

#endif
