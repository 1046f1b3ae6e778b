/*
 * checkpoint.h - certify's state on disk (checkpoint.c): the checkpoint
 * of a run (--resume DIR: DIR/certify-checkpoint.bin) and the keys of a
 * finished one (DIR/certify-keys.csv: --reuse, --check-keys).
 *
 * The checkpoint holds every task's (method, precision, region) state:
 * its result after the first pass (CK_RUN) and after the images pass
 * (CK_IMAGES), and the result of its refinement apart (CK_REFINED), so
 * that a resumed run replays the refinement's rounds on the same values
 * as an uninterrupted one.  It names the run's settings, the certify
 * engine and every group's key (keys.h); a checkpoint that differs in
 * any of them is refused, with the difference named.  Written whole to a
 * temporary, fsync'ed, renamed: a failed write leaves the last one.
 */
#ifndef ONB_CERTIFY_CHECKPOINT_H
#define ONB_CERTIFY_CHECKPOINT_H

#include <stdint.h>
#include "bracket.h"

enum { CK_RUN = 1, CK_IMAGES = 2, CK_REFINED = 4 };

#define CK_NAME "certify-checkpoint.bin"
#define KEYS_NAME "certify-keys.csv"

/* A group: a method (kernel name) in a precision, with its key. */
typedef struct {
	char name[64];
	int prec;
	uint64_t key;
} ck_group;

typedef struct {
	const char *settings;       /* the run's settings, one line          */
	const char *engine;         /* cert_engine()                          */
	int ng, nt;
	const ck_group *g;
	unsigned char *flag;        /* per task: CK_* */
	cert_result *base;          /* per task: after the first pass or the images */
	cert_result *ref;           /* per task: refined (CK_REFINED)         */
} ck_state;

/* Write s to DIR/certify-checkpoint.bin (atomically); 0 or -1 after a
   message. */
int ck_write(const char *dir, const ck_state *s);
/* Read DIR's checkpoint into s (its settings, engine and groups must be
   s's): 0 loaded, 1 none there, -1 refused or unreadable (a message
   names why). */
int ck_read(const char *dir, ck_state *s);

/* DIR/certify-keys.csv of a finished run: the settings, the engine and
   every group's key. */
int keys_write(const char *dir, const ck_state *s, const char *provenance_cmd);
/* Compare DIR/certify-keys.csv with s: into cur[g] 1 when group g's key
   is there and current, 0 when not (why[g] a word: "absent", "changed").
   Returns 0 when the settings and engine match, 1 when they differ (a
   message printed with the difference), -1 when there is no keys file. */
int keys_compare(const char *dir, const ck_state *s, int *cur, int quiet);

#endif
