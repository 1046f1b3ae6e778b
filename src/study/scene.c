/*
 * scene.c - `onbstudy scene FILE`: every method on a scene's own normals,
 * and a recommendation for that scene.
 *
 * The normals come from meshio.c, rounded to the working precision
 * (--precision, default float).  Degenerate normals (zero or non-finite
 * there) are counted and located, then left out: no basis is meaningful
 * for them, and a renderer has to catch them before building one
 * (onb_basis_checked does).  Every other normal goes to every method twice:
 *   as-read       exactly as the file holds them, or as computed from the
 *                 faces (non-unit ones included);
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
 * outputs differ in any bit.  Throughput: million bases per second on this
 * input, median of --repeats timed passes after one warm-up pass, each
 * pass at least 2 ms long.
 *
 * Recommendation: the fastest method (batch throughput) with no non-finite
 * output, no wrong-handed basis and max defect <= E.  Default E: 1e-6 in
 * float (about 8 float ulps of 1), 1e-14 in double (about 45 double ulps).
 *
 * --up picks the axis that plays n.z, by a cyclic permutation of the
 * coordinates (a proper rotation, det +1):
 *   z: (x, y, z) -> (x, y, z)     y: (x, y, z) -> (z, x, y)     x: (x, y, z) -> (y, z, x)
 * The recommendation is also computed for the other convention (z when
 * --up is y or x, y when it is z), with the errors measured again and the
 * throughput of the chosen convention reused (the same data in another
 * order; timing it again would only add noise).
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "study.h"
#include "meshio.h"

typedef struct {
	double max_defect, rms_defect, max_norm, max_dot;
	size_t nonfinite, wrong_hand, mismatch, worst, first_nonfinite;
	double batch_mbs, scalar_mbs;
	int ok;
} scene_res;

typedef struct {
	size_t n;
	int fl;                 /* 1: float arrays */
	void *in[3], *bo[6], *so[6];
	size_t *src;            /* index into the mesh normals */
} scene_buf;

static void buf_free(scene_buf *b)
{
	int k;
	for (k = 0; k < 3; k++) free(b->in[k]);
	for (k = 0; k < 6; k++) { free(b->bo[k]); free(b->so[k]); }
	free(b->src);
	memset(b, 0, sizeof *b);
}

static int buf_alloc(scene_buf *b, size_t n, int fl)
{
	size_t es = fl ? sizeof(float) : sizeof(double), cnt = n ? n : 1;
	int k, bad = 0;
	memset(b, 0, sizeof *b);
	b->n = n;
	b->fl = fl;
	for (k = 0; k < 3; k++) bad |= !(b->in[k] = calloc(cnt, es));
	for (k = 0; k < 6; k++) { bad |= !(b->bo[k] = calloc(cnt, es)); bad |= !(b->so[k] = calloc(cnt, es)); }
	bad |= !(b->src = calloc(cnt, sizeof *b->src));
	if (bad) {
		buf_free(b);
		return -1;
	}
	return 0;
}

static long double getv(const void *a, int fl, size_t i)
{
	return fl ? (long double)((const float *)a)[i] : (long double)((const double *)a)[i];
}

static void run_batch(const onb_method *m, const scene_buf *b)
{
	if (b->fl)
		m->batchf(b->n, b->in[0], b->in[1], b->in[2], b->bo[0], b->bo[1], b->bo[2], b->bo[3], b->bo[4], b->bo[5]);
	else
		m->batch(b->n, b->in[0], b->in[1], b->in[2], b->bo[0], b->bo[1], b->bo[2], b->bo[3], b->bo[4], b->bo[5]);
}

static void run_scalar(const onb_method *m, const scene_buf *b)
{
	size_t i;
	if (b->fl) {
		const float *x = b->in[0], *y = b->in[1], *z = b->in[2];
		float **o = (float **)b->so;
		for (i = 0; i < b->n; i++) {
			onb_vec3f n, b1, b2;
			n.x = x[i]; n.y = y[i]; n.z = z[i];
			m->basisf(n, &b1, &b2);
			o[0][i] = b1.x; o[1][i] = b1.y; o[2][i] = b1.z;
			o[3][i] = b2.x; o[4][i] = b2.y; o[5][i] = b2.z;
		}
	} else {
		const double *x = b->in[0], *y = b->in[1], *z = b->in[2];
		double **o = (double **)b->so;
		for (i = 0; i < b->n; i++) {
			onb_vec3 n, b1, b2;
			n.x = x[i]; n.y = y[i]; n.z = z[i];
			m->basis(n, &b1, &b2);
			o[0][i] = b1.x; o[1][i] = b1.y; o[2][i] = b1.z;
			o[3][i] = b2.x; o[4][i] = b2.y; o[5][i] = b2.z;
		}
	}
}

static double now_s(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_d(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* Million bases per second, median of `repeats` passes. */
static double throughput(const onb_method *m, const scene_buf *b, int scalar, int repeats)
{
	double t0, t1, per, times[64];
	size_t inner = 1, k;
	int r;
	if (b->n == 0)
		return 0.0;
	t0 = now_s();
	scalar ? run_scalar(m, b) : run_batch(m, b); /* warm-up */
	t1 = now_s();
	per = t1 - t0;
	if (per < 2e-3)
		inner = (size_t)(2e-3 / (per > 1e-8 ? per : 1e-8)) + 1;
	if (inner > 1000000)
		inner = 1000000;
	for (r = 0; r < repeats; r++) {
		t0 = now_s();
		for (k = 0; k < inner; k++)
			scalar ? run_scalar(m, b) : run_batch(m, b);
		t1 = now_s();
		times[r] = (t1 - t0) / (double)inner;
	}
	qsort(times, (size_t)repeats, sizeof times[0], cmp_d);
	per = times[(repeats - 1) / 2];
	return per > 0 ? (double)b->n / per / 1e6 : 0.0;
}

/* Metrics of the batch outputs in b (see the file comment). */
static void measure(const onb_method *m, const scene_buf *b, scene_res *r)
{
	size_t i;
	long double sum2 = 0;
	size_t nfin = 0;
	const size_t es = b->fl ? sizeof(float) : sizeof(double);
	memset(r, 0, sizeof *r);
	for (i = 0; i < b->n; i++) {
		long double n[3], u[3], v[3], l, e, d, det;
		int k;
		for (k = 0; k < 3; k++) {
			n[k] = getv(b->in[k], b->fl, i);
			u[k] = getv(b->bo[k], b->fl, i);
			v[k] = getv(b->bo[k + 3], b->fl, i);
		}
		for (k = 0; k < 6; k++)
			if (memcmp((const char *)b->bo[k] + i * es, (const char *)b->so[k] + i * es, es) != 0) {
				r->mismatch++;
				break;
			}
		if (!isfinite(u[0]) || !isfinite(u[1]) || !isfinite(u[2]) || !isfinite(v[0]) || !isfinite(v[1]) || !isfinite(v[2])) {
			if (r->nonfinite++ == 0)
				r->first_nonfinite = i;
			continue;
		}
		l = sqrtl(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		n[0] /= l; n[1] /= l; n[2] /= l;
		e = fabsl(sqrtl(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) - 1);
		d = fabsl(sqrtl(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) - 1);
		if (d > e) e = d;
		if (e > r->max_norm) r->max_norm = (double)e;
		d = fabsl(u[0] * n[0] + u[1] * n[1] + u[2] * n[2]);
		l = fabsl(v[0] * n[0] + v[1] * n[1] + v[2] * n[2]);
		if (l > d) d = l;
		l = fabsl(u[0] * v[0] + u[1] * v[1] + u[2] * v[2]);
		if (l > d) d = l;
		if (d > r->max_dot) r->max_dot = (double)d;
		if (d > e) e = d;
		if (e > r->max_defect || nfin == 0) {
			if (e > r->max_defect) r->max_defect = (double)e;
			r->worst = i;
		}
		sum2 += e * e;
		nfin++;
		det = (u[1] * v[2] - u[2] * v[1]) * n[0] + (u[2] * v[0] - u[0] * v[2]) * n[1] + (u[0] * v[1] - u[1] * v[0]) * n[2];
		if (m->handedness != 0 && (det > 0 ? 1 : -1) != m->handedness)
			r->wrong_hand++;
	}
	r->rms_defect = nfin ? (double)sqrtl(sum2 / (long double)nfin) : 0.0;
}

/* Fill b with the non-degenerate normals, permuted for `up`, rounded to
   the working precision, and renormalized when asked.  Returns the number
   dropped because renormalizing under- or overflowed. */
static size_t fill(const mesh_normals *mn, int fl, char up, int renorm, scene_buf *b)
{
	size_t i, k = 0, dropped = 0;
	for (i = 0; i < mn->count; i++) {
		double x = mn->x[i], y = mn->y[i], z = mn->z[i], p[3];
		if (fl) { x = (float)x; y = (float)y; z = (float)z; }
		if (!isfinite(x) || !isfinite(y) || !isfinite(z) || (x == 0 && y == 0 && z == 0))
			continue;
		if (up == 'y') { p[0] = z; p[1] = x; p[2] = y; }
		else if (up == 'x') { p[0] = y; p[1] = z; p[2] = x; }
		else { p[0] = x; p[1] = y; p[2] = z; }
		if (fl) {
			float f[3];
			f[0] = (float)p[0]; f[1] = (float)p[1]; f[2] = (float)p[2];
			if (renorm) {
				float l = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
				f[0] = f[0] / l; f[1] = f[1] / l; f[2] = f[2] / l;
				if (!isfinite(f[0]) || !isfinite(f[1]) || !isfinite(f[2])) { dropped++; continue; }
			}
			((float *)b->in[0])[k] = f[0]; ((float *)b->in[1])[k] = f[1]; ((float *)b->in[2])[k] = f[2];
		} else {
			if (renorm) {
				double l = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
				p[0] = p[0] / l; p[1] = p[1] / l; p[2] = p[2] / l;
				if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2])) { dropped++; continue; }
			}
			((double *)b->in[0])[k] = p[0]; ((double *)b->in[1])[k] = p[1]; ((double *)b->in[2])[k] = p[2];
		}
		b->src[k++] = i;
	}
	b->n = k;
	return dropped;
}

/* Index of the fastest acceptable method, and the runner-up. */
static void recommend(const scene_res *r, size_t nm, int *best, int *second)
{
	size_t i;
	*best = *second = -1;
	for (i = 0; i < nm; i++) {
		if (!r[i].ok)
			continue;
		if (*best < 0 || r[i].batch_mbs > r[*best].batch_mbs) {
			*second = *best;
			*best = (int)i;
		} else if (*second < 0 || r[i].batch_mbs > r[*second].batch_mbs) {
			*second = (int)i;
		}
	}
}

static void usage(FILE *f)
{
	fprintf(f,
	"usage: onbstudy scene FILE [--tolerance E] [--precision float|double] [--up z|y|x]\n"
	"                           [--renormalize] [--repeats N] [--out DIR]\n"
	"  Reads the normals of an OBJ or PLY file (stored, or area-weighted from the faces),\n"
	"  runs every method on them as stored and renormalized, and recommends the fastest\n"
	"  method whose max orthonormality defect stays within E (default 1e-6 float, 1e-14\n"
	"  double).  --renormalize makes the renormalized row the headline (default: the as-read row).  --up names the\n"
	"  axis that plays n.z (y: (x,y,z)->(z,x,y), x: (x,y,z)->(y,z,x)).  Writes\n"
	"  DIR/scene.csv (default results/run-DATE).\n");
}

int cmd_scene(int argc, char **argv)
{
	const char *file = NULL, *outdir = NULL, *tolarg = NULL;
	double tol = 0;
	int fl = 1, renorm_head = 0, k, rc = ONB_EXIT_USAGE;
	long repeats = 5;
	char up = 'z', other;
	mesh_normals mn;
	mesh_stats st;
	char err[512], where[160], rundir[256];
	size_t nm, i, dropped[2] = { 0, 0 };
	const onb_method *ms = onb_methods(&nm);
	scene_res *res = NULL, *ores = NULL;
	scene_buf b;
	study_out o;
	int best[2], second[2], obest[2], osecond[2], v;

	memset(&b, 0, sizeof b);
	memset(&mn, 0, sizeof mn);
	for (k = 0; k < argc; k++) {
		const char *a = argv[k];
		if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
			usage(stdout);
			return 0;
		} else if (!strcmp(a, "--renormalize")) {
			renorm_head = 1;
		} else if (!strcmp(a, "--tolerance") || !strcmp(a, "--precision") || !strcmp(a, "--up")
		           || !strcmp(a, "--out") || !strcmp(a, "--repeats")) {
			const char *val;
			if (k + 1 >= argc) {
				study_error("scene: %s needs a value", a);
				return ONB_EXIT_USAGE;
			}
			val = argv[++k];
			if (!strcmp(a, "--tolerance")) {
				if (parse_double(a, val, &tol) != 0)
					return ONB_EXIT_USAGE;
				if (!(tol > 0) || !isfinite(tol)) {
					study_error("scene: --tolerance must be a positive finite number, got '%s'", val);
					return ONB_EXIT_USAGE;
				}
				tolarg = val;
			} else if (!strcmp(a, "--precision")) {
				if (!strcmp(val, "float")) fl = 1;
				else if (!strcmp(val, "double")) fl = 0;
				else {
					study_error("scene: --precision must be float or double, got '%s'", val);
					return ONB_EXIT_USAGE;
				}
			} else if (!strcmp(a, "--up")) {
				if (strlen(val) != 1 || !strchr("xyz", val[0])) {
					study_error("scene: --up must be z, y or x, got '%s'", val);
					return ONB_EXIT_USAGE;
				}
				up = val[0];
			} else if (!strcmp(a, "--repeats")) {
				if (parse_int(a, val, 1, 64, &repeats) != 0)
					return ONB_EXIT_USAGE;
			} else {
				outdir = val;
			}
		} else if (a[0] == '-' && a[1]) {
			study_error("scene: unknown option '%s' (try 'onbstudy scene --help')", a);
			return ONB_EXIT_USAGE;
		} else if (file) {
			study_error("scene: one FILE only (got '%s' and '%s')", file, a);
			return ONB_EXIT_USAGE;
		} else {
			file = a;
		}
	}
	if (!file) {
		study_error("scene: no FILE given (try 'onbstudy scene --help')");
		return ONB_EXIT_USAGE;
	}
	if (!tolarg)
		tol = fl ? 1e-6 : 1e-14;
	other = up == 'z' ? 'y' : 'z';
	if (mesh_read_file(file, &mn, err, sizeof err) != 0) {
		study_error("scene: %s", err);
		return ONB_EXIT_USAGE;
	}
	/* Refuse an unusable output directory before the measurements. */
	if (!outdir) {
		study_default_run_dir(rundir, sizeof rundir);
		outdir = rundir;
	}
	if (study_mkdir_p(outdir) != 0)
		goto out;
	if (mesh_classify(&mn, fl, 0, &st) != 0) {
		study_error("scene: out of memory");
		goto out;
	}
	if (!fl) { /* the float-only methods (ONB_FLOAT_ONLY) have no double code */
		static onb_method dbl_ms[128];
		size_t j = 0;
		for (i = 0; i < nm && j < sizeof dbl_ms / sizeof dbl_ms[0]; i++)
			if (ms[i].basis)
				dbl_ms[j++] = ms[i];
		ms = dbl_ms;
		nm = j;
	}
	res = calloc(2 * nm, sizeof *res);
	ores = calloc(2 * nm, sizeof *ores);
	if (!res || !ores || buf_alloc(&b, mn.count, fl) != 0) {
		study_error("scene: out of memory for %zu normals", mn.count);
		goto out;
	}

	/* measure: variant 0 stored, 1 renormalized; chosen axis then the other */
	for (v = 0; v < 2; v++) {
		dropped[v] = fill(&mn, fl, up, v, &b);
		for (i = 0; i < nm; i++) {
			run_batch(&ms[i], &b);
			run_scalar(&ms[i], &b);
			measure(&ms[i], &b, &res[v * nm + i]);
			res[v * nm + i].worst = b.n ? b.src[res[v * nm + i].worst] : 0;
			res[v * nm + i].first_nonfinite = b.n ? b.src[res[v * nm + i].first_nonfinite] : 0;
			res[v * nm + i].batch_mbs = throughput(&ms[i], &b, 0, (int)repeats);
			res[v * nm + i].scalar_mbs = throughput(&ms[i], &b, 1, (int)repeats);
		}
		fill(&mn, fl, other, v, &b);
		for (i = 0; i < nm; i++) {
			run_batch(&ms[i], &b);
			run_scalar(&ms[i], &b);
			measure(&ms[i], &b, &ores[v * nm + i]);
			ores[v * nm + i].worst = b.n ? b.src[ores[v * nm + i].worst] : 0;
			ores[v * nm + i].batch_mbs = res[v * nm + i].batch_mbs;
			ores[v * nm + i].scalar_mbs = res[v * nm + i].scalar_mbs;
		}
		for (i = 0; i < nm; i++) {
			scene_res *r = &res[v * nm + i], *q = &ores[v * nm + i];
			r->ok = b.n > 0 && r->nonfinite == 0 && r->wrong_hand == 0 && r->max_defect <= tol;
			q->ok = b.n > 0 && q->nonfinite == 0 && q->wrong_hand == 0 && q->max_defect <= tol;
		}
		recommend(res + v * nm, nm, &best[v], &second[v]);
		recommend(ores + v * nm, nm, &obest[v], &osecond[v]);
	}

	/* report */
	printf("scene: %s\n", file);
	if (mn.format == MESH_OBJ)
		printf("format: OBJ, %zu vertices, %zu faces (%zu triangles)\n", mn.nvertices, mn.nfaces, mn.ntriangles);
	else
		printf("format: PLY %s, %zu vertices, %zu faces\n", mn.ply_binary == 0 ? "ascii" : mn.ply_binary == 1 ? "binary_little_endian" : "binary_big_endian",
		       mn.nvertices, mn.nfaces);
	if (mn.header_skipped)
		printf("warning: %zu header line(s) with an unknown keyword skipped (first: line %llu)\n", mn.header_skipped, (unsigned long long)mn.header_skipped_line);
	if (mn.origin == MESH_STORED)
		printf("normals: %zu stored (%s)\n", mn.count, mn.format == MESH_OBJ ? "'vn' lines" :
		       mn.stored_type == MESH_T_FLOAT ? "float nx ny nz" : mn.stored_type == MESH_T_DOUBLE ? "double nx ny nz" : "nx ny nz of mixed or integer type");
	else
		printf("normals: %zu computed (area-weighted vertex normals from the faces; %zu unreferenced vertices skipped)\n", mn.count, mn.unreferenced);
	printf("counts in %s: total %zu, unit %zu (||n|-1| <= %.2g), non-unit %zu, degenerate %zu (zero %zu, non-finite %zu)\n",
	       fl ? "float" : "double", st.total, st.unit, st.tol, st.nonunit, st.zero + st.nonfinite, st.zero, st.nonfinite);
	if (st.nonunit)
		printf("non-unit: |n|-1 in [%.3g, %.3g]; ||n|-1| median %.3g, p90 %.3g, p99 %.3g\n", st.dev_min, st.dev_max, st.q50, st.q90, st.q99);
	if (st.nbad) {
		printf("degenerate (first %zu):", st.nbad);
		for (i = 0; i < st.nbad; i++) {
			mesh_where(&mn, st.bad[i], where, sizeof where);
			printf("%s %s (%a, %a, %a)", i ? ";" : "", where, mn.x[st.bad[i]], mn.y[st.bad[i]], mn.z[st.bad[i]]);
		}
		printf("\n");
	}
	if (dropped[1])
		printf("renormalizing under/overflowed for %zu normals (left out of the renormalized row)\n", dropped[1]);
	printf("up axis: %c (%s); tolerance E = %.3g (max orthonormality defect); batch isa %s\n", up,
	       up == 'z' ? "(x,y,z) as stored" : up == 'y' ? "(x,y,z) -> (z,x,y)" : "(x,y,z) -> (y,z,x)", tol, onb_batch_isa());
	for (v = 0; v < 2; v++) {
		scene_res *r = res + v * nm;
		printf("\n%s normals, %s, %zu used:\n", v ? "renormalized" : "as-read", fl ? "float" : "double", b.n ? st.total - st.zero - st.nonfinite - dropped[v] : (size_t)0);
		printf("  %-24s %10s %10s %9s %9s %8s %10s %10s  %s\n", "method", "max_defect", "rms_defect", "nonfinite", "wronghand", "scal!=bt", "batch_M/s", "scalar_M/s", "");
		for (i = 0; i < nm; i++)
			printf("  %-24s %10.3g %10.3g %9zu %9zu %8zu %10.1f %10.1f  %s\n", ms[i].name, r[i].max_defect, r[i].rms_defect,
			       r[i].nonfinite, r[i].wrong_hand, r[i].mismatch, r[i].batch_mbs, r[i].scalar_mbs,
			       (int)i == best[v] ? "RECOMMENDED" : (int)i == second[v] ? "runner-up" : r[i].ok ? "ok" :
			       r[i].nonfinite ? "non-finite output" : r[i].wrong_hand ? "wrong-handed" : "exceeds E");
		if (best[v] >= 0) {
			printf("  recommended (%s): %s, %.1f M bases/s, max defect %.3g", v ? "renormalized" : "as-read",
			       ms[best[v]].name, r[best[v]].batch_mbs, r[best[v]].max_defect);
			if (second[v] >= 0)
				printf("; runner-up %s, %.1f M/s, max defect %.3g", ms[second[v]].name, r[second[v]].batch_mbs, r[second[v]].max_defect);
			printf("\n");
			/* the repeats of a pass on a shared machine spread by a few
			   per cent: say so rather than pretend to a ranking */
			if (second[v] >= 0 && r[second[v]].batch_mbs > 0.95 * r[best[v]].batch_mbs)
				printf("  note: the runner-up is within 5%% of the recommended method's throughput; on %zu normals that is within timing noise\n",
				       b.n);
			for (i = 0; i < nm; i++)
				if (!r[i].ok && r[i].batch_mbs > r[best[v]].batch_mbs) {
					mesh_where(&mn, r[i].nonfinite ? r[i].first_nonfinite : r[i].worst, where, sizeof where);
					if (r[i].nonfinite)
						printf("  faster but unusable: %-24s %.1f M/s, %zu non-finite bases (first: %s)\n", ms[i].name,
						       r[i].batch_mbs, r[i].nonfinite, where);
					else
						printf("  faster but over E: %-24s %.1f M/s, max defect %.3g at %s%s\n", ms[i].name, r[i].batch_mbs,
						       r[i].max_defect, where, r[i].wrong_hand ? ", wrong-handed bases" : "");
				}
		} else {
			printf("  recommended (%s): none (no method stays within E = %.3g on these normals)\n", v ? "renormalized" : "as-read", tol);
		}
		if (obest[v] == best[v])
			printf("  under --up %c: the same recommendation\n", other);
		else
			printf("  under --up %c: %s instead (max defect there %.3g)\n", other, obest[v] >= 0 ? ms[obest[v]].name : "none",
			       obest[v] >= 0 ? ores[v * nm + obest[v]].max_defect : 0.0);
	}
	v = renorm_head;
	printf("\nrecommended for %s (%s normals, %s, up %c, E %.3g): %s\n", file, v ? "renormalized" : "as-read", fl ? "float" : "double", up, tol,
	       best[v] >= 0 ? ms[best[v]].name : "none");

	/* CSV */
	if (study_out_open(&o, outdir, "scene.csv") != 0)
		goto out;
	study_provenance(o.f, "scene", 0, 1);
	fprintf(o.f, "# file: %s\n# normals: %zu %s; unit %zu (tol %.3g), non-unit %zu, zero %zu, non-finite %zu\n", file, mn.count,
	        mn.origin == MESH_STORED ? "stored" : "computed", st.unit, st.tol, st.nonunit, st.zero, st.nonfinite);
	fprintf(o.f, "# precision: %s; tolerance E: %.17g; repeats: %ld; throughput of the chosen up axis is reused for the other\n",
	        fl ? "float" : "double", tol, repeats);
	fprintf(o.f, "file,precision,up,variant,method,normals,max_defect,rms_defect,max_norm_err,max_dot_err,nonfinite,wrong_handedness,scalar_batch_mismatch,batch_mbases_s,scalar_mbases_s,within_tolerance,rank\n");
	for (k = 0; k < 2; k++)
		for (v = 0; v < 2; v++)
			for (i = 0; i < nm; i++) {
				const scene_res *r = (k ? ores : res) + v * nm + i;
				const int *bb = k ? obest : best, *ss = k ? osecond : second;
				fprintf(o.f, "\"%s\",%s,%c,%s,%s,%zu,%.6e,%.6e,%.6e,%.6e,%zu,%zu,%zu,%.2f,%.2f,%d,%s\n", file, fl ? "float" : "double",
				        k ? other : up, v ? "renormalized" : "as_read", ms[i].name, st.total - st.zero - st.nonfinite - dropped[v],
				        r->max_defect, r->rms_defect, r->max_norm, r->max_dot, r->nonfinite, r->wrong_hand, r->mismatch,
				        r->batch_mbs, r->scalar_mbs, r->ok, (int)i == bb[v] ? "recommended" : (int)i == ss[v] ? "runner-up" : "");
			}
	if (study_out_commit(&o) != 0)
		goto out;
	printf("wrote %s\n", o.path);
	rc = 0;
out:
	buf_free(&b);
	free(res);
	free(ores);
	mesh_free(&mn);
	return rc;
}
