/*
 * bits.c - one client of onb.h + libonb.a, built four ways by
 * tests/lib_client.sh:
 *   -DMODE_GEN      prints the inputs (hex floats), from integers only;
 *   -DMODE_REF      the studied bits: the inline functions, built with the
 *                   library's flags;
 *   -DMODE_OUTLINE  onb_NAME_outline[f] through onb_vec3[f];
 *   -DMODE_ARRAY    the renderer's own float[3]/double[3] vectors through
 *                   onb_NAME_array[f] and onb_basis_array[f].
 * OUTLINE and ARRAY are built with -ffast-math (and ONB_ALLOW_FAST_MATH)
 * or -ffp-contract=fast; their output must equal REF's, bit for bit.
 * Every run prints "method x y z | b1 | b2" in %a, one line per input and
 * precision.
 */
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include <math.h>
#include "libonb/onb.h"

typedef float  my_vec3f[3]; /* a renderer's own vector types */
typedef double my_vec3[3];

#define NAMES(m) #m,
static const char *const names[] = { ONB_METHOD_LIST(NAMES) };
#undef NAMES

#ifdef MODE_GEN
/* Unit-ish directions from integers: exact conversions only. */
int main(void)
{
	uint32_t s = 12345u;
	int i, c;
	static const double fixed[][3] = {
		{ 0, 0, 1 }, { 0x1p-12, 0x1p-13, -1 }, { 0x1p-9, 0, -0x1.fffffcp-1 },
		{ -0x1.d5p-1, 0x1.1p-2, 0x1p-3 }, { 0x1.ccp-1, 0x1p-1, 0x1p-4 } };
	for (i = 0; i < 5; i++)
		printf("%a %a %a\n", fixed[i][0], fixed[i][1], fixed[i][2]);
	for (i = 0; i < 200; i++) {
		double v[3], l;
		for (c = 0; c < 3; c++) {
			s = s * 1664525u + 1013904223u;
			v[c] = ((double)(int32_t)s) * 0x1p-31; /* exact */
		}
		l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
		if (l > 0x1p-4)
			printf("%a %a %a\n", v[0] / l, v[1] / l, v[2] / l);
	}
	return 0;
}
#else
static void put(const char *m, const char *p, double x, double y, double z,
		const double b1[3], const double b2[3])
{
	printf("%s %s %a %a %a | %a %a %a | %a %a %a\n", m, p, x, y, z,
	       b1[0], b1[1], b1[2], b2[0], b2[1], b2[2]);
}

#if defined(MODE_REF) || defined(MODE_OUTLINE)
/* One function per method, as a renderer calls one method at a time: with
   every kernel inlined into run(), GCC 12.2 -O2's basic-block vectorizer
   gave pbrt_v3 float's b2.x one ulp off the source's arithmetic (it used
   n.y before its rounding to float) at 0x1.6d40747170d7fp-5
   0x1.283def0758f38p-5 -0x1.ff27d65569aaap-1, in the reference and in
   the inline clients alike; not reduced to a small case. */
#if defined(__GNUC__)
#define NOINLINE __attribute__((noinline))
#else
#define NOINLINE
#endif
#ifdef MODE_REF
#define DEF(mm) static NOINLINE void call_##mm(onb_vec3 v, onb_vec3f vf, onb_vec3 *u1, onb_vec3 *u2, onb_vec3f *g1, onb_vec3f *g2) \
	{ onb_##mm(v, u1, u2); onb_##mm##f(vf, g1, g2); }
#else
#define DEF(mm) static NOINLINE void call_##mm(onb_vec3 v, onb_vec3f vf, onb_vec3 *u1, onb_vec3 *u2, onb_vec3f *g1, onb_vec3f *g2) \
	{ onb_##mm##_outline(v, u1, u2); onb_##mm##_outlinef(vf, g1, g2); }
#endif
ONB_METHOD_LIST(DEF)
#undef DEF
#endif

/* One method, one input, both precisions. */
static void run(size_t k, double x, double y, double z)
{
	const onb_method *m = onb_find(names[k]);
	double n[3], b1[3], b2[3], w1[3], w2[3];
	float nf[3], f1[3], f2[3];
	int c;
	n[0] = x; n[1] = y; n[2] = z;
	nf[0] = (float)x; nf[1] = (float)y; nf[2] = (float)z;
#if defined(MODE_REF) || defined(MODE_OUTLINE)
	{
		onb_vec3 v = { x, y, z }, u1, u2;
		onb_vec3f vf = { (float)x, (float)y, (float)z }, g1, g2;
		size_t i_ = 0;
#define CALL(mm) if (k == i_) call_##mm(v, vf, &u1, &u2, &g1, &g2); i_++;
		ONB_METHOD_LIST(CALL)
#undef CALL
		b1[0] = u1.x; b1[1] = u1.y; b1[2] = u1.z; b2[0] = u2.x; b2[1] = u2.y; b2[2] = u2.z;
		f1[0] = g1.x; f1[1] = g1.y; f1[2] = g1.z; f2[0] = g2.x; f2[1] = g2.y; f2[2] = g2.z;
	}
#else
	{
		my_vec3 nn, a1, a2;
		my_vec3f nnf, c1, c2, d1, d2;
		size_t i_ = 0;
		memcpy(nn, n, sizeof nn); memcpy(nnf, nf, sizeof nnf);
#define CALL(mm) if (k == i_) { onb_##mm##_array(nn, a1, a2); onb_##mm##_arrayf(nnf, c1, c2); } i_++;
		ONB_METHOD_LIST(CALL)
#undef CALL
		/* the registry's array call must agree with the named one */
		if (onb_basis_arrayf(m, nnf, d1, d2) != ONB_OK || memcmp(c1, d1, sizeof c1) || memcmp(c2, d2, sizeof c2) ||
		    onb_basis_array(m, nn, b1, b2) != ONB_OK || memcmp(a1, b1, sizeof a1) || memcmp(a2, b2, sizeof a2)) {
			fprintf(stderr, "%s: onb_basis_array differs from onb_%s_array\n", names[k], names[k]);
			exit(1);
		}
		memcpy(b1, a1, sizeof b1); memcpy(b2, a2, sizeof b2);
		memcpy(f1, c1, sizeof f1); memcpy(f2, c2, sizeof f2);
	}
#endif
	put(names[k], "double", x, y, z, b1, b2);
	for (c = 0; c < 3; c++) { w1[c] = (double)f1[c]; w2[c] = (double)f2[c]; }
	put(names[k], "float", (double)nf[0], (double)nf[1], (double)nf[2], w1, w2);
	(void)m;
}

/* The float-only methods (ONB_FLOAT_METHOD_LIST): float lines only. */
#define FNAMES(m) #m,
static const char *const fnames[] = { ONB_FLOAT_METHOD_LIST(FNAMES) };
#undef FNAMES
static void runf(size_t k, double x, double y, double z)
{
	float nf[3], f1[3], f2[3];
	double w1[3], w2[3];
	size_t i_ = 0;
	int c;
	nf[0] = (float)x; nf[1] = (float)y; nf[2] = (float)z;
#if defined(MODE_REF) || defined(MODE_OUTLINE)
	{
		onb_vec3f vf = { nf[0], nf[1], nf[2] }, g1, g2;
#ifdef MODE_REF
#define CALL(mm) if (k == i_) onb_##mm##f(vf, &g1, &g2); i_++;
#else
#define CALL(mm) if (k == i_) onb_##mm##_outlinef(vf, &g1, &g2); i_++;
#endif
		ONB_FLOAT_METHOD_LIST(CALL)
#undef CALL
		f1[0] = g1.x; f1[1] = g1.y; f1[2] = g1.z; f2[0] = g2.x; f2[1] = g2.y; f2[2] = g2.z;
	}
#else
	{
		my_vec3f nnf, d1, d2;
		memcpy(nnf, nf, sizeof nnf);
#define CALL(mm) if (k == i_) onb_##mm##_arrayf(nnf, f1, f2); i_++;
		ONB_FLOAT_METHOD_LIST(CALL)
#undef CALL
		if (onb_basis_arrayf(onb_find(fnames[k]), nnf, d1, d2) != ONB_OK || memcmp(f1, d1, sizeof d1) || memcmp(f2, d2, sizeof d2)) {
			fprintf(stderr, "%s: onb_basis_arrayf differs from onb_%s_arrayf\n", fnames[k], fnames[k]);
			exit(1);
		}
	}
#endif
	for (c = 0; c < 3; c++) { w1[c] = (double)f1[c]; w2[c] = (double)f2[c]; }
	put(fnames[k], "float", (double)nf[0], (double)nf[1], (double)nf[2], w1, w2);
}

int main(void)
{
	char line[256];
	size_t k, nm = sizeof names / sizeof names[0], nf = sizeof fnames / sizeof fnames[0];
	while (fgets(line, sizeof line, stdin)) {
		char *e;
		double x = strtod(line, &e), y = strtod(e, &e), z = strtod(e, &e);
		for (k = 0; k < nm; k++)
			run(k, x, y, z);
		for (k = 0; k < nf; k++)
			runf(k, x, y, z);
	}
	return 0;
}
#endif
