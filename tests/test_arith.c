/*
 * test_arith.c - conforming implementations, emulated (src/model/emu.c,
 * src/certify/emulate.c), never exceed the bound `certify --arith` proves
 * (emu_point_bound: the same mean value form over a small box around the
 * input) on random and extreme inputs, for several methods, profiles and
 * both formats; every emulated result lies within its operation's
 * allowance (checked on the operations themselves); and the check can
 * fail: an emulation allowed 2 times the profile's error exceeds some
 * bound.  Also: --arith ieee's CM_EXEC is the IEEE model bit for bit.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "certify/emulate.h"
#include "certify/region.h"
#include "model/model_int.h"
#include "inputs/rng.h"
#define CHECK_MAX_REPORTS 10
#include "check.h"

static const char *const methods[] = { "duff", "frisvad", "hughes_moeller", "pbrt_v3", "stark" };
static const char *const profiles[] = { "vulkan", "vulkan-precise", "d3d11", "opencl", "cuda-fast", "contract-any" };
#define NM (int)(sizeof methods / sizeof methods[0])
#define NP (int)(sizeof profiles / sizeof profiles[0])
#define NIN 14
#define WIDEN 2.0   /* the mutation: allowances this many times wider */

/* (double)(float)x through a volatile: GCC 12 can drop the rounding */
static double to_float(double x)
{
	volatile float f = (float)x;
	return f;
}

/* Input i in format prec: the rounding of a unit vector (random ones,
   then the axes, next to -z, a subnormal component). */
static int input(int i, int prec, double n[3])
{
	static const double ext[6][3] = { { 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 }, { 0, -1, 0 },
	                                  { 3e-4, 0, -0.999999955 }, { 1e-39, 0.6, 0.8 } };
	double u[3], l;
	int k;
	if (i < NIN - 6) {
		uint64_t s = rng_mix64(0x617269746855ull + (uint64_t)i);
		double z = 2.0 * (double)(s >> 11) * 0x1p-53 - 1.0, ph = 6.283185307179586 * (double)(rng_mix64(s) >> 11) * 0x1p-53;
		u[0] = sqrt(1 - z * z) * cos(ph);
		u[1] = sqrt(1 - z * z) * sin(ph);
		u[2] = z;
	} else {
		memcpy(u, ext[i - (NIN - 6)], sizeof u);
	}
	l = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
	for (k = 0; k < 3; k++)
		n[k] = prec == PREC_FLOAT ? to_float(u[k] / l) : u[k] / l;
	return cert_in_domain(n, prec, -1.0);
}

/* The largest defect of the nearest, 8 random and the adversarial
   implementations of p at n. */
static double worst(cm *c, ref_ctx *rc, const cm_method *m, int prec, const double n[3], const arith_profile *p)
{
	unsigned char ch[CM_EMU_MAXOP];
	emu_eval r;
	double w;
	int i;
	emu_run(c, rc, m, prec, n, p, CM_EMU_NEAREST, 0, NULL, 0, &r);
	w = r.defect;
	for (i = 0; i < 8; i++) {
		emu_run(c, rc, m, prec, n, p, CM_EMU_RANDOM, 77 + (unsigned long long)i, NULL, 0, &r);
		w = fmax(w, r.defect);
	}
	return fmax(w, emu_adversarial(c, rc, m, prec, n, p, 1, ch, &r));
}

static void bounds_hold(cm *c, ref_ctx *rc)
{
	int mi, pi, prec, i, checked = 0;
	for (mi = 0; mi < NM; mi++)
		for (pi = 0; pi < NP; pi++)
			for (prec = 0; prec < 2; prec++) {
				const cm_method *m = cm_find(methods[mi]);
				const arith_profile *p = arith_find(profiles[pi]);
				for (i = 0; i < NIN; i++) {
					double n[3], b, w;
					int unb;
					if (!input(i, prec, n))
						continue;
					b = emu_point_bound(m, p, prec, n, &unb);
					if (!(b < INFINITY))
						continue;
					w = worst(c, rc, m, prec, n, p);
					checked++;
					CHECK(w <= b, "%s %s %s n = (%a, %a, %a): emulated defect %g above the bound %g", methods[mi],
					      prec_name(prec), profiles[pi], n[0], n[1], n[2], w, b);
				}
			}
	CHECK(checked > 300, "only %d (method, profile, input) bounds were finite", checked);
	printf("  %d emulated inputs, each below its proven bound\n", checked);
}

/* The mutation: allowances WIDEN times wider than vulkan's (float) must push
   some emulated defect above a vulkan bound. */
static void mutation_caught(cm *c, ref_ctx *rc)
{
	const arith_profile *p = arith_find("vulkan");
	arith_profile w = arith_widen(p, WIDEN);
	int mi, i, above = 0;
	for (mi = 0; mi < NM; mi++)
		for (i = 0; i < NIN; i++) {
			double n[3], b;
			int unb;
			const cm_method *m = cm_find(methods[mi]);
			if (!input(i, PREC_FLOAT, n) || !((b = emu_point_bound(m, p, PREC_FLOAT, n, &unb)) < INFINITY))
				continue;
			above += worst(c, rc, m, PREC_FLOAT, n, &w) > b;
		}
	CHECK(above > 0, "an emulation %g times wider than vulkan stayed below every vulkan bound", WIDEN);
	printf("  mutation: %gx vulkan's allowances exceed the vulkan bound at %d inputs\n", WIDEN, above);
}

/* Each emulated operation within its allowance: x/y under vulkan (2.5
   ulp), d3d11 (rcp then a product) and x+y under vulkan (a neighbour). */
static void ops_within(cm *c)
{
	const arith_profile *vk = arith_find("vulkan");
	uint64_t s = 12345;
	int i, outside = 0, moved = 0;
	for (i = 0; i < 20000; i++) {
		double a = to_float(1.0 + (double)(rng_mix64(s++) >> 11) * 0x1p-53);
		double b = to_float(0.5 + (double)(rng_mix64(s++) >> 11) * 0x1p-53);
		double n[3] = { a, b, 0 }, q, e, ulp;
		int ex;
		cv in[3], r;
		cm_set_arith(c, vk);
		cm_set_emu(c, CM_EMU_RANDOM, s++, NULL, 0);
		cm_exec_begin(c, PREC_FLOAT, n, in);
		r = cm_div(c, PREC_FLOAT, in[0], in[1]);
		q = cm_value(c, r);
		e = a / b;   /* to 2^-53: far inside the margin */
		frexp(e, &ex);
		ulp = ldexp(1.0, ex - 24);
		outside += !(fabs(q - e) <= 2.5 * ulp);
		moved += q != to_float(e);
		r = cm_add(c, PREC_FLOAT, in[0], in[1]);
		frexp(a + b, &ex);   /* a neighbour of a + b: within one ulp of its binade */
		outside += !(fabs(cm_value(c, r) - (a + b)) < ldexp(1.0, ex - 24));
	}
	CHECK(outside == 0, "%d emulated results outside their allowance", outside);
	CHECK(moved > 1000, "the random emulation moved only %d of 20000 quotients off the nearest", moved);
}

/* binary16 under vulkan's half column (emu.c's half path): x/y within
   2.5 half ulps (|y| in [2^-14, 2^14]), x+y a neighbour, sqrt within the
   1.0/inversesqrt it is inherited from (2 ulps, then 2.5: under 5 ulps
   here), every result a binary16 value; and the same check catches an
   emulation allowed twice vulkan's error (the mutation).  Returns the
   number of results outside. */
static int half_ops(cm *c, const arith_profile *p, int *moved)
{
	uint64_t s = 777;
	int i, outside = 0;
	*moved = 0;
	for (i = 0; i < 20000; i++) {
		double a = prec_half_round(1.0 + (double)(rng_mix64(s++) >> 11) * 0x1p-53);
		double b = prec_half_round(0.5 + (double)(rng_mix64(s++) >> 11) * 0x1p-53);
		double n[3] = { a, b, 0 }, q, e, ulp;
		int ex;
		cv in[3], r;
		cm_set_arith(c, p);
		cm_set_emu(c, CM_EMU_RANDOM, s++, NULL, 0);
		cm_exec_begin(c, PREC_HALF, n, in);
		r = cm_div(c, PREC_HALF, in[0], in[1]);
		q = cm_value(c, r);
		e = a / b;
		frexp(e, &ex);
		ulp = ldexp(1.0, ex - 11);
		outside += !(fabs(q - e) <= 2.5 * ulp) || prec_half_round(q) != q;
		*moved += q != prec_half_round(e);
		r = cm_add(c, PREC_HALF, in[0], in[1]);
		q = cm_value(c, r);
		frexp(a + b, &ex);
		outside += !(fabs(q - (a + b)) < ldexp(1.0, ex - 11)) || prec_half_round(q) != q;
		r = cm_sqrt(c, PREC_HALF, in[0]);
		q = cm_value(c, r);
		frexp(sqrt(a), &ex);
		outside += !(fabs(q - sqrt(a)) < 5.0 * ldexp(1.0, ex - 11)) || prec_half_round(q) != q;
	}
	return outside;
}

static void half_within(cm *c)
{
	const arith_profile *vk = arith_find("vulkan");
	const arith_profile wide = arith_widen(vk, WIDEN);
	int moved, outside = half_ops(c, vk, &moved), moved2, outside2 = half_ops(c, &wide, &moved2);
	CHECK(outside == 0, "binary16 under vulkan: %d emulated results outside their allowance", outside);
	CHECK(moved > 1000, "binary16 under vulkan: the random emulation moved only %d of 20000 quotients", moved);
	CHECK(outside2 > 0, "binary16: an emulation %g times wider than vulkan stayed inside vulkan's allowance", WIDEN);
	printf("  binary16 under vulkan: 0 of 60000 results outside, %d quotients off the nearest; %gx wider: %d outside\n",
	       moved, WIDEN, outside2);
}

/* ieee (and no profile): CM_EXEC unchanged, bit for bit. */
static void ieee_same(cm *c)
{
	const cm_method *m = cm_find("hughes_moeller");
	int i, k, same = 1;
	for (i = 0; i < NIN - 6; i++) {
		double n[3], o0[6];
		cv in[3], out[6];
		input(i, PREC_FLOAT, n);
		cm_set_arith(c, NULL);
		cm_exec_begin(c, PREC_FLOAT, n, in);
		cm_run(c, m, PREC_FLOAT, in, out);
		for (k = 0; k < 6; k++)
			o0[k] = cm_value(c, out[k]);
		cm_set_arith(c, arith_ieee());
		cm_exec_begin(c, PREC_FLOAT, n, in);
		cm_run(c, m, PREC_FLOAT, in, out);
		for (k = 0; k < 6; k++)
			same &= memcmp(&o0[k], &c->x[out[k]], sizeof o0[k]) == 0;
	}
	CHECK(same, "cm_set_arith(ieee) changed CM_EXEC's bits");
}

int main(void)
{
	cm *c = cm_new(CM_EXEC);
	ref_ctx *rc = ref_new(127);
	if (!c || !rc) {
		printf("test_arith: out of memory\n");
		return 1;
	}
	ieee_same(c);
	ops_within(c);
	half_within(c);
	bounds_hold(c, rc);
	mutation_caught(c, rc);
	cm_free(c);
	ref_free(rc);
	return check_finish("test_arith");
}
