/*
 * jolt.c - Jolt Physics' Vec3::GetNormalizedPerpendicular and contact
 * tangents: b1 = (z, 0, -x)/|.| when x^2 > y^2 (the squares rounded in
 * the format), else (0, z, -y)/|.|; b2 = n x b1.  jolt_fma (variant
 * ONB__WILD_FMA) is the same formula with the cross product fused as
 * Jolt's default x86 build compiles it.  jolt_arm64 (variant
 * ONB__WILD_SCALAR) negates with unary minus (Jolt's non-SSE path).
 */
#include <math.h>
#include "families/family.h"

#define R MPFR_RNDN

#if FAMILY_RULE_PASS
/* 1 when x*x > y*y, the squares rounded in the format */
int FAMILY_BRANCH(jolt)(const onb_method *m, int prec, const double n[3])
{
	(void)m;
	if (prec == PREC_FLOAT) {
		const float x = (float)n[0], y = (float)n[1];
		return x * x > y * y;
	}
	if (prec == PREC_HALF)
		return prec_half_round(n[0] * n[0]) > prec_half_round(n[1] * n[1]);
	return n[0] * n[0] > n[1] * n[1];
}
#endif

#if FAMILY_PAIR_PASS
void FAMILY_PAIR(jolt)(const onb_method *m, int br, const double loc[3], const xv *n, xv *r1, xv *r2, int *bad)
{
	(void)m; (void)loc;
	xperp_cross(br ? 1 : 0, br ? +1 : -1, n, r1, r2, bad);
}
#endif

#if FAMILY_MAIN_PASS
#include "model/model_kit.h"

static const char *names(const onb_method *m, int b, char *buf, size_t n)
{
	(void)m; (void)buf; (void)n;
	return b ? "x^2 > y^2: b1 = (z, 0, -x) / len" : "x^2 <= y^2: b1 = (0, z, -y) / len";
}

static void mpfr(mpfr_kit *c, const onb_method *m, int br, const double loc[3], mpfr_t *n, mpfr_t *r1, mpfr_t *r2)
{
	(void)m; (void)loc;
	kit_perp_cross(c, br ? 1 : 0, br ? +1 : -1, n, r1, r2);   /* (z, 0, -x) or (0, z, -y) */
}

/* The squares, the compare of the rounded squares, one sqrt, three
   divisions (0 - v negates: exact); then Cross, fused as
   fma(b1[i+2], n[i+1], -(n[i+2] b1[i+1])) in the FMA build. */
static void model(cm *c, int P, const onb_method *m, const cv n[3], cv out[6])
{
	const cv xx = MUL(n[0], n[0]), yy = MUL(n[1], n[1]), zz = MUL(n[2], n[2]);
	const int sc = m->norm == ONB__WILD_SCALAR;   /* jolt_arm64: -x, sqrt(max(xx, yy) + zz) */
	cv len;
	int i;
	if (cm_branch(c, 0, CM_GT, xx, yy)) {
		len = cm_sqrt(c, P, sc ? MADD(n[2], n[2], xx) : ADD(xx, zz));
		out[0] = DIV(n[2], len); out[1] = DIV(K(0.0), len); out[2] = DIV(sc ? cm_neg(c, n[0]) : SUB(K(0.0), n[0]), len);
	} else {
		len = cm_sqrt(c, P, sc ? MADD(n[2], n[2], yy) : ADD(yy, zz));
		out[0] = DIV(K(0.0), len); out[1] = DIV(n[2], len); out[2] = DIV(sc ? cm_neg(c, n[1]) : SUB(K(0.0), n[1]), len);
	}
	if (m->norm != ONB__WILD_FMA) {
		mk_cross_out(c, P, n, out, 1, 1, P == PREC_FLOAT ? "fff" : "ssf");  /* as GCC fuses them (vectorized in double) */
		return;
	}
	for (i = 0; i < 3; i++) {
		const int j = (i + 1) % 3, k = (i + 2) % 3;
		out[3 + i] = cm_fma(c, P, out[k], n[j], cm_neg(c, MUL(n[k], out[j])));
	}
	mk_note_cross(c, 1, out + 3);   /* b2 = cross(n, b1), fused: the cross rule holds */
}

static unsigned zero_any_n(const onb_method *m) { (void)m; return ZN_UNIT_B1; }

/* jolt and jolt_fma: the model above is also the --fma copy's; jolt_arm64's
   copy (the scalar path) fuses otherwise, and no contracted model of it is
   written (tests/test_certify.c found 159 of 5000 float inputs differing) */
static int fma_model(const onb_method *m) { return m->norm != ONB__WILD_SCALAR; }

FAMILY_DECLARE(jolt);
const study_family family_jolt = {
	"jolt", FAMILY_PASSES(jolt), names, mpfr, FAMILY_PAIRS(jolt), family_no_variant,
	family_no_exact_zero, model, 1, zero_any_n, family_no_singular, family_meets_none,
	fma_model,
};
#endif
