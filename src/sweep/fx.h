/*
 * fx.h - exact, order-independent sums of non-negative doubles.
 *
 * Sums in the sweep (squared errors, bits of error) are accumulated as
 * 384-bit fixed-point integers with resolution 2^-300.  Integer addition
 * is associative, so the totals are the same bits whatever the thread
 * count, the chunk order, or how a run was split into shards and merged.
 * Each term is truncated to a multiple of 2^-300 (an absolute error below
 * 1e-90 per term, far under anything reported); values of 2^80 or more
 * saturate, and fx_value then returns +inf.
 */
#ifndef ONB_FX_H
#define ONB_FX_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#define FX_LIMBS 6
#define FX_SHIFT 300

typedef struct {
	uint64_t l[FX_LIMBS];
	uint64_t saturated;
} fx;

static inline void fx_add_limbs(fx *a, int from, uint64_t v)
{
	int i;
	for (i = from; i < FX_LIMBS && v; i++) {
		uint64_t s = a->l[i] + v;
		v = s < v; /* carry */
		a->l[i] = s;
	}
	if (v)
		a->saturated = 1;
}

/* a += v, for v >= 0 (NaN and negative values are ignored by the callers).
   v = m * 2^(E-1075) is read from its bits (E = the biased exponent, m
   with the hidden bit: frexp's fraction times 2^53), so that m's last bit
   lands on bit s = E - 1075 + FX_SHIFT of the sum; subnormals (E = 0) lie
   below 2^-1022, far under the resolution, and add nothing.  m spans at
   most two limbs (v < 2^80 puts its top bit below bit 380).  This runs
   some 30 times per input of a sweep: no libm call, and the carry loop
   only when a limb wraps. */
static inline void fx_add_double(fx *a, double v)
{
	int s, i, r;
	uint64_t m, u, lo, hi;
	if (!(v > 0.0))
		return;
	if (!(v < 0x1p80)) {
		a->saturated = 1;
		return;
	}
	memcpy(&u, &v, sizeof u);
	m = (u & 0xfffffffffffffull) | 0x10000000000000ull;
	s = (int)(u >> 52) - 1075 + FX_SHIFT;
	if (s < 0) {
		if (s <= -64)
			return;
		m >>= -s;
		s = 0;
	}
	i = s / 64;
	r = s % 64;
	lo = m << r;
	hi = (m >> 1) >> (63 - r);         /* m >> (64 - r), 0 for r = 0 */
	a->l[i] += lo;
	hi += a->l[i] < lo;                /* the carry: hi < 2^53, no overflow */
	if (i + 1 < FX_LIMBS) {
		a->l[i + 1] += hi;
		if (a->l[i + 1] < hi)
			fx_add_limbs(a, i + 2, 1);
	} else if (hi) {
		a->saturated = 1;
	}
}

static inline void fx_add(fx *a, const fx *b)
{
	int i;
	for (i = 0; i < FX_LIMBS; i++)
		fx_add_limbs(a, i, b->l[i]);
	a->saturated |= b->saturated;
}

static inline double fx_value(const fx *a)
{
	long double s = 0.0L;
	int i;
	if (a->saturated)
		return INFINITY;
	for (i = FX_LIMBS - 1; i >= 0; i--)
		s += ldexpl((long double)a->l[i], 64 * i - FX_SHIFT);
	return (double)s;
}

#endif
