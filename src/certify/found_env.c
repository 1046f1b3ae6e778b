/*
 * found_env.c - what every file of the found side shares (found_env.h):
 * the double-double dot product of the screen and the gate of exact
 * measurements.
 */
#include <math.h>
#include "found_env.h"

/* a b as an unevaluated sum hi + lo (exact), and s += v kept as a
   double-double with Neumaier's compensation. */
static void two_prod(double a, double b, double *hi, double *lo)
{
	*hi = a * b;
	*lo = fma(a, b, -*hi);
}

void found_acc(double *s, double *c, double v)
{
	double t = *s + v;
	*c += fabs(*s) >= fabs(v) ? (*s - t) + v : (v - t) + *s;
	*s = t;
}

/* p . q - sub, to a relative error far below 1e-20 of the terms' size. */
double found_dot_dd(const double *p, const double *q, double sub)
{
	double s = -sub, c = 0.0, hi, lo;
	int i;
	for (i = 0; i < 3; i++) {
		two_prod(p[i], q[i], &hi, &lo);
		found_acc(&s, &c, hi);
		found_acc(&s, &c, lo);
	}
	return s + c;
}

/* The gate of exact measurements (found_env.h). */
int found_worth_measuring(probe_env *e, double d)
{
	if (!(d >= e->res->found * (1.0 - 1e-9)) || !(d > e->gate * (1.0 + 0x1p-40)))
		return 0;
	e->gate = d;
	return 1;
}
