/*
 * onb.h - the old include name of libonb, kept for code written before the
 * header moved to <libonb/onb.h>.  Installed only by `make install-compat`:
 * a name as common as onb.h belongs to the renderer that includes libonb.
 * New code: #include <libonb/onb.h> (docs/library.md, "Include path").
 */
#ifndef LIBONB_COMPAT_ONB_H
#define LIBONB_COMPAT_ONB_H
#include "libonb/onb.h"
#endif /* LIBONB_COMPAT_ONB_H */
