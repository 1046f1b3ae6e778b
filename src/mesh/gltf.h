/*
 * gltf.h - the glTF 2.0 reader, .gltf JSON or .glb binary (gltf.c, links cJSON).
 */
#ifndef ONB_MESH_GLTF_H
#define ONB_MESH_GLTF_H

#include <stddef.h>
#include "mesh/common.h"

/* Normals (and geometry) of a glTF buffer under the options o; 0, or -1 via mio_fail. */
int mio_read_gltf(mctx *c, const unsigned char *buf, size_t len, const mesh_opts *o, mesh_normals *m, mesh_geom *geom);

#endif
