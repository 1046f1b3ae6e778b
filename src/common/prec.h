/*
 * prec.h - the precisions the study measures.  The ground floor: every
 * room may include it, and it includes nothing of the study.
 */
#ifndef ONB_COMMON_PREC_H
#define ONB_COMMON_PREC_H

#include <math.h>
#include <stdint.h>

/* binary32, binary64 and binary16; also the index of per-precision arrays
   (those sized 2 hold float and double only), and the format of a
   rounding model's operation (src/model/model.h) */
enum { PREC_FLOAT = 0, PREC_DOUBLE = 1, PREC_HALF = 2 };
#define PREC_COUNT 3

/* A format's parameters, in one place for every room: p bits of
   significand (the hidden bit counted), unit roundoff u = 2^-p, the
   smallest normal 2^emin, the subnormal step 2^(emin - p + 1) (the
   absolute error of an underflowing rounding is at most half of it), and
   the largest finite value (2 - 2^(1-p)) 2^emax, above which a rounding
   overflows to infinity. */
typedef struct prec_format {
	const char *name;   /* the one spelling in every output: "float", "double", "half" */
	int bits;           /* p: 24, 53, 11                                   */
	int emin, emax;     /* -126/127, -1022/1023, -14/15                    */
	double u;           /* 2^-p                                            */
	double normal_min;  /* 2^emin                                          */
	double sub_step;    /* 2^(emin - p + 1): 2^-149, 2^-1074, 2^-24         */
	double max;         /* largest finite: FLT_MAX, DBL_MAX, 65504          */
} prec_format;

static inline const prec_format *prec_fmt(int p)
{
	static const prec_format f[PREC_COUNT] = {
		{ "float",  24, -126,  127,  0x1p-24, 0x1p-126,  0x1p-149,  0x1.fffffep+127 },
		{ "double", 53, -1022, 1023, 0x1p-53, 0x1p-1022, 0x1p-1074, 0x1.fffffffffffffp+1023 },
		{ "half",   11, -14,   15,   0x1p-11, 0x1p-14,   0x1p-24,   0x1.ffcp+15 },
	};
	return &f[p >= 0 && p < PREC_COUNT ? p : PREC_DOUBLE];
}

/* The one spelling of a precision in every output: "float", "double", "half". */
static inline const char *prec_name(int p) { return prec_fmt(p)->name; }

/* binary16 in plain C (the study builds without _Float16 too): x rounded
   to binary16 (the quantum of x's binade, floored at the subnormal step
   2^-24, nearbyint's ties to even; past the largest finite, infinity),
   as a double. */
static inline double prec_half_round(double x)
{
	const prec_format *F = prec_fmt(PREC_HALF);
	double q, r;
	if (!isfinite(x) || x == 0.0)
		return x;
	q = ldexp(1.0, (ilogb(x) < F->emin ? F->emin : ilogb(x)) - (F->bits - 1));
	r = nearbyint(x / q) * q;   /* x / q and the product exact: q is a power of 2 >= 2^-24 */
	return fabs(r) > F->max ? copysign(INFINITY, x) : r;
}

/* The encoding of a binary16 value v (one prec_half_round returns), and
   the value of an encoding. */
static inline uint16_t prec_half_bits(double v)
{
	const double a = fabs(v);
	uint16_t m;
	if (isnan(v)) return 0x7e00u;
	if (isinf(v)) m = 0x7c00u;
	else if (a < 0x1p-14) m = (uint16_t)(a * 0x1p24);
	else m = (uint16_t)((ilogb(a) + 15) * 1024 + (int)(ldexp(a, 10 - ilogb(a)) - 1024.0));
	return (uint16_t)(signbit(v) ? m | 0x8000u : m);
}
static inline double prec_half_value(uint16_t b)
{
	const int e = (b >> 10) & 31, f = b & 1023;
	const double a = e == 0 ? f * 0x1p-24 : e == 31 ? (f ? NAN : INFINITY) : ldexp(1024.0 + f, e - 25);
	return (b & 0x8000u) ? -a : a;
}

#endif
