/*
 * keys.h - what determines a region's result in `onbstudy certify`,
 * hashed (keys.c): the key of a method in a precision, and of a group (a
 * method and precision with every setting of the run that enters its
 * regions' results).  The resumable and incremental runs (--resume,
 * --reuse, --check-keys) re-use a result only where its key is unchanged.
 *
 * A method and precision's regions are coupled (the images pass pools
 * every region's best inputs; the refinement picks among them), and
 * groups are not: the key is the group's, the unit of re-use.
 */
#ifndef ONB_CERTIFY_KEYS_H
#define ONB_CERTIFY_KEYS_H

#include <stdint.h>
#include "methods/kernels.h"
#include "models.h"
#include "probe.h"

/* The model of kernel k in precision prec, as an operation sequence: its
   CM_EXEC run (every value it computes, bit for bit, with the formula
   flags the bound reads) and the real kernel's defect as certify measures
   it (cert_probe), on a fixed set of inputs covering every branch path
   (the axes, the poles' neighbourhoods, random inputs); with the model's
   table row (branch count, contraction, direction) and the checksums of
   the compiled kernel and model (cert_code_sum). */
uint64_t cert_method_key(cert_ctx *x, const study_kernel *k, const cm_method *m, int prec);
/* The same for certify --precision half (certify_half.c): the format, the
   name, the model's run in binary16 and the half kernel's output bits on
   the key's inputs rounded to binary16, and the compiled half kernels
   (cert_code_sum("half", "", 0)) and family model. */
uint64_t cert_half_key(const study_kernel *k, const cm_method *m);

/* The checksum of a compiled object the keys take (scripts/code-keys.sh):
   kind "kernel" (name: a registry method; prec: PREC_FLOAT or
   PREC_DOUBLE), "family" (name: a family), "fma" or "direction" (name
   ""); 0 when there is none.  cert_method_key takes its kernel's and its
   family's, so that a changed kernel or model changes exactly the keys of
   the methods whose compiled code changed. */
unsigned long cert_code_sum(const char *kind, const char *name, int prec);

/* The certify engine: a hash of the sources that decide a region's result
   beyond its method (src/certify, src/model, src/reference, src/inputs,
   src/arith; the Makefile computes it), the compiler, the flags and the
   MPFR version. */
const char *cert_engine(void);

/* FNV-1a of s into h (h = CERT_FNV0 to start). */
#define CERT_FNV0 UINT64_C(0xcbf29ce484222325)
uint64_t cert_hash_str(uint64_t h, const char *s);
uint64_t cert_hash_bytes(uint64_t h, const void *p, size_t n);

#endif
