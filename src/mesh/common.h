/*
 * common.h - what the mesh readers (obj.c, ply.c, gltf.c) and their entry
 * points (meshio.c) share, defined in common.c (not an interface of the
 * study).
 */
#ifndef ONB_MESH_COMMON_H
#define ONB_MESH_COMMON_H

#include <stddef.h>
#include <stdint.h>
#include "mesh/meshio.h"

typedef struct {
	char *err;
	size_t errlen;
	const char *name;
	const char *dir;      /* directory of external glTF buffers, or NULL */
} mctx;

/* Writes "NAME: message" to the error buffer; returns -1. */
int  mio_fail(mctx *c, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 2, 3)))
#endif
	;
/* calloc with an overflow-checked product (n == 0 allocates one). */
void *mio_calloc(size_t n, size_t sz);
/* The five arrays of n normals; 0, or -1 (and m freed). */
int  mio_alloc_normals(mesh_normals *m, size_t n);

typedef struct { size_t first, count; uint64_t where; } face_rec;
/* Area-weighted vertex normals into m (see meshio.c). */
int  mio_compute_normals(mctx *c, mesh_normals *m, const double *pos, size_t nv, const uint64_t *vwhere,
                         const uint32_t *corners, const face_rec *faces, size_t nf);
/* Reads a whole file (at most MESH_MAX_FILE bytes); 0, or -1 with a message. */
int  mio_slurp(mctx *c, const char *path, unsigned char **buf, size_t *len);

/* Growable arrays of esz-byte elements (at most MESH_MAX_ITEMS). */
typedef struct {
	void *p;
	size_t n, cap, esz;
} gvec;
void mio_gvec_init(gvec *v, size_t esz);
void mio_gvec_free(gvec *v);
int  mio_gvec_push(gvec *v, const void *e);   /* 0, or -1 (full or out of memory) */

/* Tokens and numbers.  Callers bound OBJ and header lines before
   tokenizing, so a newline only separates tokens inside an ascii PLY body. */
int  mio_is_space(unsigned char ch);
/* Next token in [*p, end), whitespace separated; 0 at the end. */
int  mio_next_tok(const unsigned char **p, const unsigned char *end, const unsigned char **t, size_t *tl);
int  mio_tok_eq(const unsigned char *t, size_t tl, const char *s);
/* Whole token as a number (non-finite values accepted, garbage not); 1 or 0. */
int  mio_tok_double(const unsigned char *t, size_t tl, double *v);
int  mio_tok_float(const unsigned char *t, size_t tl, double *v);
int  mio_tok_ll(const unsigned char *t, size_t tl, long long *v);
/* Printable excerpt of a token for error messages. */
const char *mio_tok_show(const unsigned char *t, size_t tl, char *buf, size_t bn);

#endif
