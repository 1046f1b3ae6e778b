/*
 * prec.h - the two precisions the study measures.  The ground floor:
 * every room may include it, and it includes nothing of the study.
 */
#ifndef ONB_COMMON_PREC_H
#define ONB_COMMON_PREC_H

/* binary32 and binary64; also the index of per-precision arrays, and the
   format of a rounding model's operation (src/model/model.h) */
enum { PREC_FLOAT = 0, PREC_DOUBLE = 1 };

/* The one spelling of a precision in every output: "float", "double". */
static inline const char *prec_name(int p) { return p == PREC_FLOAT ? "float" : "double"; }

#endif
