/*
 * ziv.h - Ziv's strategy for the roundings of the exact formula: each
 * output component X of a method's exact formula (its family's MPFR
 * formula, src/families/) rounded once to the format, to double, and
 * X - cv (cv the kernel's output) rounded to double, each decided by
 * raising the precision until every real the evaluation can stand for
 * rounds to one value (docs/reference.md, "Correct rounding", gives the
 * error estimate, the cap and why).
 *
 * reference.c evaluates the formula at its own precision p0 and hands
 * the values here; the levels above (p0 + 64 bits, then doubling) are
 * evaluated here, by the same family formula, only while a rounding is
 * undecided.  Precision-generic: a format is data (ref_format).
 */
#ifndef ONB_REFERENCE_ZIV_H
#define ONB_REFERENCE_ZIV_H

#include <mpfr.h>
#include "methods/kernels.h"

/* A binary floating-point format: p bits; a normal x = m 2^e with m in
   [0.5, 1) (frexp's convention) has emin <= e <= emax; below 2^(emin-1)
   the subnormals, multiples of 2^(emin - p). */
typedef struct { int p, emin, emax; } ref_format;

/* The format of a precision (PREC_FLOAT, PREC_DOUBLE). */
const ref_format *ref_format_of(int prec);

/* RN (to nearest, ties to even, subnormals and overflow as IEEE 754) of
   the MPFR value x, taken as exact, to format f, as a double; t is
   scratch (its precision is changed). */
double ref_round(mpfr_srcptr x, const ref_format *f, mpfr_ptr t);

/* RN to f of the exact sum of q[0..k-1] (k <= 7), by mpfr_sum at the
   format's quantum at that exponent; t is scratch. */
double ref_round_sum(mpfr_ptr *q, unsigned long k, const ref_format *f, mpfr_ptr t);

/* RN to f of S/sqrt(Q) - z, S the exact sum of s[0..ks-1], Q that of
   q[0..kq-1] (Q > 0), z a double: b.n and w.n - z against n/|n| for a
   non-unit input.  Ziv's strategy with a proven error: at p bits the
   quotient is within 2^(3-p) of itself and the difference within
   2^(1-p) more; the precision doubles from 128 bits until both ends of
   that interval round alike (at most 16384 bits; beyond, an exact zero
   is +0 and anything else is rounded from there).  ks, kq <= 7. */
double ref_round_quot(mpfr_ptr *s, unsigned long ks, mpfr_ptr *q, unsigned long kq, double z,
                      const ref_format *f);

/* The roundings of one formula evaluation, per output component. */
typedef struct {
	double fmt[6];   /* X to the format: the floor's basis, the forward error's unit */
	double d[6];     /* X to double: ref[]                                         */
	double diff[6];  /* X - cv to double (cv the kernel's output), when asked      */
	double diff_up[6]; /* where diff is undecided (NaN): an upper bound of |X - cv| */
} ziv_out;

typedef struct ziv_ctx ziv_ctx;

ziv_ctx *ziv_new(mpfr_prec_t p0);  /* NULL on allocation failure */
void ziv_free(ziv_ctx *z);

/* Around the caller's evaluation at p0: ziv_watch() before it,
   ziv_exact() after: 1 when no MPFR operation in between was inexact
   (only where MPFR's flags are per thread; elsewhere always 0). */
void ziv_watch(void);
int ziv_exact(void);

/* Decide the roundings of kernel k's exact formula on n (branch br,
   local direction loc) in precision prec.  r1, r2: that formula at p0
   (reference.c's), exact0: ziv_exact() of that evaluation, cv: the
   kernel's outputs (NULL: no diff).  Every fmt[] and d[] is decided on
   return (an undecided one at the cap is reported on stderr and
   counted); a diff may stay NaN with its bound in diff_up (an exact
   X = cv computed inexactly, typically): ziv_diff decides it when the
   caller needs it. */
void ziv_round(ziv_ctx *z, const study_kernel *k, int prec, int br, const double n[3], const double loc[3],
               mpfr_t *r1, mpfr_t *r2, int exact0, const double *cv, ziv_out *o);
/* Decide diff[i] of the last ziv_round, raising the precision further. */
void ziv_diff(ziv_ctx *z, int i, ziv_out *o);

/* What the strategy did since ziv_new: formula evaluations above p0,
   exact ties and zeros settled at the cap, undecided roundings. */
typedef struct { long raised, ties, undecided; } ziv_stats;
ziv_stats ziv_get_stats(const ziv_ctx *z);

#endif
