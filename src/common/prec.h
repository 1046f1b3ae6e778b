/*
 * prec.h - the two precisions the study measures.  The ground floor:
 * every room may include it, and it includes nothing of the study.
 */
#ifndef ONB_COMMON_PREC_H
#define ONB_COMMON_PREC_H

/* binary32 and binary64; also the index of per-precision arrays */
enum { PREC_FLOAT = 0, PREC_DOUBLE = 1 };

#endif
