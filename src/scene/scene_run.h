/*
 * scene_run.h - every method on a scene's normals, measured (scene_run.c):
 * the buffers in the working precision, the batch and scalar runs and
 * their metrics, the same on uniform directions, and the scene's shape.
 * Private to src/scene/ (scene.c ranks, reports and writes).
 */
#ifndef ONB_SCENE_RUN_H
#define ONB_SCENE_RUN_H

#include <stddef.h>
#include "libonb/onb.h"
#include "mesh/meshio.h"

/* One method on the normals of a buffer (scene.c's file comment): the
   metrics, and ok when acceptable within the tolerance. */
typedef struct {
	double max_defect, rms_defect, max_norm, max_dot;
	size_t nonfinite, wrong_hand, mismatch, worst, first_nonfinite;
	int ok;
} scene_res;

/* The inputs and both outputs (batch, scalar) in the working precision. */
typedef struct {
	size_t n;
	int prec;               /* PREC_FLOAT: float arrays; PREC_HALF: binary16 bit patterns (uint16_t) */
	void *in[3], *bo[6], *so[6];
	size_t *src;            /* index into the mesh normals */
} scene_buf;

/* Normals used (non-degenerate), distinct ones, and those on an axis. */
typedef struct {
	size_t used, distinct, on_axes;
} scene_shape;

/* x rounded to the working precision: float; binary16 by rounding the
   file's float to nearest (a vertex buffer's float read as mediump);
   double as it is. */
double scene_round(int prec, double x);

/* 0, or -1 when out of memory (then b is freed). */
int  scene_buf_alloc(scene_buf *b, size_t n, int prec);
void scene_buf_free(scene_buf *b);

/* Fill b with the non-degenerate normals, permuted for `up`, rounded to
   the working precision, and renormalized when asked.  Returns the number
   dropped because renormalizing under- or overflowed. */
size_t scene_fill(const mesh_normals *mn, int prec, char up, int renorm, scene_buf *b);

/* The nm methods on b (batch and scalar), measured into r[i]; ok within
   tol; worst and first_nonfinite as indices into the mesh normals. */
void scene_run_all(const onb_method *ms, size_t nm, const scene_buf *b, double tol, scene_res *r);

/* Each method's max defect on 4096 uniform directions (seed 1) in the
   working precision; INFINITY for a non-finite or wrong-handed output.
   0, or -1 when out of memory. */
int scene_uniform_defects(const onb_method *ms, size_t nm, int prec, double *out);

/* The shape of the normals in the working precision.  0, or -1 when out
   of memory. */
int scene_shape_of(const mesh_normals *mn, int prec, scene_shape *s);

#endif
