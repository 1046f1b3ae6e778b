/*
 * certify_half.h - `onbstudy certify --precision half` (certify_half.c):
 * per region of the sphere, each method's proven defect bound in binary16
 * beside the largest defect of a scan of the region's binary16 inputs.
 */
#ifndef ONB_CERTIFY_HALF_H
#define ONB_CERTIFY_HALF_H

#include "bound.h"
#include "region.h"
#include "methods/kernels.h"

/* A region's status in binary16. */
enum {
	CH_PROVEN = 0,   /* a finite bound                                           */
	CH_NONFINITE,    /* the scan found an input whose half basis has a NaN or an
	                    infinity: no finite bound exists, and none is printed    */
	CH_OVERFLOW,     /* no bound: some value of the model may exceed 65504        */
	CH_UNBOUNDED     /* no bound: an enclosure reaches a division by 0 or a
	                    square root's pole (underflow of a squared length near a
	                    pole, or a box too wide at the depth allowed)             */
};
const char *ch_status_name(int s);

typedef struct {
	double bound;          /* proven: no input of the region exceeds it (inf: none) */
	double found;          /* the scan's largest defect (inf: a non-finite basis)   */
	double worst[3];       /* its input                                             */
	long scanned, nonfinite;
	int status;
	int unb_op;            /* --arith: why it is unbounded (arith.h's causes:
	                          the operation the profile gives no bound, or the
	                          operation whose enclosure was lost, with
	                          AR_AT_POLE or AR_OVERFLOW), CH_BELOW_SCAN, or -1 */
} ch_result;
/* unb_op of a bound below the scan's defect (no proof: the model's paths
   miss the kernel's), named "below-scan" */
#define CH_BELOW_SCAN 0x800

/* The scan: every binary16 n.z of the region's band at az azimuths per
   sector (the other two components the binary16 roundings of
   r cos phi, r sin phi, so every input is the rounding of a unit vector),
   and 2048 az inputs derived from (x, y) in the region's ring (ch_ring:
   y often drawn by its encoding, so subnormal and underflowing components
   come up), n.z the rounding of the unit vector's.  The defect of each half basis in
   double; the largest one's again in MPFR (ref_defects). */
double ch_scan(const study_kernel *k, const cert_region *r, int az, double worst[3], long *count, long *nonfinite);

/* The bound over region r: bound_box over its box, and where that is above
   target, the larger of its two halves' (n.z, then the azimuth, in turn),
   down to `depth` halvings; the smaller of the two. */
double ch_bound(bound_ctx *b, const cm_method *m, const cert_region *r, double target, int depth);

/* Both, and the status (b's profile, bound_set_arith, reset here). */
void ch_region(bound_ctx *b, const study_kernel *k, const cm_method *m, const cert_region *r, int depth, int az,
               ch_result *out);

/* The command, after certify's option parsing (certify.c): 0, 1 or 2. */
typedef struct {
	const char *methods, *out;
	int sectors, depth, az, quiet, band;
	double band_lo, band_hi;
	const arith_profile *arith;   /* --arith other than ieee, or NULL */
	const char *resume;     /* --resume DIR (out is DIR too): checkpoint, keys */
	double every;           /* --checkpoint-every S */
} ch_opts;
int cert_half_run(const ch_opts *o);

#endif
