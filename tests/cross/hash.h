/* hash.h - FNV-1a 64 over values' bit patterns, independent of the host's
   byte order (each value enters as its integer bits, low byte first).
   Every NaN enters as one pattern: the sign and payload of a NaN differ
   between CPUs (x86-64's default NaN has the sign bit set, arm64's not)
   and carry no value. */
#ifndef CROSS_HASH_H
#define CROSS_HASH_H
#include <stdint.h>
#include <string.h>
#define FNV_INIT UINT64_C(0xcbf29ce484222325)
static inline uint64_t fnv_u64(uint64_t h, uint64_t v, int bytes)
{
	int i;
	for (i = 0; i < bytes; i++) {
		h ^= (v >> (8 * i)) & 0xffu;
		h *= UINT64_C(0x100000001b3);
	}
	return h;
}
static inline uint64_t fnv_d(uint64_t h, double x)
{
	uint64_t u;
	memcpy(&u, &x, sizeof u);
	if (x != x)
		u = UINT64_C(0x7ff8000000000000);
	return fnv_u64(h, u, 8);
}
static inline uint64_t fnv_f(uint64_t h, float x)
{
	uint32_t u;
	memcpy(&u, &x, sizeof u);
	if (x != x)
		u = 0x7fc00000u;
	return fnv_u64(h, u, 4);
}
#endif
