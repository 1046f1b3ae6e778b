/*
 * bench_calls.c - per-call cost of the static inline methods, as a
 * renderer's shading loop sees it: one loop per method and precision,
 * generated from the ONB_METHOD_LIST X-macro of onb.h, each calling the
 * header's inline function (never the registry's out-of-line copy).
 *
 * Built with the study's flags (-O3, the baseline -march of the compiler):
 * the compiler may vectorize the throughput loops over the array of
 * structs, as it would in a renderer built the same way.  The functions
 * are not static, so that `bench_vector_width` can find their symbols.
 */
#include "bench/bench_calls.h"

/* Latency chain: the next input is in[i] + t with t = (b1.x + b2.x) * 0,
   an exact zero (the inputs are finite, so the outputs are, or the sum is
   NaN and so is every later input, which the checksum then shows).  With
   no -ffast-math, x * 0 cannot be folded, so each call waits for the
   previous one: add + mul + add (about 12 cycles) per call on top of the
   method, which the "chain" pseudo-method measures by itself.  b1.x and
   b2.x together cover the longest path of every method here (the cross
   product is in b2 for naive-like methods, in b1 for hughes_moeller and
   rtow; the division or square root feeds both). */
/* The double loops of method m: throughput, then latency. */
#define BENCH_CALLS_D(m)                                                        \
	void bench_tp_##m(size_t n, const onb_vec3 *in, bench_pair *out);           \
	void bench_tp_##m(size_t n, const onb_vec3 *in, bench_pair *out)            \
	{                                                                           \
		size_t i;                                                               \
		for (i = 0; i < n; i++)                                                 \
			onb_##m(in[i], &out[i].b1, &out[i].b2);                             \
	}                                                                           \
	double bench_lat_##m(size_t n, const onb_vec3 *in);                         \
	double bench_lat_##m(size_t n, const onb_vec3 *in)                          \
	{                                                                           \
		onb_vec3 b1 = { 0.0, 0.0, 0.0 }, b2 = { 0.0, 0.0, 0.0 }, v;             \
		double s = 0.0;                                                         \
		size_t i;                                                               \
		for (i = 0; i < n; i++) {                                               \
			const double t = (b1.x + b2.x) * 0.0;                               \
			v.x = in[i].x + t; v.y = in[i].y + t; v.z = in[i].z + t;            \
			onb_##m(v, &b1, &b2);                                               \
			s += ((b1.x + b1.y) + b1.z) + ((b2.x + b2.y) + b2.z);               \
		}                                                                       \
		return s;                                                               \
	}
/* The float loops of method m (alone for the float-only methods). */
#define BENCH_CALLS_F(m)                                                        \
	void bench_tp_##m##f(size_t n, const onb_vec3f *in, bench_pairf *out);      \
	void bench_tp_##m##f(size_t n, const onb_vec3f *in, bench_pairf *out)       \
	{                                                                           \
		size_t i;                                                               \
		for (i = 0; i < n; i++)                                                 \
			onb_##m##f(in[i], &out[i].b1, &out[i].b2);                          \
	}                                                                           \
	double bench_lat_##m##f(size_t n, const onb_vec3f *in);                     \
	double bench_lat_##m##f(size_t n, const onb_vec3f *in)                      \
	{                                                                           \
		onb_vec3f b1 = { 0.0f, 0.0f, 0.0f }, b2 = { 0.0f, 0.0f, 0.0f }, v;      \
		double s = 0.0;                                                         \
		size_t i;                                                               \
		for (i = 0; i < n; i++) {                                               \
			const float t = (b1.x + b2.x) * 0.0f;                               \
			v.x = in[i].x + t; v.y = in[i].y + t; v.z = in[i].z + t;            \
			onb_##m##f(v, &b1, &b2);                                            \
			s += (((double)b1.x + b1.y) + b1.z) + (((double)b2.x + b2.y) + b2.z); \
		}                                                                       \
		return s;                                                               \
	}
/* The binary16 loops of method m: libonb's out-of-line onb_NAMEh. */
#if ONB_HAVE_HALF
/* The loops' own conversions (the latency chain's) with F16C where the CPU
   has it, as libonb's half kernels have (half.c): without it GCC calls
   libgcc for each, and the chain alone cost 51 ns.  Two copies of each
   loop (SUFFIX _f16c, _plain) and the entry picks one before it loops. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(ONB_NO_CLONES)
#define BENCH_F16C_ATTR __attribute__((target("f16c"), noinline))
static int bench_f16c(void)
{
	__builtin_cpu_init();
	return __builtin_cpu_supports("f16c") != 0;
}
#else
#define BENCH_F16C_ATTR __attribute__((noinline))
static int bench_f16c(void) { return 0; }
#endif
#define BENCH_LOOPS_H(m, SUFFIX, ATTR)                                          \
	void bench_tp_##m##h##SUFFIX(size_t n, const void *vin, void *vout);        \
	ATTR void bench_tp_##m##h##SUFFIX(size_t n, const void *vin, void *vout)    \
	{                                                                           \
		const onb_vec3h *in = vin;                                              \
		bench_pairh *out = vout;                                                \
		size_t i;                                                               \
		for (i = 0; i < n; i++)                                                 \
			onb_##m##h(in[i], &out[i].b1, &out[i].b2);                          \
	}                                                                           \
	double bench_lat_##m##h##SUFFIX(size_t n, const void *vin);                 \
	ATTR double bench_lat_##m##h##SUFFIX(size_t n, const void *vin)             \
	{                                                                           \
		const onb_vec3h *in = vin;                                              \
		onb_vec3h b1, b2, v;                                                    \
		double s = 0.0;                                                         \
		size_t i;                                                               \
		b1.x = b1.y = b1.z = b2.x = b2.y = b2.z = (onb_half)0.0f;               \
		for (i = 0; i < n; i++) {                                               \
			const float t = ((float)b1.x + (float)b2.x) * 0.0f;                 \
			v.x = (onb_half)((float)in[i].x + t);                               \
			v.y = (onb_half)((float)in[i].y + t);                               \
			v.z = (onb_half)((float)in[i].z + t);                               \
			onb_##m##h(v, &b1, &b2);                                            \
			s += (((double)b1.x + (double)b1.y) + (double)b1.z) +               \
			     (((double)b2.x + (double)b2.y) + (double)b2.z);                \
		}                                                                       \
		return s;                                                               \
	}
#define BENCH_CALLS_H(m)                                                        \
	BENCH_LOOPS_H(m, _f16c, BENCH_F16C_ATTR)                                    \
	BENCH_LOOPS_H(m, _plain, __attribute__((noinline)))                         \
	static void bench_tp_##m##h(size_t n, const void *in, void *out)            \
	{                                                                           \
		if (bench_f16c())                                                       \
			bench_tp_##m##h_f16c(n, in, out);                                   \
		else                                                                    \
			bench_tp_##m##h_plain(n, in, out);                                  \
	}                                                                           \
	static double bench_lat_##m##h(size_t n, const void *in)                    \
	{                                                                           \
		return bench_f16c() ? bench_lat_##m##h_f16c(n, in) : bench_lat_##m##h_plain(n, in); \
	}
#define BENCH_H_FNS(m) , bench_tp_##m##h, bench_lat_##m##h
#else
#define BENCH_CALLS_H(m)
#define BENCH_H_FNS(m) , NULL, NULL
#endif
/* Both precisions (and binary16). */
#define BENCH_CALLS(m) BENCH_CALLS_D(m) BENCH_CALLS_F(m) BENCH_CALLS_H(m)
#define BENCH_CALLS_FH(m) BENCH_CALLS_F(m) BENCH_CALLS_H(m)

/* The pseudo-method of the chain alone: b1 = b2 = n. */
static inline void onb_chain (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { *b1 = n; *b2 = n; }
static inline void onb_chainf(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { *b1 = n; *b2 = n; }
#if ONB_HAVE_HALF
static inline void onb_chainh(onb_vec3h n, onb_vec3h *b1, onb_vec3h *b2) { *b1 = n; *b2 = n; }
#endif

ONB_METHOD_LIST(BENCH_CALLS)
BENCH_CALLS(chain)

ONB_FLOAT_METHOD_LIST(BENCH_CALLS_FH)

#define BENCH_ROW(m) { #m, bench_tp_##m, bench_tp_##m##f, bench_lat_##m, bench_lat_##m##f BENCH_H_FNS(m) },
static const bench_call bench_calls[] = {
	ONB_METHOD_LIST(BENCH_ROW)
	BENCH_ROW(chain)
#define BENCH_ROW_F(m) { #m, NULL, bench_tp_##m##f, NULL, bench_lat_##m##f BENCH_H_FNS(m) },
	ONB_FLOAT_METHOD_LIST(BENCH_ROW_F)
};

const bench_call *bench_call_find(const char *name)
{
	size_t i;
	for (i = 0; i < sizeof bench_calls / sizeof bench_calls[0]; i++)
		if (strcmp(bench_calls[i].name, name) == 0)
			return &bench_calls[i];
	return NULL;
}

const char *bench_calls_isa(void)
{
#if defined(__AVX512F__)
	return "inline-avx512f";
#elif defined(__AVX2__)
	return "inline-avx2";
#elif defined(__SSE2__)
	return "inline-sse2";
#else
	return "inline-generic";
#endif
}

/* The sum of the six outputs of every call, in index order, in double. */
double bench_pair_checksum(size_t n, const bench_pair *p)
{
	double s = 0.0;
	size_t i;
	for (i = 0; i < n; i++)
		s += ((p[i].b1.x + p[i].b1.y) + p[i].b1.z) + ((p[i].b2.x + p[i].b2.y) + p[i].b2.z);
	return s;
}

double bench_pair_checksumf(size_t n, const bench_pairf *p)
{
	double s = 0.0;
	size_t i;
	for (i = 0; i < n; i++)
		s += (((double)p[i].b1.x + p[i].b1.y) + p[i].b1.z) + (((double)p[i].b2.x + p[i].b2.y) + p[i].b2.z);
	return s;
}

double bench_pair_checksumh(size_t n, const void *vp)
{
	double s = 0.0;
#if ONB_HAVE_HALF
	const bench_pairh *p = vp;
	size_t i;
	for (i = 0; i < n; i++)
		s += (((double)p[i].b1.x + (double)p[i].b1.y) + (double)p[i].b1.z) +
		     (((double)p[i].b2.x + (double)p[i].b2.y) + (double)p[i].b2.z);
#else
	(void)n;
	(void)vp;
#endif
	return s;
}
