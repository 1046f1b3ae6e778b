/*
 * eval_arith.c - `onbstudy eval --arith PROFILE X Y Z`: per method, what
 * the profile lets conforming implementations return at one input.
 * Emulated in C (src/certify/emulate.h): every operation at round to
 * nearest, N random implementations and the greedy adversary; the range
 * of each output component and each defect over all of them; beside it
 * the proven bound over a small box of the sphere around the input (the
 * mean value form of `certify --arith`, bound_box), which every
 * conforming result at the input stays below when the input is in the
 * domain.  --format csv gives the same as rows for a harness
 * (docs/gpu.md): method,precision,profile,quantity,lo,hi in hex.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "cli/eval_arith.h"
#include "certify/emulate.h"
#include "certify/bound.h"
#include "certify/region.h"
#include "common/options.h"
#include "inputs/inputs.h"

typedef struct {
	double lo[6 + NDEF + 1], hi[6 + NDEF + 1];   /* outputs, defects, max defect */
	double nearest, random, adversarial;
	int nonfinite;
} envelope;

static void env_add(envelope *e, const emu_eval *r)
{
	double v[6 + NDEF + 1];
	int i;
	if (!isfinite(r->defect)) {
		e->nonfinite = 1;
		return;
	}
	memcpy(v, r->out, sizeof r->out);
	memcpy(v + 6, r->d, sizeof r->d);
	v[6 + NDEF] = r->defect;
	for (i = 0; i < 6 + NDEF + 1; i++) {
		if (v[i] < e->lo[i]) e->lo[i] = v[i];
		if (v[i] > e->hi[i]) e->hi[i] = v[i];
	}
}

static const char *const qname[6 + NDEF + 1] = { "b1x", "b1y", "b1z", "b2x", "b2y", "b2z",
	"n1", "n2", "d1n", "d2n", "d12", "defect" };

static void print_env(const char *name, int prec, const arith_profile *p, const envelope *e, int samples,
                      double bound, int unb, int csv)
{
	int i;
	if (csv) {
		for (i = 0; i < 6 + NDEF + 1; i++)
			printf("%s,%s,%s,%s,%a,%a\n", name, prec_name(prec), p->name, qname[i], e->lo[i], e->hi[i]);
		if (bound < INFINITY)
			printf("%s,%s,%s,bound,0,%a\n", name, prec_name(prec), p->name, bound);
		else
			printf("%s,%s,%s,bound,0,inf%s%s\n", name, prec_name(prec), p->name, unb >= 0 || unb == -2 ? ":" : "",
			       unb == -2 ? "no-half-model" : unb >= 0 ? (unb == AR_NOPS ? "direction-rule" : arith_op_name(unb)) : "");
		return;
	}
	printf("\n%s (%s) under %s\n", name, prec_name(prec), p->name);
	if (e->nonfinite)
		printf("  NON-FINITE output from some emulated implementation\n");
	printf("  defect: nearest %.6g, random max %.6g (%d implementations), adversarial %.6g\n", e->nearest,
	       e->random, samples, e->adversarial);
	for (i = 0; i < 6; i++)
		printf("  %-6s [%-24a %-24a] width %.3g\n", qname[i], e->lo[i], e->hi[i], e->hi[i] - e->lo[i]);
	printf("  defects over all runs: |b1|-1 [%.4g, %.4g]  |b2|-1 [%.4g, %.4g]  b1.n [%.4g, %.4g]  b2.n [%.4g, %.4g]  b1.b2 [%.4g, %.4g]\n",
	       e->lo[6], e->hi[6], e->lo[7], e->hi[7], e->lo[8], e->hi[8], e->lo[9], e->hi[9], e->lo[10], e->hi[10]);
	if (bound < INFINITY)
		printf("  proven bound near the input (box of ~8u around n/|n|): %.6g%s\n", bound,
		       e->hi[6 + NDEF] > bound ? "  WARNING: an emulated defect exceeds it" : "");
	else
		printf("  proven bound near the input: none (%s)\n",
		       unb == -2 ? "no binary16 proof model: the emulated range is measured, not bounded"
		       : unb >= 0 ? (unb == AR_NOPS ? "direction rule: round to nearest only" : arith_op_name(unb))
		                : "singular or not enclosed");
}

static void eval_method(cm *c, ref_ctx *rc, const cm_method *m, const char *name, int prec, const double n[3],
                        const arith_profile *p, int samples, unsigned long long seed, int csv)
{
	unsigned char ch[CM_EMU_MAXOP];
	envelope e;
	emu_eval r;
	double bound;
	int i, unb;
	for (i = 0; i < 6 + NDEF + 1; i++) {
		e.lo[i] = INFINITY;
		e.hi[i] = -INFINITY;
	}
	e.nonfinite = 0;
	emu_run(c, rc, m, prec, n, p, CM_EMU_NEAREST, 0, NULL, 0, &r);
	env_add(&e, &r);
	e.nearest = r.defect;
	e.random = 0.0;
	for (i = 0; i < samples; i++) {
		emu_run(c, rc, m, prec, n, p, CM_EMU_RANDOM, seed + (unsigned long long)i * 0x9e3779b97f4a7c15ull, NULL, 0, &r);
		env_add(&e, &r);
		if (r.defect > e.random)
			e.random = r.defect;
	}
	e.adversarial = emu_adversarial(c, rc, m, prec, n, p, 3, ch, &r);
	env_add(&e, &r);
	if (prec == PREC_HALF) {   /* no binary16 proof model (src/model/model.h): measured only */
		bound = INFINITY;
		unb = -2;
	} else
		bound = emu_point_bound(m, p, prec, n, &unb);
	print_env(name, prec, p, &e, samples, bound, unb, csv);
}

int eval_arith(const arith_profile *p, const study_kernel *ks, int nk, const int prec_on[PREC_COUNT], const double in[3],
               int samples, unsigned long long seed, int csv)
{
	cm *c = cm_new(CM_EXEC);
	ref_ctx *rc = ref_new(127);
	int k, prec, i;
	if (!c || !rc) {
		cm_free(c);
		if (rc)
			ref_free(rc);
		study_error("out of memory");
		return 1;
	}
	if (csv)
		printf("method,precision,profile,quantity,lo,hi\n");
	for (prec = 0; prec < PREC_COUNT; prec++) {
		double n[3];
		if (!prec_on[prec])
			continue;
		for (i = 0; i < 3; i++)
			n[i] = fmt_round(in[i], prec);
		if (!csv)
			printf("== %s under %s (%s): n = (%a, %a, %a)%s\n", prec_name(prec), p->name, p->title, n[0], n[1], n[2],
			       prec == PREC_HALF ? "" : cert_in_domain(n, prec, -1.0) ? ""
			       : "  (not a rounding of a unit vector: the bound does not cover it)");
		for (k = 0; k < nk; k++) {
			const cm_method *m = ks[k].fma ? NULL : cm_find(ks[k].name);
			if (!m || !kernel_runs(&ks[k], prec) || m->direction) {
				if (!csv)
					printf("\n%s (%s): %s\n", ks[k].name, prec_name(prec),
					       m && m->direction ? "no emulation (its direction bound is proven for round to nearest only)"
					                         : "no rounding model in this precision: not emulated");
				continue;
			}
			eval_method(c, rc, m, ks[k].name, prec, n, p, samples, seed, csv);
		}
	}
	cm_free(c);
	ref_free(rc);
	return 0;
}
