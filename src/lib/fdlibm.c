/*
 * fdlibm.c - V8's port of fdlibm: the Math.acos, Math.atan2, Math.sin and
 * Math.cos of Node.js (the `babylon` row evaluates Babylon.js's
 * Vector3.getNormalToRef with them, as JavaScript does).
 *
 * Transliterated to C99 from V8's src/base/ieee754.cc as Node.js ships it
 * (github.com/nodejs/node f579e1194046c50f2e6bb54348d48c8e7d1a53cf,
 * deps/v8/src/base/ieee754.cc: __ieee754_rem_pio2, __kernel_cos,
 * __kernel_rem_pio2, __kernel_sin, acos, atan, atan2, cos, sin), operation
 * for operation: the same constants, the same order, the same word tests.
 * Checked bit for bit against Node.js 20.20.2 (V8 11.3.244.8), whose
 * Math.sin/cos are these (that V8 has no use_libm_trig_functions flag):
 * scripts/babylon-node.sh and tests/data/babylon_node.csv
 * (docs/wild-specs/babylon.md gives the reading).  What differs from the
 * C++ text, none of it in a value: the word macros read the bits through
 * memcpy; std::numeric_limits<double>::signaling_NaN() is the same bits
 * (0x7FF4000000000000) built here; NegateWithWraparound and
 * SubWithWraparound are unsigned arithmetic.  sqrt is C99's (correctly
 * rounded, as V8's std::sqrt); floor and scalbn, exact where
 * __kernel_rem_pio2 uses them, are written here (fd_floor, fd_scalbn), and
 * that function's end is krp_finish, so that no function is over 100
 * lines.  Built with -ffp-contract=off like the rest of libonb: no fused
 * operation, as V8's x86-64 build has none.
 *
 * The original license notice (fdlibm):
 * ====================================================
 * Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved.
 *
 * Developed at SunSoft, a Sun Microsystems, Inc. business.
 * Permission to use, copy, modify, and distribute this
 * software is freely granted, provided that this notice
 * is preserved.
 * ====================================================
 * and V8's: "The original source code covered by the above license above
 * has been modified significantly by Google Inc.  Copyright 2016 the V8
 * project authors. All rights reserved." (BSD-3-Clause, V8's LICENSE).
 */
#define ONB_BUILDING_LIB 1
#include "libonb/onb.h"
#include <math.h>
#include <stdint.h>
#include <string.h>

static uint64_t bits_of(double d)
{
	uint64_t u;
	memcpy(&u, &d, sizeof u);
	return u;
}
static double of_bits(uint64_t u)
{
	double d;
	memcpy(&d, &u, sizeof d);
	return d;
}
#define GET_HIGH_WORD(i, d) ((i) = (int32_t)(uint32_t)(bits_of(d) >> 32))
#define GET_LOW_WORD(i, d) ((i) = (uint32_t)(bits_of(d) & 0xFFFFFFFFu))
#define EXTRACT_WORDS(hi, lo, d) do { GET_HIGH_WORD(hi, d); GET_LOW_WORD(lo, d); } while (0)
#define INSERT_WORDS(d, hi, lo) ((d) = of_bits(((uint64_t)(uint32_t)(hi) << 32) | (uint32_t)(lo)))
#define SET_HIGH_WORD(d, v) ((d) = of_bits((bits_of(d) & 0xFFFFFFFFu) | ((uint64_t)(uint32_t)(v) << 32)))
#define SET_LOW_WORD(d, v) ((d) = of_bits((bits_of(d) & UINT64_C(0xFFFFFFFF00000000)) | (uint32_t)(v)))
#define SIGNALING_NAN of_bits(UINT64_C(0x7FF4000000000000))

/* scalbn and floor as kernel_rem_pio2 uses them: exact there (its values
   stay normal and |x| < 2^53), so any correct scalbn and floor give these
   bits; written here to keep libonb to sqrt of libm */
static double fd_scalbn(double x, int n)
{
	while (n > 1000) { x *= 0x1p1000; n -= 1000; }
	while (n < -1000) { x *= 0x1p-1000; n += 1000; }
	return x * of_bits((uint64_t)(n + 1023) << 52);
}
static double fd_floor(double x)
{
	double t;
	if (!(fabs(x) < 0x1p52))
		return x;
	t = (double)(int64_t)x;
	return t > x ? t - 1.0 : t;
}

static const double PIo2[] = {
	1.57079625129699707031e+00, 7.54978941586159635335e-08, 5.39030252995776476554e-15,
	3.28200341580791294123e-22, 1.27065575308067607349e-29, 1.22933308981111328932e-36,
	2.73370053816464559624e-44, 2.16741683877804819444e-51,
};

/* The end of __kernel_rem_pio2 once n is known: chop off zero terms, turn
   the 24-bit chunks iq[0..jz] into floating point, fq = PIo2 * q, and
   compress fq into y[0] + y[1] (prec 2, as __ieee754_rem_pio2 calls it:
   V8's case 1: case 2:) */
static void krp_finish(double z, int32_t *iq, int32_t jz, int32_t q0, int32_t ih, int32_t jp, double *y)
{
	static const double two24 = 1.67772160000000000000e+07, twon24 = 5.96046447753906250000e-08;
	double fw, fq[20] = {0}, q[20] = {0};   /* zeroed: GCC cannot see that jz >= 0 writes fq[0] (-Wmaybe-uninitialized under the sanitizers); every read follows a write, as in V8 */
	int32_t i, k;
	if (z == 0.0) {
		jz -= 1;
		q0 -= 24;
		while (iq[jz] == 0) {
			jz--;
			q0 -= 24;
		}
	} else {
		z = fd_scalbn(z, -q0);
		if (z >= two24) {
			fw = (double)(int32_t)(twon24 * z);
			iq[jz] = (int32_t)(z - two24 * fw);
			jz += 1;
			q0 += 24;
			iq[jz] = (int32_t)fw;
		} else {
			iq[jz] = (int32_t)z;
		}
	}
	fw = fd_scalbn(1.0, q0);
	for (i = jz; i >= 0; i--) {
		q[i] = fw * iq[i];
		fw *= twon24;
	}
	for (i = jz; i >= 0; i--) {
		for (fw = 0.0, k = 0; k <= jp && k <= jz - i; k++) fw += PIo2[k] * q[i + k];
		fq[jz - i] = fw;
	}
	fw = 0.0;
	for (i = jz; i >= 0; i--) fw += fq[i];
	y[0] = (ih == 0) ? fw : -fw;
	fw = fq[0] - fw;
	for (i = 1; i <= jz; i++) fw += fq[i];
	y[1] = (ih == 0) ? fw : -fw;
}

/* __kernel_rem_pio2: the large arguments' reduction (|x| >= 2^19 pi/2),
   prec 2 as __ieee754_rem_pio2 calls it */
static int kernel_rem_pio2(const double *x, double *y, int e0, int nx, int prec, const int32_t *ipio2)
{
	static const int init_jk[] = {2, 3, 4, 6};
	static const double zero = 0.0, one = 1.0, two24 = 1.67772160000000000000e+07,
		twon24 = 5.96046447753906250000e-08;
	int32_t jz, jx, jv, jp, jk, carry, n, iq[20], i, j, k, m, q0, ih;
	double z, fw, f[20], q[20];

	jk = init_jk[prec];
	jp = jk;
	jx = nx - 1;
	jv = (e0 - 3) / 24;
	if (jv < 0) jv = 0;
	q0 = e0 - 24 * (jv + 1);
	j = jv - jx;
	m = jx + jk;
	for (i = 0; i <= m; i++, j++)
		f[i] = (j < 0) ? zero : (double)ipio2[j];
	for (i = 0; i <= jk; i++) {
		for (j = 0, fw = 0.0; j <= jx; j++) fw += x[j] * f[jx + i - j];
		q[i] = fw;
	}
	jz = jk;
recompute:
	for (i = 0, j = jz, z = q[jz]; j > 0; i++, j--) {
		fw = (double)(int32_t)(twon24 * z);
		iq[i] = (int32_t)(z - two24 * fw);
		z = q[j - 1] + fw;
	}
	z = fd_scalbn(z, q0);
	z -= 8.0 * fd_floor(z * 0.125);
	n = (int32_t)z;
	z -= (double)n;
	ih = 0;
	if (q0 > 0) {
		i = (iq[jz - 1] >> (24 - q0));
		n += i;
		iq[jz - 1] -= i << (24 - q0);
		ih = iq[jz - 1] >> (23 - q0);
	} else if (q0 == 0) {
		ih = iq[jz - 1] >> 23;
	} else if (z >= 0.5) {
		ih = 2;
	}
	if (ih > 0) {
		n += 1;
		carry = 0;
		for (i = 0; i < jz; i++) {
			j = iq[i];
			if (carry == 0) {
				if (j != 0) {
					carry = 1;
					iq[i] = 0x1000000 - j;
				}
			} else {
				iq[i] = 0xFFFFFF - j;
			}
		}
		if (q0 > 0) {
			switch (q0) {
			case 1: iq[jz - 1] &= 0x7FFFFF; break;
			case 2: iq[jz - 1] &= 0x3FFFFF; break;
			}
		}
		if (ih == 2) {
			z = one - z;
			if (carry != 0) z -= fd_scalbn(one, q0);
		}
	}
	if (z == zero) {
		j = 0;
		for (i = jz - 1; i >= jk; i--) j |= iq[i];
		if (j == 0) {
			for (k = 1; jk >= k && iq[jk - k] == 0; k++) {
			}
			for (i = jz + 1; i <= jz + k; i++) {
				f[jx + i] = ipio2[jv + i];
				for (j = 0, fw = 0.0; j <= jx; j++) fw += x[j] * f[jx + i - j];
				q[i] = fw;
			}
			jz += k;
			goto recompute;
		}
	}
	krp_finish(z, iq, jz, q0, ih, jp, y);
	return n & 7;
}

/* __ieee754_rem_pio2's medium arguments, 3pi/4 <= |x| <= 2^19 pi/2 (hx, ix
   x's high word and its magnitude's) */
static int32_t rem_pio2_medium(double x, int32_t hx, int32_t ix, double *y)
{
	static const int32_t npio2_hw[] = {
		0x3FF921FB, 0x400921FB, 0x4012D97C, 0x401921FB, 0x401F6A7A, 0x4022D97C,
		0x4025FDBB, 0x402921FB, 0x402C463A, 0x402F6A7A, 0x4031475C, 0x4032D97C,
		0x40346B9C, 0x4035FDBB, 0x40378FDB, 0x403921FB, 0x403AB41B, 0x403C463A,
		0x403DD85A, 0x403F6A7A, 0x40407E4C, 0x4041475C, 0x4042106C, 0x4042D97C,
		0x4043A28C, 0x40446B9C, 0x404534AC, 0x4045FDBB, 0x4046C6CB, 0x40478FDB,
		0x404858EB, 0x404921FB,
	};
	static const double half = 5.00000000000000000000e-01, invpio2 = 6.36619772367581382433e-01,
		pio2_1 = 1.57079632673412561417e+00, pio2_1t = 6.07710050650619224932e-11,
		pio2_2 = 6.07710050630396597660e-11, pio2_2t = 2.02226624879595063154e-21,
		pio2_3 = 2.02226624871116645580e-21, pio2_3t = 8.47842766036889956997e-32;
	double w, t, r, fn;
	int32_t i, j, n;
	t = fabs(x);
	n = (int32_t)(t * invpio2 + half);
	fn = (double)n;
	r = t - fn * pio2_1;
	w = fn * pio2_1t;
	if (n < 32 && ix != npio2_hw[n - 1]) {
		y[0] = r - w;
	} else {
		uint32_t high;
		j = ix >> 20;
		y[0] = r - w;
		high = (uint32_t)(bits_of(y[0]) >> 32);
		i = j - (int32_t)((high >> 20) & 0x7FF);
		if (i > 16) {
			t = r;
			w = fn * pio2_2;
			r = t - w;
			w = fn * pio2_2t - ((t - r) - w);
			y[0] = r - w;
			high = (uint32_t)(bits_of(y[0]) >> 32);
			i = j - (int32_t)((high >> 20) & 0x7FF);
			if (i > 49) {
				t = r;
				w = fn * pio2_3;
				r = t - w;
				w = fn * pio2_3t - ((t - r) - w);
				y[0] = r - w;
			}
		}
	}
	y[1] = (r - y[0]) - w;
	if (hx < 0) {
		y[0] = -y[0];
		y[1] = -y[1];
		return -n;
	}
	return n;
}

/* __ieee754_rem_pio2: x - n pi/2 in y[0] + y[1], n returned */
static int32_t rem_pio2(double x, double *y)
{
	static const int32_t two_over_pi[] = {
		0xA2F983, 0x6E4E44, 0x1529FC, 0x2757D1, 0xF534DD, 0xC0DB62, 0x95993C,
		0x439041, 0xFE5163, 0xABDEBB, 0xC561B7, 0x246E3A, 0x424DD2, 0xE00649,
		0x2EEA09, 0xD1921C, 0xFE1DEB, 0x1CB129, 0xA73EE8, 0x8235F5, 0x2EBB44,
		0x84E99C, 0x7026B4, 0x5F7E41, 0x3991D6, 0x398353, 0x39F49C, 0x845F8B,
		0xBDF928, 0x3B1FF8, 0x97FFDE, 0x05980F, 0xEF2F11, 0x8B5A0A, 0x6D1F6D,
		0x367ECF, 0x27CB09, 0xB74F46, 0x3F669E, 0x5FEA2D, 0x7527BA, 0xC7EBE5,
		0xF17B3D, 0x0739F7, 0x8A5292, 0xEA6BFB, 0x5FB11F, 0x8D5D08, 0x560330,
		0x46FC7B, 0x6BABF0, 0xCFBC20, 0x9AF436, 0x1DA9E3, 0x91615E, 0xE61B08,
		0x659985, 0x5F14A0, 0x68408D, 0xFFD880, 0x4D7327, 0x310606, 0x1556CA,
		0x73A8C9, 0x60E27B, 0xC08C6B,
	};
	static const double zero = 0.00000000000000000000e+00, two24 = 1.67772160000000000000e+07,
		pio2_1 = 1.57079632673412561417e+00, pio2_1t = 6.07710050650619224932e-11,
		pio2_2 = 6.07710050630396597660e-11, pio2_2t = 2.02226624879595063154e-21;
	double z;
	double tx[3];
	int32_t e0, i, nx, n, ix, hx;
	uint32_t low;

	z = 0;
	GET_HIGH_WORD(hx, x);
	ix = hx & 0x7FFFFFFF;
	if (ix <= 0x3FE921FB) {
		y[0] = x;
		y[1] = 0;
		return 0;
	}
	if (ix < 0x4002D97C) {
		if (hx > 0) {
			z = x - pio2_1;
			if (ix != 0x3FF921FB) {
				y[0] = z - pio2_1t;
				y[1] = (z - y[0]) - pio2_1t;
			} else {
				z -= pio2_2;
				y[0] = z - pio2_2t;
				y[1] = (z - y[0]) - pio2_2t;
			}
			return 1;
		} else {
			z = x + pio2_1;
			if (ix != 0x3FF921FB) {
				y[0] = z + pio2_1t;
				y[1] = (z - y[0]) + pio2_1t;
			} else {
				z += pio2_2;
				y[0] = z + pio2_2t;
				y[1] = (z - y[0]) + pio2_2t;
			}
			return -1;
		}
	}
	if (ix <= 0x413921FB)
		return rem_pio2_medium(x, hx, ix, y);
	if (ix >= 0x7FF00000) {
		y[0] = y[1] = x - x;
		return 0;
	}
	GET_LOW_WORD(low, x);
	SET_LOW_WORD(z, low);
	e0 = (ix >> 20) - 1046;
	SET_HIGH_WORD(z, ix - (int32_t)((uint32_t)e0 << 20));
	for (i = 0; i < 2; i++) {
		tx[i] = (double)(int32_t)z;
		z = (z - tx[i]) * two24;
	}
	tx[2] = z;
	nx = 3;
	while (tx[nx - 1] == zero) nx--;
	n = kernel_rem_pio2(tx, y, e0, nx, 2, two_over_pi);
	if (hx < 0) {
		y[0] = -y[0];
		y[1] = -y[1];
		return -n;
	}
	return n;
}

/* __kernel_cos on [-pi/4, pi/4], y the tail of x */
static double kernel_cos(double x, double y)
{
	static const double one = 1.00000000000000000000e+00,
		C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
		C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
		C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
	double a, iz, z, r, qx;
	int32_t ix;
	GET_HIGH_WORD(ix, x);
	ix &= 0x7FFFFFFF;
	if (ix < 0x3E400000) {
		if ((int)x == 0) return one;
	}
	z = x * x;
	r = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
	if (ix < 0x3FD33333) {
		return one - (0.5 * z - (z * r - x * y));
	} else {
		if (ix > 0x3FE90000) {
			qx = 0.28125;
		} else {
			INSERT_WORDS(qx, ix - 0x00200000, 0);
		}
		iz = 0.5 * z - qx;
		a = one - qx;
		return a - (iz - (z * r - x * y));
	}
}

/* __kernel_sin on [-pi/4, pi/4], y the tail of x, iy 0 when y is 0 */
static double kernel_sin(double x, double y, int iy)
{
	static const double half = 5.00000000000000000000e-01,
		S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
		S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
		S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
	double z, r, v;
	int32_t ix;
	GET_HIGH_WORD(ix, x);
	ix &= 0x7FFFFFFF;
	if (ix < 0x3E400000) {
		if ((int)x == 0) return x;
	}
	z = x * x;
	v = z * x;
	r = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
	if (iy == 0)
		return x + v * (S1 + z * r);
	return x - ((z * (half * y - v * r) - y) - v * S1);
}

double onb__fdlibm_acos(double x)
{
	static const double one = 1.00000000000000000000e+00, pi = 3.14159265358979311600e+00,
		pio2_hi = 1.57079632679489655800e+00, pio2_lo = 6.12323399573676603587e-17,
		pS0 = 1.66666666666666657415e-01, pS1 = -3.25565818622400915405e-01,
		pS2 = 2.01212532134862925881e-01, pS3 = -4.00555345006794114027e-02,
		pS4 = 7.91534994289814532176e-04, pS5 = 3.47933107596021167570e-05,
		qS1 = -2.40339491173441421878e+00, qS2 = 2.02094576023350569471e+00,
		qS3 = -6.88283971605453293030e-01, qS4 = 7.70381505559019352791e-02;
	double z, p, q, r, w, s, c, df;
	int32_t hx, ix;
	GET_HIGH_WORD(hx, x);
	ix = hx & 0x7FFFFFFF;
	if (ix >= 0x3FF00000) {
		uint32_t lx;
		GET_LOW_WORD(lx, x);
		if (((uint32_t)(ix - 0x3FF00000) | lx) == 0) {
			if (hx > 0)
				return 0.0;
			return pi + 2.0 * pio2_lo;
		}
		return SIGNALING_NAN;
	}
	if (ix < 0x3FE00000) {
		if (ix <= 0x3C600000) return pio2_hi + pio2_lo;
		z = x * x;
		p = z * (pS0 + z * (pS1 + z * (pS2 + z * (pS3 + z * (pS4 + z * pS5)))));
		q = one + z * (qS1 + z * (qS2 + z * (qS3 + z * qS4)));
		r = p / q;
		return pio2_hi - (x - (pio2_lo - x * r));
	} else if (hx < 0) {
		z = (one + x) * 0.5;
		p = z * (pS0 + z * (pS1 + z * (pS2 + z * (pS3 + z * (pS4 + z * pS5)))));
		q = one + z * (qS1 + z * (qS2 + z * (qS3 + z * qS4)));
		s = sqrt(z);
		r = p / q;
		w = r * s - pio2_lo;
		return pi - 2.0 * (s + w);
	} else {
		z = (one - x) * 0.5;
		s = sqrt(z);
		df = s;
		SET_LOW_WORD(df, 0);
		c = (z - df * df) / (s + df);
		p = z * (pS0 + z * (pS1 + z * (pS2 + z * (pS3 + z * (pS4 + z * pS5)))));
		q = one + z * (qS1 + z * (qS2 + z * (qS3 + z * qS4)));
		r = p / q;
		w = r * s + c;
		return 2.0 * (df + w);
	}
}

static double fd_atan(double x)
{
	static const double atanhi[] = {
		4.63647609000806093515e-01, 7.85398163397448278999e-01,
		9.82793723247329054082e-01, 1.57079632679489655800e+00,
	};
	static const volatile double atanlo[] = {
		2.26987774529616870924e-17, 3.06161699786838301793e-17,
		1.39033110312309984516e-17, 6.12323399573676603587e-17,
	};
	static const double aT[] = {
		3.33333333333329318027e-01, -1.99999999998764832476e-01, 1.42857142725034663711e-01,
		-1.11111104054623557880e-01, 9.09088713343650656196e-02, -7.69187620504482999495e-02,
		6.66107313738753120669e-02, -5.83357013379057348645e-02, 4.97687799461593236017e-02,
		-3.65315727442169155270e-02, 1.62858201153657823623e-02,
	};
	static const double one = 1.0, huge = 1.0e300;
	double w, s1, s2, z;
	int32_t ix, hx, id;

	GET_HIGH_WORD(hx, x);
	ix = hx & 0x7FFFFFFF;
	if (ix >= 0x44100000) {
		uint32_t low;
		GET_LOW_WORD(low, x);
		if (ix > 0x7FF00000 || (ix == 0x7FF00000 && (low != 0)))
			return x + x;
		if (hx > 0)
			return atanhi[3] + atanlo[3];
		return -atanhi[3] - atanlo[3];
	}
	if (ix < 0x3FDC0000) {
		if (ix < 0x3E400000) {
			if (huge + x > one) return x;
		}
		id = -1;
	} else {
		x = fabs(x);
		if (ix < 0x3FF30000) {
			if (ix < 0x3FE60000) {
				id = 0;
				x = (2.0 * x - one) / (2.0 + x);
			} else {
				id = 1;
				x = (x - one) / (x + one);
			}
		} else {
			if (ix < 0x40038000) {
				id = 2;
				x = (x - 1.5) / (one + 1.5 * x);
			} else {
				id = 3;
				x = -1.0 / x;
			}
		}
	}
	z = x * x;
	w = z * z;
	s1 = z * (aT[0] + w * (aT[2] + w * (aT[4] + w * (aT[6] + w * (aT[8] + w * aT[10])))));
	s2 = w * (aT[1] + w * (aT[3] + w * (aT[5] + w * (aT[7] + w * aT[9]))));
	if (id < 0)
		return x - x * (s1 + s2);
	z = atanhi[id] - ((x * (s1 + s2) - atanlo[id]) - x);
	return (hx < 0) ? -z : z;
}

double onb__fdlibm_atan2(double y, double x)
{
	static volatile double tiny = 1.0e-300;
	static const double zero = 0.0, pi_o_4 = 7.8539816339744827900E-01,
		pi_o_2 = 1.5707963267948965580E+00, pi = 3.1415926535897931160E+00;
	static volatile double pi_lo = 1.2246467991473531772E-16;
	double z;
	int32_t k, m, hx, hy, ix, iy;
	uint32_t lx, ly;

	EXTRACT_WORDS(hx, lx, x);
	ix = hx & 0x7FFFFFFF;
	EXTRACT_WORDS(hy, ly, y);
	iy = hy & 0x7FFFFFFF;
	/* NegateWithWraparound<int32_t>(lx): 0 - lx modulo 2^32; the shift of
	   an int32_t is arithmetic in V8's compilers, read so here */
	if ((ix | (int32_t)((lx | (0u - lx)) >> 31)) > 0x7FF00000 ||
	    (iy | (int32_t)((ly | (0u - ly)) >> 31)) > 0x7FF00000)
		return x + y;
	if ((((uint32_t)hx - 0x3FF00000u) | lx) == 0)
		return fd_atan(y);
	m = (int32_t)((((uint32_t)hy >> 31) & 1) | (((uint32_t)hx >> 30) & 2));
	if ((iy | (int32_t)ly) == 0) {
		switch (m) {
		case 0:
		case 1: return y;
		case 2: return pi + tiny;
		case 3: return -pi - tiny;
		}
	}
	if ((ix | (int32_t)lx) == 0) return (hy < 0) ? -pi_o_2 - tiny : pi_o_2 + tiny;
	if (ix == 0x7FF00000) {
		if (iy == 0x7FF00000) {
			switch (m) {
			case 0: return pi_o_4 + tiny;
			case 1: return -pi_o_4 - tiny;
			case 2: return 3.0 * pi_o_4 + tiny;
			case 3: return -3.0 * pi_o_4 - tiny;
			}
		} else {
			switch (m) {
			case 0: return zero;
			case 1: return -zero;
			case 2: return pi + tiny;
			case 3: return -pi - tiny;
			}
		}
	}
	if (iy == 0x7FF00000) return (hy < 0) ? -pi_o_2 - tiny : pi_o_2 + tiny;
	k = (iy - ix) >> 20;
	if (k > 60) {
		z = pi_o_2 + 0.5 * pi_lo;
		m &= 1;
	} else if (hx < 0 && k < -60) {
		z = 0.0;
	} else {
		z = fd_atan(fabs(y / x));
	}
	switch (m) {
	case 0: return z;
	case 1: return -z;
	case 2: return pi - (z - pi_lo);
	default: return (z - pi_lo) - pi;
	}
}

double onb__fdlibm_cos(double x)
{
	double y[2], z = 0.0;
	int32_t n, ix;
	GET_HIGH_WORD(ix, x);
	ix &= 0x7FFFFFFF;
	if (ix <= 0x3FE921FB)
		return kernel_cos(x, z);
	if (ix >= 0x7FF00000)
		return x - x;
	n = rem_pio2(x, y);
	switch (n & 3) {
	case 0: return kernel_cos(y[0], y[1]);
	case 1: return -kernel_sin(y[0], y[1], 1);
	case 2: return -kernel_cos(y[0], y[1]);
	default: return kernel_sin(y[0], y[1], 1);
	}
}

double onb__fdlibm_sin(double x)
{
	double y[2], z = 0.0;
	int32_t n, ix;
	GET_HIGH_WORD(ix, x);
	ix &= 0x7FFFFFFF;
	if (ix <= 0x3FE921FB)
		return kernel_sin(x, z, 0);
	if (ix >= 0x7FF00000)
		return x - x;
	n = rem_pio2(x, y);
	switch (n & 3) {
	case 0: return kernel_sin(y[0], y[1], 1);
	case 1: return kernel_cos(y[0], y[1]);
	case 2: return -kernel_sin(y[0], y[1], 1);
	default: return -kernel_cos(y[0], y[1]);
	}
}
