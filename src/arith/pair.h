/*
 * pair.h - the fast reference's value types and constants, shared by its
 * two instantiations (pair_kit.h: pairs of doubles, pairs of long
 * doubles) and by the families' fast formulas (src/families/).
 */
#ifndef ONB_REFERENCE_PAIR_H
#define ONB_REFERENCE_PAIR_H

/* A value h + l with a bound e on its error, in pairs of doubles (the
   float precision's instantiation) and of long doubles (double's). */
typedef struct { double h, l, e; } xv_pd;
typedef struct { long double h, l; double e; } xv_pl;

/* The hot helpers are inlined into their callers (measured: about a
   fifth of the fast path's time went to calls and spills), and so are the
   formula's building blocks (xrecip, xrsqrt, xdot, xcross, xnormalize,
   xfrisvad, xduff: 4% in both precisions, for twice the code). */
#if defined(__GNUC__)
#define HOT static inline __attribute__((always_inline))
#else
#define HOT static inline
#endif

#define INFL (1.0 + 0x1p-40)     /* inflation of every computed bound        */
#define TINY 0x1p-900            /* smallest magnitude allowed (no underflow) */
#define FLOOR 0x1p-1000          /* absolute floor added to inexact bounds   */

#endif
