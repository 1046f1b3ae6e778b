/*
 * test_certify.c - the rounding models are the kernels.
 *
 * Every method's model (its family's, src/families/), executed in its format with
 * every rounding performed, must give libonb's bits: the out-of-line
 * kernels of the registry, compiled with the library's flags, on 10^6
 * inputs per method and precision (argv[1] changes the count): uniform,
 * both poles down to 1 + n.z = 1e-18, Frisvad's and Max's thresholds, the
 * |x| = 0.9, |x| = |y|, |x| = |z| and |y| = |z| thresholds, the axes with
 * signed zeros, the n.z = +-0 seam and the approach to -x.
 * A model that drops, adds or moves one rounding fails here.
 * The contracted models (cm_find_fma: every method whose family's fma_model
 * says it has one, cm_fma_name) are
 * checked the same way against the study's --fma copies of their kernels
 * (compiled with -mfma -ffp-contract=fast), where the CPU has FMA, on a
 * quarter of the count.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "libonb/onb.h"
#include "certify/models.h"
#include "methods/kernels.h"
#include "model/model_int.h"
#include "inputs/rng.h"

static double unif(uint64_t i, int k) { return (double)(rng_mix64(i * 8 + (uint64_t)k) >> 11) * 0x1p-53; }

/* A unit vector (in double) with z and the azimuth given. */
static void from_z(double z, double phi, double u[3])
{
	double r;
	z = z < -1.0 ? -1.0 : z > 1.0 ? 1.0 : z;
	r = sqrt((1.0 - z) * (1.0 + z));
	u[0] = r * cos(phi);
	u[1] = r * sin(phi);
	u[2] = z;
}

/* Two components of equal magnitude (up to a relative 1e-7): a, b. */
static void tie(uint64_t i, int a, int b, double u[3])
{
	double s = (1.0 + (unif(i, 3) - 0.5) * 2e-7), c = unif(i, 4) * 0.9;
	double m = sqrt((1.0 - c * c) / (1.0 + s * s));
	int o = 3 - a - b;
	u[a] = m * (unif(i, 5) < 0.5 ? -1 : 1);
	u[b] = m * s * (unif(i, 6) < 0.5 ? -1 : 1);
	u[o] = c * (unif(i, 7) < 0.5 ? -1 : 1);
}

static void input(uint64_t i, double u[3])
{
	const double tau = 6.283185307179586;
	double phi = tau * unif(i, 1), r = unif(i, 2);
	switch (i % 9) {
	case 0: from_z(2.0 * r - 1.0, phi, u); break;
	case 1: from_z(-1.0 + pow(10.0, -18.0 * r), phi, u); break;
	case 2: from_z(1.0 - pow(10.0, -18.0 * r), phi, u); break;
	case 3: from_z((i & 16 ? ONB_FRISVAD_T : ONB_FRISVAD_MAX_T) * (1.0 + (r - 0.5) * 2e-6), phi, u); break;
	case 4: { /* |x| near 0.9 */
		double x = (i & 16 ? -0.9 : 0.9) + (r - 0.5) * 1e-6, q = sqrt(1.0 - x * x);
		u[0] = x; u[1] = q * cos(phi); u[2] = q * sin(phi); break;
	}
	case 5: tie(i, (int)(i / 9 % 3), (int)(i / 9 % 3 + 1) % 3, u); break;
	case 6: { /* an axis, with signed zeros */
		int k = (int)(rng_mix64(i) % 3), j;
		for (j = 0; j < 3; j++)
			u[j] = (rng_mix64(i + (uint64_t)j) & 1) ? -0.0 : 0.0;
		u[k] = (rng_mix64(i) & 8) ? -1.0 : 1.0;
		break;
	}
	case 7: u[0] = cos(phi); u[1] = sin(phi); u[2] = (i & 16) ? -0.0 : 0.0; break;
	default: from_z(0.0, 0.0, u); { /* the approach to -x */
		double e = pow(10.0, -18.0 * r), q = sqrt(e * (2.0 - e));
		u[0] = -1.0 + e; u[1] = q * cos(phi); u[2] = q * sin(phi);
	}
	}
}

static int same_bits(double a, double b, int prec)
{
	if (prec == PREC_FLOAT) {
		float fa = (float)a, fb = (float)b;
		return memcmp(&fa, &fb, sizeof fa) == 0;
	}
	return memcmp(&a, &b, sizeof a) == 0;
}

static void kernel(const onb_method *m, int prec, const double n[3], double o[6])
{
	if (prec == PREC_FLOAT) {
		onb_vec3f v = { (float)n[0], (float)n[1], (float)n[2] }, b1, b2;
		m->basisf(v, &b1, &b2);
		o[0] = b1.x; o[1] = b1.y; o[2] = b1.z; o[3] = b2.x; o[4] = b2.y; o[5] = b2.z;
	} else {
		onb_vec3 v = { n[0], n[1], n[2] }, b1, b2;
		m->basis(v, &b1, &b2);
		o[0] = b1.x; o[1] = b1.y; o[2] = b1.z; o[3] = b2.x; o[4] = b2.y; o[5] = b2.z;
	}
}

/* Mismatches of method m's model in precision prec over count inputs,
   two or more threads at a time (each its own model context); -1 when a
   context cannot be made. */
static long check(const onb_method *m, const cm_method *cmm, int prec, long count)
{
	long bad = 0;
	int fail = 0;
#pragma omp parallel reduction(+ : bad)
	{
		cm *c = cm_new(CM_EXEC);
		long i;
#pragma omp for schedule(static)
		for (i = 0; i < count; i++) {
			double u[3], n[3], ko[6];
			cv in[3], out[6];
			int k, ok = 1;
			if (!c) {
#pragma omp atomic write
				fail = 1;
				continue;
			}
			input((uint64_t)i, u);
			for (k = 0; k < 3; k++)
				n[k] = prec == PREC_FLOAT ? (double)(float)u[k] : u[k];
			kernel(m, prec, n, ko);
			cm_exec_begin(c, prec, n, in);
			cm_run(c, cmm, prec, in, out);
			for (k = 0; k < 6; k++)
				ok &= same_bits(ko[k], cm_value(c, out[k]), prec);
			if (!ok && bad++ < 3)
#pragma omp critical(test_certify_print)
				printf("  %s %s: n = (%a, %a, %a): kernel b1.x %a model %a\n", m->name,
				       prec_name(prec), n[0], n[1], n[2], ko[0], cm_value(c, out[0]));
		}
		cm_free(c);
	}
	return fail ? -1 : bad;
}

/* The contracted models against the --fma copies of their kernels. */
static int check_fma(const char *only, long count, int *checked)
{
	int i, prec, fail = 0;
	if (!fma_available()) {
		printf("skip the contracted models: no FMA on this CPU or build\n");
		return 0;
	}
	for (i = 0; cm_fma_name((size_t)i); i++) {
		const char *name = cm_fma_name((size_t)i);
		const onb_method *m = onb_find(name);
		const cm_method *cmm = cm_find_fma(name);
		onb_method mf;
		rotate_fn rot;
		rotatef_fn rotf;
		if (only && strcmp(only, name) != 0)
			continue;
		if (!m || !cmm) {
			printf("FAIL %s+fma: no method or contracted model\n", name);
			fail = 1;
			continue;
		}
		mf = *m;
		if (fma_lookup(m->name, &mf.basis, &mf.basisf, &rot, &rotf) != 0) {
			printf("FAIL %s+fma: no --fma copy\n", m->name);
			fail = 1;
			continue;
		}
		for (prec = PREC_FLOAT; prec <= PREC_DOUBLE; prec++) {
			long bad;
			if (prec == PREC_DOUBLE && !mf.basis)
				continue;
			bad = check(&mf, cmm, prec, count);
			(*checked)++;
			printf("%s %-24s %-6s %ld inputs, %ld not bit-identical\n", bad ? "FAIL" : "ok  ",
			       name, prec == PREC_FLOAT ? "float+fma" : "double+fma", count, bad);
			fail |= bad != 0;
		}
	}
	return fail;
}

/* argv[1]: inputs per method and precision; argv[2]: one method alone. */
int main(int argc, char **argv)
{
	long count = argc > 1 ? atol(argv[1]) : 1000000;
	const char *only = argc > 2 ? argv[2] : NULL;
	size_t nm, i;
	const onb_method *ms = onb_methods(&nm);
	int fail = 0, checked = 0;
	if (count <= 0)
		return 2;
	for (i = 0; i < nm; i++) {
		const cm_method *cmm = cm_find(ms[i].name);
		int prec;
		if (only && strcmp(only, ms[i].name) != 0)
			continue;
		if (!cmm) {
			printf("FAIL %s: no rounding model\n", ms[i].name);
			fail = 1;
			continue;
		}
		for (prec = PREC_FLOAT; prec <= PREC_DOUBLE; prec++) {
			long bad;
			if (prec == PREC_DOUBLE && !ms[i].basis)
				continue;
			bad = check(&ms[i], cmm, prec, count);
			checked++;
			printf("%s %-24s %-6s %ld inputs, %ld not bit-identical\n", bad ? "FAIL" : "ok  ",
			       ms[i].name, prec_name(prec), count, bad);
			fail |= bad != 0;
		}
	}
	/* a quarter as many for the contracted models: 76 more pairs, and a
	   misplaced fusion shows on 1% to 78% of inputs */
	fail |= check_fma(only, count >= 4 ? count / 4 : count, &checked);
	printf("%s: %d method-precision pairs, the models %s the kernels' bits\n",
	       fail ? "FAIL" : "ok", checked, fail ? "do not reproduce" : "reproduce");
	return fail;
}
