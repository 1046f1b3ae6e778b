/*
 * eval.c - `onbstudy eval x y z`: one input, every method, every metric.
 * The microscope that worst.csv's hex floats point to.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <ctype.h>
#include "cli/eval.h"
#include "common/options.h"
#include "methods/kernels.h"
#include "reference/reference.h"
#include "inputs/inputs.h"
#include "cli/eval_arith.h"

static void usage(FILE *f)
{
	fprintf(f, "usage: onbstudy eval [--precision float|double|both|half|all] [--methods a,b] [--fma]\n"
	           "                     [--ref-bits B] [--local x,y,z] X Y Z\n"
	           "       onbstudy eval --arith PROFILE [--samples N] [--seed S] [--format table|csv]\n"
	           "                     [--precision P] [--methods a,b] X Y Z\n"
	           "Every method's outputs (hex and decimal) and every metric for one input.\n"
	           "X Y Z may be decimal or C99 hex floats (as worst.csv prints them); each is\n"
	           "rounded to the precision, and the rounding is reported.  --precision half (or all:\n"
	           "float, double and half) runs libonb's binary16 kernels (each operation rounded to\n"
	           "binary16) on the input rounded to binary16 (its encodings printed in hex);\n"
	           "forward errors in binary16's ulps and eps = 2^-10, u = 2^-11.\n"
	           "With --arith PROFILE (onbstudy list --arith; docs/gpu.md): per method, what\n"
	           "conforming implementations of the profile return at the input, emulated in C\n"
	           "from the method's rounding model: every operation at round to nearest, N random\n"
	           "implementations (--samples, default 256, from --seed) and a greedy adversary;\n"
	           "the range of each output component and defect over all of them, and the proven\n"
	           "bound over a box of ~8u around the input (certify --arith's mean value form).\n"
	           "--format csv: rows method,precision,profile,quantity,lo,hi (hex floats;\n"
	           "quantity b1x..b2z, n1, n2, d1n, d2n, d12, defect, bound).  --precision half\n"
	           "under a profile with a binary16 row (vulkan's half column): emulated and\n"
	           "measured; no binary16 proof model, so no bound.\n");
}

static void show3(const char *label, const double *v)
{
	printf("  %-6s (%-24a %-24a %-24a)\n         (%-24.17g %-24.17g %-24.17g)\n", label, v[0], v[1], v[2], v[0], v[1], v[2]);
}

typedef struct {
	const char *methods;
	int prec_on[PREC_COUNT], fma, npos;
	long bits;
	const arith_profile *arith;
	long samples;
	unsigned long long seed;
	int csv;
	double in[3], loc[3];
} eval_opts;

/* A negative number ("-0.5", "-0x1p-3", "-inf") is an operand, not an option. */
static int is_negative_number(const char *a)
{
	return a[0] == '-' && (isdigit((unsigned char)a[1]) || a[1] == '.' || a[1] == 'i' || a[1] == 'I' ||
	                       a[1] == 'n' || a[1] == 'N');
}

static int eval_option(int v, const char *a, eval_opts *o)
{
	char tail;
	switch (v) {
	case 'm': o->methods = a; return 0;
	case 'b': return parse_int("--ref-bits", a, 64, 4096, &o->bits);
	case 'f': o->fma = 1; return 0;
	case 'A':
		if (!(o->arith = arith_find(a))) {
			char names[256];
			arith_names(names, sizeof names);
			study_error("--arith: unknown profile '%s' (one of: %s)", a, names);
			return -1;
		}
		return 0;
	case 'n': return parse_int("--samples", a, 0, 1000000, &o->samples);
	case 'S': return parse_u64("--seed", a, 0, ~0ull, &o->seed);
	case 'F': return (o->csv = cli_format("--format", a, 0)) < 0 ? -1 : 0;
	case 'p': return cli_precision_half("--precision", a, o->prec_on);
	case 'l':
		if (sscanf(a, "%lf,%lf,%lf%c", &o->loc[0], &o->loc[1], &o->loc[2], &tail) != 3 || !isfinite(o->loc[0]) ||
		    !isfinite(o->loc[1]) || !isfinite(o->loc[2])) {
			study_error("--local: expected x,y,z (finite numbers), not '%s'", a);
			return -1;
		}
		return 0;
	}
	return -1;
}

static int eval_operand(const char *a, eval_opts *o)
{
	if (o->npos >= 3) {
		study_error("eval: expected exactly three numbers X Y Z");
		return -1;
	}
	if (parse_double("eval", a, &o->in[o->npos]))
		return -1;
	o->npos++;
	return 0;
}

/* Options and the operands X Y Z.  0; 1 after --help; ONB_EXIT_USAGE. */
static int eval_parse(int argc, char **argv, eval_opts *o)
{
	static const struct option lo[] = {
		{ "precision", required_argument, NULL, 'p' }, { "methods", required_argument, NULL, 'm' },
		{ "ref-bits", required_argument, NULL, 'b' }, { "local", required_argument, NULL, 'l' },
		{ "fma", no_argument, NULL, 'f' }, { "arith", required_argument, NULL, 'A' },
		{ "samples", required_argument, NULL, 'n' }, { "seed", required_argument, NULL, 'S' },
		{ "format", required_argument, NULL, 'F' }, CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
	};
	char **opts = malloc(((size_t)argc + 1) * sizeof *opts), **rest;
	int i, n = 0, v, rc = 0, dashdash = 0;
	cli_args c;
	if (!opts) { study_error("out of memory"); return 1; }
	/* Operands (negative numbers too) are taken out in order before
	   getopt_long sees the options; an option's value stays with it. */
	for (i = 0; i < argc && rc == 0; i++) {
		const char *a = argv[i];
		if (dashdash || !(a[0] == '-' && a[1]) || is_negative_number(a)) {
			rc = eval_operand(a, o) ? ONB_EXIT_USAGE : 0;
		} else if (!strcmp(a, "--")) {
			dashdash = 1;
		} else {
			opts[n++] = argv[i];
			if (cli_option_arity(lo, a, 0) == 1 && i + 1 < argc)
				opts[n++] = argv[++i];
		}
	}
	if (rc == 0 && cli_begin(&c, "eval", n, opts) == 0) {
		while (rc == 0 && (v = cli_next(&c, lo)) != -1) {
			if (v == CLI_HELP) { usage(stdout); rc = 1; }
			else if (v == CLI_ERROR || eval_option(v, c.arg, o) != 0) rc = ONB_EXIT_USAGE;
		}
		rest = cli_rest(&c, &n);
		for (i = 0; i < n && rc == 0; i++)
			rc = eval_operand(rest[i], o) ? ONB_EXIT_USAGE : 0;
		cli_end(&c);
	}
	free(opts);
	if (rc == 0 && o->npos != 3) {
		study_error("eval: expected three numbers X Y Z, got %d (try 'onbstudy eval --help')", o->npos);
		rc = ONB_EXIT_USAGE;
	}
	return rc;
}

/* What branch b of kernel k means, in words (its family's names). */
static const char *branch_name(const study_kernel *k, int b, char *buf, size_t n)
{
	return k->fam->branch_name(k->m, b, buf, n);
}

/* Warnings on an input the methods do not expect (they assume a unit n). */
static void input_warnings(const char *pn, const double n[3])
{
	const double l2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
	const double tol = pn[0] == 'f' ? 1e-6 : pn[0] == 'h' ? 0x1p-9 : 1e-12;
	if (!isfinite(n[0]) || !isfinite(n[1]) || !isfinite(n[2]))
		printf("   WARNING: the input is not finite: every method's output is garbage (onb_basis_checked refuses it)\n");
	else if (l2 == 0.0)
		printf("   WARNING: the input is the zero vector, which has no direction: every method's output is garbage "
		       "(onb_basis_checked refuses it)\n");
	else if (!(fabs(l2 - 1.0) <= tol))
		printf("   WARNING: the input is not unit (|n| = %.9g): every method but rtow assumes |n| = 1 "
		       "(onb_basis_checked normalizes it)\n", sqrt(l2));
}

/* One kernel on input n (precision p, named pn): its outputs, the
   reference's and every metric, and whether a wider reference agrees. */
static void eval_one(ref_ctx *rc, ref_ctx *rc2, long bits, const study_kernel *k, int p, const char *pn,
                     const double n[3], const double lv[3])
{
	sample_metrics m, m2;
	char why[256];
	if (!kernel_runs(k, p)) {
		printf("\n%s (%s): %s\n", k->name, pn, p == PREC_HALF ? "no binary16 version" : "float only (no double version)");
		return;
	}
	ref_eval(rc, k, p, n, lv, 0, &m);
	ref_eval(rc2, k, p, n, lv, 0, &m2);
	printf("\n%s (%s), branch %d (%s)\n", k->name, pn, m.branch,
	       branch_name(k, m.branch, why, sizeof why));
	if (k->m) {
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
		return;
	}
	if (k->m) {
		printf("  defects: |b1|-1 %.6g  |b2|-1 %.6g  b1.n %.6g  b2.n %.6g  b1.b2 %.6g  (max %.6g)\n",
		       m.d[0], m.d[1], m.d[2], m.d[3], m.d[4], m.defect);
		printf("  det(b1,b2,n) %.17g: %s for handedness %+d\n", m.det,
		       m.wrong_hand ? "WRONG" : "right", k->m->handedness);
	}
	printf("  forward: max %.6g ulp (|exact| >= eps), max %.6g eps absolute, bits mean %.4g max %.4g\n",
	       m.ulp_max, m.abs_eps_max, m.nbits ? m.bits_sum / m.nbits : 0.0, m.bits_max);
	printf("  direction: w = (%a, %a, %a); | |w|-1 | %.6g, | w.n - z | %.6g\n",
	       m.w[0], m.w[1], m.w[2], m.dir_norm, m.dir_cos);
	printf("  floor (the exact formula rounded once): defect %.6g, | |w|-1 | %.6g, | w.n - z | %.6g\n",
	       m.floor, m.floor_dir_norm, m.floor_dir_cos);
	if (k->m && m.floor > 0.0)
		printf("  defect / floor: %.6g\n", m.defect / m.floor);
	if (!ref_agree(&m, &m2, why, sizeof why))
		printf("  WARNING: the reference at %ld bits disagrees with %ld bits: %s\n", bits, bits + 64, why);
}

int cmd_eval(int argc, char **argv)
{
	eval_opts o = { NULL, { 1, 1, 0 }, 0, 0, 127, NULL, 256, 1, 0, { 0, 0, 0 }, { 0.6, 0.0, 0.8 } };
	const char *methods;
	int prec_on[PREC_COUNT], fma, i, p, k, nk;
	long bits;
	double in[3], loc[3];
	study_kernel ks[256];
	if ((i = eval_parse(argc, argv, &o)) != 0)
		return i == 1 ? 0 : i;
	methods = o.methods; fma = o.fma; bits = o.bits;
	memcpy(prec_on, o.prec_on, sizeof prec_on);
	memcpy(in, o.in, sizeof in);
	memcpy(loc, o.loc, sizeof loc);
	if (fma && !fma_available()) { study_error("--fma: this CPU (or build) has no FMA"); return ONB_EXIT_USAGE; }
	if (o.arith && (fma || o.bits != 127)) {
		study_error("eval: --arith takes neither --fma nor --ref-bits (a profile's contraction covers the +fma copies)");
		return ONB_EXIT_USAGE;
	}
	if (!o.arith && (o.csv || o.samples != 256 || o.seed != 1)) {
		study_error("eval: --format, --samples and --seed go with --arith");
		return ONB_EXIT_USAGE;
	}
	nk = kernels_select(methods, fma, ks, 256);
	if (nk < 0)
		return ONB_EXIT_USAGE;
	if (o.arith && prec_on[PREC_HALF] && !arith_has_format(o.arith, PREC_HALF)) {
		study_error("eval: --arith %s gives binary16 no precision (docs/gpu.md; ieee, vulkan, vulkan-precise, opencl, cuda-fast and contract-any have a half row)",
		            o.arith->name);
		return ONB_EXIT_USAGE;
	}
	if (o.arith)
		return eval_arith(o.arith, ks, nk, prec_on, in, (int)o.samples, o.seed, o.csv);
	{
		ref_ctx *rc = ref_new(bits), *rc2 = ref_new(bits + 64);
		if (!rc || !rc2) { study_error("out of memory"); return 1; }
		for (p = 0; p < PREC_COUNT; p++) {
			double n[3], lv[3];
			const char *pn = prec_name(p);
			if (!prec_on[p])
				continue;
			for (i = 0; i < 3; i++) {
				n[i] = fmt_round(in[i], p);
				lv[i] = fmt_round(loc[i], p);
			}
			printf("== %s: n = (%a, %a, %a)\n", pn, n[0], n[1], n[2]);
			if (p == PREC_HALF)
				printf("   binary16 encodings: (0x%04x, 0x%04x, 0x%04x)\n", prec_half_bits(n[0]), prec_half_bits(n[1]),
				       prec_half_bits(n[2]));
			for (i = 0; i < 3; i++)
				if (n[i] != in[i] && !(isnan(n[i]) && isnan(in[i])))
					printf("   note: component %d rounded to %s: %.17g -> %a\n", i, pn, in[i], n[i]);
			input_warnings(pn, n);
			printf("   local direction for the direction error: (%a, %a, %a)\n", lv[0], lv[1], lv[2]);
			for (k = 0; k < nk; k++)
				eval_one(rc, rc2, bits, &ks[k], p, pn, n, lv);
			printf("\n");
		}
		ref_free(rc);
		ref_free(rc2);
	}
	return 0;
}
