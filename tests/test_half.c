/*
 * test_half.c - the binary16 kernels round every operation to binary16.
 *
 * Each method's onb_NAME_arrayh (src/lib/half.c: float operations rounded
 * through _Float16 casts) against its rounding model executed in binary16
 * (src/model/model.c, CM_EXEC with PREC_HALF: every operation by MPFR at
 * 11 bits, brought into binary16's exponent range with mpfr_check_range
 * and mpfr_subnormalize), bit for bit on every output component (+0 and
 * -0 apart; any NaN matches any NaN: the payload is the hardware's).  The
 * two share no arithmetic code, so a kernel that rounds once per
 * expression (as x86-64 compilers evaluate _Float16), contracts into an
 * fma, or drops or moves a rounding fails here; so does a model that does.
 *
 * Inputs (argv[1] per method, default 50000; results/half/ holds a run of
 * 10^6 per method): roundings to binary16 of unit vectors (uniform, both
 * poles down to 1 + n.z = 1e-8, the branch thresholds, the approach to
 * -x), the axes with signed zeros, components down in binary16's
 * subnormals and below 2^-24 (rounded to 0), non-unit vectors (scaled by
 * 2^-20 .. 2^16, past 65504 to infinity), and arbitrary bit patterns
 * (NaN, infinities, subnormals).  An input with a NaN component is run
 * (no crash, no undefined behaviour under the sanitizers) but not
 * compared: the models' branches compare ordered values (eigen's |x| > zp
 * where its kernel writes !(|x| <= zp)), which differ on NaN alone.
 * argv[2]: one method alone.
 * Where the compiler has no _Float16 (ONB_HAVE_HALF 0), the test checks
 * that the registry offers no half entry.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "libonb/onb.h"
#include "certify/models.h"
#include "model/model_int.h"
#include "inputs/rng.h"

#if ONB_HAVE_HALF
static double unif(uint64_t i, int k) { return (double)(rng_mix64(i * 16 + (uint64_t)k) >> 11) * 0x1p-53; }

static uint16_t hbits(double v) { onb_half h = (onb_half)v; uint16_t b; memcpy(&b, &h, sizeof b); return b; }
static double hval(uint16_t b) { onb_half h; memcpy(&h, &b, sizeof h); return (double)h; }

static void from_z(double z, double phi, double u[3])
{
	const double r = sqrt((1.0 - z) * (1.0 + z));
	u[0] = r * cos(phi);
	u[1] = r * sin(phi);
	u[2] = z;
}

/* Input i as three binary16 bit patterns. */
static void input(uint64_t i, uint16_t h[3])
{
	const double tau = 6.283185307179586;
	double u[3], phi = tau * unif(i, 1), r = unif(i, 2), s = 1.0;
	int k;
	switch (i % 10) {
	case 0: from_z(2.0 * r - 1.0, phi, u); break;
	case 1: from_z(-1.0 + pow(10.0, -8.0 * r), phi, u); break;
	case 2: from_z(1.0 - pow(10.0, -8.0 * r), phi, u); break;
	case 3: { /* |x| near 0.9, |x| = |y|, |y| near 1/2 and 1/sqrt(2) */
		const double t[4] = { 0.9, 0x1.6a09e667f3bcdp-1, 0.5, 0.9999 };
		const double x = t[i / 10 % 4] * (1.0 + (r - 0.5) * 4e-3) * (i & 32 ? -1 : 1), q = sqrt(1.0 - x * x);
		u[i / 40 % 3] = x; u[(i / 40 + 1) % 3] = q * cos(phi); u[(i / 40 + 2) % 3] = q * sin(phi);
		break;
	}
	case 4: { /* an axis, with signed zeros */
		const int a = (int)(rng_mix64(i) % 3);
		for (k = 0; k < 3; k++)
			u[k] = (rng_mix64(i + (uint64_t)k) & 1) ? -0.0 : 0.0;
		u[a] = (rng_mix64(i) & 8) ? -1.0 : 1.0;
		break;
	}
	case 5: /* the n.z = +-0 seam and the approach to -x */
		if (i & 16) { u[0] = cos(phi); u[1] = sin(phi); u[2] = (i & 32) ? -0.0 : 0.0; }
		else { double e = pow(10.0, -8.0 * r), q = sqrt(e * (2.0 - e)); u[0] = -1.0 + e; u[1] = q * cos(phi); u[2] = q * sin(phi); }
		break;
	case 6: { /* components down to binary16's subnormals and below 2^-24 */
		double a = ldexp(unif(i, 3), -(int)(rng_mix64(i) % 30)), b = ldexp(unif(i, 4), -(int)(rng_mix64(i + 1) % 30));
		const double l = sqrt(a * a + b * b);
		if (l > 1.0) { a /= l; b /= l; }   /* unit, z = +-0 (since kernels.txt's run at e92113a) */
		u[0] = (i & 16) ? -a : a; u[1] = (i & 32) ? -b : b; u[2] = (i & 64 ? -1.0 : 1.0) * sqrt(fmax(0.0, 1.0 - a * a - b * b));
		break;
	}
	case 7: from_z(2.0 * r - 1.0, phi, u); s = ldexp(1.0, (int)(rng_mix64(i) % 37) - 20); break; /* not unit */
	case 8: /* any bit patterns: NaN, infinities, subnormals, huge */
		for (k = 0; k < 3; k++)
			h[k] = (uint16_t)(rng_mix64(i * 3 + (uint64_t)k) & 0xffffu);
		return;
	default: from_z(2.0 * r - 1.0, phi, u); break;
	}
	for (k = 0; k < 3; k++)
		h[k] = hbits(u[k] * s);
}

static int same(uint16_t a, double model)
{
	const double b = model;
	if (isnan(b) || (a & 0x7fffu) > 0x7c00u)
		return isnan(b) && (a & 0x7fffu) > 0x7c00u;
	return a == hbits(b) && hval(hbits(b)) == b;   /* the model's value is a binary16 value */
}

/* Mismatches of method m over count inputs. */
static long check(const onb_method *m, const cm_method *cmm, long count, long *nan_in)
{
	cm *c = cm_new(CM_EXEC);
	long bad = 0, i;
	if (!c)
		return -1;
	for (i = 0; i < count; i++) {
		uint16_t h[3], b[6];
		double n[3];
		cv in[3], out[6];
		int k, ok = 1;
		input((uint64_t)i, h);
		for (k = 0; k < 3; k++)
			n[k] = hval(h[k]);
		m->arrayh(h, b, b + 3);
		if (isnan(n[0]) || isnan(n[1]) || isnan(n[2])) {
			(*nan_in)++;   /* run (no crash, no UB under the sanitizers), not compared */
			continue;
		}
		cm_exec_begin(c, PREC_HALF, n, in);
		cm_run(c, cmm, PREC_HALF, in, out);
		for (k = 0; k < 6; k++)
			ok &= same(b[k], cm_value(c, out[k]));
		if (cm_failed(c))
			ok = 0;
		if (!ok && bad++ < 3)
			printf("  %s half: n = (%a, %a, %a) [%04x %04x %04x]: kernel b1 (%a, %a, %a) b2 (%a, %a, %a), model b1 (%a, %a, %a) b2 (%a, %a, %a)\n",
			       m->name, n[0], n[1], n[2], h[0], h[1], h[2], hval(b[0]), hval(b[1]), hval(b[2]), hval(b[3]), hval(b[4]), hval(b[5]),
			       cm_value(c, out[0]), cm_value(c, out[1]), cm_value(c, out[2]), cm_value(c, out[3]), cm_value(c, out[4]), cm_value(c, out[5]));
	}
	cm_free(c);
	return bad;
}

/* onb_basis_checkedh on count inputs: every rounding of a unit vector
   (input categories 0-6) passes unchanged and gets arrayh's bits; the
   non-unit ones (category 7) come back renormalized to within the
   tolerance; NaN, infinity, zero and a NULL method get their status and
   the safe frame.  Returns the failures. */
static long check_checked(const onb_method *m, long count)
{
	long bad = 0, i;
	for (i = 0; i < count; i++) {
		uint16_t h[3], b[6], c[6];
		onb_vec3h n, b1, b2, nu;
		double l2;
		onb_status st;
		int k, nonfin = 0;
		input((uint64_t)i, h);
		memcpy(&n.x, &h[0], 2); memcpy(&n.y, &h[1], 2); memcpy(&n.z, &h[2], 2);
		for (k = 0; k < 3; k++)
			nonfin |= !isfinite(hval(h[k]));
		l2 = hval(h[0]) * hval(h[0]) + hval(h[1]) * hval(h[1]) + hval(h[2]) * hval(h[2]);
		st = onb_basis_checkedh(m, n, &b1, &b2, &nu);
		memcpy(&c[0], &b1.x, 2); memcpy(&c[1], &b1.y, 2); memcpy(&c[2], &b1.z, 2);
		memcpy(&c[3], &b2.x, 2); memcpy(&c[4], &b2.y, 2); memcpy(&c[5], &b2.z, 2);
		if (nonfin) {
			bad += st != ONB_NONFINITE || c[0] != 0x3c00u || c[4] != 0x3c00u;
			continue;
		}
		if (l2 == 0.0) {
			bad += st != ONB_ZERO;
			continue;
		}
		if (i % 10 <= 6 && st != ONB_OK) {
			bad++;
			if (bad < 4) printf("  checkedh %s: n = (%a, %a, %a), |n|^2 - 1 = %g: status %d, not ONB_OK\n", m->name, hval(h[0]), hval(h[1]), hval(h[2]), l2 - 1.0, (int)st);
			continue;
		}
		{
			uint16_t nb[3];
			double u2;
			memcpy(&nb[0], &nu.x, 2); memcpy(&nb[1], &nu.y, 2); memcpy(&nb[2], &nu.z, 2);
			u2 = hval(nb[0]) * hval(nb[0]) + hval(nb[1]) * hval(nb[1]) + hval(nb[2]) * hval(nb[2]);
			m->arrayh(nb, b, b + 3);
			if (memcmp(b, c, sizeof b) != 0 || !(fabs(u2 - 1.0) <= ONB_CHECK_TOLH)) {
				if (bad++ < 3) printf("  checkedh %s: n = (%a, %a, %a): status %d, n_used (%a, %a, %a), |n_used|^2 - 1 = %g\n", m->name,
				                     hval(h[0]), hval(h[1]), hval(h[2]), (int)st, hval(nb[0]), hval(nb[1]), hval(nb[2]), u2 - 1.0);
			}
		}
	}
	{
		onb_vec3h z = { (onb_half)0.0f, (onb_half)0.0f, (onb_half)1.0f }, b1, b2;
		bad += onb_basis_checkedh(NULL, z, &b1, &b2, NULL) != ONB_BAD_METHOD;
	}
	return bad;
}

/* The two copies of the kernels (half.c: libgcc's soft conversions and
   F16C's), where this build has both (GCC on x86-64) and the CPU has F16C:
   every conversion the kernels can meet (NaNs included), then each kernel
   on the inputs above, bit for bit (any NaN matching any NaN: same_bits).  Returns the failures, or
   -1 when there is nothing to compare here (reported). */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(ONB_NO_CLONES)
typedef void (*hkernel)(onb_vec3h, onb_vec3h *, onb_vec3h *);
#define COPY_DECL(m) void onb__##m##h_soft(onb_vec3h, onb_vec3h *, onb_vec3h *); \
	void onb__##m##h_f16c(onb_vec3h, onb_vec3h *, onb_vec3h *);
ONB_METHOD_LIST(COPY_DECL)
ONB_FLOAT_METHOD_LIST(COPY_DECL)
#define COPY_ROW(m) { #m, onb__##m##h_soft, onb__##m##h_f16c },
static const struct { const char *name; hkernel soft, f16c; } copies[] = {
	ONB_METHOD_LIST(COPY_ROW) ONB_FLOAT_METHOD_LIST(COPY_ROW)
};
__attribute__((target("f16c"), noinline)) static float widen_f16c(uint16_t b) { onb_half h; memcpy(&h, &b, 2); return (float)h; }
__attribute__((target("f16c"), noinline)) static uint16_t narrow_f16c(float f) { onb_half h = (onb_half)f; uint16_t b; memcpy(&b, &h, 2); return b; }
__attribute__((noinline)) static float widen_soft(uint16_t b) { onb_half h; memcpy(&h, &b, 2); return (float)h; }
__attribute__((noinline)) static uint16_t narrow_soft(float f) { onb_half h = (onb_half)f; uint16_t b; memcpy(&b, &h, 2); return b; }
static uint32_t fbits(float f) { uint32_t u; memcpy(&u, &f, 4); return u; }
static float fval(uint32_t u) { float f; memcpy(&f, &u, 4); return f; }

/* Every binary16 widened; every float within 2 ulps of a binary16 value or
   of a midpoint between two (the rounding boundaries), and 2^20 spread
   over all floats (NaNs, infinities, subnormals), narrowed. */
static long check_conversions(void)
{
	long bad = 0;
	uint32_t b, d;
	for (b = 0; b < 0x10000u; b++) {
		const uint32_t w = fbits(widen_soft((uint16_t)b));
		const float lo = widen_soft((uint16_t)b), hi = widen_soft((uint16_t)(b + 1));
		bad += fbits(widen_f16c((uint16_t)b)) != w;
		for (d = 0; d < 5; d++) {
			const float m = fval(fbits(isfinite(lo) && isfinite(hi) ? 0.5f * (lo + hi) : lo) + d - 2u);
			const float v = fval(w + d - 2u);
			bad += narrow_soft(m) != narrow_f16c(m);
			bad += narrow_soft(v) != narrow_f16c(v);
		}
	}
	for (b = 0; b < (1u << 20); b++) {
		const float v = fval(b * 4093u + (uint32_t)rng_mix64(b));
		bad += narrow_soft(v) != narrow_f16c(v);
	}
	return bad;
}

/* Bit for bit, but any NaN matches any NaN: where two NaNs meet in one
   float operation, x86 returns the first operand's payload, and the two
   compilations may order a commutative operation's operands differently
   (the payloads are the hardware's, as in check above). */
static int same_bits(const onb_vec3h *a, const onb_vec3h *b)
{
	uint16_t x[3], y[3];
	int k;
	memcpy(x, a, sizeof x);
	memcpy(y, b, sizeof y);
	for (k = 0; k < 3; k++)
		if (x[k] != y[k] && !((x[k] & 0x7fffu) > 0x7c00u && (y[k] & 0x7fffu) > 0x7c00u))
			return 0;
	return 1;
}

static long check_copies(long count)
{
	long bad, i;
	size_t k;
	__builtin_cpu_init();
	if (!__builtin_cpu_supports("f16c")) {
		printf("note: this CPU has no F16C: the F16C copy cannot run here, not compared\n");
		return -1;
	}
	bad = check_conversions();
	printf("%s conversions: libgcc's and F16C's, %ld differ\n", bad ? "FAIL" : "ok  ", bad);
	for (k = 0; k < sizeof copies / sizeof copies[0]; k++) {
		long kb = 0;
		for (i = 0; i < count; i++) {
			uint16_t h[3];
			onb_vec3h n, s1, s2, f1, f2;
			input((uint64_t)i, h);
			memcpy(&n.x, &h[0], 2); memcpy(&n.y, &h[1], 2); memcpy(&n.z, &h[2], 2);
			copies[k].soft(n, &s1, &s2);
			copies[k].f16c(n, &f1, &f2);
			if (!same_bits(&s1, &f1) || !same_bits(&s2, &f2))
				if (kb++ < 2)
					printf("  %s: n [%04x %04x %04x]: the soft and F16C copies differ\n", copies[k].name, h[0], h[1], h[2]);
		}
		if (kb)
			printf("FAIL %-24s half   soft and F16C copies differ on %ld of %ld inputs\n", copies[k].name, kb, count);
		bad += kb;
	}
	printf("%s the soft and F16C copies of %zu kernels: %ld inputs each, %ld differ\n", bad ? "FAIL" : "ok  ",
	       sizeof copies / sizeof copies[0], count, bad);
	return bad;
}
#else
static long check_copies(long count)
{
	(void)count;
	printf("note: one copy of the half kernels in this build (no F16C dispatch): nothing to compare\n");
	return -1;
}
#endif

/* A bare _Float16 expression on this compiler: does it round per
   operation?  (Informative: the kernels never rely on it.) */
static void report_eval(void)
{
	volatile onb_half one = (onb_half)1.0, e = (onb_half)0x1p-11;
	const onb_half r = one + e + e;
	printf("note: this compiler evaluates (1 + 2^-11) + 2^-11 in _Float16 as %a (per operation: 0x1p+0)\n", (double)r);
}

int main(int argc, char **argv)
{
	const long count = argc > 1 ? atol(argv[1]) : 50000;
	const char *only = argc > 2 ? argv[2] : NULL;
	size_t nm, i;
	const onb_method *ms = onb_methods(&nm);
	int fail = 0, checked = 0;
	if (count <= 0)
		return 2;
	report_eval();
	for (i = 0; i < nm; i++) {
		const cm_method *cmm = cm_find(ms[i].name);
		long bad, nan_in = 0;
		if (only && strcmp(only, ms[i].name) != 0)
			continue;
		if (!cmm || !ms[i].arrayh) {
			printf("FAIL %s: no %s\n", ms[i].name, cmm ? "half entry (arrayh)" : "rounding model");
			fail = 1;
			continue;
		}
		bad = check(&ms[i], cmm, count, &nan_in);
		checked++;
		printf("%s %-24s half   %ld inputs, %ld compared, %ld not bit-identical\n", bad ? "FAIL" : "ok  ", ms[i].name, count, count - nan_in, bad);
		fail |= bad != 0;
	}
	if (!only || onb_find(only)) {
		const onb_method *dm = onb_find(only ? only : "duff");
		const long cb = check_checked(dm, count);
		printf("%s onb_basis_checkedh (%s): %ld inputs, %ld wrong\n", cb ? "FAIL" : "ok  ", dm->name, count, cb);
		fail |= cb != 0;
	}
	if (!only && check_copies(count) > 0)
		fail = 1;
	if (checked == 0) {
		printf("FAIL: no method checked\n");
		fail = 1;
	}
	printf("%s: %d methods, the half kernels %s the model's per-operation binary16 bits\n",
	       fail ? "FAIL" : "ok", checked, fail ? "do not give" : "give");
	return fail;
}
#else
int main(void)
{
	size_t nm, i;
	const onb_method *ms = onb_methods(&nm);
	int fail = 0;
	for (i = 0; i < nm; i++)
		if (ms[i].arrayh) {
			printf("FAIL %s: a half entry in a build without _Float16\n", ms[i].name);
			fail = 1;
		}
	printf("%s: no _Float16 here (ONB_HAVE_HALF 0): the registry has %s half entries\n", fail ? "FAIL" : "ok", fail ? "" : "no");
	return fail;
}
#endif
