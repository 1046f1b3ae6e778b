/*
 * emulate.h - conforming implementations of an arithmetic profile,
 * emulated in C (emulate.c): a method's rounding model run in CM_EXEC with
 * each operation taking an allowed result (model.h, cm_set_emu), at
 * random or adversarially, and the defect of its basis measured exactly.
 * Used by `certify --arith` (the found side), `sweep --arith` and
 * `eval --arith`, and by tests/test_arith.c against the proven bounds.
 */
#ifndef ONB_CERTIFY_EMULATE_H
#define ONB_CERTIFY_EMULATE_H

#include "models.h"
#include "reference/reference.h"

typedef struct {
	double out[6];     /* b1, b2 as the emulation returned them            */
	double d[NDEF];    /* the five defects (exact to 2^-50 relative)        */
	double defect;     /* max |d[k]| (inf where an output is not finite)    */
	int ops;           /* operations of the run                            */
} emu_eval;

/* One run of method m on n (a format value) under profile p: mode and
   choices as cm_set_emu.  c is a CM_EXEC context; rc measures. */
void emu_run(cm *c, ref_ctx *rc, const cm_method *m, int prec, const double n[3], const arith_profile *p,
             int mode, unsigned long long seed, const unsigned char *choice, int nchoice, emu_eval *r);

/* The adversarial implementation: from every operation at its nearest
   result, `passes` greedy sweeps over the operations, each trying the
   choices that applied to it in the best run so far (lowest, highest,
   flushed operands or result, fused, a zero's sign the other way) and
   keeping any that raises the defect.  ch (CM_EMU_MAXOP entries) gets the
   choices; *best the worst run; returns its defect. */
double emu_adversarial(cm *c, ref_ctx *rc, const cm_method *m, int prec, const double n[3], const arith_profile *p,
                       int passes, unsigned char *ch, emu_eval *best);

/* The proven bound under p over the box of real unit vectors within about
   8u of n/|n| (z +- 8u, the azimuth alike), n.z fixed to n's (bound_box);
   *unb the operation that left it unbounded (-1).  Every conforming
   result at n stays below it when n is the rounding of a unit vector of
   the box (`eval --arith` and tests/test_arith.c). */
double emu_point_bound(const cm_method *m, const arith_profile *p, int prec, const double n[3], int *unb);

#endif
