/*
 * domain32.c - which side of the default float domain an input lies on,
 * and the run of domain members along one axis (domain32.h).
 *
 * The domain side.  A float v is the rounding of the reals whose magnitude
 * lies between |v| - down/2 and |v| + up/2 (down, up: the gaps to the next
 * floats towards and away from 0; down = 0 for a zero).  cert_in_domain
 * takes n as a member when the box of those reals holds a point of
 * |u| = 1 inside: sum of the squared low ends < 1 < sum of the squared high
 * ends.  Both sums grow with |n[axis]|, so along a ray of one component the
 * side goes -1, 0, +1, and the members are one run of consecutive floats.
 * In double the ends (at most 26 significant bits, above 2^-151) and their
 * squares are exact, and each sum of three squares below 4.1 is within
 * 2^-48 of exact; cert_f32_side decides from those sums unless one is
 * within 2^-46 of 1, and then asks cert_in_domain.  Near 1 the two sums
 * are at least 2^-26 apart (some component is above 0.57, its gaps above
 * 2^-25), so at most one of them is that close to 1 and a non-member's
 * side is the side of that one.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "domain32.h"
#include "region.h"
#include "common/options.h"
#include "common/prec.h"
#include "inputs/inputs.h"

#define SIDE_TOL 0x1p-46

int cert_f32_side(const double n[3])
{
	double lo = 0.0, hi = 0.0;
	int i;
	for (i = 0; i < 3; i++) {
		const double a = fabs(n[i]);
		float f;
		double up, down;
		if (!isfinite(n[i]) || fmt_round(n[i], PREC_FLOAT) != n[i])
			return 2;
		if (!(a < 2.0))
			return 1;   /* every low end is above 1.99 */
		f = (float)a;
		up = (double)nextafterf(f, INFINITY) - a;
		down = a > 0.0 ? a - (double)nextafterf(f, 0.0f) : 0.0;
		lo += (a - down / 2) * (a - down / 2);
		hi += (a + up / 2) * (a + up / 2);
	}
	if (lo - 1.0 > SIDE_TOL)
		return 1;
	if (hi - 1.0 < -SIDE_TOL)
		return -1;
	if (lo - 1.0 < -SIDE_TOL && hi - 1.0 > SIDE_TOL)
		return 0;
	if (cert_in_domain(n, PREC_FLOAT, -1.0))
		return 0;
	if (fabs(lo - 1.0) <= SIDE_TOL && fabs(hi - 1.0) <= SIDE_TOL)
		return 2;
	return fabs(lo - 1.0) <= SIDE_TOL ? 1 : -1;
}

/* The double domain, for the found side's moves off the completion
   (in double cert_in_domain works at 4400 bits, tens of microseconds).
   The ends a -+ gap/2 are each an exact double-double (two_sum), their
   squares exact sums of products (fma), and each sum of three squares a
   Neumaier-compensated sum of those: within 2^-100 of exact, so a sum
   more than SIDE64_TOL from 1 decides.  Components below 2^-500 add
   under 2^-999 to either sum and are left out (a product of theirs could
   underflow); so is a zero's high end (2^-2150). */
#define SIDE64_TOL 0x1p-96

static void acc2(double *s, double *c, double v)   /* s + c += v, Neumaier */
{
	double t = *s + v;
	*c += fabs(*s) >= fabs(v) ? (*s - t) + v : (v - t) + *s;
	*s = t;
}

/* s + c += (a + g)^2, a and g doubles, a + g computed exactly as hi + lo. */
static void add_sq(double *s, double *c, double a, double g)
{
	const double hi = a + g, bb = hi - a, lo = (a - (hi - bb)) + (g - bb);
	double p = hi * hi, q = 2.0 * hi * lo, r = lo * lo;
	acc2(s, c, p);
	acc2(s, c, fma(hi, hi, -p));
	acc2(s, c, q);
	acc2(s, c, fma(2.0 * hi, lo, -q));
	acc2(s, c, r);
}

int cert_f64_side(const double n[3])
{
	double lo = 0.0, lc = 0.0, hi = 0.0, hc = 0.0, dl, dh;
	int i;
	for (i = 0; i < 3; i++) {
		const double a = fabs(n[i]);
		if (!isfinite(n[i]))
			return 2;
		if (!(a < 2.0))
			return 1;
		if (a < 0x1p-500)
			continue;
		add_sq(&lo, &lc, a, -(a - nextafter(a, 0.0)) / 2);
		add_sq(&hi, &hc, a, (nextafter(a, INFINITY) - a) / 2);
	}
	dl = (lo - 1.0) + lc;   /* lo - 1 exact near 1 (Sterbenz) */
	dh = (hi - 1.0) + hc;
	if (dl > SIDE64_TOL)
		return 1;
	if (dh < -SIDE64_TOL)
		return -1;
	if (dl < -SIDE64_TOL && dh > SIDE64_TOL)
		return 0;
	if (cert_in_domain(n, PREC_DOUBLE, -1.0))
		return 0;
	return fabs(dl) <= SIDE64_TOL && fabs(dh) <= SIDE64_TOL ? 2 : fabs(dl) <= SIDE64_TOL ? 1 : -1;
}

/* The float of ordinal k >= 0 (its bits), with the sign of sign. */
static double fval(int64_t k, int sign)
{
	const uint32_t b = (uint32_t)k;
	float f;
	memcpy(&f, &b, 4);
	return sign < 0 ? -(double)f : (double)f;
}

/* 1 when n with n[axis] = fval(k, sign) is on side >= want; -1: no side. */
static int at_least(const double n[3], int axis, int sign, int64_t k, int want)
{
	double v[3];
	int s;
	memcpy(v, n, sizeof v);
	v[axis] = fval(k, sign);
	s = cert_f32_side(v);
	return s == 2 ? -1 : s >= want;
}

#define KMAX ((int64_t)0x7f7fffff) /* the ordinal of FLT_MAX */

/* The first k in [0, KMAX] with at_least (KMAX + 1 if none), -1 when a
   side could not be told: galloping from k0, then bisection.  Invariant:
   at_least fails at a (or a = -1), holds at b (or b = KMAX + 1). */
static int64_t first_at_least(const double n[3], int axis, int sign, int64_t k0, int want)
{
	int64_t a, b, step = 1;
	int t = at_least(n, axis, sign, k0, want);
	if (t < 0)
		return -1;
	if (t) {
		for (b = k0;; b = a, step *= 2) {
			if (step > b) {
				a = -1;
				break;
			}
			a = b - step;
			if ((t = at_least(n, axis, sign, a, want)) < 0)
				return -1;
			if (!t)
				break;
		}
	} else {
		for (a = k0;; a = b, step *= 2) {
			if (step > KMAX - a) {
				b = KMAX + 1;
				break;
			}
			b = a + step;
			if ((t = at_least(n, axis, sign, b, want)) < 0)
				return -1;
			if (t)
				break;
		}
	}
	while (b - a > 1) {
		const int64_t mid = a + (b - a) / 2;
		if ((t = at_least(n, axis, sign, mid, want)) < 0)
			return -1;
		if (t)
			b = mid;
		else
			a = mid;
	}
	return b;
}

long long cert_f32_run(const double n[3], int axis, int sign, double *lo, double *hi)
{
	double q = 1.0, v[3];
	float g;
	uint32_t bits;
	int64_t l, h;
	int i;
	for (i = 0; i < 3; i++)
		if (i != axis)
			q -= n[i] * n[i];
	g = (float)sqrt(fmax(0.0, q));   /* a start near the run */
	memcpy(&bits, &g, 4);
	if ((l = first_at_least(n, axis, sign, (int64_t)bits, 0)) < 0)
		goto fail;
	memcpy(v, n, sizeof v);
	v[axis] = fval(l, sign);
	if (l > KMAX || cert_f32_side(v) != 0)
		return 0;
	if ((h = first_at_least(n, axis, sign, l, 1)) < 0)
		goto fail;
	*lo = fval(l, sign);
	*hi = fval(h - 1, sign);
	return (long long)(h - l);
fail:
	study_error("enumerate: the domain side of (%a, %a, %a) along axis %d could not be told", n[0], n[1], n[2],
	            axis);
	return -1;
}
