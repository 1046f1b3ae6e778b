/*
 * render.c - the README's library quick start: what a renderer does with
 * libonb at every shading point, in a page.  It builds the basis of a
 * normal with the library's default method (duff_branchless, float),
 * turns cosine-weighted local directions into world directions with it,
 * and checks them: every direction unit and on the normal's side.  An
 * untrusted normal (from a mesh file) goes through onb_basis_checkedf,
 * which normalizes it first.  Needs libonb.a and libm alone:
 *
 *   cc -O2 -I$HOME/.local/include examples/render.c -L$HOME/.local/lib -lonb -lm
 *   ./a.out
 *
 * Prints one line per normal (the mean cos theta of 4096 directions,
 * 2/3 for a cosine-weighted hemisphere, and the largest | |w| - 1 |),
 * and exits 1 if a direction is not unit to 1e-5 or leaves the
 * hemisphere: a basis that is not orthonormal shows up here.
 */
#include <math.h>
#include <stdio.h>
#include <libonb/onb.h>

#define DIRS 4096

/* Direction k of DIRS, cosine-weighted about +z in the local frame
   (a 2-D lattice instead of random numbers: the same on every run). */
static void local_dir(int k, float *x, float *y, float *z)
{
	const float u = ((float)k + 0.5f) / DIRS;
	const float phi = 6.2831853f * (float)k * 0.6180340f;
	const float r = sqrtf(u);
	*x = r * cosf(phi);
	*y = r * sinf(phi);
	*z = sqrtf(1.0f - u);
}

/* Shade one normal with its basis: returns the number of bad directions. */
static int shade(const char *what, onb_vec3f n, onb_vec3f b1, onb_vec3f b2)
{
	double cos_sum = 0.0, worst = 0.0;
	int k, bad = 0;
	for (k = 0; k < DIRS; k++) {
		float x, y, z;
		onb_vec3f w;
		double len, c;
		local_dir(k, &x, &y, &z);
		w.x = b1.x * x + b2.x * y + n.x * z;   /* to world: w = b1 x + b2 y + n z */
		w.y = b1.y * x + b2.y * y + n.y * z;
		w.z = b1.z * x + b2.z * y + n.z * z;
		len = sqrt((double)w.x * w.x + (double)w.y * w.y + (double)w.z * w.z);
		c = ((double)w.x * n.x + (double)w.y * n.y + (double)w.z * n.z) / len;
		cos_sum += c;
		worst = fmax(worst, fabs(len - 1.0));
		bad += !(fabs(len - 1.0) <= 1e-5) || !(c > -1e-6);
	}
	printf("%-28s mean cos %.4f  max | |w| - 1 | %.2e%s\n", what, cos_sum / DIRS, worst, bad ? "  BAD" : "");
	return bad;
}

int main(void)
{
	/* a floor, a wall, a tilted normal, and a ceiling (n = -z: the pole
	   where Frisvad's 2012 method fails in float) */
	static const onb_vec3f normals[] = {
		{ 0.0f, 0.0f, 1.0f }, { 1.0f, 0.0f, 0.0f }, { 0.0f, 0.6f, -0.8f }, { 0.0f, 0.0f, -1.0f }
	};
	const onb_vec3f untrusted = { 0.0f, 3.0f, -4.0f };   /* not unit: |n| = 5 */
	onb_vec3f b1, b2, n;
	char what[64];
	unsigned i;
	int bad = 0;
	for (i = 0; i < sizeof normals / sizeof normals[0]; i++) {
		onb_duff_branchlessf(normals[i], &b1, &b2);
		snprintf(what, sizeof what, "n = (%g, %g, %g)", normals[i].x, normals[i].y, normals[i].z);
		bad += shade(what, normals[i], b1, b2);
	}
	if (onb_basis_checkedf(onb_find("duff_branchless"), untrusted, &b1, &b2, &n) != ONB_RENORMALIZED) {
		printf("onb_basis_checkedf: (0, 3, -4) was not renormalized\n");
		return 1;
	}
	bad += shade("checked n = (0, 3, -4)", n, b1, b2);
	printf("render: %s\n", bad ? "FAILED: a direction was not unit or left the hemisphere" : "every direction unit and in the hemisphere");
	return bad != 0;
}
