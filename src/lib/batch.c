/*
 * batch.c - structure-of-arrays loops over every method, and the
 * out-of-line scalar copies that the registry points to.
 *
 * Each batch loop calls the header's static inline kernel, so it computes
 * the same IEEE operations in the same order as the scalar function: with
 * -ffp-contract=off (no FMA contraction) the vectorized loop gives the same
 * bits as the scalar code.  tests/test_lib.c checks that, per method.
 *
 * Run-time ISA dispatch: on x86-64 with GCC, each loop is compiled three
 * times (target_clones: AVX-512F, AVX2, baseline SSE2) and an ifunc
 * resolver picks the widest one the CPU has.  The instruction set never
 * changes the bits, because none of these clones may contract into FMA and
 * IEEE +, -, *, /, sqrt are correctly rounded at every width.  The one
 * exception by design is the _rsqrt family: rsqrtps is an approximation
 * whose table is the CPU vendor's (Intel and AMD differ in the last bits),
 * but not the clone's, since every clone issues the same SSE rsqrtps
 * (VEX-encoded under AVX) and never the AVX-512 rsqrt14.
 * Two float kernels (naive, hughes_moeller) dispatch by hand instead, to
 * run 256-bit code on AVX-512 CPUs: see ONB__BATCH_F_256 below.
 *
 * One object per batch function (split.h): every method gets the plain
 * loop over its inline kernel, and the table at the end names the few that
 * need another; onb_batch_isa is in the common object.
 */
#include "split.h"
#if ONB_HAVE_HW_RSQRT
#include <xmmintrin.h>
#endif

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(ONB_NO_CLONES)
#define ONB__CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#define ONB__HAVE_CLONES 1
#else
#define ONB__CLONES
#define ONB__HAVE_CLONES 0
#endif

/* Block size of the three-pass loops (pre, rsqrt, post): small enough for
   the stack and L1, large enough to amortize the loop overhead. */
#define ONB__BLOCK 256

#if ONB__COMMON
const char *onb_batch_isa(void)
{
#if ONB__HAVE_CLONES
	__builtin_cpu_init();
	if (__builtin_cpu_supports("avx512f"))
		return "avx512f";
	if (__builtin_cpu_supports("avx2"))
		return "avx2";
	return "sse2";
#elif defined(__x86_64__)
	return "sse2";
#else
	return "generic";
#endif
}
#endif

/* Hardware rsqrt over a block, four lanes at a time, with the same
   instruction as the scalar onb__hw_rsqrtf (rsqrtss and rsqrtps share one
   table), so a batch gives the scalar bits. */
static inline void onb__rsqrt_blockf(size_t m, const float *x, float *y)
{
	size_t j = 0;
#if ONB_HAVE_HW_RSQRT
	for (; j + 4 <= m; j += 4)
		_mm_storeu_ps(y + j, _mm_rsqrt_ps(_mm_loadu_ps(x + j)));
#endif
	for (; j < m; j++)
		y[j] = onb__hw_rsqrtf(x[j]);
}

/* Methods without an approximate rsqrt: one fused loop over the inline
   kernel. */
#define ONB__LOOP_D(m)                                                         \
	{                                                                          \
		size_t i;                                                              \
		for (i = 0; i < count; i++) {                                          \
			onb_vec3 n, b1, b2;                                                \
			n.x = nx[i]; n.y = ny[i]; n.z = nz[i];                             \
			onb_##m(n, &b1, &b2);                                              \
			b1x[i] = b1.x; b1y[i] = b1.y; b1z[i] = b1.z;                       \
			b2x[i] = b2.x; b2y[i] = b2.y; b2z[i] = b2.z;                       \
		}                                                                      \
	}
#define ONB__LOOP_F(m)                                                         \
	{                                                                          \
		size_t i;                                                              \
		for (i = 0; i < count; i++) {                                          \
			onb_vec3f n, b1, b2;                                               \
			n.x = nx[i]; n.y = ny[i]; n.z = nz[i];                             \
			onb_##m##f(n, &b1, &b2);                                           \
			b1x[i] = b1.x; b1y[i] = b1.y; b1z[i] = b1.z;                       \
			b2x[i] = b2.x; b2y[i] = b2.y; b2z[i] = b2.z;                       \
		}                                                                      \
	}
#define ONB__ARGS_D size_t count,                                              \
		const double *restrict nx, const double *restrict ny,                  \
		const double *restrict nz, double *restrict b1x,                       \
		double *restrict b1y, double *restrict b1z, double *restrict b2x,      \
		double *restrict b2y, double *restrict b2z
#define ONB__ARGS_F size_t count,                                              \
		const float *restrict nx, const float *restrict ny,                    \
		const float *restrict nz, float *restrict b1x, float *restrict b1y,    \
		float *restrict b1z, float *restrict b2x, float *restrict b2y,         \
		float *restrict b2z
#define ONB__BATCH_SIMPLE_D(m)                                                 \
	ONB__CLONES void onb_##m##_batch(ONB__ARGS_D) ONB__LOOP_D(m)
#define ONB__BATCH_SIMPLE_F(m)                                                 \
	ONB__CLONES void onb_##m##_batchf(ONB__ARGS_F) ONB__LOOP_F(m)
#define ONB__BATCH_SIMPLE(m) ONB__BATCH_SIMPLE_D(m) ONB__BATCH_SIMPLE_F(m)

/* naive and hughes_moeller in float with the libm normalization,
   (float)(1.0/sqrt((double)x)), spend their time in double sqrt and
   division on converted lanes.  On AVX-512 CPUs these run faster with
   256-bit vectors than with 512-bit ones: on the project's machine
   (onbstudy bench, 4 interleaved runs) the 512-bit clone ran at 0.90-0.93
   of the -march=native yardstick, this code at 0.98-1.02, about 8% faster.
   In double, and for the other methods, 512 bits win or tie (stark and the
   _rsqrt variants lose up to 40% at 256).  target_clones cannot carry
   -mprefer-vector-width, so these two dispatch by hand on the same CPU
   tests as the clones.  Same loop, same operations: same bits. */
#if ONB__HAVE_CLONES
#define ONB__BATCH_F_256(m)                                                    \
	__attribute__((target("avx512f,prefer-vector-width=256"), noinline))      \
	static void onb__##m##_batchf_avx512f(ONB__ARGS_F) ONB__LOOP_F(m)          \
	__attribute__((target("avx2"), noinline))                                 \
	static void onb__##m##_batchf_avx2(ONB__ARGS_F) ONB__LOOP_F(m)             \
	__attribute__((noinline))                                                 \
	static void onb__##m##_batchf_default(ONB__ARGS_F) ONB__LOOP_F(m)          \
	void onb_##m##_batchf(ONB__ARGS_F)                                         \
	{                                                                          \
		__builtin_cpu_init();                                                  \
		if (__builtin_cpu_supports("avx512f"))                                 \
			onb__##m##_batchf_avx512f(count, nx, ny, nz, b1x, b1y, b1z, b2x, b2y, b2z); \
		else if (__builtin_cpu_supports("avx2"))                               \
			onb__##m##_batchf_avx2(count, nx, ny, nz, b1x, b1y, b1z, b2x, b2y, b2z); \
		else                                                                   \
			onb__##m##_batchf_default(count, nx, ny, nz, b1x, b1y, b1z, b2x, b2y, b2z); \
	}
#else
#define ONB__BATCH_F_256(m) ONB__BATCH_SIMPLE_F(m)
#endif

/* The float-only methods (this project's, at the accuracy floor).  duff_wide converts to double and
   back: an ordinary clone loop.  duff_comp calls fmaf(), a libm call
   unless the code is compiled for an FMA target, so it dispatches by hand
   to clones built with FMA (AVX-512F + FMA, AVX2 + FMA) when the CPU has
   it, and to the baseline loop (libm fmaf) otherwise.  -ffp-contract=off
   still holds in the FMA clones: only the explicit fmaf() calls fuse, and
   fma is correctly rounded, so every clone gives the scalar bits. */
#if ONB__HAVE_CLONES
#define ONB__BATCH_DUFF_COMP_F \
__attribute__((target("avx512f,fma"), noinline))                               \
static void onb__duff_comp_batchf_avx512f(ONB__ARGS_F) ONB__LOOP_F(duff_comp)  \
__attribute__((target("avx2,fma"), noinline))                                  \
static void onb__duff_comp_batchf_avx2(ONB__ARGS_F) ONB__LOOP_F(duff_comp)     \
__attribute__((noinline))                                                      \
static void onb__duff_comp_batchf_default(ONB__ARGS_F) ONB__LOOP_F(duff_comp)  \
void onb_duff_comp_batchf(ONB__ARGS_F)                                         \
{                                                                              \
	__builtin_cpu_init();                                                         \
	if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("fma"))       \
		onb__duff_comp_batchf_avx512f(count, nx, ny, nz, b1x, b1y, b1z, b2x, b2y, b2z); \
	else if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))     \
		onb__duff_comp_batchf_avx2(count, nx, ny, nz, b1x, b1y, b1z, b2x, b2y, b2z); \
	else                                                                          \
		onb__duff_comp_batchf_default(count, nx, ny, nz, b1x, b1y, b1z, b2x, b2y, b2z); \
}
#else
#define ONB__BATCH_DUFF_COMP_F ONB__BATCH_SIMPLE_F(duff_comp)
#endif

/* Methods whose kernels call fma() or fmaf() (jolt_fma: the fused cross
   product of Jolt's default x86 build): dispatched as duff_comp is, to
   clones built for an FMA target when the CPU has one, else to the
   baseline loop (libm fma).  fma is correctly rounded, so every clone
   gives the scalar bits. */
#if ONB__HAVE_CLONES
#define ONB__FMA_DISPATCH(m, suf, P)                                           \
__attribute__((target("avx512f,fma"), noinline))                               \
static void onb__##m##_batch##suf##_avx512f(ONB__ARGS_##P) ONB__LOOP_##P(m)    \
__attribute__((target("avx2,fma"), noinline))                                  \
static void onb__##m##_batch##suf##_avx2(ONB__ARGS_##P) ONB__LOOP_##P(m)       \
__attribute__((noinline))                                                      \
static void onb__##m##_batch##suf##_default(ONB__ARGS_##P) ONB__LOOP_##P(m)    \
void onb_##m##_batch##suf(ONB__ARGS_##P)                                       \
{                                                                              \
	__builtin_cpu_init();                                                  \
	if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("fma")) \
		onb__##m##_batch##suf##_avx512f(count, nx, ny, nz, b1x, b1y, b1z, b2x, b2y, b2z); \
	else if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) \
		onb__##m##_batch##suf##_avx2(count, nx, ny, nz, b1x, b1y, b1z, b2x, b2y, b2z); \
	else                                                                   \
		onb__##m##_batch##suf##_default(count, nx, ny, nz, b1x, b1y, b1z, b2x, b2y, b2z); \
}
#define ONB__BATCH_FMA_D(m) ONB__FMA_DISPATCH(m, , D)
#define ONB__BATCH_FMA_F(m) ONB__FMA_DISPATCH(m, f, F)
#else
#define ONB__BATCH_FMA_D(m) ONB__BATCH_SIMPLE_D(m)
#define ONB__BATCH_FMA_F(m) ONB__BATCH_SIMPLE_F(m)
#endif

/* Methods with the hardware rsqrt: three passes per block, because GCC
   cannot vectorize a loop around the scalar rsqrtss intrinsic.  Pass 1
   builds the unnormalized vector and its squared length, pass 2 runs
   rsqrtps, pass 3 applies the optional Newton step, scales and crosses.
   Each pass calls the same inline pieces as the scalar kernel. */
#define ONB__BATCH_RSQRT_D(fam, var, newton)                                   \
	ONB__CLONES void onb_##fam##var##_batch(size_t count,                      \
		const double *restrict nx, const double *restrict ny,                  \
		const double *restrict nz, double *restrict b1x,                       \
		double *restrict b1y, double *restrict b1z, double *restrict b2x,      \
		double *restrict b2y, double *restrict b2z)                            \
	{                                                                          \
		double ux[ONB__BLOCK], uy[ONB__BLOCK], uz[ONB__BLOCK], l2[ONB__BLOCK]; \
		float l2f[ONB__BLOCK], sf[ONB__BLOCK];                                 \
		size_t i0, j;                                                          \
		for (i0 = 0; i0 < count; i0 += ONB__BLOCK) {                           \
			size_t m = count - i0 < ONB__BLOCK ? count - i0 : ONB__BLOCK;      \
			for (j = 0; j < m; j++) {                                          \
				onb_vec3 n, u;                                                 \
				n.x = nx[i0 + j]; n.y = ny[i0 + j]; n.z = nz[i0 + j];          \
				l2[j] = onb__##fam##_pre(n, &u);                               \
				ux[j] = u.x; uy[j] = u.y; uz[j] = u.z;                         \
				l2f[j] = (float)l2[j];                                         \
			}                                                                  \
			onb__rsqrt_blockf(m, l2f, sf);                                     \
			for (j = 0; j < m; j++) {                                          \
				onb_vec3 n, u, b1, b2;                                         \
				double s = (double)sf[j];                                      \
				if (newton) s = onb__newton(l2[j], s);                         \
				n.x = nx[i0 + j]; n.y = ny[i0 + j]; n.z = nz[i0 + j];          \
				u.x = ux[j]; u.y = uy[j]; u.z = uz[j];                         \
				onb__##fam##_post(n, u, s, &b1, &b2);                          \
				b1x[i0 + j] = b1.x; b1y[i0 + j] = b1.y; b1z[i0 + j] = b1.z;    \
				b2x[i0 + j] = b2.x; b2y[i0 + j] = b2.y; b2z[i0 + j] = b2.z;    \
			}                                                                  \
		}                                                                      \
	}
#define ONB__BATCH_RSQRT_F(fam, var, newton)                                   \
	ONB__CLONES void onb_##fam##var##_batchf(size_t count,                     \
		const float *restrict nx, const float *restrict ny,                    \
		const float *restrict nz, float *restrict b1x, float *restrict b1y,    \
		float *restrict b1z, float *restrict b2x, float *restrict b2y,         \
		float *restrict b2z)                                                   \
	{                                                                          \
		float ux[ONB__BLOCK], uy[ONB__BLOCK], uz[ONB__BLOCK], l2[ONB__BLOCK];  \
		float sf[ONB__BLOCK];                                                  \
		size_t i0, j;                                                          \
		for (i0 = 0; i0 < count; i0 += ONB__BLOCK) {                           \
			size_t m = count - i0 < ONB__BLOCK ? count - i0 : ONB__BLOCK;      \
			for (j = 0; j < m; j++) {                                          \
				onb_vec3f n, u;                                                \
				n.x = nx[i0 + j]; n.y = ny[i0 + j]; n.z = nz[i0 + j];          \
				l2[j] = onb__##fam##_pref(n, &u);                              \
				ux[j] = u.x; uy[j] = u.y; uz[j] = u.z;                         \
			}                                                                  \
			onb__rsqrt_blockf(m, l2, sf);                                      \
			for (j = 0; j < m; j++) {                                          \
				onb_vec3f n, u, b1, b2;                                        \
				float s = sf[j];                                               \
				if (newton) s = onb__newtonf(l2[j], s);                        \
				n.x = nx[i0 + j]; n.y = ny[i0 + j]; n.z = nz[i0 + j];          \
				u.x = ux[j]; u.y = uy[j]; u.z = uz[j];                         \
				onb__##fam##_postf(n, u, s, &b1, &b2);                         \
				b1x[i0 + j] = b1.x; b1y[i0 + j] = b1.y; b1z[i0 + j] = b1.z;    \
				b2x[i0 + j] = b2.x; b2y[i0 + j] = b2.y; b2z[i0 + j] = b2.z;    \
			}                                                                  \
		}                                                                      \
	}

/* Which macro defines each batch function.  Every method of onb.h's lists
   gets the plain loop over its inline kernel (ONB__BATCH_SIMPLE_D/_F) with
   no line here.  The few that need another kernel have their own: listed
   as `#define ONB__OWN_NAME ~,`, with both of their kernels (one, float
   only) named by ONB__BD_NAME (double) and ONB__BF_NAME (float).
   ONB__BD(m) reads the list: for a listed m, ONB__OWN_m puts `~,` before
   ONB__OWN_D, which ONB__SECOND then picks, and ONB__OWN_D(m) is
   ONB__BD_m; for any other m the first argument is one run of tokens and
   ONB__SECOND picks the plain loop.  (A form cppcheck's preprocessor
   follows too: scripts/harden.sh runs it on this file.) */
#define ONB__OWN_naive                  ~,
#define ONB__OWN_naive_rsqrt            ~,
#define ONB__OWN_naive_rsqrt_nr         ~,
#define ONB__OWN_hughes_moeller         ~,
#define ONB__OWN_hughes_moeller_rsqrt   ~,
#define ONB__OWN_hughes_moeller_rsqrt_nr ~,
#define ONB__OWN_duff_comp              ~,
#define ONB__OWN_jolt_fma               ~,
#define ONB__BD_naive                   ONB__BATCH_SIMPLE_D(naive)
#define ONB__BF_naive                   ONB__BATCH_F_256(naive)
#define ONB__BD_naive_rsqrt             ONB__BATCH_RSQRT_D(naive, _rsqrt, 0)
#define ONB__BF_naive_rsqrt             ONB__BATCH_RSQRT_F(naive, _rsqrt, 0)
#define ONB__BD_naive_rsqrt_nr          ONB__BATCH_RSQRT_D(naive, _rsqrt_nr, 1)
#define ONB__BF_naive_rsqrt_nr          ONB__BATCH_RSQRT_F(naive, _rsqrt_nr, 1)
#define ONB__BD_hughes_moeller          ONB__BATCH_SIMPLE_D(hughes_moeller)
#define ONB__BF_hughes_moeller          ONB__BATCH_F_256(hughes_moeller)
#define ONB__BD_hughes_moeller_rsqrt    ONB__BATCH_RSQRT_D(hughes_moeller, _rsqrt, 0)
#define ONB__BF_hughes_moeller_rsqrt    ONB__BATCH_RSQRT_F(hughes_moeller, _rsqrt, 0)
#define ONB__BD_hughes_moeller_rsqrt_nr ONB__BATCH_RSQRT_D(hughes_moeller, _rsqrt_nr, 1)
#define ONB__BF_hughes_moeller_rsqrt_nr ONB__BATCH_RSQRT_F(hughes_moeller, _rsqrt_nr, 1)
#define ONB__BF_duff_comp               ONB__BATCH_DUFF_COMP_F
#define ONB__BD_jolt_fma                ONB__BATCH_FMA_D(jolt_fma)
#define ONB__BF_jolt_fma                ONB__BATCH_FMA_F(jolt_fma)
#define ONB__OWN_D(m) ONB__BD_##m
#define ONB__OWN_F(m) ONB__BF_##m
#define ONB__SECOND_(a, b, ...) b
#define ONB__SECOND(...) ONB__SECOND_(__VA_ARGS__)
#define ONB__BD(m) ONB__SECOND(ONB__OWN_##m ONB__OWN_D, ONB__BATCH_SIMPLE_D, ~)(m)
#define ONB__BF(m) ONB__SECOND(ONB__OWN_##m ONB__OWN_F, ONB__BATCH_SIMPLE_F, ~)(m)
ONB__SPLIT(ONB__BD, ONB__BF)
