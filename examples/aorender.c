/*
 * aorender.c - ambient occlusion with cosine-weighted hemisphere sampling,
 * as a renderer that links libonb.a would do it.  Links only libonb.a and
 * libm; writes PNG with a dependency-free writer (stored deflate blocks).
 *
 *   aorender --method NAME [--precision float|double] --out FILE.png
 *            [--diff DIFF.png] [--spp N (256)] [--list]
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
 * black (0) through blue and red to yellow (DIFF_MAX = 0.05 or more; NaN
 * is yellow too), with the scale as a bar along the bottom.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "onb.h"

#define W 160
#define H 120

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
				v3 w, pp, nn, o;
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

static void colour(double v, unsigned char *c)
{
	/* 0 black, 1/3 blue, 2/3 red, 1 yellow */
	double r, g, b;
	if (!(v >= 0)) v = 1; /* NaN: top of the scale */
	if (v > 1) v = 1;
	if (v < 1.0 / 3) { r = 0; g = 0; b = 3 * v; }
	else if (v < 2.0 / 3) { r = 3 * v - 1; g = 0; b = 2 - 3 * v; }
	else { r = 1; g = 3 * v - 2; b = 0; }
	c[0] = (unsigned char)(255 * r + 0.5); c[1] = (unsigned char)(255 * g + 0.5); c[2] = (unsigned char)(255 * b + 0.5);
}

/* the palette entry of a value of the colour scale (NaN: the top) */
static unsigned char pal_index(double v)
{
	if (!(v >= 0)) v = 1;
	if (v > 1) v = 1;
	return (unsigned char)(255 * v + 0.5);
}

int main(int argc, char **argv)
{
	static unsigned char plte[768];
	const char *name = NULL, *out = NULL, *diff = NULL;
	int fl = 1, spp = 256, k, i;
	const onb_method *m;
	static double img[W * H], ref[W * H];
	static unsigned char rgb[W * H * 3];
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
		else if (k + 1 < argc && !strcmp(argv[k], "--spp")) {
			spp = atoi(argv[++k]);
			if (spp < 1 || spp > 100000) { fprintf(stderr, "aorender: --spp must be 1..100000\n"); return 2; }
		} else if (k + 1 < argc && !strcmp(argv[k], "--precision")) {
			k++;
			if (!strcmp(argv[k], "float")) fl = 1;
			else if (!strcmp(argv[k], "double")) fl = 0;
			else { fprintf(stderr, "aorender: --precision must be float or double\n"); return 2; }
		} else {
			fprintf(stderr, "usage: aorender --method NAME [--precision float|double] [--spp N] --out FILE.png [--diff DIFF.png] | --list\n");
			return 2;
		}
	}
	if (!name || !out) {
		fprintf(stderr, "aorender: --method and --out are required (--list names the methods)\n");
		return 2;
	}
	m = onb_find(name);
	if (!m) {
		fprintf(stderr, "aorender: unknown method '%s' (--list names them)\n", name);
		return 2;
	}
	render(m, fl, spp, img);
	for (i = 0; i < W * H; i++) {
		double v = img[i];
		unsigned char g = (unsigned char)(v >= 0 ? 255 * (v > 1 ? 1 : v) + 0.5 : 0);
		rgb[i] = g;
	}
	if (write_png(out, rgb, W, H, 1, NULL) != 0) {
		fprintf(stderr, "aorender: cannot write '%s'\n", out);
		return 1;
	}
	if (diff) {
		double maxd = 0, sumd = 0;
		int nan = 0, over = 0;
		render(onb_find("duff_branchless"), 0, spp, ref);
		for (i = 0; i < W * H; i++) {
			double d = fabs(img[i] - ref[i]);
			if (d != d) nan++;
			else { if (d > maxd) maxd = d; sumd += d; over += d > DIFF_MAX / 2; }
			rgb[i] = pal_index(d / DIFF_MAX);
		}
		for (i = (H - 6) * W; i < W * H; i++) /* the scale, 0 at the left to DIFF_MAX at the right */
			rgb[i] = pal_index((double)(i % W) / (W - 1));
		for (k = 0; k < 256; k++) /* the colour scale as a 256-entry palette */
			colour(k / 255.0, plte + 3 * k);
		if (write_png(diff, rgb, W, H, 1, plte) != 0) {
			fprintf(stderr, "aorender: cannot write '%s'\n", diff);
			return 1;
		}
		printf("%-24s %-6s mean |diff| %.4f  max %.3f  pixels > %.3f: %5d  NaN pixels %d\n", name, fl ? "float" : "double",
		       sumd / (W * H - nan), maxd, DIFF_MAX / 2, over, nan);
	}
	return 0;
}
