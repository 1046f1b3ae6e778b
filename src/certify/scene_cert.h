/*
 * scene_cert.h - proven bounds for a scene's interpolated shading normals
 * (`onbstudy scene --certify`, scene_cert.c).
 */
#ifndef ONB_CERTIFY_SCENE_CERT_H
#define ONB_CERTIFY_SCENE_CERT_H

#include <stddef.h>
#include "libonb/onb.h"
#include "search.h"

/* Prints, for each of the nm methods, the proven bound over the patches of
   the scene in `path` (up: 'z', 'y' or 'x' as scene --up) beside its
   measured maximum (measured[i]), and whether `recommended` (may be NULL)
   is proven within E, in precision prec (PREC_FLOAT or PREC_DOUBLE; PREC_HALF
   reads the committed proof results/half/certify/certify-half.csv instead
   of proving: scene_cert.c's file comment).
   proven[i] (nm entries) gets the bound, inf where the method is singular
   on the scene, and is left as it is for a method certify has no model
   of.  0, or -1 after a message. */
int scene_certify(const char *path, char up, int prec, double E, const onb_method *ms, size_t nm,
                  const double *measured, const char *recommended, double *proven);

#endif
