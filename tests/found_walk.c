/*
 * found_walk.c - an outside search against certify's found side: ulp walks
 * with random restarts in every region of a certify.csv, compared with the
 * region's found value.
 *
 * usage: found_walk CERTIFY.CSV [RESTARTS [STEPS [SEED]]]
 *
 * Per region (not the whole-sphere rows, not singular ones): RESTARTS
 * (default 20) walks from random inputs of the region, and one from the
 * row's own found input, each STEPS (default 300) steps long.  A start is
 * the rounding to the format of a unit vector at a random n.z (uniform, or
 * log-uniform in 1 -+ n.z in the bands next to the poles) and azimuth in
 * the sector, its largest component the rounding of the exact value that
 * makes it unit.  A step moves each component by a random -4..4 ulps (or
 * the two smaller ones, the largest again the rounding that makes the
 * vector unit), and is kept when the input stays in the region and the
 * domain and its defect (cert_probe, as `onbstudy eval` measures it) is
 * larger.  Prints each region whose walk beats found by more than 5%, and
 * a summary: regions, how many are beaten by more than 5%, the largest and
 * the median walk / found; and every region where the walk exceeds the
 * bound (a failed proof).  Exit 0, 1 when some walk exceeds a bound, or 2
 * on bad input.  The regions run in parallel (OpenMP), each on its own
 * random stream from SEED and its row number: the same result on any
 * number of threads.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "methods/kernels.h"
#include "inputs/inputs.h"
#include "certify/region.h"
#include "certify/search.h"
#include "inputs/rng.h"

#define MAXK 128
#define MAXROW 40000

typedef struct {
	cert_ctx *x;
	const study_kernel *k;
	int prec;
	cert_region r;
	uint64_t rng;   /* the row's own stream: the same walks on any thread */
} walker;

static uint64_t next_of(walker *w)   /* SplitMix64: the mix of the counter, then the step */
{
	const uint64_t v = rng_mix64(w->rng);
	w->rng += 0x9e3779b97f4a7c15u;
	return v;
}
#define next() next_of(w)
static double unit_of(walker *w) { return (double)(next() >> 11) * 0x1p-53; }
#define unit() unit_of(w)

/* The defect at n, or -1 when n is outside the region or the domain. */
static double defect(walker *w, const double n[3])
{
	int nf = 0;
	double d;
	if (!cert_in_region(&w->r, n) || !cert_in_domain(n, w->prec == PREC_FLOAT ? 0 : 1, -1.0))
		return -1.0;
	d = cert_probe(w->x, w->k, w->prec, n, &nf);
	return nf ? -1.0 : d;
}

static void start(walker *w, double n[3])
{
	const cert_region *r = &w->r;
	double z, phi, rr, c;
	int b, sure;
	if (r->nz_hi <= -0.9 || r->nz_lo >= 0.9) {   /* log-uniform in 1 -+ z */
		const int south = r->nz_hi <= -0.9;
		double a = south ? 1.0 + r->nz_lo : 1.0 - r->nz_hi, e = south ? 1.0 + r->nz_hi : 1.0 - r->nz_lo;
		if (a <= 0.0)
			a = e * 1e-3;
		z = a * pow(e / a, unit());
		z = south ? -1.0 + z : 1.0 - z;
	} else {
		z = r->nz_lo + (r->nz_hi - r->nz_lo) * unit();
	}
	phi = (r->phi_lo + (r->phi_hi - r->phi_lo) * unit()) * 3.14159265358979323846 / 180.0;
	rr = sqrt(fmax(0.0, (1.0 - z) * (1.0 + z)));
	n[0] = fmt_round(rr * cos(phi), w->prec);
	n[1] = fmt_round(rr * sin(phi), w->prec);
	n[2] = fmt_round(z, w->prec);
	b = cert_biggest(n);
	c = cert_complete(w->x, w->prec, n[(b + 1) % 3], n[(b + 2) % 3], &sure);
	if (!isnan(c))
		n[b] = copysign(c, n[b]);
}

/* A hill climb of `steps` steps from n; returns the best defect (n then
   holds its input). */
static double climb(walker *w, double n[3], long steps)
{
	double best = defect(w, n), m[3];
	long s;
	int i;
	for (s = 0; s < steps; s++) {
		double d;
		memcpy(m, n, sizeof m);
		if (next() & 1) {
			for (i = 0; i < 3; i++)
				m[i] = fmt_step(m[i], (int64_t)(next() % 9) - 4, w->prec);
		} else {
			int b = cert_biggest(m), sure;
			double c;
			m[(b + 1) % 3] = fmt_step(m[(b + 1) % 3], (int64_t)(next() % 9) - 4, w->prec);
			m[(b + 2) % 3] = fmt_step(m[(b + 2) % 3], (int64_t)(next() % 9) - 4, w->prec);
			c = cert_complete(w->x, w->prec, m[(b + 1) % 3], m[(b + 2) % 3], &sure);
			if (isnan(c))
				continue;
			m[b] = copysign(c, m[b]);
		}
		if ((d = defect(w, m)) > best) {
			best = d;
			memcpy(n, m, sizeof m);
		}
	}
	return best;
}

static int cmp_d(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return x < y ? -1 : x > y;
}

typedef struct {
	char meth[64];
	int k, prec;
	cert_region r;
	double bound, found, n[3];
	double best, at[3];   /* the walks' result */
} row;

static row rows[MAXROW];
static double ratios[MAXROW];

/* The rows of a certify.csv to walk: not singular, not whole-sphere, with
   a found input, of a method this build has. */
static int read_rows(FILE *in, const study_kernel *ks, int nk)
{
	char line[4096];
	int nr = 0;
	while (fgets(line, sizeof line, in) && nr < MAXROW) {
		char prec[16], status[16], fx[64], fy[64], fz[64];
		row *w = &rows[nr];
		int k;
		if (line[0] == '#' || strncmp(line, "method,", 7) == 0)
			continue;
		for (k = 0; line[k]; k++)
			if (line[k] == ',')
				line[k] = ' ';
		if (sscanf(line, "%63s %15s %lf %lf %lf %lf %lf %lf %63s %63s %63s %15s", w->meth, prec, &w->r.nz_lo,
		           &w->r.nz_hi, &w->r.phi_lo, &w->r.phi_hi, &w->bound, &w->found, fx, fy, fz, status) != 12)
			continue;
		if (strcmp(status, "singular") == 0 || (w->r.nz_lo == -1.0 && w->r.nz_hi == 1.0 && w->r.phi_hi == 360.0 &&
		                                        w->r.phi_lo == 0.0) || !(w->found > 0.0))
			continue;
		for (k = 0; k < nk && strcmp(ks[k].name, w->meth) != 0; k++)
			;
		if (k == nk)
			continue;
		w->k = k;
		w->prec = strcmp(prec, "double") == 0 ? PREC_DOUBLE : PREC_FLOAT;
		w->n[0] = strtod(fx, NULL); w->n[1] = strtod(fy, NULL); w->n[2] = strtod(fz, NULL);
		nr++;
	}
	return nr;
}

/* One row's walks: from its found input, then `restarts` random starts. */
static void walk_row(walker *w, row *r, long restarts, long steps)
{
	double n[3];
	long i;
	memcpy(n, r->n, sizeof n);
	r->best = climb(w, n, steps);
	memcpy(r->at, n, sizeof n);
	for (i = 0; i < restarts; i++) {
		double d;
		start(w, n);
		if ((d = climb(w, n, steps)) > r->best) {   /* keep its input: the one printed */
			r->best = d;
			memcpy(r->at, n, sizeof n);
		}
	}
}

int main(int argc, char **argv)
{
	static study_kernel ks[MAXK];
	long restarts = argc > 2 ? atol(argv[2]) : 20, steps = argc > 3 ? atol(argv[3]) : 300;
	int nk = kernels_select(NULL, 0, ks, MAXK), nr, i, beaten = 0, above = 0, fail = 0;
	uint64_t seed;
	double worst = 0.0;
	FILE *in;
	if (argc < 2 || argc > 5 || restarts < 0 || steps < 0) {
		fprintf(stderr, "usage: found_walk CERTIFY.CSV [RESTARTS [STEPS [SEED]]]\n");
		return 2;
	}
	seed = argc > 4 ? strtoull(argv[4], NULL, 0) : 12345;
	if (!(in = fopen(argv[1], "r"))) {
		fprintf(stderr, "found_walk: %s: cannot open\n", argv[1]);
		return 2;
	}
	nr = read_rows(in, ks, nk);
	fclose(in);
#pragma omp parallel
	{
		walker w;
		int j;
		memset(&w, 0, sizeof w);
		if (!(w.x = cert_ctx_new())) {
#pragma omp atomic write
			fail = 1;
		}
#pragma omp for schedule(dynamic, 1)
		for (j = 0; j < nr; j++) {
			if (!w.x)
				continue;
			w.k = &ks[rows[j].k];
			w.prec = rows[j].prec;
			w.r = rows[j].r;
			w.rng = rng_mix64(seed ^ rng_mix64((uint64_t)j));
			walk_row(&w, &rows[j], restarts, steps);
		}
		cert_ctx_free(w.x);
	}
	if (fail) {
		fprintf(stderr, "found_walk: out of memory\n");
		return 2;
	}
	for (i = 0; i < nr; i++) {
		const row *r = &rows[i];
		ratios[i] = r->best / r->found;
		if (r->best > r->bound) {   /* the proof fails: never expected */
			above++;
			printf("%s %s n.z [%.17g, %.17g] phi [%g, %g]: ABOVE THE BOUND %.6g: walk %.6g at (%a, %a, %a)\n", r->meth,
			       prec_name(r->prec), r->r.nz_lo, r->r.nz_hi, r->r.phi_lo, r->r.phi_hi, r->bound, r->best, r->at[0],
			       r->at[1], r->at[2]);
		}
		if (r->best > 1.05 * r->found) {
			beaten++;
			printf("%s %s n.z [%.17g, %.17g] phi [%g, %g]: found %.6g, walk %.6g (x%.3f) at (%a, %a, %a)\n", r->meth,
			       prec_name(r->prec), r->r.nz_lo, r->r.nz_hi, r->r.phi_lo, r->r.phi_hi, r->found, r->best,
			       r->best / r->found, r->at[0], r->at[1], r->at[2]);
		}
		if (ratios[i] > worst)
			worst = ratios[i];
	}
	qsort(ratios, (size_t)nr, sizeof *ratios, cmp_d);
	printf("found_walk: %d regions, %ld restarts x %ld steps: walk beats found by > 5%% in %d; largest walk/found %.4f, median %.4f; above the bound in %d\n",
	       nr, restarts, steps, beaten, worst, nr ? ratios[nr / 2] : NAN, above);
	return above ? 1 : 0;
}
