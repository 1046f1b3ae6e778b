/*
 * fastfi.h - MPFI's copy, negation and interval-from-doubles for mvf.c's
 * values, without MPFR's general paths: the same bits, faster.
 *
 * mvf.c's values all have one precision (MV_PREC, two 64-bit limbs).
 * Copying or negating a regular (finite, nonzero) endpoint of that
 * precision is exact: sign, exponent and limbs, as mpfr_set4 does for
 * equal precisions (without its memmove call); mpfi_neg also allocates a
 * temporary on every call.  A double that is a normal number converts
 * exactly into the limbs (53 <= MV_PREC bits).  Everything else (zeros,
 * infinities, NaN, subnormal doubles, another precision or limb size)
 * goes to MPFR and MPFI themselves, which treat signed zeros and NaN flags
 * their own way.  Certify's output is byte-identical with and without
 * these (results/certify/profile/README.md: how that was checked).
 */
#ifndef ONB_MODEL_FASTFI_H
#define ONB_MODEL_FASTFI_H

#include <float.h>
#include <stdint.h>
#include <math.h>
#include <string.h>
#include <mpfi.h>

#if GMP_NUMB_BITS == 64 && GMP_NAIL_BITS == 0
#define FASTFI_LIMBS(prec) (((prec) + 63) / 64)
/* An endpoint the fast paths take: regular, of precision prec. */
#define FASTFI_OK(x, prec) (mpfr_regular_p(x) && mpfr_get_prec(x) == (prec))
#else
#define FASTFI_LIMBS(prec) 0
#define FASTFI_OK(x, prec) 0
#endif

/* a = b (sign s: 1 copy, -1 negation); both regular of precision prec. */
static inline void fastfi_move(mpfr_ptr a, mpfr_srcptr b, int s, mpfr_prec_t prec)
{
	int i;
	a->_mpfr_sign = s * b->_mpfr_sign;
	a->_mpfr_exp = b->_mpfr_exp;
	for (i = 0; i < FASTFI_LIMBS(prec); i++)
		a->_mpfr_d[i] = b->_mpfr_d[i];
}

/* mpfi_set(a, b), bit for bit. */
static inline void fastfi_set(mpfi_ptr a, mpfi_srcptr b, mpfr_prec_t prec)
{
	if (a == b)
		return;
	if (FASTFI_OK(&b->left, prec) && FASTFI_OK(&b->right, prec) && mpfr_get_prec(&a->left) == prec &&
	    mpfr_get_prec(&a->right) == prec) {
		fastfi_move(&a->left, &b->left, 1, prec);
		fastfi_move(&a->right, &b->right, 1, prec);
	} else {
		mpfi_set(a, b);
	}
}

/* mpfi_neg(a, b), bit for bit (a may be b). */
static inline void fastfi_neg(mpfi_ptr a, mpfi_srcptr b, mpfr_prec_t prec)
{
	if (FASTFI_OK(&b->left, prec) && FASTFI_OK(&b->right, prec) && mpfr_get_prec(&a->left) == prec &&
	    mpfr_get_prec(&a->right) == prec) {
		if (a == b) {
			mpfr_swap(&a->left, &a->right);   /* swaps the limb pointers */
			a->left._mpfr_sign = -a->left._mpfr_sign;
			a->right._mpfr_sign = -a->right._mpfr_sign;
		} else {
			fastfi_move(&a->left, &b->right, -1, prec);
			fastfi_move(&a->right, &b->left, -1, prec);
		}
	} else {
		mpfi_neg(a, b);
	}
}

/* x = d exactly for a normal double d (|d| >= DBL_MIN, finite); 0 when d
   is not one (nothing written). */
static inline int fastfi_set_d(mpfr_ptr x, double d, mpfr_prec_t prec)
{
#if GMP_NUMB_BITS == 64 && GMP_NAIL_BITS == 0
	uint64_t bits;
	int e, i;
	const double a = fabs(d);
	if (!(a >= DBL_MIN && a <= DBL_MAX) || mpfr_get_prec(x) != prec || prec < 53)
		return 0;
	memcpy(&bits, &d, sizeof bits);
	e = (int)((bits >> 52) & 0x7ff);       /* normal: 1 <= e <= 2046 */
	bits = (bits & UINT64_C(0xfffffffffffff)) | UINT64_C(0x10000000000000);
	x->_mpfr_sign = d < 0 ? -1 : 1;
	x->_mpfr_exp = e - 1022;               /* d = 0.1xxx (binary) * 2^(e - 1022) */
	for (i = 0; i < FASTFI_LIMBS(prec) - 1; i++)
		x->_mpfr_d[i] = 0;
	x->_mpfr_d[FASTFI_LIMBS(prec) - 1] = (mp_limb_t)(bits << 11);
	return 1;
#else
	(void)x; (void)d; (void)prec;
	return 0;
#endif
}

/* mpfi_interv_d(a, lo, hi), bit for bit. */
static inline void fastfi_interv_d(mpfi_ptr a, double lo, double hi, mpfr_prec_t prec)
{
	if (!(lo <= hi) || !fastfi_set_d(&a->left, lo, prec) || !fastfi_set_d(&a->right, hi, prec))
		mpfi_interv_d(a, lo, hi);
}

#endif
