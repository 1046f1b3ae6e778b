/*
 * test_babylon_node.c - the `babylon` row against Node.js itself: every
 * row of tests/data/babylon_node.csv (scripts/babylon-node.sh: Babylon.js's
 * getNormalToRef, normalize() and CrossToRef run by node v20.20.2, V8
 * 11.3.244.8) must be the bits of onb_babylon (the inline kernel and
 * libonb's out-of-line copy), and onb_babylonf on the same input rounded
 * to float (where the input is a float) the golden b1, b2 rounded to
 * float.  NaN matches NaN (JavaScript has one NaN).  This is the check of
 * src/lib/fdlibm.c (V8's fdlibm) and of the kernel's operation order: a
 * libm other than V8's differs (glibc 2.36's atan2, sin and cos differ from
 * it on 63777 of 1.8 million values, docs/wild-specs/babylon.md).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <inttypes.h>
#include "libonb/onb.h"

static double of_bits(uint64_t u) { double d; memcpy(&d, &u, sizeof d); return d; }
static uint64_t bits(double d) { uint64_t u; memcpy(&u, &d, sizeof u); return u; }
static int same(double a, double b) { return bits(a) == bits(b) || (a != a && b != b); }
static int samef(float a, float b)
{
	uint32_t x, y;
	memcpy(&x, &a, sizeof x);
	memcpy(&y, &b, sizeof y);
	return x == y || (a != a && b != b);
}

int main(int argc, char **argv)
{
	const char *path = argc > 1 ? argv[1] : "tests/data/babylon_node.csv";
	FILE *f = fopen(path, "r");
	char line[512];
	long rows = 0, bad = 0, badf = 0, nf = 0;
	if (!f) {
		printf("FAIL test_babylon_node: cannot read %s\n", path);
		return 1;
	}
	while (fgets(line, sizeof line, f)) {
		uint64_t v[9];
		double d[9];
		onb_vec3 n, b1, b2, o1, o2;
		int i, float_input;
		if (sscanf(line, "%" SCNx64 ",%" SCNx64 ",%" SCNx64 ",%" SCNx64 ",%" SCNx64 ",%" SCNx64 ",%" SCNx64
		           ",%" SCNx64 ",%" SCNx64, &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6], &v[7], &v[8]) != 9)
			continue;   /* the comment and the header */
		for (i = 0; i < 9; i++)
			d[i] = of_bits(v[i]);
		n.x = d[0]; n.y = d[1]; n.z = d[2];
		onb_babylon(n, &b1, &b2);
		onb_babylon_outline(n, &o1, &o2);
		rows++;
		{
			const double got[6] = { b1.x, b1.y, b1.z, b2.x, b2.y, b2.z };
			const double out[6] = { o1.x, o1.y, o1.z, o2.x, o2.y, o2.z };
			int ok = 1;
			for (i = 0; i < 6; i++)
				ok &= same(got[i], d[3 + i]) && same(out[i], d[3 + i]);
			if (!ok && bad++ < 5)
				printf("FAIL babylon (%a, %a, %a): b1 (%a, %a, %a), b2 (%a, %a, %a); node b1 (%a, %a, %a), b2 (%a, %a, %a)\n",
				       n.x, n.y, n.z, got[0], got[1], got[2], got[3], got[4], got[5], d[3], d[4], d[5], d[6], d[7], d[8]);
		}
		{   /* through volatile floats: GCC at -O3 may keep a (double)(float) pair unrounded */
			volatile float fx = (float)n.x, fy = (float)n.y, fz = (float)n.z;
			float_input = (double)fx == n.x && (double)fy == n.y && (double)fz == n.z;
		}
		if (float_input) {
			onb_vec3f nf3, f1, f2;
			nf3.x = (float)n.x; nf3.y = (float)n.y; nf3.z = (float)n.z;
			onb_babylonf(nf3, &f1, &f2);
			nf++;
			{
				const float got[6] = { f1.x, f1.y, f1.z, f2.x, f2.y, f2.z };
				int ok = 1;
				for (i = 0; i < 6; i++)
					ok &= samef(got[i], (float)d[3 + i]);
				if (!ok && badf++ < 5)
					printf("FAIL babylonf (%a, %a, %a): not node's bits rounded to float\n", n.x, n.y, n.z);
			}
		}
	}
	fclose(f);
	if (rows < 700 || nf < 10) {
		printf("FAIL test_babylon_node: %ld rows (%ld float inputs) in %s, expected 800 (16)\n", rows, nf, path);
		return 1;
	}
	printf("test_babylon_node: %ld inputs, %ld differ from node's bits (double); %ld float inputs, %ld differ\n",
	       rows, bad, nf, badf);
	return bad || badf ? 1 : 0;
}
