/*
 * sweep/halfscan.h - `onbstudy halfscan` (halfscan.c): every method in
 * binary16 over the binary16 roundings of unit vectors near each axis.
 */
#ifndef ONB_HALFSCAN_H
#define ONB_HALFSCAN_H

int cmd_halfscan(int argc, char **argv);

#endif
