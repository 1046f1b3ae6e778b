/*
 * lib_cases.c - every registry method on the bad inputs (zero, non-finite, non-unit), in
 * double and float, through the scalar function, the batch kernel and
 * onb_basis_checked[f].  Built by scripts/robustness.sh with the library
 * sources and -fsanitize=address,undefined, so any memory error or
 * undefined behaviour stops it (a failure); a hang is caught by the
 * script's timeout.
 * Output, tab-separated, one line per method and input:
 *   method case double float batch_agrees checked_double checked_float
 * where double/float is the scalar output class: "finite" (all six
 * components finite), "NaN" (some component NaN) or "Inf" (some infinite,
 * none NaN); batch_agrees is "yes" when the batch kernel gives the same
 * class in both precisions; checked_* is the onb_status name, with
 * "+finite" when the basis it returned is finite.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "libonb/onb.h"

typedef struct { const char *name; double x, y, z; } kase;

static const char *cls(const double *o)
{
	int i, nan_ = 0, inf_ = 0;
	for (i = 0; i < 6; i++) {
		if (isnan(o[i])) nan_ = 1;
		else if (isinf(o[i])) inf_ = 1;
	}
	return nan_ ? "NaN" : inf_ ? "Inf" : "finite";
}

static const char *stname(onb_status s)
{
	switch (s) {
	case ONB_OK: return "OK";
	case ONB_RENORMALIZED: return "RENORMALIZED";
	case ONB_ZERO: return "ZERO";
	case ONB_NONFINITE: return "NONFINITE";
	case ONB_BAD_METHOD: return "BAD_METHOD";
	}
	return "?";
}

int main(void)
{
	const double s20 = 1e-20, b20 = 1e20;
	const kase cases[] = {
		{ "unit (0.48,0.6,0.64)", 0.48, 0.6, 0.64 },
		{ "(0,0,0)", 0.0, 0.0, 0.0 },
		{ "(-0,-0,-0)", -0.0, -0.0, -0.0 },
		{ "(0,0,-1)", 0.0, 0.0, -1.0 },
		{ "(-0,-0,-1)", -0.0, -0.0, -1.0 },
		{ "(-0,+0,+1)", -0.0, 0.0, 1.0 },
		{ "(NaN,0,1)", NAN, 0.0, 1.0 },
		{ "(0,NaN,1)", 0.0, NAN, 1.0 },
		{ "(0,0,NaN)", 0.0, 0.0, NAN },
		{ "(Inf,0,0)", INFINITY, 0.0, 0.0 },
		{ "(0,Inf,0)", 0.0, INFINITY, 0.0 },
		{ "(0,0,+Inf)", 0.0, 0.0, INFINITY },
		{ "(0,0,-Inf)", 0.0, 0.0, -INFINITY },
		{ "(sub,sub,sub)", -1.0, -1.0, -1.0 },   /* smallest subnormal of the format */
		{ "(sub,0,-1)", -2.0, 0.0, -1.0 },       /* x = that subnormal, z = -1 */
		{ "norm 1e-20", 0.48 * s20, 0.6 * s20, 0.64 * s20 },
		{ "norm 1e20", 0.48 * b20, 0.6 * b20, 0.64 * b20 },
	};
	const size_t nc = sizeof cases / sizeof cases[0];
	size_t nm, i, c;
	const onb_method *ms = onb_methods(&nm);
	for (i = 0; i < nm; i++) {
		const onb_method *m = &ms[i];
		for (c = 0; c < nc; c++) {
			onb_vec3 n, b1, b2;
			onb_vec3f nf, b1f, b2f;
			double od[6], of[6], bd[6], bf[6];
			float fin[3], fout[6];
			double din[3];
			onb_status sd, sf;
			int k, fd, ff;
			n.x = cases[c].x; n.y = cases[c].y; n.z = cases[c].z;
			nf.x = (float)n.x; nf.y = (float)n.y; nf.z = (float)n.z;
			if (cases[c].x == -1.0) { /* all subnormal */
				n.x = n.y = n.z = 4.9406564584124654e-324;
				nf.x = nf.y = nf.z = 1.40129846e-45f;
			} else if (cases[c].x == -2.0) {
				n.x = 4.9406564584124654e-324;
				nf.x = 1.40129846e-45f;
			}
			for (k = 0; k < 6; k++)
				od[k] = bd[k] = 0.0;
			if (m->basis) /* NULL for the float-only methods */
				m->basis(n, &b1, &b2);
			else
				b1 = b2 = n;
			od[0] = b1.x; od[1] = b1.y; od[2] = b1.z; od[3] = b2.x; od[4] = b2.y; od[5] = b2.z;
			m->basisf(nf, &b1f, &b2f);
			of[0] = b1f.x; of[1] = b1f.y; of[2] = b1f.z; of[3] = b2f.x; of[4] = b2f.y; of[5] = b2f.z;
			din[0] = n.x; din[1] = n.y; din[2] = n.z;
			if (m->batch)
				m->batch(1, &din[0], &din[1], &din[2], &bd[0], &bd[1], &bd[2], &bd[3], &bd[4], &bd[5]);
			fin[0] = nf.x; fin[1] = nf.y; fin[2] = nf.z;
			m->batchf(1, &fin[0], &fin[1], &fin[2], &fout[0], &fout[1], &fout[2], &fout[3], &fout[4], &fout[5]);
			for (k = 0; k < 6; k++)
				bf[k] = fout[k];
			sd = onb_basis_checked(m, n, &b1, &b2, NULL);
			fd = isfinite(b1.x) && isfinite(b1.y) && isfinite(b1.z) && isfinite(b2.x) && isfinite(b2.y) && isfinite(b2.z);
			sf = onb_basis_checkedf(m, nf, &b1f, &b2f, NULL);
			ff = isfinite(b1f.x) && isfinite(b1f.y) && isfinite(b1f.z) && isfinite(b2f.x) && isfinite(b2f.y) && isfinite(b2f.z);
			printf("%s\t%s\t%s\t%s\t%s\t%s%s\t%s%s\n", m->name, cases[c].name, m->basis ? cls(od) : "(float only)", cls(of),
			       ((!m->basis || !strcmp(cls(od), cls(bd))) && !strcmp(cls(of), cls(bf))) ? "yes" : "no",
			       stname(sd), fd ? "+finite" : "+NONFINITE", stname(sf), ff ? "+finite" : "+NONFINITE");
		}
	}
	{	/* a NULL method */
		onb_vec3 n = { 0, 0, 1 }, b1, b2;
		printf("(NULL method)\t(0,0,1)\t-\t-\t-\t%s\t-\n", stname(onb_basis_checked(NULL, n, &b1, &b2, NULL)));
	}
	return 0;
}
