/*
 * src/certify/ - proven extremes.  For every method, precision
 * and region of the sphere, `onbstudy certify` brackets the largest
 * orthonormality defect between an input found (search.c) and a bound no
 * input can exceed: each kernel's operations written once more as a model
 * (its family's model, src/families/, bit-exact to the kernel:
 * tests/test_certify.c), evaluated in a mean value form over MPFI
 * intervals (src/model/mvf.c, bound.c), by branch and
 * bound over boxes of the sphere (search.c, regions.c).  seeds.c bounds the
 * approximate reciprocal square roots; scene_cert.c answers for a scene.
 *
 * certify.h - the command.
 */
#ifndef ONB_CERTIFY_CERTIFY_H
#define ONB_CERTIFY_CERTIFY_H

int cmd_certify(int argc, char **argv);

#endif
