/*
 * seeds_get.c - seed_bound_get's once-per-process cache, the CPU the
 * rsqrtss bound belongs to, and what the seeds do outside their domain.
 */
#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#define HAVE_CPUID 1
#else
#define HAVE_CPUID 0
#endif
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>
#include "seeds.h"

static seed_bound cache[NSEED];
static int status[NSEED];
static pthread_once_t once[NSEED] = { PTHREAD_ONCE_INIT, PTHREAD_ONCE_INIT, PTHREAD_ONCE_INIT };

/* rsqrtss is this CPU's table: every normal float is measured.  The bit
   trick's seed depends on the exponent only through its parity (seeds.c
   proves s(4x) = s(x) / 2 exactly for every normal float), so the base
   binade pair (eb 1, 2) holds every value of s sqrt(x) - 1 that the other
   252 binades hold: the same bound and worst input as the full scan, in
   1/127 of the time (test_seeds checks the periodicity by measurement). */
static void compute(seed_kind k)
{
	if (k == SEED_INVSQRT_D)
		status[k] = seed_prove_double(1e-12, &cache[k], NULL);
	else if (k == SEED_RSQRTSS)
		status[k] = seed_scan_float(k, 1, 254, &cache[k], NULL);
	else if ((status[k] = seed_scan_float(k, 1, 2, &cache[k], NULL)) == 0) {
		cache[k].x_lo = 0x1p-126;          /* every positive normal float */
		cache[k].x_hi = 0x1.fffffep127;
		cache[k].how = "0x5f3759df - (i >> 1), the binades eb 1 and 2 (s(4x) = s(x) / 2 exactly: "
		               "every positive normal float has their values), extremes of s^2 x - 1 from exact partial products";
	}
}
static void once_rsqrtss(void)   { compute(SEED_RSQRTSS); }
static void once_invsqrt_f(void) { compute(SEED_INVSQRT_F); }
static void once_invsqrt_d(void) { compute(SEED_INVSQRT_D); }

int seed_bound_get(seed_kind k, seed_bound *out)
{
	static void (*const init[NSEED])(void) = { once_rsqrtss, once_invsqrt_f, once_invsqrt_d };
	if ((unsigned)k >= NSEED || !out) {
		fprintf(stderr, "seed_bound_get: bad seed kind %d\n", (int)k);
		return -1;
	}
	if (pthread_once(&once[k], init[k]) != 0)
		return -1;
	if (status[k] != 0)
		return -1;
	*out = cache[k];
	return 0;
}

static char cpu_buf[200];

/* Vendor, brand string and family/model/stepping, decoded as the SDM and
   AMD's CPUID guide say (extended family only when family is 0xf). */
static void cpu_fill(void)
{
#if HAVE_CPUID
	unsigned r[12] = { 0 }, a = 0, b = 0, c = 0, d = 0, fam, mod, base;
	char vendor[13] = { 0 }, brand[49] = { 0 };
	__get_cpuid(0, &a, &b, &c, &d);
	memcpy(vendor, &b, 4); memcpy(vendor + 4, &d, 4); memcpy(vendor + 8, &c, 4);
	__get_cpuid(1, &a, &b, &c, &d);
	base = (a >> 8) & 0xf;
	fam = base + (base == 0xf ? (a >> 20) & 0xff : 0);
	mod = ((a >> 4) & 0xf) | ((base >= 6 ? (a >> 16) & 0xf : 0) << 4);
	for (unsigned j = 0; j < 3; j++)
		__get_cpuid(0x80000002u + j, &r[4 * j], &r[4 * j + 1], &r[4 * j + 2], &r[4 * j + 3]);
	memcpy(brand, r, 48);
	snprintf(cpu_buf, sizeof cpu_buf, "%s \"%s\" family 0x%x model 0x%x stepping %u",
		 vendor, brand, fam, mod, a & 0xf);
#else
	snprintf(cpu_buf, sizeof cpu_buf, "unknown (no CPUID on this architecture)");
#endif
}

const char *seed_cpu(void)
{
	static pthread_once_t done = PTHREAD_ONCE_INIT;
	pthread_once(&done, cpu_fill);
	return cpu_buf;
}

static void edge_line(FILE *f, const char *seed, const char *what, double x, double s)
{
	fprintf(f, "  %-9s %-18s x = %-24a seed = %-24a s*sqrt(x) - 1 = %g\n", seed, what, x, s,
		x > 0 && isfinite(x) ? s * sqrt(x) - 1.0 : NAN);
}

void seed_edge_report(FILE *f)
{
	static const float xf[4] = { 0.0f, 0x1p-149f, 0x1.fffffcp-127f, INFINITY };
	static const double xd[4] = { 0.0, 0x1p-1074, 0x1.ffffffffffffep-1023, INFINITY };
	static const char *const what[4] = { "+0", "smallest subnormal", "largest subnormal", "+inf" };
	for (int j = 0; j < 4; j++)
		edge_line(f, "rsqrtss", what[j], xf[j], seed_rsqrtss(xf[j]));
	for (int j = 0; j < 4; j++)
		edge_line(f, "invsqrt_f", what[j], xf[j], seed_invsqrt_f(xf[j]));
	for (int j = 0; j < 4; j++)
		edge_line(f, "invsqrt_d", what[j], xd[j], seed_invsqrt_d(xd[j]));
}
