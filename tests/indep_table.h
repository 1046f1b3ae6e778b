/*
 * indep_table.h - the library's methods as tests/test_indep.c sees them:
 * name, the inline double and float functions of include/libonb/onb.h, and the
 * id of the independent implementation (tests/indep.h) with its
 * normalization.  Needs onb.h and indep.h first.  With INDEP_TABLE_DEFINE
 * it defines the table T and NT; without, only the row type.
 */
#ifndef INDEP_TABLE_H
#define INDEP_TABLE_H
typedef void (*fn_d)(onb_vec3, onb_vec3 *, onb_vec3 *);
typedef void (*fn_f)(onb_vec3f, onb_vec3f *, onb_vec3f *);
typedef struct { const char *name; fn_d d; fn_f f; int id, k; } indep_row;
#ifdef INDEP_TABLE_DEFINE
static const indep_row T[] = {
	{ "naive", onb_naive, onb_naivef, IM_NAIVE, IND_RSQRT },
	{ "naive_invsqrt", onb_naive_invsqrt, onb_naive_invsqrtf, IM_NAIVE, IND_INVSQRT },
	{ "naive_rsqrt", onb_naive_rsqrt, onb_naive_rsqrtf, IM_NAIVE, IND_SSE },
	{ "naive_rsqrt_nr", onb_naive_rsqrt_nr, onb_naive_rsqrt_nrf, IM_NAIVE, IND_SSE_1N },
	{ "naive_nonorm", onb_naive_nonorm, onb_naive_nonormf, IM_NAIVE, IND_NONE },
	{ "hughes_moeller", onb_hughes_moeller, onb_hughes_moellerf, IM_HM, IND_RSQRT },
	{ "hughes_moeller_invsqrt", onb_hughes_moeller_invsqrt, onb_hughes_moeller_invsqrtf, IM_HM, IND_INVSQRT },
	{ "hughes_moeller_rsqrt", onb_hughes_moeller_rsqrt, onb_hughes_moeller_rsqrtf, IM_HM, IND_SSE },
	{ "hughes_moeller_rsqrt_nr", onb_hughes_moeller_rsqrt_nr, onb_hughes_moeller_rsqrt_nrf, IM_HM, IND_SSE_1N },
	{ "hughes_moeller_nonorm", onb_hughes_moeller_nonorm, onb_hughes_moeller_nonormf, IM_HM, IND_NONE },
	{ "frisvad", onb_frisvad, onb_frisvadf, IM_FRISVAD, 0 },
	{ "frisvad_max", onb_frisvad_max, onb_frisvad_maxf, IM_FRISVAD_MAX, 0 },
	{ "duff", onb_duff, onb_dufff, IM_DUFF, 0 },
	{ "duff_branchless", onb_duff_branchless, onb_duff_branchlessf, IM_DUFF_BL, 0 },
	{ "stark", onb_stark, onb_starkf, IM_STARK, 0 },
	{ "stark_fixed", onb_stark_fixed, onb_stark_fixedf, IM_STARK_FIXED, 0 },
	{ "pbrt_v3", onb_pbrt_v3, onb_pbrt_v3f, IM_PBRT3, 0 },
	{ "rtow", onb_rtow, onb_rtowf, IM_RTOW, 0 },
	{ "tangent_cross_z", onb_tangent_cross_z, onb_tangent_cross_zf, IM_BLOG, 0 },
	{ "q2rtx", onb_q2rtx, onb_q2rtxf, IW_Q2RTX, 0 },
	{ "filament", onb_filament, onb_filamentf, IW_FILAMENT, 0 },
	{ "mitsuba3", onb_mitsuba3, onb_mitsuba3f, IW_MITSUBA3, 0 },
	{ "cycles_cross111", onb_cycles_cross111, onb_cycles_cross111f, IW_CYCLES111, 0 },
	{ "cycles_cross111_avx2", onb_cycles_cross111_avx2, onb_cycles_cross111_avx2f, IW_CYCLES111_AVX2, 0 },
	{ "embree", onb_embree, onb_embreef, IW_EMBREE, 0 },
	{ "luxcore", onb_luxcore, onb_luxcoref, IW_LUXCORE, 0 },
	{ "jolt", onb_jolt, onb_joltf, IW_JOLT, 0 },
	{ "jolt_fma", onb_jolt_fma, onb_jolt_fmaf, IW_JOLT_FMA, 0 },
	{ "bullet", onb_bullet, onb_bulletf, IW_BULLET, 0 },
	{ "mujoco", onb_mujoco, onb_mujocof, IW_MUJOCO, 0 },
	{ "eigen", onb_eigen, onb_eigenf, IW_EIGEN, 0 },
	{ "physx", onb_physx, onb_physxf, IW_PHYSX, 0 },
	{ "rp3d", onb_rp3d, onb_rp3df, IW_RP3D, 0 },
	{ "open3d", onb_open3d, onb_open3df, IW_OPEN3D, 0 },
	{ "physx_fixed", onb_physx_fixed, onb_physx_fixedf, IW_PHYSX_FIXED, 0 },
	{ "open3d_fixed", onb_open3d_fixed, onb_open3d_fixedf, IW_OPEN3D_FIXED, 0 },
	{ "filament_fixed", onb_filament_fixed, onb_filament_fixedf, IW_FILAMENT_FIXED, 0 },
	/* float only (ONB_FLOAT_ONLY): no double function */
	{ "duff_wide", NULL, onb_duff_widef, IM_DUFF_WIDE, 0 },
	{ "duff_comp", NULL, onb_duff_compf, IM_DUFF_COMP, 0 },
};
#define NT (sizeof T / sizeof T[0])
#endif
#endif /* INDEP_TABLE_H */
