/*
 * open3d.c - Open3D's PlaneDetector::ConstructOrthogonalBasis with
 * Eigen's normalized(): b1 = unit(n x (0,1,1)) (the guard's other branch,
 * n x (1,0,1), is unreachable on the unit sphere), b2 = unit(n x b1);
 * normalized() leaves a zero vector unchanged, so on the line
 * n || (0,1,1) b1 = b2 = 0.  open3d_fixed (variant ONB__WILD_FIXED, this
 * project's fix) compares n with +-(0, c, c), c = 1/sqrt(2) rounded, and
 * takes the cross with (1, 0, 1) near them.
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN
#define C45 0.70710678118654752440 /* the singular directions' |n.y| = |n.z| */

#if FAMILY_RULE_PASS
/* 1 when |a - n|^2 > 1e-3 (and, fixed, |a + n|^2 > 1e-3), with a = (0,1,1)
   (fixed: (0, c, c)); Eigen's summation order per type */
/* v0^2 + (v1^2 + v2^2) in binary16, of the differences rounded to it */
static double o3d_sq_h(double v0, double v1, double v2)
{
	const double a = prec_half_round(v0), b = prec_half_round(v1), c = prec_half_round(v2);
	return prec_half_round(prec_half_round(a * a) +
	                       prec_half_round(prec_half_round(b * b) + prec_half_round(c * c)));
}
int FAMILY_BRANCH(open3d)(const onb_method *m, int prec, const double n[3])
{
	const int fixed = m->norm == ONB__WILD_FIXED;
	if (prec == PREC_FLOAT) {
		const float x = (float)n[0], y = (float)n[1], z = (float)n[2], a = fixed ? 0x1.6a09e6p-1f : 1.0f;
		const float dx = 0.0f - x, dy = a - y, dz = a - z, ex = 0.0f + x, ey = a + y, ez = a + z;
		return dx * dx + (dy * dy + dz * dz) > 1e-3f && (!fixed || ex * ex + (ey * ey + ez * ez) > 1e-3f);
	} else if (prec == PREC_HALF) {   /* Eigen's scalar order, each operation rounded to binary16 */
		const double a = fixed ? prec_half_round(0x1.6a09e667f3bcdp-1) : 1.0, t = prec_half_round(1e-3);
		return o3d_sq_h(0.0 - n[0], a - n[1], a - n[2]) > t && (!fixed || o3d_sq_h(n[0], a + n[1], a + n[2]) > t);
	} else {
		const double x = n[0], y = n[1], z = n[2], a = fixed ? 0x1.6a09e667f3bcdp-1 : 1.0;
		const double dx = 0.0 - x, dy = a - y, dz = a - z, ex = 0.0 + x, ey = a + y, ez = a + z;
		return (dx * dx + dy * dy) + dz * dz > 1e-3 && (!fixed || (ex * ex + ey * ey) + ez * ez > 1e-3);
	}
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(open3d)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	if (br) {
		r1[0] = xsub(n[1], n[2], bad); r1[1] = xneg(n[0]); r1[2] = n[0];
	} else {
		r1[0] = n[1]; r1[1] = xsub(n[2], n[0], bad); r1[2] = xneg(n[1]);
	}
	if (is_zero(r1[0]) && is_zero(r1[1]) && is_zero(r1[2])) { /* Eigen returns it unchanged */
		xset3(r2, 0.0, 0.0, 0.0);
		return;
	}
	xnormalize(r1, bad);
	xcross(r2, n, r1, bad);
	xnormalize(r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "far from the guard: b1 = unit(y - z, -x, x)" : "near the guard's point: b1 = unit(y, z - x, -y)";
}

static int zero3(mpfr_t *v) { return mpfr_zero_p(v[0]) && mpfr_zero_p(v[1]) && mpfr_zero_p(v[2]); }

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	if (br) {
		mpfr_sub(r1[0], n[1], n[2], R); mpfr_neg(r1[1], n[0], R); mpfr_set(r1[2], n[0], R);
	} else {
		mpfr_set(r1[0], n[1], R); mpfr_sub(r1[1], n[2], n[0], R); mpfr_neg(r1[2], n[1], R);
	}
	if (zero3(r1)) { /* Eigen's normalized() returns a zero vector unchanged */
		kit_set3(r2, 0.0, 0.0, 0.0);
		return;
	}
	kit_normalize(c, r1);
	kit_cross(c, r2, n, r1);
	kit_normalize(c, r2);
}

/* Eigen's squaredNorm: (v0^2 + v1^2) + v2^2 for a Vector3d,
   v0^2 + (v1^2 + v2^2) for a Vector3f */
static cv sqnorm(cm *c, int P, const cv v[3])
{
	if (P == PREC_DOUBLE)
		return mk_dot3_xf(c, P, v, v);
	if (c->contract)   /* as GCC fuses it: fma(x, x, fma(y, y, z*z)) */
		return MADD(v[0], v[0], MADD(v[1], v[1], MUL(v[2], v[2])));
	return ADD(MUL(v[0], v[0]), ADD(MUL(v[1], v[1]), MUL(v[2], v[2])));
}

/* normalized(): if |v|^2 > 0, three divisions by sqrt(|v|^2) */
static void normalized(cm *c, int P, int id, cv v[3])
{
	const cv s2 = sqnorm(c, P, v);
	int i;
	if (cm_branch(c, id, CM_GT, s2, K(0.0))) {
		const cv s = cm_sqrt(c, P, s2);
		for (i = 0; i < 3; i++)
			v[i] = DIV(v[i], s);
	}
}

static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const int fixed = m->norm == ONB__WILD_FIXED;
	const cv a = K(fixed ? 0x1.6a09e667f3bcdp-1 : 1.0);
	cv d[3], e[3];
	d[0] = SUB(K(0.0), n[0]); d[1] = SUB(a, n[1]); d[2] = SUB(a, n[2]);
	e[0] = ADD(K(0.0), n[0]); e[1] = ADD(a, n[1]); e[2] = ADD(a, n[2]);
	if (cm_branch(c, 0, CM_GT, sqnorm(c, P, d), K(1e-3)) && (!fixed || cm_branch(c, 3, CM_GT, sqnorm(c, P, e), K(1e-3)))) {
		out[0] = SUB(n[1], n[2]); out[1] = cm_neg(c, n[0]); out[2] = n[0];
	} else {
		out[0] = n[1]; out[1] = SUB(n[2], n[0]); out[2] = cm_neg(c, n[1]);
	}
	normalized(c, P, 1, out);
	mk_cross_fused(c, P, n, out, out + 3, "ssf");  /* as GCC fuses it */
	mk_note_cross(c, 1, out + 3);
	normalized(c, P, 2, out + 3);
}

/* b1 and b2 normalized, b1 = unit(n x a), b2 = unit(n x b1): all five */
static unsigned zero_any_n(const onb_method *m) { (void)m; return CQ_ALL; }

static const char *singular(const onb_method *m)
{
	if (m->norm == ONB__WILD_FIXED)
		return "none";
	return "n parallel to (0,1,1): b1 = b2 = 0 (finite; defect 1), and near it where |n.x| and n.y - n.z underflow";
}

/* The line meets the sphere at (0, c, c) (azimuth 90 degrees) and
   (0, -c, -c) (azimuth 270); a small margin keeps the region test safe. */
static int meets_singular(const onb_method *m, double nz_lo, double nz_hi, double phi_lo, double phi_hi)
{
	const double e = 1e-9;
	if (m->norm == ONB__WILD_FIXED)
		return 0;
	return (nz_lo <= C45 + e && nz_hi >= C45 - e && phi_lo <= 90.0 + e && phi_hi >= 90.0 - e) ||
	       (nz_lo <= -C45 + e && nz_hi >= -C45 - e && phi_lo <= 270.0 + e && phi_hi >= 270.0 - e);
}

FAMILY_DECLARE(open3d);
const study_family family_open3d = {
	"open3d", FAMILY_PASSES(open3d), names, mpfr, FAMILY_PAIRS(open3d), family_no_variant,
	family_no_exact_zero, model, 4, zero_any_n, singular, meets_singular,
	family_fma_model,
};
#endif
