/*
 * babylon.c - Babylon.js's Vector3.getNormalToRef (math.vector.ts) as
 * JavaScript evaluates it (double, V8's fdlibm: src/lib/fdlibm.c),
 * completed with normalize() and b2 = Vector3.CrossToRef(n, b1).
 *
 * The exact formula.  With r = |n|, rho = sqrt(x^2 + z^2), theta =
 * acos(y/r) and phi = atan2(z, x): cos(phi) = x/rho, sin(phi) = z/rho,
 * cos(theta) = y/r, sin(theta) = rho/r.  Branch 0 (theta <= PI/2 as the
 * kernel decides) takes theta + PI/2: sin = cos(theta), cos = -sin(theta);
 * branch 1 takes theta - PI/2: sin = -cos(theta), cos = sin(theta).  So
 * the result r (sin cos(phi), cos, sin sin(phi)) is s (x y, -rho^2, z y) /
 * rho with s = +1 on branch 0, -1 on branch 1, and b1 = s (x y, -(x^2 +
 * z^2), z y) normalized, b2 = n x b1: algebraic, no trigonometry.  At
 * rho = 0 (x = z = +-0: +-y) the formula is 0/0; the kernel's atan2(+-0,
 * +-0) is +-0 or +-pi there (cos = +1 for x = +0, -1 for x = -0) and
 * theta' = PI/2 on both branches, so b1 = (copysign(1, x), 0, 0) exactly.
 *
 * The model runs the kernel's operations with cm_libm for the four fdlibm
 * calls: bit-exact in CM_EXEC (tests/test_certify.c), no bound in CM_MVF
 * (certify: not bounded, docs/wild-specs/babylon.md).  The float (and
 * binary16) row is the double row on n widened, rounded once at the end.
 */
#include <math.h>
#include "families/family.h"

#if FAMILY_RULE_PASS
/* 0: acos(y/r) <= PI/2 (theta + PI/2), 1: acos(y/r) > PI/2 (theta - PI/2),
   as the kernel computes them (in double for both precisions) */
int FAMILY_BRANCH(babylon)(const onb_method *m, int prec, const double n[3])
{
	const double x = n[0], y = n[1], z = n[2];
	const double radius = sqrt(x * x + y * y + z * z);
	(void)m; (void)prec;
	return onb__fdlibm_acos(y / radius) > 0x1.921fb54442d18p+0 ? 1 : 0;
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(babylon)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	if (is_zero(n[0]) && is_zero(n[2])) {
		xset3(r1, signbit(n[0].h) ? -1.0 : 1.0, 0.0, 0.0);
	} else {
		const xv s = xc(br ? -1.0 : 1.0);
		r1[0] = xmul(s, xmul(n[0], n[1], bad), bad);
		r1[1] = xneg(xmul(s, xadd(xmul(n[0], n[0], bad), xmul(n[2], n[2], bad), bad), bad));
		r1[2] = xmul(s, xmul(n[2], n[1], bad), bad);
		xnormalize(r1, bad);
	}
	xcross(r2, n, r1, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b == 0 ? "acos(y/r) <= PI/2: theta + PI/2, b1 = (x y, -(x^2 + z^2), z y)/|.|"
	              : "acos(y/r) > PI/2: theta - PI/2, b1 = -(x y, -(x^2 + z^2), z y)/|.|";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	if (mpfr_zero_p(n[0]) && mpfr_zero_p(n[2])) {
		kit_set3(r1, mpfr_signbit(n[0]) ? -1.0 : 1.0, 0.0, 0.0);
	} else {
		mpfr_mul(r1[0], n[0], n[1], MPFR_RNDN);
		mpfr_mul(c->t[0], n[0], n[0], MPFR_RNDN);
		mpfr_mul(c->t[1], n[2], n[2], MPFR_RNDN);
		mpfr_add(r1[1], c->t[0], c->t[1], MPFR_RNDN);
		mpfr_neg(r1[1], r1[1], MPFR_RNDN);
		mpfr_mul(r1[2], n[2], n[1], MPFR_RNDN);
		if (br) {
			mpfr_neg(r1[0], r1[0], MPFR_RNDN);
			mpfr_neg(r1[1], r1[1], MPFR_RNDN);
			mpfr_neg(r1[2], r1[2], MPFR_RNDN);
		}
		kit_normalize(c, r1);
	}
	kit_cross(c, r2, n, r1);
}

/* The kernel's operations in double (float and binary16 inputs widened
   exactly, b1 and b2 rounded once at the end).  Two branch points: theta >
   PI/2, and normalize()'s length == 0 or 1 (one point: the scaling is
   skipped on either). */
static void model(cm *c, int P, const onb_method *m, const cv n0[3], cv out[6])
{
	const int D = PREC_DOUBLE;
	const cv pio2 = cm_cst(c, 0x1.921fb54442d18p+0);
	cv n[3], radius, theta, phi, st, x, y, z, len;
	int i;
	(void)m;
	for (i = 0; i < 3; i++)
		n[i] = P == D ? n0[i] : cm_cvt(c, D, n0[i]);
	radius = cm_sqrt(c, D, cm_add(c, D, cm_add(c, D, cm_mul(c, D, n[0], n[0]), cm_mul(c, D, n[1], n[1])),
	                              cm_mul(c, D, n[2], n[2])));
	theta = cm_libm(c, CM_ACOS, cm_div(c, D, n[1], radius), -1);
	phi = cm_libm(c, CM_ATAN2, n[2], n[0]);
	theta = cm_branch(c, 0, CM_GT, theta, pio2) ? cm_sub(c, D, theta, pio2) : cm_add(c, D, theta, pio2);
	st = cm_libm(c, CM_SIN, theta, -1);
	x = cm_mul(c, D, cm_mul(c, D, radius, st), cm_libm(c, CM_COS, phi, -1));
	y = cm_mul(c, D, radius, cm_libm(c, CM_COS, theta, -1));
	z = cm_mul(c, D, cm_mul(c, D, radius, st), cm_libm(c, CM_SIN, phi, -1));
	len = cm_sqrt(c, D, cm_add(c, D, cm_add(c, D, cm_mul(c, D, x, x), cm_mul(c, D, y, y)), cm_mul(c, D, z, z)));
	/* normalizeFromLength: unchanged where len === 0 or len === 1 */
	{
		const cv one = cm_cst(c, 1.0);
		const int lt1 = cm_branch(c, 1, CM_LT, len, one);
		const int gt1 = lt1 ? 0 : cm_branch(c, 2, CM_GT, len, one);
		const int gt0 = lt1 ? cm_branch(c, 3, CM_GT, len, cm_cst(c, 0.0)) : 0;
		if (gt1 || gt0) {
			const cv s = cm_div(c, D, one, len);
			x = cm_mul(c, D, x, s); y = cm_mul(c, D, y, s); z = cm_mul(c, D, z, s);
		}
	}
	/* Vector3.CrossToRef(n, b1) */
	out[0] = x; out[1] = y; out[2] = z;
	out[3] = cm_sub(c, D, cm_mul(c, D, n[1], z), cm_mul(c, D, n[2], y));
	out[4] = cm_sub(c, D, cm_mul(c, D, n[2], x), cm_mul(c, D, n[0], z));
	out[5] = cm_sub(c, D, cm_mul(c, D, n[0], y), cm_mul(c, D, n[1], x));
	if (P != D)
		for (i = 0; i < 6; i++)
			out[i] = cm_cvt(c, P, out[i]);
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return 0; }

/* b2 = n x b1 = s (z, 0, -x) r / rho (and (0, 0, -y copysign(1, x)) at the
   poles): b2.y is 0 for every n, which the MPFR and pair formulas compute
   as a rounding residue (adding-a-method.md: declared, or every input falls
   back to MPFR) */
static int exact_zero(const onb_method *m, int br) { (void)m; (void)br; return 4; }

FAMILY_DECLARE(babylon);
const study_family family_babylon = {
	"babylon", FAMILY_PASSES(babylon), names, mpfr, FAMILY_PAIRS(babylon), family_no_variant,
	exact_zero, model, 4, zero_any_n, family_no_singular, family_meets_none,
	family_no_fma_model,
};
#endif
