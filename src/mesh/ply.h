/*
 * ply.h - the PLY reader, ascii and binary (ply.c).
 */
#ifndef ONB_MESH_PLY_H
#define ONB_MESH_PLY_H

#include <stddef.h>
#include "mesh/common.h"

/* Normals (and, when geom is not NULL, geometry) of a PLY buffer; 0, or -1 via mio_fail. */
int mio_read_ply(mctx *c, const unsigned char *buf, size_t len, mesh_normals *m, mesh_geom *geom);

#endif
