/*
 * rtao.c - DirectX-Graphics-Samples' RTAO GetRandomRayDirection
 * (RayGen.hlsli): right = 0.3 n + c, c = (-0.72, 0.56, -0.34); b2 =
 * unit(n x right), b1 = b2 x n.  Exactly n x right = n x c: singular
 * where n is parallel to c.  Variant ONB__WILD_FIXED (rtao_fixed, this
 * project's fix): c' = (0.56, 0.72, 0), orthogonal to c, where
 * |n . c| > 0.875.
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 0: c; 1: c' (fixed only) */
int FAMILY_BRANCH(rtao)(const onb_method *m, int prec, const double n[3])
{
	if (m->norm != ONB__WILD_FIXED)
		return 0;
	if (prec == PREC_FLOAT)
		return fabsf((float)n[0] * -0.72f + (float)n[1] * 0.56f + (float)n[2] * -0.34f) > 0.875f;
	return fabs(n[0] * -0.72 + n[1] * 0.56 + n[2] * -0.34) > 0.875;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(rtao)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	xv u[3];
	(void)m; (void)loc;
	if (br)
		xset3(u, 0.56, 0.72, 0.0);
	else
		xset3(u, -0.72, 0.56, -0.34);
	xcross(r2, n, u, bad);
	xnormalize(r2, bad);
	xcross(r1, r2, n, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "fixed, |n . c| > 0.875: right = 0.3 n + (0.56, 0.72, 0)" : "right = 0.3 n + (-0.72, 0.56, -0.34)";
}

/* n x right = n x c exactly (0.3 n x n = 0): b2 = unit(n x c), b1 = b2 x n
   (c as the double constants; the float kernel's differ by < 2^-24
   relatively, well inside test_parts' tolerance) */
static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	if (br)
		kit_set3(c->u, 0.56, 0.72, 0.0);
	else
		kit_set3(c->u, -0.72, 0.56, -0.34);
	kit_cross(c, r2, n, c->u);
	kit_normalize(c, r2);
	kit_cross(c, r1, r2, n);
}

/* (fixed) |dot(n, c)| > 0.875, one branch point; right = 0.3*n + c;
   q = n x right, b2 = q / sqrt(q.q), b1 = b2 x n */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	double cx = -0.72, cy = 0.56, cz = -0.34;
	cv r[3], q[3], l;
	int i;
	if (m->norm == ONB__WILD_FIXED) {
		const cv d = ADD(ADD(MUL(n[0], K(cx)), MUL(n[1], K(cy))), MUL(n[2], K(cz)));
		if (cm_branch_abs(c, 0, CM_GT, d, K(0.875))) {
			cx = 0.56; cy = 0.72; cz = 0.0;
		}
	}
	r[0] = ADD(MUL(K(0.3), n[0]), K(cx));
	r[1] = ADD(MUL(K(0.3), n[1]), K(cy));
	r[2] = ADD(MUL(K(0.3), n[2]), K(cz));
	mk_cross(c, P, n, r, q);
	l = cm_sqrt(c, P, mk_dot3(c, P, q, q));
	for (i = 0; i < 3; i++)
		out[3 + i] = DIV(q[i], l);
	mk_cross_out(c, P, n, out, 0, 0, "nnn");
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B2; }
static int variant(const onb_method *m) { return m->norm == ONB__WILD_FIXED; }

static const char *singular(const onb_method *m)
{
	if (m->norm == ONB__WILD_FIXED)
		return "none";
	return "n parallel to (-0.72, 0.56, -0.34): n x right = 0 exactly (O(1) defect near it; NaN where it rounds to 0)";
}

/* +-c/|c|: n.z = -+0.3493, azimuth 142.1 and 322.1 degrees; a margin
   covers the float constants' rounding */
static int meets_singular(const onb_method *m, double nz_lo, double nz_hi, double phi_lo, double phi_hi)
{
	const double e = 1e-6, len = sqrt(0.72 * 0.72 + 0.56 * 0.56 + 0.34 * 0.34);
	const double z = -0.34 / len, ph = atan2(0.56, -0.72) * (180.0 / 3.14159265358979323846);
	if (m->norm == ONB__WILD_FIXED)
		return 0;
	return (nz_lo <= z + e && nz_hi >= z - e && phi_lo <= ph + e && phi_hi >= ph - e) ||
	       (nz_lo <= -z + e && nz_hi >= -z - e && phi_lo <= ph + 180.0 + e && phi_hi >= ph + 180.0 - e);
}

FAMILY_DECLARE(rtao);
const study_family family_rtao = {
	"rtao", FAMILY_PASSES(rtao), names, mpfr, FAMILY_PAIRS(rtao), variant,
	family_no_exact_zero, model, 1, zero_any_n, singular, meets_singular,
	family_no_fma_model,  /* no --fma model: the kernel is studied as compiled, -ffp-contract=off */
};
#endif
