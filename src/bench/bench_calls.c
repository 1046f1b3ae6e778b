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
/* Both precisions. */
#define BENCH_CALLS(m) BENCH_CALLS_D(m) BENCH_CALLS_F(m)

/* The pseudo-method of the chain alone: b1 = b2 = n. */
static inline void onb_chain (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { *b1 = n; *b2 = n; }
static inline void onb_chainf(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { *b1 = n; *b2 = n; }

ONB_METHOD_LIST(BENCH_CALLS)
BENCH_CALLS(chain)

ONB_FLOAT_METHOD_LIST(BENCH_CALLS_F)

#define BENCH_ROW(m) { #m, bench_tp_##m, bench_tp_##m##f, bench_lat_##m, bench_lat_##m##f },
static const bench_call bench_calls[] = {
	ONB_METHOD_LIST(BENCH_ROW)
	BENCH_ROW(chain)
#define BENCH_ROW_F(m) { #m, NULL, bench_tp_##m##f, NULL, bench_lat_##m##f },
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
