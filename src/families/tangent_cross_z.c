/*
 * tangent_cross_z.c - sydneyzh's get_onb: t = n + z, b2 = unit(n x t),
 * b1 = n x b2; no branch, singular at n = +-z.
 */
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
int FAMILY_BRANCH(tangent_cross_z)(const onb_method *m, int prec, const double n[3])
{
	(void)m; (void)prec; (void)n;
	return 0;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(tangent_cross_z)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2,
                                  int *bad)
{
	xv u[3];
	(void)m; (void)br; (void)loc;
	u[0] = n[0]; u[1] = n[1]; u[2] = xadd(n[2], xc(1.0), bad);
	xcross(r2, n, u, bad);
	xnormalize(r2, bad);
	xcross(r1, n, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)b; (void)buf; (void)n;
	return "no branch";
}

/* t = (x, y, z+1); b2 = unit(n x t); b1 = n x b2 */
static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	mpfr_t *u = c->u;
	(void)m; (void)br; (void)loc;
	mpfr_set(u[0], n[0], R);
	mpfr_set(u[1], n[1], R);
	mpfr_add_ui(u[2], n[2], 1, R);
	kit_cross(c, r2, n, u);
	kit_normalize(c, r2);
	kit_cross(c, r1, n, r2);
}

static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	cv t[3], cr[3], l;
	int i;
	(void)m;
	t[0] = n[0]; t[1] = n[1]; t[2] = ADD(n[2], K(1.0));
	mk_cross_fused(c, P, n, t, cr, "ffn");   /* as GCC fuses it: cr.z = x*y - y*x, one product CSE'd */
	l = cm_sqrt(c, P, mk_dot3_xf(c, P, cr, cr));
	for (i = 0; i < 3; i++)
		out[3 + i] = DIV(cr[i], l);
	mk_cross_out(c, P, n, out, 0, 1, "fff");
}

/* b1 and b2 swapped against stark's: b2 = p/|p| with p = n x t */
static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B2; }

static const char *singular(const onb_method *m)
{
	(void)m;
	return "n = +-z (and, in float, n.x^2 + n.y^2 below the smallest subnormal)";
}

static int meets_singular(const onb_method *m, double nz_lo, double nz_hi, double phi_lo, double phi_hi)
{
	(void)m; (void)phi_lo; (void)phi_hi;
	return nz_lo <= -1.0 || nz_hi >= 1.0;
}

FAMILY_DECLARE(tangent_cross_z);
const study_family family_tangent_cross_z = {
	"tangent_cross_z", FAMILY_PASSES(tangent_cross_z), names, mpfr, FAMILY_PAIRS(tangent_cross_z),
	family_no_variant, family_no_exact_zero, model, 0, zero_any_n, singular, meets_singular,
	family_fma_model,
};
#endif
