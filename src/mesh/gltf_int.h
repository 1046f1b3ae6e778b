/*
 * gltf_int.h - what the two halves of the glTF reader share (private to
 * src/mesh/): the reader's state, the JSON property helpers and the
 * accessors (gltf_data.c), read by the meaning of the file's objects
 * (gltf.c).
 */
#ifndef ONB_MESH_GLTF_INT_H
#define ONB_MESH_GLTF_INT_H

#include <stddef.h>
#include <stdint.h>
#include <cjson/cJSON.h>
#include "mesh/meshio.h"
#include "mesh/common.h"

#define GL_BYTE 5120
#define GL_UBYTE 5121
#define GL_SHORT 5122
#define GL_USHORT 5123
#define GL_UINT 5125
#define GL_FLOAT 5126

typedef struct {
	unsigned char *data;  /* owned (data: URI, external file), or into bin */
	size_t len;
	int state;            /* 0 not loaded, 1 loaded */
	int owned;
} gbuf;

typedef struct {
	mctx *c;
	const mesh_opts *o;
	cJSON *root;
	const unsigned char *bin;
	size_t binlen;
	int glb;
	gbuf *bufs;
	int nbufs;
	size_t inbytes;       /* bytes read: the file and external buffers */
	mesh_normals *m;
	size_t cap;           /* allocated normals in m */
	int ntypes;           /* stored component types seen: 1 float, 2 quantized */
} gltf;

/* o[k] when o is an object, else NULL. */
cJSON *gl_item(const cJSON *o, const char *k);
/* An optional integer property in [lo, hi]; def when absent (def < lo:
   required; lo = -2: an index, >= 0).  0, or -1 after a message naming
   `what` (and wi, when >= 0). */
int gl_jint(gltf *g, const cJSON *o, const char *what, long wi, const char *k, long long def, long long lo,
            long long hi, long long *out);
/* The array o[k] (NULL when absent); -1 when present but not an array. */
int gl_jarr(gltf *g, const cJSON *o, const char *what, long wi, const char *k, const cJSON **out);
/* Element i of the top-level array k, which must be an object. */
const cJSON *gl_top(gltf *g, const char *k, const char *what, long long i);
/* Adds a warning to m->warning (the first few fit; the rest are counted). */
void gl_warn(gltf *g, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 2, 3)))
#endif
	;

enum { ACC_NORMAL, ACC_POSITION, ACC_INDEX };
/* Accessor ai for `use`: *count elements of 3 (or 1, for indices)
   doubles in a new array *out (free it), sparse substitution applied;
   *ctype its componentType.  0, or -1 after a message. */
int gl_accessor(gltf *g, long long ai, int use, double **out, size_t *count, long long *ctype);

#endif
