/*
 * certify_half.c - `onbstudy certify --precision half`: proven extremes in
 * binary16 (issue 43, item 3).
 *
 * The bound side is certify's own: the methods' rounding models (their
 * families' models, run in PREC_HALF) on mvf.c's mean value form, whose
 * every rounding takes binary16's parameters (common/prec.h): u = 2^-11,
 * an absolute 2^-25 where a result can fall below 2^-14 (a subnormal, or
 * 0 below 2^-25), and no bound where a value can exceed 65504 (overflow to
 * infinity).  A region whose enclosures reach a division by an interval
 * holding 0 gets no number: its status says why (ch_status_name).
 *
 * The found side is a scan, not a search: binary16 is small enough that
 * every n.z of a band is tried (ch_scan), so the worst input is found
 * nearly everywhere without the float search's walks.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "certify_half.h"
#include "regions.h"
#include "common/options.h"
#include "common/output.h"
#include "common/progress.h"
#include "inputs/inputs.h"
#include "reference/reference.h"

#define CH_MAXREG 1024

const char *ch_status_name(int s)
{
	return s == CH_PROVEN ? "proven" : s == CH_NONFINITE ? "non-finite" : s == CH_OVERFLOW ? "overflow" : "unbounded";
}

/* The defect max(| |b1|-1 |, | |b2|-1 |, |b1.n|, |b2.n|, |b1.b2|) in double
   (binary16 values: each product exact, each sum within 2^-52 of it). */
static double defect_d(const double n[3], const double b[6])
{
	const double *p = b, *q = b + 3;
	const double s1 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2], s2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
	double d = fmax(fabs((s1 - 1.0) / (sqrt(s1) + 1.0)), fabs((s2 - 1.0) / (sqrt(s2) + 1.0)));
	d = fmax(d, fabs(p[0] * n[0] + p[1] * n[1] + p[2] * n[2]));
	d = fmax(d, fabs(q[0] * n[0] + q[1] * n[1] + q[2] * n[2]));
	return fmax(d, fabs(p[0] * q[0] + p[1] * q[1] + p[2] * q[2]));
}

typedef struct {
	const study_kernel *k;
	const cert_region *r;
	double dmax, worst[3];
	long count, nonfinite;
} ch_acc;

/* One input n (binary16 values) of the scan: skipped outside the region. */
static void ch_eval(ch_acc *a, const double n[3])
{
	uint16_t hn[3], hb[6];
	double b[6], d;
	int q, fin = 1;
	if (!cert_in_region(a->r, n))
		return;
	for (q = 0; q < 3; q++)
		hn[q] = prec_half_bits(n[q]);
	a->k->m->arrayh(hn, hb, hb + 3);
	for (q = 0; q < 6; q++) {
		b[q] = prec_half_value(hb[q]);
		fin &= isfinite(b[q]) != 0;
	}
	a->count++;
	d = fin ? defect_d(n, b) : INFINITY;
	if (!fin)
		a->nonfinite++;
	if (d > a->dmax || (a->count == 1 && d == a->dmax)) {
		a->dmax = d;
		memcpy(a->worst, n, sizeof a->worst);
	}
}

/* splitmix64: the sampler's deterministic stream */
static uint64_t ch_rand(uint64_t *st)
{
	uint64_t z = (*st += 0x9e3779b97f4a7c15ull);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
	return z ^ (z >> 31);
}

static double ch_unit(uint64_t *st) { return (double)(ch_rand(st) >> 11) * 0x1p-53; }

/* A binary16 value of [lo, hi] (0 <= lo <= hi) uniform in the encodings,
   so every binade is tried as often: the subnormals and the small
   components whose squares underflow among them. */
static double ch_half_in(uint64_t *st, double lo, double hi)
{
	const unsigned a = prec_half_bits(prec_half_round(lo)), b = prec_half_bits(prec_half_round(hi));
	return prec_half_value((uint16_t)(a + (unsigned)(ch_rand(st) % (b - a + 1u))));
}

/* Inputs derived from (x, y): x the rounding of r cos(phi) for r and phi
   random in the region's ring and sector, y every other sample its
   partner r sin(phi) rounded, else a binary16 value drawn by encoding from
   the ring's y range at that x; n.z = +-RN(sqrt(1 - x^2 - y^2)) (each sign
   the band allows), so n is the rounding of the unit vector
   (x, y, sqrt(1 - x^2 - y^2)). */
static void ch_ring(ch_acc *a, long count, uint64_t seed)
{
	const double deg = 3.14159265358979323846 / 180.0, zl = a->r->nz_lo, zh = a->r->nz_hi;
	const double za = fmin(fabs(zl), fabs(zh)), zb = fmax(fabs(zl), fabs(zh));
	const double r_lo = zl < 0.0 && zh > 0.0 ? 0.0 : sqrt(fmax(0.0, 1.0 - zb * zb)) * (1 - 1e-9);
	const double r_hi = fmin(1.0, sqrt(fmax(0.0, 1.0 - (zl < 0.0 && zh > 0.0 ? 0.0 : za * za))) * (1 + 1e-9));
	uint64_t st = seed;
	long i;
	for (i = 0; i < count; i++) {
		const double phi = (a->r->phi_lo + (a->r->phi_hi - a->r->phi_lo) * ch_unit(&st)) * deg;
		const double rr = r_lo + (r_hi - r_lo) * ch_unit(&st), sy = sin(phi) < 0.0 ? -1.0 : 1.0;
		double n[3], y2;
		n[0] = prec_half_round(rr * cos(phi));
		if (i % 2 == 0) {
			n[1] = prec_half_round(rr * sin(phi));
		} else {
			y2 = r_hi * r_hi - n[0] * n[0];
			if (!(y2 >= 0.0))
				continue;
			n[1] = sy * ch_half_in(&st, sqrt(fmax(0.0, r_lo * r_lo - n[0] * n[0])), sqrt(y2));
		}
		n[2] = prec_half_round(sqrt(fmax(0.0, 1.0 - n[0] * n[0] - n[1] * n[1])));
		if (zh > 0.0)
			ch_eval(a, n);
		n[2] = -n[2];
		if (zl < 0.0)
			ch_eval(a, n);
	}
}

double ch_scan(const study_kernel *k, const cert_region *r, int az, double worst[3], long *count, long *nonfinite)
{
	const double deg = 3.14159265358979323846 / 180.0;
	ch_acc a;
	double z;
	int j;
	memset(&a, 0, sizeof a);
	a.k = k;
	a.r = r;
	/* every binary16 n.z of the band, from its lowest up */
	for (z = fmax(-1.0, prec_half_round(r->nz_lo)); z <= fmin(1.0, r->nz_hi); z = fmt_step(z, 1, PREC_HALF)) {
		const double rr = sqrt(fmax(0.0, (1.0 - z) * (1.0 + z)));
		for (j = 0; j <= az; j++) {
			const double phi = (r->phi_lo + (r->phi_hi - r->phi_lo) * j / az) * deg;
			const double n[3] = { prec_half_round(rr * cos(phi)), prec_half_round(rr * sin(phi)), z };
			ch_eval(&a, n);
		}
		if (z >= 1.0)
			break;
	}
	ch_ring(&a, 2048L * az, 0x68616c66ull ^ (uint64_t)(1e6 * (r->nz_lo + 2.0)) ^ ((uint64_t)r->phi_lo << 40));
	*count = a.count;
	*nonfinite = a.nonfinite;
	memcpy(worst, a.worst, sizeof a.worst);
	return a.dmax;
}

double ch_bound(bound_ctx *b, const cm_method *m, const cert_region *r, double target, int depth)
{
	mvf_box box;
	cert_region h[2];
	double v, w = 0.0;
	int i;
	if (half_band_empty(r))
		return 0.0;   /* no input */
	region_box(r, PREC_HALF, -1.0, &box);
	v = bound_box(b, m, &box);
	if (v < 0.0)
		v = 0.0;   /* no path: no input of the region lies in the box */
	if (depth <= 0 || v <= target)
		return v;
	h[0] = h[1] = *r;
	if (r->nz_hi - r->nz_lo >= 1e-4 && (depth % 2 == 0 || r->phi_hi - r->phi_lo < 1e-3))
		h[0].nz_hi = h[1].nz_lo = 0.5 * (r->nz_lo + r->nz_hi);
	else
		h[0].phi_hi = h[1].phi_lo = 0.5 * (r->phi_lo + r->phi_hi);
	for (i = 0; i < 2 && w < v; i++)
		w = fmax(w, ch_bound(b, m, &h[i], target, depth - 1));
	return fmin(v, w);
}

/* The defect of k's half basis at n in MPFR (ref_defects: within 2^-50). */
static double exact_defect(const study_kernel *k, const double n[3])
{
	ref_ctx *rc = ref_new(127);
	uint16_t hn[3], hb[6];
	double b[6], d[NDEF], D = 0.0;
	int q;
	if (!rc)
		return INFINITY;
	for (q = 0; q < 3; q++)
		hn[q] = prec_half_bits(n[q]);
	k->m->arrayh(hn, hb, hb + 3);
	for (q = 0; q < 6; q++)
		b[q] = prec_half_value(hb[q]);
	ref_defects(rc, n, b, d);
	for (q = 0; q < NDEF; q++)
		D = fmax(D, fabs(d[q]));
	ref_free(rc);
	return D;
}

void ch_region(bound_ctx *b, const study_kernel *k, const cm_method *m, const cert_region *r, int depth, int az,
               ch_result *out)
{
	const double u = prec_fmt(PREC_HALF)->u;
	memset(out, 0, sizeof *out);
	out->unb_op = -1;
	out->found = ch_scan(k, r, az, out->worst, &out->scanned, &out->nonfinite);
	if (out->found > 0.0 && out->found < INFINITY)
		out->found = exact_defect(k, out->worst);
	(void)bound_overflow_seen(b);
	out->bound = ch_bound(b, m, r, fmax(2.0 * out->found, u), depth);
	if (out->nonfinite)
		out->status = CH_NONFINITE;
	else if (!(out->bound < INFINITY)) {
		out->status = bound_overflow_seen(b) ? CH_OVERFLOW : CH_UNBOUNDED;
		out->unb_op = bound_unbounded_op(b);
	} else
		out->status = CH_PROVEN;
	if (out->status == CH_PROVEN && out->found > out->bound)
		out->status = CH_UNBOUNDED;   /* a bound under a defect the scan measured is no proof: the model's
		                                 paths miss the kernel's (physx in half: every box "no path") */
	if (out->status != CH_PROVEN)
		out->bound = INFINITY;
}

static int ch_threads(void)
{
#ifdef _OPENMP
	return omp_get_max_threads();
#else
	return 1;
#endif
}

/* One task: kernel k over region i. */
typedef struct {
	int k, i;
} ch_task;

static void ch_run_all(const ch_opts *o, const study_kernel *ks, const cm_method **ms, const cert_region *reg,
                       const ch_task *t, int nt, ch_result *res)
{
	int j;
#pragma omp parallel
	{
		bound_ctx *b = bound_new();
#pragma omp for schedule(dynamic, 1)
		for (j = 0; j < nt; j++) {
			if (!b) {
				res[j].status = CH_UNBOUNDED;
				res[j].bound = INFINITY;
				continue;
			}
			bound_set_arith(b, o->arith);   /* NULL: ieee; resets the unbounded operation */
			ch_region(b, &ks[t[j].k], ms[t[j].k], &reg[t[j].i], o->depth, o->az, &res[j]);
		}
		bound_free(b);
	}
}

/* --arith: the operation an unbounded row owes it to (certify.c's unbounded_by) */
static const char *ch_unb(const ch_result *x)
{
	return x->status == CH_UNBOUNDED && x->unb_op >= 0 ? arith_op_name(x->unb_op) : "";
}

static void ch_write_rows(FILE *f, const study_kernel *ks, const cert_region *reg, const ch_task *t, int nt,
                          const ch_result *res, int arith)
{
	int j;
	fprintf(f, "method,precision,nz_lo,nz_hi,phi_lo,phi_hi,bound,found,found_nx,found_ny,found_nz,status,scanned,nonfinite%s\n",
	        arith ? ",unbounded_by" : "");
	for (j = 0; j < nt; j++) {
		const cert_region *r = &reg[t[j].i];
		const ch_result *x = &res[j];
		fprintf(f, "%s,half,%.17g,%.17g,%g,%g,%.17g,%.17g,%a,%a,%a,%s,%ld,%ld", ks[t[j].k].name, r->nz_lo,
		        r->nz_hi, r->phi_lo, r->phi_hi, x->bound, x->found, x->worst[0], x->worst[1], x->worst[2],
		        ch_status_name(x->status), x->scanned, x->nonfinite);
		fprintf(f, arith ? ",%s\n" : "\n", ch_unb(x));
	}
}

/* The whole-sphere row of kernel k: the largest bound and found of its
   regions, and how many are proven, non-finite, overflow, unbounded. */
static void ch_summary(FILE *f, const study_kernel *ks, int nk, const ch_task *t, int nt, const ch_result *res)
{
	const double u = prec_fmt(PREC_HALF)->u;
	int k, j;
	fprintf(f, "%-24s %-6s %12s %12s %7s  %s\n", "method", "prec", "bound/u", "found/u", "ratio",
	        "regions proven/non-finite/overflow/unbounded");
	for (k = 0; k < nk; k++) {
		double B = 0.0, F = 0.0;
		int c[4] = { 0, 0, 0, 0 }, any = 0;
		const char *unb = "";
		for (j = 0; j < nt; j++)
			if (t[j].k == k) {
				any = 1;
				B = fmax(B, res[j].bound);
				F = fmax(F, res[j].found);
				c[res[j].status]++;
				if (!unb[0])
					unb = ch_unb(&res[j]);
			}
		if (!any)
			continue;
		fprintf(f, "%-24s %-6s %12.4g %12.4g %7.3g  %d/%d/%d/%d%s%s\n", ks[k].name, "half", B / u, F / u,
		        B < INFINITY && F > 0.0 ? B / F : NAN, c[0], c[1], c[2], c[3], unb[0] ? "  unbounded by " : "", unb);
	}
}

static int ch_write(const ch_opts *o, const study_kernel *ks, int nk, const cert_region *reg, const ch_task *t,
                    int nt, const ch_result *res, double secs)
{
	study_out out;
	char dir[4096];
	if (o->out)
		snprintf(dir, sizeof dir, "%s", o->out);
	else
		study_current_run_dir(dir, sizeof dir);
	if (study_mkdir_p(dir) != 0 || study_out_open(&out, dir, "certify-half.csv") != 0)
		return 1;
	study_provenance(out.f, "certify", 0, ch_threads());
	fprintf(out.f, "# binary16: u = 2^-11, normal min 2^-14, subnormal step 2^-24, max 65504; "
	               "depth %d, %d azimuths per sector, %d sectors; %.1f s\n", o->depth, o->az, o->sectors, secs);
	fprintf(out.f, "# bound: proven over every binary16 rounding of a unit vector in the region (inf: none; status says why)\n");
	fprintf(out.f, "# found: the largest defect of the scan (every binary16 n.z of the band at the azimuths; at a pole, small (x, y))%s\n",
	        o->arith ? " of the IEEE binary16 kernel, whose every result the profile allows (its flushing is a permission)" : "");
	if (o->arith) {   /* as certify.c's header: the profile and every allowance */
		char d[2048];
		arith_describe(o->arith, d, sizeof d);
		fprintf(out.f, "# arith: %s (%s; %s)\n", o->arith->name, o->arith->title, o->arith->spec);
		fprintf(out.f, "# model: the IEEE model's operations, each widened to the profile's allowance (src/model/arith.c): %s\n", d);
	}
	ch_write_rows(out.f, ks, reg, t, nt, res, o->arith != NULL);
	if (study_out_commit(&out) != 0)
		return 1;
	if (!o->quiet) {
		ch_summary(stdout, ks, nk, t, nt, res);
		printf("wrote %s/certify-half.csv\n", dir);
	}
	return 0;
}

/* The kernels with a half entry and a rounding model (ms[k] NULL: none). */
static int ch_select(const ch_opts *o, study_kernel *ks, const cm_method **ms)
{
	int nk = kernels_select(o->methods, 0, ks, STUDY_MAX_KERNELS), k, sk;
	const int all = !o->methods || strcmp(o->methods, "all") == 0;
	if (nk < 0)
		return -1;
	for (k = 0; k < nk; k++) {
		ms[k] = kernel_runs(&ks[k], PREC_HALF) ? cm_find(ks[k].name) : NULL;
		if (!ms[k] && !all) {
			study_error("--methods: %s has no binary16 kernel with a rounding model", ks[k].name);
			return -1;
		}
	}
	for (sk = 0; sk < NSEED; sk++) {   /* computed once, outside the parallel regions */
		seed_bound sb;
		if (seed_bound_get((seed_kind)sk, &sb) != 0) {
			study_error("the seed bound of %s could not be computed", seed_name((seed_kind)sk));
			return -1;
		}
	}
	return nk;
}

int cert_half_run(const ch_opts *o)
{
	static study_kernel ks[STUDY_MAX_KERNELS];
	static const cm_method *ms[STUDY_MAX_KERNELS];
	static cert_region reg[CH_MAXREG];
	ch_task *t;
	ch_result *res;
	size_t nreg, i;
	int nk = ch_select(o, ks, ms), k, nt = 0, rc;
	double t0;
	if (nk < 0)
		return ONB_EXIT_USAGE;
	nreg = o->band ? regions_band(PREC_HALF, o->sectors, o->band_lo, o->band_hi, reg, CH_MAXREG)
	               : regions_default(PREC_HALF, o->sectors, reg, CH_MAXREG);
	t = malloc((size_t)nk * nreg * sizeof *t + 1);
	res = calloc((size_t)nk * nreg + 1, sizeof *res);
	if (!t || !res) {
		free(t);
		free(res);
		study_error("out of memory");
		return 1;
	}
	for (k = 0; k < nk; k++)
		for (i = 0; ms[k] && i < nreg; i++) {
			t[nt].k = k;
			t[nt++].i = (int)i;
		}
	t0 = study_now();
	ch_run_all(o, ks, ms, reg, t, nt, res);
	rc = ch_write(o, ks, nk, reg, t, nt, res, study_now() - t0);
	free(t);
	free(res);
	return rc;
}
