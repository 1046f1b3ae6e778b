/*
 * cli/eval.h - `onbstudy eval x y z` (eval.c): one input, every method, every metric.
 */
#ifndef ONB_EVAL_H
#define ONB_EVAL_H

int cmd_eval(int argc, char **argv);

#endif
