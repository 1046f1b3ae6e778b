/*
 * test_found.c - the found side's completion without MPFR is MPFR's.
 *
 * The walks complete every step's input to a domain member: (a, b) in the
 * format, |c| = sqrt(1 - a^2 - b^2) rounded to nearest.  found.c does that
 * in double arithmetic where double decides the rounding for certain, and
 * asks MPFR (cert_complete) elsewhere.  Here, on inputs from the equator
 * to 1 - |c| = 2^-80 (where |c| rounds to 1 or to one of the last floats or
 * doubles below it) and next to midpoints between them, every answer of
 * the fast path must be cert_complete's bits, and cert_complete must call
 * that rounding certain.  The share of inputs the fast path answers is
 * printed, and must be most of them (it is the walks' speed).
 *
 * The images pass (found_images.c) takes a domain member's 48 signed
 * permutations for members without asking: here cert_in_domain must give
 * every image of an input the input's own answer, on completed inputs and
 * on inputs whose largest component is an ulp off (members or not).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "certify/found.h"
#include "certify/probe.h"
#include "inputs/inputs.h"
#include "inputs/rng.h"

static double unif(uint64_t *s) { return (double)(rng_mix64((*s)++) >> 11) * 0x1p-53; }

/* (a, b) in the format at distance r from the axis, azimuth random;
   r = 0 and exact-midpoint inputs now and then. */
static void draw(uint64_t *s, int prec, long i, double *a, double *b)
{
	const double r = i % 97 == 0 ? 0.0 : exp2(-40.0 * unif(s)) * 0.86, phi = 6.283185307179586 * unif(s);
	*a = fmt_round(r * cos(phi), prec);
	*b = fmt_round(r * sin(phi), prec);
	if (i % 3 == 0) {
		/* |c| next to a midpoint m between two formats' numbers below 1:
		   a random, b the rounding of sqrt(1 - m^2 - a^2); the residual of
		   a^2 + b^2 is then within a few ulps of b^2, so about one input
		   in two lies nearer m than the fast path can decide */
		const int p = prec == PREC_FLOAT ? 24 : 53;
		const double h = (2.0 * floor(64.0 * unif(s)) + 1.0) * exp2(-p - 1);   /* 1 - m, exact */
		const double t = 2.0 * h - h * h;                                        /* 1 - m^2 */
		*a = fmt_round(sqrt(t) * unif(s), prec);
		*b = fmt_round(sqrt(fmax(0.0, t - *a * *a)), prec);
	}
}

static long check(cert_ctx *x, int prec, long count, long *fast)
{
	uint64_t s = 12345 + (uint64_t)prec;
	long i, bad = 0;
	*fast = 0;
	for (i = 0; i < count; i++) {
		double a, b, f, c;
		int sure;
		draw(&s, prec, i, &a, &b);
		f = found_complete_fast(prec, a, b);
		if (isnan(f))
			continue;
		(*fast)++;
		c = cert_complete(x, prec, a, b, &sure);
		if (a == 0.0 && b == 0.0)
			sure = 1;   /* |c| = 1 exactly: MPFR cannot call an exact 1 certain */
		if (!sure || memcmp(&c, &f, sizeof c) != 0) {
			if (bad++ < 5)
				printf("FAIL %s a %a b %a: fast %a, MPFR %a (%s)\n", prec_name(prec), a, b, f, c,
				       sure ? "certain" : "not certain");
		}
	}
	return bad;
}

/* The number of inputs some signed permutation of which cert_in_domain
   answers differently from the input itself. */
static long check_images(int prec, long count, long *members)
{
	uint64_t s = 777 + (uint64_t)prec;
	long i, bad = 0;
	*members = 0;
	for (i = 0; i < count; i++) {
		double a, b, n[3], m[3];
		int p[3], in, g;
		draw(&s, prec, i, &a, &b);
		n[0] = a;
		n[1] = b;
		n[2] = sqrt(fmax(0.0, 1.0 - a * a - b * b));
		n[2] = fmt_step(fmt_round(n[2], prec), (int64_t)(i % 3) - 1, prec);
		in = cert_in_domain(n, prec, -1.0);
		*members += in;
		for (g = 0; g < 48; g++) {
			p[0] = g % 3;
			p[1] = (p[0] + 1 + (g / 3) % 2) % 3;
			p[2] = 3 - p[0] - p[1];
			m[0] = (g / 6) & 1 ? -n[p[0]] : n[p[0]];
			m[1] = (g / 6) & 2 ? -n[p[1]] : n[p[1]];
			m[2] = (g / 6) & 4 ? -n[p[2]] : n[p[2]];
			if (cert_in_domain(m, prec, -1.0) != in) {
				if (bad++ < 5)
					printf("FAIL %s images: (%a, %a, %a) %s, its image (%a, %a, %a) not\n", prec_name(prec), n[0],
					       n[1], n[2], in ? "a member" : "no member", m[0], m[1], m[2]);
				break;
			}
		}
	}
	return bad;
}

int main(int argc, char **argv)
{
	const long count = argc > 1 ? atol(argv[1]) : 400000;
	cert_ctx *x = cert_ctx_new();
	int prec, fail = 0;
	if (!x || count <= 0)
		return 2;
	for (prec = PREC_FLOAT; prec <= PREC_DOUBLE; prec++) {
		long fast, bad = check(x, prec, count, &fast);
		const int few = fast < count / 2;
		printf("%s %-6s %ld inputs: the fast path answered %ld, %ld differ from MPFR%s\n",
		       bad || few ? "FAIL" : "ok  ", prec_name(prec), count, fast, bad,
		       few ? " (it should answer half or more)" : "");
		fail |= bad != 0 || few;
	}
	for (prec = PREC_FLOAT; prec <= PREC_DOUBLE; prec++) {
		long members, bad = check_images(prec, count / 100, &members);
		const int none = members == 0 || members == count / 100;
		printf("%s %-6s %ld inputs (%ld members): %ld with an image on the other side of the domain%s\n",
		       bad || none ? "FAIL" : "ok  ", prec_name(prec), count / 100, members, bad,
		       none ? " (both kinds should be drawn)" : "");
		fail |= bad != 0 || none;
	}
	cert_ctx_free(x);
	return fail;
}
