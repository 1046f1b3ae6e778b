/*
 * aorender.c - ambient occlusion with cosine-weighted hemisphere sampling,
 * as a renderer that links libonb.a would do it.  Links libonb.a and libm
 * (and cJSON, for the glTF part of the scene reader); writes PNG with a
 * dependency-free writer (stored deflate blocks).
 *
 *   aorender --method NAME [--precision float|double] --out FILE.png
 *            [--diff DIFF.png] [--spp N (256)] [--list]
 *            [--brushed FILE.dat] (the brushed-metal highlight, below)
 *            [--mesh FILE [--up z|y|x] [--no-renormalize]]
 *
 * --mesh (or --obj) renders a mesh read by the scene reader: OBJ, PLY or
 * glTF 2.0, told by content (the files of src/mesh/, compiled
 * into this program; the same reader as `onbstudy scene`) instead of the
 * scene below; see "--obj" further down for the camera, the shading
 * normals, the hidden floor and the reference of --diff (there: the
 * method's own frame made exact, not duff_branchless).  Bad input (a
 * missing or malformed file) exits 2 with one line on stderr.
 *
 * Scene (z up), built so that only the basis can change the picture.  A
 * floor z = 0 (normal exactly +z) under a ceiling 1.4 above it: the
 * underside of a sphere of radius 400 (a shallow dome whose normals come
 * within 1 + n.z <= 3.8e-6 of -z), which meets a flat ceiling (normal
 * exactly -z) at rho = 1.1 from the dome's lowest point.  The camera, 1.2 below the dome's lowest point, looks
 * straight up: the image is the dome (centre), the flat ceiling (corners).
 * At each hit the basis {b1, b2} of the method turns a cosine-weighted
 * local direction (r cos phi, r sin phi, sqrt(1 - u)) into
 * w = b1 x + b2 y + n z; the pixel is the fraction of such rays that
 * travel a distance 2 without hitting anything.  The floor lies right at
 * that horizon (cos theta = 0.7, where the estimate is most sensitive to
 * the distribution of cos theta), and seen from every ceiling point it is
 * the same within the dome's tilt (< 2.8e-3 rad): a correct frame only
 * rotates the samples about n, so it changes almost no sample's outcome,
 * and the difference to the reference is a faint noise (mean ~0.001).
 * A frame that is not orthonormal changes the distribution of cos theta
 * around each normal, and the difference shows where: float frisvad in a
 * ring (its formula with 1 + n.z = 4..16 float ulps, whose rounding is an
 * O(1/k) relative error), tangent_cross_z on the flat ceiling (NaN at
 * n = -z exactly, drawn black).  The ring is speckled with moire rings:
 * the sign of frisvad's error is that of the rounding of n.z to float.
 *
 * --diff renders the reference (duff_branchless in double, the same
 * random numbers) and writes |image - reference| on a colour scale from
 * black (0) through blue and red to yellow (DIFF_MAX = 0.05 or more),
 * NaN in a colour of its own (cyan), with the scale as a bar under the
 * image, numbered 0, 0.025 and >=0.05, a cyan swatch named NaN, and a line
 * naming the quantity and its largest value ("|image - double reference|:
 * max 0.156"; with --obj "|image - exact frame|";
 * "max 0" when the images are identical), in a 5x7 font drawn 2x.
 * Both images are written UP (3) times their size, nearest-neighbour,
 * so that each rendered pixel stays one visible square.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include "libonb/onb.h"
#include "mesh/meshio.h"

#define W 160
#define H 120
#define UP 3       /* the written images: UP x UP pixels per rendered pixel */
#define STRIP 58   /* the written diff image's legend strip, in its pixels */

/* ---- PNG: zlib stored blocks, crc32, adler32 ---- */
static unsigned long crc_table[256];
static void crc_init(void)
{
	unsigned long c;
	int n, k;
	for (n = 0; n < 256; n++) {
		c = (unsigned long)n;
		for (k = 0; k < 8; k++)
			c = c & 1 ? 0xedb88320UL ^ (c >> 1) : c >> 1;
		crc_table[n] = c;
	}
}
static unsigned long crc(unsigned long c, const unsigned char *b, size_t n)
{
	size_t i;
	c ^= 0xffffffffUL;
	for (i = 0; i < n; i++)
		c = crc_table[(c ^ b[i]) & 0xff] ^ (c >> 8);
	return c ^ 0xffffffffUL;
}
static void be32(unsigned char *p, unsigned long v)
{
	p[0] = (unsigned char)(v >> 24); p[1] = (unsigned char)(v >> 16); p[2] = (unsigned char)(v >> 8); p[3] = (unsigned char)v;
}
static int chunk(FILE *f, const char *type, const unsigned char *d, size_t n)
{
	unsigned char h[8], t[4];
	unsigned long c;
	be32(h, (unsigned long)n);
	memcpy(h + 4, type, 4);
	c = crc(0, h + 4, 4);
	c = crc(c ^ 0, d, n); /* crc continues over the data */
	be32(t, c);
	return fwrite(h, 1, 8, f) != 8 || (n && fwrite(d, 1, n, f) != n) || fwrite(t, 1, 4, f) != 4;
}
/* pix: w*h*ch bytes, ch 1 (grey, or palette indices when plte is given:
   256 RGB entries) or 3 (RGB).  The deflate blocks are stored, not
   compressed, so palette images are a third of the size of RGB ones. */
static int write_png(const char *path, const unsigned char *rgb, int w, int h, int ch, const unsigned char *plte)
{
	size_t raw_n = (size_t)h * (size_t)(1 + ch * w), nblk = (raw_n + 65534) / 65535, i, z = 0;
	unsigned char *raw = malloc(raw_n), *zb = malloc(2 + raw_n + 5 * nblk + 4), hdr[13];
	unsigned long a = 1, b = 0;
	FILE *f;
	int y, bad;
	if (!raw || !zb) { free(raw); free(zb); return -1; }
	for (y = 0; y < h; y++) {
		raw[(size_t)y * (size_t)(1 + ch * w)] = 0; /* filter: none */
		memcpy(raw + (size_t)y * (size_t)(1 + ch * w) + 1, rgb + (size_t)y * (size_t)(w * ch), (size_t)(w * ch));
	}
	zb[z++] = 0x78; zb[z++] = 0x01; /* zlib, deflate, no dictionary */
	for (i = 0; i < raw_n; i += 65535) {
		size_t n = raw_n - i < 65535 ? raw_n - i : 65535;
		zb[z++] = i + n == raw_n; /* BFINAL, BTYPE 00 stored */
		zb[z++] = (unsigned char)n; zb[z++] = (unsigned char)(n >> 8);
		zb[z++] = (unsigned char)~n; zb[z++] = (unsigned char)(~n >> 8);
		memcpy(zb + z, raw + i, n);
		z += n;
	}
	for (i = 0; i < raw_n; i++) { a = (a + raw[i]) % 65521; b = (b + a) % 65521; }
	be32(zb + z, (b << 16) | a);
	z += 4;
	be32(hdr, (unsigned long)w); be32(hdr + 4, (unsigned long)h);
	hdr[8] = 8; hdr[9] = ch == 3 ? 2 : plte ? 3 : 0; hdr[10] = 0; hdr[11] = 0; hdr[12] = 0; /* 8-bit RGB, palette or grey */
	f = fopen(path, "wb");
	if (!f) { free(raw); free(zb); return -1; }
	bad = fwrite("\x89PNG\r\n\x1a\n", 1, 8, f) != 8;
	bad |= chunk(f, "IHDR", hdr, 13);
	if (plte && ch == 1)
		bad |= chunk(f, "PLTE", plte, 768);
	bad |= chunk(f, "IDAT", zb, z);
	bad |= chunk(f, "IEND", NULL, 0);
	bad |= fclose(f) != 0;
	free(raw); free(zb);
	return bad ? -1 : 0;
}

/* ---- scene ---- */
typedef struct { double x, y, z; } v3;
static v3 add(v3 a, v3 b) { v3 r; r.x = a.x + b.x; r.y = a.y + b.y; r.z = a.z + b.z; return r; }
static v3 mul(v3 a, double s) { v3 r; r.x = a.x * s; r.y = a.y * s; r.z = a.z * s; return r; }
static double dot(v3 a, v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static v3 norm(v3 a) { return mul(a, 1.0 / sqrt(dot(a, a))); }

/* The dome is the underside of a sphere of radius R whose lowest point is
   at height HC above the floor z = 0.  At horizontal distance rho from
   that point its normal has 1 + n.z = rho^2 / (2 R^2) (to first order):
   with R = 400 and the dome ending at RHO_FLAT = 1.1, 1 + n.z runs from 0
   to 3.8e-6 (63 float ulps of -1).  Float frisvad keeps its fallback
   below 4 ulps (rho < 0.28) and runs its formula above, with a relative
   error in a = 1/(1 + n.z) of up to half an ulp over 1 + n.z: 12% at
   4 ulps, 3% at 16 ulps (rho = 0.55).  HC = 1.4 and AO_DIST = 2 put the
   floor at the occlusion horizon cos(theta) = 0.7 of a ceiling point
   (u = cos^2 = 0.49, where the estimate is most sensitive), and the
   ceiling at the same horizon for a floor point. */
#define R 400.0
#define HC 1.4
#define RHO_FLAT 1.1 /* the dome meets the flat ceiling there */
#define CEIL (HC + RHO_FLAT * RHO_FLAT / (2 * R))
#define EXTENT 50.0
#define AO_DIST 2.0
#define DIFF_MAX 0.05 /* top of the difference colour scale */
#define MESH_AO 0.3   /* --obj: AO distance, in bounding-sphere radii */
#define MESH_FLOOR 0.1 /* --obj: the hidden floor, this far below the mesh */
static const v3 C = { 0.0, 0.0, HC + R };

/* Nearest hit with t in (1e-6, tmax); fills point and unit normal. */
static int hit(v3 o, v3 d, double tmax, double *t, v3 *p, v3 *n)
{
	double best = tmax;
	int any = 0;
	v3 oc = add(o, mul(C, -1.0));
	/* |oc|^2 - R^2 = (|oc| - R)(|oc| + R) loses nothing that matters here:
	   its absolute error is ~ R^2 eps = 3e-11 */
	double dd = dot(d, d), bq = dot(oc, d), cq = dot(oc, oc) - R * R, disc = bq * bq - dd * cq;
	if (disc >= 0) {
		/* stable roots: q = -(b + sign(b) sqrt(disc)); t = c/q and q/dd */
		double q = -(bq + (bq >= 0 ? sqrt(disc) : -sqrt(disc))), t0 = q != 0 ? cq / q : -1, t1 = q / dd, tt;
		if (t0 > t1) { tt = t0; t0 = t1; t1 = tt; }
		tt = t0 > 1e-6 ? t0 : t1;
		if (tt > 1e-6 && tt < best) {
			best = tt; any = 1;
			*p = add(o, mul(d, tt));
			*n = mul(add(*p, mul(C, -1.0)), 1.0 / R);
			*n = norm(*n);
		}
	}
	if (d.z != 0) { /* the floor z = 0 (normal +z) and the flat ceiling (normal -z) */
		static const double pz[2] = { 0.0, CEIL }, nz[2] = { 1.0, -1.0 };
		int k;
		for (k = 0; k < 2; k++) {
			double tc = (pz[k] - o.z) / d.z;
			if (tc > 1e-6 && tc < best) {
				v3 q = add(o, mul(d, tc));
				if (fabs(q.x) < EXTENT && fabs(q.y) < EXTENT) {
					best = tc; any = 1;
					*p = q;
					n->x = 0; n->y = 0; n->z = nz[k];
				}
			}
		}
	}
	*t = best;
	return any;
}

static unsigned long long mix(unsigned long long x)
{
	x ^= x >> 30; x *= 0xbf58476d1ce4e5b9ULL;
	x ^= x >> 27; x *= 0x94d049bb133111ebULL;
	return x ^ (x >> 31);
}
static double u01(unsigned long long *s) { *s = mix(*s + 0x9e3779b97f4a7c15ULL); return (double)(*s >> 11) * 0x1p-53; }

/* The cosine-weighted local direction (lx, ly, lz) turned into the world
   by the method's frame around n: w = b1 lx + b2 ly + n lz, in float
   (fl: n and the local direction rounded to float first) or double. */
static v3 frame_dir(const onb_method *m, int fl, v3 n, double lx, double ly, double lz)
{
	v3 w;
	if (fl) {
		onb_vec3f nf, b1, b2;
		float fx = (float)lx, fy = (float)ly, fz = (float)lz;
		nf.x = (float)n.x; nf.y = (float)n.y; nf.z = (float)n.z;
		m->basisf(nf, &b1, &b2);
		w.x = b1.x * fx + b2.x * fy + nf.x * fz;
		w.y = b1.y * fx + b2.y * fy + nf.y * fz;
		w.z = b1.z * fx + b2.z * fy + nf.z * fz;
	} else {
		onb_vec3 nd, b1, b2;
		nd.x = n.x; nd.y = n.y; nd.z = n.z;
		m->basis(nd, &b1, &b2);
		w.x = b1.x * lx + b2.x * ly + nd.x * lz;
		w.y = b1.y * lx + b2.y * ly + nd.y * lz;
		w.z = b1.z * lx + b2.z * ly + nd.z * lz;
	}
	return w;
}

static void render(const onb_method *m, int fl, int spp, double *img)
{
	const v3 eye = { 0.0, 0.0, 0.2 }, at = { 0.0, 0.0, 1.4 }, upv = { 0, 1, 0 };
	v3 fw = norm(add(at, mul(eye, -1.0))), rt, up;
	int x, y, s;
	rt.x = fw.y * upv.z - fw.z * upv.y; rt.y = fw.z * upv.x - fw.x * upv.z; rt.z = fw.x * upv.y - fw.y * upv.x;
	rt = norm(rt);
	up.x = rt.y * fw.z - rt.z * fw.y; up.y = rt.z * fw.x - rt.x * fw.z; up.z = rt.x * fw.y - rt.y * fw.x;
	for (y = 0; y < H; y++)
		for (x = 0; x < W; x++) {
			double sx = (2.0 * (x + 0.5) / W - 1.0) * 0.75 * W / H, sy = (1.0 - 2.0 * (y + 0.5) / H) * 0.75, t, sum = 0;
			v3 d = norm(add(fw, add(mul(rt, sx), mul(up, sy)))), p, n;
			unsigned long long seed = mix((unsigned long long)(y * W + x) + 12345);
			if (!hit(eye, d, 1e30, &t, &p, &n)) {
				img[y * W + x] = 0.75;
				continue;
			}
			for (s = 0; s < spp; s++) {
				double u1 = u01(&seed), u2 = u01(&seed), r = sqrt(u1), ph = 2.0 * 3.14159265358979323846 * u2;
				double lx = r * cos(ph), ly = r * sin(ph), lz = sqrt(1.0 - u1), tt;
				v3 w = frame_dir(m, fl, n, lx, ly, lz), pp, nn, o;
				if (!isfinite(w.x) || !isfinite(w.y) || !isfinite(w.z)) {
					sum = NAN;
					continue;
				}
				/* AO_DIST is a distance: trace the unit direction.  (Tracing w
				   as it is would also scale the AO distance by |w|, which for a
				   stretched frame partly cancels the change of direction.) */
				o = add(p, mul(n, 1e-4));
				if (dot(w, w) > 0 && !hit(o, norm(w), AO_DIST, &tt, &pp, &nn))
					sum += 1.0;
			}
			img[y * W + x] = sum / spp;
		}
}

/* ---- --obj: a mesh from the scene reader (src/mesh/) ----
   The file's positions and normals are turned so that the --up axis is z
   (the cyclic permutation of `onbstudy scene`: y: (x,y,z) -> (z,x,y),
   x: (x,y,z) -> (y,z,x)), so the normals the method sees have that axis
   as n.z.  The camera sits below and to the side of the bounding box's
   centre, looking at it, far enough for the bounding sphere to fit the
   view: the undersides (normals near -z) face it.  Triangles are found
   through a bounding volume hierarchy (median splits, up to 4 triangles
   a leaf) and intersected with Moller-Trumbore in double.  The shading
   normal at a hit is the barycentric blend of the corners' normals from
   the file, renormalized (or, --no-renormalize, passed to the method as
   it is); a triangle with a corner without a normal is shaded with its
   flat face normal.  A floor MESH_FLOOR radii below the mesh occludes the
   AO rays but not the camera's: it gives the undersides, where normals
   come near -z, a horizon within reach, as the default scene's floor
   gives its ceiling, so that a frame that is not orthonormal there
   changes the picture. */
/* a leaf has count > 0 triangles tid[first ..]; an inner node, children */
typedef struct { double lo[3], hi[3]; size_t first, count, left, right; } bnode;
typedef struct {
	const mesh_geom *g;
	double *P, *N;          /* turned positions and normals                 */
	size_t *tid;            /* triangle order of the leaves                 */
	bnode *node;
	size_t nnode;
	double ao_dist, eps, floor_z;
	v3 eye, fw, rt, up;
	int renorm;
} mscene;

static const double *g_cen; /* centroids, for the qsort comparator */
static int g_axis;
static int cmp_cen(const void *a, const void *b)
{
	double x = g_cen[3 * *(const size_t *)a + g_axis], y = g_cen[3 * *(const size_t *)b + g_axis];
	return (x > y) - (x < y);
}

static size_t bvh_build(mscene *s, const double *cen, size_t first, size_t count)
{
	size_t me = s->nnode++, i, k;
	bnode *nd = &s->node[me];
	double clo[3], chi[3];
	int a;
	for (a = 0; a < 3; a++) {
		nd->lo[a] = clo[a] = INFINITY;
		nd->hi[a] = chi[a] = -INFINITY;
	}
	for (i = first; i < first + count; i++) {
		const uint32_t *t = s->g->tri + 3 * s->tid[i];
		for (k = 0; k < 3; k++)
			for (a = 0; a < 3; a++) {
				double v = s->P[3 * t[k] + a];
				if (v < nd->lo[a]) nd->lo[a] = v;
				if (v > nd->hi[a]) nd->hi[a] = v;
			}
		for (a = 0; a < 3; a++) {
			double v = cen[3 * s->tid[i] + a];
			if (v < clo[a]) clo[a] = v;
			if (v > chi[a]) chi[a] = v;
		}
	}
	nd->first = first;
	nd->count = count;
	nd->left = nd->right = 0;
	if (count > 4) {
		size_t half = count / 2, l, r;
		g_axis = chi[1] - clo[1] > chi[0] - clo[0] ? 1 : 0;
		if (chi[2] - clo[2] > chi[g_axis] - clo[g_axis])
			g_axis = 2;
		g_cen = cen;
		qsort(s->tid + first, count, sizeof *s->tid, cmp_cen);
		l = bvh_build(s, cen, first, half);
		r = bvh_build(s, cen, first + half, count - half);
		s->node[me].left = l; /* s->node is never reallocated: nd stays valid, */
		s->node[me].right = r; /* but say which node is meant */
		s->node[me].count = 0;
	}
	return me;
}

static int box_hit(const bnode *nd, v3 o, v3 inv, double tmax)
{
	double t0 = 0, t1 = tmax, oo[3], ii[3];
	int a;
	oo[0] = o.x; oo[1] = o.y; oo[2] = o.z;
	ii[0] = inv.x; ii[1] = inv.y; ii[2] = inv.z;
	for (a = 0; a < 3; a++) {
		double ta = (nd->lo[a] - oo[a]) * ii[a], tb = (nd->hi[a] - oo[a]) * ii[a];
		if (ta > tb) { double tt = ta; ta = tb; tb = tt; }
		if (ta > t0) t0 = ta; /* NaN (0 * inf) leaves the bound as it was */
		if (tb < t1) t1 = tb;
		if (t0 > t1)
			return 0;
	}
	return 1;
}

/* Moller-Trumbore: t in (tmin, *t), barycentrics (u, v) of corners 1, 2. */
static int tri_hit(const mscene *s, size_t ti, v3 o, v3 d, double *t, double *u, double *v)
{
	const uint32_t *c = s->g->tri + 3 * ti;
	const double *a = s->P + 3 * c[0], *b = s->P + 3 * c[1], *e = s->P + 3 * c[2];
	double e1[3], e2[3], pv[3], tv[3], qv[3], det, inv, uu, vv, tt;
	int k;
	for (k = 0; k < 3; k++) { e1[k] = b[k] - a[k]; e2[k] = e[k] - a[k]; }
	pv[0] = d.y * e2[2] - d.z * e2[1]; pv[1] = d.z * e2[0] - d.x * e2[2]; pv[2] = d.x * e2[1] - d.y * e2[0];
	det = e1[0] * pv[0] + e1[1] * pv[1] + e1[2] * pv[2];
	if (det == 0 || !isfinite(det))
		return 0;
	inv = 1.0 / det;
	tv[0] = o.x - a[0]; tv[1] = o.y - a[1]; tv[2] = o.z - a[2];
	uu = (tv[0] * pv[0] + tv[1] * pv[1] + tv[2] * pv[2]) * inv;
	if (uu < 0 || uu > 1)
		return 0;
	qv[0] = tv[1] * e1[2] - tv[2] * e1[1]; qv[1] = tv[2] * e1[0] - tv[0] * e1[2]; qv[2] = tv[0] * e1[1] - tv[1] * e1[0];
	vv = (d.x * qv[0] + d.y * qv[1] + d.z * qv[2]) * inv;
	if (vv < 0 || uu + vv > 1)
		return 0;
	tt = (e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2]) * inv;
	if (!(tt > s->eps * 1e-3 && tt < *t))
		return 0;
	*t = tt; *u = uu; *v = vv;
	return 1;
}

/* Nearest hit (any = 0) or any hit (any = 1) with t < tmax. */
static int mesh_hit(const mscene *s, v3 o, v3 d, double tmax, int any, double *t, size_t *ti, double *u, double *v)
{
	size_t stack[128], sp = 0;
	v3 inv;
	int found = 0;
	inv.x = 1.0 / d.x; inv.y = 1.0 / d.y; inv.z = 1.0 / d.z;
	*t = tmax;
	stack[sp++] = 0;
	while (sp) {
		const bnode *nd = &s->node[stack[--sp]];
		if (!box_hit(nd, o, inv, *t))
			continue;
		if (nd->count) {
			size_t i;
			for (i = nd->first; i < nd->first + nd->count; i++)
				if (tri_hit(s, s->tid[i], o, d, t, u, v)) {
					*ti = s->tid[i];
					found = 1;
					if (any)
						return 1;
				}
		} else if (sp + 2 <= sizeof stack / sizeof stack[0]) {
			stack[sp++] = nd->right;
			stack[sp++] = nd->left;
		}
	}
	return found;
}

static void turn(char up, const double *in, double *out)
{
	double x = in[0], y = in[1], z = in[2];
	if (up == 'y') { out[0] = z; out[1] = x; out[2] = y; }
	else if (up == 'x') { out[0] = y; out[1] = z; out[2] = x; }
	else { out[0] = x; out[1] = y; out[2] = z; }
}

/* Builds the scene; 0, or -1 with a message in err. */
static int mscene_init(mscene *s, const mesh_geom *g, char up, int renorm, char *err, size_t errlen)
{
	double *cen, lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY }, r, dist;
	size_t i;
	int a, k;
	v3 c, dir, wup = { 0.0, 0.0, 1.0 };
	memset(s, 0, sizeof *s);
	s->g = g;
	s->renorm = renorm;
	if (g->ntris == 0) {
		snprintf(err, errlen, "no faces to render (%zu vertices)", g->nverts);
		return -1;
	}
	s->P = malloc(3 * g->nverts * sizeof *s->P);
	s->N = malloc(3 * (g->nnormals ? g->nnormals : 1) * sizeof *s->N);
	s->tid = malloc(g->ntris * sizeof *s->tid);
	s->node = malloc(2 * g->ntris * sizeof *s->node); /* at most 2n - 1 nodes */
	cen = malloc(3 * g->ntris * sizeof *cen);
	if (!s->P || !s->N || !s->tid || !s->node || !cen) {
		free(cen);
		snprintf(err, errlen, "out of memory for %zu triangles", g->ntris);
		return -1;
	}
	for (i = 0; i < g->nverts; i++)
		turn(up, g->pos + 3 * i, s->P + 3 * i);
	for (i = 0; i < g->nnormals; i++)
		turn(up, g->nrm + 3 * i, s->N + 3 * i);
	for (i = 0; i < g->ntris; i++) {
		s->tid[i] = i;
		for (a = 0; a < 3; a++)
			cen[3 * i + a] = 0;
		for (k = 0; k < 3; k++) {
			const double *p = s->P + 3 * g->tri[3 * i + k];
			for (a = 0; a < 3; a++) {
				if (!isfinite(p[a])) {
					free(cen);
					snprintf(err, errlen, "line %llu: a face uses a vertex with a non-finite coordinate",
					         (unsigned long long)g->tri_line[i]);
					return -1;
				}
				cen[3 * i + a] += p[a] / 3;
				if (p[a] < lo[a]) lo[a] = p[a];
				if (p[a] > hi[a]) hi[a] = p[a];
			}
		}
	}
	bvh_build(s, cen, 0, g->ntris);
	free(cen);
	c.x = (lo[0] + hi[0]) / 2; c.y = (lo[1] + hi[1]) / 2; c.z = (lo[2] + hi[2]) / 2;
	r = 0.5 * sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
	if (!(r > 0) || !isfinite(r)) {
		snprintf(err, errlen, "the faces span no volume or area (bounding box radius %g)", r);
		return -1;
	}
	/* from below and to the side, towards the centre; the distance puts
	   every corner of the box inside the view (half-angles: tan 1.0
	   across, 0.75 up) with a 5% margin */
	dir.x = 0.55; dir.y = -0.7; dir.z = -0.45;
	s->fw = norm(mul(dir, -1.0));
	s->rt.x = s->fw.y * wup.z - s->fw.z * wup.y; s->rt.y = s->fw.z * wup.x - s->fw.x * wup.z; s->rt.z = s->fw.x * wup.y - s->fw.y * wup.x;
	s->rt = norm(s->rt);
	s->up.x = s->rt.y * s->fw.z - s->rt.z * s->fw.y; s->up.y = s->rt.z * s->fw.x - s->rt.x * s->fw.z; s->up.z = s->rt.x * s->fw.y - s->rt.y * s->fw.x;
	dist = 0;
	for (k = 0; k < 8; k++) {
		v3 q;
		double ahead, need;
		q.x = (k & 1 ? hi[0] : lo[0]) - c.x; q.y = (k & 2 ? hi[1] : lo[1]) - c.y; q.z = (k & 4 ? hi[2] : lo[2]) - c.z;
		ahead = dot(q, s->fw);
		need = fabs(dot(q, s->rt)) * H / (0.75 * W);
		if (fabs(dot(q, s->up)) / 0.75 > need)
			need = fabs(dot(q, s->up)) / 0.75;
		need = 1.05 * need - ahead;
		if (need > dist)
			dist = need;
	}
	s->eye = add(c, mul(s->fw, -dist));
	s->ao_dist = MESH_AO * r;
	s->floor_z = lo[2] - MESH_FLOOR * r;
	s->eps = 1e-6 * r;
	return 0;
}

static void mscene_free(mscene *s)
{
	free(s->P); free(s->N); free(s->tid); free(s->node);
	memset(s, 0, sizeof *s);
}

/* The reference of --obj --diff: the method's own frame made exact.  A
   correct frame may be any rotation of another about n, and on a mesh
   (unlike the default scene) a rotation changes which samples are
   occluded: against duff_branchless every method would differ by noise.
   So the reference keeps the method's orientation and drops its error:
   nh = n / |n|, b1' = b1 - (b1.nh) nh normalized, b2' = +-nh x b1' (the
   sign of the method's b2), all in double; where b1 is not finite or
   parallel to n, duff_branchless's frame in double.  The difference then
   shows only what the method's frame (and, with --no-renormalize, a
   non-unit n) costs. */
static v3 frame_dir_exact(const onb_method *m, int fl, v3 n, double lx, double ly, double lz)
{
	v3 b1, b2, nh, c, w;
	double l = sqrt(dot(n, n)), k;
	nh = mul(n, 1.0 / l);
	if (fl) {
		onb_vec3f nf, f1, f2;
		nf.x = (float)n.x; nf.y = (float)n.y; nf.z = (float)n.z;
		m->basisf(nf, &f1, &f2);
		b1.x = f1.x; b1.y = f1.y; b1.z = f1.z;
		b2.x = f2.x; b2.y = f2.y; b2.z = f2.z;
	} else {
		onb_vec3 nd, d1, d2;
		nd.x = n.x; nd.y = n.y; nd.z = n.z;
		m->basis(nd, &d1, &d2);
		b1.x = d1.x; b1.y = d1.y; b1.z = d1.z;
		b2.x = d2.x; b2.y = d2.y; b2.z = d2.z;
	}
	b1 = add(b1, mul(nh, -dot(b1, nh)));
	k = sqrt(dot(b1, b1));
	if (!(k > 1e-3) || !isfinite(k)) {
		onb_vec3 nd, d1, d2;
		nd.x = nh.x; nd.y = nh.y; nd.z = nh.z;
		onb_find("duff_branchless")->basis(nd, &d1, &d2);
		b1.x = d1.x; b1.y = d1.y; b1.z = d1.z;
		b2.x = d2.x; b2.y = d2.y; b2.z = d2.z;
	} else {
		b1 = mul(b1, 1.0 / k);
		c.x = nh.y * b1.z - nh.z * b1.y; c.y = nh.z * b1.x - nh.x * b1.z; c.z = nh.x * b1.y - nh.y * b1.x;
		b2 = dot(c, b2) < 0 ? mul(c, -1.0) : c;
	}
	w.x = b1.x * lx + b2.x * ly + nh.x * lz;
	w.y = b1.y * lx + b2.y * ly + nh.y * lz;
	w.z = b1.z * lx + b2.z * ly + nh.z * lz;
	return w;
}

/* exact: render the reference of frame_dir_exact instead */
static void render_mesh(const mscene *s, const onb_method *m, int fl, int exact, int spp, double *img)
{
	const mesh_geom *g = s->g;
	int x, y, sm;
	for (y = 0; y < H; y++)
		for (x = 0; x < W; x++) {
			double sx = (2.0 * (x + 0.5) / W - 1.0) * 0.75 * W / H, sy = (1.0 - 2.0 * (y + 0.5) / H) * 0.75, t, u, v, sum = 0, side;
			v3 d = norm(add(s->fw, add(mul(s->rt, sx), mul(s->up, sy)))), p, ng, n, e1, e2;
			unsigned long long seed = mix((unsigned long long)(y * W + x) + 12345);
			size_t ti;
			const uint32_t *c, *cn;
			if (!mesh_hit(s, s->eye, d, 1e300, 0, &t, &ti, &u, &v)) {
				img[y * W + x] = 0.75;
				continue;
			}
			c = g->tri + 3 * ti;
			cn = g->tri_n + 3 * ti;
			p = add(s->eye, mul(d, t));
			e1.x = s->P[3 * c[1]] - s->P[3 * c[0]]; e1.y = s->P[3 * c[1] + 1] - s->P[3 * c[0] + 1]; e1.z = s->P[3 * c[1] + 2] - s->P[3 * c[0] + 2];
			e2.x = s->P[3 * c[2]] - s->P[3 * c[0]]; e2.y = s->P[3 * c[2] + 1] - s->P[3 * c[0] + 1]; e2.z = s->P[3 * c[2] + 2] - s->P[3 * c[0] + 2];
			ng.x = e1.y * e2.z - e1.z * e2.y; ng.y = e1.z * e2.x - e1.x * e2.z; ng.z = e1.x * e2.y - e1.y * e2.x;
			ng = norm(ng);
			if (cn[0] != MESH_NO_NORMAL && cn[1] != MESH_NO_NORMAL && cn[2] != MESH_NO_NORMAL) {
				const double *n0 = s->N + 3 * cn[0], *n1 = s->N + 3 * cn[1], *n2 = s->N + 3 * cn[2];
				double w0 = 1 - u - v, l2;
				n.x = w0 * n0[0] + u * n1[0] + v * n2[0];
				n.y = w0 * n0[1] + u * n1[1] + v * n2[1];
				n.z = w0 * n0[2] + u * n1[2] + v * n2[2];
				l2 = dot(n, n);
				if (s->renorm && l2 > 0 && isfinite(l2))
					n = mul(n, 1.0 / sqrt(l2));
			} else
				n = ng;
			/* leave the surface on the side the shading normal faces */
			side = dot(ng, n) >= 0 ? 1.0 : -1.0;
			for (sm = 0; sm < spp; sm++) {
				double u1 = u01(&seed), u2 = u01(&seed), r = sqrt(u1), ph = 2.0 * 3.14159265358979323846 * u2;
				double lx = r * cos(ph), ly = r * sin(ph), lz = sqrt(1.0 - u1), tt, uu, vv;
				v3 w = exact ? frame_dir_exact(m, fl, n, lx, ly, lz) : frame_dir(m, fl, n, lx, ly, lz), o;
				size_t tj;
				if (!isfinite(w.x) || !isfinite(w.y) || !isfinite(w.z)) {
					sum = NAN;
					continue;
				}
				o = add(p, mul(ng, side * s->eps * 100));
				if (!(dot(w, w) > 0))
					continue;
				w = norm(w);
				if (w.z < 0 && (s->floor_z - o.z) / w.z < s->ao_dist)
					continue; /* the hidden floor */
				if (!mesh_hit(s, o, w, s->ao_dist, 1, &tt, &tj, &uu, &vv))
					sum += 1.0;
			}
			img[y * W + x] = sum / spp;
		}
}

/* The diff palette: entries 0..SCALE_N-1 the colour scale, then the
   legend's text (white) and NaN (cyan, which the scale never reaches). */
#define SCALE_N 254
#define PAL_TEXT 254
#define PAL_NAN 255
static void colour(double v, unsigned char *c)
{
	/* 0 black, 1/3 blue, 2/3 red, 1 yellow */
	double r, g, b;
	if (v > 1) v = 1;
	if (v < 1.0 / 3) { r = 0; g = 0; b = 3 * v; }
	else if (v < 2.0 / 3) { r = 3 * v - 1; g = 0; b = 2 - 3 * v; }
	else { r = 1; g = 3 * v - 2; b = 0; }
	c[0] = (unsigned char)(255 * r + 0.5); c[1] = (unsigned char)(255 * g + 0.5); c[2] = (unsigned char)(255 * b + 0.5);
}

/* the palette entry of a value of the colour scale (NaN: its own) */
static unsigned char pal_index(double v)
{
	if (!(v >= 0)) return PAL_NAN;
	if (v > 1) v = 1;
	return (unsigned char)((SCALE_N - 1) * v + 0.5);
}

/* A 5x7 pixel font for the legend (the HD44780's glyphs): the characters
   of FONT_CHARS, each 7 rows of 5 bits (most significant: left). */
static const char *const FONT_CHARS = "0123456789.>=|-:Nabcdefgilmnorstux";
static const unsigned char FONT[][7] = {
	{14, 17, 19, 21, 25, 17, 14}, {4, 12, 4, 4, 4, 4, 14}, {14, 17, 1, 2, 4, 8, 31}, {31, 2, 4, 2, 1, 17, 14},
	{2, 6, 10, 18, 31, 2, 2}, {31, 16, 30, 1, 1, 17, 14}, {6, 8, 16, 30, 17, 17, 14}, {31, 1, 2, 4, 8, 8, 8},
	{14, 17, 17, 14, 17, 17, 14}, {14, 17, 17, 15, 1, 2, 12}, {0, 0, 0, 0, 0, 12, 12}, {8, 4, 2, 1, 2, 4, 8},
	{0, 0, 31, 0, 31, 0, 0}, {4, 4, 4, 4, 4, 4, 4}, {0, 0, 0, 31, 0, 0, 0}, {0, 12, 12, 0, 12, 12, 0},
	{17, 17, 25, 21, 19, 17, 17}, {0, 0, 14, 1, 15, 17, 15}, {16, 16, 22, 25, 17, 17, 30}, {0, 0, 14, 16, 16, 17, 14}, {1, 1, 13, 19, 17, 17, 15},
	{0, 0, 14, 17, 31, 16, 14}, {6, 9, 8, 28, 8, 8, 8}, {0, 15, 17, 17, 15, 1, 14}, {4, 0, 12, 4, 4, 4, 14},
	{12, 4, 4, 4, 4, 4, 14}, {0, 0, 26, 21, 21, 17, 17}, {0, 0, 22, 25, 17, 17, 17}, {0, 0, 14, 17, 17, 17, 14},
	{0, 0, 22, 25, 16, 16, 16}, {0, 0, 14, 16, 14, 1, 30}, {8, 8, 28, 8, 8, 9, 6}, {0, 0, 17, 17, 17, 19, 13},
	{0, 0, 17, 10, 4, 10, 17}};

/* text at (x, y) of an image w wide, each font pixel s x s, in entry c
   (a space, or a character without a glyph, leaves a gap) */
static void draw_text(unsigned char *img, int w, int x, int y, int s, const char *t, unsigned char c)
{
	for (; *t; t++, x += 6 * s) {
		const char *g = strchr(FONT_CHARS, *t);
		int r, b, i, j;
		if (!g || *t == '\0') continue;
		for (r = 0; r < 7; r++)
			for (b = 0; b < 5; b++)
				if (FONT[g - FONT_CHARS][r] >> (4 - b) & 1)
					for (i = 0; i < s; i++)
						for (j = 0; j < s; j++)
							img[(size_t)(y + r * s + i) * (size_t)w + (size_t)(x + b * s + j)] = c;
	}
}

/* pix (W x H, one byte each) written UP times larger, nearest-neighbour,
   with `extra` more rows of `below` (NULL: none) under it. */
static int write_up(const char *path, const unsigned char *pix, const unsigned char *below, int extra, const unsigned char *plte)
{
	const int w = W * UP, h = H * UP + extra;
	unsigned char *big = malloc((size_t)w * (size_t)h);
	int x, y, rc;
	if (!big) return -1;
	for (y = 0; y < H * UP; y++)
		for (x = 0; x < w; x++)
			big[(size_t)y * (size_t)w + (size_t)x] = pix[(y / UP) * W + x / UP];
	if (extra > 0) memcpy(big + (size_t)H * UP * (size_t)w, below, (size_t)extra * (size_t)w);
	rc = write_png(path, big, w, h, 1, plte);
	free(big);
	return rc;
}

/* The diff image's legend: the scale as a bar (0 to DIFF_MAX over the
   left 3/4), its numbers, a NaN swatch, and a line naming the quantity
   and its largest value ("max 0" when the images are identical); STRIP
   rows of W * UP. */
static void diff_legend(unsigned char *strip, const char *what, double maxd)
{
	const int w = W * UP, bar = w * 3 / 4 - 24, s = 2;
	char line[64];
	int x, y;
	memset(strip, 0, (size_t)STRIP * (size_t)w);
	for (y = 4; y < 16; y++) {
		for (x = 12; x < 12 + bar; x++)
			strip[y * w + x] = pal_index((double)(x - 12) / (bar - 1));
		for (x = w - 60; x < w - 36; x++)
			strip[y * w + x] = PAL_NAN;
	}
	draw_text(strip, w, 12, 20, s, "0", PAL_TEXT);
	draw_text(strip, w, 12 + bar / 2 - 5 * 6 * s / 2, 20, s, "0.025", PAL_TEXT);
	draw_text(strip, w, 12 + bar - 6 * 6 * s, 20, s, ">=0.05", PAL_TEXT);
	draw_text(strip, w, w - 66, 20, s, "NaN", PAL_TEXT);
	if (maxd == 0) snprintf(line, sizeof line, "|image - %s|: max 0", what);
	else snprintf(line, sizeof line, "|image - %s|: max %.3f", what, maxd);
	draw_text(strip, w, 12, 40, s, line, PAL_TEXT);
}

/* ---- --brushed: a brushed-metal highlight that uses b1 and b2 ----
   Ambient occlusion only turns the hemisphere about n, so a frame's defect
   and its seams hardly reach its pixels.  A brushed metal does: its
   highlight is Ward's anisotropic lobe, exp(-((h.b1 / AX)^2 + (h.b2 /
   AY)^2) / (h.n)^2) with h the half vector of the light L and the view,
   rough along b2 and smooth along b1 (the grooves run along b1), peak 1.
   The frame is the method's, in float (n rounded to float, the products
   in double) or double; the reference is the method's own frame made
   exact (frame_exact): a correct frame differs from it by rounding only,
   a frame that is not orthonormal (nonorm on the ball's flank, frisvad in
   float near -z) stretches or turns the lobe, a non-finite one gives NaN, and a seam of
   the frame (b1 jumping between neighbouring normals) is a line in the
   highlight of both images.  No sampling: one evaluation a pixel. */
#define AX 0.10
#define AY 0.45
/* a brushed ball hangs under the ceiling, off the dome, so that normals
   far from -z (where the nonorm variants and the seams of duff, at n.z =
   0, and hughes_moeller live) face the camera too; the camera looks 40
   degrees off +z, so that the ball's normals with n.z = 0 face it (not
   only its limb, as from straight below) */
static const v3 BALL = { 0.2, 0.15, 0.95 };
#define BALL_R 0.34
static int hit_brushed(v3 o, v3 d, double *t, v3 *p, v3 *n)
{
	int any = hit(o, d, 1e30, t, p, n);
	v3 oc = add(o, mul(BALL, -1.0));
	double bq = dot(oc, d), cq = dot(oc, oc) - BALL_R * BALL_R, disc = bq * bq - cq, tt;
	if (disc >= 0 && (tt = -bq - sqrt(disc)) > 1e-6 && (!any || tt < *t)) {
		*t = tt; *p = add(o, mul(d, tt));
		*n = norm(add(*p, mul(BALL, -1.0)));
		any = 1;
	}
	return any;
}
static void frame_vecs(const onb_method *m, int fl, v3 n, v3 *b1, v3 *b2)
{
	if (fl) {
		onb_vec3f nf, f1, f2;
		nf.x = (float)n.x; nf.y = (float)n.y; nf.z = (float)n.z;
		m->basisf(nf, &f1, &f2);
		b1->x = f1.x; b1->y = f1.y; b1->z = f1.z;
		b2->x = f2.x; b2->y = f2.y; b2->z = f2.z;
	} else {
		onb_vec3 nd, d1, d2;
		nd.x = n.x; nd.y = n.y; nd.z = n.z;
		m->basis(nd, &d1, &d2);
		b1->x = d1.x; b1->y = d1.y; b1->z = d1.z;
		b2->x = d2.x; b2->y = d2.y; b2->z = d2.z;
	}
}
/* the method's frame made exact, as frame_dir_exact builds it */
static void frame_exact(const onb_method *m, int fl, v3 n, v3 *b1, v3 *b2)
{
	v3 nh = norm(n), c;
	double k;
	frame_vecs(m, fl, n, b1, b2);
	*b1 = add(*b1, mul(nh, -dot(*b1, nh)));
	k = sqrt(dot(*b1, *b1));
	if (!(k > 1e-3) || !isfinite(k)) {
		frame_vecs(onb_find("duff_branchless"), 0, nh, b1, b2);
		return;
	}
	*b1 = mul(*b1, 1.0 / k);
	c.x = nh.y * b1->z - nh.z * b1->y; c.y = nh.z * b1->x - nh.x * b1->z; c.z = nh.x * b1->y - nh.y * b1->x;
	*b2 = dot(c, *b2) < 0 ? mul(c, -1.0) : c;
}
/* Ward's lobe of light L for the view ray d at normal n, frame b1, b2 */
static double lobe(v3 L, v3 d, v3 n, v3 b1, v3 b2)
{
	v3 h = norm(add(L, mul(d, -1.0)));
	double hx = dot(h, b1) / AX, hy = dot(h, b2) / AY, hn = dot(h, n);
	return exp(-(hx * hx + hy * hy) / (hn * hn));
}
/* the third light: its mirror direction at the ball's normal SEAM_N
   (n.z = 0, where duff's b1 jumps: duff takes copysign(1, n.z), so b1's
   z component changes sign, a turn of 2 |n.x| about n), so that the
   highlight straddles the seam and the jump breaks it */
static const v3 SEAM_N = { -0.85, -0.5, 0.0 };
static v3 seam_light(v3 eye)
{
	v3 n0 = norm(SEAM_N), p0 = add(BALL, mul(n0, BALL_R)), v = norm(add(eye, mul(p0, -1.0)));
	return norm(add(mul(n0, 2.0 * dot(n0, v)), mul(v, -1.0)));
}
static void render_brushed(const onb_method *m, int fl, int exact, double *img)
{
	/* two lights: one whose highlight lies on the dome and the ceiling
	   (normals at -z), one whose highlight lies on the ball's flank, where
	   |n.x| is large and the nonorm variants' b1 is short */
	const v3 eye = { -0.77, 0.0, 0.48 }, at = { 0.0, 0.0, 1.4 }, upv = { 0, 1, 0 }, lraw = { 0.25, 0.1, -1.0 }, l2raw = { -0.9, 0.0, -0.45 };
	v3 fw = norm(add(at, mul(eye, -1.0))), rt, up, L = norm(lraw), L2 = norm(l2raw), L3 = seam_light(eye);
	int x, y;
	rt.x = fw.y * upv.z - fw.z * upv.y; rt.y = fw.z * upv.x - fw.x * upv.z; rt.z = fw.x * upv.y - fw.y * upv.x;
	rt = norm(rt);
	up.x = rt.y * fw.z - rt.z * fw.y; up.y = rt.z * fw.x - rt.x * fw.z; up.z = rt.x * fw.y - rt.y * fw.x;
	for (y = 0; y < H; y++)
		for (x = 0; x < W; x++) {
			double sx = (2.0 * (x + 0.5) / W - 1.0) * 0.75 * W / H, sy = (1.0 - 2.0 * (y + 0.5) / H) * 0.75, t;
			v3 d = norm(add(fw, add(mul(rt, sx), mul(up, sy)))), p, n, b1, b2;
			if (!hit_brushed(eye, d, &t, &p, &n)) {
				img[y * W + x] = 0;
				continue;
			}
			if (exact) frame_exact(m, fl, n, &b1, &b2);
			else frame_vecs(m, fl, n, &b1, &b2);
			/* a dim diffuse term shows the shapes; the lobes show the frame */
			img[y * W + x] = 0.15 * fmax(0.0, dot(L, n)) + 0.85 * (lobe(L, d, n, b1, b2) + lobe(L2, d, n, b1, b2));
			/* the seam's light on the ball only (its mirror direction
			   would light the dome elsewhere) */
			if (dot(add(p, mul(BALL, -1.0)), add(p, mul(BALL, -1.0))) < 1.01 * BALL_R * BALL_R)
				img[y * W + x] += 0.85 * lobe(L3, d, n, b1, b2);
		}
}
/* --brushed FILE: "x y image reference" per pixel (y up), for
   scripts/brushed.gp; prints the summary line of make render */
static int write_brushed(const char *path, const char *name, int fl, const double *img, const double *ref)
{
	FILE *f = fopen(path, "w");
	double maxd = 0;
	int nan = 0, x, y, over = 0;
	if (!f) { fprintf(stderr, "aorender: cannot write '%s'\n", path); return 1; }
	fprintf(f, "# aorender --brushed: %s %s; x y image reference (the method's frame made exact, double)\n", name, fl ? "float" : "double");
	for (y = 0; y < H; y++) {
		for (x = 0; x < W; x++) {
			double a = img[y * W + x], b = ref[y * W + x], d = fabs(a - b);
			if (d != d) nan++;
			else { if (d > maxd) maxd = d; over += d > 0.01; }
			fprintf(f, "%d %d %.9g %.9g\n", x, H - 1 - y, a, b);
		}
		fputc('\n', f);
	}
	if (fclose(f) != 0) { fprintf(stderr, "aorender: cannot write '%s'\n", path); return 1; }
	printf("%-24s %-6s brushed: max |image - exact frame| %.3g  pixels > 0.01: %5d  NaN pixels %d\n", name, fl ? "float" : "double", maxd, over, nan);
	return 0;
}

/* --diff: |img - ref| on the colour scale, written to path, its legend
   naming ref as `what`; prints the summary line make render collects
   (renders/summary.txt). */
static int write_diff(const char *path, const char *name, int fl, const char *what, const double *img, const double *ref)
{
	static unsigned char pix[W * H], plte[768], strip[STRIP * W * UP];
	double maxd = 0, sumd = 0;
	int nan = 0, over = 0, i, k;
	for (i = 0; i < W * H; i++) {
		double d = fabs(img[i] - ref[i]);
		if (d != d) nan++;
		else { if (d > maxd) maxd = d; sumd += d; over += d > DIFF_MAX / 2; }
		pix[i] = pal_index(d / DIFF_MAX);
	}
	for (k = 0; k < SCALE_N; k++) /* the colour scale, then text and NaN */
		colour(k / (SCALE_N - 1.0), plte + 3 * k);
	memset(plte + 3 * PAL_TEXT, 255, 3);
	plte[3 * PAL_NAN] = 0; plte[3 * PAL_NAN + 1] = 255; plte[3 * PAL_NAN + 2] = 255;
	diff_legend(strip, what, maxd);
	if (write_up(path, pix, strip, STRIP, plte) != 0) {
		fprintf(stderr, "aorender: cannot write '%s'\n", path);
		return 1;
	}
	printf("%-24s %-6s mean |diff| %.4f  max %.3f  pixels > %.3f: %5d  NaN pixels %d\n", name, fl ? "float" : "double",
	       sumd / (W * H - nan), maxd, DIFF_MAX / 2, over, nan);
	return 0;
}

int main(int argc, char **argv)
{
	const char *name = NULL, *out = NULL, *diff = NULL, *obj = NULL, *brushed = NULL;
	int fl = 1, spp = 256, k, i, renorm = 1;
	char up = 'z';
	const onb_method *m;
	mesh_normals mn;
	mesh_geom mg;
	mscene sc;
	static double img[W * H], ref[W * H];
	static unsigned char rgb[W * H];
	crc_init();
	for (k = 1; k < argc; k++) {
		if (!strcmp(argv[k], "--list")) {
			size_t n, j;
			const onb_method *ms = onb_methods(&n);
			for (j = 0; j < n; j++)
				printf("%s\n", ms[j].name);
			return 0;
		} else if (k + 1 < argc && !strcmp(argv[k], "--method")) name = argv[++k];
		else if (k + 1 < argc && !strcmp(argv[k], "--out")) out = argv[++k];
		else if (k + 1 < argc && !strcmp(argv[k], "--diff")) diff = argv[++k];
		else if (k + 1 < argc && !strcmp(argv[k], "--brushed")) brushed = argv[++k];
		else if (k + 1 < argc && (!strcmp(argv[k], "--obj") || !strcmp(argv[k], "--mesh"))) obj = argv[++k];
		else if (!strcmp(argv[k], "--no-renormalize")) renorm = 0;
		else if (k + 1 < argc && !strcmp(argv[k], "--up")) {
			k++;
			if (strlen(argv[k]) != 1 || !strchr("zyx", argv[k][0])) {
				fprintf(stderr, "aorender: --up must be z, y or x, got '%s'\n", argv[k]);
				return 2;
			}
			up = argv[k][0];
		}
		else if (k + 1 < argc && !strcmp(argv[k], "--spp")) {
			spp = atoi(argv[++k]);
			if (spp < 1 || spp > 100000) { fprintf(stderr, "aorender: --spp must be 1..100000\n"); return 2; }
		} else if (k + 1 < argc && !strcmp(argv[k], "--precision")) {
			k++;
			if (!strcmp(argv[k], "float")) fl = 1;
			else if (!strcmp(argv[k], "double")) fl = 0;
			else { fprintf(stderr, "aorender: --precision must be float or double\n"); return 2; }
		} else {
			fprintf(stderr, "usage: aorender --method NAME [--precision float|double] [--spp N] [--mesh FILE [--up z|y|x] [--no-renormalize]] --out FILE.png [--diff DIFF.png] [--brushed FILE.dat] | --list\n");
			return 2;
		}
	}
	if (!name || (!out && !brushed)) {
		fprintf(stderr, "aorender: --method and --out (or --brushed) are required (--list names the methods)\n");
		return 2;
	}
	m = onb_find(name);
	if (!m) {
		fprintf(stderr, "aorender: unknown method '%s' (--list names them)\n", name);
		return 2;
	}
	if (brushed) {
		if (obj) { fprintf(stderr, "aorender: --brushed renders the default scene, not --mesh\n"); return 2; }
		render_brushed(m, fl, 0, img);
		render_brushed(m, fl, 1, ref);
		if (write_brushed(brushed, name, fl, img, ref) != 0)
			return 1;
		if (!out)
			return 0;
	}
	if (obj) {
		char err[600], msg[700];
		if (mesh_read_geom_file(obj, &mn, &mg, err, sizeof err) != 0) {
			fprintf(stderr, "aorender: %s\n", err);
			return 2;
		}
		if (mscene_init(&sc, &mg, up, renorm, msg, sizeof msg) != 0) {
			fprintf(stderr, "aorender: %s: %s\n", obj, msg);
			mscene_free(&sc); mesh_geom_free(&mg); mesh_free(&mn);
			return 2;
		}
		render_mesh(&sc, m, fl, 0, spp, img);
	} else
		render(m, fl, spp, img);
	for (i = 0; i < W * H; i++) {
		double v = img[i];
		unsigned char g = (unsigned char)(v >= 0 ? 255 * (v > 1 ? 1 : v) + 0.5 : 0);
		rgb[i] = g;
	}
	if (write_up(out, rgb, NULL, 0, NULL) != 0) {
		fprintf(stderr, "aorender: cannot write '%s'\n", out);
		return 1;
	}
	if (diff) {
		if (obj)
			render_mesh(&sc, m, fl, 1, spp, ref);
		else
			render(onb_find("duff_branchless"), 0, spp, ref);
		if (write_diff(diff, name, fl, obj ? "exact frame" : "double reference", img, ref) != 0)
			return 1;
	}
	if (obj) {
		mscene_free(&sc); mesh_geom_free(&mg); mesh_free(&mn);
	}
	return 0;
}
