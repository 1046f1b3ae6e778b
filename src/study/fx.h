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

/* a += v, for v >= 0 (NaN and negative values are ignored by the callers). */
static inline void fx_add_double(fx *a, double v)
{
	int e, s;
	uint64_t m;
	if (!(v > 0.0))
		return;
	if (!(v < 0x1p80)) {
		a->saturated = 1;
		return;
	}
	m = (uint64_t)ldexp(frexp(v, &e), 53); /* v = m * 2^(e-53) */
	s = e - 53 + FX_SHIFT;                 /* bit position of m's last bit */
	if (s < 0) {
		if (s <= -64)
			return;
		m >>= -s;
		s = 0;
	}
	fx_add_limbs(a, s / 64, m << (s % 64));
	if (s % 64)
		fx_add_limbs(a, s / 64 + 1, m >> (64 - s % 64));
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
