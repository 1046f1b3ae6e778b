/*
 * fma_kernels.c - a second copy of every kernel, compiled with
 * -mfma -ffp-contract=fast (see the Makefile), so that the sweep can show
 * what fused multiply-adds do to each method's error.  Only called after
 * fma_available() said the CPU has FMA.
 */
#include <string.h>
/* This copy must contract: no FP pragmas from onb.h. */
#define ONB_INLINE_FOLLOWS_CLIENT_FP 1
#include "methods/kernels.h"

#if defined(__FMA__)
#define FMA_BUILT 1
#else
#define FMA_BUILT 0
#endif

#define FMA_DEF(m) \
	static void fma_##m (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb_##m (n, b1, b2); } \
	static void fma_##m##f(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb_##m##f(n, b1, b2); }
ONB_METHOD_LIST(FMA_DEF)
#undef FMA_DEF
#define FMA_DEF_F(m) \
	static void fma_##m##f(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb_##m##f(n, b1, b2); }
ONB_FLOAT_METHOD_LIST(FMA_DEF_F)
#undef FMA_DEF_F

#define FMA_DEF_DIR(d) \
	static onb_vec3  fma_##d   (onb_vec3  n, double x, double y, double z) { return onb_##d(n, x, y, z); } \
	static onb_vec3f fma_##d##f(onb_vec3f n, float x, float y, float z)    { return onb_##d##f(n, x, y, z); }
STUDY_DIRECTION_LIST(FMA_DEF_DIR)
#undef FMA_DEF_DIR

static const struct {
	const char *name;
	onb_basis_fn basis;
	onb_basisf_fn basisf;
	rotate_fn rot;          /* the direction kernels' rows (kernels.h) */
	rotatef_fn rotf;
} fma_table[] = {
#define FMA_ROW(m) { #m, fma_##m, fma_##m##f, NULL, NULL },
	ONB_METHOD_LIST(FMA_ROW)
#undef FMA_ROW
#define FMA_ROW_F(m) { #m, NULL, fma_##m##f, NULL, NULL },
	ONB_FLOAT_METHOD_LIST(FMA_ROW_F)
#undef FMA_ROW_F
#define FMA_ROW_DIR(d) { #d, NULL, NULL, fma_##d, fma_##d##f },
	STUDY_DIRECTION_LIST(FMA_ROW_DIR)
#undef FMA_ROW_DIR
};

int fma_available(void)
{
#if FMA_BUILT && (defined(__x86_64__) || defined(__i386__))
	__builtin_cpu_init();
	return __builtin_cpu_supports("fma") != 0;
#elif FMA_BUILT
	return 1;
#else
	return 0;
#endif
}

int fma_lookup(const char *name, onb_basis_fn *basis, onb_basisf_fn *basisf, rotate_fn *rot, rotatef_fn *rotf)
{
	size_t i;
	for (i = 0; i < sizeof fma_table / sizeof fma_table[0]; i++)
		if (strcmp(fma_table[i].name, name) == 0) {
			*basis = fma_table[i].basis;
			*basisf = fma_table[i].basisf;
			*rot = fma_table[i].rot;
			*rotf = fma_table[i].rotf;
			return 0;
		}
	return -1;
}

/* The family's branch rule compiled with contraction, like the kernels
   here (its FMA pass, src/families/family.h). */
int fma_branch(const study_kernel *k, int prec, const double n[3])
{
	return k->fam->branch_fma(k->m, prec, n);
}
