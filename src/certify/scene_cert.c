/*
 * scene_cert.c - `onbstudy scene --certify`: a proven
 * bound for the normals a renderer builds its bases from.
 *
 * A renderer interpolates the three vertex normals of a triangle and
 * normalizes the result, so the shading normals of a triangle sweep the
 * spherical triangle of its vertex normals.  For each triangle we bound
 * that patch by a band of n.z (the vertices, the extremes of the three
 * great-circle arcs, and +-1 when a pole is inside) and an azimuth arc
 * (the shortest arc holding the three vertices' azimuths; all of them when
 * a pole is inside), then certify every default region that meets one of
 * them, each cut to the band of n.z the scene reaches.  Without faces,
 * each stored normal is its own patch.  The domain is every format vector
 * within 4 ulps of 1 of unit length (the renderer's own normalization of the
 * interpolated normal).
 *
 * In binary16 (--precision half) nothing is proven anew: the committed
 * proof results/half/certify/certify-half.csv (`certify --precision half`
 * of every method, 68 regions each) is read, the same patches mark its
 * regions, and each method's bound is the largest of its rows over the
 * regions the scene reaches (whole regions, not cut to the scene's band:
 * coarser, still a bound); a reached row that is not proven (non-finite,
 * overflow, unbounded) makes it inf.  Its domain is the committed run's:
 * every binary16 rounding of a unit vector.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include <unistd.h>
#include "common/csv.h"
#include "mesh/meshio.h"
#include "scene_cert.h"

#define DEGS (180.0 / 3.14159265358979323846)
#define MAXREG 512

static void unit(double v[3])
{
	double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
	v[0] /= l; v[1] /= l; v[2] /= l;
}

/* The z-extremes of the great-circle arc from p to q (unit): into lo, hi. */
static void arc_z(const double p[3], const double q[3], double *lo, double *hi)
{
	double c = p[0] * q[0] + p[1] * q[1] + p[2] * q[2], e2[3], th, ts;
	int i;
	if (c > 1.0 - 1e-15)
		return;
	for (i = 0; i < 3; i++)
		e2[i] = q[i] - c * p[i];
	unit(e2);
	th = acos(fmax(-1.0, fmin(1.0, c)));
	ts = atan2(e2[2], p[2]);              /* z(t) = p.z cos t + e2.z sin t */
	for (i = 0; i < 2; i++, ts += 3.14159265358979323846) {
		double t = fmod(ts + 4 * 3.14159265358979323846, 2 * 3.14159265358979323846);
		if (t <= th) {
			double z = p[2] * cos(t) + e2[2] * sin(t);
			*lo = fmin(*lo, z);
			*hi = fmax(*hi, z);
		}
	}
}

static double det3(const double a[3], const double b[3], const double c[3])
{
	return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/* 1 when direction p lies in the spherical triangle abc (or on it). */
static int inside(const double *v[3], const double p[3])
{
	double s0 = det3(v[0], v[1], p), s1 = det3(v[1], v[2], p), s2 = det3(v[2], v[0], p);
	double c = (v[0][0] + v[1][0] + v[2][0]) * p[0] + (v[0][1] + v[1][1] + v[2][1]) * p[1] + (v[0][2] + v[1][2] + v[2][2]) * p[2];
	const double e = 1e-12;
	return c > 0 && ((s0 >= -e && s1 >= -e && s2 >= -e) || (s0 <= e && s1 <= e && s2 <= e));
}

/* The azimuth arc [lo, lo + w] (degrees) holding the three azimuths:
   the complement of the widest gap between them. */
static void azimuth_arc(const double *v[3], double *lo, double *w)
{
	double a[3], t;
	int i, j;
	for (i = 0; i < 3; i++)
		a[i] = cert_phi_deg(v[i][0], v[i][1]);
	for (i = 0; i < 3; i++)
		for (j = i + 1; j < 3; j++)
			if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t; }
	*lo = a[0];
	*w = a[2] - a[0];
	if (a[1] - a[0] > 360.0 - *w) { *lo = a[1]; *w = a[0] + 360.0 - a[1]; }
	if (a[2] - a[1] > 360.0 - *w) { *lo = a[2]; *w = a[1] + 360.0 - a[2]; }
	if (*w >= 180.0) { *lo = 0.0; *w = 360.0; }  /* no short arc: all of them */
}

/* Mark the regions that patch abc can reach; widen *zmin, *zmax to it. */
static void mark_patch(const double *v[3], const cert_region *reg, size_t nreg, unsigned char *hit,
                       double *zmin, double *zmax)
{
	static const double pz[3] = { 0, 0, 1 }, mz[3] = { 0, 0, -1 };
	double zlo = 2, zhi = -2, plo, pw;
	size_t i, k;
	for (i = 0; i < 3; i++) {
		zlo = fmin(zlo, v[i][2]);
		zhi = fmax(zhi, v[i][2]);
		arc_z(v[i], v[(i + 1) % 3], &zlo, &zhi);
	}
	azimuth_arc(v, &plo, &pw);
	if (inside(v, pz)) { zhi = 1.0; plo = 0.0; pw = 360.0; }
	if (inside(v, mz)) { zlo = -1.0; plo = 0.0; pw = 360.0; }
	zlo -= 1e-5; zhi += 1e-5; plo -= 1e-4; pw += 2e-4;   /* the arithmetic above, the rounded n */
	*zmin = fmin(*zmin, zlo);
	*zmax = fmax(*zmax, zhi);
	for (k = 0; k < nreg; k++) {
		const cert_region *r = &reg[k];
		double d = fmod(r->phi_lo - plo + 720.0, 360.0);   /* sector start, from the arc's start */
		if (r->nz_hi < zlo || r->nz_lo > zhi)
			continue;
		if (pw >= 360.0 || d <= pw || d + (r->phi_hi - r->phi_lo) >= 360.0)
			hit[k] = 1;
	}
}

/* The patches of the scene, with the --up permutation applied. */
static int mark_scene(const char *path, char up, const cert_region *reg, size_t nreg, unsigned char *hit, size_t *npatch,
                      double *zmin, double *zmax)
{
	mesh_normals mn;
	mesh_geom g;
	char err[512];
	size_t t, i;
	double *n;
	memset(&g, 0, sizeof g);
	if (mesh_read_geom_file(path, &mn, &g, err, sizeof err) != 0) {
		fprintf(stderr, "onbstudy scene --certify: %s\n", err);
		return -1;
	}
	n = malloc((g.nnormals + mn.count + 1) * 3 * sizeof *n);
	if (!n) {
		mesh_geom_free(&g);
		mesh_free(&mn);
		return -1;
	}
	for (i = 0; i < g.nnormals + mn.count; i++) {
		const double *s = i < g.nnormals ? &g.nrm[3 * i] : NULL;
		double x = s ? s[0] : mn.x[i - g.nnormals], y = s ? s[1] : mn.y[i - g.nnormals], z = s ? s[2] : mn.z[i - g.nnormals];
		double *p = &n[3 * i];
		if (up == 'y') { p[0] = z; p[1] = x; p[2] = y; }
		else if (up == 'x') { p[0] = y; p[1] = z; p[2] = x; }
		else { p[0] = x; p[1] = y; p[2] = z; }
		if (!(isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2])) || (p[0] == 0 && p[1] == 0 && p[2] == 0))
			p[0] = p[1] = 0, p[2] = 1;   /* degenerate: the renderer falls back; counted below */
		unit(p);
	}
	*npatch = 0;
	for (t = 0; t < g.ntris; t++) {
		const double *v[3];
		if (g.tri_n[3 * t] == MESH_NO_NORMAL || g.tri_n[3 * t + 1] == MESH_NO_NORMAL || g.tri_n[3 * t + 2] == MESH_NO_NORMAL)
			continue;
		for (i = 0; i < 3; i++)
			v[i] = &n[3 * (size_t)g.tri_n[3 * t + i]];
		mark_patch(v, reg, nreg, hit, zmin, zmax);
		(*npatch)++;
	}
	if (*npatch == 0)   /* no shading patches: the stored normals themselves */
		for (i = 0; i < mn.count; i++) {
			const double *v[3];
			v[0] = v[1] = v[2] = &n[3 * (g.nnormals + i)];
			mark_patch(v, reg, nreg, hit, zmin, zmax);
			(*npatch)++;
		}
	free(n);
	mesh_geom_free(&g);
	mesh_free(&mn);
	return 0;
}

typedef struct {
	double bound, found;
	int singular, budget;
} scene_bound;

/* Certify the hit regions of every method, in parallel. */
static int certify_hits(const onb_method *ms, size_t nm, int prec, const cert_region *reg, size_t nreg,
                        const unsigned char *hit, const cert_opts *o, scene_bound *sb)
{
	study_kernel ks[STUDY_MAX_KERNELS];
	int fail = 0;
	long t, nt = (long)(nm * nreg);
	size_t i;
	if (nm > STUDY_MAX_KERNELS)
		return -1;
	for (i = 0; i < nm; i++)
		if (kernels_select(ms[i].name, 0, &ks[i], 1) != 1)
			return -1;
	memset(sb, 0, nm * sizeof *sb);
#pragma omp parallel
	{
		cert_ctx *x = cert_ctx_new();
		if (!x) {
#pragma omp atomic write
			fail = 1;
		}
#pragma omp for schedule(dynamic, 1)
		for (t = 0; t < nt; t++) {
			size_t k = (size_t)t / nreg, r = (size_t)t % nreg;
			const cm_method *m = cm_find(ms[k].name);
			cert_result res;
			if (!x || !hit[r] || !m)
				continue;
			cert_region_run(x, &ks[k], m, prec, &reg[r], o, &res);
#pragma omp critical(scene_cert)
			{
				if (!(res.bound <= sb[k].bound)) sb[k].bound = res.bound;
				if (res.found > sb[k].found) sb[k].found = res.found;
				sb[k].singular |= res.status == CERT_SINGULAR;
				sb[k].budget |= res.status == CERT_BUDGET;
			}
		}
		cert_ctx_free(x);
	}
	return fail ? -1 : 0;
}

static int scene_certify_half(const char *path, char up, double E, const onb_method *ms, size_t nm,
                              const double *measured, const char *recommended, double *proven);

int scene_certify(const char *path, char up, int prec, double E, const onb_method *ms, size_t nm,
                  const double *measured, const char *recommended, double *proven)
{
	static cert_region reg[MAXREG];
	unsigned char hit[MAXREG];
	scene_bound *sb = calloc(nm ? nm : 1, sizeof *sb);
	size_t nreg = regions_default(prec, 8, reg, MAXREG), i, nhit = 0, npatch = 0;
	cert_opts o = { 60, 150, 1.25, 0.0, 1, NULL, NULL, NULL, 0, NULL };
	double zmin = 2.0, zmax = -2.0;
	if (prec == PREC_HALF) {
		free(sb);
		return scene_certify_half(path, up, E, ms, nm, measured, recommended, proven);
	}
	o.tolerance = prec == PREC_FLOAT ? 0x1p-22 : 0x1p-51;   /* 4 ulps of 1: the renderer's normalization */
	memset(hit, 0, sizeof hit);
	if (!sb || mark_scene(path, up, reg, nreg, hit, &npatch, &zmin, &zmax) != 0) {
		free(sb);
		return -1;
	}
	for (i = 0; i < nreg; i++) {   /* the bands, cut to the n.z the scene reaches */
		reg[i].nz_lo = fmax(reg[i].nz_lo, zmin);
		reg[i].nz_hi = fmin(reg[i].nz_hi, zmax);
		hit[i] &= reg[i].nz_lo <= reg[i].nz_hi;
	}
	if (certify_hits(ms, nm, prec, reg, nreg, hit, &o, sb) != 0) {
		free(sb);
		return -1;
	}
	for (i = 0; i < nreg; i++)
		nhit += hit[i];
	printf("\nproven bounds for this scene (--certify): %zu shading patches (spherical triangles of the vertex normals)\n"
	       "  touch %zu of the %zu regions; domain: every %s n with | |n| - 1 | <= %.3g (the renderer's normalization)\n",
	       npatch, nhit, nreg, prec_name(prec), o.tolerance);
	printf("  %-24s %12s %12s  %s\n", "method", "proven_max", "measured", "verdict (E = tolerance)");
	for (i = 0; i < nm; i++) {
		const char *v = sb[i].singular ? "singular here: not bounded"
		              : sb[i].bound <= E ? "proven within E" : "not proven within E";
		if (!cm_find(ms[i].name))
			continue;
		proven[i] = sb[i].singular ? INFINITY : sb[i].bound;
		printf("  %-24s %12.4g %12.4g  %s\n", ms[i].name, proven[i], measured[i], v);
		if (recommended && strcmp(recommended, ms[i].name) == 0)
			nhit = (size_t)-1 - (sb[i].singular || !(sb[i].bound <= E));
	}
	if (recommended)
		printf("  recommended %s: %s\n", recommended, nhit == (size_t)-1 ? "proven within E on every normal a renderer can interpolate here"
		                                                          : "NOT proven within E on this scene's interpolated normals");
	free(sb);
	return 0;
}

/* ------------------------------------------------------------------ */
/* binary16: the committed proof                                       */
/* ------------------------------------------------------------------ */

#define HALF_CERT "results/half/certify/certify-half.csv"

typedef struct {
	char method[64];
	int region, proven;   /* index into the regions; status proven */
	double bound;
	char status[16];
} half_row;

typedef struct {
	half_row *rows;
	size_t nrows, nreg;
	cert_region reg[MAXREG];
	char path[4096], rev[128];
} half_cert;

/* The committed file beside the executable, else in the working directory. */
static int half_cert_path(char *buf, size_t n)
{
	char exe[4096];
	ssize_t l = readlink("/proc/self/exe", exe, sizeof exe - 1);
	char *sl;
	if (l > 0) {
		exe[l] = '\0';
		if ((sl = strrchr(exe, '/')) != NULL) {
			*sl = '\0';
			if ((size_t)snprintf(buf, n, "%s/%s", exe, HALF_CERT) < n && access(buf, R_OK) == 0)
				return 0;
		}
	}
	snprintf(buf, n, "%s", HALF_CERT);
	return access(buf, R_OK) == 0 ? 0 : -1;
}

/* The region of a row: an existing one, or a new one (-1: too many). */
static int half_region(half_cert *h, const cert_region *r)
{
	size_t k;
	for (k = 0; k < h->nreg; k++)
		if (!memcmp(&h->reg[k], r, sizeof *r))
			return (int)k;
	if (h->nreg == MAXREG)
		return -1;
	h->reg[h->nreg] = *r;
	return (int)h->nreg++;
}

/* One data line into a row; 0, or -1 when it is malformed. */
static int half_line(half_cert *h, char **f, int n, const int *c, half_row *w)
{
	cert_region r;
	char *e[5];
	if (n <= c[7] || strcmp(f[c[1]], "half") != 0)
		return -1;
	r.nz_lo = strtod(f[c[2]], &e[0]); r.nz_hi = strtod(f[c[3]], &e[1]);
	r.phi_lo = strtod(f[c[4]], &e[2]); r.phi_hi = strtod(f[c[5]], &e[3]);
	w->bound = strtod(f[c[6]], &e[4]);
	if (*e[0] || *e[1] || *e[2] || *e[3] || *e[4] || !(r.nz_lo <= r.nz_hi) || !(r.phi_lo < r.phi_hi))
		return -1;
	snprintf(w->method, sizeof w->method, "%s", f[c[0]]);
	snprintf(w->status, sizeof w->status, "%s", f[c[7]]);
	w->proven = strcmp(w->status, "proven") == 0 && isfinite(w->bound);
	return (w->region = half_region(h, &r)) < 0 ? -1 : 0;
}

/* Reads the committed proof; 0, or -1 after a message. */
static int half_read(half_cert *h)
{
	static const char *const names[8] = { "method", "precision", "nz_lo", "nz_hi", "phi_lo", "phi_hi", "bound", "status" };
	char line[4096], *f[64];
	int c[8], hdr = 0, n, k;
	size_t cap = 0;
	FILE *in;
	if (half_cert_path(h->path, sizeof h->path) != 0 || !(in = fopen(h->path, "r"))) {
		fprintf(stderr, "onbstudy scene --certify --precision half: no readable %s (the committed proof in binary16)\n", HALF_CERT);
		return -1;
	}
	while (fgets(line, sizeof line, in)) {
		line[strcspn(line, "\r\n")] = '\0';
		if (line[0] == '#') {
			if (!h->rev[0] && !strncmp(line, "# revision: ", 12))
				snprintf(h->rev, sizeof h->rev, "%.100s", line + 12);
			continue;
		}
		n = csv_split(line, f, 64, 0);
		if (!hdr++) {
			for (k = 0; k < 8; k++)
				if ((c[k] = csv_col(f, n, names[k])) < 0)
					goto bad;
			continue;
		}
		if (h->nrows == cap) {
			half_row *w = realloc(h->rows, (cap = cap ? 2 * cap : 1024) * sizeof *w);
			if (!w)
				goto bad;
			h->rows = w;
		}
		if (half_line(h, f, n, c, &h->rows[h->nrows]) != 0)
			goto bad;
		h->nrows++;
	}
	fclose(in);
	if (h->nrows)
		return 0;
	fprintf(stderr, "onbstudy scene --certify --precision half: %s holds no rows\n", h->path);
	return -1;
bad:
	fclose(in);
	fprintf(stderr, "onbstudy scene --certify --precision half: %s: malformed after %zu rows\n", h->path, h->nrows);
	return -1;
}

/* Method name's bound over the reached regions: 0 and *found 0 when it has
   no row there, inf when a reached row is not proven (*why: its status). */
static double half_bound(const half_cert *h, const unsigned char *hit, const char *name, int *found, const char **why)
{
	double b = 0.0;
	size_t k;
	*found = 0;
	*why = NULL;
	for (k = 0; k < h->nrows; k++) {
		const half_row *w = &h->rows[k];
		if (!hit[w->region] || strcmp(w->method, name) != 0)
			continue;
		*found = 1;
		if (!w->proven) {
			b = INFINITY;
			if (!*why)
				*why = w->status;
		} else if (w->bound > b) {
			b = w->bound;
		}
	}
	return b;
}

static int scene_certify_half(const char *path, char up, double E, const onb_method *ms, size_t nm,
                              const double *measured, const char *recommended, double *proven)
{
	half_cert *h = calloc(1, sizeof *h);
	unsigned char hit[MAXREG];
	size_t i, npatch = 0, nhit = 0;
	double zmin = 2.0, zmax = -2.0;
	int rec = -1;
	memset(hit, 0, sizeof hit);
	if (!h || half_read(h) != 0 || mark_scene(path, up, h->reg, h->nreg, hit, &npatch, &zmin, &zmax) != 0) {
		if (h) free(h->rows);
		free(h);
		return -1;
	}
	for (i = 0; i < h->nreg; i++)
		nhit += hit[i];
	printf("\nproven bounds for this scene (--certify, half): %zu shading patches reach %zu of the %zu regions of the committed proof\n"
	       "  %s (revision %s; not proven anew); each bound is its rows' largest over those regions; domain: every binary16\n"
	       "  rounding of a unit vector (a mediump normalize() that lands off that set is not covered); in u = 2^-11\n",
	       npatch, nhit, h->nreg, h->path, h->rev[0] ? h->rev : "?");
	printf("  %-24s %12s %12s  %s\n", "method", "proven/u", "measured/u", "verdict (E = tolerance)");
	for (i = 0; i < nm; i++) {
		const char *why;
		int found;
		const double b = half_bound(h, hit, ms[i].name, &found, &why);
		char v[96];
		if (!found)
			continue;   /* no committed row: proven[i] stays NaN */
		proven[i] = b;
		if (why)
			snprintf(v, sizeof v, "not bounded here: a reached region is %s", why);
		else
			snprintf(v, sizeof v, "%s", b <= E ? "proven within E" : "not proven within E");
		printf("  %-24s %12.4g %12.4g  %s\n", ms[i].name, b * 0x1p11, measured[i] * 0x1p11, v);
		if (recommended && strcmp(recommended, ms[i].name) == 0)
			rec = b <= E;
	}
	if (recommended)
		printf("  recommended %s: %s\n", recommended, rec == 1 ? "proven within E on every binary16 rounding of a unit vector in the reached regions"
		       : rec == 0 ? "NOT proven within E on this scene's regions" : "no committed binary16 proof");
	free(h->rows);
	free(h);
	return 0;
}
