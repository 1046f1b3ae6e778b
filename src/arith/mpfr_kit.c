/*
 * mpfr_kit.c - the MPFR vector helpers (see mpfr_kit.h).
 */
#include "arith/mpfr_kit.h"

#define R MPFR_RNDN

void kit_vinit(mpfr_t *v, int k, mpfr_prec_t p)
{
	int i;
	for (i = 0; i < k; i++)
		mpfr_init2(v[i], p);
}

void kit_vclear(mpfr_t *v, int k)
{
	int i;
	for (i = 0; i < k; i++)
		mpfr_clear(v[i]);
}

void kit_init(mpfr_kit *c, mpfr_prec_t prec)
{
	kit_vinit(c->t, KIT_NT, prec);
	mpfr_init2(c->p0, prec);
	mpfr_init2(c->p1, prec);
	kit_vinit(c->u, 3, prec);
	kit_vinit(c->w, 3, prec);
}

void kit_clear(mpfr_kit *c)
{
	kit_vclear(c->t, KIT_NT);
	mpfr_clear(c->p0);
	mpfr_clear(c->p1);
	kit_vclear(c->u, 3);
	kit_vclear(c->w, 3);
}

void kit_dot(mpfr_kit *c, mpfr_t out, mpfr_t *a, mpfr_t *b)
{
	mpfr_mul(c->p0, a[0], b[0], R);
	mpfr_mul(c->p1, a[1], b[1], R);
	mpfr_add(out, c->p0, c->p1, R);
	mpfr_mul(c->p0, a[2], b[2], R);
	mpfr_add(out, out, c->p0, R);
}

void kit_cross(mpfr_kit *c, mpfr_t *o, mpfr_t *a, mpfr_t *b)
{
	mpfr_mul(c->p0, a[1], b[2], R); mpfr_mul(c->p1, a[2], b[1], R); mpfr_sub(o[0], c->p0, c->p1, R);
	mpfr_mul(c->p0, a[2], b[0], R); mpfr_mul(c->p1, a[0], b[2], R); mpfr_sub(o[1], c->p0, c->p1, R);
	mpfr_mul(c->p0, a[0], b[1], R); mpfr_mul(c->p1, a[1], b[0], R); mpfr_sub(o[2], c->p0, c->p1, R);
}

void kit_set3(mpfr_t *o, double x, double y, double z)
{
	mpfr_set_d(o[0], x, R);
	mpfr_set_d(o[1], y, R);
	mpfr_set_d(o[2], z, R);
}

void kit_copy3(mpfr_t *o, mpfr_t *a)
{
	mpfr_set(o[0], a[0], R);
	mpfr_set(o[1], a[1], R);
	mpfr_set(o[2], a[2], R);
}

void kit_normalize(mpfr_kit *c, mpfr_t *a)
{
	kit_dot(c, c->t[5], a, a);
	mpfr_rec_sqrt(c->t[5], c->t[5], R);
	mpfr_mul(a[0], a[0], c->t[5], R);
	mpfr_mul(a[1], a[1], c->t[5], R);
	mpfr_mul(a[2], a[2], c->t[5], R);
}

void kit_axis_cross(mpfr_t *o, int axis, int sg, mpfr_t *n)
{
	const int i = (axis + 1) % 3, j = (axis + 2) % 3;
	mpfr_set_zero(o[axis], 1);
	if (sg > 0) {
		mpfr_neg(o[i], n[j], R);
		mpfr_set(o[j], n[i], R);
	} else {
		mpfr_set(o[i], n[j], R);
		mpfr_neg(o[j], n[i], R);
	}
}

void kit_perp_cross(mpfr_kit *c, int axis, int sg, mpfr_t *n, mpfr_t *b1, mpfr_t *b2)
{
	kit_axis_cross(b1, axis, sg, n);
	kit_normalize(c, b1);
	kit_cross(c, b2, n, b1);
}

/* Round to nearest is symmetric, so -RN(v) = RN(-v): the signs cost no
   rounding, and each sg gives exactly the values (and signed zeros) of
   its own listing. */
void kit_frisvad(mpfr_kit *c, int sg, mpfr_t *n, mpfr_t *b1, mpfr_t *b2)
{
	mpfr_t *t = c->t;
	if (sg > 0)
		mpfr_add_ui(t[0], n[2], 1, R);
	else
		mpfr_ui_sub(t[0], 1, n[2], R);
	mpfr_ui_div(t[0], 1, t[0], R);           /* a */
	mpfr_mul(t[1], n[0], n[1], R);
	mpfr_mul(t[1], t[1], t[0], R);           /* b */
	mpfr_sqr(t[2], n[0], R);
	mpfr_mul(t[2], t[2], t[0], R);
	mpfr_ui_sub(b1[0], 1, t[2], R);
	mpfr_neg(b1[1], t[1], R);
	if (sg > 0)
		mpfr_neg(b1[2], n[0], R);
	else
		mpfr_set(b1[2], n[0], R);
	if (sg > 0)
		mpfr_neg(b2[0], t[1], R);
	else
		mpfr_set(b2[0], t[1], R);
	mpfr_sqr(t[2], n[1], R);
	mpfr_mul(t[2], t[2], t[0], R);
	if (sg > 0)
		mpfr_ui_sub(b2[1], 1, t[2], R);
	else
		mpfr_sub_ui(b2[1], t[2], 1, R);    /* not a negated 1 - y^2 a: the sign of an exact 0 */
	mpfr_neg(b2[2], n[1], R);
}
