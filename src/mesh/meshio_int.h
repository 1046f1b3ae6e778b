/*
 * meshio_int.h - what the readers of meshio.c and mesh_gltf.c share (not
 * an interface of the study).
 */
#ifndef ONB_MESHIO_INT_H
#define ONB_MESHIO_INT_H

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

/* mesh_gltf.c: .gltf JSON or .glb binary */
int  mio_read_gltf(mctx *c, const unsigned char *buf, size_t len, const mesh_opts *o, mesh_normals *m, mesh_geom *geom);

#endif
