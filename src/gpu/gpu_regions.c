/*
 * gpu_regions.c - a certify CSV's regions of one method in float (or
 * half: gpu_regions_loadp, the box 8 half ulps wide), and the
 * bound that holds at one input: certify proves each region's bound for
 * every rounding of a real unit vector v in the region (nz = v.z in
 * [nz_lo, nz_hi], its azimuth in [phi_lo, phi_hi] degrees).  The input n
 * is the rounding of some v within a few u of n/|n|, so the bound at n
 * is the largest over the regions that reach within 8u of n/|n| (as
 * emu_point_bound's box), and never above the whole sphere's.  Used only
 * when the regions tile the sphere (their areas sum to its 2 x 360).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "gpu/compare.h"

int gpu_regions_load(const char *csv, const char *name, gpu_regions *r)
{
	return gpu_regions_loadp(csv, name, "float", r);
}

int gpu_regions_loadp(const char *csv, const char *name, const char *prec, gpu_regions *r)
{
	FILE *f = fopen(csv, "r");
	char line[1024], key[32];
	const size_t len = strlen(name);
	double area = 0.0;
	memset(r, 0, sizeof *r);
	r->whole = INFINITY;
	r->w = 8.0 * (strcmp(prec, "half") == 0 ? 0x1p-11 : 0x1p-24);
	snprintf(key, sizeof key, ",%s,", prec);
	if (!f)
		return -1;
	while (fgets(line, sizeof line, f)) {
		double v[5];
		gpu_region *g;
		if (strncmp(line, name, len) != 0 || strncmp(line + len, key, strlen(key)) != 0 ||
		    sscanf(line + len + strlen(key), "%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4]) != 5)
			continue;   /* "inf" reads as inf with %lf */
		if (v[0] == -1.0 && v[1] == 1.0 && v[2] == 0.0 && v[3] == 360.0) {
			r->whole = v[4];
			r->have_whole = 1;
			continue;
		}
		if (r->n == r->cap) {
			size_t cap = r->cap ? 2 * r->cap : 256;
			gpu_region *p = realloc(r->g, cap * sizeof *p);
			if (!p)
				break;
			r->g = p;
			r->cap = cap;
		}
		g = &r->g[r->n++];
		g->zlo = v[0]; g->zhi = v[1]; g->plo = v[2]; g->phi = v[3]; g->b = v[4];
		area += (v[1] - v[0]) * (v[3] - v[2]);
	}
	fclose(f);
	r->tiled = r->n > 0 && fabs(area - 720.0) <= 1e-9 * 720.0;
	if (!r->have_whole && r->tiled) {   /* certify --precision half writes regions alone */
		size_t i;
		r->whole = 0.0;
		for (i = 0; i < r->n; i++)
			r->whole = fmax(r->whole, r->g[i].b);   /* NaN-free: inf reads as inf */
		r->have_whole = 1;
	}
	return 0;
}

void gpu_regions_free(gpu_regions *r)
{
	free(r->g);
	memset(r, 0, sizeof *r);
}

/* does [a, b] (degrees, a <= b, within [0, 360]) meet [c - d, c + d] mod 360 */
static int meets_phi(double a, double b, double c, double d)
{
	int k;
	if (d >= 180.0)
		return 1;
	for (k = -1; k <= 1; k++)
		if (c + 360.0 * k + d >= a && c + 360.0 * k - d <= b)
			return 1;
	return 0;
}

double gpu_regions_bound(const gpu_regions *r, const float nf[3])
{
	const double x = nf[0], y = nf[1], zz = nf[2], l = sqrt(x * x + y * y + zz * zz), w = r->w;
	double z, rho, phi, dphi, b = -INFINITY;
	size_t i;
	if (!r->tiled || !(l > 0.0) || !isfinite(l))
		return r->whole;
	z = zz / l;
	rho = sqrt(fmax(0.0, 1.0 - z * z));
	phi = atan2(y, x) * (180.0 / 3.141592653589793);
	if (phi < 0.0)
		phi += 360.0;
	dphi = rho > w ? (2.0 * w / rho) * (180.0 / 3.141592653589793) : 360.0;
	for (i = 0; i < r->n; i++) {
		const gpu_region *g = &r->g[i];
		if (g->zhi >= z - w && g->zlo <= z + w && meets_phi(g->plo, g->phi, phi, dphi) && !(g->b <= b))
			b = g->b;
	}
	return b > -INFINITY && b < r->whole ? b : r->whole;
}
