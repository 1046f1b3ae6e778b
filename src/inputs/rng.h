/*
 * rng.h - counter-based random numbers.
 *
 * Every random number in the study is a pure function of (seed, stream,
 * index): sample i of a distribution is the same value whatever the
 * thread count, the chunk order or the shard that computes it.  The mixer
 * is SplitMix64's finalizer (Steele, Lea & Flood 2014) applied to a
 * Weyl-sequence counter, chained over the three keys.
 */
#ifndef ONB_RNG_H
#define ONB_RNG_H

#include <stdint.h>

/* SplitMix64's Weyl increment (2^64 / the golden ratio), and its
   finalizer (a bijection of 64-bit words): the one definition in src/. */
#define RNG_GOLDEN 0x9e3779b97f4a7c15u
#define RNG_FMIX_M1 0xbf58476d1ce4e5b9u

static inline uint64_t rng_fmix64(uint64_t z)
{
	z = (z ^ (z >> 30)) * RNG_FMIX_M1;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return z ^ (z >> 31);
}

/* One SplitMix64 step from state z. */
static inline uint64_t rng_mix64(uint64_t z)
{
	return rng_fmix64(z + RNG_GOLDEN);
}

static inline uint64_t rng_u64(uint64_t seed, uint64_t stream, uint64_t index)
{
	return rng_mix64(rng_mix64(rng_mix64(seed) ^ stream) ^ index);
}

/* Uniform in [0, 1), 53 random bits. */
static inline double rng_u01(uint64_t seed, uint64_t stream, uint64_t index)
{
	return (double)(rng_u64(seed, stream, index) >> 11) * 0x1p-53;
}

#endif
