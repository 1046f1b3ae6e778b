/*
 * meshio.h - scene normals from Wavefront OBJ, PLY and glTF 2.0 files
 * (study only, not part of libonb; the glTF reader links cJSON).
 *
 * src/mesh/ holds the readers, the bottom of the study (they import
 * nothing of it): meshio.c detects the format and calls obj.c, ply.c or
 * gltf.c, which share common.c (errors, arrays, tokens, vertex normals,
 * whole-file reads, the classification of normals).  This header is the
 * folder's face, for `onbstudy scene`, examples/aorender.c and the fuzzers;
 * common.h, obj.h, ply.h and gltf.h are internal.
 *
 * Every reader parses a memory buffer (mesh_read_mem), so a fuzzer can call
 * it on arbitrary bytes; mesh_read_file reads a whole file and calls it.
 * The readers never crash and never return a partial result: on malformed
 * input they return -1 with one line in err naming the OBJ line or the PLY
 * byte offset (and line, for ascii PLY), and *out is left empty.
 *
 * What counts as a normal
 *   OBJ   every `vn` line, in file order.  When the file has no `vn`, the
 *         area-weighted vertex normal of every vertex that a face uses:
 *         the sum over the (fan-triangulated) faces around it of the cross
 *         product (b - a) x (c - a), which is twice the triangle's area
 *         times its unit normal, then normalized in long double.
 *   PLY   (nx, ny, nz) of every element that has all three properties
 *         (per-vertex and per-face normals both count), in file order.
 *         When no element has them, area-weighted vertex normals from the
 *         `face` element's vertex_indices (or vertex_index) lists, as above.
 *         The properties may also be named normal_x, normal_y, normal_z
 *         (the PCL and Open3D convention).
 *   glTF  the NORMAL attribute of every primitive of every mesh, in mesh
 *         and primitive order, through its accessor (FLOAT; BYTE and SHORT
 *         normalized, KHR_mesh_quantization, decoded max(c/127, -1) and
 *         max(c/32767, -1) in double: not unit in general), byte strides
 *         and sparse accessors honoured.  A primitive without NORMAL gets
 *         area-weighted normals from its POSITION and triangles (counted
 *         in ncomputed).  With mesh_opts.world, normals instead come once
 *         per node that instances a mesh, in the default scene (`scene`,
 *         else scene 0; without scenes, every root node), each multiplied
 *         by the inverse transpose of the node's world matrix, computed
 *         in the working precision (mesh_opts.prec), not renormalized.
 *   Unreferenced vertices get no computed normal; they are counted.
 *
 * Format by content (mesh_read_mem): "ply" + newline is PLY; "glTF" (GLB
 * magic) or a JSON object is glTF; STL, FBX, Collada, 3DS, ELF and other
 * binary data are refused with a message naming the format; other text is
 * OBJ, unless the name ends in .ply or .gltf (then that reader's message).
 * OBJ lines ending in a backslash continue on the next line.  Bytes after
 * the last element of a binary PLY are a warning (m->warning), not an
 * error, as assimp reads such files.
 */
#ifndef ONB_MESHIO_H
#define ONB_MESHIO_H

#include <stddef.h>
#include <stdint.h>
#include "common/prec.h"  /* the working precision of mesh_opts and mesh_classify */

enum { MESH_OBJ = 1, MESH_PLY = 2, MESH_GLTF = 3 };
enum { MESH_STORED = 1, MESH_COMPUTED = 2 };
/* Type the stored normals had in the file. */
enum { MESH_T_TEXT = 1, MESH_T_FLOAT, MESH_T_DOUBLE, MESH_T_OTHER, MESH_T_QUANT };

typedef struct {
	size_t count;          /* number of normals                              */
	double *x, *y, *z;     /* the normals, exactly as stored (or computed)   */
	uint64_t *where;       /* OBJ: line number; PLY: byte offset of the record;
	                          glTF: mesh (or node) << 40 | primitive << 32 | vertex */
	size_t *index;         /* index of the normal's vertex/element (0-based)  */
	int format;            /* MESH_OBJ, MESH_PLY or MESH_GLTF                */
	int origin;            /* MESH_STORED or MESH_COMPUTED                   */
	int stored_type;       /* MESH_T_*                                       */
	int ply_binary;        /* 0 ascii, 1 little endian, 2 big endian         */
	char element[32];      /* PLY: element that held them ("vertex", ...)    */
	size_t nvertices;      /* `v` lines / vertex elements                    */
	size_t nfaces;         /* faces (polygons)                               */
	size_t ntriangles;     /* triangles after fan triangulation              */
	size_t unreferenced;   /* computed normals: vertices used by no face     */
	size_t header_skipped; /* PLY: header lines with an unknown keyword      */
	uint64_t header_skipped_line; /* ...the first of them                    */
	char warning[256];     /* a problem read past (e.g. trailing bytes), or "" */
	/* glTF */
	int gltf_binary;       /* 1: .glb                                        */
	int world;             /* 1: world space (mesh_opts.world)               */
	size_t nmeshes, nprims;/* meshes; primitives read                        */
	size_t ncomputed;      /* normals computed for primitives without NORMAL  */
	size_t nprims_computed;
} mesh_normals;

typedef struct {
	int world;             /* glTF: node transforms (see above)              */
	int prec;              /* glTF --world: the working precision (PREC_*)   */
} mesh_opts;

/* Format from the content (see above).  External glTF buffers (a .bin
   beside the .gltf) are read only through mesh_read_file*, relative to the
   file's directory; from memory they are refused. */
int  mesh_read_mem(const char *name, const unsigned char *buf, size_t len,
                   mesh_normals *out, char *err, size_t errlen);
/* Reads the whole file (refusing files over MESH_MAX_FILE bytes). */
int  mesh_read_file(const char *path, mesh_normals *out, char *err, size_t errlen);
void mesh_free(mesh_normals *m);

/* Optional geometry, for a renderer (OBJ, PLY and glTF; for PLY and glTF
 * the corners index per-vertex normals: the stored ones, or the computed
 * ones; PLY per-face normals are not used for shading).
 *   pos      the `v` positions (x, y, z; any 4th to 7th number dropped).
 *   nrm      the normals the corners refer to: with `vn` lines, exactly the
 *            `vn` values in file order (the same as mesh_normals x, y, z);
 *            without, one computed normal per vertex, indexed like pos (the
 *            same values as mesh_normals; unreferenced vertices get 0 0 0).
 *   tri      3 position indices per triangle; polygons are fan-triangulated
 *            (a b c d ...) -> (a b c) (a c d) ..., in file order.
 *   tri_n    3 normal indices per triangle, one per corner: the corner's
 *            `v//vn` or `v/vt/vn`, or the vertex's computed normal; a
 *            corner without one in a file that has `vn` lines gets
 *            MESH_NO_NORMAL (a renderer then uses the flat face normal).
 *   tri_line the OBJ line of each triangle's face.
 * The same checks and errors as mesh_read_mem; on failure both outputs are
 * empty.  geom == NULL reads normals only (what mesh_read_mem does). */
#define MESH_NO_NORMAL UINT32_MAX
typedef struct {
	size_t nverts;      /* positions                                     */
	double *pos;        /* 3 * nverts                                    */
	size_t nnormals;    /* normals the corners index                     */
	double *nrm;        /* 3 * nnormals                                  */
	size_t ntris;       /* triangles                                     */
	uint32_t *tri;      /* 3 * ntris position indices                    */
	uint32_t *tri_n;    /* 3 * ntris normal indices, or MESH_NO_NORMAL   */
	uint64_t *tri_line; /* ntris: line of the face                       */
} mesh_geom;
int  mesh_read_geom_mem(const char *name, const unsigned char *buf, size_t len,
                        mesh_normals *out, mesh_geom *geom, char *err, size_t errlen);
int  mesh_read_geom_file(const char *path, mesh_normals *out, mesh_geom *geom,
                         char *err, size_t errlen);
void mesh_geom_free(mesh_geom *g);
/* The same with options (o == NULL: the defaults, all zero). */
int  mesh_read_mem_opts(const char *name, const unsigned char *buf, size_t len, const mesh_opts *o,
                        mesh_normals *out, mesh_geom *geom, char *err, size_t errlen);
int  mesh_read_file_opts(const char *path, const mesh_opts *o, mesh_normals *out, mesh_geom *geom,
                         char *err, size_t errlen);


#define MESH_MAX_FILE ((size_t)1 << 31)
/* Most normals, vertices or face corners accepted (before any allocation). */
#define MESH_MAX_ITEMS ((uint64_t)1 << 28)

/* Classification of the normals.  |n| is computed in long double from the
   values rounded to the working precision prec (PREC_FLOAT: to float first;
   PREC_HALF: to float, then to nearest binary16, where a component above
   65504 is infinite and one below 2^-25 is 0). */
typedef struct {
	size_t total, unit, nonunit, zero, nonfinite;
	double tol;                    /* unit means ||n| - 1| <= tol            */
	double dev_min, dev_max;       /* signed |n| - 1 over the non-unit ones  */
	double q50, q90, q99;          /* quantiles of ||n| - 1| over the non-unit */
	size_t nbad;                   /* locations kept in bad[] (first few)    */
	size_t bad[8];                 /* indices (into the normals) of degenerate ones */
} mesh_stats;

/* tol <= 0 selects the default: 4 ulps of 1 in the working precision
   (4 * FLT_EPSILON = 4.8e-7 for float, 4 * DBL_EPSILON = 8.9e-16 for double,
   2^-8 for half).
   Returns 0, or -1 when out of memory (quantiles need a sorted copy). */
int mesh_classify(const mesh_normals *m, int prec, double tol, mesh_stats *st);
/* "line 12" (OBJ) or "vertex 17 at byte 345" (PLY) for normal i. */
void mesh_where(const mesh_normals *m, size_t i, char *buf, size_t n);

#endif
