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
#include <inttypes.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "certify_half.h"
#include "certify.h"
#include "checkpoint.h"
#include "keys.h"
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

/* ch_bound, and in *cause why it is +inf (bound_box_cause of a box
   without a bound that no split replaced). */
static double ch_bound_c(bound_ctx *b, const cm_method *m, const cert_region *r, double target, int depth, int *cause)
{
	mvf_box box;
	cert_region h[2];
	double v, w = 0.0;
	int i, vc, wc = -1;
	if (half_band_empty(r))
		return 0.0;   /* no input */
	region_box(r, PREC_HALF, -1.0, &box);
	v = bound_box(b, m, &box);
	vc = bound_box_cause(b);
	if (v < 0.0)
		v = 0.0;   /* no path: no input of the region lies in the box */
	if (!(v < INFINITY))
		*cause = vc;
	if (depth <= 0 || v <= target)
		return v;
	h[0] = h[1] = *r;
	if (r->nz_hi - r->nz_lo >= 1e-4 && (depth % 2 == 0 || r->phi_hi - r->phi_lo < 1e-3))
		h[0].nz_hi = h[1].nz_lo = 0.5 * (r->nz_lo + r->nz_hi);
	else
		h[0].phi_hi = h[1].phi_lo = 0.5 * (r->phi_lo + r->phi_hi);
	for (i = 0; i < 2 && w < v; i++) {
		int c = -1;
		w = fmax(w, ch_bound_c(b, m, &h[i], target, depth - 1, &c));
		if (!(w < INFINITY) && wc < 0)
			wc = c;
	}
	if (!(w < INFINITY) && wc >= 0)
		*cause = wc;
	return fmin(v, w);
}

double ch_bound(bound_ctx *b, const cm_method *m, const cert_region *r, double target, int depth)
{
	int cause = -1;
	return ch_bound_c(b, m, r, target, depth, &cause);
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
	int cause = -1;
	out->bound = ch_bound_c(b, m, r, fmax(2.0 * out->found, u), depth, &cause);
	if (out->nonfinite)
		out->status = CH_NONFINITE;
	else if (!(out->bound < INFINITY)) {
		out->status = bound_overflow_seen(b) ? CH_OVERFLOW : CH_UNBOUNDED;
		out->unb_op = bound_unbounded_op(b) >= 0 ? bound_unbounded_op(b) : cause;
	} else
		out->status = CH_PROVEN;
	if (out->status == CH_PROVEN && out->found > out->bound) {
		out->status = CH_UNBOUNDED;   /* a bound under a defect the scan measured is no proof: the model's
		                                 paths miss the kernel's (physx in half: every box "no path") */
		out->unb_op = CH_BELOW_SCAN;
	}
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

/* A region's ch_result travels as a cert_result (bound, found, found_n,
   status: CH_*, unb_op; scanned in boxes, nonfinite in probes; the rest zero), so
   that certify's checkpoint (checkpoint.c) and onbstudy-mpi's passes
   (cert_distribute) carry it unchanged. */
static void ch_to_cert(const ch_result *h, cert_result *r)
{
	memset(r, 0, sizeof *r);
	r->bound = h->bound;
	r->found = h->found;
	memcpy(r->found_n, h->worst, sizeof r->found_n);
	r->status = h->status;
	r->boxes = h->scanned;
	r->probes = h->nonfinite;
	r->unb_op = h->unb_op;
}
static void ch_from_cert(const cert_result *r, ch_result *h)
{
	memset(h, 0, sizeof *h);
	h->bound = r->bound;
	h->found = r->found;
	memcpy(h->worst, r->found_n, sizeof h->worst);
	h->status = r->status;
	h->scanned = r->boxes;
	h->nonfinite = r->probes;
	h->unb_op = r->unb_op;
}

/* The run's state: its tasks, their results, the checkpoint (--resume). */
typedef struct {
	const ch_opts *o;
	const study_kernel *ks;
	const cm_method *const *ms;
	const cert_region *reg;
	const ch_task *t;
	cert_result *res;      /* per task */
	ck_state ck;           /* flag[i] & CK_RUN: task i is done */
	const char *dir;       /* where the checkpoint goes (rank 0, --resume); NULL: none */
	double last;
	int failed, commits, kill_at;
} ch_run;

/* Task i's result r: into the results and the checkpoint, written when
   due; ONB_CERT_KILL=run:N (tests/certify_resume.sh) kills the process
   after its N-th commit. */
static void ch_commit(ch_run *s, int i, const cert_result *r)
{
#pragma omp critical(ch_commit)
	if (!s->failed) {
		s->res[i] = *r;
		s->ck.base[i] = *r;
		s->ck.flag[i] |= CK_RUN;
		if (s->dir && study_now() - s->last >= s->o->every) {
			s->failed = ck_write(s->dir, &s->ck) != 0;
			s->last = study_now();
		}
		if (s->kill_at && ++s->commits == s->kill_at)
			raise(SIGKILL);
	}
}

static void ch_one(cert_ctx *x, int i, void *arg)
{
	ch_run *s = arg;
	ch_result h;
	cert_result r;
	bound_ctx *b;
	(void)x;
	if ((s->ck.flag[i] & CK_RUN) || s->failed)
		return;
	memset(&h, 0, sizeof h);
	h.unb_op = -1;
	if ((b = bound_new()) != NULL) {
		bound_set_arith(b, s->o->arith);   /* NULL: ieee; resets the unbounded operation */
		ch_region(b, &s->ks[s->t[i].k], s->ms[s->t[i].k], &s->reg[s->t[i].i], s->o->depth, s->o->az, &h);
	} else {
		h.status = CH_UNBOUNDED;
		h.bound = INFINITY;
	}
	bound_free(b);
	ch_to_cert(&h, &r);
	ch_commit(s, i, &r);
}

static void ch_commit_remote(void *arg, int i, const cert_result *r)
{
	ch_commit(arg, i, r);
}

/* Every task not done yet, here (OpenMP) or over onbstudy-mpi's ranks.
   0, or -1 (a checkpoint could not be written, a rank failed). */
static int ch_run_all(ch_run *s, int nt)
{
	int j;
	if (cert_distribute) {
		cert_pass p;
		memset(&p, 0, sizeof p);
		p.n = nt;
		p.flag = CK_RUN;
		p.fn = ch_one;
		p.arg = s;
		p.commit = ch_commit_remote;
		p.res = s->res;
		p.flags = s->ck.flag;
		p.nres = nt;
		p.failed = &s->failed;
		return cert_distribute->run(&p) != 0 || s->failed ? -1 : 0;
	}
#pragma omp parallel for schedule(dynamic, 1)
	for (j = 0; j < nt; j++)
		ch_one(NULL, j, s);
	return s->failed ? -1 : 0;
}

/* --arith: the operation an unbounded row owes it to (certify.c's unbounded_by) */
static const char *ch_unb(const ch_result *x)
{
	if (x->status != CH_UNBOUNDED)
		return "";
	return x->unb_op == CH_BELOW_SCAN ? "below-scan" : arith_cause_name(x->unb_op);
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
	if (cert_distribute && cert_distribute->note)
		fprintf(out.f, "# %s\n", cert_distribute->note);
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

/* Does a selected method's model take a seed's bound (mvf_seed)?  Those
   whose normalization is a seed (model_kit.h's mk_norm) and embree's rsqrt
   (embree.c).  The others never ask for one, and a run of them skips the
   scan of every float that SEED_RSQRTSS's bound costs (seeds.c: ~7 s of
   CPU); a model that asks anyway still gets the same bound, computed in
   its parallel region on one thread (seed_bound_get is pthread_once). */
static int ch_uses_seeds(const study_kernel *ks, const cm_method **ms, int nk)
{
	int k;
	for (k = 0; k < nk; k++)
		if (ms[k] && ks[k].m && (ks[k].m->norm == ONB__NORM_INVSQRT || ks[k].m->norm == ONB__NORM_RSQRT ||
		                         ks[k].m->norm == ONB__NORM_RSQRT_NR ||
		                         (ks[k].fam && strcmp(ks[k].fam->name, "embree") == 0)))
			return 1;
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
	for (sk = 0; sk < NSEED && ch_uses_seeds(ks, ms, nk); sk++) {   /* computed once, outside the parallel regions */
		seed_bound sb;
		if (seed_bound_get((seed_kind)sk, &sb) != 0) {
			study_error("the seed bound of %s could not be computed", seed_name((seed_kind)sk));
			return -1;
		}
	}
	return nk;
}

/* The settings line of the checkpoint and the keys file: checkpoint.c
   tells a half run's by its first word, precision=half. */
static void ch_settings(const ch_opts *o, char *buf, size_t cap)
{
	char d[4096];
	arith_describe(o->arith ? o->arith : arith_ieee(), d, sizeof d);   /* the profile and every allowance */
	snprintf(buf, cap, "precision=half sectors=%d depth=%d azimuths=%d band=%s%a,%a arith=%s:%016" PRIx64, o->sectors,
	         o->depth, o->az, o->band ? "" : "none:", o->band ? o->band_lo : 0.0, o->band ? o->band_hi : 0.0,
	         (o->arith ? o->arith : arith_ieee())->name, cert_hash_str(CERT_FNV0, d));
}

/* The groups (one per method, format half) with their keys (the settings,
   the engine, the regions, cert_half_key), and the state's arrays.  0 or -1. */
static int ch_state(ch_run *s, int nk, int nt, size_t nreg, ck_group *g, char *settings, size_t cap)
{
	int k, ng = 0;
	ch_settings(s->o, settings, cap);
	for (k = 0; k < nk; k++)
		if (s->ms[k]) {
			uint64_t h = cert_hash_str(CERT_FNV0, settings), mk = cert_half_key(&s->ks[k], s->ms[k]);
			h = cert_hash_str(h, cert_engine());
			h = cert_hash_bytes(h, &mk, sizeof mk);
			h = cert_hash_bytes(h, s->reg, nreg * sizeof *s->reg);
			snprintf(g[ng].name, sizeof g[ng].name, "%s", s->ks[k].name);
			g[ng].prec = PREC_HALF;
			g[ng++].key = h;
		}
	s->ck.settings = settings;
	s->ck.engine = cert_engine();
	s->ck.ng = ng;
	s->ck.nt = nt;
	s->ck.g = g;
	s->ck.flag = calloc((size_t)nt + 1, 1);
	s->ck.base = calloc((size_t)nt + 1, sizeof *s->ck.base);
	s->ck.ref = calloc((size_t)nt + 1, sizeof *s->ck.ref);
	return s->ck.flag && s->ck.base && s->ck.ref ? 0 : -1;
}

/* --resume DIR (rank 0): 0 to run (the checkpoint's results loaded, when
   there is one), 1 when the work is done, -1 refused (a message said why). */
static int ch_resume(ch_run *s)
{
	const char *dir = s->o->resume;
	char path[4096];
	int i, n = 0, r, *cur;
	FILE *f;
	if (!dir)
		return 0;
	if ((r = ck_read(dir, &s->ck)) < 0)
		return -1;
	if (r == 0) {
		for (i = 0; i < s->ck.nt; i++)
			if (s->ck.flag[i]) {
				s->res[i] = s->ck.base[i];
				n++;
			}
		fprintf(stderr, "certify: --resume %s: continuing from its checkpoint (%d of %d regions run)\n", dir, n,
		        s->ck.nt);
		return 0;
	}
	if (!(cur = calloc((size_t)s->ck.ng + 1, sizeof *cur)))
		return -1;
	r = keys_compare(dir, &s->ck, cur, 0);
	for (i = 0; i < s->ck.ng && r == 0; i++)
		if (!cur[i]) {
			study_error("--resume %s: its finished run is of another revision of %s half's model or kernel", dir,
			            s->ck.g[i].name);
			r = 1;
		}
	free(cur);
	if (r > 0)
		return -1;
	if (r == 0 && snprintf(path, sizeof path, "%s/certify-half.csv", dir) < (int)sizeof path && (f = fopen(path, "r"))) {
		fclose(f);
		fprintf(stderr, "certify: --resume %s: the work is done (its certify-half.csv is of this command line and "
		        "every key is current); nothing to do\n", dir);
		return 1;
	}
	fprintf(stderr, "certify: --resume %s: no checkpoint there yet: starting from the beginning\n", dir);
	return 0;
}

/* ONB_CERT_KILL=run:N on rank ONB_CERT_KILL_RANK (default 0): as certify.c's. */
static int ch_kill_at(void)
{
	const char *e = getenv("ONB_CERT_KILL"), *kr = getenv("ONB_CERT_KILL_RANK");
	if ((cert_distribute ? cert_distribute->rank : 0) != (kr ? atoi(kr) : 0))
		return 0;
	return e && strncmp(e, "run:", 4) == 0 ? atoi(e + 4) : 0;
}

/* After the run (rank 0): certify-half.csv, then with --resume the keys
   file (so that the same command line is "done") and no checkpoint. */
static int ch_finish(ch_run *s, int nk, int nt, double secs)
{
	ch_result *hr = calloc((size_t)nt + 1, sizeof *hr);
	char path[4096];
	int i, rc;
	if (!hr) {
		study_error("out of memory");
		return 1;
	}
	for (i = 0; i < nt; i++)
		ch_from_cert(&s->res[i], &hr[i]);
	rc = ch_write(s->o, s->ks, nk, s->reg, s->t, nt, hr, secs);
	free(hr);
	if (rc == 0 && s->o->resume) {
		if (keys_write(s->o->resume, &s->ck, study_cmdline))
			return 1;
		if (snprintf(path, sizeof path, "%s/%s", s->o->resume, CK_NAME) < (int)sizeof path)
			remove(path);
	}
	return rc;
}

int cert_half_run(const ch_opts *o)
{
	static study_kernel ks[STUDY_MAX_KERNELS];
	static const cm_method *ms[STUDY_MAX_KERNELS];
	static cert_region reg[CH_MAXREG];
	static char settings[512];
	const int writes = !cert_distribute || cert_distribute->rank == 0;
	ch_task *t;
	ch_run s;
	ck_group *g;
	size_t nreg, i;
	int nk = ch_select(o, ks, ms), k, nt = 0, rc = 1, r;
	double t0;
	if (nk < 0)
		return ONB_EXIT_USAGE;
	nreg = o->band ? regions_band(PREC_HALF, o->sectors, o->band_lo, o->band_hi, reg, CH_MAXREG)
	               : regions_default(PREC_HALF, o->sectors, reg, CH_MAXREG);
	memset(&s, 0, sizeof s);
	t = malloc((size_t)nk * nreg * sizeof *t + 1);
	s.res = calloc((size_t)nk * nreg + 1, sizeof *s.res);
	g = calloc((size_t)nk + 1, sizeof *g);
	for (k = 0; t && k < nk; k++)
		for (i = 0; ms[k] && i < nreg; i++) {
			t[nt].k = k;
			t[nt++].i = (int)i;
		}
	s.o = o; s.ks = ks; s.ms = ms; s.reg = reg; s.t = t;
	if (!t || !s.res || !g || ch_state(&s, nk, nt, nreg, g, settings, sizeof settings) != 0) {
		study_error("out of memory");
		goto done;
	}
	r = writes ? ch_resume(&s) : 0;
	if (r == 0 && writes && o->resume && study_mkdir_p(o->resume) != 0)
		r = -1;
	if (cert_distribute) {   /* rank 0's outcome and state to every rank */
		cert_distribute->share(&r, sizeof r);
		cert_distribute->share(s.res, (size_t)nt * sizeof *s.res);
		cert_distribute->share(s.ck.flag, (size_t)nt);
	}
	if (r != 0) {
		rc = r < 0 ? ONB_EXIT_USAGE : 0;
		goto done;
	}
	s.dir = writes ? o->resume : NULL;
	s.last = study_now();
	s.kill_at = ch_kill_at();
	t0 = study_now();
	if (ch_run_all(&s, nt) != 0)
		study_error("certify --precision half: the run stopped (a checkpoint could not be written, or a rank failed)");
	else
		rc = writes ? ch_finish(&s, nk, nt, study_now() - t0) : 0;
done:
	free(t);
	free(s.res);
	free(g);
	free(s.ck.flag);
	free(s.ck.base);
	free(s.ck.ref);
	return rc;
}
