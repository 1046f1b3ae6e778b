/*
 * reproduce/reproduce.h - `onbstudy reproduce` (reproduce.c): every published figure the study can
 * check, beside a fresh measurement with the same definitions.  src/reproduce/
 * holds this one command: its published constants and their protocols.
 */
#ifndef ONB_REPRODUCE_H
#define ONB_REPRODUCE_H

int cmd_reproduce(int argc, char **argv);

#endif
