/*
 * bench/bench_calls.h - the per-call cost loops of the static inline methods
 * (bench_calls.c, generated from ONB_METHOD_LIST).
 */
#ifndef ONB_BENCH_CALLS_H
#define ONB_BENCH_CALLS_H

#include <stddef.h>
#include <stdint.h>
#include "libonb/onb.h"

/* ---- the inline call loops (macro-generated in bench_calls.c) -------- */
typedef struct { onb_vec3  b1, b2; } bench_pair;
typedef struct { onb_vec3f b1, b2; } bench_pairf;
typedef struct {
	const char *name;
	/* Throughput: out[i] = method(in[i]) for i < n, independent calls to
	   the static inline function, as a shading loop over structs makes. */
	void   (*tp) (size_t n, const onb_vec3  *in, bench_pair  *out);
	void   (*tpf)(size_t n, const onb_vec3f *in, bench_pairf *out);
	/* Latency: a chain of n calls, each input in[i] plus t, where
	   t = (b1.x + b2.x) * 0 of the previous call: an exact zero the
	   compiler cannot fold, so each call waits for the last.  Returns the
	   sum of the six outputs of every call. */
	double (*lat) (size_t n, const onb_vec3  *in);
	double (*latf)(size_t n, const onb_vec3f *in);
	/* binary16 (NULL without ONB_HAVE_HALF): the same loops over onb_vec3h
	   (in) and bench_pairh (out), calling libonb's out-of-line onb_NAMEh
	   (the half kernels have no inline form); the latency chain's
	   t = ((float)b1.x + (float)b2.x) * 0 and the input + t are computed
	   in float and rounded to binary16 (exact: t = 0). */
	void   (*tph) (size_t n, const void *in, void *out);
	double (*lath)(size_t n, const void *in);
} bench_call;
#if ONB_HAVE_HALF
typedef struct { onb_vec3h b1, b2; } bench_pairh;
#endif

/* The entry of registry method `name`, or NULL.  The pseudo-method
   "chain" returns b1 = b2 = n: its latency is the cost of the chain alone. */
const bench_call *bench_call_find(const char *name);
/* The instruction set the call loops were compiled for ("inline-sse2"...). */
const char *bench_calls_isa(void);
double bench_pair_checksum (size_t n, const bench_pair  *p);
double bench_pair_checksumf(size_t n, const bench_pairf *p);
/* The same over n bench_pairh (0 without ONB_HAVE_HALF). */
double bench_pair_checksumh(size_t n, const void *p);


#endif
