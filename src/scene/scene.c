/*
 * scene.c - `onbstudy scene FILE`: every method on a scene's own normals,
 * and a recommendation for that scene that does not change between
 * identical runs.
 *
 * The normals come from meshio.c (OBJ, PLY, glTF 2.0; the format from the
 * content), rounded to the working precision (--precision, default float;
 * half: binary16, each component the file's float rounded to nearest, as a
 * vertex buffer of floats read by a mediump shader; --world's transforms
 * are then done in float before that rounding).
 * Degenerate normals (zero or non-finite there) are counted and located,
 * then left out: no basis is meaningful for them, and a renderer has to
 * catch them before building one (onb_basis_checked does).  Every other
 * normal goes to every method twice:
 *   as-read       exactly as the file holds them, or as computed from the
 *                 faces (non-unit ones included); with --world, after the
 *                 node transforms (see meshio.h), before renormalizing;
 *   renormalized  n / sqrt(n.n) in the working precision, as a renderer's
 *                 normalize() would.
 * For each method: the batch kernel (m->batch / m->batchf) and the scalar
 * out-of-line function (m->basis / m->basisf) on the same input.  Metrics
 * come from the batch outputs and are evaluated in long double against
 * n/|n| of the input the method received:
 *   defect = max(||b1|-1|, ||b2|-1|, |b1.n|, |b2.n|, |b1.b2|)
 * (max and RMS over the normals), the count of non-finite outputs, the
 * count of bases whose det(b1, b2, n) has the other sign than the
 * registry's handedness, and the count of normals where scalar and batch
 * outputs differ in any bit.  The same metrics on 4096 uniform directions
 * (seed 1) give each method's general accuracy, to tell a scene that
 * flatters a method from one that does not.
 *
 * Recommendation.  Acceptable: no non-finite output, no wrong-handed basis,
 * max defect <= E (default 1e-6 in float, about 8 float ulps of 1; 1e-14 in
 * double, about 45 double ulps; 2^-7 in half, 8 binary16 ulps of 1 = 16 u
 * with u = 2^-11, in which the half report prints its defects).  Speed is never timed on the scene: it is
 * the batch throughput of speed.c (a per-machine cache measured by
 * --refresh-speed, else the committed reference run), each figure with an
 * interval.  Among acceptable methods with a speed figure, let F be the
 * fastest by median; every acceptable method whose interval reaches F's
 * (hi >= F's lo) is tied with F.  Of the tied ones the most accurate on the
 * scene wins (smaller max defect, then smaller RMS defect), then the
 * earlier in the registry's order (`onbstudy list`).  The runner-up is the
 * next by the same rule.  Same file, options and speed source: same answer.
 *
 * --up picks the axis that plays n.z, by a cyclic permutation of the
 * coordinates (a proper rotation, det +1):
 *   z: (x, y, z) -> (x, y, z)     y: (x, y, z) -> (z, x, y)     x: (x, y, z) -> (y, z, x)
 * The recommendation is also computed for the other convention (z when
 * --up is y or x, y when it is z), with the errors measured again.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "scene/scene.h"
#include "scene/scene_run.h"
#include "common/options.h"
#include "common/output.h"
#include "mesh/meshio.h"
#include "scene/speed.h"
#include "certify/scene_cert.h"

/* ------------------------------------------------------------------ */
/* options                                                             */
/* ------------------------------------------------------------------ */

typedef struct {
	const char *file, *outdir, *speed_file;
	double tol;
	int prec, renorm_head, world, refresh, tol_given, certify;
	long repeats;
	char up, other;
} scene_opts;

static void usage(FILE *f)
{
	fprintf(f,
	"usage: onbstudy scene FILE [options]\n"
	"       onbstudy scene --refresh-speed [--precision P] [--repeats N]\n"
	"  Reads the normals of an OBJ, PLY or glTF 2.0 (.gltf, .glb) file (stored, or\n"
	"  area-weighted from the faces; the format is told by the content), runs every\n"
	"  method on them as read and renormalized, and recommends one.\n"
	"  --tolerance E      max orthonormality defect accepted (default 1e-6 float, 1e-14 double,\n"
	"                     2^-7 = 0.0078125 half)\n"
	"  --precision P      float (default), double or half (binary16: each component the file's\n"
	"                     float rounded to nearest binary16, every operation of the kernels and\n"
	"                     of the renormalization rounded to binary16; defects printed in\n"
	"                     u = 2^-11; --certify takes the committed proof results/half/certify)\n"
	"  --up z|y|x         the axis that plays n.z (y: (x,y,z)->(z,x,y), x: (x,y,z)->(y,z,x))\n"
	"  --renormalize      make the renormalized row the headline (default: as read)\n"
	"  --world            glTF: transform each normal by its node's inverse transpose world\n"
	"                     matrix (in the working precision); object space is reported too\n"
	"  --speed BENCH_CSV  take speeds from this bench.csv (of 'onbstudy bench')\n"
	"  --refresh-speed    measure the batch throughput of every method on this machine now\n"
	"                     and cache it (~/.cache/onbstudy or $XDG_CACHE_HOME/onbstudy)\n"
	"  --repeats N        repetitions of --refresh-speed (1..64, default 15)\n"
	"  --out DIR          write DIR/scene.csv (default results/run-DATE)\n"
	"  --certify          also prove each method's bound over every normal a renderer can\n"
	"                     interpolate on the scene's triangles (onbstudy certify's model)\n"
	"  Speed is never timed on the scene: it comes from --speed, else the cache, else the\n"
	"  committed reference run (results/reference/bench.csv).  Methods whose speed\n"
	"  intervals overlap the fastest one's are tied; the most accurate on the scene wins,\n"
	"  then the registry's order.\n");
}

static int parse_opts(int argc, char **argv, scene_opts *o)
{
	static const struct option lo[] = {
		{ "tolerance", required_argument, NULL, 't' }, { "precision", required_argument, NULL, 'p' },
		{ "up", required_argument, NULL, 'u' }, { "renormalize", no_argument, NULL, 'r' },
		{ "repeats", required_argument, NULL, 'n' }, { "out", required_argument, NULL, 'o' },
		{ "world", no_argument, NULL, 'w' }, { "speed", required_argument, NULL, 's' },
		{ "refresh-speed", no_argument, NULL, 'R' }, { "certify", no_argument, NULL, 'C' },
		CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
	};
	static const char *const precs[] = { "float", "double", "half" }, *const ups[] = { "z", "y", "x" };
	cli_args c;
	char **rest;
	int v, nrest, rc = -1;
	if (cli_begin(&c, "scene", argc, argv) != 0)
		return -1;
	while ((v = cli_next(&c, lo)) != -1) {
		switch (v) {
		case CLI_HELP: usage(stdout); rc = 1; goto out;
		case CLI_ERROR: goto out;
		case 'r': o->renorm_head = 1; break;
		case 'w': o->world = 1; break;
		case 'R': o->refresh = 1; break;
		case 'C': o->certify = 1; break;
		case 'o': o->outdir = c.arg; break;
		case 's': o->speed_file = c.arg; break;
		case 'n':
			if (parse_int("--repeats", c.arg, 1, 64, &o->repeats) != 0)
				goto out;
			break;
		case 't':
			if (parse_double("--tolerance", c.arg, &o->tol) != 0)
				goto out;
			if (!(o->tol > 0)) {
				study_error("scene: --tolerance must be a positive finite number, got '%s'", c.arg);
				goto out;
			}
			o->tol_given = 1;
			break;
		case 'p':
			if ((v = cli_choice("--precision", c.arg, precs, 3)) < 0)
				goto out;
			if (v == PREC_HALF && !ONB_HAVE_HALF) {
				study_error("scene: --precision half: this build has no binary16 kernels: its compiler lacks "
				            "_Float16 (GCC >= 12, or clang >= 15, on x86-64 or arm64); rebuild with one (make CC=gcc-12)");
				goto out;
			}
			o->prec = v;   /* precs[] in PREC_ order */
			break;
		case 'u':
			if ((v = cli_choice("--up", c.arg, ups, 3)) < 0)
				goto out;
			o->up = ups[v][0];
			break;
		}
	}
	rest = cli_rest(&c, &nrest);
	if (nrest > 1) {
		study_error("scene: one FILE only (got '%s' and '%s')", rest[0], rest[1]);
		goto out;
	}
	o->file = nrest ? rest[0] : NULL;
	if (!o->file && !o->refresh) {
		study_error("scene: no FILE given (try 'onbstudy scene --help')");
		goto out;
	}
	if (o->refresh && o->speed_file) {
		study_error("scene: --refresh-speed measures this machine; --speed names a file instead: give one of them");
		goto out;
	}
	rc = 0;
out:
	cli_end(&c);
	return rc;
}

/* ------------------------------------------------------------------ */
/* evaluation and ranking                                              */
/* ------------------------------------------------------------------ */

typedef struct {
	scene_res *r[2][2];         /* [0: chosen up, 1: the other][variant] */
	unsigned char *tied[2][2];  /* tied with the fastest acceptable method */
	int best[2][2], second[2][2], fastest[2][2];
	size_t used[2], dropped[2];
} scene_eval;

static void eval_free(scene_eval *e)
{
	int a, v;
	for (a = 0; a < 2; a++)
		for (v = 0; v < 2; v++) {
			free(e->r[a][v]);
			free(e->tied[a][v]);
		}
	memset(e, 0, sizeof *e);
}

/* 1 when a (method ia) is more accurate on the scene than b (method ib),
   the registry's order deciding between equals. */
static int acc_before(const scene_res *a, size_t ia, const scene_res *b, size_t ib)
{
	if (a->max_defect != b->max_defect)
		return a->max_defect < b->max_defect;
	if (a->rms_defect != b->rms_defect)
		return a->rms_defect < b->rms_defect;
	return ia < ib;
}

/* The rule of the file comment. sp[i]: method i's speed, or NULL. */
static void rank(const scene_res *r, size_t nm, const speed_row *const *sp, unsigned char *tied,
                 int *best, int *second, int *fastest)
{
	size_t i;
	int f = -1, b = -1, s = -1;
	for (i = 0; i < nm; i++)
		if (r[i].ok && sp[i] && (f < 0 || sp[i]->med > sp[f]->med))
			f = (int)i;
	for (i = 0; i < nm; i++)
		tied[i] = f >= 0 && r[i].ok && sp[i] && sp[i]->hi >= sp[f]->lo;
	for (i = 0; i < nm; i++)
		if (tied[i] && (b < 0 || acc_before(&r[i], i, &r[b], (size_t)b)))
			b = (int)i;
	for (i = 0; i < nm; i++)
		if (tied[i] && (int)i != b && (s < 0 || acc_before(&r[i], i, &r[s], (size_t)s)))
			s = (int)i;
	if (s < 0)
		for (i = 0; i < nm; i++)
			if (r[i].ok && sp[i] && !tied[i] && (s < 0 || sp[i]->med > sp[s]->med))
				s = (int)i;
	*best = b;
	*second = s;
	*fastest = f;
}

static int evaluate(const mesh_normals *mn, const scene_opts *o, const onb_method *ms, size_t nm,
                    const speed_row *const *sp, scene_eval *e)
{
	scene_buf b;
	int a, v;
	memset(e, 0, sizeof *e);
	for (a = 0; a < 2; a++)
		for (v = 0; v < 2; v++)
			if (!(e->r[a][v] = calloc(nm ? nm : 1, sizeof *e->r[a][v])) || !(e->tied[a][v] = calloc(nm ? nm : 1, 1))) {
				eval_free(e);
				return -1;
			}
	if (scene_buf_alloc(&b, mn->count, o->prec) != 0) {
		eval_free(e);
		return -1;
	}
	for (v = 0; v < 2; v++)
		for (a = 0; a < 2; a++) {
			size_t d = scene_fill(mn, o->prec, a ? o->other : o->up, v, &b);
			if (a == 0) {
				e->dropped[v] = d;
				e->used[v] = b.n;
			}
			scene_run_all(ms, nm, &b, o->tol, e->r[a][v]);
			rank(e->r[a][v], nm, sp, e->tied[a][v], &e->best[a][v], &e->second[a][v], &e->fastest[a][v]);
		}
	scene_buf_free(&b);
	return 0;
}

/* ------------------------------------------------------------------ */
/* scenes too small or too special for a general recommendation        */
/* ------------------------------------------------------------------ */

#define SCENE_FEW 64      /* fewer normals: too small for a general choice */
#define SCENE_FEW_DISTINCT 16

/* ------------------------------------------------------------------ */
/* report                                                              */
/* ------------------------------------------------------------------ */

static const char *variant_name(int v) { return v ? "renormalized" : "as-read"; }

static void print_speed_source(const speed_table *t, int prec)
{
	if (prec == PREC_HALF)
		printf("half speeds: libonb's binary16 kernels emulated in float (F16C conversions where the CPU has them): "
		       "a cost on this CPU, not a hardware half speed%s\n", t->kind == SPEED_REFERENCE ?
		       "; the committed half bench was run at load 21 on 2 cores and is not a measurement to quote "
		       "(results/half/bench/README.md): the ranking by speed is indicative only" : "");
	if (t->kind == SPEED_CACHE)
		printf("speed (%s): this machine's cache %s (%s); %d repetitions, interval = confidence interval of the median\n",
		       prec_name(prec), t->path, t->desc, t->reps);
	else if (t->kind == SPEED_FILE)
		printf("speed (%s): %s (%s); %d repetitions, interval = median -/+ (best - median)\n", prec_name(prec),
		       t->path, t->desc, t->reps);
	else
		printf("speed (%s): the committed reference run %s (%s), NOT measured on this machine; %d repetitions, "
		       "interval = median -/+ (best - median); 'onbstudy scene --refresh-speed --precision %s' measures and caches this machine's\n",
		       prec_name(prec), t->path, t->desc, t->reps, prec_name(prec));
}

static void print_input(const char *file, const mesh_normals *mn, const mesh_stats *st, int prec)
{
	char where[160];
	size_t i;
	printf("scene: %s\n", file);
	if (mn->format == MESH_OBJ)
		printf("format: OBJ, %zu vertices, %zu faces (%zu triangles)\n", mn->nvertices, mn->nfaces, mn->ntriangles);
	else if (mn->format == MESH_PLY)
		printf("format: PLY %s, %zu vertices, %zu faces\n", mn->ply_binary == 0 ? "ascii" : mn->ply_binary == 1 ?
		       "binary_little_endian" : "binary_big_endian", mn->nvertices, mn->nfaces);
	else
		printf("format: glTF 2.0 %s, %zu meshes, %zu primitives with triangles or normals, %zu vertices%s\n",
		       mn->gltf_binary ? "binary (.glb)" : "JSON (.gltf)", mn->nmeshes, mn->nprims, mn->nvertices,
		       mn->world ? ", world space (--world)" : ", object space (as stored)");
	if (mn->warning[0])
		printf("warning: %s\n", mn->warning);
	if (mn->header_skipped)
		printf("warning: %zu header line(s) with an unknown keyword skipped (first: line %llu)\n", mn->header_skipped,
		       (unsigned long long)mn->header_skipped_line);
	if (mn->origin == MESH_STORED)
		printf("normals: %zu stored (%s)%s\n", mn->count, mn->format == MESH_OBJ ? "'vn' lines" :
		       mn->stored_type == MESH_T_FLOAT ? "float nx ny nz" : mn->stored_type == MESH_T_DOUBLE ? "double nx ny nz" :
		       mn->stored_type == MESH_T_QUANT ? "normalized integers (KHR_mesh_quantization), decoded" :
		       "nx ny nz of mixed or integer type", mn->ncomputed ? "" : "");
	else
		printf("normals: %zu computed (area-weighted vertex normals from the faces; %zu unreferenced vertices skipped)\n",
		       mn->count, mn->unreferenced);
	if (mn->origin == MESH_STORED && mn->ncomputed)
		printf("normals: %zu of them computed (area-weighted) for %zu primitive(s) without NORMAL\n", mn->ncomputed, mn->nprims_computed);
	printf("counts in %s: total %zu, unit %zu (||n|-1| <= %.2g), non-unit %zu, degenerate %zu (zero %zu, non-finite %zu)\n",
	       prec_name(prec), st->total, st->unit, st->tol, st->nonunit, st->zero + st->nonfinite, st->zero, st->nonfinite);
	if (st->nonunit)
		printf("non-unit: |n|-1 in [%.3g, %.3g]; ||n|-1| median %.3g, p90 %.3g, p99 %.3g\n", st->dev_min, st->dev_max, st->q50, st->q90, st->q99);
	if (st->nbad) {
		printf("degenerate (first %zu):", st->nbad);
		for (i = 0; i < st->nbad; i++) {
			mesh_where(mn, st->bad[i], where, sizeof where);
			printf("%s %s (%a, %a, %a)", i ? ";" : "", where, mn->x[st->bad[i]], mn->y[st->bad[i]], mn->z[st->bad[i]]);
		}
		printf("\n");
	}
}

static const char *status(const scene_eval *e, int v, size_t i, const speed_row *sp)
{
	const scene_res *r = &e->r[0][v][i];
	if ((int)i == e->best[0][v]) return "RECOMMENDED";
	if ((int)i == e->second[0][v]) return e->tied[0][v][i] ? "runner-up (tied)" : "runner-up";
	if (e->tied[0][v][i]) return "tied";
	if (!r->ok) return r->nonfinite ? "non-finite output" : r->wrong_hand ? "wrong-handed" : "exceeds E";
	return sp ? "ok" : "ok, no speed figure";
}

/* In half the defects are printed in u = 2^-11 (binary16's unit
   roundoff), the unit of every half result of the study; scene.csv keeps
   them as numbers in every precision. */
static void print_table(const onb_method *ms, size_t nm, const speed_row *const *sp, const scene_eval *e, int v,
                        const double *udef, int prec)
{
	const double s = prec == PREC_HALF ? 0x1p11 : 1.0;
	size_t i;
	printf("  %-24s %10s %10s %9s %9s %8s %11s %9s %21s  %s\n", "method", prec == PREC_HALF ? "max_def/u" : "max_defect",
	       prec == PREC_HALF ? "rms_def/u" : "rms_defect", "nonfinite", "wronghand", "scal!=bt",
	       prec == PREC_HALF ? "unif_max/u" : "uniform_max", "M/s", "[interval]", "");
	for (i = 0; i < nm; i++) {
		const scene_res *r = &e->r[0][v][i];
		char sb[64] = "-", ib[64] = "";
		if (sp[i]) {
			snprintf(sb, sizeof sb, "%.1f", sp[i]->med);
			snprintf(ib, sizeof ib, "[%.1f, %.1f]", sp[i]->lo, sp[i]->hi);
		}
		printf("  %-24s %10.3g %10.3g %9zu %9zu %8zu %11.3g %9s %21s  %s\n", ms[i].name, s * r->max_defect, s * r->rms_defect,
		       r->nonfinite, r->wrong_hand, r->mismatch, s * udef[i], sb, ib, status(e, v, i, sp[i]));
	}
}

/* Why the recommendation won, the margin to the runner-up, and faster
   methods that were not acceptable. */
static void print_verdict(const mesh_normals *mn, const onb_method *ms, size_t nm, const speed_row *const *sp,
                          const scene_eval *e, int v, double tol)
{
	const scene_res *r = e->r[0][v];
	const int b = e->best[0][v], s = e->second[0][v], f = e->fastest[0][v];
	size_t i, nt = 0;
	char where[160];
	if (b < 0) {
		printf("  recommended (%s): none (no method with a speed figure stays within E = %.3g on these normals)\n", variant_name(v), tol);
		return;
	}
	for (i = 0; i < nm; i++)
		nt += e->tied[0][v][i];
	printf("  recommended (%s): %s, max defect %.3g, %.1f M bases/s [%.1f, %.1f]; ", variant_name(v), ms[b].name,
	       r[b].max_defect, sp[b]->med, sp[b]->lo, sp[b]->hi);
	if (nt == 1)
		printf("the fastest acceptable method, alone in its speed interval\n");
	else if (b == f)
		printf("the fastest acceptable method by median, and the most accurate of the %zu tied with it\n", nt);
	else if (acc_before(&r[b], (size_t)b, &r[f], (size_t)f) && (r[b].max_defect != r[f].max_defect || r[b].rms_defect != r[f].rms_defect))
		printf("tied in speed with the fastest (%s, %.1f M/s): the most accurate of the %zu tied\n", ms[f].name, sp[f]->med, nt);
	else
		printf("tied in speed and accuracy with the fastest (%s): the earlier in the registry's order\n", ms[f].name);
	if (s >= 0)
		printf("  runner-up: %s, max defect %.3g, %.1f M/s [%.1f, %.1f]; margin %+.1f%% in median speed, %s\n", ms[s].name,
		       r[s].max_defect, sp[s]->med, sp[s]->lo, sp[s]->hi, 100.0 * (sp[b]->med - sp[s]->med) / sp[s]->med,
		       e->tied[0][v][s] ? "within the speed intervals (tied; decided by accuracy, then order)" : "outside the speed intervals");
	else
		printf("  runner-up: none (no other method with a speed figure stays within E)\n");
	for (i = 0; i < nm; i++)
		if (!r[i].ok && sp[i] && sp[i]->med > sp[b]->med) {
			mesh_where(mn, r[i].nonfinite ? r[i].first_nonfinite : r[i].worst, where, sizeof where);
			if (r[i].nonfinite)
				printf("  faster but unusable: %-24s %.1f M/s, %zu non-finite bases (first: %s)\n", ms[i].name, sp[i]->med,
				       r[i].nonfinite, where);
			else
				printf("  faster but over E: %-24s %.1f M/s, max defect %.3g at %s%s\n", ms[i].name, sp[i]->med,
				       r[i].max_defect, where, r[i].wrong_hand ? ", wrong-handed bases" : "");
		}
	for (i = 0; i < nm; i++)
		if (r[i].ok && !sp[i])
			printf("  not ranked: %s is within E but has no speed figure in the speed source\n", ms[i].name);
}

/* Scenes too small or too special for a general recommendation, and a
   recommendation that is only right for this scene. */
static void print_flags(const onb_method *ms, const scene_shape *sh, const scene_eval *e, int v, const double *udef,
                        double tol)
{
	const int b = e->best[0][v];
	if (sh->used < SCENE_FEW)
		printf("  flag: only %zu usable normals: too few for a general recommendation\n", sh->used);
	if (sh->used && sh->distinct < SCENE_FEW_DISTINCT)
		printf("  flag: only %zu distinct normals: too special for a general recommendation\n", sh->distinct);
	if (sh->used && sh->on_axes == sh->used)
		printf("  flag: every normal is a coordinate axis (+-x, +-y, +-z): methods that are inexact in general are exact here\n");
	if (b >= 0 && !(udef[b] <= tol))
		printf("  flag: %s is within E here but not in general (max defect %.3g > E on 4096 uniform directions); it wins "
		       "because %s; do not use it for other scenes\n", ms[b].name, udef[b],
		       sh->used && sh->on_axes == sh->used ? "every normal here is a coordinate axis, where it is exact"
		       : sh->distinct < SCENE_FEW_DISTINCT ? "this scene has only a few distinct normals, all of which it happens to handle"
		       : "this scene's normals avoid the directions where it fails");
}

static void print_variant(const mesh_normals *mn, const scene_opts *o, const onb_method *ms, size_t nm,
                          const speed_row *const *sp, const scene_eval *e, int v, const double *udef,
                          const scene_shape *sh)
{
	const int b = e->best[0][v], ob = e->best[1][v];
	printf("\n%s normals, %s, %zu used:\n", v ? "renormalized" : "as-read", prec_name(o->prec), e->used[v]);
	print_table(ms, nm, sp, e, v, udef, o->prec);
	print_verdict(mn, ms, nm, sp, e, v, o->tol);
	print_flags(ms, sh, e, v, udef, o->tol);
	if (ob == b)
		printf("  under --up %c: the same recommendation\n", o->other);
	else
		printf("  under --up %c: %s instead (max defect there %.3g)\n", o->other, ob >= 0 ? ms[ob].name : "none",
		       ob >= 0 ? e->r[1][v][ob].max_defect : 0.0);
}

/* ------------------------------------------------------------------ */
/* CSV and the command                                                 */
/* ------------------------------------------------------------------ */

static void csv_rows(FILE *f, const scene_opts *o, const char *space, const onb_method *ms, size_t nm,
                     const speed_row *const *sp, const speed_table *t, const scene_eval *e, const double *udef,
                     const double *proven)
{
	static const char *kind[] = { "", "file", "cache", "reference" };
	int a, v;
	size_t i;
	for (a = 0; a < 2; a++)
		for (v = 0; v < 2; v++)
			for (i = 0; i < nm; i++) {
				const scene_res *r = &e->r[a][v][i];
				const char *rk = (int)i == e->best[a][v] ? "recommended" : (int)i == e->second[a][v] ? "runner-up" : "";
				fprintf(f, "\"%s\",%s,%c,%s,%s,%zu,%.6e,%.6e,%.6e,%.6e,%zu,%zu,%zu,", o->file, prec_name(o->prec),
				        a ? o->other : o->up, v ? "renormalized" : "as_read", ms[i].name, e->used[v], r->max_defect,
				        r->rms_defect, r->max_norm, r->max_dot, r->nonfinite, r->wrong_hand, r->mismatch);
				if (sp[i])
					fprintf(f, "%.6g,%.6g,", sp[i]->med, sp[i]->lo);
				else
					fprintf(f, "nan,nan,");
				fprintf(f, "%d,%s,%.6g,%d,%.6e,%s,%s,", r->ok, rk, sp[i] ? sp[i]->hi : NAN, e->tied[a][v][i], udef[i],
				        kind[t->kind], space);
				/* the proof covers the renormalized normals of the file's
				   own space and up axis */
				if (proven && !isnan(proven[i]) && a == 0 && v == 1 && strcmp(space, "object") == 0)
					fprintf(f, "%.6e\n", proven[i]);
				else
					fputc('\n', f);
			}
}

static int write_csv(const scene_opts *o, const mesh_normals *mn, const mesh_stats *st, const onb_method *ms, size_t nm,
                     const speed_row *const *sp, const speed_table *t, const scene_eval *e, const scene_eval *obj,
                     const double *udef, const double *proven)
{
	study_out out;
	if (study_out_open(&out, o->outdir, "scene.csv") != 0)
		return -1;
	study_provenance(out.f, "scene", 0, 1);
	fprintf(out.f, "# file: %s\n# normals: %zu %s%s; unit %zu (tol %.3g), non-unit %zu, zero %zu, non-finite %zu\n", o->file,
	        mn->count, mn->origin == MESH_STORED ? "stored" : "computed", mn->world ? ", world space (--world)" : "",
	        st->unit, st->tol, st->nonunit, st->zero, st->nonfinite);
	fprintf(out.f, "# precision: %s; tolerance E: %.17g%s\n", prec_name(o->prec), o->tol, o->prec == PREC_HALF ?
	        "; binary16: each component the file's float rounded to nearest binary16, u = 2^-11 (stdout prints the "
	        "defects in u; the columns here are the defects themselves)" : "");
	fprintf(out.f, "# speed: %s %s (%s), %d repetitions; batch_mbases_s is its median, speed_lo and speed_hi its interval; "
	        "never timed on the scene\n", t->kind == SPEED_CACHE ? "cache" : t->kind == SPEED_FILE ? "file" : "reference run",
	        t->path, t->desc, t->reps);
	fprintf(out.f, "# rank: among methods within E, those whose speed interval reaches the fastest one's are tied "
	        "(tied_with_fastest); the most accurate on the scene wins (max_defect, rms_defect), then the registry's order\n");
	fprintf(out.f, "# uniform_max_defect: max defect on 4096 uniform directions (seed 1) in this precision (inf: non-finite or wrong-handed)\n");
	fprintf(out.f, "# proven_max: with --certify, the proven bound on the defect over every normal a renderer can interpolate "
	        "on the file's triangles, on the renormalized rows of the file's own space and up axis (inf: singular there); "
	        "empty elsewhere\n");
	fprintf(out.f, "file,precision,up,variant,method,normals,max_defect,rms_defect,max_norm_err,max_dot_err,nonfinite,"
	        "wrong_handedness,scalar_batch_mismatch,batch_mbases_s,speed_lo,within_tolerance,rank,speed_hi,tied_with_fastest,"
	        "uniform_max_defect,speed_source,space,proven_max\n");
	csv_rows(out.f, o, mn->world ? "world" : "object", ms, nm, sp, t, e, udef, proven);
	if (obj)
		csv_rows(out.f, o, "object", ms, nm, sp, t, obj, udef, proven);
	if (study_out_commit(&out) != 0)
		return -1;
	printf("wrote %s\n", out.path);
	return 0;
}

static int refresh_only(const scene_opts *o)
{
	speed_table t;
	size_t i;
	if (speed_load(o->prec, NULL, 1, (int)o->repeats, &t) != 0)
		return ONB_EXIT_USAGE;
	print_speed_source(&t, o->prec);
	for (i = 0; i < t.n; i++)
		printf("  %-24s %9.1f M/s [%.1f, %.1f]\n", t.rows[i].method, t.rows[i].med, t.rows[i].lo, t.rows[i].hi);
	speed_free(&t);
	return 0;
}

/* --certify: the proven bounds over the scene's patches into proven[]
   (NaN for a method without a model), printed beside the measured maxima
   of variant v. */
static int certify(const scene_opts *o, const onb_method *ms, size_t nm, const scene_eval *e, int v, double *proven)
{
	double *measured = malloc((nm ? nm : 1) * sizeof *measured);
	size_t i;
	int rc;
	if (!measured) {
		study_error("scene: out of memory");
		return -1;
	}
	for (i = 0; i < nm; i++) {
		measured[i] = e->r[0][v][i].max_defect;
		proven[i] = NAN;
	}
	rc = scene_certify(o->file, o->up, o->prec, o->tol, ms, nm, measured,
	                   e->best[0][v] >= 0 ? ms[e->best[0][v]].name : NULL, proven);
	free(measured);
	return rc;
}

/* With --world: the object-space recommendation too, from a second read. */
static int object_space(const scene_opts *o, const onb_method *ms, size_t nm, const speed_row *const *sp, scene_eval *obj)
{
	mesh_normals mn;
	mesh_opts mo;
	char err[512];
	int v;
	memset(&mo, 0, sizeof mo);
	mo.prec = o->prec == PREC_HALF ? PREC_FLOAT : o->prec;
	if (mesh_read_file_opts(o->file, &mo, &mn, NULL, err, sizeof err) != 0) {
		study_error("scene: %s", err);
		return -1;
	}
	if (evaluate(&mn, o, ms, nm, sp, obj) != 0) {
		study_error("scene: out of memory");
		mesh_free(&mn);
		return -1;
	}
	printf("\nobject space (the normals as stored, without the node transforms): %zu normals\n", mn.count);
	for (v = 0; v < 2; v++)
		printf("  recommended (%s): %s\n", variant_name(v), obj->best[0][v] >= 0 ? ms[obj->best[0][v]].name : "none");
	mesh_free(&mn);
	return 0;
}

/* The registry's methods that have code in this precision: in double, the
   float-only ones (ONB_FLOAT_ONLY) are left out; in half, those without a
   binary16 entry (arrayh; none in a build without _Float16). */
static const onb_method *methods_for(int prec, size_t *nm)
{
	static onb_method dbl_ms[128];
	const onb_method *ms = onb_methods(nm);
	size_t i, j = 0;
	if (prec == PREC_FLOAT)
		return ms;
	for (i = 0; i < *nm && j < sizeof dbl_ms / sizeof dbl_ms[0]; i++)
		if (prec == PREC_HALF ? ms[i].arrayh != NULL : ms[i].basis && ms[i].batch)
			dbl_ms[j++] = ms[i];
	*nm = j;
	return dbl_ms;
}

/* The kernels' instruction set: in half the arithmetic is emulated in
   float (no native half instruction), the conversions are onb_half_isa()'s
   (bench's isa column says the same). */
static const char *scene_isa(int prec)
{
	static char buf[48];
	if (prec != PREC_HALF)
		return onb_batch_isa();
#if ONB_HAVE_HALF
	snprintf(buf, sizeof buf, "emulated-%s", onb_half_isa());
#else
	snprintf(buf, sizeof buf, "none");
#endif
	return buf;
}

/* The input, the run's settings and the speed source, before the tables. */
static void print_head(const scene_opts *o, const mesh_normals *mn, const mesh_stats *st, const speed_table *t,
                       const scene_eval *e)
{
	print_input(o->file, mn, st, o->prec);
	if (e->dropped[1])
		printf("renormalizing under/overflowed for %zu normals (left out of the renormalized row)\n", e->dropped[1]);
	printf("up axis: %c (%s); tolerance E = %.3g (max orthonormality defect%s); batch isa %s\n", o->up,
	       o->up == 'z' ? "(x,y,z) as stored" : o->up == 'y' ? "(x,y,z) -> (z,x,y)" : "(x,y,z) -> (y,z,x)", o->tol,
	       o->prec == PREC_HALF ? "; in u = 2^-11 below" : "", scene_isa(o->prec));
	if (o->prec == PREC_HALF)
		printf("binary16: each component the file's float rounded to nearest binary16 (u = 2^-11, largest 65504, "
		       "smallest subnormal 2^-24: a component above 65504 becomes infinite and the normal is degenerate); "
		       "every operation rounded to binary16 (libonb's half kernels: onb_NAME_arrayh per basis as the batch, "
		       "onb_NAMEh as the scalar)\n");
	print_speed_source(t, o->prec);
}

/* The headline: the recommendation for variant v in the chosen up axis. */
static void print_recommended(const scene_opts *o, const onb_method *ms, const speed_table *t, const scene_eval *e, int v)
{
	printf("\nrecommended for %s (%s normals%s, %s, up %c, E %.3g, speed from %s): %s\n", o->file, variant_name(v),
	       o->world ? ", world space" : "", prec_name(o->prec), o->up, o->tol,
	       t->kind == SPEED_CACHE ? "this machine's cache" : t->kind == SPEED_FILE ? "--speed" : "the reference run",
	       e->best[0][v] >= 0 ? ms[e->best[0][v]].name : "none");
}

int cmd_scene(int argc, char **argv)
{
	scene_opts o;
	mesh_normals mn;
	mesh_opts mo;
	mesh_stats st;
	scene_shape sh;
	speed_table t;
	scene_eval e, obj;
	char err[512], rundir[256];
	size_t nm, i;
	const onb_method *ms;
	const speed_row **sp = NULL;
	double *udef = NULL, *proven = NULL;
	int rc = ONB_EXIT_USAGE, v;

	memset(&o, 0, sizeof o);
	o.prec = PREC_FLOAT;
	o.up = 'z';
	o.repeats = 15;
	if ((v = parse_opts(argc, argv, &o)) != 0)
		return v > 0 ? 0 : ONB_EXIT_USAGE;
	if (!o.tol_given)
		o.tol = o.prec == PREC_FLOAT ? 1e-6 : o.prec == PREC_HALF ? 0x1p-7 : 1e-14;
	o.other = o.up == 'z' ? 'y' : 'z';
	ms = methods_for(o.prec, &nm);
	if (!o.file)
		return refresh_only(&o);
	memset(&mo, 0, sizeof mo);
	mo.world = o.world;
	mo.prec = o.prec == PREC_HALF ? PREC_FLOAT : o.prec;   /* half: the float transform, then the rounding */
	if (mesh_read_file_opts(o.file, &mo, &mn, NULL, err, sizeof err) != 0) {
		study_error("scene: %s", err);
		return ONB_EXIT_USAGE;
	}
	memset(&t, 0, sizeof t);
	memset(&e, 0, sizeof e);
	memset(&obj, 0, sizeof obj);
	/* refuse an unusable output directory before the measurements */
	if (!o.outdir) {
		study_default_run_dir(rundir, sizeof rundir);
		o.outdir = rundir;
	}
	if (study_mkdir_p(o.outdir) != 0 || speed_load(o.prec, o.speed_file, o.refresh, (int)o.repeats, &t) != 0)
		goto out;
	rc = 1;
	sp = calloc(nm ? nm : 1, sizeof *sp);
	udef = calloc(nm ? nm : 1, sizeof *udef);
	proven = calloc(nm ? nm : 1, sizeof *proven);
	if (!sp || !udef || !proven || mesh_classify(&mn, o.prec, 0, &st) != 0 || scene_shape_of(&mn, o.prec, &sh) != 0
	    || scene_uniform_defects(ms, nm, o.prec, udef) != 0) {
		study_error("scene: out of memory for %zu normals", mn.count);
		goto out;
	}
	for (i = 0; i < nm; i++)
		sp[i] = speed_find(&t, ms[i].name);
	if (evaluate(&mn, &o, ms, nm, sp, &e) != 0) {
		study_error("scene: out of memory for %zu normals", mn.count);
		goto out;
	}
	print_head(&o, &mn, &st, &t, &e);
	for (v = 0; v < 2; v++)
		print_variant(&mn, &o, ms, nm, sp, &e, v, udef, &sh);
	if (o.world && object_space(&o, ms, nm, sp, &obj) != 0)
		goto out;
	v = o.renorm_head;
	print_recommended(&o, ms, &t, &e, v);
	if (o.certify && certify(&o, ms, nm, &e, v, proven) != 0)
		goto out;
	if (write_csv(&o, &mn, &st, ms, nm, sp, &t, &e, o.world ? &obj : NULL, udef, o.certify ? proven : NULL) != 0)
		goto out;
	rc = 0;
out:
	eval_free(&e);
	eval_free(&obj);
	speed_free(&t);
	free(sp);
	free(udef);
	free(proven);
	mesh_free(&mn);
	return rc;
}
