/*
 * found_images.c - the found side's images pass: the best inputs of every
 * region of a kernel and precision, and the --starts inputs, under the 48
 * signed permutations of their components, tried in the regions they fall
 * in.
 *
 * A signed permutation of the rounding of a unit vector is the rounding of
 * a unit vector (round to nearest is odd and acts on each component), and
 * in the tolerance domain | |n| - 1 | does not change: the images of a
 * domain member are members.  Many kernels are exactly equivariant under
 * some of these maps (a sign flip is exact; naive's y and z play the same
 * part), so a defect one region's search reached is often reached again,
 * bit for bit, in another region: the searches of all regions pool their
 * luck.  An image is evaluated like any other input (found_try, then
 * measured as `onbstudy eval` measures it), so the pass can only raise a
 * region's found to what the kernel does on one of its inputs.
 */
#include <string.h>
#include "found.h"

/* Could n.z = z lie in r's band (a band at a pole holds what lies beyond)? */
static int in_band(const cert_region *r, double z)
{
	return (z >= r->nz_lo || r->nz_lo <= -1.0) && (z <= r->nz_hi || r->nz_hi >= 1.0);
}

/* The 8 images of pool input p whose n.z is z (+-p->n[a]): the other two
   components in either order, each with either sign. */
static void try_with_z(probe_env *e, const cert_pool_in *p, int a, double z)
{
	double m[3];
	int sw, sg;
	for (sw = 0; sw < 2; sw++)
		for (sg = 0; sg < 4; sg++) {
			m[0] = (sg & 1) ? -p->n[(a + 1 + sw) % 3] : p->n[(a + 1 + sw) % 3];
			m[1] = (sg & 2) ? -p->n[(a + 2 - sw) % 3] : p->n[(a + 2 - sw) % 3];
			m[2] = z;
			found_try(e, m, p->sure);
		}
}

void found_images(probe_env *e, const cert_pool_in *pool, long np)
{
	long i;
	int a;
	if (e->k->rot)   /* frisvad_rotate's found carries a local direction too */
		return;
	for (i = 0; i < np; i++)
		for (a = 0; a < 3; a++) {
			if (in_band(e->r, pool[i].n[a]))
				try_with_z(e, &pool[i], a, pool[i].n[a]);
			if (in_band(e->r, -pool[i].n[a]))
				try_with_z(e, &pool[i], a, -pool[i].n[a]);
		}
	found_polish(e, 4, 0.9);
}
