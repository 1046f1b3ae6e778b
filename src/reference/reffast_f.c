/*
 * reffast_f.c - the fast reference for float inputs: reffast.c compiled
 * with pairs of doubles instead of pairs of long doubles (see there).
 */
#define REFFAST_PAIR_DOUBLE 1
#include "reference/reffast.c"
