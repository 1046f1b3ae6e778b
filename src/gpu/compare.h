/*
 * compare.h - the shader kernels against libonb's C kernels (gpu_compare.c)
 * and the report of a comparison run (gpu_report.c).
 */
#ifndef ONB_GPU_COMPARE_H
#define ONB_GPU_COMPARE_H

#include <stddef.h>
#include "gpu/gpu.h"

typedef struct {
	int id;             /* specialization constant of kernel.comp / kernel.hlsl */
	const char *name;   /* the method (libonb's registry name)                 */
	const char *twin;   /* its bits when fma() rounds twice, or "none"          */
	int f64;            /* 1: needs shaderFloat64; 2: and a double sqrt (GLSL only) */
} gpu_method;

const gpu_method *gpu_methods(size_t *count);

/* D of outputs b (b1, b2) for input n, long double; +inf if not finite. */
double gpu_defect(const float n[3], const float b[6]);
/* libonb's C float kernel `name` on every input; -1 if unknown. */
int gpu_c_outputs(const char *name, const gpu_inputs *in, float *b);
/* How the outputs of C (a) and of the driver (b) for one input differ. */
enum { GPU_SAME = 0, GPU_NAN, GPU_ZERO, GPU_NONFINITE, GPU_VALUE, GPU_NCLASS };
int gpu_class(const float *a, const float *b);
/* whole-sphere float bound of `name` in a certify CSV; inf: singular; -1: absent */
double gpu_bound(const char *csv, const char *name);

/* A certify CSV's float regions of one method (gpu_regions.c): the bound
   at an input is the largest of the regions within 8u of it, at most the
   whole sphere's (the whole sphere's alone unless the regions tile it). */
typedef struct { double zlo, zhi, plo, phi, b; } gpu_region;
typedef struct {
	gpu_region *g;
	size_t n, cap;
	double whole;   /* the whole-sphere bound; inf if absent */
	int tiled;      /* the regions' areas sum to the sphere's 2 x 360 */
	int have_whole; /* the CSV has the whole-sphere row                */
	double w;       /* the box around n/|n|: 8u of the precision       */
} gpu_regions;
int gpu_regions_load(const char *csv, const char *name, gpu_regions *r);
/* The same for precision prec ("float", "half"). */
int gpu_regions_loadp(const char *csv, const char *name, const char *prec, gpu_regions *r);
void gpu_regions_free(gpu_regions *r);
double gpu_regions_bound(const gpu_regions *r, const float n[3]);

/* The profile of a certify CSV (its "# arith:" line); "ieee" without one. */
void gpu_bounds_profile(const char *csv, char *name, size_t len);

/* One variant of the shaders: its SPIR-V file (under the SPIR-V folder). */
typedef struct {
	const char *label, *spv;
} gpu_variant;

/* The comparison of one method, per variant and over them. */
#define GPU_NVAR 4
typedef struct {
	const gpu_method *m;
	const char *expect;      /* the C kernel it must match                 */
	size_t n[GPU_NVAR][GPU_NCLASS]; /* inputs per variant and class (gpu_class) */
	int ran[GPU_NVAR];       /* 0: the variant cannot hold the method     */
	size_t un[GPU_NCLASS];   /* rounded unit inputs per class, GLSL precise */
	size_t first;            /* first input differing by value (or, if none, at all), or count */
	int first_cls;
	int first_var;
	float first_out[6], first_ref[6]; /* the driver's and C's outputs there */
	size_t domain;           /* rounded unit inputs                         */
	double dmax;             /* largest D over them, every variant          */
	size_t dmax_at;
	double bound;            /* -1: no bound applies                        */
	const char *bound_of;    /* the kernel whose bound it is                */
	size_t above;            /* domain inputs with D > bound                */
	size_t above_at;
} gpu_cmp;

/* The comparison of method m on the inputs (ref, got: 6 floats per input, scratch). */
int gpu_compare_one(gpu_dev *d, const char *spvdir, const gpu_inputs *in, const gpu_method *m,
                    int fma_fused, const char *bounds, float *ref, float *got, gpu_cmp *c);
/* Every method (or those of the comma-separated list) as a markdown table;
   the number not explained or outside their envelope, or -1. */
int gpu_compare_all(gpu_dev *d, const char *spvdir, FILE *f, const gpu_inputs *in, int fused,
                    const char *bounds, const char *methods);
/* -1 with a message when --methods names a method not in methods.inc. */
int gpu_methods_check(const char *list);
/* The engines' own lines (src/gpu/wild/, the registry's GLSL, HLSL and
   Slang rows) against their C rows; as above.  fallback: a C row absent
   from bounds takes its bound from the wild runs' CSVs (results/wild/add). */
int gpu_wild(gpu_dev *d, const char *spvdir, FILE *f, const gpu_inputs *in, const char *bounds, int fallback);

/* onbstudy-gpu half (gpu_half.c): the binary16 kernels of half.comp
   against libonb's C half kernels and within a half certify CSV's bounds
   at each input; the number of kernels that fail, or -1.  A list naming
   no kernel of half_methods.inc (or broken_*): -1 with a message. */
int gpu_half(gpu_dev *d, const char *spvdir, FILE *f, uint64_t seed, uint64_t per, const char *bounds, const char *methods);
int gpu_half_check(const char *list);
/* gltf_viewer built with `precision mediump float` (RelaxedPrecision)
   against C's float kernel and its plain build: a table of what the
   driver does (Vulkan grants no precision, so nothing is bounded); 0, or
   -1 on error. */
int gpu_relaxed(gpu_dev *d, const char *spvdir, FILE *f, uint64_t seed, uint64_t per);

#endif
