/*
 * obj.h - the Wavefront OBJ reader (obj.c).
 */
#ifndef ONB_MESH_OBJ_H
#define ONB_MESH_OBJ_H

#include <stddef.h>
#include "mesh/common.h"

/* Normals (and, when geom is not NULL, geometry) of an OBJ buffer; 0, or -1 via mio_fail. */
int mio_read_obj(mctx *c, const unsigned char *buf, size_t len, mesh_normals *m, mesh_geom *geom);

#endif
