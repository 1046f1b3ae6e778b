/*
 * gpu.h - onbstudy-gpu's commands (src/gpu/): GLSL and HLSL kernels of
 * the methods (include/libonb/onb.glsl, onb.hlsl) run on a real Vulkan
 * driver, lavapipe by default, and compared bit for bit with libonb's C
 * float kernels; the driver's own rounding of each operation; the shader
 * engines' own lines.  lavapipe runs on the CPU: nothing here times it.
 */
#ifndef ONB_GPU_GPU_H
#define ONB_GPU_GPU_H

#include <stdint.h>
#include <stdio.h>
#include "gpu/vk.h"

/* The inputs of one comparison: count triples (x, y, z) of floats, and
   which of them are rounded unit vectors (the domain of the bounds). */
typedef struct {
	float *n;
	unsigned char *unit;
	size_t count;
} gpu_inputs;

/* The study's input distributions (src/inputs, float): `per` inputs of
   each random one, the whole threshold list, and the extremes (signed
   zeros, subnormals, axes, n.z next to -1, inf, NaN, zero vectors). */
int gpu_inputs_make(gpu_inputs *in, uint64_t seed, uint64_t per);
/* The same for another format (gpu_half.c: binary16): the distributions
   at prec, each component rounded by round() (to a value that a float
   holds), then every triple of the next values ext[], each input marked
   by unit(); `what` names them in the out-of-memory message ("binary16 "). */
typedef struct {
	int prec;
	float (*round)(double);
	int (*unit)(const float n[3]);
	const double *ext;
	size_t next;
	const char *what;
} gpu_format;
int gpu_inputs_build(gpu_inputs *in, const gpu_format *fmt, uint64_t seed, uint64_t per);
void gpu_inputs_free(gpu_inputs *in);

/* Float bits in an order where adjacent floats differ by 1 (-0 = +0). */
int64_t gpu_ord(float f);
uint32_t gpu_bits(float f);

/* The operations probe (gpu_ops.c): each GLSL operation of ops.comp on
   `count` operand triples against IEEE binary32; writes its table to f.
   The number of operations whose results are not all IEEE, or -1. */
int gpu_ops(gpu_dev *d, const char *spvdir, FILE *f, uint64_t seed, size_t count);

#endif
