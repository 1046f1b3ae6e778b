/*
 * cli/list.h - `onbstudy list` (list.c): the registry, as a table or CSV.
 */
#ifndef ONB_LIST_H
#define ONB_LIST_H

int cmd_list(int argc, char **argv);

#endif
