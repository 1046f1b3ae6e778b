/*
 * test_ziv.c - the reference's roundings against n/|n| (ref_round_quot,
 * src/reference/ziv.c): RN of S/sqrt(Q) - z correct however close the
 * exact value lies to a rounding boundary, where one product by a
 * rounded 1/|n| rounds twice.  Run: build/tests/test_ziv.
 */
#include <stdio.h>
#include <string.h>
#include <math.h>
#include <mpfr.h>
#include "reference/ziv.h"
#include "common/prec.h"
#include "check.h"

static int same(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* S = 3 (M + d) with M = 1 + 2^-53 (the midpoint of 1 and 1 + 2^-52),
   Q = 9: S/sqrt(Q) - z = M + d - z exactly */
static double midpoint_case(long dexp, int dsign, double z)
{
	mpfr_t s0, s1, q0;
	mpfr_ptr s[2], q[1];
	double r;
	mpfr_inits2(4096, s0, s1, q0, (mpfr_ptr)0);
	mpfr_set_d(s0, 1.0, MPFR_RNDN);
	mpfr_add_d(s0, s0, 0x1p-53, MPFR_RNDN);
	mpfr_add_d(s0, s0, z, MPFR_RNDN);
	mpfr_mul_ui(s0, s0, 3, MPFR_RNDN);        /* 3 (M + z), exact */
	mpfr_set_si_2exp(s1, 3 * dsign, dexp, MPFR_RNDN); /* 3 d */
	mpfr_set_ui(q0, 9, MPFR_RNDN);
	s[0] = s0; s[1] = s1; q[0] = q0;
	r = ref_round_quot(s, 2, q, 1, z, ref_format_of(PREC_DOUBLE));
	mpfr_clears(s0, s1, q0, (mpfr_ptr)0);
	return r;
}

/* random dots against a 20000-bit evaluation rounded once */
static void random_cases(int count)
{
	gmp_randstate_t st;
	mpfr_t s[3], q[3], a, b, v;
	mpfr_ptr sp[3], qp[3];
	int i, j, bad = 0;
	gmp_randinit_default(st);
	gmp_randseed_ui(st, 1);
	for (j = 0; j < 3; j++) {
		mpfr_inits2(106, s[j], q[j], (mpfr_ptr)0);
		sp[j] = s[j]; qp[j] = q[j];
	}
	mpfr_inits2(20000, a, b, v, (mpfr_ptr)0);
	for (i = 0; i < count; i++) {
		double z = i % 2 ? 0.0 : 0.5, got, want;
		for (j = 0; j < 3; j++) {
			mpfr_urandomb(a, st); mpfr_urandomb(b, st);
			mpfr_set_d(a, mpfr_get_d(a, MPFR_RNDN) - 0.5, MPFR_RNDN);
			mpfr_set_d(b, ldexp(mpfr_get_d(b, MPFR_RNDN) + 0.5, -(i % 40)), MPFR_RNDN);
			mpfr_mul(s[j], a, b, MPFR_RNDN);       /* a product of doubles: exact */
			mpfr_sqr(q[j], b, MPFR_RNDN);
		}
		got = ref_round_quot(sp, 3, qp, 3, z, ref_format_of(PREC_DOUBLE));
		mpfr_sum(a, qp, 3, MPFR_RNDN);
		mpfr_rec_sqrt(a, a, MPFR_RNDN);
		mpfr_sum(v, sp, 3, MPFR_RNDN);
		mpfr_mul(v, v, a, MPFR_RNDN);
		mpfr_sub_d(v, v, z, MPFR_RNDN);
		want = mpfr_get_d(v, MPFR_RNDN);
		bad += !same(got, want);
	}
	CHECK(bad == 0, "%d of %d random quotients differ from a 20000-bit evaluation", bad, count);
	for (j = 0; j < 3; j++)
		mpfr_clears(s[j], q[j], (mpfr_ptr)0);
	mpfr_clears(a, b, v, (mpfr_ptr)0);
	gmp_randclear(st);
}

int main(void)
{
	const double up = 1.0 + 0x1p-52;
	double r;
	/* just above and just below the midpoint, by far less than 2^-127 */
	r = midpoint_case(-300, 1, 0.0);
	CHECK(same(r, up), "M + 2^-300 rounded to %a, not %a", r, up);
	r = midpoint_case(-300, -1, 0.0);
	CHECK(same(r, 1.0), "M - 2^-300 rounded to %a, not 0x1p+0", r);
	r = midpoint_case(-5000, 1, 0.0);
	CHECK(same(r, up), "M + 2^-5000 rounded to %a, not %a", r, up);
	/* the difference with z: (M + z + d) - z */
	r = midpoint_case(-300, 1, 0.25);
	CHECK(same(r, up), "(M + 0.25 + 2^-300) - 0.25 rounded to %a, not %a", r, up);
	/* an exact tie beyond the cap goes to even, an exact zero is +0 */
	{
		mpfr_t s0, q0;
		mpfr_ptr s[1], q[1];
		mpfr_inits2(200, s0, q0, (mpfr_ptr)0);
		mpfr_set_d(s0, 3.0, MPFR_RNDN);
		mpfr_set_ui(q0, 9, MPFR_RNDN);
		s[0] = s0; q[0] = q0;
		r = ref_round_quot(s, 1, q, 1, 1.0, ref_format_of(PREC_DOUBLE));
		CHECK(same(r, 0.0), "3/sqrt(9) - 1 rounded to %a, not +0", r);
		mpfr_set_zero(s0, 1);
		r = ref_round_quot(s, 1, q, 1, 0.0, ref_format_of(PREC_DOUBLE));
		CHECK(same(r, 0.0), "0/sqrt(9) rounded to %a, not +0", r);
		mpfr_set_d(s0, 3.0 * (1.0 + 0x1p-52), MPFR_RNDN);
		mpfr_add_d(s0, s0, 3.0 * 0x1p-53, MPFR_RNDN);
		r = ref_round_quot(s, 1, q, 1, 0.0, ref_format_of(PREC_DOUBLE));
		CHECK(same(r, 1.0 + 0x1p-51), "the exact tie 1 + 3 2^-53 rounded to %a, not to even", r);
		mpfr_clears(s0, q0, (mpfr_ptr)0);
	}
	random_cases(2000);
	return check_finish("test_ziv");
}
