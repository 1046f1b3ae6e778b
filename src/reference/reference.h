/*
 * reference.h - the MPFR reference and the per-input metrics.
 *
 * src/reference/ holds what every figure is measured against: the MPFR
 * reference and the accuracy floor (reference.c), and the certified fast
 * reference in pairs of long doubles and of doubles (reffast.c, compiled a
 * second time as reffast_f.c; reffast.h), which writes MPFR's bytes and
 * asks MPFR where it cannot decide.  It imports methods/ (the kernels and
 * their branches) and nothing above it.
 *
 * For one kernel, one precision and one input n (the exact binary value
 * the kernel received), ref_eval runs the kernel and measures, in MPFR at
 * the context's precision (never MPFR's default precision):
 *   - the orthonormality defect from the rounded outputs and n:
 *     |b1|-1, |b2|-1, b1.n, b2.n, b1.b2 (against n/|n| when asked);
 *   - the forward error against the kernel's own formula evaluated exactly
 *     on the same input along the same branch: ulps of the exact value,
 *     absolute error in units of the format's epsilon, Herbie's bits;
 *   - det(b1, b2, n) against the registry's handedness, non-finite output;
 *   - the direction error of w = x b1 + y b2 + z n for a local direction
 *     (x, y, z): | |w| - 1 | and | w.n - z |;
 *   - the accuracy floor: the defect and direction error of the exact
 *     formula rounded once to the format (reference.c, floor_eval).
 * Each thread owns one ref_ctx.
 */
#ifndef ONB_REFERENCE_H
#define ONB_REFERENCE_H

#include <mpfr.h>
#include <stdint.h>
#include <string.h>
#include "methods/kernels.h"

typedef struct ref_ctx ref_ctx;

ref_ctx *ref_new(mpfr_prec_t prec);  /* NULL on allocation failure */
void ref_free(ref_ctx *c);
mpfr_prec_t ref_prec(const ref_ctx *c);

enum { DEF_N1 = 0, DEF_N2, DEF_D1N, DEF_D2N, DEF_D12, NDEF };

typedef struct {
	int branch;          /* branch id the kernel took (its family's rule)       */
	int stratum;         /* the input's stratum (inputs.h), set by the engine    */
	int nonfinite;       /* an output was NaN or infinite: no other metric       */
	int wrong_hand;      /* det(b1, b2, n) * handedness <= 0                     */
	int has_basis;       /* 0 for frisvad_rotate (direction metrics only)        */
	double in_norm;      /* |n| - 1 of the input as received                     */
	double d[NDEF];      /* the five defects, signed                             */
	double defect;       /* max |d[k]|: the per-input error                      */
	double sumsq;        /* sum of d[k]^2: the RMSE term of Frisvad's Table 1    */
	double ulp_max;      /* forward error in ulps, components with |exact| >= eps */
	double abs_eps_max;  /* forward error / eps, every component                 */
	double bits_sum;     /* Herbie bits, summed over the components with |exact| >= eps */
	int    nbits;        /* how many components that is                          */
	double bits_max;
	int    ncomp;        /* number of output components (6, or 3 for rotate)     */
	double det;
	double dir_norm;     /* | |w| - 1 |                                          */
	double dir_cos;      /* | w.n - z |                                          */
	double out[6];       /* the kernel's outputs b1, b2 (or w), widened          */
	double ref[6];       /* the exact formula, rounded to double                 */
	double w[3];         /* the rotated direction (format precision)             */
	/* The accuracy floor: the same metrics for the exact formula
	   (the family's, on the kernel's branch) rounded once to the format.
	   NaN where the exact formula is not finite. */
	double floor;          /* its defect (max |.| of the five)                   */
	double floor_dir_norm; /* | |w|-1 | of its direction                         */
	double floor_dir_cos;  /* | w.n - z | of its direction                       */
	double floor_ratio;    /* max(e, u^2) / max(f, u^2): e the per-input error
	                          (defect; frisvad_rotate: max of the direction
	                          errors), f the floor's, u = 2^-24 or 2^-53; NaN
	                          when either is not finite                       */
} sample_metrics;

/* Evaluate kernel k on n (values exactly representable in `prec`) with the
   local direction loc; normalize_n measures the defects against n/|n|. */
void ref_eval(ref_ctx *c, const study_kernel *k, int prec, const double n[3],
              const double loc[3], int normalize_n, sample_metrics *s);

/* ref_eval's first half, shared with the fast reference (reffast.c): n =
   n_in as the kernel receives it (rounded to `prec`), s cleared with its
   branch, the kernel's outputs s->out (6, or 3 for a rotation) and the
   direction through its basis with loc, s->w. */
void ref_run_kernel(const study_kernel *k, int prec, const double n_in[3], const double loc[3],
                    double n[3], sample_metrics *s);

/* The five defects of the basis b = (b1, b2) for the input n, all doubles:
   |b1|-1, |b2|-1, b1.n, b2.n, b1.b2, each to 2^-50 relative or better. */
void ref_defects(ref_ctx *c, const double n[3], const double b[6], double d[NDEF]);

/* From s->d and s->out: defect (max |d|), sumsq, det(b1, b2, n) in long
   double and wrong_hand, as ref_eval sets them (shared with reffast.c). */
void ref_defect_summary(const study_kernel *k, const double n[3], sample_metrics *s);

/* Representable values of the format (PREC_FLOAT, PREC_DOUBLE or PREC_HALF) between
   a and b: the forward error in "bits" counts them. */
static inline double ref_float_distance(double a, double b, int prec)
{
	if (prec == PREC_HALF) {   /* binary16 values: encodings' magnitudes, signed */
		const uint16_t ua = prec_half_bits(a), ub = prec_half_bits(b);
		const int32_t oa = (ua >> 15) ? -(int32_t)(ua & 0x7fffu) : (int32_t)ua;
		const int32_t ob = (ub >> 15) ? -(int32_t)(ub & 0x7fffu) : (int32_t)ub;
		return (double)(oa > ob ? oa - ob : ob - oa);
	}
	if (prec == PREC_FLOAT) {
		float fa = (float)a, fb = (float)b;
		uint32_t ua, ub;
		int64_t oa, ob;
		memcpy(&ua, &fa, 4);
		memcpy(&ub, &fb, 4);
		oa = (ua >> 31) ? -(int64_t)(ua & 0x7fffffffu) : (int64_t)ua;
		ob = (ub >> 31) ? -(int64_t)(ub & 0x7fffffffu) : (int64_t)ub;
		return (double)(oa > ob ? oa - ob : ob - oa);
	} else {
		uint64_t ua, ub, ma, mb;
		memcpy(&ua, &a, 8);
		memcpy(&ub, &b, 8);
		ma = ua & 0x7fffffffffffffffu;
		mb = ub & 0x7fffffffffffffffu;
		if ((ua >> 63) != (ub >> 63))
			return (double)ma + (double)mb;
		return (double)(ma > mb ? ma - mb : mb - ma);
	}
}

/* 1 when two evaluations of the same input (at different MPFR precisions)
   agree in every reported metric to a relative 2^-40; else 0 and a
   description in why. */
int ref_agree(const sample_metrics *a, const sample_metrics *b, char *why, size_t n);

#endif
