/*
 * eval.c - `onbstudy eval x y z`: one input, every method, every metric.
 * The microscope that worst.csv's hex floats point to.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "study.h"
#include "kernels.h"
#include "reference.h"
#include "inputs.h"

static void usage(FILE *f)
{
	fprintf(f, "usage: onbstudy eval [--precision float|double|both] [--methods a,b] [--fma]\n"
	           "                     [--ref-bits B] [--local x,y,z] X Y Z\n"
	           "Every method's outputs (hex and decimal) and every metric for one input.\n"
	           "X Y Z may be decimal or C99 hex floats (as worst.csv prints them); each is\n"
	           "rounded to the precision, and the rounding is reported.\n");
}

static void show3(const char *label, const double *v)
{
	printf("  %-6s (%-24a %-24a %-24a)\n         (%-24.17g %-24.17g %-24.17g)\n", label, v[0], v[1], v[2], v[0], v[1], v[2]);
}

int cmd_eval(int argc, char **argv)
{
	const char *methods = NULL;
	int prec_on[2] = { 1, 1 }, fma = 0, i, p, k, nk, npos = 0;
	long bits = 127;
	double in[3], loc[3] = { 0.6, 0.0, 0.8 };
	study_kernel ks[64];
	for (i = 0; i < argc; i++) {
		const char *a = argv[i];
		if (!strcmp(a, "--help") || !strcmp(a, "-h")) { usage(stdout); return 0; }
		if (!strcmp(a, "--precision") || !strcmp(a, "--methods") || !strcmp(a, "--ref-bits") || !strcmp(a, "--local")) {
			const char *v;
			if (i + 1 >= argc) { study_error("%s needs a value", a); return ONB_EXIT_USAGE; }
			v = argv[++i];
			if (!strcmp(a, "--methods")) methods = v;
			else if (!strcmp(a, "--ref-bits")) { if (parse_int(a, v, 64, 4096, &bits)) return ONB_EXIT_USAGE; }
			else if (!strcmp(a, "--local")) {
				char tail;
				if (sscanf(v, "%lf,%lf,%lf%c", &loc[0], &loc[1], &loc[2], &tail) != 3 || !isfinite(loc[0]) ||
				    !isfinite(loc[1]) || !isfinite(loc[2])) {
					study_error("--local: expected x,y,z (finite numbers), not '%s'", v);
					return ONB_EXIT_USAGE;
				}
			} else {
				prec_on[0] = !strcmp(v, "float") || !strcmp(v, "both");
				prec_on[1] = !strcmp(v, "double") || !strcmp(v, "both");
				if (!prec_on[0] && !prec_on[1]) { study_error("--precision: expected float, double or both, not '%s'", v); return ONB_EXIT_USAGE; }
			}
			continue;
		}
		if (!strcmp(a, "--fma")) { fma = 1; continue; }
		if (!strcmp(a, "--")) { /* the rest are numbers */
			for (i++; i < argc; i++) {
				if (npos >= 3) { study_error("eval: expected exactly three numbers X Y Z"); return ONB_EXIT_USAGE; }
				if (parse_double("eval", argv[i], &in[npos])) return ONB_EXIT_USAGE;
				npos++;
			}
			break;
		}
		if (a[0] == '-' && a[1] == '-') { study_error("eval: unknown option '%s'", a); return ONB_EXIT_USAGE; }
		if (npos >= 3) { study_error("eval: expected exactly three numbers X Y Z"); return ONB_EXIT_USAGE; }
		if (parse_double("eval", a, &in[npos])) return ONB_EXIT_USAGE;
		npos++;
	}
	if (npos != 3) { usage(stderr); return ONB_EXIT_USAGE; }
	if (fma && !fma_available()) { study_error("--fma: this CPU (or build) has no FMA"); return ONB_EXIT_USAGE; }
	nk = kernels_select(methods, fma, ks, 64);
	if (nk < 0)
		return ONB_EXIT_USAGE;
	{
		ref_ctx *rc = ref_new(bits), *rc2 = ref_new(bits + 64);
		if (!rc || !rc2) { study_error("out of memory"); return 1; }
		for (p = 0; p < 2; p++) {
			double n[3], lv[3];
			const char *pn = p == PREC_FLOAT ? "float" : "double";
			if (!prec_on[p])
				continue;
			for (i = 0; i < 3; i++) {
				n[i] = fmt_round(in[i], p);
				lv[i] = fmt_round(loc[i], p);
			}
			printf("== %s: n = (%a, %a, %a)\n", pn, n[0], n[1], n[2]);
			for (i = 0; i < 3; i++)
				if (n[i] != in[i] && !(isnan(n[i]) && isnan(in[i])))
					printf("   note: component %d rounded to %s: %.17g -> %a\n", i, pn, in[i], n[i]);
			printf("   local direction for the direction error: (%a, %a, %a)\n", lv[0], lv[1], lv[2]);
			for (k = 0; k < nk; k++) {
				sample_metrics m, m2;
				char why[256];
				if (!kernel_runs(&ks[k], p)) {
					printf("\n%s (%s): float only (no double version)\n", ks[k].name, pn);
					continue;
				}
				ref_eval(rc, &ks[k], p, n, lv, 0, &m);
				ref_eval(rc2, &ks[k], p, n, lv, 0, &m2);
				printf("\n%s (%s), branch %d\n", ks[k].name, pn, m.branch);
				if (ks[k].m) {
					show3("b1", m.out);
					show3("b2", m.out + 3);
					show3("ref b1", m.ref);
					show3("ref b2", m.ref + 3);
				} else {
					show3("w", m.out);
					show3("ref w", m.ref);
				}
				printf("  |n|-1 of the input: %.6g\n", m.in_norm);
				if (m.nonfinite) {
					printf("  NON-FINITE output: no other metric\n");
					continue;
				}
				if (ks[k].m) {
					printf("  defects: |b1|-1 %.6g  |b2|-1 %.6g  b1.n %.6g  b2.n %.6g  b1.b2 %.6g  (max %.6g)\n",
					       m.d[0], m.d[1], m.d[2], m.d[3], m.d[4], m.defect);
					printf("  det(b1,b2,n) %.17g: %s for handedness %+d\n", m.det,
					       m.wrong_hand ? "WRONG" : "right", ks[k].m->handedness);
				}
				printf("  forward: max %.6g ulp (|exact| >= eps), max %.6g eps absolute, bits mean %.4g max %.4g\n",
				       m.ulp_max, m.abs_eps_max, m.nbits ? m.bits_sum / m.nbits : 0.0, m.bits_max);
				printf("  direction: w = (%a, %a, %a); | |w|-1 | %.6g, | w.n - z | %.6g\n",
				       m.w[0], m.w[1], m.w[2], m.dir_norm, m.dir_cos);
				if (!ref_agree(&m, &m2, why, sizeof why))
					printf("  WARNING: the reference at %ld bits disagrees with %ld bits: %s\n", bits, bits + 64, why);
			}
			printf("\n");
		}
		ref_free(rc);
		ref_free(rc2);
	}
	return 0;
}
