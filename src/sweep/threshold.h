/*
 * sweep/threshold.h - `onbstudy threshold` (threshold.c): Nelson Max's analysis of Frisvad's
 * threshold, and the merge of its shards' states.
 */
#ifndef ONB_THRESHOLD_H
#define ONB_THRESHOLD_H

int cmd_threshold(int argc, char **argv);
/* merge support for threshold shards */
int threshold_is_state(const char *path);
int threshold_merge(int nfiles, char **files, const char *out, int threads);

#endif
