/*
 * yardstick.c - the benchmark's yardstick: plain hand-written SoA loops of
 * four methods' formulas, and the copy kernel of the roofline.
 *
 * The Makefile compiles this file alone with -O3 -march=native (keeping
 * FPFLAGS: no FMA contraction, no errno, no traps) and
 * -fno-tree-loop-distribute-patterns (so the copy stays a loop and does not
 * become six memcpy calls).  Each loop writes the published formula out
 * by hand, in the same operation order as onb.h, so it gives the same bits
 * as libonb (tests/test_bench.c checks) and differs from libonb's batch
 * kernel only in how it was compiled: the batch/yardstick ratio then
 * measures what run-time dispatch and the shared inline kernels cost.
 */
#include <math.h>
#include "bench/yardstick.h"

const char *bench_yardstick_isa(void)
{
#if defined(__AVX512F__)
	return "avx512f";
#elif defined(__AVX2__)
	return "avx2";
#elif defined(__SSE2__)
	return "sse2";
#else
	return "generic";
#endif
}

#define SOA_ARGS(T) size_t count, const T *restrict nx, const T *restrict ny, const T *restrict nz, \
	T *restrict b1x, T *restrict b1y, T *restrict b1z, T *restrict b2x, T *restrict b2y, T *restrict b2z

/* The copy runs at the CPU's full vector width even where -march=native
   tunes for 256 bits (GCC does on recent Intel): whole-cache-line stores
   can skip the read-for-ownership, as libonb's 512-bit kernels' do, and a
   roofline must not be slower than the kernels it bounds for that reason. */
#if defined(__AVX512F__) && defined(__GNUC__) && !defined(__clang__)
#define BENCH_FULL_WIDTH __attribute__((target("prefer-vector-width=512")))
#else
#define BENCH_FULL_WIDTH
#endif

BENCH_FULL_WIDTH void bench_copy(SOA_ARGS(double))
{
	size_t i;
	for (i = 0; i < count; i++) {
		const double x = nx[i], y = ny[i], z = nz[i];
		b1x[i] = x; b1y[i] = y; b1z[i] = z;
		b2x[i] = x; b2y[i] = y; b2z[i] = z;
	}
}

BENCH_FULL_WIDTH void bench_copyf(SOA_ARGS(float))
{
	size_t i;
	for (i = 0; i < count; i++) {
		const float x = nx[i], y = ny[i], z = nz[i];
		b1x[i] = x; b1y[i] = y; b1z[i] = z;
		b2x[i] = x; b2y[i] = y; b2z[i] = z;
	}
}

/* binary16 bit patterns: the half roofline. */
BENCH_FULL_WIDTH void bench_copyh(SOA_ARGS(uint16_t))
{
	size_t i;
	for (i = 0; i < count; i++) {
		const uint16_t x = nx[i], y = ny[i], z = nz[i];
		b1x[i] = x; b1y[i] = y; b1z[i] = z;
		b2x[i] = x; b2y[i] = y; b2z[i] = z;
	}
}

/* Duff et al. 2017, Listing 3. */
void bench_yard_duff_branchless(SOA_ARGS(double));
void bench_yard_duff_branchless(SOA_ARGS(double))
{
	size_t i;
	for (i = 0; i < count; i++) {
		const double x = nx[i], y = ny[i], z = nz[i];
		const double sign = copysign(1.0, z);
		const double a = -1.0 / (sign + z);
		const double b = x * y * a;
		b1x[i] = 1.0 + sign * x * x * a; b1y[i] = sign * b; b1z[i] = -sign * x;
		b2x[i] = b; b2y[i] = sign + y * y * a; b2z[i] = -y;
	}
}
void bench_yard_duff_branchlessf(SOA_ARGS(float));
void bench_yard_duff_branchlessf(SOA_ARGS(float))
{
	size_t i;
	for (i = 0; i < count; i++) {
		const float x = nx[i], y = ny[i], z = nz[i];
		const float sign = copysignf(1.0f, z);
		const float a = -1.0f / (sign + z);
		const float b = x * y * a;
		b1x[i] = 1.0f + sign * x * x * a; b1y[i] = sign * b; b1z[i] = -sign * x;
		b2x[i] = b; b2y[i] = sign + y * y * a; b2z[i] = -y;
	}
}

/* Frisvad 2012, Listing 2 (t = -0.9999999). */
void bench_yard_frisvad(SOA_ARGS(double));
void bench_yard_frisvad(SOA_ARGS(double))
{
	size_t i;
	for (i = 0; i < count; i++) {
		const double x = nx[i], y = ny[i], z = nz[i];
		const double a = 1.0 / (1.0 + z);
		const double b = -x * y * a;
		const int f = z < -0.9999999;
		b1x[i] = f ? 0.0 : 1.0 - x * x * a; b1y[i] = f ? -1.0 : b; b1z[i] = f ? 0.0 : -x;
		b2x[i] = f ? -1.0 : b; b2y[i] = f ? 0.0 : 1.0 - y * y * a; b2z[i] = f ? 0.0 : -y;
	}
}
void bench_yard_frisvadf(SOA_ARGS(float));
void bench_yard_frisvadf(SOA_ARGS(float))
{
	size_t i;
	for (i = 0; i < count; i++) {
		const float x = nx[i], y = ny[i], z = nz[i];
		const float a = 1.0f / (1.0f + z);
		const float b = -x * y * a;
		const int f = z < -0.9999999f;
		b1x[i] = f ? 0.0f : 1.0f - x * x * a; b1y[i] = f ? -1.0f : b; b1z[i] = f ? 0.0f : -x;
		b2x[i] = f ? -1.0f : b; b2y[i] = f ? 0.0f : 1.0f - y * y * a; b2z[i] = f ? 0.0f : -y;
	}
}

/* Hughes & Moller 1999 as Frisvad 2012 Listing 1, rsqrt = 1/sqrt. */
void bench_yard_hughes_moeller(SOA_ARGS(double));
void bench_yard_hughes_moeller(SOA_ARGS(double))
{
	size_t i;
	for (i = 0; i < count; i++) {
		const double x = nx[i], y = ny[i], z = nz[i];
		const int c = fabs(x) > fabs(z);
		const double vx0 = c ? -y : 0.0, vy0 = c ? x : -z, vz0 = c ? 0.0 : y;
		const double s = 1.0 / sqrt(vx0 * vx0 + vy0 * vy0 + vz0 * vz0);
		const double vx = vx0 * s, vy = vy0 * s, vz = vz0 * s;
		b2x[i] = vx; b2y[i] = vy; b2z[i] = vz;
		b1x[i] = vy * z - vz * y; b1y[i] = vz * x - vx * z; b1z[i] = vx * y - vy * x;
	}
}
void bench_yard_hughes_moellerf(SOA_ARGS(float));
void bench_yard_hughes_moellerf(SOA_ARGS(float))
{
	size_t i;
	for (i = 0; i < count; i++) {
		const float x = nx[i], y = ny[i], z = nz[i];
		const int c = fabsf(x) > fabsf(z);
		const float vx0 = c ? -y : 0.0f, vy0 = c ? x : -z, vz0 = c ? 0.0f : y;
		const float s = (float)(1.0 / sqrt((double)(vx0 * vx0 + vy0 * vy0 + vz0 * vz0)));
		const float vx = vx0 * s, vy = vy0 * s, vz = vz0 * s;
		b2x[i] = vx; b2y[i] = vy; b2z[i] = vz;
		b1x[i] = vy * z - vz * y; b1y[i] = vz * x - vx * z; b1z[i] = vx * y - vy * x;
	}
}

/* naive, Frisvad 2012 Listing 1, rsqrt = 1/sqrt. */
void bench_yard_naive(SOA_ARGS(double));
void bench_yard_naive(SOA_ARGS(double))
{
	size_t i;
	for (i = 0; i < count; i++) {
		const double x = nx[i], y = ny[i], z = nz[i];
		const int c = x > 0.9;
		double ux = c ? 0.0 : 1.0, uy = c ? 1.0 : 0.0, uz = 0.0, d, s;
		d = ux * x + uy * y + uz * z;
		ux -= x * d; uy -= y * d; uz -= z * d;
		s = 1.0 / sqrt(ux * ux + uy * uy + uz * uz);
		ux *= s; uy *= s; uz *= s;
		b1x[i] = ux; b1y[i] = uy; b1z[i] = uz;
		b2x[i] = y * uz - z * uy; b2y[i] = z * ux - x * uz; b2z[i] = x * uy - y * ux;
	}
}
void bench_yard_naivef(SOA_ARGS(float));
void bench_yard_naivef(SOA_ARGS(float))
{
	size_t i;
	for (i = 0; i < count; i++) {
		const float x = nx[i], y = ny[i], z = nz[i];
		const int c = x > 0.9f;
		float ux = c ? 0.0f : 1.0f, uy = c ? 1.0f : 0.0f, uz = 0.0f, d, s;
		d = ux * x + uy * y + uz * z;
		ux -= x * d; uy -= y * d; uz -= z * d;
		s = (float)(1.0 / sqrt((double)(ux * ux + uy * uy + uz * uz)));
		ux *= s; uy *= s; uz *= s;
		b1x[i] = ux; b1y[i] = uy; b1z[i] = uz;
		b2x[i] = y * uz - z * uy; b2y[i] = z * ux - x * uz; b2z[i] = x * uy - y * ux;
	}
}

static const bench_yardstick bench_yards[] = {
	{ "naive", bench_yard_naive, bench_yard_naivef },
	{ "hughes_moeller", bench_yard_hughes_moeller, bench_yard_hughes_moellerf },
	{ "frisvad", bench_yard_frisvad, bench_yard_frisvadf },
	{ "duff_branchless", bench_yard_duff_branchless, bench_yard_duff_branchlessf },
};

const bench_yardstick *bench_yardsticks(size_t *count)
{
	*count = sizeof bench_yards / sizeof bench_yards[0];
	return bench_yards;
}
