/*
 * mpfr_kit.h - the MPFR vector helpers the families' exact formulas are
 * written with (src/families/), and the reference (reference.c) uses for
 * its metrics.  Every operation rounds to nearest at the kit's precision.
 * The kit imports MPFR alone; nothing here knows a method.
 */
#ifndef ONB_REFERENCE_MPFR_KIT_H
#define ONB_REFERENCE_MPFR_KIT_H

#include <mpfr.h>

#define KIT_NT 6

/* The scratch a formula may use: t[] temporaries, p0 and p1 the products
   of dot and cross, u[] and w[] vectors.  A formula writes its outputs
   into b1[] and b2[], which are never these. */
typedef struct mpfr_kit {
	mpfr_t t[KIT_NT];
	mpfr_t p0, p1;
	mpfr_t u[3], w[3];
} mpfr_kit;

/* k values at precision p; and their release */
void kit_vinit(mpfr_t *v, int k, mpfr_prec_t p);
void kit_vclear(mpfr_t *v, int k);
void kit_init(mpfr_kit *c, mpfr_prec_t prec);
void kit_clear(mpfr_kit *c);

/* out = a.b (out may be a temporary, never a component of a or b) */
void kit_dot(mpfr_kit *c, mpfr_t out, mpfr_t *a, mpfr_t *b);
/* o = a x b (o distinct from a and b) */
void kit_cross(mpfr_kit *c, mpfr_t *o, mpfr_t *a, mpfr_t *b);
void kit_set3(mpfr_t *o, double x, double y, double z);
void kit_copy3(mpfr_t *o, mpfr_t *a);
/* a *= 1/|a| (exactly rounded reciprocal square root; uses t[5]) */
void kit_normalize(mpfr_kit *c, mpfr_t *a);
/* o = sg (e_axis x n), sg = +1 or -1: the vector perpendicular to n and
   to coordinate axis `axis` that the "pick an axis" methods start from:
   axis 0 gives sg (0, -z, y), 1 gives sg (z, 0, -x), 2 gives sg (-y, x, 0).
   Exact (copies and negations); o[axis] is +0 whatever sg; o distinct
   from n. */
void kit_axis_cross(mpfr_t *o, int axis, int sg, mpfr_t *n);
/* The body those methods share: b1 = the above normalized, b2 = n x b1. */
void kit_perp_cross(mpfr_kit *c, int axis, int sg, mpfr_t *n, mpfr_t *b1, mpfr_t *b2);
/* Frisvad's formula (sg = +1, Equations 4-6) and Duff's lower branch
   (sg = -1), which differ only in signs:
     a = 1/(1 + sg z), b = x y a,
     b1 = (1 - x^2 a, -b, -sg x), b2 = (-sg b, sg (1 - y^2 a), -y).
   Uses t[0..2]. */
void kit_frisvad(mpfr_kit *c, int sg, mpfr_t *n, mpfr_t *b1, mpfr_t *b2);

#endif
