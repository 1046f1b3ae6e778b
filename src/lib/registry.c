/*
 * registry.c - the one method table.  Every tool (list, sweep, bench,
 * table, scene, the tests) loops over it; adding a method means adding a
 * row here and its kernel in include/libonb/onb.h.
 */
#define ONB_BUILDING_LIB 1
#include "libonb/onb.h"

#if ONB_HAVE_HW_RSQRT
#define ONB__HW ONB_HW_RSQRT
#else
#define ONB__HW (ONB_HW_RSQRT | ONB_FELL_BACK)
#endif

#define ONB__PTRS(m) onb_##m##_outline, onb_##m##_outlinef, onb_##m##_batch, onb_##m##_batchf
#define ONB__PTRS_F(m) NULL, onb_##m##_outlinef, NULL, onb_##m##_batchf

#define SRC_L1 "Frisvad 2012, JGT 16(3), Listing 1"
#define SRC_HM "Hughes & Moller 1999, JGT 4(4), as Frisvad 2012 Listing 1"
#define SING_NAIVE "n = -x (b1 cancels to 0; precision lost as n.x -> -1)"
#define THR_NAIVE "n.x > 0.9"
#define THR_HM "|n.x| > |n.z|"

static const onb_method onb__table[] = {
	{ "naive", "naive", SRC_L1 " naive, rsqrt = (float)(1.0/sqrt(x))",
	  SING_NAIVE, THR_NAIVE, +1, 0, NAN, ONB__NORM_LIBM, ONB__PTRS(naive) },
	{ "naive_invsqrt", "naive", SRC_L1 " naive + Listing 3 InvSqrt (0x5f3759df, 1 Newton step)",
	  SING_NAIVE, THR_NAIVE, +1, ONB_APPROX_NORM, NAN, ONB__NORM_INVSQRT, ONB__PTRS(naive_invsqrt) },
	{ "naive_rsqrt", "naive", SRC_L1 " naive + Listing 3 SSE_rsqrt (rsqrtss)",
	  SING_NAIVE, THR_NAIVE, +1, ONB_APPROX_NORM | ONB__HW, NAN, ONB__NORM_RSQRT, ONB__PTRS(naive_rsqrt) },
	{ "naive_rsqrt_nr", "naive", SRC_L1 " naive + Listing 3 SSE_rsqrt_1N (rsqrtss + 1 Newton step)",
	  SING_NAIVE, THR_NAIVE, +1, ONB_APPROX_NORM | ONB__HW, NAN, ONB__NORM_RSQRT_NR, ONB__PTRS(naive_rsqrt_nr) },
	{ "naive_nonorm", "naive", SRC_L1 " naive, no normalization (Table 1)",
	  SING_NAIVE, THR_NAIVE, +1, ONB_APPROX_NORM, NAN, ONB__NORM_NONE, ONB__PTRS(naive_nonorm) },
	{ "hughes_moeller", "hughes_moeller", SRC_HM ", rsqrt = (float)(1.0/sqrt(x))",
	  "none", THR_HM, +1, 0, NAN, ONB__NORM_LIBM, ONB__PTRS(hughes_moeller) },
	{ "hughes_moeller_invsqrt", "hughes_moeller", SRC_HM " + Listing 3 InvSqrt",
	  "none", THR_HM, +1, ONB_APPROX_NORM, NAN, ONB__NORM_INVSQRT, ONB__PTRS(hughes_moeller_invsqrt) },
	{ "hughes_moeller_rsqrt", "hughes_moeller", SRC_HM " + Listing 3 SSE_rsqrt",
	  "none", THR_HM, +1, ONB_APPROX_NORM | ONB__HW, NAN, ONB__NORM_RSQRT, ONB__PTRS(hughes_moeller_rsqrt) },
	{ "hughes_moeller_rsqrt_nr", "hughes_moeller", SRC_HM " + Listing 3 SSE_rsqrt_1N",
	  "none", THR_HM, +1, ONB_APPROX_NORM | ONB__HW, NAN, ONB__NORM_RSQRT_NR, ONB__PTRS(hughes_moeller_rsqrt_nr) },
	{ "hughes_moeller_nonorm", "hughes_moeller", SRC_HM ", no normalization (Table 1)",
	  "none", THR_HM, +1, ONB_APPROX_NORM, NAN, ONB__NORM_NONE, ONB__PTRS(hughes_moeller_nonorm) },
	{ "frisvad", "frisvad", "Frisvad 2012, JGT 16(3), Listing 2 (t = -0.9999999)",
	  "none exactly; error ~ eps/(1+n.z) just above t (O(1) in float)", "n.z < -0.9999999",
	  +1, 0, ONB_FRISVAD_T, 0, ONB__PTRS(frisvad) },
	{ "frisvad_max", "frisvad", "Max 2017, JCGT 6(1): Frisvad Listing 2 with t = -0.99998796",
	  "none exactly; error ~ eps/(1+n.z) just above t", "n.z < -0.99998796",
	  +1, 0, ONB_FRISVAD_MAX_T, 0, ONB__PTRS(frisvad_max) },
	{ "duff", "duff", "Duff et al. 2017, JCGT 6(1), Listing 2 (revisedONB, branch on n.z < 0)",
	  "none", "n.z < 0 (-0 takes the upper branch)", +1, 0, NAN, 0, ONB__PTRS(duff) },
	{ "duff_branchless", "duff_branchless", "Duff et al. 2017, JCGT 6(1), Listing 3 (branchlessONB; pbrt-v4, Mitsuba 3)",
	  "none", "signbit(n.z) (-0 takes the lower branch)", +1, 0, NAN, 0, ONB__PTRS(duff_branchless) },
	{ "stark", "stark", "Stark 2009, JGT 14(1): branch-free perpendicular as published (zm = 1^(xm & ym)), then 1/sqrt normalize and cross",
	  "none", "|n.x| = |n.y|, |n.x| = |n.z|, |n.y| = |n.z|", +1, 0, NAN, 0, ONB__PTRS(stark) },
	{ "stark_fixed", "stark_fixed", "Stark 2009 with Hill 2011's fix zm = 1^(xm | ym) (axis of the smallest |component|)",
	  "none", "|n.x| = |n.y|, |n.x| = |n.z|, |n.y| = |n.z|", +1, 0, NAN, 0, ONB__PTRS(stark_fixed) },
	{ "pbrt_v3", "pbrt_v3", "pbrt-v3 CoordinateSystem (src/core/geometry.h)",
	  "none", "|n.x| > |n.y|", +1, 0, NAN, 0, ONB__PTRS(pbrt_v3) },
	{ "rtow", "rtow", "Shirley, Ray Tracing: The Rest of Your Life, onb::build_from_w",
	  "n = 0 only (normalizes its input)", "|n.x| > 0.9", -1, ONB_NORMALIZES_N, NAN, 0, ONB__PTRS(rtow) },
	{ "tangent_cross_z", "tangent_cross_z", "sydneyzh blog, Vector transformation using projection between ONBs, get_onb",
	  "n = +z and n = -z (0/0 = NaN); float n.x^2+n.y^2 underflow", "none", -1, 0, NAN, 0, ONB__PTRS(tangent_cross_z) },
	/* This project's own methods (issue 16), float only: Duff's formula at
	   the accuracy floor.  Their MPFR reference is duff_branchless's. */
	{ "duff_wide", "duff_branchless", "onbstudy (issue 16), not published: Duff et al. 2017 Listing 3 on float input, evaluated in double, rounded once",
	  "none", "signbit(n.z) (-0 takes the lower branch)", +1, ONB_FLOAT_ONLY, NAN, 0, ONB__PTRS_F(duff_wide) },
	{ "duff_comp", "duff_branchless", "onbstudy (issue 16), not published: Duff et al. 2017 Listing 3 in float, fma-compensated products and sums",
	  "none", "signbit(n.z) (-0 takes the lower branch)", +1, ONB_FLOAT_ONLY, NAN, 0, ONB__PTRS_F(duff_comp) },
};

/* One row for every method of ONB_METHOD_LIST and ONB_FLOAT_METHOD_LIST
   (include/libonb/onb.h): a list entry without a row stops the build here (a
   negative array size); tests/test_parts.c checks the rows' names. */
#define ONB__ONE(m) + 1
typedef char onb__one_row_per_listed_method[
	sizeof onb__table / sizeof onb__table[0] == 0 ONB_METHOD_LIST(ONB__ONE) ONB_FLOAT_METHOD_LIST(ONB__ONE) ? 1 : -1];
#undef ONB__ONE

const onb_method *onb_methods(size_t *count)
{
	if (count)
		*count = sizeof onb__table / sizeof onb__table[0];
	return onb__table;
}

const onb_method *onb_find(const char *name)
{
	size_t i;
	if (!name)
		return NULL;
	for (i = 0; i < sizeof onb__table / sizeof onb__table[0]; i++)
		if (strcmp(onb__table[i].name, name) == 0)
			return &onb__table[i];
	return NULL;
}
