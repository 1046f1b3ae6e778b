/*
 * domain32.h - the default float domain (region.h) along one axis: which
 * side of it an input lies on, and the run of its members (domain32.c).
 * Below both the enumeration of a box (enumerate.c) and the found side's
 * completion of an input (found.c).
 */
#ifndef ONB_CERTIFY_DOMAIN32_H
#define ONB_CERTIFY_DOMAIN32_H

/* Which side of the default float domain n lies on: 0 in it (exactly when
   cert_in_domain(n, PREC_FLOAT, -1) is 1), -1 too short (every real that
   rounds to n has |u| <= 1), +1 too long (|u| >= 1), 2 when a component
   is not a finite float or the side cannot be told.  Exact: a double sum
   decides unless it is within 2^-46 of 1, then cert_in_domain does. */
int cert_f32_side(const double n[3]);

/* The same for the default double domain (cert_in_domain(n, PREC_DOUBLE,
   -1)): sums in double-double decide unless within 2^-96 of 1. */
int cert_f64_side(const double n[3]);

/* The domain members with n[axis] of the sign of `sign` (+1: +0 and up,
   -1: -0 and down), the other two components as in n: the run *lo..*hi in
   magnitude order.  Returns its length (0: none, -1: a side could not be
   told, after a message). */
long long cert_f32_run(const double n[3], int axis, int sign, double *lo, double *hi);

#endif
