/*
 * certify_check.c - soundness of `onbstudy certify` against every defect
 * the study has measured: for each input of the given worst-case
 * files (results/reference/worst.csv, results/poles/.../worst.csv) that is
 * in the certified domain, the bound of the certify.csv region holding it
 * must not be below its measured defect.
 *
 * usage: certify_check CERTIFY.CSV WORST.CSV...
 * Prints the number of inputs checked and every violation; exits 1 on a
 * violation or when nothing could be checked, 2 on bad input.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "common/csv.h"
#include "methods/kernels.h"
#include "certify/region.h"
#include "certify/search.h"

#define MAXROW 100000
#define MAXCOL 64

typedef struct {
	char method[64];
	int prec;
	cert_region r;
	double bound;
	int singular;
} crow;

static crow rows[MAXROW];
static int nrows;

static int load_certify(const char *path)
{
	char line[4096], *f[MAXCOL];
	FILE *in = fopen(path, "r");
	if (!in) {
		fprintf(stderr, "certify_check: %s: cannot open\n", path);
		return -1;
	}
	while (fgets(line, sizeof line, in)) {
		crow *c = &rows[nrows];
		if (line[0] == '#' || strncmp(line, "method,", 7) == 0)
			continue;
		if (nrows == MAXROW) {   /* every region must be checked, none dropped */
			fprintf(stderr, "certify_check: %s: more than %d regions\n", path, MAXROW);
			fclose(in);
			return -1;
		}
		if (csv_split(line, f, MAXCOL, 0) < 12)
			continue;
		snprintf(c->method, sizeof c->method, "%s", f[0]);
		c->prec = strcmp(f[1], "double") == 0 ? PREC_DOUBLE : PREC_FLOAT;
		c->r.nz_lo = strtod(f[2], NULL); c->r.nz_hi = strtod(f[3], NULL);
		c->r.phi_lo = strtod(f[4], NULL); c->r.phi_hi = strtod(f[5], NULL);
		c->bound = strtod(f[6], NULL);
		c->singular = strcmp(f[11], "singular") == 0;
		if (!(c->r.nz_lo == -1.0 && c->r.nz_hi == 1.0 && c->r.phi_lo == 0.0 && c->r.phi_hi == 360.0))
			nrows++;   /* the whole-sphere rows are maxima of these */
	}
	fclose(in);
	return nrows > 0 ? 0 : -1;
}

static int unit_domain(const char *dist)
{
	static const char *const ok[] = { "uniform", "north", "south", "threshold", "exhaustive", "grid" };
	size_t i;
	for (i = 0; i < sizeof ok / sizeof ok[0]; i++)
		if (strcmp(dist, ok[i]) == 0)
			return 1;
	return 0;
}

/* Check one measured input; returns 1 checked, 0 skipped, -1 violated. */
static int check_one(const char *method, int prec, const double n[3], double err)
{
	int i, seen = 0;
	if (!cert_in_domain(n, prec == PREC_FLOAT ? 0 : 1, -1.0))
		return 0;
	for (i = 0; i < nrows; i++) {
		const crow *c = &rows[i];
		if (c->prec != prec || strcmp(c->method, method) != 0 || !cert_in_region(&c->r, n))
			continue;
		seen = 1;
		/* the worst-case files print the error to 6 significant digits:
		   it may read up to 5e-6 relative above the value measured */
		if (!c->singular && !(c->bound >= err * (1.0 - 5e-6))) {
			printf("VIOLATION %s %s n = (%a, %a, %a): measured %.17g > bound %.17g (region n.z [%g, %g], phi [%g, %g])\n",
			       method, prec_name(prec), n[0], n[1], n[2], err, c->bound,
			       c->r.nz_lo, c->r.nz_hi, c->r.phi_lo, c->r.phi_hi);
			return -1;
		}
	}
	return seen;
}

static int check_file(const char *path, long *checked, long *bad)
{
	char line[8192], *h[MAXCOL], *f[MAXCOL], head[8192];
	int nh = 0, cmeth = -1, cp = -1, cd = -1, ce = -1, cx = -1, cy = -1, cz = -1;
	FILE *in = fopen(path, "r");
	if (!in) {
		fprintf(stderr, "certify_check: %s: cannot open\n", path);
		return -1;
	}
	while (fgets(line, sizeof line, in)) {
		double n[3];
		int r;
		if (line[0] == '#')
			continue;
		if (!nh) {
			memcpy(head, line, sizeof head);
			nh = csv_split(head, h, MAXCOL, 0);
			cmeth = csv_col(h, nh, "method"); cp = csv_col(h, nh, "precision"); cd = csv_col(h, nh, "distribution");
			ce = csv_col(h, nh, "error"); cx = csv_col(h, nh, "nx"); cy = csv_col(h, nh, "ny"); cz = csv_col(h, nh, "nz");
			if (cmeth < 0 || cd < 0 || ce < 0 || cx < 0 || cy < 0 || cz < 0) {
				fprintf(stderr, "certify_check: %s: no method/distribution/error/nx/ny/nz columns\n", path);
				fclose(in);
				return -1;
			}
			continue;
		}
		if (csv_split(line, f, MAXCOL, 0) < nh || !unit_domain(f[cd]))
			continue;
		n[0] = strtod(f[cx], NULL); n[1] = strtod(f[cy], NULL); n[2] = strtod(f[cz], NULL);
		r = check_one(f[cmeth], cp >= 0 && strcmp(f[cp], "double") == 0 ? PREC_DOUBLE : PREC_FLOAT, n, strtod(f[ce], NULL));
		*checked += r > 0;
		*bad += r < 0;
	}
	fclose(in);
	return 0;
}

int main(int argc, char **argv)
{
	long checked = 0, bad = 0;
	int i;
	if (argc < 3) {
		fprintf(stderr, "usage: certify_check CERTIFY.CSV WORST.CSV...\n");
		return 2;
	}
	if (load_certify(argv[1]))
		return 2;
	for (i = 2; i < argc; i++)
		if (check_file(argv[i], &checked, &bad))
			return 2;
	printf("certify_check: %ld measured inputs in the domain checked against %d region bounds, %ld above their bound\n",
	       checked, nrows, bad);
	return bad || checked == 0;
}
