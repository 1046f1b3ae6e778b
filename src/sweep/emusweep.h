/*
 * emusweep.h - `onbstudy sweep --arith PROFILE` (emusweep.c): the sweep's
 * distributions run through the emulated conforming implementations of a
 * profile (src/certify/emulate.h: every operation at round to nearest, R
 * random implementations and the greedy adversary), each input's worst
 * emulated defect held to the proven bound at that input (emu_point_bound,
 * certify --arith's mean value form over a box of ~8u around it) and each
 * method's largest defect to its whole-sphere bound from a certify --arith
 * CSV.  Writes DIR/arith-sweep.csv; exit 1 when any defect exceeds a bound.
 */
#ifndef ONB_SWEEP_EMUSWEEP_H
#define ONB_SWEEP_EMUSWEEP_H

#include "sweep/plan.h"

/* Run pl's kernels, precisions and distributions under pl->arith: 0 when
   every checked defect is within its bound, 1 when one is not (or on an
   error, after a message), ONB_EXIT_USAGE on a bad bounds file. */
int emusweep_run(const sweep_plan *pl);

#endif
