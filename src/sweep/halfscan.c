/*
 * halfscan.c - `onbstudy halfscan`: every method in binary16 (libonb's
 * onb_NAME_arrayh, each operation rounded to binary16) over every
 * binary16 rounding of a unit vector near each axis, and which of them
 * keep a finite, orthonormal basis (issue 43, step 4's first question).
 *
 * Inputs, deterministic (no seed): for each axis k (z, then y, then x),
 * every binary16 value c of [-1, 1] as n_k (30721 values, so every
 * representable distance to each pole, down to the pole itself), at A
 * azimuths phi = 2 pi a / A (a = 0..A-1: the axes' own planes included
 * when 4 divides A), the other two components r cos phi and r sin phi
 * (r = sqrt(1 - c^2)) each rounded to binary16.  So each input is the
 * binary16 rounding of a unit vector, as a renderer's normal stored in
 * half is; components below 2^-25 round to 0, and x^2 underflows (to a
 * subnormal below 2^-7, to 0 below 2^-12) on the methods' squares.
 *
 * Measured per method: the orthonormality defect D = max(| |b1|-1 |,
 * | |b2|-1 |, |b1.n|, |b2.n|, |b1.b2|) in MPFR (ref_defects, exact to
 * 2^-50), in units of u = 2^-11; the largest D over the finite bases and
 * its input (hex); the count of inputs with a NaN or an infinity in the
 * basis, and the first of them.  This is the sweep's defect alone;
 * `sweep --precision half` measures the forward error and the floor too,
 * on the families' binary16 branch rules (docs/reference.md, "Binary16").
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "sweep/halfscan.h"
#include "common/options.h"
#include "common/output.h"
#include "methods/kernels.h"
#include "reference/reference.h"
#include "inputs/inputs.h"

typedef struct {
	double dmax, worst[3];   /* largest finite defect, in absolute terms, and its input */
	long nonfinite, count;
	double bad[3];           /* the first input with a non-finite basis          */
	long bad_at;
} hs_row;

static uint16_t to_bits(double v)
{
	/* v is a binary16 value (fmt_round): its encoding, in plain C */
	const double a = fabs(v);
	uint16_t m;
	if (isnan(v)) return 0x7e00u;
	if (isinf(v)) m = 0x7c00u;
	else if (a < 0x1p-14) m = (uint16_t)(a * 0x1p24);
	else m = (uint16_t)((ilogb(a) + 15) * 1024 + (int)(ldexp(a, 10 - ilogb(a)) - 1024.0));
	return (uint16_t)(signbit(v) ? m | 0x8000u : m);
}

static double from_bits(uint16_t b)
{
	const int e = (b >> 10) & 31, f = b & 1023;
	const double a = e == 0 ? f * 0x1p-24 : e == 31 ? (f ? NAN : INFINITY) : ldexp(1024.0 + f, e - 25);
	return (b & 0x8000u) ? -a : a;
}

/* Input j of the scan (j < 3 * 30721 * A) into n. */
static void hs_input(long j, int az, double n[3])
{
	const long per = 30721L * az;
	const int k = 2 - (int)(j / per);               /* z, y, x */
	const long i = j % per, ci = i / az;
	const int a = (int)(i % az);
	/* the binary16 values of [-1, 1] in order: ordinals -15360 .. 15360 */
	const double c = fmt_step(0.0, ci - 15360, PREC_HALF);
	const double r = sqrt(fmax(0.0, (1.0 - c) * (1.0 + c)));
	const double phi = 6.283185307179586 * a / az;
	n[k] = c;
	n[(k + 1) % 3] = fmt_round(r * cos(phi), PREC_HALF);
	n[(k + 2) % 3] = fmt_round(r * sin(phi), PREC_HALF);
}

static void hs_method(const onb_method *m, int az, int threads, hs_row *row)
{
	const long total = 3L * 30721L * az;
	long j;
	memset(row, 0, sizeof *row);
	row->bad_at = -1;
	row->count = total;
#pragma omp parallel num_threads(threads)
	{
		ref_ctx *rc = ref_new(127);
		hs_row mine;
		memset(&mine, 0, sizeof mine);
		mine.bad_at = -1;
#pragma omp for schedule(static)
		for (j = 0; j < total; j++) {
			double n[3], b[6], d[NDEF], D = 0.0;
			uint16_t hn[3], hb[6];
			int q, fin = 1;
			if (!rc)
				continue;
			hs_input(j, az, n);
			for (q = 0; q < 3; q++)
				hn[q] = to_bits(n[q]);
			m->arrayh(hn, hb, hb + 3);
			for (q = 0; q < 6; q++) {
				b[q] = from_bits(hb[q]);
				fin &= isfinite(b[q]) != 0;
			}
			if (!fin) {
				if (mine.bad_at < 0 || j < mine.bad_at) { mine.bad_at = j; memcpy(mine.bad, n, sizeof n); }
				mine.nonfinite++;
				continue;
			}
			ref_defects(rc, n, b, d);
			for (q = 0; q < NDEF; q++)
				D = fmax(D, fabs(d[q]));
			if (D > mine.dmax) { mine.dmax = D; memcpy(mine.worst, n, sizeof n); }
		}
#pragma omp critical(halfscan_merge)
		{
			row->nonfinite += mine.nonfinite;
			if (mine.dmax > row->dmax) { row->dmax = mine.dmax; memcpy(row->worst, mine.worst, sizeof row->worst); }
			if (mine.bad_at >= 0 && (row->bad_at < 0 || mine.bad_at < row->bad_at)) {
				row->bad_at = mine.bad_at; memcpy(row->bad, mine.bad, sizeof row->bad);
			}
		}
		ref_free(rc);
	}
}

static void usage(FILE *f)
{
	fprintf(f, "usage: onbstudy halfscan [--methods a,b] [--azimuths A] [--threads T] [--out DIR]\n"
	           "Every method in binary16 (libonb's half kernels, each operation rounded to\n"
	           "binary16) over every binary16 rounding of a unit vector with one component\n"
	           "any binary16 value of [-1, 1] (each axis in turn) at A azimuths (default 16):\n"
	           "the largest orthonormality defect over finite bases in u = 2^-11 (MPFR), its\n"
	           "input, and the inputs whose basis has a NaN or an infinity.  Writes\n"
	           "halfscan.csv into DIR (default: the current run, results/latest).  Needs a\n"
	           "build whose compiler has _Float16.\n");
}

static int hs_parse(int argc, char **argv, const char **methods, long *az, int *threads, const char **out)
{
	static const struct option lo[] = {
		{ "methods", required_argument, NULL, 'm' }, { "azimuths", required_argument, NULL, 'a' },
		{ "threads", required_argument, NULL, 't' }, { "out", required_argument, NULL, 'o' },
		CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
	};
	cli_args c;
	long l;
	int v, rc = 0;
	if (cli_begin(&c, "halfscan", argc, argv))
		return 1;
	while (rc == 0 && (v = cli_next(&c, lo)) != -1) {
		if (v == CLI_HELP) { usage(stdout); rc = 1; }
		else if (v == 'm') *methods = c.arg;
		else if (v == 'a') rc = parse_int("--azimuths", c.arg, 1, 4096, az) ? ONB_EXIT_USAGE : 0;
		else if (v == 't') { rc = parse_int("--threads", c.arg, 0, 1024, &l) ? ONB_EXIT_USAGE : 0; *threads = (int)l; }
		else if (v == 'o') *out = c.arg;
		else rc = ONB_EXIT_USAGE;
	}
	if (rc == 0 && cli_no_rest(&c) != 0)
		rc = ONB_EXIT_USAGE;
	cli_end(&c);
	return rc;
}

static void hs_print(FILE *f, const char *name, const hs_row *r, int csv)
{
	const double u = prec_fmt(PREC_HALF)->u;
	if (csv)
		fprintf(f, "%s,%ld,%ld,%.6g,%a,%a,%a,%a,%a,%a\n", name, r->count, r->nonfinite, r->dmax / u,
		        r->worst[0], r->worst[1], r->worst[2], r->bad[0], r->bad[1], r->bad[2]);
	else if (r->nonfinite)
		printf("%-24s %9.4g  (%a, %a, %a)  %8ld non-finite, first at (%a, %a, %a)\n", name, r->dmax / u,
		       r->worst[0], r->worst[1], r->worst[2], r->nonfinite, r->bad[0], r->bad[1], r->bad[2]);
	else
		printf("%-24s %9.4g  (%a, %a, %a)\n", name, r->dmax / u, r->worst[0], r->worst[1], r->worst[2]);
}

int cmd_halfscan(int argc, char **argv)
{
	const char *methods = NULL, *out = NULL;
	long az = 16;
	int threads = 0, rc = hs_parse(argc, argv, &methods, &az, &threads, &out), nk, k;
	study_kernel ks[256];
	study_out o;
	char outbuf[4096];
	if (rc != 0)
		return rc == 1 ? 0 : rc;
	if (!ONB_HAVE_HALF) {
		study_error("halfscan: this build has no binary16 kernels: its compiler lacks _Float16 "
		            "(GCC >= 12, or clang >= 15, on x86-64 or arm64)");
		return ONB_EXIT_USAGE;
	}
#ifdef _OPENMP
	if (!threads) threads = omp_get_num_procs();
#else
	threads = 1;
#endif
	if ((nk = kernels_select(methods, 0, ks, 256)) < 0)
		return ONB_EXIT_USAGE;
	if (out) snprintf(outbuf, sizeof outbuf, "%s", out);
	else study_current_run_dir(outbuf, sizeof outbuf);
	if (study_mkdir_p(outbuf) != 0 || study_out_open(&o, outbuf, "halfscan.csv") != 0)
		return ONB_EXIT_USAGE;
	study_provenance(o.f, "halfscan", 0, threads);
	fprintf(o.f, "# every binary16 value of [-1, 1] as n.z, then n.y, then n.x, at %ld azimuths 2 pi a/%ld, the other two components rounded to binary16 (%ld inputs)\n",
	        az, az, 3L * 30721L * az);
	fprintf(o.f, "# max_defect_u: largest orthonormality defect of a finite basis (MPFR), in u = 2^-11; nonfinite: inputs whose basis has a NaN or an infinity\n");
	fprintf(o.f, "method,inputs,nonfinite,max_defect_u,worst_x,worst_y,worst_z,first_nonfinite_x,first_nonfinite_y,first_nonfinite_z\n");
	printf("%-24s %9s  %s\n", "method (half)", "max D/u", "worst input; non-finite bases");
	for (k = 0; k < nk; k++) {
		hs_row r;
		if (!ks[k].m || !ks[k].m->arrayh)
			continue;
		hs_method(ks[k].m, (int)az, threads, &r);
		hs_print(o.f, ks[k].name, &r, 1);
		hs_print(stdout, ks[k].name, &r, 0);
	}
	if (study_out_commit(&o) != 0)
		return 1;
	fprintf(stderr, "onbstudy: wrote %s/halfscan.csv\n", outbuf);
	return 0;
}
