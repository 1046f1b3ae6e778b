/*
 * list.c - `onbstudy list`: the registry, as a table or CSV; with --axes,
 * each method's frame at +-x, +-y and +-z (docs/library.md, "Migrating").
 */
#include <math.h>
#include <string.h>
#include "cli/list.h"
#include "model/arith.h"
#include "common/options.h"

/* x as %g, every NaN as "nan" (its sign bit differs between CPUs). */
static const char *num(char *buf, size_t len, double x)
{
	if (isnan(x))
		snprintf(buf, len, "nan");
	else
		snprintf(buf, len, "%g", x);
	return buf;
}

/* v as "(x, y, z)" (csv 0) or "x,y,z" (csv 1) into buf. */
static const char *vec(char *buf, size_t len, onb_vec3 v, int csv)
{
	char a[32], b[32], c[32];
	snprintf(buf, len, csv ? "%s,%s,%s" : "(%s, %s, %s)", num(a, sizeof a, v.x), num(b, sizeof b, v.y),
	         num(c, sizeof c, v.z));
	return buf;
}

/* The binary16 kernel on the encodings of v (an axis), widened. */
static void axes_half(onb_arrayh_fn f, onb_vec3 v, onb_vec3 *b1, onb_vec3 *b2)
{
	uint16_t hn[3] = { prec_half_bits(v.x), prec_half_bits(v.y), prec_half_bits(v.z) }, hb[6];
	f(hn, hb, hb + 3);
	b1->x = prec_half_value(hb[0]); b1->y = prec_half_value(hb[1]); b1->z = prec_half_value(hb[2]);
	b2->x = prec_half_value(hb[3]); b2->y = prec_half_value(hb[4]); b2->z = prec_half_value(hb[5]);
}

/* b1, b2 and det(b1, b2, n) of every method at the six axes: in double
   through method->basis, in float (widened) for the float-only methods. */
static void list_axes(const onb_method *m, size_t n, int csv, int half)
{
	static const char *const an[6] = { "+x", "-x", "+y", "-y", "+z", "-z" };
	size_t i, a;
	if (csv)
		printf("name,axis,b1x,b1y,b1z,b2x,b2y,b2z,det\n");
	else
		printf(half ? "# b1 and b2 at the six axes (binary16: onb_NAME_arrayh, values exact); det = det(b1, b2, n)\n"
		            "%-24s %-4s %-22s %-22s %s\n" :
		       "# b1 and b2 at the six axes (double; float for float-only methods); det = det(b1, b2, n)\n"
		       "%-24s %-4s %-22s %-22s %s\n", "name", "n", "b1", "b2", "det");
	for (i = 0; i < n; i++)
		for (a = 0; a < 6; a++) {
			onb_vec3 v = { 0.0, 0.0, 0.0 }, b1, b2;
			char v1[128], v2[128], dd[32];
			double d;
			*(&v.x + a / 2) = (a % 2) ? -1.0 : 1.0;
			if (half) {
				if (!m[i].arrayh)
					break;
				axes_half(m[i].arrayh, v, &b1, &b2);
			} else if (m[i].basis) {
				m[i].basis(v, &b1, &b2);
			} else {
				onb_vec3f vf = { (float)v.x, (float)v.y, (float)v.z }, f1, f2;
				m[i].basisf(vf, &f1, &f2);
				b1.x = f1.x; b1.y = f1.y; b1.z = f1.z; b2.x = f2.x; b2.y = f2.y; b2.z = f2.z;
			}
			d = v.x * (b1.y * b2.z - b1.z * b2.y) + v.y * (b1.z * b2.x - b1.x * b2.z) + v.z * (b1.x * b2.y - b1.y * b2.x);
			printf(csv ? "%s,%s,%s,%s,%s\n" : "%-24s %-4s %-22s %-22s %s\n", csv || a == 0 ? m[i].name : "", an[a],
			       vec(v1, sizeof v1, b1, csv), vec(v2, sizeof v2, b2, csv), num(dd, sizeof dd, d));
		}
}

/* A provenance's fields as CSV cells (empty for a paper's method). */
static void prov_csv(const onb_provenance *p)
{
	static const onb_provenance none = { "", "", "", "", "", "", "" };
	if (!p)
		p = &none;
	printf(",%s,%s,\"%s\",%s,\"%s\",\"%s\",\"%s\"", p->repository, p->commit, p->path, p->license, p->language,
	       p->precision, p->build);
}

/* The aliases: engines' code that is a registry method bit for bit. */
static void list_aliases(int csv)
{
	size_t n, i;
	const onb_alias *a = onb_aliases(&n);
	if (csv) {
		printf("name,target,precisions,source,note,repository,commit,path,license,language,precision,build\n");
		for (i = 0; i < n; i++) {
			printf("%s,%s,%s,\"%s\",\"%s\"", a[i].name, a[i].target, a[i].precisions, a[i].source, a[i].note);
			prov_csv(&a[i].prov);
			printf("\n");
		}
		return;
	}
	printf("# %zu aliases: shipped code that is a method above, bit for bit\n", n);
	for (i = 0; i < n; i++) {
		printf("%-24s = %s, bit for bit (%s): %s\n", a[i].name, a[i].target, a[i].precisions, a[i].source);
		printf("%-24s   %s %.12s %s (%s)\n", "", a[i].prov.repository, a[i].prov.commit, a[i].prov.path, a[i].prov.license);
		if (a[i].note[0])
			printf("%-24s   note: %s\n", "", a[i].note);
	}
}

/* list --arith: the profiles' table, then each profile's sources. */
static void list_arith(void)
{
	int i;
	arith_print_table();
	printf("\n");
	for (i = 0; i < arith_count(); i++) {
		const arith_profile *p = arith_at(i);
		printf("%s: %s\n  spec: %s\n  float: %s\n  double: %s\n  half: %s\n  built-ins: %s\n", p->name, p->title,
		       p->spec, p->fmt[PREC_FLOAT].note, p->fmt[PREC_DOUBLE].note,
		       p->fmt[PREC_HALF].note ? p->fmt[PREC_HALF].note : "not transcribed here: every operation unbounded",
		       p->compose);
	}
}

int cmd_list(int argc, char **argv)
{
	static const struct option lo[] = {
		{ "format", required_argument, NULL, 'f' }, { "axes", no_argument, NULL, 'a' },
		{ "aliases", no_argument, NULL, 'l' }, { "arith", no_argument, NULL, 'r' },
		{ "precision", required_argument, NULL, 'p' }, CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
	};
	size_t n, i;
	const onb_method *m = onb_methods(&n);
	int csv = 0, axes = 0, aliases = 0, arith = 0, v, rc = 0, prec = -1, on[PREC_COUNT];
	cli_args c;
	if (cli_begin(&c, "list", argc, argv))
		return 1;
	while (rc == 0 && (v = cli_next(&c, lo)) != -1) {
		if (v == CLI_HELP) {
			printf("usage: onbstudy list [--axes [--precision double|half] | --aliases | --arith] [--format table|csv]\n"
			       "  The methods in the registry: name, handedness, singular directions, source;\n"
			       "  then the aliases (an engine's code that is a method bit for bit).\n"
			       "  CSV: one row per method, with the provenance of shipped code (repository,\n"
			       "  commit, path:lines, license, language, precision, build).\n"
			       "  --axes: each method's b1 and b2 at +-x, +-y, +-z, and det(b1, b2, n) there;\n"
			       "  in double (float for float-only methods), or with --precision half in binary16\n"
			       "  (libonb's onb_NAME_arrayh, each operation rounded to binary16).\n"
			       "  --aliases: the aliases alone (target, precisions, exceptions, provenance).\n"
			       "  --arith: the arithmetic profiles of certify/sweep/eval --arith, per format:\n"
			       "  each operation's allowance (RN: round to nearest; Nulp; rel: relative;\n"
			       "  ulp24: in float ulps; mul+add, 1/rsqrt, x*rcp: performed as those;\n"
			       "  none: unspecified), flushing, contraction, reassociation, zero signs.\n");
			rc = -1;
		} else if (v == 'a') {
			axes = 1;
		} else if (v == 'l') {
			aliases = 1;
		} else if (v == 'r') {
			arith = 1;
		} else if (v == 'p') {
			if (cli_precision_half("--precision", c.arg, on) != 0)
				rc = ONB_EXIT_USAGE;
			else if (on[PREC_FLOAT] || on[PREC_DOUBLE] + on[PREC_HALF] != 1) {
				study_error("list --axes --precision: double or half, not '%s'", c.arg);
				rc = ONB_EXIT_USAGE;
			} else
				prec = on[PREC_HALF] ? PREC_HALF : PREC_DOUBLE;
		} else if (v != 'f' || (csv = cli_format("--format", c.arg, 0)) < 0) {
			rc = ONB_EXIT_USAGE;
		}
	}
	if (rc == 0 && cli_no_rest(&c) != 0)
		rc = ONB_EXIT_USAGE;
	cli_end(&c);
	if (rc)
		return rc < 0 ? 0 : rc;
	if (axes + aliases + arith > 1) {
		study_error("list: --axes, --aliases and --arith exclude each other");
		return ONB_EXIT_USAGE;
	}
	if (prec >= 0 && !axes) {
		study_error("list: --precision goes with --axes");
		return ONB_EXIT_USAGE;
	}
	if (arith) {
		list_arith();
		return 0;
	}
	if (axes) {
		list_axes(m, n, csv, prec == PREC_HALF);
		return 0;
	}
	if (aliases) {
		list_aliases(csv);
		return 0;
	}
	if (csv) {
		printf("name,family,handedness,flags,threshold,source,singular,thresholds,"
		       "repository,commit,path,license,language,precision,build\n");
		for (i = 0; i < n; i++) {
			printf("%s,%s,%+d,%u,%a,\"%s\",\"%s\",\"%s\"", m[i].name, m[i].family, m[i].handedness,
			       m[i].flags, m[i].threshold, m[i].source, m[i].singular, m[i].thresholds);
			prov_csv(m[i].prov);
			printf("\n");
		}
		return 0;
	}
	printf("# %zu methods; batch kernels run %s; hardware rsqrt: %s\n", n, onb_batch_isa(),
	       ONB_HAVE_HW_RSQRT ? "rsqrtss/rsqrtps" : "absent (the _rsqrt variants fell back to 1/sqrt)");
	printf("%-24s %4s  %-52s %s\n", "name", "hand", "singular directions", "source");
	for (i = 0; i < n; i++)
		printf("%-24s %+4d  %-52s %s%s\n", m[i].name, m[i].handedness, m[i].singular, m[i].source,
		       (m[i].flags & ONB_FELL_BACK) ? " [FELL BACK: no hardware rsqrt]" :
		       (m[i].flags & ONB_FLOAT_ONLY) ? " [float only]" : "");
	list_aliases(0);
	return 0;
}
