/*
 * emusweep.c - `onbstudy sweep --arith PROFILE` (emusweep.h).
 *
 * Per method, precision, distribution and input: the emulated defect of
 * the nearest implementation, of R random ones and of the adversary (one
 * greedy pass, as certify --arith's found side), their largest w, and
 * where the input is a rounding of a real unit vector, the proven bound b
 * at it (emu_point_bound): w <= b must hold, and w <= the whole-sphere
 * bound of the method under the profile (the certify --arith CSV's row
 * nz -1..1, phi 0..360).  Every number is a pure function of (profile,
 * seed, distribution, precision, index), so any thread count gives the
 * same bytes; ties for the worst input go to the lowest index.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "sweep/emusweep.h"
#include "certify/emulate.h"
#include "certify/region.h"
#include "common/options.h"
#include "common/output.h"
#include "common/progress.h"

typedef struct {
	uint64_t inputs, checked, unbounded, above, nonfinite, unit, above_whole;
	double nearest, random, adversarial, worst, ratio, uworst;   /* uworst: over unit inputs */
	uint64_t worst_i;
	double worst_n[3];
	int worst_kind, unb_op;
} ecell;

typedef struct {           /* a method's whole-sphere row of the bounds CSV */
	double bound;
	char status[16], unb[24];
	int found;
} whole_row;

static const char *const kind_name[3] = { "nearest", "random", "adversarial" };

static void ecell_init(ecell *e)
{
	memset(e, 0, sizeof *e);
	e->worst = -1.0;
	e->worst_i = UINT64_MAX;
	e->unb_op = -1;
}

static void ecell_merge(ecell *d, const ecell *s)
{
	d->inputs += s->inputs; d->checked += s->checked; d->unbounded += s->unbounded; d->above += s->above;
	d->nonfinite += s->nonfinite; d->unit += s->unit; d->above_whole += s->above_whole;
	d->nearest = fmax(d->nearest, s->nearest);
	d->random = fmax(d->random, s->random);
	d->adversarial = fmax(d->adversarial, s->adversarial);
	d->ratio = fmax(d->ratio, s->ratio);
	d->uworst = fmax(d->uworst, s->uworst);
	if (s->worst > d->worst || (s->worst == d->worst && s->worst_i < d->worst_i)) {
		d->worst = s->worst;
		d->worst_i = s->worst_i;
		memcpy(d->worst_n, s->worst_n, sizeof d->worst_n);
		d->worst_kind = s->worst_kind;
	}
	if (s->unb_op > d->unb_op)   /* the largest: the same for any merge order */
		d->unb_op = s->unb_op;
}

/* The seed of random implementation r at input i of (prec, dist). */
static unsigned long long emu_seed(unsigned long long seed, int prec, int dist, uint64_t i, int r)
{
	unsigned long long z = seed ^ ((unsigned long long)(prec * 16 + dist) << 56) ^ (i * 0x9e3779b97f4a7c15ull) ^
	                       ((unsigned long long)r * 0xbf58476d1ce4e5b9ull);
	z = (z ^ (z >> 31)) * 0x94d049bb133111ebull;
	return z ^ (z >> 29);
}

/* One input: every emulated implementation, then the bounds. */
static void one_input(cm *c, ref_ctx *rc, const sweep_plan *pl, const arith_profile *emu_p, const cm_method *m,
                      int prec, int dist, uint64_t i, const double n[3], double whole, ecell *e)
{
	unsigned char ch[CM_EMU_MAXOP];
	emu_eval r;
	double w[3], worst;
	int k, kind = 0;
	emu_run(c, rc, m, prec, n, emu_p, CM_EMU_NEAREST, 0, NULL, 0, &r);
	w[0] = r.defect;
	w[1] = 0.0;
	for (k = 0; k < pl->emu_random; k++) {
		emu_run(c, rc, m, prec, n, emu_p, CM_EMU_RANDOM, emu_seed(pl->cfg.seed, prec, dist, i, k), NULL, 0, &r);
		w[1] = fmax(w[1], r.defect);
	}
	w[2] = emu_adversarial(c, rc, m, prec, n, emu_p, 1, ch, &r);
	worst = w[0];
	for (k = 1; k < 3; k++)
		if (w[k] > worst)
			worst = w[k], kind = k;
	e->inputs++;
	e->nearest = fmax(e->nearest, w[0]);
	e->random = fmax(e->random, w[1]);
	e->adversarial = fmax(e->adversarial, w[2]);
	if (!(worst < INFINITY))
		e->nonfinite++;
	if (worst > e->worst || (worst == e->worst && i < e->worst_i)) {
		e->worst = worst;
		e->worst_i = i;
		memcpy(e->worst_n, n, sizeof e->worst_n);
		e->worst_kind = kind;
	}
	if (prec == PREC_HALF) {   /* no binary16 domain test or proof model: measured, not checked */
		if (dist == DIST_NONUNIT)
			return;
		e->unit++;
		e->uworst = fmax(e->uworst, worst);
		e->unbounded++;
		e->unb_op = AR_NOPS + 1;
		return;
	}
	if (!cert_in_domain(n, prec, -1.0))
		return;
	e->unit++;
	e->uworst = fmax(e->uworst, worst);
	e->above_whole += !(worst <= whole);
	{
		int unb;
		const double b = emu_point_bound(m, pl->arith, prec, n, &unb);
		if (!(b < INFINITY)) {
			e->unbounded++;
			if (unb > e->unb_op)
				e->unb_op = unb;
			return;
		}
		e->checked++;
		e->above += !(worst <= b);
		if (b > 0.0)
			e->ratio = fmax(e->ratio, worst / b);
		else if (worst > 0.0)
			e->ratio = INFINITY;
	}
}

/* Every input of (prec, dist) for kernel m into *out, on pl->threads threads. */
static int run_cell(const sweep_plan *pl, const arith_profile *emu_p, const cm_method *m, int prec, int dist,
                    double whole, ecell *out)
{
	dist_spec ds;
	int err = 0;
	plan_dist_spec(pl, prec, dist, &ds);
	if (dist_prepare(&ds) != 0)
		return -1;
	ecell_init(out);
#pragma omp parallel num_threads(pl->threads)
	{
		cm *c = cm_new(CM_EXEC);
		ref_ctx *rc = ref_new(127);
		ecell e;
		long long i;
		ecell_init(&e);
		if (!c || !rc) {
#pragma omp atomic write
			err = 1;
		}
#pragma omp for schedule(dynamic, 8)
		for (i = 0; i < (long long)ds.count; i++) {
			double n[3], loc[3], aux;
			if (!c || !rc)
				continue;
			dist_sample(&ds, (uint64_t)i, n, loc, &aux);
			one_input(c, rc, pl, emu_p, m, prec, dist, (uint64_t)i, n, whole, &e);
		}
#pragma omp critical
		ecell_merge(out, &e);
		cm_free(c);
		if (rc)
			ref_free(rc);
	}
	dist_free(&ds);
	if (err)
		study_error("out of memory");
	return err ? -1 : 0;
}

/* The whole-sphere row of method name in precision prec of the bounds CSV;
   w->found 0 when it has none. */
static void whole_of(const char *csv, const char *name, int prec, whole_row *w)
{
	FILE *f = csv ? fopen(csv, "r") : NULL;
	char line[2048], key[128];
	memset(w, 0, sizeof *w);
	w->bound = INFINITY;
	if (!f)
		return;
	snprintf(key, sizeof key, "%s,%s,-1,1,0,360,", name, prec_name(prec));
	while (!w->found && fgets(line, sizeof line, f)) {
		char *p, *fld[17];
		int k = 0;
		if (strncmp(line, key, strlen(key)) != 0)
			continue;
		line[strcspn(line, "\r\n")] = '\0';
		for (p = line; k < 17; k++) {
			fld[k] = p;
			p = strchr(p, ',');
			if (!p)
				break;
			*p++ = '\0';
		}
		if (k < 16)
			continue;
		w->found = 1;
		w->bound = strcmp(fld[6], "inf") == 0 ? INFINITY : strtod(fld[6], NULL);
		snprintf(w->status, sizeof w->status, "%s", fld[11]);
		snprintf(w->unb, sizeof w->unb, "%s", fld[16]);
	}
	fclose(f);
}

/* The bounds CSV's profile ("# arith: NAME", ieee without one); 0 when it
   is p's, else -1 after a message. */
static int bounds_profile_ok(const char *csv, const arith_profile *p)
{
	FILE *f = fopen(csv, "r");
	char line[4096], name[64] = "ieee";
	if (!f) {
		study_error("--bounds: cannot open %s", csv);
		return -1;
	}
	while (fgets(line, sizeof line, f) && line[0] == '#')
		if (strncmp(line, "# arith: ", 9) == 0) {
			snprintf(name, sizeof name, "%.*s", (int)strcspn(line + 9, " \n"), line + 9);
			break;
		}
	fclose(f);
	if (strcmp(name, p->name) != 0) {
		study_error("--bounds: %s holds bounds under %s, not %s", csv, name, p->name);
		return -1;
	}
	return 0;
}

static void csv_header(FILE *f, const sweep_plan *pl, const char *bounds)
{
	char desc[4096];
	study_provenance(f, "sweep --arith", (unsigned long long)pl->cfg.seed, pl->threads);
	arith_describe(pl->arith, desc, sizeof desc);
	fprintf(f, "# arith: %s (%s; %s)\n# model: %s\n", pl->arith->name, pl->arith->title, pl->arith->spec, desc);
	fprintf(f, "# emulation: per input the nearest implementation, %d random ones and the greedy adversary (1 pass)"
	           " (src/certify/emulate.c)%s; defects measured in MPFR at 127 bits\n", pl->emu_random,
	        pl->widen != 1.0 ? "; MUTATED: every ulp or relative allowance of the emulation widened (--widen), a"
	                           " nonconforming implementation the bounds must not cover" : "");
	if (pl->widen != 1.0)
		fprintf(f, "# widen: %g\n", pl->widen);
	fprintf(f, "# point bound: emu_point_bound, certify --arith's mean value form over a box of ~8u around each input"
	           " that is a rounding of a real unit vector (checked: the worst emulated defect <= it)\n");
	fprintf(f, "# whole-sphere bound: %s\n", bounds ? bounds : "none given (no --bounds and no results/gpu/PROFILE/certify.csv)");
	fprintf(f, "method,precision,distribution,inputs,unit_inputs,checked,unbounded,nonfinite,nearest_max,random_max,"
	           "adversarial_max,max_defect,max_defect_unit,worst_by,worst_nx,worst_ny,worst_nz,max_defect_over_point_bound,above_point_bound,"
	           "whole_bound,above_whole_bound,unbounded_by\n");
}

static void csv_row(FILE *f, const char *name, int prec, int dist, const ecell *e, const whole_row *w)
{
	fprintf(f, "%s,%s,%s,%llu,%llu,%llu,%llu,%llu,%.17g,%.17g,%.17g,%.17g,%.17g,%s,%a,%a,%a,%.6g,%llu,", name, prec_name(prec),
	        dist_name(dist), (unsigned long long)e->inputs, (unsigned long long)e->unit, (unsigned long long)e->checked,
	        (unsigned long long)e->unbounded, (unsigned long long)e->nonfinite, e->nearest, e->random, e->adversarial,
	        e->worst, e->uworst, kind_name[e->worst_kind], e->worst_n[0], e->worst_n[1], e->worst_n[2], e->ratio,
	        (unsigned long long)e->above);
	if (w->found && w->bound < INFINITY)
		fprintf(f, "%.17g,%llu,", w->bound, (unsigned long long)e->above_whole);
	else
		fprintf(f, "%s,,", w->found ? "inf" : "");
	fprintf(f, "%s\n", e->unb_op >= 0 ? (e->unb_op == AR_NOPS ? "direction-rule" : e->unb_op == AR_NOPS + 1 ? "no-half-model"
	                    : arith_op_name(e->unb_op)) : "");
}

/* stdout: one line per method and precision, over its distributions. */
static void print_line(const char *name, int prec, const ecell *e, const whole_row *w)
{
	const double u = prec_fmt(prec)->u;
	char wb[64];
	if (!w->found)
		snprintf(wb, sizeof wb, "-");
	else if (!(w->bound < INFINITY))
		snprintf(wb, sizeof wb, "%s%s%s", w->status, w->unb[0] ? " " : "", w->unb);
	else
		snprintf(wb, sizeof wb, "%.3g", w->bound / u);
	printf("%-24s %-6s %9llu %12.4g %12s %7llu/%-7llu %9.3g %s\n", name, prec_name(prec),
	       (unsigned long long)e->unit, e->uworst / u, wb, (unsigned long long)e->checked, (unsigned long long)e->unit, e->ratio,
	       e->above || e->above_whole ? "EXCEEDS" : e->checked ? "ok"
	       : prec == PREC_HALF ? "measured (no binary16 proof model)" : "-");
}

/* The bounds file: --bounds, else results/gpu/PROFILE/certify.csv when it
   exists; NULL when none. */
static const char *bounds_file(const sweep_plan *pl, char *buf, size_t n)
{
	FILE *f;
	if (pl->bounds)
		return pl->bounds;
	snprintf(buf, n, "results/gpu/%s/certify.csv", pl->arith->name);
	if (!(f = fopen(buf, "r")))
		return NULL;
	fclose(f);
	return buf;
}

/* One kernel in one precision: every distribution into the CSV. */
static int run_kernel(const sweep_plan *pl, const arith_profile *emu_p, const cm_method *m, const char *name, int prec,
                      const char *bounds, FILE *f, ecell *all, whole_row *w)
{
	int d;
	whole_of(bounds, name, prec, w);
	ecell_init(all);
	for (d = 0; d < NDIST; d++) {
		ecell e;
		if (!pl->cfg.dist_on[d])
			continue;
		if (run_cell(pl, emu_p, m, prec, d, w->found ? w->bound : INFINITY, &e) != 0)
			return -1;
		if (!w->found)
			e.above_whole = 0;
		csv_row(f, name, prec, d, &e, w);
		ecell_merge(all, &e);
	}
	return 0;
}

int emusweep_run(const sweep_plan *pl)
{
	char bbuf[4200];
	const char *bounds = bounds_file(pl, bbuf, sizeof bbuf);
	arith_profile emu_p = arith_widen(pl->arith, pl->widen);
	study_out o;
	int k, prec, bad = 0;
	double t0 = study_now();
	if (bounds && bounds_profile_ok(bounds, pl->arith) != 0)
		return ONB_EXIT_USAGE;
	if (study_mkdir_p(pl->out) != 0 || study_out_open(&o, pl->out, "arith-sweep.csv") != 0)
		return 1;
	csv_header(o.f, pl, bounds);
	printf("sweep --arith %s%s: per method, the largest emulated defect on unit inputs and its whole-sphere bound,\n"
	       "in u (2^-24 float, 2^-53 double, 2^-11 half); w/b: the worst defect over the proven bound at the same input\n", pl->arith->name,
	       pl->widen != 1.0 ? " (MUTATED: allowances widened)" : "");
	printf("%-24s %-6s %9s %12s %12s %15s %9s %s\n", "method", "prec", "unit in", "worst defect", "whole bound",
	       "checked/unit", "max w/b", "");
	for (prec = 0; prec < PREC_COUNT; prec++)
		for (k = 0; k < pl->cfg.nk; k++) {
			const study_kernel *sk = &pl->kernels[k];
			const cm_method *m = sk->fma ? NULL : cm_find(sk->name);
			ecell all;
			whole_row w;
			if (!pl->cfg.prec_on[prec] || !kernel_runs(sk, prec))
				continue;
			if (!m || m->direction) {
				printf("%-24s %-6s not emulated: %s\n", sk->name, prec_name(prec),
				       m ? "its direction bound is proven for round to nearest only" : "no rounding model");
				continue;
			}
			if (run_kernel(pl, &emu_p, m, sk->name, prec, bounds, o.f, &all, &w) != 0) {
				study_out_abort(&o);
				return 1;
			}
			print_line(sk->name, prec, &all, &w);
			bad += all.above > 0 || all.above_whole > 0;
		}
	fprintf(o.f, "# time: %.1f s wall\n", study_now() - t0);
	if (study_out_commit(&o) != 0)
		return 1;
	fprintf(stderr, "onbstudy: wrote %s/arith-sweep.csv (%.1f s)%s\n", pl->out, study_now() - t0,
	        bad ? "; an emulated defect EXCEEDS its proven bound" : "");
	return bad ? 1 : 0;
}
