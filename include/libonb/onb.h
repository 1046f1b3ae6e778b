/*
 * libonb/onb.h - orthonormal bases {b1, b2, n} from a 3D unit vector n.
 *
 * The whole public face of libonb.  C99, libm only.  Include it as
 * <libonb/onb.h> (pkg-config's -I names the folder above libonb/), so it
 * cannot clash with a renderer's own onb.h; its guard is LIBONB_ONB_H.
 *
 * Index
 *   Types ............ onb_vec3 (double), onb_vec3f (float), onb_vec3h (half), onb_method
 *   Methods .......... one static inline pair per method, double plain,
 *                      float with the `f` suffix (as in <math.h>):
 *     onb_naive            onb_naivef             Frisvad 2012 Listing 1
 *     onb_naive_invsqrt    onb_naive_invsqrtf       + Listing 3 InvSqrt
 *     onb_naive_rsqrt      onb_naive_rsqrtf         + Listing 3 SSE_rsqrt
 *     onb_naive_rsqrt_nr   onb_naive_rsqrt_nrf      + Listing 3 SSE_rsqrt_1N
 *     onb_naive_nonorm     onb_naive_nonormf        + no normalization
 *     onb_hughes_moeller*  (same five variants)   Hughes & Moller 1999
 *     onb_frisvad          onb_frisvadf           Frisvad 2012 Listing 2
 *     onb_frisvad_max      onb_frisvad_maxf       Max 2017 threshold
 *     onb_duff             onb_dufff              Duff et al. 2017 Listing 2
 *     onb_duff_branchless  onb_duff_branchlessf   Duff et al. 2017 Listing 3
 *     onb_stark            onb_starkf             Stark 2009, as published
 *     onb_stark_fixed      onb_stark_fixedf         + Hill 2011's zm fix
 *     onb_pbrt_v3          onb_pbrt_v3f           pbrt-v3 CoordinateSystem
 *     onb_rtow             onb_rtowf              RTTROYL onb::build_from_w
 *     onb_tangent_cross_z  onb_tangent_cross_zf   blog get_onb
 *     engines' shipped code (onb_method.prov: repository, commit, lines):
 *     onb_q2rtx            onb_q2rtxf             Quake II RTX construct_ONB_frisvad
 *     onb_filament         onb_filamentf          Filament frisvadKernel (y-up)
 *     onb_filament_hm      onb_filament_hmf       Filament hughesMollerMethod
 *     onb_capsaicin        onb_capsaicinf         AMD Capsaicin GetOrthoVectors
 *     onb_capsaicin_fixed  onb_capsaicin_fixedf   this project: Capsaicin fixed
 *     onb_unity            onb_unityf             Unity SRP core GetLocalFrame
 *     onb_willems          onb_willemsf           Sascha Willems' Vulkan pbribl
 *     onb_gltf_viewer      onb_gltf_viewerf       Khronos glTF-Sample-Viewer generateTBN
 *     onb_rtao             onb_rtaof              DirectX-Graphics-Samples RTAO
 *     onb_rtao_fixed       onb_rtao_fixedf        this project: RTAO fixed
 *     onb_mitsuba3         onb_mitsuba3f          Mitsuba 3 coordinate_system
 *     onb_cycles_cross111  onb_cycles_cross111f   Blender Cycles make_orthonormals
 *     onb_cycles_cross111_avx2[f]                   ... as its AVX2 kernel (fmsub cross)
 *     onb_embree           onb_embreef            Embree frame(N) (rsqrtss + Newton)
 *     onb_luxcore          onb_luxcoref           LuxCoreRender CoordinateSystem
 *     onb_nori             onb_norif              Nori coordinateSystem (= Mitsuba 0.6)
 *     onb_osl_ortho        onb_osl_orthof         OpenShadingLanguage testrender ortho
 *     onb_ospray           onb_osprayf            OSPRay/rkcommon frame(N) (ISPC, IEEE)
 *     onb_osl_gabornoise   onb_osl_gabornoisef    OpenShadingLanguage make_orthonormals
 *     onb_cauldron2        onb_cauldron2f         FidelityFX Cauldron2 CreateTangentVectors
 *     onb_threejs          onb_threejsf           three.js PMREM ggxConvolution (TSL)
 *     onb_q2rtx_fixed      onb_q2rtx_fixedf       this project: Quake II RTX (and nvpro) fixed
 *     onb_jolt_arm64       onb_jolt_arm64f        Jolt, its non-x86 build (scalar -x)
 *     onb_jolt             onb_joltf              Jolt GetNormalizedPerpendicular
 *     onb_jolt_fma         onb_jolt_fmaf            its default x86 build (fma)
 *     onb_bullet           onb_bulletf            Bullet btPlaneSpace1 (= ODE)
 *     onb_mujoco           onb_mujocof            MuJoCo mju_makeFrame
 *     onb_eigen            onb_eigenf             Eigen unitOrthogonal + cross
 *     onb_physx            onb_physxf             PhysX PxComputeBasisVectors
 *     onb_rp3d             onb_rp3df              ReactPhysics3D
 *     onb_open3d           onb_open3df            Open3D ConstructOrthogonalBasis
 *     onb_raylib           onb_raylibf            raylib Vector3Perpendicular + cross
 *     onb_godot            onb_godotf             Godot get_any_perpendicular + cross
 *     onb_directxmath      onb_directxmathf       DirectXMath XMVector3Orthogonal + cross
 *     onb_ogre             onb_ogref              Ogre Vector3::perpendicular + cross
 *     onb_bx               onb_bxf                bgfx bx::calcTangentFrame
 *     onb_blender          onb_blenderf           Blender BLI ortho_basis_v3v3_v3
 *     onb_box3d            onb_box3df             Box3D b3Perp + contact tangents
 *     onb_appleseed        onb_appleseedf         appleseed Basis3::build
 *     onb_babylon          onb_babylonf           Babylon.js getNormalToRef + cross (JS double)
 *     onb_godot_fixed      onb_godot_fixedf       this project: Godot fixed
 *     onb_bx_fixed         onb_bx_fixedf          this project: bx fixed
 *     onb_physx_fixed      onb_physx_fixedf       this project: PhysX fixed
 *     onb_filament_fixed   onb_filament_fixedf    this project: Filament fixed
 *     onb_open3d_fixed     onb_open3d_fixedf      this project: Open3D fixed
 *     onb_luxcore_fixed    onb_luxcore_fixedf     this project: LuxCoreRender fixed
 *     (float only)         onb_duff_widef         this project: Duff in double
 *     (float only)         onb_duff_compf         this project: Duff, fma-compensated
 *   Half (binary16) .. onb_NAMEh for every method above (onb_frisvadh, ...),
 *                      onb_vec3h, onb_NAME_arrayh on bit patterns; out of
 *                      line, each operation rounded to binary16; only where
 *                      ONB_HAVE_HALF is 1 (a compiler with _Float16)
 *   Tools ............ onb_frisvad_threshold[f]  Listing 2 with t as a parameter
 *                      onb_frisvad_rotate[f]     Frisvad 2012 Equation 3
 *                      onb_basis_checked[f]      normalize + status + method
 *   Batch (libonb.a) . onb_<method>_batch[f]     structure-of-arrays loops
 *   Registry ......... onb_methods, onb_find, onb_batch_isa; onb_provenance
 *                      (shipped code: repository, commit, lines, license)
 *   Aliases .......... onb_aliases, onb_find_alias: engines' code that is an
 *                      existing method bit for bit (pbrt_v4 = duff_branchless)
 *
 * Conventions
 *   - Precondition of every method: n is a unit vector as received in the
 *     format (so |n| = 1 within a few ulps).  Methods never normalize n except
 *     `rtow`, whose source does.  Non-unit, zero and non-finite input is
 *     defined (no UB, no hang) but garbage in, garbage out: see
 *     docs/library.md, "Library contract", or use onb_basis_checked.
 *   - Handedness is det(b1, b2, n): +1 means b1 x b2 = n.
 *   - Each method is written out by hand for double and float, exactly as
 *     published, flaws included.  A fix of a published method is a new,
 *     named method, never an edit of an old one.
 *   - Error is the orthonormality defect D = max(| |b1|-1 |, | |b2|-1 |,
 *     |b1.n|, |b2.n|, |b1.b2|).  Each method's comment below gives the
 *     tested bound that tests/test_lib.c checks (a simple formula, loose
 *     by design); the proven one is in this table (docs/certify.md).
 * Proven bounds (generated by scripts/findings.sh --onbh from results/certify/certify.csv; edit scripts/onbh.in):
 *     The largest defect D that `onbstudy certify` proves for each method
 *     over every rounding of a real unit vector (the whole sphere, n = +-z
 *     included), as a multiple of u = 2^-24 (float) or 2^-53 (double),
 *     beside the largest D it found on a real input; "singular": the method
 *     returns NaN or inf on some such input, no bound.  Assumes IEEE
 *     round to nearest, no FMA contraction, correctly rounded sqrt, and,
 *     for _rsqrt, the rsqrtss of the CPU named in certify.csv:
 *   method                   float                          double
 *   naive                    singular                       singular
 *   naive_invsqrt            singular                       singular
 *   naive_rsqrt              singular                       singular
 *   naive_rsqrt_nr           singular                       singular
 *   naive_nonorm             <= 1.68e+07u (found 1.68e+07u) <= 9.01e+15u (found 9.01e+15u)
 *   hughes_moeller           <= 5.5u (found 3.94u)          <= 6.58u (found 4.06u)
 *   hughes_moeller_invsqrt   <= 3.67e+04u (found 2.94e+04u) <= 1.97e+13u (found 1.58e+13u)
 *   hughes_moeller_rsqrt     <= 6.82e+03u (found 5.46e+03u) <= 3.58e+12u (found 2.88e+12u)
 *   hughes_moeller_rsqrt_nr  <= 9.39u (found 6.39u)         <= 1.79e+09u (found 1.44e+09u)
 *   hughes_moeller_nonorm    <= 5.92e+06u (found 4.91e+06u) <= 3.18e+15u (found 2.64e+15u)
 *   frisvad                  <= 1.3e+07u (found 1.05e+07u)  <= 4.03e+12u (found 4.03e+12u)
 *   frisvad_max              <= 1.04e+05u (found 8.32e+04u) <= 5.37e+13u (found 4.42e+13u)
 *   duff                     <= 5u (found 3.33u)            <= 5u (found 3.34u)
 *   duff_branchless          <= 5u (found 3.33u)            <= 5u (found 3.34u)
 *   stark                    <= 7.07u (found 4.48u)         <= 7.07u (found 4.45u)
 *   stark_fixed              <= 6.58u (found 4.05u)         <= 6.58u (found 4.1u)
 *   pbrt_v3                  <= 5.8u (found 3.73u)          <= 6.58u (found 4.08u)
 *   rtow                     <= 10.3u (found 5.39u)         <= 10.3u (found 5.67u)
 *   tangent_cross_z          singular                       singular
 *   q2rtx                    <= 3.65e+05u (found 3.31e+05u) <= 1.96e+14u (found 1.78e+14u)
 *   filament                 <= 1.31e+07u (found 1.05e+07u) <= 5.28e+12u (found 4.38e+12u)
 *   mitsuba3                 <= 5u (found 3.36u)            <= 5u (found 3.26u)
 *   cycles_cross111          <= 6.78u (found 3.78u)         <= 5.78u (found 4.07u)
 *   cycles_cross111_avx2     <= 6.78u (found 3.69u)         <= 5.78u (found 3.72u)
 *   embree                   <= 6.38u (found 4.95u)         <= 1.44e+09u (found 1.44e+09u)
 *   luxcore                  <= 168u (found 168u)           <= 9.01e+10u (found 9.01e+10u)
 *   jolt                     <= 5.52u (found 3.29u)         <= 5.13u (found 3.67u)
 *   jolt_fma                 <= 5.5u (found 3.34u)          <= 5.12u (found 3.22u)
 *   bullet                   <= 5.07u (found 3u)            <= 5.07u (found 3.03u)
 *   mujoco                   <= 15.6u (found 8.65u)         <= 15.6u (found 8.66u)
 *   eigen                    <= 6.91u (found 4u)            <= 6.91u (found 4.06u)
 *   physx                    <= 2.57e+05u (found 2.37e+05u) <= 1.38e+14u (found 1.26e+14u)
 *   rp3d                     <= 5.52u (found 3.25u)         <= 5.13u (found 3.67u)
 *   open3d                   singular                       singular
 *   physx_fixed              <= 6.59u (found 4.06u)         <= 6.59u (found 4.08u)
 *   open3d_fixed             <= 3.71u (found 2.59u)         <= 3.93u (found 2.99u)
 *   filament_fixed           <= 5u (found 3.41u)            <= 5u (found 3.43u)
 *   duff_wide                <= 2.06u (found 1.48u)         -
 *   duff_comp                <= 2.7u (found 1.48u)          -
 *   frisvad_rotate           <= 2.09e+07u (found 1.68e+07u) <= 1.12e+16u (found 9.01e+15u)
 * (end of the proven bounds)
 *
 * Floating-point flags (docs/library.md, "Compiler flags"):
 *   - The method names are inline kernels where the caller's flags cannot
 *     change their bits, and calls to libonb.a's out-of-line copies (the
 *     studied bits) where they could: under -ffast-math, and under GCC
 *     with an FMA target outside ISO C mode.  The block after the
 *     includes below gives the exact rule and the defines that override
 *     it (ONB_FP_CONTRACT_OFF, ONB_INLINE_FOLLOWS_CLIENT_FP,
 *     ONB_FORCE_OUTLINE).  onb.h compiles under every flag, -ffast-math
 *     included, with no define.
 *   - onb_NAME_outline[f], onb_NAME_array[f] and method->basis[f] are
 *     always the out-of-line copies, compiled with the library's flags.
 */
#ifndef LIBONB_ONB_H
#define LIBONB_ONB_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* Which code the method names (onb_duff_branchless, ...) run in the
   including file (docs/library.md, "Compiler flags"):
     ONB__INLINE 1  the kernels below, inlined into the caller;
     ONB__INLINE 0  calls to libonb.a's out-of-line copies, compiled with
                    the library's flags: the studied bits, whatever the
                    caller's flags.
   Inline whenever the caller's flags cannot change the bits:
     - GCC: no FMA target (__FP_FAST_FMA[F] undefined), or ISO C mode
       (-std=c99/c11/c17: GCC's default there is -ffp-contract=off), or the
       client defines ONB_FP_CONTRACT_OFF to promise -ffp-contract=off
       (GCC gives no macro for it);
     - clang, without -ffast-math: `#pragma clang fp contract(off)` below
       keeps a*b+c unfused and does not stop inlining;
   out of line under -ffast-math (__FAST_MATH__), and under GCC with an FMA
   target in GNU C or C++ mode (default -ffp-contract=fast), unless
     - ONB_INLINE_FOLLOWS_CLIENT_FP: inline, and no pragma: the kernels
       follow the caller's flags (contraction, -ffast-math), which changes
       their bits and voids the study's error figures for them;
     - ONB_FORCE_OUTLINE: out of line, whatever the compiler and flags.
   Out of line too where float arithmetic is wider than binary32
   (FLT_EVAL_METHOD 1 or 2: GCC on s390x, or on i386 with x87 maths, in
   ISO C mode): the float kernels would be evaluated in double there and
   rounded differently; the library's copies are binary32.
   libonb's own sources define ONB_BUILDING_LIB (inline, built with
   -ffp-contract=off by the Makefile). */
#ifdef __FLT_EVAL_METHOD__
#define ONB__EVAL_METHOD __FLT_EVAL_METHOD__
#else
#include <float.h>
#define ONB__EVAL_METHOD FLT_EVAL_METHOD
#endif
#define ONB__WIDE_FLOAT (ONB__EVAL_METHOD == 1 || ONB__EVAL_METHOD == 2)
#if defined(ONB_BUILDING_LIB) && ONB__WIDE_FLOAT
#error "libonb: float arithmetic is wider than binary32 here (FLT_EVAL_METHOD 1 or 2), so the float kernels would not round as published; build the library with -fexcess-precision=fast (GCC in ISO C mode, e.g. on s390x) or -std=gnu99, or -mfpmath=sse on i386 (docs/library.md)"
#endif
#if defined(ONB_BUILDING_LIB) || defined(ONB_INLINE_FOLLOWS_CLIENT_FP)
#define ONB__INLINE 1
#elif defined(ONB_FORCE_OUTLINE) || defined(__FAST_MATH__) || ONB__WIDE_FLOAT
#define ONB__INLINE 0
#elif defined(__clang__)
#define ONB__INLINE 1
#elif defined(__GNUC__)
#if (!defined(__FP_FAST_FMA) && !defined(__FP_FAST_FMAF)) || \
    (defined(__STRICT_ANSI__) && !defined(__cplusplus)) || defined(ONB_FP_CONTRACT_OFF)
#define ONB__INLINE 1
#else
#define ONB__INLINE 0
#endif
#else
#define ONB__INLINE 1
#endif

/* "Did it inline?": ONB_INLINE_ACTIVE is 1 when the method names in this
   file are the inline kernels, 0 when they call libonb.a's out-of-line
   copies (same bits, a call each).  Test it (#if ONB_INLINE_ACTIVE) or
   insist on it: _Static_assert(ONB_INLINE_ACTIVE, "...") in C11,
   static_assert in C++, typedef char t[ONB_INLINE_ACTIVE ? 1 : -1] in C99.
   Define ONB_WARN_OUTLINE to have the header say so, with the reason, at
   compile time when it takes the out-of-line copies (a #pragma message:
   a note with GCC, a warning with clang). */
#define ONB_INLINE_ACTIVE ONB__INLINE
#if !ONB__INLINE && defined(ONB_WARN_OUTLINE)
#if defined(ONB_FORCE_OUTLINE)
#pragma message("libonb: the method names call libonb.a's out-of-line copies (ONB_FORCE_OUTLINE is defined)")
#elif defined(__FAST_MATH__)
#pragma message("libonb: the method names call libonb.a's out-of-line copies (-ffast-math could change the kernels' bits; ONB_INLINE_FOLLOWS_CLIENT_FP inlines them anyway)")
#elif ONB__WIDE_FLOAT
#pragma message("libonb: the method names call libonb.a's out-of-line copies (FLT_EVAL_METHOD 1 or 2: float arithmetic wider than binary32 here)")
#else
#pragma message("libonb: the method names call libonb.a's out-of-line copies (GCC with an FMA target outside ISO C mode contracts a*b+c; -std=c99/c11/c17, or -ffp-contract=off with -DONB_FP_CONTRACT_OFF, inlines them)")
#endif
#endif

/* No contraction into FMA inside the kernels, where a pragma does it
   without stopping inlining.  Popped at the end of the header. */
#if ONB__INLINE && !defined(ONB_INLINE_FOLLOWS_CLIENT_FP) && defined(__clang__)
#pragma float_control(push)
#pragma clang fp contract(off)
#define ONB__FP_PRAGMAS 1
#else
#define ONB__FP_PRAGMAS 0
#endif

/* Kernel names: the method names themselves when inline; otherwise the
   kernels are renamed (and never instantiated) and the method names are
   wrappers around the out-of-line copies, defined at the end. */
#if ONB__INLINE
#define ONB__K(m) onb_##m
#else
#define ONB__K(m) onb__k_##m
#endif

/* Casts that C++ -Wold-style-cast accepts. */
#ifdef __cplusplus
#define ONB__CAST(t, x) static_cast<t>(x)
#else
#define ONB__CAST(t, x) ((t)(x))
#endif
/* x == 0 (false for NaN, as ==) without -Wfloat-equal's warning: clients
   build onb.h with it (tests/lib_client.sh) */
#define ONB__IS0(x) ((x) <= 0 && (x) >= 0)

/* The hardware rsqrt (the _rsqrt variants): on x86-64 GCC and clang reach
   rsqrtss through their builtin, without <xmmintrin.h>; other compilers
   include it.  Elsewhere (arm64, s390x, ...) the variants run 1/sqrt and
   the registry says so (ONB_FELL_BACK). */
#if (defined(__SSE__) || defined(_M_X64) || defined(__x86_64__)) && !defined(ONB_NO_HW_RSQRT)
#define ONB_HAVE_HW_RSQRT 1
#if !defined(__GNUC__)
#include <xmmintrin.h>
#endif
#else
#define ONB_HAVE_HW_RSQRT 0
#endif

#ifdef __cplusplus
extern "C" {
#endif

#define ONB_VERSION "0.1.0"

typedef struct { double x, y, z; } onb_vec3;
typedef struct { float  x, y, z; } onb_vec3f;

/* binary16 ("half": GLSL mediump, HLSL half, CUDA __half).  ONB_HAVE_HALF
   is 1 where the compiler has _Float16 (GCC >= 12 and clang >= 15 on
   x86-64 and arm64; __FLT16_MAX__ says so), else 0, and then this header
   declares no half entry point: the library builds without them (C99 has
   no binary16 type).  Define ONB_NO_HALF to leave them out anyway.  The
   half kernels are out of line only (src/lib/half.c), compiled with the
   library's flags, and every operation in them is rounded to binary16 on
   its own, as a GPU's half arithmetic does: x86-64 compilers evaluate
   `_Float16` expressions in float and round once at the end
   (FLT_EVAL_METHOD 0 with _Float16 promoted, or -fexcess-precision), so
   the kernels never write a bare half expression (half.c says how).
   The registry reaches them through onb_method.arrayh, on binary16 bit
   patterns (uint16_t), which every build can declare. */
#if !defined(ONB_NO_HALF) && defined(__FLT16_MAX__) && (defined(__x86_64__) || defined(__aarch64__)) && \
    (defined(__clang__) || (defined(__GNUC__) && __GNUC__ >= 12))
#define ONB_HAVE_HALF 1
__extension__ typedef _Float16 onb_half;
typedef struct { onb_half x, y, z; } onb_vec3h;
#else
#define ONB_HAVE_HALF 0
#endif

/* ------------------------------------------------------------------ */
/* Reciprocal square roots of Frisvad 2012, Listing 3                  */
/* ------------------------------------------------------------------ */

/* Listing 3 `rsqrt`: static_cast<float>(1.0/sqrt(x)), i.e. computed in
   double and rounded once to float: correctly rounded for float. */
static inline double onb__rsqrt_libm (double x) { return 1.0 / sqrt(x); }
static inline float  onb__rsqrt_libmf(float x)  { return ONB__CAST(float, 1.0 / sqrt(ONB__CAST(double, x))); }

/* Listing 3 `InvSqrt`: the bit trick and one Newton step.  Unsigned
   arithmetic reads the listing's int shift without implementation-defined
   behaviour; for x >= 0 (a dot product) the bits are the same. */
static inline float onb__invsqrtf(float x)
{
	float xhalf = 0.5f * x;
	uint32_t i;
	memcpy(&i, &x, sizeof i);
	i = 0x5f3759dfu - (i >> 1); /* rsqrt seed, 32-bit */
	memcpy(&x, &i, sizeof x);
	x = x * (1.5f - xhalf * x * x);
	return x;
}
static inline double onb__invsqrt(double x)
{
	double xhalf = 0.5 * x;
	uint64_t i;
	memcpy(&i, &x, sizeof i);
	i = UINT64_C(0x5fe6eb50c7b537a9) - (i >> 1); /* rsqrt seed, 64-bit (Lomont) */
	memcpy(&x, &i, sizeof x);
	x = x * (1.5 - xhalf * x * x);
	return x;
}

/* Listing 3 `SSE_rsqrt`: the hardware approximation (rsqrtss, relative
   error <= 1.5*2^-12).  Double has no such instruction below AVX-512, so
   the double variant rounds x to float, runs rsqrtss and widens the result:
   the same 12-bit approximation a float renderer gets, on every x86-64.
   Without SSE both fall back to 1/sqrt and the registry says so
   (ONB_FELL_BACK). */
static inline float onb__hw_rsqrtf(float x)
{
#if ONB_HAVE_HW_RSQRT && defined(__GNUC__)
	typedef float onb__v4sf __attribute__((__vector_size__(16)));
	onb__v4sf v = { x, 0.0f, 0.0f, 0.0f };
	v = __builtin_ia32_rsqrtss(v);
	return v[0];
#elif ONB_HAVE_HW_RSQRT
	return _mm_cvtss_f32(_mm_rsqrt_ss(_mm_set_ss(x)));
#else
	return 1.0f / sqrtf(x);
#endif
}
static inline double onb__hw_rsqrt(double x) { return ONB__CAST(double, onb__hw_rsqrtf(ONB__CAST(float, x))); }

/* Listing 3 `SSE_rsqrt_1N`: one Newton step on the hardware estimate y. */
static inline float  onb__newtonf(float x, float y)   { return y * (1.5f - 0.5f * x * y * y); }
static inline double onb__newton (double x, double y) { return y * (1.5 - 0.5 * x * y * y); }
static inline float  onb__hw_rsqrt_nrf(float x)  { return onb__newtonf(x, onb__hw_rsqrtf(x)); }
static inline double onb__hw_rsqrt_nr (double x) { return onb__newton(x, onb__hw_rsqrt(x)); }

/* Normalization selectors of the naive and hughes_moeller families.  The
   family kernels take one as a constant, which inlining folds away. */
enum {
	ONB__NORM_LIBM = 0, /* Listing 3 rsqrt       */
	ONB__NORM_INVSQRT,  /* Listing 3 InvSqrt     */
	ONB__NORM_RSQRT,    /* Listing 3 SSE_rsqrt   */
	ONB__NORM_RSQRT_NR, /* Listing 3 SSE_rsqrt_1N*/
	ONB__NORM_NONE      /* no normalization      */
};
/* The float-only evaluations of duff_branchless's formula (onb_method.norm
   of duff_wide and duff_comp): one exact formula, other roundings. */
enum { ONB__EVAL_WIDE = 16, ONB__EVAL_COMP, ONB__EVAL_MITSUBA3, ONB__EVAL_FMSUB };
/* Variants of the engines' families (onb_method.norm): jolt_fma, the
   build that fuses the cross product; physx_fixed and open3d_fixed, this
   project's one-line fixes of the engines' code. */
enum { ONB__WILD_FMA = 32, ONB__WILD_FIXED };
/* jolt_arm64: Jolt's non-SSE perpendicular (unary minus, std::max) */
enum { ONB__WILD_SCALAR = 48 };

static inline double onb__rsq(double x, int norm)
{
	switch (norm) {
	case ONB__NORM_INVSQRT:  return onb__invsqrt(x);
	case ONB__NORM_RSQRT:    return onb__hw_rsqrt(x);
	case ONB__NORM_RSQRT_NR: return onb__hw_rsqrt_nr(x);
	case ONB__NORM_NONE:     return 1.0;
	default:                 return onb__rsqrt_libm(x);
	}
}
static inline float onb__rsqf(float x, int norm)
{
	switch (norm) {
	case ONB__NORM_INVSQRT:  return onb__invsqrtf(x);
	case ONB__NORM_RSQRT:    return onb__hw_rsqrtf(x);
	case ONB__NORM_RSQRT_NR: return onb__hw_rsqrt_nrf(x);
	case ONB__NORM_NONE:     return 1.0f;
	default:                 return onb__rsqrt_libmf(x);
	}
}

/* ------------------------------------------------------------------ */
/* naive (Frisvad 2012, Listing 1, credited there to a reviewer)       */
/* ------------------------------------------------------------------ */
/* b1 = x-axis, or y-axis when n.x > 0.9; b1 -= n*dot(b1, n); b1 *= rsqrt(
   dot(b1, b1)); b2 = cross(n, b1).  Handedness +1.
   Threshold: n.x > 0.9 (one-sided: n.x < -0.9 keeps the x-axis).
   Singular: n = -x exactly (b1 - n*dot = 0, 0*inf = NaN); precision falls
   as n approaches -x, where b1 cancels (relative error ~ eps/|1 + n.x|).
   The dot products are evaluated in full, zeros included, as the Vec3f
   code of the listing does.
   The kernel is split at the normalization (pre/post) so that the batch
   loops can vectorize the hardware rsqrt; the scalar function chains the
   same three steps, so both give the same bits.
   Tested bound (tests/test_lib.c; u = 2^-24 or 2^-53): defect D <= 12u (1 +
   1/sqrt(1 - (n.e)^2)) for unit-to-rounding n, e the chosen axis.  The
   variants: _invsqrt adds 1.76e-3 to the lengths (Lomont 2003), _rsqrt
   1.5 * 2^-12, _rsqrt_nr 1.5 (1.5 * 2^-12)^2 + 3u; _nonorm's lengths are
   the unnormalized ones. */
static inline double onb__naive_pre(onb_vec3 n, onb_vec3 *b1)
{
	double bx, by, bz, d;
	if (n.x > 0.9) { bx = 0.0; by = 1.0; bz = 0.0; }
	else           { bx = 1.0; by = 0.0; bz = 0.0; }
	d = bx * n.x + by * n.y + bz * n.z;
	bx -= n.x * d;
	by -= n.y * d;
	bz -= n.z * d;
	b1->x = bx; b1->y = by; b1->z = bz;
	return bx * bx + by * by + bz * bz;
}
static inline float onb__naive_pref(onb_vec3f n, onb_vec3f *b1)
{
	float bx, by, bz, d;
	if (n.x > 0.9f) { bx = 0.0f; by = 1.0f; bz = 0.0f; }
	else            { bx = 1.0f; by = 0.0f; bz = 0.0f; }
	d = bx * n.x + by * n.y + bz * n.z;
	bx -= n.x * d;
	by -= n.y * d;
	bz -= n.z * d;
	b1->x = bx; b1->y = by; b1->z = bz;
	return bx * bx + by * by + bz * bz;
}
static inline void onb__naive_post(onb_vec3 n, onb_vec3 u, double s, onb_vec3 *b1, onb_vec3 *b2)
{
	u.x *= s; u.y *= s; u.z *= s;
	*b1 = u;
	b2->x = n.y * u.z - n.z * u.y;
	b2->y = n.z * u.x - n.x * u.z;
	b2->z = n.x * u.y - n.y * u.x;
}
static inline void onb__naive_postf(onb_vec3f n, onb_vec3f u, float s, onb_vec3f *b1, onb_vec3f *b2)
{
	u.x *= s; u.y *= s; u.z *= s;
	*b1 = u;
	b2->x = n.y * u.z - n.z * u.y;
	b2->y = n.z * u.x - n.x * u.z;
	b2->z = n.x * u.y - n.y * u.x;
}
static inline void onb__naive(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2, int norm)
{
	onb_vec3 u;
	double l2 = onb__naive_pre(n, &u);
	onb__naive_post(n, u, onb__rsq(l2, norm), b1, b2);
}
static inline void onb__naivef(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2, int norm)
{
	onb_vec3f u;
	float l2 = onb__naive_pref(n, &u);
	onb__naive_postf(n, u, onb__rsqf(l2, norm), b1, b2);
}

static inline void ONB__K(naive)            (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__naive (n, b1, b2, ONB__NORM_LIBM); }
static inline void ONB__K(naivef)           (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__naivef(n, b1, b2, ONB__NORM_LIBM); }
static inline void ONB__K(naive_invsqrt)    (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__naive (n, b1, b2, ONB__NORM_INVSQRT); }
static inline void ONB__K(naive_invsqrtf)   (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__naivef(n, b1, b2, ONB__NORM_INVSQRT); }
static inline void ONB__K(naive_rsqrt)      (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__naive (n, b1, b2, ONB__NORM_RSQRT); }
static inline void ONB__K(naive_rsqrtf)     (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__naivef(n, b1, b2, ONB__NORM_RSQRT); }
static inline void ONB__K(naive_rsqrt_nr)   (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__naive (n, b1, b2, ONB__NORM_RSQRT_NR); }
static inline void ONB__K(naive_rsqrt_nrf)  (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__naivef(n, b1, b2, ONB__NORM_RSQRT_NR); }
static inline void ONB__K(naive_nonorm)     (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__naive (n, b1, b2, ONB__NORM_NONE); }
static inline void ONB__K(naive_nonormf)    (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__naivef(n, b1, b2, ONB__NORM_NONE); }

/* ------------------------------------------------------------------ */
/* hughes_moeller (Hughes & Moller 1999, as in Frisvad 2012 Listing 1) */
/* ------------------------------------------------------------------ */
/* b2 = (-n.y, n.x, 0) if |n.x| > |n.z|, else (0, -n.z, n.y); b2 *= rsqrt(
   dot(b2, b2)); b1 = cross(b2, n).  Handedness +1.
   Threshold: |n.x| = |n.z| (the frame jumps there).  No singular unit
   direction: the chosen vector has squared length >= 1/2 - O(eps) for
   unit n.  Note this is Frisvad's listing, which compares x with z only;
   the 1999 paper's "smallest component" variant is not this one.
   Tested bound (tests/test_lib.c): D <= 12u; the normalization variants add to
   the lengths what naive's do. */
static inline double onb__hughes_moeller_pre(onb_vec3 n, onb_vec3 *b2)
{
	double bx, by, bz;
	if (fabs(n.x) > fabs(n.z)) { bx = -n.y; by = n.x;  bz = 0.0; }
	else                       { bx = 0.0;  by = -n.z; bz = n.y; }
	b2->x = bx; b2->y = by; b2->z = bz;
	return bx * bx + by * by + bz * bz;
}
static inline float onb__hughes_moeller_pref(onb_vec3f n, onb_vec3f *b2)
{
	float bx, by, bz;
	if (fabsf(n.x) > fabsf(n.z)) { bx = -n.y; by = n.x;  bz = 0.0f; }
	else                         { bx = 0.0f; by = -n.z; bz = n.y; }
	b2->x = bx; b2->y = by; b2->z = bz;
	return bx * bx + by * by + bz * bz;
}
static inline void onb__hughes_moeller_post(onb_vec3 n, onb_vec3 v, double s, onb_vec3 *b1, onb_vec3 *b2)
{
	v.x *= s; v.y *= s; v.z *= s;
	*b2 = v;
	b1->x = v.y * n.z - v.z * n.y;
	b1->y = v.z * n.x - v.x * n.z;
	b1->z = v.x * n.y - v.y * n.x;
}
static inline void onb__hughes_moeller_postf(onb_vec3f n, onb_vec3f v, float s, onb_vec3f *b1, onb_vec3f *b2)
{
	v.x *= s; v.y *= s; v.z *= s;
	*b2 = v;
	b1->x = v.y * n.z - v.z * n.y;
	b1->y = v.z * n.x - v.x * n.z;
	b1->z = v.x * n.y - v.y * n.x;
}
static inline void onb__hughes_moeller(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2, int norm)
{
	onb_vec3 v;
	double l2 = onb__hughes_moeller_pre(n, &v);
	onb__hughes_moeller_post(n, v, onb__rsq(l2, norm), b1, b2);
}
static inline void onb__hughes_moellerf(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2, int norm)
{
	onb_vec3f v;
	float l2 = onb__hughes_moeller_pref(n, &v);
	onb__hughes_moeller_postf(n, v, onb__rsqf(l2, norm), b1, b2);
}

static inline void ONB__K(hughes_moeller)           (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__hughes_moeller (n, b1, b2, ONB__NORM_LIBM); }
static inline void ONB__K(hughes_moellerf)          (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__hughes_moellerf(n, b1, b2, ONB__NORM_LIBM); }
static inline void ONB__K(hughes_moeller_invsqrt)   (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__hughes_moeller (n, b1, b2, ONB__NORM_INVSQRT); }
static inline void ONB__K(hughes_moeller_invsqrtf)  (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__hughes_moellerf(n, b1, b2, ONB__NORM_INVSQRT); }
static inline void ONB__K(hughes_moeller_rsqrt)     (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__hughes_moeller (n, b1, b2, ONB__NORM_RSQRT); }
static inline void ONB__K(hughes_moeller_rsqrtf)    (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__hughes_moellerf(n, b1, b2, ONB__NORM_RSQRT); }
static inline void ONB__K(hughes_moeller_rsqrt_nr)  (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__hughes_moeller (n, b1, b2, ONB__NORM_RSQRT_NR); }
static inline void ONB__K(hughes_moeller_rsqrt_nrf) (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__hughes_moellerf(n, b1, b2, ONB__NORM_RSQRT_NR); }
static inline void ONB__K(hughes_moeller_nonorm)    (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__hughes_moeller (n, b1, b2, ONB__NORM_NONE); }
static inline void ONB__K(hughes_moeller_nonormf)   (onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__hughes_moellerf(n, b1, b2, ONB__NORM_NONE); }

/* ------------------------------------------------------------------ */
/* frisvad (Frisvad 2012, Listing 2 / Equations 4-6)                   */
/* ------------------------------------------------------------------ */
/* a = 1/(1 + n.z), b = -n.x*n.y*a, b1 = (1 - n.x*n.x*a, b, -n.x),
   b2 = (b, 1 - n.y*n.y*a, -n.y); when n.z < t, the fallback
   b1 = (0, -1, 0), b2 = (-1, 0, 0).  Handedness +1 (fallback included).
   onb_frisvad uses the published t = -0.9999999 (the float literal
   -0.9999999f = -0x1.fffffcp-1 in float; the decimal -0.9999999 rounded
   to double in double, our reading for a listing written only in float).
   Singular: none exactly (the fallback covers n.z = -1), but the formula
   loses all precision as n.z -> -1: its error grows like eps/(1 + n.z),
   and in float it reaches O(1) just above the threshold.  That failure is
   the published behaviour and is kept.
   Tested bound (tests/test_lib.c): D <= 12u (1 + 2/(1 + n.z)) above t (from
   |b1|^2 - 1 = nx^2 delta/(1 + n.z)^2 with |n|^2 = 1 + delta), and
   sqrt(1 - n.z^2) + 12u for the fallback below t. */
static inline void ONB__K(frisvad_threshold)(onb_vec3 n, double t, onb_vec3 *b1, onb_vec3 *b2)
{
	double a, b;
	if (n.z < t) {
		b1->x = 0.0;  b1->y = -1.0; b1->z = 0.0;
		b2->x = -1.0; b2->y = 0.0;  b2->z = 0.0;
		return;
	}
	a = 1.0 / (1.0 + n.z);
	b = -n.x * n.y * a;
	b1->x = 1.0 - n.x * n.x * a; b1->y = b; b1->z = -n.x;
	b2->x = b; b2->y = 1.0 - n.y * n.y * a; b2->z = -n.y;
}
static inline void ONB__K(frisvad_thresholdf)(onb_vec3f n, float t, onb_vec3f *b1, onb_vec3f *b2)
{
	float a, b;
	if (n.z < t) {
		b1->x = 0.0f;  b1->y = -1.0f; b1->z = 0.0f;
		b2->x = -1.0f; b2->y = 0.0f;  b2->z = 0.0f;
		return;
	}
	a = 1.0f / (1.0f + n.z);
	b = -n.x * n.y * a;
	b1->x = 1.0f - n.x * n.x * a; b1->y = b; b1->z = -n.x;
	b2->x = b; b2->y = 1.0f - n.y * n.y * a; b2->z = -n.y;
}

#define ONB_FRISVAD_T      (-0.9999999)    /* Frisvad 2012, Listing 2 */
#define ONB_FRISVAD_TF     (-0.9999999f)
#define ONB_FRISVAD_MAX_T  (-0.99998796)   /* Max 2017, minimax for float */
#define ONB_FRISVAD_MAX_TF (-0.99998796f)

static inline void ONB__K(frisvad) (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { ONB__K(frisvad_threshold)(n, ONB_FRISVAD_T,  b1, b2); }
static inline void ONB__K(frisvadf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { ONB__K(frisvad_thresholdf)(n, ONB_FRISVAD_TF, b1, b2); }

/* frisvad_max (Nelson Max 2017, JCGT 6(1), "Improved accuracy when
   building an orthonormal basis"): Listing 2 with t = -0.99998796, where the
   formula's error above t and the fallback's error below t balance in
   float (both ~5e-3 at t).  Handedness +1.  The double variant keeps the
   same published t, although the double minimax lies much nearer -1
   (`onbstudy threshold --precision double` finds it). */
static inline void ONB__K(frisvad_max) (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { ONB__K(frisvad_threshold)(n, ONB_FRISVAD_MAX_T,  b1, b2); }
static inline void ONB__K(frisvad_maxf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { ONB__K(frisvad_thresholdf)(n, ONB_FRISVAD_MAX_TF, b1, b2); }

/* Frisvad 2012, Equation 3: the direction (x, y, z) given around the
   z-axis, rotated to the same direction around n, without the basis:
   w = x*(1 - nx^2 a, -nx ny a, -nx) + y*(-nx ny a, 1 - ny^2 a, -ny) + z*n
   with a = 1/(1 + n.z).  Singular case as published: when 1 + n.z == 0
   (n = -z), w = (-y, -x, -z).  No threshold: just above -1 the float
   result has the formula's full O(eps/(1 + n.z)) error. */
static inline onb_vec3 ONB__K(frisvad_rotate)(onb_vec3 n, double x, double y, double z)
{
	onb_vec3 w;
	double s = 1.0 + n.z, a, b;
	if (s <= 0.0 && s >= 0.0) { w.x = -y; w.y = -x; w.z = -z; return w; } /* s == 0, without -Wfloat-equal */
	a = 1.0 / s;
	b = -n.x * n.y * a;
	w.x = x * (1.0 - n.x * n.x * a) + y * b + z * n.x;
	w.y = x * b + y * (1.0 - n.y * n.y * a) + z * n.y;
	w.z = x * -n.x + y * -n.y + z * n.z;
	return w;
}
static inline onb_vec3f ONB__K(frisvad_rotatef)(onb_vec3f n, float x, float y, float z)
{
	onb_vec3f w;
	float s = 1.0f + n.z, a, b;
	if (s <= 0.0f && s >= 0.0f) { w.x = -y; w.y = -x; w.z = -z; return w; } /* s == 0 */
	a = 1.0f / s;
	b = -n.x * n.y * a;
	w.x = x * (1.0f - n.x * n.x * a) + y * b + z * n.x;
	w.y = x * b + y * (1.0f - n.y * n.y * a) + z * n.y;
	w.z = x * -n.x + y * -n.y + z * n.z;
	return w;
}

/* ------------------------------------------------------------------ */
/* duff (Duff et al. 2017, JCGT 6(1), Listing 2, "revisedONB")         */
/* ------------------------------------------------------------------ */
/* Frisvad's formula for n.z >= 0, and its mirror for n.z < 0:
   a = 1/(1 - n.z), b = n.x*n.y*a, b1 = (1 - n.x*n.x*a, -b, n.x),
   b2 = (b, n.y*n.y*a - 1, -n.y).  Handedness +1 in both branches.
   Threshold: the sign of n.z (n.z = -0 takes the n.z >= 0 branch, since
   -0 < 0 is false).  No singular unit direction: 1 +- n.z >= 1.  The
   frame is discontinuous across n.z = 0 (b2 flips sign in y).
   Tested bound (tests/test_lib.c): D <= 12u on unit-to-rounding n, n = +-z
   included. */
static inline void ONB__K(duff)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	if (n.z < 0.0) {
		const double a = 1.0 / (1.0 - n.z);
		const double b = n.x * n.y * a;
		b1->x = 1.0 - n.x * n.x * a; b1->y = -b; b1->z = n.x;
		b2->x = b; b2->y = n.y * n.y * a - 1.0; b2->z = -n.y;
	} else {
		const double a = 1.0 / (1.0 + n.z);
		const double b = -n.x * n.y * a;
		b1->x = 1.0 - n.x * n.x * a; b1->y = b; b1->z = -n.x;
		b2->x = b; b2->y = 1.0 - n.y * n.y * a; b2->z = -n.y;
	}
}
static inline void ONB__K(dufff)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	if (n.z < 0.0f) {
		const float a = 1.0f / (1.0f - n.z);
		const float b = n.x * n.y * a;
		b1->x = 1.0f - n.x * n.x * a; b1->y = -b; b1->z = n.x;
		b2->x = b; b2->y = n.y * n.y * a - 1.0f; b2->z = -n.y;
	} else {
		const float a = 1.0f / (1.0f + n.z);
		const float b = -n.x * n.y * a;
		b1->x = 1.0f - n.x * n.x * a; b1->y = b; b1->z = -n.x;
		b2->x = b; b2->y = 1.0f - n.y * n.y * a; b2->z = -n.y;
	}
}

/* duff_branchless (Duff et al. 2017, Listing 3; pbrt-v4's CoordinateSystem
   bit for bit, the alias pbrt_v4; Mitsuba 3's coordinate_system is the same
   formula with another product order): sign = copysign(1, n.z),
   a = -1/(sign + n.z), b = n.x*n.y*a,
   b1 = (1 + sign*n.x*n.x*a, sign*b, -sign*n.x), b2 = (b, sign + n.y*n.y*a, -n.y).
   Handedness +1.  Threshold: the sign bit of n.z, so n.z = -0 takes the
   lower branch (unlike `duff`).  No singular unit direction.
   Tested bound (tests/test_lib.c): D <= 12u, as duff. */
static inline void ONB__K(duff_branchless)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double sign = copysign(1.0, n.z);
	const double a = -1.0 / (sign + n.z);
	const double b = n.x * n.y * a;
	b1->x = 1.0 + sign * n.x * n.x * a; b1->y = sign * b; b1->z = -sign * n.x;
	b2->x = b; b2->y = sign + n.y * n.y * a; b2->z = -n.y;
}
static inline void ONB__K(duff_branchlessf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float sign = copysignf(1.0f, n.z);
	const float a = -1.0f / (sign + n.z);
	const float b = n.x * n.y * a;
	b1->x = 1.0f + sign * n.x * n.x * a; b1->y = sign * b; b1->z = -sign * n.x;
	b2->x = b; b2->y = sign + n.y * n.y * a; b2->z = -n.y;
}

/* ------------------------------------------------------------------ */
/* stark (Stark 2009, JGT 14(1), "Efficient construction of            */
/* perpendicular vectors without branching"), as published             */
/* ------------------------------------------------------------------ */
/* p = cross(n, (xm, ym, zm)) with Stark's branch-free listing:
   uyx = SIGNBIT(|x| - |y|), uzx = SIGNBIT(|x| - |z|), uzy = SIGNBIT(|y| -
   |z|), xm = uyx & uzx, ym = (1^xm) & uzy, zm = 1^(xm & ym).  Since xm and
   ym are never both 1, the published zm is always 1 (Hill 2011, "Perpendicular
   Possibilities", points this out: the intent is 1^(xm | ym), which is
   `stark_fixed`).  So e = (1,0,1) when |x| is smallest, (0,1,1) when |y|
   is, (0,0,1) otherwise.  SIGNBIT of a difference of two absolute values
   is `< 0` (x - x = +0); the uint-to-float conversion of 0 and 1 is a
   select.  Then (our completion, as the issue reads it) b1 = p / |p| with
   1/sqrt, b2 = cross(n, b1).  Handedness +1.  Thresholds: |x| = |y|,
   |x| = |z|, |y| = |z|.  No singular unit direction: |p|^2 >= 2/3 -
   O(eps).  Tested bound (tests/test_lib.c): D <= 12u. */
static inline double onb__stark_pre(onb_vec3 n, onb_vec3 *p, int fixed)
{
	const double ax = fabs(n.x), ay = fabs(n.y), az = fabs(n.z);
	const int xm = (ax - ay < 0.0) & (ax - az < 0.0);
	const int ym = (ay - az < 0.0) & !xm;
	const int zm = fixed ? !(xm | ym) : !(xm & ym);
	const double ex = xm ? 1.0 : 0.0, ey = ym ? 1.0 : 0.0, ez = zm ? 1.0 : 0.0;
	p->x = n.y * ez - n.z * ey;
	p->y = n.z * ex - n.x * ez;
	p->z = n.x * ey - n.y * ex;
	return p->x * p->x + p->y * p->y + p->z * p->z;
}
static inline float onb__stark_pref(onb_vec3f n, onb_vec3f *p, int fixed)
{
	const float ax = fabsf(n.x), ay = fabsf(n.y), az = fabsf(n.z);
	const int xm = (ax - ay < 0.0f) & (ax - az < 0.0f);
	const int ym = (ay - az < 0.0f) & !xm;
	const int zm = fixed ? !(xm | ym) : !(xm & ym);
	const float ex = xm ? 1.0f : 0.0f, ey = ym ? 1.0f : 0.0f, ez = zm ? 1.0f : 0.0f;
	p->x = n.y * ez - n.z * ey;
	p->y = n.z * ex - n.x * ez;
	p->z = n.x * ey - n.y * ex;
	return p->x * p->x + p->y * p->y + p->z * p->z;
}
static inline void ONB__K(stark)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 p;
	const double s = 1.0 / sqrt(onb__stark_pre(n, &p, 0));
	onb__naive_post(n, p, s, b1, b2);
}
static inline void ONB__K(starkf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f p;
	const float s = 1.0f / sqrtf(onb__stark_pref(n, &p, 0));
	onb__naive_postf(n, p, s, b1, b2);
}

/* stark_fixed: Stark's listing with zm = 1^(xm | ym), the correction of
   Hill 2011 (blog.selfshadow.com/2011/10/17/perp-vectors, after Listing 3),
   so that e_k is the axis of n's smallest |component| as Stark's text
   says.  Otherwise as `stark`.  |p|^2 >= 2/3 - O(eps).  Tested bound: D <= 12u. */
static inline void ONB__K(stark_fixed)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 p;
	const double s = 1.0 / sqrt(onb__stark_pre(n, &p, 1));
	onb__naive_post(n, p, s, b1, b2);
}
static inline void ONB__K(stark_fixedf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f p;
	const float s = 1.0f / sqrtf(onb__stark_pref(n, &p, 1));
	onb__naive_postf(n, p, s, b1, b2);
}

/* ------------------------------------------------------------------ */
/* pbrt_v3 (pbrt-v3 src/core/geometry.h, CoordinateSystem)             */
/* ------------------------------------------------------------------ */
/* if |v.x| > |v.y|: b1 = (-v.z, 0, v.x) / sqrt(v.x^2 + v.z^2)
   else:            b1 = (0, v.z, -v.y) / sqrt(v.y^2 + v.z^2)
   b2 = cross(v, b1).  pbrt-v3's Vector3 operator/ multiplies by
   inv = (Float)1/f, which we keep.  pbrt-v3's Cross widens both operands
   to double, subtracts the (exact, for float operands) products in double
   and converts the result to the vector's type: the float variant does
   the same (the double variant is pbrt-v3 built with
   PBRT_FLOAT_AS_DOUBLE, where the widening is a no-op).  Handedness +1.
   Threshold: |x| = |y|.
   No singular unit direction (squared length >= 1/2 - O(eps)).
   Tested bound (tests/test_lib.c): D <= 12u. */
static inline void ONB__K(pbrt_v3)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 u;
	double inv;
	if (fabs(n.x) > fabs(n.y)) {
		inv = 1.0 / sqrt(n.x * n.x + n.z * n.z);
		u.x = -n.z * inv; u.y = 0.0 * inv; u.z = n.x * inv;
	} else {
		inv = 1.0 / sqrt(n.y * n.y + n.z * n.z);
		u.x = 0.0 * inv; u.y = n.z * inv; u.z = -n.y * inv;
	}
	onb__naive_post(n, u, 1.0, b1, b2);
}
static inline void ONB__K(pbrt_v3f)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f u;
	float inv;
	if (fabsf(n.x) > fabsf(n.y)) {
		inv = 1.0f / sqrtf(n.x * n.x + n.z * n.z);
		u.x = -n.z * inv; u.y = 0.0f * inv; u.z = n.x * inv;
	} else {
		inv = 1.0f / sqrtf(n.y * n.y + n.z * n.z);
		u.x = 0.0f * inv; u.y = n.z * inv; u.z = -n.y * inv;
	}
	*b1 = u;
	{	/* pbrt-v3 Cross: operands widened to double (products exact), the
		   difference rounded to double, then converted to float */
		const double vx = ONB__CAST(double, n.x), vy = ONB__CAST(double, n.y), vz = ONB__CAST(double, n.z), wx = ONB__CAST(double, u.x), wy = ONB__CAST(double, u.y), wz = ONB__CAST(double, u.z);
		b2->x = ONB__CAST(float, vy * wz - vz * wy);
		b2->y = ONB__CAST(float, vz * wx - vx * wz);
		b2->z = ONB__CAST(float, vx * wy - vy * wx);
	}
}

/* ------------------------------------------------------------------ */
/* rtow ("Ray Tracing: The Rest of Your Life", onb::build_from_w)      */
/* ------------------------------------------------------------------ */
/* unit_w = w / |w| (the book's operator/ multiplies by 1/t);
   a = (0,1,0) if |unit_w.x| > 0.9 else (1,0,0); v = unit(cross(unit_w, a));
   u = cross(unit_w, v).  Returned in the book's axis order: b1 = u,
   b2 = v, with unit_w (not n) as the implied third axis.  Handedness -1:
   u x v = -w.  The only method here that normalizes its input.
   Threshold: |w.x| = 0.9.  Singular: w = 0 only.
   Tested bound (tests/test_lib.c): D <= 12u, measured against unit(w). */
static inline void ONB__K(rtow)(onb_vec3 w, onb_vec3 *b1, onb_vec3 *b2)
{
	double inv = 1.0 / sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
	onb_vec3 uw, a, c, v;
	double il;
	uw.x = inv * w.x; uw.y = inv * w.y; uw.z = inv * w.z;
	if (fabs(uw.x) > 0.9) { a.x = 0.0; a.y = 1.0; a.z = 0.0; }
	else                  { a.x = 1.0; a.y = 0.0; a.z = 0.0; }
	c.x = uw.y * a.z - uw.z * a.y;
	c.y = uw.z * a.x - uw.x * a.z;
	c.z = uw.x * a.y - uw.y * a.x;
	il = 1.0 / sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
	v.x = il * c.x; v.y = il * c.y; v.z = il * c.z;
	b1->x = uw.y * v.z - uw.z * v.y;
	b1->y = uw.z * v.x - uw.x * v.z;
	b1->z = uw.x * v.y - uw.y * v.x;
	*b2 = v;
}
static inline void ONB__K(rtowf)(onb_vec3f w, onb_vec3f *b1, onb_vec3f *b2)
{
	float inv = 1.0f / sqrtf(w.x * w.x + w.y * w.y + w.z * w.z);
	onb_vec3f uw, a, c, v;
	float il;
	uw.x = inv * w.x; uw.y = inv * w.y; uw.z = inv * w.z;
	if (fabsf(uw.x) > 0.9f) { a.x = 0.0f; a.y = 1.0f; a.z = 0.0f; }
	else                    { a.x = 1.0f; a.y = 0.0f; a.z = 0.0f; }
	c.x = uw.y * a.z - uw.z * a.y;
	c.y = uw.z * a.x - uw.x * a.z;
	c.z = uw.x * a.y - uw.y * a.x;
	il = 1.0f / sqrtf(c.x * c.x + c.y * c.y + c.z * c.z);
	v.x = il * c.x; v.y = il * c.y; v.z = il * c.z;
	b1->x = uw.y * v.z - uw.z * v.y;
	b1->y = uw.z * v.x - uw.x * v.z;
	b1->z = uw.x * v.y - uw.y * v.x;
	*b2 = v;
}

/* ------------------------------------------------------------------ */
/* tangent_cross_z (blog "Vector transformation using projection       */
/* between orthonormal bases", Python get_onb)                         */
/* ------------------------------------------------------------------ */
/* t = (n.x, n.y, n.z + 1) (our reading of the post's garbled
   `t = [n, n, n + 1]`), binormal = normalize(cross(n, t)) with
   normalize(v) = v / |v| (division, as a Python list comprehension
   would), tangent = cross(n, binormal); returned [tangent, binormal, n],
   so b1 = tangent, b2 = binormal.  Handedness -1.
   Singular: n = +z and n = -z exactly (cross(n, t) = 0, 0/0 = NaN), and
   in float any n with n.x^2 + n.y^2 below the smallest subnormal, where
   the squared length underflows.
   Tested bound (tests/test_lib.c): D <= 12u away from +-z. */
static inline void ONB__K(tangent_cross_z)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double tx = n.x, ty = n.y, tz = n.z + 1.0;
	double cx = n.y * tz - n.z * ty;
	double cy = n.z * tx - n.x * tz;
	double cz = n.x * ty - n.y * tx;
	const double l = sqrt(cx * cx + cy * cy + cz * cz);
	cx = cx / l; cy = cy / l; cz = cz / l;
	b2->x = cx; b2->y = cy; b2->z = cz;
	b1->x = n.y * cz - n.z * cy;
	b1->y = n.z * cx - n.x * cz;
	b1->z = n.x * cy - n.y * cx;
}
static inline void ONB__K(tangent_cross_zf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float tx = n.x, ty = n.y, tz = n.z + 1.0f;
	float cx = n.y * tz - n.z * ty;
	float cy = n.z * tx - n.x * tz;
	float cz = n.x * ty - n.y * tx;
	const float l = sqrtf(cx * cx + cy * cy + cz * cz);
	cx = cx / l; cy = cy / l; cz = cz / l;
	b2->x = cx; b2->y = cy; b2->z = cz;
	b1->x = n.y * cz - n.z * cy;
	b1->y = n.z * cx - n.x * cz;
	b1->z = n.x * cy - n.y * cx;
}

/* ------------------------------------------------------------------ */
/* Engines' shipped code ("every ONB in the wild"): each as the engine */
/* writes it, at the commit its registry row names (onb_method.prov). */
/* ------------------------------------------------------------------ */

/* q2rtx (Quake II RTX, src/refresh/vkpt/shader/utils.glsl,
   construct_ONB_frisvad): Frisvad's Listing 2 term for term with the
   threshold -0.999805696f (Max's digits, mistyped?: 16 times further from
   -1 than Max's -0.99998796), under GLSL `precise`.  The double variant
   keeps the float literal, widened (the same n.z splits the branches).
   Handedness +1 (the shader's mat3 columns are (b1, n, b2)). */
#define ONB_Q2RTX_TF (-0.999805696f)
static inline void ONB__K(q2rtx) (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { ONB__K(frisvad_threshold)(n, ONB__CAST(double, ONB_Q2RTX_TF), b1, b2); }
static inline void ONB__K(q2rtxf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { ONB__K(frisvad_thresholdf)(n, ONB_Q2RTX_TF, b1, b2); }

/* filament (Filament libs/geometry/src/TangentSpaceMesh.cpp,
   frisvadKernel): Frisvad's Listing 2 rotated to y-up, x -> z -> y -> x:
   when n.y < -1 + FLT_EPSILON (= -0x1.fffffcp-1, Frisvad's float t),
   b1 = (-1, 0, 0), b2 = (0, 0, -1); else va = 1/(1 + n.y), vb = -n.z*n.x*va,
   b1 = (vb, -n.z, 1 - n.z*n.z*va), b2 = (1 - n.x*n.x*va, -n.x, vb)
   (Filament's tangent t and bitangent b).  Bit for bit Frisvad's float
   kernel on (n.z, n.x, n.y), outputs relabelled back; the pole is -y.
   Handedness +1.  The double variant keeps the float constant, widened. */
#define ONB_FILAMENT_TF (-0x1.fffffcp-1f) /* -1.0f + FLT_EPSILON */
static inline void ONB__K(filament)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	double va, vb;
	if (n.y < ONB__CAST(double, ONB_FILAMENT_TF)) {
		b1->x = -1.0; b1->y = 0.0; b1->z = 0.0;
		b2->x = 0.0;  b2->y = 0.0; b2->z = -1.0;
		return;
	}
	va = 1.0 / (1.0 + n.y);
	vb = -n.z * n.x * va;
	b1->x = vb; b1->y = -n.z; b1->z = 1.0 - n.z * n.z * va;
	b2->x = 1.0 - n.x * n.x * va; b2->y = -n.x; b2->z = vb;
}
static inline void ONB__K(filamentf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	float va, vb;
	if (n.y < ONB_FILAMENT_TF) {
		b1->x = -1.0f; b1->y = 0.0f; b1->z = 0.0f;
		b2->x = 0.0f;  b2->y = 0.0f; b2->z = -1.0f;
		return;
	}
	va = 1.0f / (1.0f + n.y);
	vb = -n.z * n.x * va;
	b1->x = vb; b1->y = -n.z; b1->z = 1.0f - n.z * n.z * va;
	b2->x = 1.0f - n.x * n.x * va; b2->y = -n.x; b2->z = vb;
}

/* filament_hm (Filament libs/geometry/src/TangentSpaceMesh.cpp,
   hughesMollerMethod, the HUGHES_MOLLER algorithm of the same file):
   t = (-n.y, n.x, 0) when |n.x| > |n.z| + FLT_EPSILON, else (0, -n.z,
   n.y); t = t * (1/sqrt(dot(t, t))) (filament::math normalize); b = n x t;
   the frame {t, b, n}: b1 = t, b2 = b.  Handedness +1.  The exact formula
   is eigen's with another branch rule (|x| = |z| + 2^-23).  The double
   variant keeps FLT_EPSILON (2^-23).  No singular unit direction.
   Tested bound (tests/test_lib.c): D <= 12u. */
#define ONB_FILAMENT_HM_EPS 0x1p-23f /* std::numeric_limits<float>::epsilon() */
static inline void ONB__K(filament_hm)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 t;
	double r;
	if (fabs(n.x) > fabs(n.z) + ONB__CAST(double, ONB_FILAMENT_HM_EPS)) {
		t.x = -n.y; t.y = n.x; t.z = 0.0;
	} else {
		t.x = 0.0; t.y = -n.z; t.z = n.y;
	}
	r = 1.0 / sqrt(t.x * t.x + t.y * t.y + t.z * t.z);
	t.x *= r; t.y *= r; t.z *= r;
	*b1 = t;
	b2->x = n.y * t.z - n.z * t.y;
	b2->y = n.z * t.x - n.x * t.z;
	b2->z = n.x * t.y - n.y * t.x;
}
static inline void ONB__K(filament_hmf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f t;
	float r;
	if (fabsf(n.x) > fabsf(n.z) + ONB_FILAMENT_HM_EPS) {
		t.x = -n.y; t.y = n.x; t.z = 0.0f;
	} else {
		t.x = 0.0f; t.y = -n.z; t.z = n.y;
	}
	r = 1.0f / sqrtf(t.x * t.x + t.y * t.y + t.z * t.z);
	t.x *= r; t.y *= r; t.z *= r;
	*b1 = t;
	b2->x = n.y * t.z - n.z * t.y;
	b2->y = n.z * t.x - n.x * t.z;
	b2->z = n.x * t.y - n.y * t.x;
}

/* capsaicin (AMD Capsaicin src/core/src/math/sampling.hlsl,
   GetOrthoVectors, HLSL float): when |n.z| > 0, k = 1/sqrt(z*z + y*y),
   b1 = (0, (-z)*k, y*k); when n.z is +-0, k = 1/sqrt(x*x + y*y) and b1 =
   (y*k, (-x)*k, 0) (the source's swizzles p2 = n.zyx, b1.zyx); b2 = n x b1.
   Handedness +1.  Exactly b1 = unit(e_x x n) or unit(n x e_z), never
   singular on the sphere; in rounding, z*z + y*y underflows near +-x with
   n.z != 0: NaN at n = (1, 0, 1e-25) in float (k = inf, 0*inf), and the
   squares lose precision in the subnormals above that.  The published
   behaviour, kept; capsaicin_fixed is the fix.  The double variant is the
   same code in double (underflow near 1e-162). */
static inline void onb__capsaicin(onb_vec3 n, int sel, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 b;
	double k;
	if (sel) {
		k = 1.0 / sqrt(n.z * n.z + n.y * n.y);
		b.x = 0.0; b.y = -n.z * k; b.z = n.y * k;
	} else {
		k = 1.0 / sqrt(n.x * n.x + n.y * n.y);
		b.x = n.y * k; b.y = -n.x * k; b.z = 0.0;
	}
	*b1 = b;
	b2->x = n.y * b.z - n.z * b.y;
	b2->y = n.z * b.x - n.x * b.z;
	b2->z = n.x * b.y - n.y * b.x;
}
static inline void onb__capsaicinf(onb_vec3f n, int sel, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f b;
	float k;
	if (sel) {
		k = 1.0f / sqrtf(n.z * n.z + n.y * n.y);
		b.x = 0.0f; b.y = -n.z * k; b.z = n.y * k;
	} else {
		k = 1.0f / sqrtf(n.x * n.x + n.y * n.y);
		b.x = n.y * k; b.y = -n.x * k; b.z = 0.0f;
	}
	*b1 = b;
	b2->x = n.y * b.z - n.z * b.y;
	b2->y = n.z * b.x - n.x * b.z;
	b2->z = n.x * b.y - n.y * b.x;
}
static inline void ONB__K(capsaicin) (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__capsaicin (n, fabs(n.z) > 0.0, b1, b2); }
static inline void ONB__K(capsaicinf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__capsaicinf(n, fabsf(n.z) > 0.0f, b1, b2); }
/* capsaicin_fixed (this project's fix of capsaicin, not shipped code): the
   one-line change sel = abs(n.z) > abs(n.x) in place of abs(n.z) > 0, so
   the vector normalized has squared length >= 1/2 - O(u) for unit n (as
   Hughes-Moller's); the same formulas and the same frames at the six axes
   (the tie |z| = |x| = 0 at +-y takes the n.z = 0 branch, as before). */
static inline void ONB__K(capsaicin_fixed) (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2) { onb__capsaicin (n, fabs(n.z) > fabs(n.x), b1, b2); }
static inline void ONB__K(capsaicin_fixedf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__capsaicinf(n, fabsf(n.z) > fabsf(n.x), b1, b2); }

/* unity (Unity Graphics, com.unity.render-pipelines.core ShaderLibrary/
   CommonLighting.hlsl, GetLocalFrame(localZ), HLSL real = float): Reynolds'
   form of Duff's basis (ortho_basis_pixar_r2), turned by 180 degrees:
   sz = FastSign(z) = (z >= 0 ? 1 : -1: -0 takes +1, NaN -1), a = 1/(sz + z),
   ya = y*a, b = x*ya, c = x*sz; b1 = localX = ((c*x)*a - 1, sz*b, c),
   b2 = localY = (b, y*ya - sz, y).  Exactly (-b1, -b2) of duff's formula, with
   the products grouped x*(y*a) and y*(y*a).  Handedness +1.  At +z, b1 =
   -x and b2 = -y.  The double variant is the same code in double. */
static inline void ONB__K(unity)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double sz = n.z >= 0.0 ? 1.0 : -1.0;
	const double a = 1.0 / (sz + n.z);
	const double ya = n.y * a, b = n.x * ya, c = n.x * sz;
	b1->x = c * n.x * a - 1.0; b1->y = sz * b; b1->z = c;
	b2->x = b; b2->y = n.y * ya - sz; b2->z = n.y;
}
static inline void ONB__K(unityf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float sz = n.z >= 0.0f ? 1.0f : -1.0f;
	const float a = 1.0f / (sz + n.z);
	const float ya = n.y * a, b = n.x * ya, c = n.x * sz;
	b1->x = c * n.x * a - 1.0f; b1->y = sz * b; b1->z = c;
	b2->x = b; b2->y = n.y * ya - sz; b2->z = n.y;
}

/* ------------------------------------------------------------------ */
/* Shader sources read under IEEE arithmetic (GLSL/HLSL float as C     */
/* float, no mad contraction): willems, gltf_viewer, rtao              */
/* ------------------------------------------------------------------ */
/* cross(a, b) = (a.y*b.z - b.y*a.z, a.z*b.x - b.z*a.x, a.x*b.y -
   b.x*a.y) (GLSL; HLSL's a.yzx*b.zxy - a.zxy*b.yzx is the same), the
   products of onb.h's cross; normalize(v) = v / length(v): each component
   divided by sqrt(dot(v, v)), dot = (x*x + y*y) + z*z. */
static inline onb_vec3 onb__sh_cross(onb_vec3 a, onb_vec3 b)
{
	onb_vec3 r;
	r.x = a.y * b.z - a.z * b.y; r.y = a.z * b.x - a.x * b.z; r.z = a.x * b.y - a.y * b.x;
	return r;
}
static inline onb_vec3f onb__sh_crossf(onb_vec3f a, onb_vec3f b)
{
	onb_vec3f r;
	r.x = a.y * b.z - a.z * b.y; r.y = a.z * b.x - a.x * b.z; r.z = a.x * b.y - a.y * b.x;
	return r;
}
static inline onb_vec3 onb__sh_normalize(onb_vec3 v)
{
	const double l = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
	v.x /= l; v.y /= l; v.z /= l;
	return v;
}
static inline onb_vec3f onb__sh_normalizef(onb_vec3f v)
{
	const float l = sqrtf(v.x * v.x + v.y * v.y + v.z * v.z);
	v.x /= l; v.y /= l; v.z /= l;
	return v;
}

/* willems (Sascha Willems' Vulkan samples, shaders/glsl/pbribl/
   prefilterenvmap.frag importanceSample_GGX, GLSL float; the HLSL and
   Slang copies are the same): up = (0,0,1) when abs(n.z) < 0.999 (NaN:
   false), else (1,0,0); b1 = tangentX = normalize(cross(up, n)), b2 =
   tangentY = normalize(cross(n, tangentX)).  Handedness +1.  On the unit
   sphere |cross(up, n)|^2 >= 1 - 0.999^2: no singular direction.  The
   double variant is the same code in double (0.999 a double). */
static inline void ONB__K(willems)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 up;
	up.x = 0.0; up.y = 0.0; up.z = 1.0;
	if (!(fabs(n.z) < 0.999)) {
		up.x = 1.0; up.z = 0.0;
	}
	*b1 = onb__sh_normalize(onb__sh_cross(up, n));
	*b2 = onb__sh_normalize(onb__sh_cross(n, *b1));
}
static inline void ONB__K(willemsf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f up;
	up.x = 0.0f; up.y = 0.0f; up.z = 1.0f;
	if (!(fabsf(n.z) < 0.999f)) {
		up.x = 1.0f; up.z = 0.0f;
	}
	*b1 = onb__sh_normalizef(onb__sh_crossf(up, n));
	*b2 = onb__sh_normalizef(onb__sh_crossf(n, *b1));
}

/* gltf_viewer (Khronos glTF-Sample-Viewer, source/shaders/ibl_filtering.frag
   generateTBN, GLSL mediump read as float): bitangent = (0,1,0); NdotUp =
   dot(n, (0,1,0)) = (n.x*0 + n.y*1) + n.z*0; when 1 - abs(NdotUp) <=
   0.0000001 the bitangent is (0,0,1) if NdotUp > 0 else (0,0,-1);
   b1 = tangent = normalize(cross(bitangent, n)), b2 = cross(n, tangent),
   the mat3 columns (tangent, bitangent, normal).  Handedness +1.  The guard
   keeps |cross|^2 >= ~2e-7: no singular direction.  The double variant is
   the same code in double (the threshold 1e-7 a double). */
static inline void ONB__K(gltf_viewer)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double d = n.x * 0.0 + n.y * 1.0 + n.z * 0.0;
	onb_vec3 up;
	up.x = 0.0; up.y = 1.0; up.z = 0.0;
	if (1.0 - fabs(d) <= 0.0000001) {
		up.y = 0.0; up.z = d > 0.0 ? 1.0 : -1.0;
	}
	*b1 = onb__sh_normalize(onb__sh_cross(up, n));
	*b2 = onb__sh_cross(n, *b1);
}
static inline void ONB__K(gltf_viewerf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float d = n.x * 0.0f + n.y * 1.0f + n.z * 0.0f;
	onb_vec3f up;
	up.x = 0.0f; up.y = 1.0f; up.z = 0.0f;
	if (1.0f - fabsf(d) <= 0.0000001f) {
		up.y = 0.0f; up.z = d > 0.0f ? 1.0f : -1.0f;
	}
	*b1 = onb__sh_normalizef(onb__sh_crossf(up, n));
	*b2 = onb__sh_crossf(n, *b1);
}

/* rtao (DirectX-Graphics-Samples, D3D12RaytracingRealTimeDenoisedAmbient-
   Occlusion RTAO/Shaders/RayGen.hlsli GetRandomRayDirection, HLSL float):
   w = n, right = 0.3f*w + (-0.72f, 0.56f, -0.34f); v = normalize(cross(w,
   right)), u = cross(v, w); the ray is sample.x*u + sample.y*v + sample.z*w:
   b1 = u, b2 = v.  Handedness +1.  Exactly cross(w, right) = cross(w, c):
   zero where n is parallel to c = (-0.72, 0.56, -0.34), O(1) defect near it
   (NaN where the cross product rounds to 0).  fixed = 1 (rtao_fixed, not
   shipped): c' = (0.56, 0.72, 0), orthogonal to c, in place of c where
   abs(dot(w, c)) > 0.875 (within ~26 degrees of +-c), so |cross(w, c)| >=
   ~0.42 and |cross(w, c')| >= ~0.82: the same frames at the six axes.
   The double variant is the same code in double (the constants doubles). */
static inline void onb__rtao(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2, int fixed)
{
	onb_vec3 c, r;
	c.x = -0.72; c.y = 0.56; c.z = -0.34;
	if (fixed && fabs(n.x * -0.72 + n.y * 0.56 + n.z * -0.34) > 0.875) {
		c.x = 0.56; c.y = 0.72; c.z = 0.0;
	}
	r.x = 0.3 * n.x + c.x; r.y = 0.3 * n.y + c.y; r.z = 0.3 * n.z + c.z;
	*b2 = onb__sh_normalize(onb__sh_cross(n, r));
	*b1 = onb__sh_cross(*b2, n);
}
static inline void onb__rtaof(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2, int fixed)
{
	onb_vec3f c, r;
	c.x = -0.72f; c.y = 0.56f; c.z = -0.34f;
	if (fixed && fabsf(n.x * -0.72f + n.y * 0.56f + n.z * -0.34f) > 0.875f) {
		c.x = 0.56f; c.y = 0.72f; c.z = 0.0f;
	}
	r.x = 0.3f * n.x + c.x; r.y = 0.3f * n.y + c.y; r.z = 0.3f * n.z + c.z;
	*b2 = onb__sh_normalizef(onb__sh_crossf(n, r));
	*b1 = onb__sh_crossf(*b2, n);
}
static inline void ONB__K(rtao)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2) { onb__rtao(n, b1, b2, 0); }
static inline void ONB__K(rtaof)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__rtaof(n, b1, b2, 0); }
static inline void ONB__K(rtao_fixed)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2) { onb__rtao(n, b1, b2, 1); }
static inline void ONB__K(rtao_fixedf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__rtaof(n, b1, b2, 1); }

/* filament_fixed (this project's fix of filament, not shipped code):
   Filament's formula for n.y >= 0 (-0 included), and below it Duff et
   al.'s lower-hemisphere formula on the same relabelled (n.z, n.x, n.y),
   its pair turned a quarter (b1, b2) -> (b2, -b1) so that n = -y keeps
   Filament's fallback frame ((-1, 0, 0), (0, 0, -1)): a = 1/(1 - n.y),
   b = n.z*n.x*a, b1 = (n.x*n.x*a - 1, -n.x, b), b2 = (b, -n.z,
   -(1 - n.z*n.z*a)).  A branch on the sign instead of the threshold, as
   Duff et al. revised Frisvad's; the same frame at the six axes (up to
   the sign of a zero).  Handedness +1. */
static inline void ONB__K(filament_fixed)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	double a, b;
	if (n.y < 0.0) {
		a = 1.0 / (1.0 - n.y);
		b = n.z * n.x * a;
		b1->x = n.x * n.x * a - 1.0; b1->y = -n.x; b1->z = b;
		b2->x = b; b2->y = -n.z; b2->z = -(1.0 - n.z * n.z * a);
		return;
	}
	a = 1.0 / (1.0 + n.y);
	b = -n.z * n.x * a;
	b1->x = b; b1->y = -n.z; b1->z = 1.0 - n.z * n.z * a;
	b2->x = 1.0 - n.x * n.x * a; b2->y = -n.x; b2->z = b;
}
static inline void ONB__K(filament_fixedf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	float a, b;
	if (n.y < 0.0f) {
		a = 1.0f / (1.0f - n.y);
		b = n.z * n.x * a;
		b1->x = n.x * n.x * a - 1.0f; b1->y = -n.x; b1->z = b;
		b2->x = b; b2->y = -n.z; b2->z = -(1.0f - n.z * n.z * a);
		return;
	}
	a = 1.0f / (1.0f + n.y);
	b = -n.z * n.x * a;
	b1->x = b; b1->y = -n.z; b1->z = 1.0f - n.z * n.z * a;
	b2->x = 1.0f - n.x * n.x * a; b2->y = -n.x; b2->z = b;
}

/* mitsuba3 (Mitsuba 3 include/mitsuba/core/vector.h, coordinate_system,
   scalar variants, Dr.Jit without FMA): Duff's Listing 3 with Dr.Jit's
   helpers: a = -(1/(s + n.z)), b1.x = mulsign(x*x*a, z) + 1 (the sign
   flip is exact: s*(x*x*a)), b2.y = fmadd(y, y*a, s) = y*(y*a) + s: the
   product order differs from Listing 3's (y*y)*a, so the bits differ from
   duff_branchless (about 8% of float inputs, in b2.y).  Same exact
   formula and branch (signbit(n.z)).  Handedness +1. */
static inline void ONB__K(mitsuba3)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double sign = copysign(1.0, n.z);
	const double a = -(1.0 / (sign + n.z));
	const double b = n.x * n.y * a;
	b1->x = sign * (n.x * n.x * a) + 1.0; b1->y = sign * b; b1->z = -sign * n.x;
	b2->x = b; b2->y = n.y * (n.y * a) + sign; b2->z = -n.y;
}
static inline void ONB__K(mitsuba3f)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float sign = copysignf(1.0f, n.z);
	const float a = -(1.0f / (sign + n.z));
	const float b = n.x * n.y * a;
	b1->x = sign * (n.x * n.x * a) + 1.0f; b1->y = sign * b; b1->z = -sign * n.x;
	b2->x = b; b2->y = n.y * (n.y * a) + sign; b2->z = -n.y;
}

/* cycles_cross111 (Blender Cycles src/util/math_float3.h,
   make_orthonormals, since its first release): a = (1,1,1) x n =
   (n.z - n.y, n.x - n.z, n.y - n.x), or (-1,1,1) x n = (n.z - n.y,
   n.x + n.z, -n.y - n.x) when n.x = n.y = n.z; b1 = a / |a| (three
   divisions, |a| = sqrt of the squares summed left to right), b2 =
   cross(n, b1).  Cycles' SSE4.2 kernel (dpps, lane-wise division and
   products) gives these bits; its AVX2 kernel fuses the cross (fmsub).
   Near +-(1,1,1)/sqrt(3) the differences are exact (Sterbenz), so no
   precision is lost there; the frame jumps across that diagonal.
   Handedness +1.  No singular unit direction. */
static inline onb_vec3 onb__cycles111_b1(onb_vec3 n)
{
	onb_vec3 a;
	double l;
	if (!(n.x <= n.y && n.x >= n.y && n.x <= n.z && n.x >= n.z)) { /* n.x != n.y || n.x != n.z */
		a.x = n.z - n.y; a.y = n.x - n.z; a.z = n.y - n.x;
	} else {
		a.x = n.z - n.y; a.y = n.x + n.z; a.z = -n.y - n.x;
	}
	l = sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
	a.x = a.x / l; a.y = a.y / l; a.z = a.z / l;
	return a;
}
static inline onb_vec3f onb__cycles111_b1f(onb_vec3f n)
{
	onb_vec3f a;
	float l;
	if (!(n.x <= n.y && n.x >= n.y && n.x <= n.z && n.x >= n.z)) {
		a.x = n.z - n.y; a.y = n.x - n.z; a.z = n.y - n.x;
	} else {
		a.x = n.z - n.y; a.y = n.x + n.z; a.z = -n.y - n.x;
	}
	l = sqrtf(a.x * a.x + a.y * a.y + a.z * a.z);
	a.x = a.x / l; a.y = a.y / l; a.z = a.z / l;
	return a;
}
static inline void ONB__K(cycles_cross111)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb__naive_post(n, onb__cycles111_b1(n), 1.0, b1, b2);
}
static inline void ONB__K(cycles_cross111f)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb__naive_postf(n, onb__cycles111_b1f(n), 1.0f, b1, b2);
}

/* cycles_cross111_avx2: the same in Cycles' AVX2 CPU kernel (-mavx2
   -mfma), whose cross product is msub = _mm_fmsub_ps: each component of
   b2 = n x b1 is fma(p, q, -(r s)), the second product rounded and the
   first fused.  The rest (dpps, lane-wise division) as cycles_cross111. */
static inline void ONB__K(cycles_cross111_avx2)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const onb_vec3 a = onb__cycles111_b1(n);
	*b1 = a;
	b2->x = fma(n.y, a.z, -(n.z * a.y));
	b2->y = fma(n.z, a.x, -(n.x * a.z));
	b2->z = fma(n.x, a.y, -(n.y * a.x));
}
static inline void ONB__K(cycles_cross111_avx2f)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const onb_vec3f a = onb__cycles111_b1f(n);
	*b1 = a;
	b2->x = fmaf(n.y, a.z, -(n.z * a.y));
	b2->y = fmaf(n.z, a.x, -(n.x * a.z));
	b2->z = fmaf(n.x, a.y, -(n.y * a.x));
}

/* embree (Embree common/math/linearspace3.h, frame(N), on Vec3fa): dx0 =
   (0, n.z, -n.y), dx1 = (-n.z, 0, n.x); dx = normalize(dx0 if |dx0|^2 >
   |dx1|^2 else dx1); dy = normalize(cross(n, dx)).  normalize(v) = v *
   rsqrt(dot(v, v)) with Embree's rsqrt: the hardware estimate r (rsqrtss)
   and the Newton step 1.5 r + ((x (-0.5)) r)(r r), an order of its own.
   dot is dpps: ((p0 + p1) + (p2 + p3)), so |dx0|^2 = n.z^2 + n.y^2 and
   |dx1|^2 = n.z^2 + n.x^2.  The estimate's bits are the CPU's (Intel and AMD
   differ), as for the _rsqrt variants; without SSE it falls back to
   1/sqrt (ONB_FELL_BACK).  The SSE4.2 kernel's arithmetic (the AVX2 one
   fuses the cross).  Double: the estimate of the float-rounded argument,
   widened (onb__hw_rsqrt), then the same Newton step in double: a 24-bit
   normalization.  Handedness +1.  No singular unit direction. */
static inline float  onb__embree_rsqrtf(float x)  { const float  r = onb__hw_rsqrtf(x); return 1.5f * r + ((x * -0.5f) * r) * (r * r); }
static inline double onb__embree_rsqrt (double x) { const double r = onb__hw_rsqrt(x);  return 1.5 * r + ((x * -0.5) * r) * (r * r); }
static inline void ONB__K(embree)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double zz = n.z * n.z, d0 = zz + n.y * n.y, d1 = zz + n.x * n.x;
	onb_vec3 u, c;
	double s;
	if (d0 > d1) { u.x = 0.0;  u.y = n.z; u.z = -n.y; s = onb__embree_rsqrt(d0); }
	else         { u.x = -n.z; u.y = 0.0; u.z = n.x;  s = onb__embree_rsqrt(d1); }
	u.x *= s; u.y *= s; u.z *= s;
	c.x = n.y * u.z - n.z * u.y;
	c.y = n.z * u.x - n.x * u.z;
	c.z = n.x * u.y - n.y * u.x;
	s = onb__embree_rsqrt(c.x * c.x + c.y * c.y + c.z * c.z);
	*b1 = u;
	b2->x = c.x * s; b2->y = c.y * s; b2->z = c.z * s;
}
static inline void ONB__K(embreef)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float zz = n.z * n.z, d0 = zz + n.y * n.y, d1 = zz + n.x * n.x;
	onb_vec3f u, c;
	float s;
	if (d0 > d1) { u.x = 0.0f; u.y = n.z;  u.z = -n.y; s = onb__embree_rsqrtf(d0); }
	else         { u.x = -n.z; u.y = 0.0f; u.z = n.x;  s = onb__embree_rsqrtf(d1); }
	u.x *= s; u.y *= s; u.z *= s;
	c.x = n.y * u.z - n.z * u.y;
	c.y = n.z * u.x - n.x * u.z;
	c.z = n.x * u.y - n.y * u.x;
	s = onb__embree_rsqrtf(c.x * c.x + c.y * c.y + c.z * c.z);
	*b1 = u;
	b2->x = c.x * s; b2->y = c.y * s; b2->z = c.z * s;
}

/* luxcore (LuxCoreRender include/luxrays/core/geometry/vector.h,
   CoordinateSystem; Frame::SetFromZ makes X = v2, Y = v3): len =
   sqrt(n.x^2 + n.y^2); when len < 1e-5 (a double literal), v3 = (1, 0, 0),
   else v3 = (-n.y/len, n.x/len, 0); v2 = cross(n, v3).  b1 = v2, b2 = v3.
   Handedness -1 (v2 x v3 = -n).  Near the poles (len < 1e-5) v3 is not
   orthogonal to n: the defect there is up to |n.x| < 1e-5 (about 170u in
   float), by design.  No singular unit direction. */
static inline void ONB__K(luxcore)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double len = sqrt(n.x * n.x + n.y * n.y);
	onb_vec3 v;
	if (len < 1e-5) { v.x = 1.0; v.y = 0.0; v.z = 0.0; }
	else            { v.x = -n.y / len; v.y = n.x / len; v.z = 0.0; }
	onb__naive_post(n, v, 1.0, b2, b1);
}
static inline void ONB__K(luxcoref)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float len = sqrtf(n.x * n.x + n.y * n.y);
	onb_vec3f v;
	if (ONB__CAST(double, len) < 1e-5) { v.x = 1.0f; v.y = 0.0f; v.z = 0.0f; }
	else                               { v.x = -n.y / len; v.y = n.x / len; v.z = 0.0f; }
	onb__naive_postf(n, v, 1.0f, b2, b1);
}

/* luxcore_fixed (this project's fix of luxcore, not shipped code):
   LuxCore's lines with one change in the fallback (len < 1e-5): v3 =
   Normalize((1 - x*x, -x*y, -x*z)), (1, 0, 0) made perpendicular to n
   (e1 - x n), in place of (1, 0, 0).  LuxCore's Normalize is v / Length():
   l = sqrt((vx*vx + vy*vy) + vz*vz), inv = 1/l, v*inv.  Then v2 =
   Cross(n, v3) as before; b1 = v2, b2 = v3.  At +-z v3 is (1, 0, 0) (up to
   the sign of a zero), so the frame at the six axes is luxcore's.  In
   exact arithmetic n x (e1 - x n) = (0, z, -y) for any n.  Handedness -1.
   No singular unit direction (v3.x = 1 - x*x >= 1 - 1e-10 there). */
static inline void ONB__K(luxcore_fixed)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double len = sqrt(n.x * n.x + n.y * n.y);
	onb_vec3 v;
	if (len < 1e-5) {
		double inv;
		v.x = 1.0 - n.x * n.x; v.y = -n.x * n.y; v.z = -n.x * n.z;
		inv = 1.0 / sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
		v.x *= inv; v.y *= inv; v.z *= inv;
	} else { v.x = -n.y / len; v.y = n.x / len; v.z = 0.0; }
	onb__naive_post(n, v, 1.0, b2, b1);
}
static inline void ONB__K(luxcore_fixedf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float len = sqrtf(n.x * n.x + n.y * n.y);
	onb_vec3f v;
	if (ONB__CAST(double, len) < 1e-5) {
		float inv;
		v.x = 1.0f - n.x * n.x; v.y = -n.x * n.y; v.z = -n.x * n.z;
		inv = 1.0f / sqrtf(v.x * v.x + v.y * v.y + v.z * v.z);
		v.x *= inv; v.y *= inv; v.z *= inv;
	} else { v.x = -n.y / len; v.y = n.x / len; v.z = 0.0f; }
	onb__naive_postf(n, v, 1.0f, b2, b1);
}

/* ------------------------------------------------------------------ */
/* nori (Nori src/common.cpp coordinateSystem; Mitsuba 0.6 is the same  */
/* arithmetic: the alias mitsuba06) and jolt_arm64 (Jolt's non-SSE     */
/* build of GetNormalizedPerpendicular)                                */
/* ------------------------------------------------------------------ */
/* nori: coordinateSystem(a, b, c), Frame(n) = (s, t, n) = (b, c, n):
   if |a.x| > |a.y|: invLen = 1/sqrt(a.x*a.x + a.z*a.z),
   c = (a.z*invLen, 0, -a.x*invLen); else invLen = 1/sqrt(a.y*a.y + a.z*a.z),
   c = (0, a.z*invLen, -a.y*invLen); b = c.cross(a) (Eigen's cross, c
   first).  b1 = b, b2 = c.  Handedness +1 ((c x a) x c = a).  The
   zero component of c is the literal 0 (+0), -a.x*invLen is (-a.x)*invLen.
   Threshold |x| = |y|.  No singular unit direction (squared length
   >= 1/2 - O(eps)). */
static inline void ONB__K(nori)(onb_vec3 a, onb_vec3 *b, onb_vec3 *c)
{
	onb_vec3 t;
	if (fabs(a.x) > fabs(a.y)) {
		const double inv = 1.0 / sqrt(a.x * a.x + a.z * a.z);
		t.x = a.z * inv; t.y = 0.0; t.z = -a.x * inv;
	} else {
		const double inv = 1.0 / sqrt(a.y * a.y + a.z * a.z);
		t.x = 0.0; t.y = a.z * inv; t.z = -a.y * inv;
	}
	*c = t;
	b->x = t.y * a.z - t.z * a.y;
	b->y = t.z * a.x - t.x * a.z;
	b->z = t.x * a.y - t.y * a.x;
}
static inline void ONB__K(norif)(onb_vec3f a, onb_vec3f *b, onb_vec3f *c)
{
	onb_vec3f t;
	if (fabsf(a.x) > fabsf(a.y)) {
		const float inv = 1.0f / sqrtf(a.x * a.x + a.z * a.z);
		t.x = a.z * inv; t.y = 0.0f; t.z = -a.x * inv;
	} else {
		const float inv = 1.0f / sqrtf(a.y * a.y + a.z * a.z);
		t.x = 0.0f; t.y = a.z * inv; t.z = -a.y * inv;
	}
	*c = t;
	b->x = t.y * a.z - t.z * a.y;
	b->y = t.z * a.x - t.x * a.z;
	b->z = t.x * a.y - t.y * a.x;
}

/* osl_ortho (OpenShadingLanguage testrender raytracer.h, ortho(n, x, y)):
   x = (|n.x| > .01f ? (n.z, 0, -n.x) : (0, -n.z, n.y)).normalize();
   y = n.cross(x).  Imath's Vec3::normalize divides each component by
   length() unless it is 0; length() is sqrt(x*x + y*y + z*z), or, when
   that sum is below 2 * the format's smallest normal, lengthTiny(): the
   largest |component| m, then m * sqrt of the sum of the squares of the
   components divided by m.  b1 = x, b2 = y.  Handedness +1.  The float
   literal .01f is kept in the double variant.  No singular unit
   direction (|p|^2 >= 1e-4). */
#define ONB__OSL_ORTHO(S, T, SQRT, FABS, TMIN) \
static inline T onb__osl_len##S(T x, T y, T z) \
{ \
	const T l2 = x * x + y * y + z * z; \
	T ax, ay, az, m; \
	if (!(l2 < ONB__CAST(T, 2) * TMIN)) \
		return SQRT(l2); \
	ax = (x >= ONB__CAST(T, 0)) ? x : -x; ay = (y >= ONB__CAST(T, 0)) ? y : -y; az = (z >= ONB__CAST(T, 0)) ? z : -z; \
	m = ax; \
	if (m < ay) m = ay; \
	if (m < az) m = az; \
	if (ONB__IS0(m)) \
		return ONB__CAST(T, 0); \
	ax /= m; ay /= m; az /= m; \
	return m * SQRT(ax * ax + ay * ay + az * az); \
}
ONB__OSL_ORTHO(d, double, sqrt, fabs, 0x1p-1022)   /* DBL_MIN */
ONB__OSL_ORTHO(f, float, sqrtf, fabsf, 0x1p-126f)  /* FLT_MIN */
static inline void ONB__K(osl_ortho)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 p;
	double l;
	if (fabs(n.x) > ONB__CAST(double, .01f)) { p.x = n.z; p.y = 0.0; p.z = -n.x; }
	else                          { p.x = 0.0; p.y = -n.z; p.z = n.y; }
	l = onb__osl_lend(p.x, p.y, p.z);
	if (!ONB__IS0(l)) { p.x /= l; p.y /= l; p.z /= l; }
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}
static inline void ONB__K(osl_orthof)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f p;
	float l;
	if (fabsf(n.x) > .01f) { p.x = n.z; p.y = 0.0f; p.z = -n.x; }
	else                   { p.x = 0.0f; p.y = -n.z; p.z = n.y; }
	l = onb__osl_lenf(p.x, p.y, p.z);
	if (!ONB__IS0(l)) { p.x /= l; p.y /= l; p.z /= l; }
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}

/* ospray (OSPRay's ISPC renderer, rkcommon math/LinearSpace.ih frame(N),
   vec.ih normalize and cross), read as source-level IEEE arithmetic:
   dx0 = (0, z, -y), dx1 = (-z, 0, x); u = |x| < |y| ? dx0 : dx1 (the tie
   |x| = |y| and NaN take dx1); dx = u * (1/sqrt(dot(u, u))), the dot
   u.x*u.x + u.y*u.y + u.z*u.z over all three components (the literal 0
   included), one division and three products; dy = cross(N, dx) in the
   format.  b1 = dx, b2 = dy.  Handedness +1.  pbrt_v3's exact formula with
   the tie rule reversed, its cross product not widened.  OSPRay compiles
   with ISPC_FAST_MATH (contract, reassoc, nsz, arcp: not modelled here).
   No singular unit direction (|u|^2 >= 1/2 - O(eps)). */
static inline void ONB__K(ospray)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 u;
	double s;
	if (fabs(n.x) < fabs(n.y)) { u.x = 0.0; u.y = n.z; u.z = -n.y; }
	else                       { u.x = -n.z; u.y = 0.0; u.z = n.x; }
	s = 1.0 / sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
	u.x = u.x * s; u.y = u.y * s; u.z = u.z * s;
	*b1 = u;
	b2->x = n.y * u.z - n.z * u.y;
	b2->y = n.z * u.x - n.x * u.z;
	b2->z = n.x * u.y - n.y * u.x;
}
static inline void ONB__K(osprayf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f u;
	float s;
	if (fabsf(n.x) < fabsf(n.y)) { u.x = 0.0f; u.y = n.z; u.z = -n.y; }
	else                         { u.x = -n.z; u.y = 0.0f; u.z = n.x; }
	s = 1.0f / sqrtf(u.x * u.x + u.y * u.y + u.z * u.z);
	u.x = u.x * s; u.y = u.y * s; u.z = u.z * s;
	*b1 = u;
	b2->x = n.y * u.z - n.z * u.y;
	b2->y = n.z * u.x - n.x * u.z;
	b2->z = n.x * u.y - n.y * u.x;
}

/* osl_gabornoise (OpenShadingLanguage liboslnoise/gabornoise.h,
   make_orthonormals(v, a, b)): v.normalize() (the input normalized first,
   Imath's normalize: each component divided by length() unless it is 0);
   a = |v.x| < 0.9f ? (0, v.z, -v.y) : (-v.z, 0, v.x); a.normalize();
   b = v.cross(a).  b1 = a, b2 = b (the frame (t, b, n) of gabornoise.cpp).
   Handedness +1, measured against n (b1 and b2 are built from n/|n|).
   The float literal 0.9f is kept in the double variant.  Imath's length
   and lengthTiny as in osl_ortho.  No singular unit direction
   (|a|^2 >= 0.19 - O(eps)). */
static inline void ONB__K(osl_gabornoise)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 v = n, a;
	double l = onb__osl_lend(v.x, v.y, v.z);
	if (!ONB__IS0(l)) { v.x /= l; v.y /= l; v.z /= l; }
	if (fabs(v.x) < ONB__CAST(double, .9f)) { a.x = 0.0; a.y = v.z; a.z = -v.y; }
	else                                   { a.x = -v.z; a.y = 0.0; a.z = v.x; }
	l = onb__osl_lend(a.x, a.y, a.z);
	if (!ONB__IS0(l)) { a.x /= l; a.y /= l; a.z /= l; }
	*b1 = a;
	b2->x = v.y * a.z - v.z * a.y;
	b2->y = v.z * a.x - v.x * a.z;
	b2->z = v.x * a.y - v.y * a.x;
}
static inline void ONB__K(osl_gabornoisef)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f v = n, a;
	float l = onb__osl_lenf(v.x, v.y, v.z);
	if (!ONB__IS0(l)) { v.x /= l; v.y /= l; v.z /= l; }
	if (fabsf(v.x) < .9f) { a.x = 0.0f; a.y = v.z; a.z = -v.y; }
	else                  { a.x = -v.z; a.y = 0.0f; a.z = v.x; }
	l = onb__osl_lenf(a.x, a.y, a.z);
	if (!ONB__IS0(l)) { a.x /= l; a.y /= l; a.z /= l; }
	*b1 = a;
	b2->x = v.y * a.z - v.z * a.y;
	b2->y = v.z * a.x - v.x * a.z;
	b2->z = v.x * a.y - v.y * a.x;
}

/* cauldron2 (AMD FidelityFX SDK, Cauldron2 framework raytracingcommon.hlsl
   CreateTangentVectors, HLSL float read under IEEE as willems and rtao):
   up = (0,0,1) when abs(n.z) < 0.99999f (NaN: false), else (1,0,0);
   b1 = tangents[0] = normalize(cross(up, n)); b2 = tangents[1] =
   cross(n, b1), not normalized.  Handedness +1.  On the unit sphere
   |cross(up, n)|^2 >= 1 - 0.99999^2 = 2e-5: no singular direction.  The
   float literal 0.99999f is kept in the double variant. */
static inline void ONB__K(cauldron2)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 up;
	up.x = 0.0; up.y = 0.0; up.z = 1.0;
	if (!(fabs(n.z) < ONB__CAST(double, 0.99999f))) {
		up.x = 1.0; up.z = 0.0;
	}
	*b1 = onb__sh_normalize(onb__sh_cross(up, n));
	*b2 = onb__sh_cross(n, *b1);
}
static inline void ONB__K(cauldron2f)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f up;
	up.x = 0.0f; up.y = 0.0f; up.z = 1.0f;
	if (!(fabsf(n.z) < 0.99999f)) {
		up.x = 1.0f; up.z = 0.0f;
	}
	*b1 = onb__sh_normalizef(onb__sh_crossf(up, n));
	*b2 = onb__sh_crossf(n, *b1);
}

/* threejs (three.js src/nodes/pmrem/PMREMUtils.js ggxConvolution, a TSL
   node shader that the WebGPU renderer emits as WGSL or GLSL, float, read
   under IEEE as willems): up = select(abs(N.z) < 0.999, (0,0,1), (1,0,0))
   (NaN: x); tangent = normalize(cross(up, N)); bitangent = cross(N,
   tangent), not normalized.  b1 = tangent, b2 = bitangent.  Handedness +1.
   cauldron2's arithmetic with the threshold 0.999 (a float in the shader,
   kept as 0.999f in the double variant).  No singular direction. */
static inline void ONB__K(threejs)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 up;
	up.x = 0.0; up.y = 0.0; up.z = 1.0;
	if (!(fabs(n.z) < ONB__CAST(double, 0.999f))) {
		up.x = 1.0; up.z = 0.0;
	}
	*b1 = onb__sh_normalize(onb__sh_cross(up, n));
	*b2 = onb__sh_cross(n, *b1);
}
static inline void ONB__K(threejsf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f up;
	up.x = 0.0f; up.y = 0.0f; up.z = 1.0f;
	if (!(fabsf(n.z) < 0.999f)) {
		up.x = 1.0f; up.z = 0.0f;
	}
	*b1 = onb__sh_normalizef(onb__sh_crossf(up, n));
	*b2 = onb__sh_crossf(n, *b1);
}

/* q2rtx_fixed (this project's fix of q2rtx, Quake II RTX
   construct_ONB_frisvad, and of nvpro = frisvad_max, not shipped code):
   Frisvad's Listing 2 for n.z >= 0 (-0 included), as both compute it;
   below, Duff et al.'s lower-hemisphere formula (revisedONB) in place of
   the threshold's fixed fallback, its pair turned a quarter (b1, b2) ->
   (b2, -b1) so that n = -z keeps their fallback frame ((0, -1, 0),
   (-1, 0, 0)): a = 1/(1 - n.z), b = n.x*n.y*a, b1 = (b, n.y*n.y*a - 1,
   -n.y), b2 = (-(1 - n.x*n.x*a), b, -n.x).  The same frame at the six
   axes (up to the sign of a zero).  Handedness +1. */
static inline void ONB__K(q2rtx_fixed)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	if (n.z < 0.0) {
		const double a = 1.0 / (1.0 - n.z);
		const double b = n.x * n.y * a;
		b1->x = b; b1->y = n.y * n.y * a - 1.0; b1->z = -n.y;
		b2->x = -(1.0 - n.x * n.x * a); b2->y = b; b2->z = -n.x;
	} else {
		const double a = 1.0 / (1.0 + n.z);
		const double b = -n.x * n.y * a;
		b1->x = 1.0 - n.x * n.x * a; b1->y = b; b1->z = -n.x;
		b2->x = b; b2->y = 1.0 - n.y * n.y * a; b2->z = -n.y;
	}
}
static inline void ONB__K(q2rtx_fixedf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	if (n.z < 0.0f) {
		const float a = 1.0f / (1.0f - n.z);
		const float b = n.x * n.y * a;
		b1->x = b; b1->y = n.y * n.y * a - 1.0f; b1->z = -n.y;
		b2->x = -(1.0f - n.x * n.x * a); b2->y = b; b2->z = -n.x;
	} else {
		const float a = 1.0f / (1.0f + n.z);
		const float b = -n.x * n.y * a;
		b1->x = 1.0f - n.x * n.x * a; b1->y = b; b1->z = -n.x;
		b2->x = b; b2->y = 1.0f - n.y * n.y * a; b2->z = -n.y;
	}
}

/* jolt_arm64: Jolt Vec3::GetNormalizedPerpendicular's non-SSE path (the
   arm64/NEON build; JPH_CROSS_PLATFORM_DETERMINISTIC off) and the NEON
   Cross: as jolt, but the perpendicular negates with unary minus
   ((z, 0, -x) or (0, z, -y), so x = +0 gives -0 where jolt's 0 - x gives
   +0), divided by sqrt(max(xx, yy) + zz) (the same value as jolt's
   branch's square, but NaN where x*x is NaN: std::max(xx, yy) =
   xx < yy ? yy : xx).  Build/CMakeLists.txt gives non-x86 builds
   -ffp-contract=on: GCC 12 treats it as off, and clang contracts only
   within an expression, which these statements and intrinsics are not:
   nothing fuses (checked: aarch64-linux-gnu-gcc 12 -O2 -ffp-contract=on
   under qemu-aarch64 gives these bits).  Handedness +1. */
static inline void ONB__K(jolt_arm64)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double xx = n.x * n.x, yy = n.y * n.y, zz = n.z * n.z;
	onb_vec3 p;
	const double len = sqrt((xx < yy ? yy : xx) + zz);   /* std::max */
	if (xx > yy) { p.x = n.z / len; p.y = 0.0 / len; p.z = -n.x / len; }
	else         { p.x = 0.0 / len; p.y = n.z / len; p.z = -n.y / len; }
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}
static inline void ONB__K(jolt_arm64f)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float xx = n.x * n.x, yy = n.y * n.y, zz = n.z * n.z;
	onb_vec3f p;
	const float len = sqrtf((xx < yy ? yy : xx) + zz);   /* std::max */
	if (xx > yy) { p.x = n.z / len; p.y = 0.0f / len; p.z = -n.x / len; }
	else         { p.x = 0.0f / len; p.y = n.z / len; p.z = -n.y / len; }
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}

/* ------------------------------------------------------------------ */
/* This project's own methods, not published ones: Duff's branchless */
/* formula pushed to the accuracy floor, float only                  */
/* ------------------------------------------------------------------ */
/* The floor: the exact duff_branchless basis of the float input, rounded
   once to float, still has a defect (the output roundings, plus the
   input's own distance from the unit sphere); `onbstudy sweep` reports it
   per input (README, "The accuracy floor").  Float duff_branchless sits up
   to about 2x above it, because its products and its 1 + s x^2 a round
   before the output does.  These two methods remove those intermediate
   roundings.  Same branch and handedness as duff_branchless (the sign bit
   of n.z; -0 takes the lower branch), same exact formula, so the MPFR
   reference family is duff_branchless.  Float only: for double input the
   analogue needs double-double arithmetic (see the README).
   There is no double version: the registry's basis and batch are NULL
   and its flags carry ONB_FLOAT_ONLY. */

/* duff_wide: the float input widened to double, duff_branchless's formula
   in double, each output rounded once to float.  Each output component
   before its final rounding is within a few 2^-53 of the exact formula,
   so it is the correctly rounded exact value except within a few 2^-53 of
   a float rounding boundary.
   Tested bound (tests/test_lib.c): D <= 12u (u = 2^-24); measured (onbstudy sweep):
   largest defect within 1.05x of the floor's largest on every distribution. */
static inline void ONB__K(duff_widef)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const double x = ONB__CAST(double, n.x), y = ONB__CAST(double, n.y), z = ONB__CAST(double, n.z);
	const double sign = copysign(1.0, z);
	const double a = -1.0 / (sign + z);
	const double b = x * y * a;
	b1->x = ONB__CAST(float, 1.0 + sign * x * x * a); b1->y = ONB__CAST(float, sign * b); b1->z = ONB__CAST(float, -sign * x);
	b2->x = ONB__CAST(float, b); b2->y = ONB__CAST(float, sign + y * y * a); b2->z = ONB__CAST(float, -y);
}

/* duff_comp: the same formula in float arithmetic, with each rounding
   before the output compensated by error-free transformations: h = s + z
   and its error (Fast2Sum, |s| >= |z|), a = -1/h with the division's exact
   residual fma(a, h, 1), the products x x, x y, y y and their products
   with a split by fma into hi + lo, and 1 + s x^2 a, s + y^2 a by
   Fast2Sum; the lo parts are summed (in float) and added once at the end.
   Each output is then within about u + O(u^2) relative of the exact
   formula (faithful, correctly rounded in most cases).  Seven fmaf()
   calls: built without an FMA target (as libonb.a's scalar code is, see
   the Makefile) they are libm calls; the batch runs an FMA clone when the
   CPU has FMA.  fma is correctly rounded everywhere, so the bits do not
   depend on which.
   Tested bound (tests/test_lib.c): D <= 12u. */
static inline void ONB__K(duff_compf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float x = n.x, y = n.y, z = n.z;
	const float s = copysignf(1.0f, z);
	const float h = s + z, hl = (s - h) + z;         /* s + z = h + hl          */
	const float a = -1.0f / h;
	const float e = fmaf(a, h, 1.0f);                /* a h + 1, exactly        */
	const float al = a * (e + a * hl);               /* -1/(h + hl) ~ a + al    */
	const float xx = x * x, xxl = fmaf(x, x, -xx);
	const float xy = x * y, xyl = fmaf(x, y, -xy);
	const float yy = y * y, yyl = fmaf(y, y, -yy);
	const float p = xx * a, pl = fmaf(xx, a, -p) + (xx * al + xxl * a); /* x^2 a */
	const float b = xy * a, bl = fmaf(xy, a, -b) + (xy * al + xyl * a); /* x y a */
	const float q = yy * a, ql = fmaf(yy, a, -q) + (yy * al + yyl * a); /* y^2 a */
	const float sp = s * p;
	const float t1 = 1.0f + sp, t1l = (1.0f - t1) + sp; /* 1 + s x^2 a          */
	const float t2 = s + q, t2l = (s - t2) + q;          /* s + y^2 a            */
	const float bb = b + bl;
	b1->x = t1 + (t1l + s * pl); b1->y = s * bb; b1->z = -s * x;
	b2->x = bb; b2->y = t2 + (t2l + ql); b2->z = -y;
}

/* ------------------------------------------------------------------ */
/* Out-of-line library: batch kernels and registry                     */
/* ------------------------------------------------------------------ */

typedef void (*onb_basis_fn) (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2);
typedef void (*onb_basisf_fn)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2);
typedef void (*onb_array_fn) (const double *n, double *b1, double *b2);
typedef void (*onb_arrayf_fn)(const float  *n, float  *b1, float  *b2);
/* binary16 bit patterns (IEEE 754 binary16 in a uint16_t): n[3] read,
   b1[3] and b2[3] written. */
typedef void (*onb_arrayh_fn)(const uint16_t *n, uint16_t *b1, uint16_t *b2);

/* Structure-of-arrays batch: for i < count, (b1[i], b2[i]) = method(n[i]).
   The nine arrays must not overlap.  Bit-identical to the scalar function
   built with the library's flags (see the Makefile).  The loop runs the
   widest clone the CPU supports (onb_batch_isa names it). */
typedef void (*onb_batch_fn)(size_t count,
	const double *nx, const double *ny, const double *nz,
	double *b1x, double *b1y, double *b1z,
	double *b2x, double *b2y, double *b2z);
typedef void (*onb_batchf_fn)(size_t count,
	const float *nx, const float *ny, const float *nz,
	float *b1x, float *b1y, float *b1z,
	float *b2x, float *b2y, float *b2z);

/* onb_method.flags */
#define ONB_HW_RSQRT     0x1u /* uses the hardware rsqrt approximation        */
#define ONB_FELL_BACK    0x2u /* ...which this build lacks: runs 1/sqrt instead */
#define ONB_APPROX_NORM  0x4u /* normalization is approximate or absent        */
#define ONB_NORMALIZES_N 0x8u /* the method normalizes n itself (rtow)        */
#define ONB_FLOAT_ONLY   0x10u /* float only: basis and batch (double) are NULL */

/* Where a method or an alias comes from when it is code that an engine
   ships (the registry's "wild" rows), rather than a paper's listing: what a
   reader needs to find the lines and judge the transliteration. */
typedef struct onb_provenance {
	const char *repository; /* e.g. "github.com/mmp/pbrt-v4"                   */
	const char *commit;     /* the 40-hex commit that was read                */
	const char *path;       /* file:first-last line, e.g. "src/x.h:10-20"      */
	const char *license;    /* SPDX identifier of that file                   */
	const char *language;   /* "C++", "GLSL", "ISPC", ...                      */
	const char *precision;  /* the source's own precision and what sets it    */
	const char *build;      /* the build the kernel follows (IEEE source, FMA) */
} onb_provenance;

typedef struct onb_method {
	const char   *name;       /* e.g. "duff_branchless"                        */
	const char   *family;     /* the exact formula the MPFR reference follows  */
	const char   *source;     /* one line: publication and listing             */
	const char   *singular;   /* unit directions where it fails, or "none"     */
	const char   *thresholds; /* its branch conditions                         */
	int           handedness; /* det(b1, b2, n): +1, -1, or 0 if it depends on n */
	unsigned      flags;      /* ONB_* above                                   */
	double        threshold;  /* Frisvad-family t, or NAN                      */
	int           norm;       /* variant in its family: ONB__NORM_*, ONB__EVAL_* */
	onb_basis_fn  basis;      /* out-of-line scalar, double (NULL: float only) */
	onb_basisf_fn basisf;     /* out-of-line scalar, float                     */
	onb_batch_fn  batch;      /* SoA batch, double (NULL: float only)          */
	onb_batchf_fn batchf;     /* SoA batch, float                              */
	onb_array_fn  array;      /* onb_NAME_array, double (NULL: float only)     */
	onb_arrayf_fn arrayf;     /* onb_NAME_arrayf                               */
	onb_arrayh_fn arrayh;     /* onb_NAME_arrayh, binary16 bits (NULL: no half) */
	const onb_provenance *prov; /* shipped code: where it is; NULL for papers  */
} onb_method;

/* An alias: an engine's code that is bit-for-bit an existing method (in the
   precisions named), recorded instead of a copy.  `onbstudy list` shows
   each as "NAME = TARGET, bit for bit"; the command line accepts the alias
   where it accepts a method name and runs the target. */
typedef struct onb_alias {
	const char    *name;       /* e.g. "pbrt_v4"                                */
	const char    *target;     /* the method it equals, e.g. "duff_branchless"  */
	const char    *precisions; /* where the identity holds: "float and double", "float" */
	const char    *source;     /* one line: engine and function                 */
	const char    *note;       /* inputs excepted and why, or ""                */
	onb_provenance prov;
} onb_alias;

/* All methods, in a fixed order; *count receives their number. */
const onb_method *onb_methods(size_t *count);
/* The method called `name`, or NULL (an alias's name gives NULL). */
const onb_method *onb_find(const char *name);
/* All aliases; *count receives their number. */
const onb_alias *onb_aliases(size_t *count);
/* The alias called `name`, or NULL. */
const onb_alias *onb_find_alias(const char *name);
/* The instruction set the batch kernels run on this CPU:
   "avx512f", "avx2" or "sse2" (or "generic" off x86-64). */
const char *onb_batch_isa(void);

/* Status of onb_basis_checked. */
typedef enum {
	ONB_OK = 0,          /* n was unit within ONB_CHECK_TOL, used as given  */
	ONB_RENORMALIZED,    /* n was finite, non-zero, not unit: normalized    */
	ONB_ZERO,            /* n was zero (or too small to normalize)          */
	ONB_NONFINITE,       /* n had a NaN or an infinity                      */
	ONB_BAD_METHOD       /* method was NULL, or has no double (float only) */
} onb_status;

/* ================================================================== */
/* Methods found in shipping code ("in the wild"): physics engines,    */
/* geometry and math libraries.  Each is the engine's own arithmetic,  */
/* flaws included; the registry row gives the repository, commit,      */
/* path:lines, license, the source's precision and the build reading.  */
/* Where the source is float only, the double variant is the same      */
/* arithmetic in double (the study pairs both precisions).             */
/* ================================================================== */

/* ------------------------------------------------------------------ */
/* jolt, jolt_fma (Jolt Physics Vec3::GetNormalizedPerpendicular and   */
/* the contact tangents b2 = n.Cross(b1))                              */
/* ------------------------------------------------------------------ */
/* xx, yy, zz = the squares; if xx > yy (the rounded squares compared):
   b1 = (z, 0, 0 - x) / sqrt(xx + zz), else (0, z, 0 - y) / sqrt(yy + zz),
   each lane divided (no reciprocal); negation is 0 - v, as the SSE code
   subtracts from +0, so -(+0) is +0.  b2 = n x b1.  jolt: every product
   and difference rounded (-ffp-contract=off); jolt_fma: Jolt's default
   x86 build (-mfma -ffp-contract=fast), where GCC and clang fuse each
   component of the cross product as fma(b1[i+2], n[i+1], -(n[i+2]*b1[i+1]))
   with the indices of Cross's shuffles.  Handedness +1.  Threshold:
   x^2 = y^2.  No singular unit direction (the squared length is
   >= 1/2 - O(eps)).
   Tested bound (tests/test_lib.c): D <= 12u. */
static inline onb_vec3 onb__jolt_perp(onb_vec3 n)
{
	const double xx = n.x * n.x, yy = n.y * n.y, zz = n.z * n.z;
	onb_vec3 p;
	if (xx > yy) {
		const double len = sqrt(xx + zz);
		p.x = n.z / len; p.y = 0.0 / len; p.z = (0.0 - n.x) / len;
	} else {
		const double len = sqrt(yy + zz);
		p.x = 0.0 / len; p.y = n.z / len; p.z = (0.0 - n.y) / len;
	}
	return p;
}
static inline onb_vec3f onb__jolt_perpf(onb_vec3f n)
{
	const float xx = n.x * n.x, yy = n.y * n.y, zz = n.z * n.z;
	onb_vec3f p;
	if (xx > yy) {
		const float len = sqrtf(xx + zz);
		p.x = n.z / len; p.y = 0.0f / len; p.z = (0.0f - n.x) / len;
	} else {
		const float len = sqrtf(yy + zz);
		p.x = 0.0f / len; p.y = n.z / len; p.z = (0.0f - n.y) / len;
	}
	return p;
}
static inline void ONB__K(jolt)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const onb_vec3 p = onb__jolt_perp(n);
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}
static inline void ONB__K(joltf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const onb_vec3f p = onb__jolt_perpf(n);
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}
static inline void ONB__K(jolt_fma)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const onb_vec3 p = onb__jolt_perp(n);
	*b1 = p;
	b2->x = fma(p.z, n.y, -(n.z * p.y));
	b2->y = fma(p.x, n.z, -(n.x * p.z));
	b2->z = fma(p.y, n.x, -(n.y * p.x));
}
static inline void ONB__K(jolt_fmaf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const onb_vec3f p = onb__jolt_perpf(n);
	*b1 = p;
	b2->x = fmaf(p.z, n.y, -(n.z * p.y));
	b2->y = fmaf(p.x, n.z, -(n.x * p.z));
	b2->z = fmaf(p.y, n.x, -(n.y * p.x));
}

/* ------------------------------------------------------------------ */
/* bullet (Bullet Physics btPlaneSpace1; ODE's dPlaneSpace is the same  */
/* arithmetic bit for bit: the alias `ode`)                            */
/* ------------------------------------------------------------------ */
/* If |z| > t (t = SIMDSQRT12, 1/sqrt(2) rounded to the format):
   a = y*y + z*z, k = 1/sqrt(a), b1 = (0, (-z)*k, y*k),
   b2 = (a*k, (-x)*b1.z, x*b1.y);
   else a = x*x + y*y, k = 1/sqrt(a), b1 = ((-y)*k, x*k, 0),
   b2 = ((-z)*b1.y, z*b1.x, a*k).  b2 is n x b1 written out, its one
   long component simplified to a*k, the others from the rounded b1.
   Handedness +1.  Threshold: |z| = 1/sqrt(2).  No singular unit
   direction (a >= 1/2 - O(eps)).
   Tested bound (tests/test_lib.c): D <= 12u. */
static inline void ONB__K(bullet)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	if (fabs(n.z) > 0x1.6a09e667f3bcdp-1 /* SIMDSQRT12 */) {
		const double a = n.y * n.y + n.z * n.z, k = 1.0 / sqrt(a);
		b1->x = 0.0; b1->y = -n.z * k; b1->z = n.y * k;
		b2->x = a * k; b2->y = -n.x * b1->z; b2->z = n.x * b1->y;
	} else {
		const double a = n.x * n.x + n.y * n.y, k = 1.0 / sqrt(a);
		b1->x = -n.y * k; b1->y = n.x * k; b1->z = 0.0;
		b2->x = -n.z * b1->y; b2->y = n.z * b1->x; b2->z = a * k;
	}
}
static inline void ONB__K(bulletf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	if (fabsf(n.z) > 0x1.6a09e6p-1f /* SIMDSQRT12 as a float */) {
		const float a = n.y * n.y + n.z * n.z, k = 1.0f / sqrtf(a);
		b1->x = 0.0f; b1->y = -n.z * k; b1->z = n.y * k;
		b2->x = a * k; b2->y = -n.x * b1->z; b2->z = n.x * b1->y;
	} else {
		const float a = n.x * n.x + n.y * n.y, k = 1.0f / sqrtf(a);
		b1->x = -n.y * k; b1->y = n.x * k; b1->z = 0.0f;
		b2->x = -n.z * b1->y; b2->y = n.z * b1->x; b2->z = a * k;
	}
}

/* ------------------------------------------------------------------ */
/* mujoco (MuJoCo mju_makeFrame, the contact frame)                    */
/* ------------------------------------------------------------------ */
/* m = n normalized as mju_normalize3 does (s = sqrt(x*x + y*y + z*z);
   s < 1e-15 gives (1, 0, 0), else each component times 1/s); e = (0,1,0)
   if -1/2 < m.y < 1/2, else (0,0,1); d = m.e (all three products, left to
   right); e = e - m*d; b1 = e normalized the same way; b2 = m x b1.
   Handedness +1 (against m).  Threshold: |m.y| = 1/2.  No singular unit
   direction (|e - m d| >= 1/2).  MuJoCo reports an error when |n| < 1/2;
   the kernel goes on (garbage in, garbage out).
   Tested bound (tests/test_lib.c): D <= 12u, measured against n. */
static inline void onb__mj_normalize(onb_vec3 *v)
{
	const double s = sqrt(v->x * v->x + v->y * v->y + v->z * v->z);
	if (s < 1e-15) {
		v->x = 1.0; v->y = 0.0; v->z = 0.0;
	} else {
		const double inv = 1.0 / s;
		v->x *= inv; v->y *= inv; v->z *= inv;
	}
}
static inline void onb__mj_normalizef(onb_vec3f *v)
{
	const float s = sqrtf(v->x * v->x + v->y * v->y + v->z * v->z);
	if (s < 1e-15f) {
		v->x = 1.0f; v->y = 0.0f; v->z = 0.0f;
	} else {
		const float inv = 1.0f / s;
		v->x *= inv; v->y *= inv; v->z *= inv;
	}
}
static inline void ONB__K(mujoco)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 m = n, e;
	double d;
	onb__mj_normalize(&m);
	e.x = 0.0; e.y = 0.0; e.z = 0.0;
	if (m.y < 0.5 && m.y > -0.5) e.y = 1.0; else e.z = 1.0;
	d = m.x * e.x + m.y * e.y + m.z * e.z;
	e.x -= m.x * d; e.y -= m.y * d; e.z -= m.z * d;
	onb__mj_normalize(&e);
	*b1 = e;
	b2->x = m.y * e.z - m.z * e.y;
	b2->y = m.z * e.x - m.x * e.z;
	b2->z = m.x * e.y - m.y * e.x;
}
static inline void ONB__K(mujocof)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f m = n, e;
	float d;
	onb__mj_normalizef(&m);
	e.x = 0.0f; e.y = 0.0f; e.z = 0.0f;
	if (m.y < 0.5f && m.y > -0.5f) e.y = 1.0f; else e.z = 1.0f;
	d = m.x * e.x + m.y * e.y + m.z * e.z;
	e.x -= m.x * d; e.y -= m.y * d; e.z -= m.z * d;
	onb__mj_normalizef(&e);
	*b1 = e;
	b2->x = m.y * e.z - m.z * e.y;
	b2->y = m.z * e.x - m.x * e.z;
	b2->z = m.x * e.y - m.y * e.x;
}

/* ------------------------------------------------------------------ */
/* eigen (Eigen MatrixBase::unitOrthogonal, size 3; b2 = n.cross(b1))  */
/* ------------------------------------------------------------------ */
/* Unless |x| <= |z| p and |y| <= |z| p (Eigen's isMuchSmallerThan, p =
   dummy_precision: 1e-12 for double, 1e-5f for float):
   r = 1/sqrt(x*x + y*y), b1 = ((-y)*r, x*r, 0); else r = 1/sqrt(y*y + z*z),
   b1 = (0, (-z)*r, y*r).  Eigen returns b1 only; b2 = n x b1 by Eigen's
   cross (our reading).  Handedness +1.  Thresholds: |x| = p|z|, |y| = p|z|.
   No singular unit direction.
   Tested bound (tests/test_lib.c): D <= 12u. */
static inline void ONB__K(eigen)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double zp = fabs(n.z) * 1e-12;
	onb_vec3 p;
	if (!(fabs(n.x) <= zp) || !(fabs(n.y) <= zp)) {
		const double r = 1.0 / sqrt(n.x * n.x + n.y * n.y);
		p.x = -n.y * r; p.y = n.x * r; p.z = 0.0;
	} else {
		const double r = 1.0 / sqrt(n.y * n.y + n.z * n.z);
		p.x = 0.0; p.y = -n.z * r; p.z = n.y * r;
	}
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}
static inline void ONB__K(eigenf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float zp = fabsf(n.z) * 1e-5f;
	onb_vec3f p;
	if (!(fabsf(n.x) <= zp) || !(fabsf(n.y) <= zp)) {
		const float r = 1.0f / sqrtf(n.x * n.x + n.y * n.y);
		p.x = -n.y * r; p.y = n.x * r; p.z = 0.0f;
	} else {
		const float r = 1.0f / sqrtf(n.y * n.y + n.z * n.z);
		p.x = 0.0f; p.y = -n.z * r; p.z = n.y * r;
	}
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}

/* ------------------------------------------------------------------ */
/* physx (NVIDIA PhysX PxComputeBasisVectors)                          */
/* ------------------------------------------------------------------ */
/* If |y| <= 0.9999f: r = (z, 0, -x), m = sqrt(r.r) (in component order),
   if m > 0: r = r * (1/m); b1 = r, b2 = (y*r.z, z*r.x - x*r.z, (-y)*r.x)
   (n x r with r.y = 0 dropped; not normalized).  Else b1 = (1, 0, 0)
   whatever n is, b2 = (0, z, -y) normalized the same way.  Handedness +1.
   Threshold: |y| = 0.9999f (the float constant in double too).
   Flaw, as shipped: on the second branch b1.n = x, up to
   sqrt(1 - 0.9999^2) = 0.0141; no non-finite output on unit input.
   Tested bound (tests/test_lib.c): D <= 12u, and sqrt(1 - n.y^2) + 12u
   on the fallback. */
static inline void ONB__K(physx)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 r, u;
	double m;
	if (fabs(n.y) <= ONB__CAST(double, 0.9999f)) {
		r.x = n.z; r.y = 0.0; r.z = -n.x;
		m = sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
		if (m > 0.0) {
			const double f = 1.0 / m;
			r.x *= f; r.y *= f; r.z *= f;
		}
		u.x = n.y * r.z; u.y = n.z * r.x - n.x * r.z; u.z = -n.y * r.x;
	} else {
		r.x = 1.0; r.y = 0.0; r.z = 0.0;
		u.x = 0.0; u.y = n.z; u.z = -n.y;
		m = sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
		if (m > 0.0) {
			const double f = 1.0 / m;
			u.x *= f; u.y *= f; u.z *= f;
		}
	}
	*b1 = r;
	*b2 = u;
}
static inline void ONB__K(physxf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f r, u;
	float m;
	if (fabsf(n.y) <= 0.9999f) {
		r.x = n.z; r.y = 0.0f; r.z = -n.x;
		m = sqrtf(r.x * r.x + r.y * r.y + r.z * r.z);
		if (m > 0.0f) {
			const float f = 1.0f / m;
			r.x *= f; r.y *= f; r.z *= f;
		}
		u.x = n.y * r.z; u.y = n.z * r.x - n.x * r.z; u.z = -n.y * r.x;
	} else {
		r.x = 1.0f; r.y = 0.0f; r.z = 0.0f;
		u.x = 0.0f; u.y = n.z; u.z = -n.y;
		m = sqrtf(u.x * u.x + u.y * u.y + u.z * u.z);
		if (m > 0.0f) {
			const float f = 1.0f / m;
			u.x *= f; u.y *= f; u.z *= f;
		}
	}
	*b1 = r;
	*b2 = u;
}

/* physx_fixed (this project's fix of physx, not shipped code): PhysX's
   lines with one change in the fallback branch, right = up.cross(dir)
   after up.normalize() in place of (1, 0, 0), so right is perpendicular
   to dir there too; the frame at +-x, +-y, +-z is PhysX's.  Handedness +1.
   Threshold: |y| = 0.9999f.  No singular unit direction.
   Tested bound (tests/test_lib.c): D <= 12u. */
static inline void ONB__K(physx_fixed)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	if (fabs(n.y) <= ONB__CAST(double, 0.9999f)) {
		ONB__K(physx)(n, b1, b2);
		return;
	} else {
		onb_vec3 u;
		double m;
		u.x = 0.0; u.y = n.z; u.z = -n.y;
		m = sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
		if (m > 0.0) {
			const double f = 1.0 / m;
			u.x *= f; u.y *= f; u.z *= f;
		}
		b1->x = u.y * n.z - u.z * n.y;
		b1->y = u.z * n.x - u.x * n.z;
		b1->z = u.x * n.y - u.y * n.x;
		*b2 = u;
	}
}
static inline void ONB__K(physx_fixedf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	if (fabsf(n.y) <= 0.9999f) {
		ONB__K(physxf)(n, b1, b2);
		return;
	} else {
		onb_vec3f u;
		float m;
		u.x = 0.0f; u.y = n.z; u.z = -n.y;
		m = sqrtf(u.x * u.x + u.y * u.y + u.z * u.z);
		if (m > 0.0f) {
			const float f = 1.0f / m;
			u.x *= f; u.y *= f; u.z *= f;
		}
		b1->x = u.y * n.z - u.z * n.y;
		b1->y = u.z * n.x - u.x * n.z;
		b1->z = u.x * n.y - u.y * n.x;
		*b2 = u;
	}
}

/* ------------------------------------------------------------------ */
/* rp3d (ReactPhysics3D Vector3::getOneUnitOrthogonalVector and the    */
/* friction vectors b2 = normal.cross(b1))                             */
/* ------------------------------------------------------------------ */
/* k = the axis of the smallest |n_i| (ax < ay ? (ax < az ? 0 : 2) :
   (ay < az ? 1 : 2): ties go to the later axis); b1 = e_k x n divided
   component by component by its length: k = 0: (0, -z, y) / sqrt(y*y + z*z),
   k = 1: (-z, 0, x) / sqrt(x*x + z*z), k = 2: (-y, x, 0) / sqrt(x*x + y*y).
   b2 = n x b1.  Handedness +1.  Thresholds: |x| = |y|, |x| = |z|,
   |y| = |z|.  No singular unit direction (squared length >= 2/3 - O(eps)).
   Tested bound (tests/test_lib.c): D <= 12u. */
static inline void ONB__K(rp3d)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double ax = fabs(n.x), ay = fabs(n.y), az = fabs(n.z);
	const int k = ax < ay ? (ax < az ? 0 : 2) : (ay < az ? 1 : 2);
	onb_vec3 p;
	double l;
	if (k == 0) {
		l = sqrt(n.y * n.y + n.z * n.z);
		p.x = 0.0 / l; p.y = -n.z / l; p.z = n.y / l;
	} else if (k == 1) {
		l = sqrt(n.x * n.x + n.z * n.z);
		p.x = -n.z / l; p.y = 0.0 / l; p.z = n.x / l;
	} else {
		l = sqrt(n.x * n.x + n.y * n.y);
		p.x = -n.y / l; p.y = n.x / l; p.z = 0.0 / l;
	}
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}
static inline void ONB__K(rp3df)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float ax = fabsf(n.x), ay = fabsf(n.y), az = fabsf(n.z);
	const int k = ax < ay ? (ax < az ? 0 : 2) : (ay < az ? 1 : 2);
	onb_vec3f p;
	float l;
	if (k == 0) {
		l = sqrtf(n.y * n.y + n.z * n.z);
		p.x = 0.0f / l; p.y = -n.z / l; p.z = n.y / l;
	} else if (k == 1) {
		l = sqrtf(n.x * n.x + n.z * n.z);
		p.x = -n.z / l; p.y = 0.0f / l; p.z = n.x / l;
	} else {
		l = sqrtf(n.x * n.x + n.y * n.y);
		p.x = -n.y / l; p.y = n.x / l; p.z = 0.0f / l;
	}
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}

/* ------------------------------------------------------------------ */
/* open3d (Open3D PlaneDetector::ConstructOrthogonalBasis, with Eigen) */
/* ------------------------------------------------------------------ */
/* If |(0,1,1) - n|^2 > 1e-3 (always, for a unit n): p = n x (0,1,1) =
   (y - z, -x, x), else p = n x (1,0,1) = (y, z - x, -y); b1 = p
   normalized as Eigen's normalized() does (s2 = |p|^2; if s2 > 0, each
   component divided by sqrt(s2), else p unchanged); b2 = n x b1,
   normalized the same way.  Eigen sums a Vector3d's squares as
   (v0^2 + v1^2) + v2^2 (vectorized) and a Vector3f's as
   v0^2 + (v1^2 + v2^2) (its scalar unroller): each variant keeps the
   order of its type.  Handedness +1.  Singular: n parallel to (0,1,1),
   where p = 0 and b1 = b2 = 0 (the guard compares n with the non-unit
   (0,1,1), so it never fires); the outputs stay finite.
   Tested bound (tests/test_lib.c): D <= 12u (random inputs never meet the
   line). */
static inline void onb__o3d_normalize(onb_vec3 *v)
{
	const double s2 = (v->x * v->x + v->y * v->y) + v->z * v->z;
	if (s2 > 0.0) {
		const double s = sqrt(s2);
		v->x /= s; v->y /= s; v->z /= s;
	}
}
static inline void onb__o3d_normalizef(onb_vec3f *v)
{
	const float s2 = v->x * v->x + (v->y * v->y + v->z * v->z);
	if (s2 > 0.0f) {
		const float s = sqrtf(s2);
		v->x /= s; v->y /= s; v->z /= s;
	}
}
static inline void ONB__K(open3d)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 d, p, q;
	d.x = 0.0 - n.x; d.y = 1.0 - n.y; d.z = 1.0 - n.z;
	if ((d.x * d.x + d.y * d.y) + d.z * d.z > 1e-3) {
		p.x = n.y - n.z; p.y = -n.x; p.z = n.x;
	} else {
		p.x = n.y; p.y = n.z - n.x; p.z = -n.y;
	}
	onb__o3d_normalize(&p);
	q.x = n.y * p.z - n.z * p.y;
	q.y = n.z * p.x - n.x * p.z;
	q.z = n.x * p.y - n.y * p.x;
	onb__o3d_normalize(&q);
	*b1 = p;
	*b2 = q;
}
static inline void ONB__K(open3df)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f d, p, q;
	d.x = 0.0f - n.x; d.y = 1.0f - n.y; d.z = 1.0f - n.z;
	if (d.x * d.x + (d.y * d.y + d.z * d.z) > 1e-3f) {
		p.x = n.y - n.z; p.y = -n.x; p.z = n.x;
	} else {
		p.x = n.y; p.y = n.z - n.x; p.z = -n.y;
	}
	onb__o3d_normalizef(&p);
	q.x = n.y * p.z - n.z * p.y;
	q.y = n.z * p.x - n.x * p.z;
	q.z = n.x * p.y - n.y * p.x;
	onb__o3d_normalizef(&q);
	*b1 = p;
	*b2 = q;
}

/* ------------------------------------------------------------------ */
/* raylib (raymath.h Vector3Perpendicular, completed)                   */
/* ------------------------------------------------------------------ */
/* raylib picks the cardinal axis e of the smallest |component|: e = x,
   then y if |y| < min, then z if |z| < min (min = |x|, or |y| after the
   switch; ties keep the earlier axis), and returns p = cross(v, e) with
   the zero and one products written out (v.y*e.z - v.z*e.y, ...).  It does
   not normalize: completed (docs/wild-specs/README.md) with raylib's
   Vector3Normalize (length = sqrtf(x*x + y*y + z*z); if length != 0,
   multiply by ilength = 1/length) and b2 = Vector3CrossProduct(n, b1).
   stark_fixed's arithmetic with another tie rule (and the zero guard).
   raylib is float only; the double kernel is the same operations in
   double.  Handedness +1.  Thresholds: |y| = |x|, |z| = min(|x|, |y|).
   No singular unit direction (|p|^2 >= 2/3 - O(eps)). */
static inline void ONB__K(raylib)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	double min = fabs(n.x), ex = 1.0, ey = 0.0, ez = 0.0, len;
	onb_vec3 p;
	if (fabs(n.y) < min) { min = fabs(n.y); ex = 0.0; ey = 1.0; }
	if (fabs(n.z) < min) { ex = 0.0; ey = 0.0; ez = 1.0; }
	p.x = n.y * ez - n.z * ey;
	p.y = n.z * ex - n.x * ez;
	p.z = n.x * ey - n.y * ex;
	len = sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
	if (!ONB__IS0(len)) {
		const double il = 1.0 / len;
		p.x *= il; p.y *= il; p.z *= il;
	}
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}
static inline void ONB__K(raylibf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	float min = fabsf(n.x), ex = 1.0f, ey = 0.0f, ez = 0.0f, len;
	onb_vec3f p;
	if (fabsf(n.y) < min) { min = fabsf(n.y); ex = 0.0f; ey = 1.0f; }
	if (fabsf(n.z) < min) { ex = 0.0f; ey = 0.0f; ez = 1.0f; }
	p.x = n.y * ez - n.z * ey;
	p.y = n.z * ex - n.x * ez;
	p.z = n.x * ey - n.y * ex;
	len = sqrtf(p.x * p.x + p.y * p.y + p.z * p.z);
	if (!ONB__IS0(len)) {
		const float il = 1.0f / len;
		p.x *= il; p.y *= il; p.z *= il;
	}
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}

/* ------------------------------------------------------------------ */
/* godot (Godot Vector3::get_any_perpendicular, completed)              */
/* ------------------------------------------------------------------ */
/* (0,0,0) when every |component| < CMP_EPSILON (1e-5; (float)1e-5 in a
   float build); else p = cross(n, e) with e = RIGHT (1,0,0) when |x| <= |y|
   and |x| <= |z|, else UP (0,1,0); normalized(): lengthsq = (x*x + y*y) +
   z*z, (0,0,0) when it is 0, else each component divided by
   sqrt(lengthsq).  b2 = n.cross(b1), Godot's cross (the completion of
   docs/wild-specs/README.md).  real_t: float (default) or double
   (precision=double).  Handedness +1.  Thresholds: |x| = |y|, |x| = |z|.
   Where |x| is not the smallest and |y| is the largest, p = (-z, 0, x) is
   short: its squares underflow (float: x, z below ~1e-19) and b1 = b2 = 0;
   fixed = 1 (godot_fixed, not shipped) takes BACK (0,0,1) when |z| is the
   smallest of the three (|z| < |y|), so |p|^2 >= 2/3: the same frame at
   the six axes. */
static inline void onb__godot(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2, int fixed)
{
	onb_vec3 p;
	if (fabs(n.x) < 0.00001 && fabs(n.y) < 0.00001 && fabs(n.z) < 0.00001) {
		p.x = 0.0; p.y = 0.0; p.z = 0.0;
	} else {
		double ex = 0.0, ey = 0.0, ez = 0.0, lsq;
		if (fabs(n.x) <= fabs(n.y) && fabs(n.x) <= fabs(n.z)) ex = 1.0;
		else if (!fixed || fabs(n.y) <= fabs(n.z)) ey = 1.0;
		else ez = 1.0;
		p.x = n.y * ez - n.z * ey;
		p.y = n.z * ex - n.x * ez;
		p.z = n.x * ey - n.y * ex;
		lsq = p.x * p.x + p.y * p.y + p.z * p.z;
		if (ONB__IS0(lsq)) {
			p.x = 0.0; p.y = 0.0; p.z = 0.0;
		} else {
			const double len = sqrt(lsq);
			p.x /= len; p.y /= len; p.z /= len;
		}
	}
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}
static inline void onb__godotf(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2, int fixed)
{
	onb_vec3f p;
	if (fabsf(n.x) < ONB__CAST(float, 0.00001) && fabsf(n.y) < ONB__CAST(float, 0.00001) && fabsf(n.z) < ONB__CAST(float, 0.00001)) {
		p.x = 0.0f; p.y = 0.0f; p.z = 0.0f;
	} else {
		float ex = 0.0f, ey = 0.0f, ez = 0.0f, lsq;
		if (fabsf(n.x) <= fabsf(n.y) && fabsf(n.x) <= fabsf(n.z)) ex = 1.0f;
		else if (!fixed || fabsf(n.y) <= fabsf(n.z)) ey = 1.0f;
		else ez = 1.0f;
		p.x = n.y * ez - n.z * ey;
		p.y = n.z * ex - n.x * ez;
		p.z = n.x * ey - n.y * ex;
		lsq = p.x * p.x + p.y * p.y + p.z * p.z;
		if (ONB__IS0(lsq)) {
			p.x = 0.0f; p.y = 0.0f; p.z = 0.0f;
		} else {
			const float len = sqrtf(lsq);
			p.x /= len; p.y /= len; p.z /= len;
		}
	}
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}
static inline void ONB__K(godot)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2) { onb__godot(n, b1, b2, 0); }
static inline void ONB__K(godotf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__godotf(n, b1, b2, 0); }
static inline void ONB__K(godot_fixed)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2) { onb__godot(n, b1, b2, 1); }
static inline void ONB__K(godot_fixedf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__godotf(n, b1, b2, 1); }

/* ------------------------------------------------------------------ */
/* directxmath (DirectXMath XMVector3Orthogonal, completed)             */
/* ------------------------------------------------------------------ */
/* XMVector3Orthogonal (x86 SSE path; its lanes written out): with
   same = ((z < 0) == (y < 0)), p = (y + z, 0 - x, 0 - x) when same, else
   (y - z, 0 - x, x): |p.x| = |y| + |z| either way, so |p|^2 = (|y| + |z|)^2
   + 2 x^2 >= 1 + x^2 on the unit sphere (no cancellation anywhere).  It
   does not normalize: completed (docs/wild-specs/README.md) with
   XMVector3Normalize's SSE path (lengthsq = (x*x + y*y) + z*z, each
   component divided by sqrt(lengthsq); +0 when that is 0, the quiet NaN
   when lengthsq is +inf) and b2 = XMVector3Cross(n, b1) (SSE, no FMA: the
   default x64 build).  DirectXMath is float only; the double kernel is the
   same operations in double.  Handedness +1.  Threshold: signbit-free
   z < 0 against y < 0.  No singular unit direction. */
static inline void ONB__K(directxmath)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const int same = (n.z < 0.0) == (n.y < 0.0);
	onb_vec3 p;
	double lsq, len;
	p.x = same ? n.y + n.z : n.y - n.z;
	p.y = 0.0 - n.x;
	p.z = same ? 0.0 - n.x : n.x;
	lsq = (p.x * p.x + p.y * p.y) + p.z * p.z;
	len = sqrt(lsq);
	if (lsq >= ONB__CAST(double, INFINITY)) {
		p.x = p.y = p.z = ONB__CAST(double, NAN);
	} else if (ONB__IS0(len)) {
		p.x = p.y = p.z = 0.0;
	} else {
		p.x = p.x / len; p.y = p.y / len; p.z = p.z / len;
	}
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}
static inline void ONB__K(directxmathf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const int same = (n.z < 0.0f) == (n.y < 0.0f);
	onb_vec3f p;
	float lsq, len;
	p.x = same ? n.y + n.z : n.y - n.z;
	p.y = 0.0f - n.x;
	p.z = same ? 0.0f - n.x : n.x;
	lsq = (p.x * p.x + p.y * p.y) + p.z * p.z;
	len = sqrtf(lsq);
	if (lsq >= INFINITY) {
		p.x = p.y = p.z = NAN;
	} else if (ONB__IS0(len)) {
		p.x = p.y = p.z = 0.0f;
	} else {
		p.x = p.x / len; p.y = p.y / len; p.z = p.z / len;
	}
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}

/* ------------------------------------------------------------------ */
/* ogre (Ogre Vector3::perpendicular, completed)                        */
/* ------------------------------------------------------------------ */
/* Hocevar's vector: p = (-y, x, 0) when |x| > |z|, else (0, -z, y);
   normalisedCopy(): length = sqrt(dotProduct(p)) with dotProduct summed
   from 0 in component order, if length > 0 each component multiplied by
   1/length.  Ogre normalizes, so b1 = p as returned; b2 =
   n.crossProduct(b1) (docs/wild-specs/README.md).  Real: float, double
   with OGRE_DOUBLE_PRECISION.  hughes_moeller's vectors, but as b1 and
   with b2 = n x b1 (HM takes them as b2).  Handedness +1.  Threshold:
   |x| = |z|.  No singular unit direction (|p|^2 >= 1/2 - O(eps)). */
static inline void ONB__K(ogre)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 p;
	double sq, len;
	if (fabs(n.x) > fabs(n.z)) { p.x = -n.y; p.y = n.x; p.z = 0.0; }
	else { p.x = 0.0; p.y = -n.z; p.z = n.y; }
	sq = 0.0;
	sq += p.x * p.x; sq += p.y * p.y; sq += p.z * p.z;
	len = sqrt(sq);
	if (len > 0.0) {
		const double inv = 1.0 / len;
		p.x *= inv; p.y *= inv; p.z *= inv;
	}
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}
static inline void ONB__K(ogref)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f p;
	float sq, len;
	if (fabsf(n.x) > fabsf(n.z)) { p.x = -n.y; p.y = n.x; p.z = 0.0f; }
	else { p.x = 0.0f; p.y = -n.z; p.z = n.y; }
	sq = 0.0f;
	sq += p.x * p.x; sq += p.y * p.y; sq += p.z * p.z;
	len = sqrtf(sq);
	if (len > 0.0f) {
		const float inv = 1.0f / len;
		p.x *= inv; p.y *= inv; p.z *= inv;
	}
	*b1 = p;
	b2->x = n.y * p.z - n.z * p.y;
	b2->y = n.z * p.x - n.x * p.z;
	b2->z = n.x * p.y - n.y * p.x;
}

/* ------------------------------------------------------------------ */
/* bx (bgfx's bx::calcTangentFrame), bx_fixed                           */
/* ------------------------------------------------------------------ */
/* pbrt-v3's vectors on another branch: if |x| > |z| (bx::abs: a < 0 ? -a :
   a), T = (-z, 0, x) * rcpSafe(sqrt(x*x + z*z)), else T = (0, z, -y) *
   rcpSafe(sqrt(y*y + z*z)); B = cross(n, T).  bx::sqrt (sqrtSimd on x86)
   returns 0 below kFloatSmallest = FLT_MIN (and a NaN pattern below 0);
   rcpSafe(a) = 1 / copysign(max(FLT_MIN, |a|), a), so a flushed square
   gives T = (-z, 0, x) * 2^126.  Where |x| > |z| but |y| ~ 1 the squares
   are tiny: in float |T| grows to ~8.5e17 at n = (1e-20, 1, 0).  bx is
   float only; the double kernel is the same operations (and the same
   FLT_MIN constant) in double.  fixed = 1 (bx_fixed, not shipped): the
   branch |x| > |y| (pbrt-v3's), so the square is >= 1/2: the same frame
   at the six axes.  Handedness +1. */
/* bx::kFloatSmallest = 1.175494351e-38f = FLT_MIN = 0x1p-126f */
static inline double onb__bx_sqrt(double a)
{
	if (a < 0.0)
		return ONB__CAST(double, NAN);
	if (a < ONB__CAST(double, 0x1p-126f))
		return 0.0;
	return sqrt(a);
}
static inline double onb__bx_rcp_safe(double a)
{
	const double m = ONB__CAST(double, 0x1p-126f) > (a < 0.0 ? -a : a) ? ONB__CAST(double, 0x1p-126f) : (a < 0.0 ? -a : a);
	return 1.0 / copysign(m, a);
}
static inline float onb__bx_sqrtf(float a)
{
	if (a < 0.0f)
		return NAN;
	if (a < 0x1p-126f)
		return 0.0f;
	return sqrtf(a);
}
static inline float onb__bx_rcp_safef(float a)
{
	const float m = 0x1p-126f > (a < 0.0f ? -a : a) ? 0x1p-126f : (a < 0.0f ? -a : a);
	return 1.0f / copysignf(m, a);
}
static inline void onb__bx(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2, int fixed)
{
	const double ax = n.x < 0.0 ? -n.x : n.x, ay = n.y < 0.0 ? -n.y : n.y, az = n.z < 0.0 ? -n.z : n.z;
	onb_vec3 t;
	if (fixed ? ax > ay : ax > az) {
		const double inv = onb__bx_rcp_safe(onb__bx_sqrt(n.x * n.x + n.z * n.z));
		t.x = -n.z * inv; t.y = 0.0; t.z = n.x * inv;
	} else {
		const double inv = onb__bx_rcp_safe(onb__bx_sqrt(n.y * n.y + n.z * n.z));
		t.x = 0.0; t.y = n.z * inv; t.z = -n.y * inv;
	}
	*b1 = t;
	b2->x = n.y * t.z - n.z * t.y;
	b2->y = n.z * t.x - n.x * t.z;
	b2->z = n.x * t.y - n.y * t.x;
}
static inline void onb__bxf(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2, int fixed)
{
	const float ax = n.x < 0.0f ? -n.x : n.x, ay = n.y < 0.0f ? -n.y : n.y, az = n.z < 0.0f ? -n.z : n.z;
	onb_vec3f t;
	if (fixed ? ax > ay : ax > az) {
		const float inv = onb__bx_rcp_safef(onb__bx_sqrtf(n.x * n.x + n.z * n.z));
		t.x = -n.z * inv; t.y = 0.0f; t.z = n.x * inv;
	} else {
		const float inv = onb__bx_rcp_safef(onb__bx_sqrtf(n.y * n.y + n.z * n.z));
		t.x = 0.0f; t.y = n.z * inv; t.z = -n.y * inv;
	}
	*b1 = t;
	b2->x = n.y * t.z - n.z * t.y;
	b2->y = n.z * t.x - n.x * t.z;
	b2->z = n.x * t.y - n.y * t.x;
}
static inline void ONB__K(bx)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2) { onb__bx(n, b1, b2, 0); }
static inline void ONB__K(bxf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__bxf(n, b1, b2, 0); }
static inline void ONB__K(bx_fixed)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2) { onb__bx(n, b1, b2, 1); }
static inline void ONB__K(bx_fixedf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) { onb__bxf(n, b1, b2, 1); }

/* ------------------------------------------------------------------ */
/* blender (Blender BLI ortho_basis_v3v3_v3)                            */
/* ------------------------------------------------------------------ */
/* f = len_squared_v2(n) = x*x + y*y; if f > FLT_EPSILON (2^-23):
   d = 1/sqrtf(f), b1 = (y*d, (-x)*d, 0), b2 = ((-z)*b1.y, z*b1.x,
   x*b1.y - y*b1.x) (n x b1 with the zero products left out); else the
   fixed frame b1 = (z < 0 ? -1 : 1, 0, 0), b2 = (0, 1, 0), whose b1.n =
   +-x reaches sqrt(FLT_EPSILON) ~ 3.45e-4 just inside the threshold (the
   formula's own defect, near +-z).  Blender's BLI is float only; the
   double kernel is the same operations and the same FLT_EPSILON constant
   in double.  Handedness +1. */
static inline void ONB__K(blender)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double f = n.x * n.x + n.y * n.y;
	if (f > ONB__CAST(double, 0x1p-23f)) {
		const double d = 1.0 / sqrt(f);
		b1->x = n.y * d; b1->y = -n.x * d; b1->z = 0.0;
		b2->x = -n.z * b1->y; b2->y = n.z * b1->x; b2->z = n.x * b1->y - n.y * b1->x;
	} else {
		b1->x = n.z < 0.0 ? -1.0 : 1.0; b1->y = 0.0; b1->z = 0.0;
		b2->x = 0.0; b2->y = 1.0; b2->z = 0.0;
	}
}
static inline void ONB__K(blenderf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float f = n.x * n.x + n.y * n.y;
	if (f > 0x1p-23f) {
		const float d = 1.0f / sqrtf(f);
		b1->x = n.y * d; b1->y = -n.x * d; b1->z = 0.0f;
		b2->x = -n.z * b1->y; b2->y = n.z * b1->x; b2->z = n.x * b1->y - n.y * b1->x;
	} else {
		b1->x = n.z < 0.0f ? -1.0f : 1.0f; b1->y = 0.0f; b1->z = 0.0f;
		b2->x = 0.0f; b2->y = 1.0f; b2->z = 0.0f;
	}
}

/* ------------------------------------------------------------------ */
/* box3d (Box3D b3Perp + the contact solver's tangent2)                 */
/* ------------------------------------------------------------------ */
/* b3Perp: p = (y, -x, 0) if x < -0.5 || 0.5 < x, else (0, z, -y) (a NaN x
   takes the else); b1 = b3Normalize(p): ls = x*x + y*y + z*z, if ls >
   1000*FLT_MIN, s = 1/sqrtf(ls) and b1 = (s*p.x, s*p.y, s*p.z), else
   (0, 0, 0); the contact solver's b2 = b3Cross(b1, n) (b1 the LEFT
   operand).  (b1, b2, n) is left-handed: b1 x b2 = -n.  On the unit
   sphere |p|^2 >= 1/4.  Box3D is float only (built -ffp-contract=off);
   the double kernel is the same operations and the same float constant in
   double.  Handedness -1. */
static inline void ONB__K(box3d)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 p;
	double ls;
	if (n.x < -0.5 || 0.5 < n.x) { p.x = n.y; p.y = -n.x; p.z = 0.0; }
	else { p.x = 0.0; p.y = n.z; p.z = -n.y; }
	ls = p.x * p.x + p.y * p.y + p.z * p.z;
	if (ls > ONB__CAST(double, 1000.0f * 0x1p-126f)) {
		const double s = 1.0 / sqrt(ls);
		b1->x = s * p.x; b1->y = s * p.y; b1->z = s * p.z;
	} else {
		b1->x = 0.0; b1->y = 0.0; b1->z = 0.0;
	}
	b2->x = b1->y * n.z - b1->z * n.y;
	b2->y = b1->z * n.x - b1->x * n.z;
	b2->z = b1->x * n.y - b1->y * n.x;
}
static inline void ONB__K(box3df)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f p;
	float ls;
	if (n.x < -0.5f || 0.5f < n.x) { p.x = n.y; p.y = -n.x; p.z = 0.0f; }
	else { p.x = 0.0f; p.y = n.z; p.z = -n.y; }
	ls = p.x * p.x + p.y * p.y + p.z * p.z;
	if (ls > 1000.0f * 0x1p-126f) {
		const float s = 1.0f / sqrtf(ls);
		b1->x = s * p.x; b1->y = s * p.y; b1->z = s * p.z;
	} else {
		b1->x = 0.0f; b1->y = 0.0f; b1->z = 0.0f;
	}
	b2->x = b1->y * n.z - b1->z * n.y;
	b2->y = b1->z * n.x - b1->x * n.z;
	b2->z = b1->x * n.y - b1->y * n.x;
}

/* ------------------------------------------------------------------ */
/* appleseed (appleseed foundation Basis3<T>::build(normal))            */
/* ------------------------------------------------------------------ */
/* Hughes-Moller's choice of the smallest |component| (strict <: |x| <
   |y| ? (|x| < |z| ? x : z) : (|y| < |z| ? y : z)), u = (0, -z, y),
   (-z, 0, x) or (-y, x, 0) with that component zeroed; foundation's
   normalize: n = sqrt(dot(u, u)), the dot a loop from 0 ((0 + u.x^2) +
   u.y^2) + u.z^2 (0 + u.x^2 = u.x^2 exactly, as written here), and the
   float and double operator/ multiply by 1/n; v = cross(u, n).  The basis
   is (u, n, v); as (b1, b2) = (u, v) it is left-handed (u x v = -n).
   Basis3f (float) and Basis3d (double) both ship.  Handedness -1. */
static inline void ONB__K(appleseed)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	onb_vec3 u;
	double s;
	if (fabs(n.x) < fabs(n.y)) {
		if (fabs(n.x) < fabs(n.z)) { u.x = 0.0; u.y = -n.z; u.z = n.y; }
		else { u.x = -n.y; u.y = n.x; u.z = 0.0; }
	} else {
		if (fabs(n.y) < fabs(n.z)) { u.x = -n.z; u.y = 0.0; u.z = n.x; }
		else { u.x = -n.y; u.y = n.x; u.z = 0.0; }
	}
	s = 1.0 / sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
	b1->x = u.x * s; b1->y = u.y * s; b1->z = u.z * s;
	b2->x = b1->y * n.z - n.y * b1->z;
	b2->y = b1->z * n.x - n.z * b1->x;
	b2->z = b1->x * n.y - n.x * b1->y;
}
static inline void ONB__K(appleseedf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3f u;
	float s;
	if (fabsf(n.x) < fabsf(n.y)) {
		if (fabsf(n.x) < fabsf(n.z)) { u.x = 0.0f; u.y = -n.z; u.z = n.y; }
		else { u.x = -n.y; u.y = n.x; u.z = 0.0f; }
	} else {
		if (fabsf(n.y) < fabsf(n.z)) { u.x = -n.z; u.y = 0.0f; u.z = n.x; }
		else { u.x = -n.y; u.y = n.x; u.z = 0.0f; }
	}
	s = 1.0f / sqrtf(u.x * u.x + u.y * u.y + u.z * u.z);
	b1->x = u.x * s; b1->y = u.y * s; b1->z = u.z * s;
	b2->x = b1->y * n.z - n.y * b1->z;
	b2->y = b1->z * n.x - n.z * b1->x;
	b2->z = b1->x * n.y - n.x * b1->y;
}

/* ------------------------------------------------------------------ */
/* babylon (Babylon.js Vector3.getNormalToRef, JavaScript double)       */
/* ------------------------------------------------------------------ */
/* V8's fdlibm (src/lib/fdlibm.c): Node.js's Math.acos, atan2, sin, cos. */
extern double onb__fdlibm_acos(double x);   /* internal: the babylon kernel's */
extern double onb__fdlibm_atan2(double y, double x);
extern double onb__fdlibm_sin(double x);
extern double onb__fdlibm_cos(double x);
/* getNormalToRef: radius = length() = sqrt(x*x + y*y + z*z); theta =
   acos(y / radius), phi = atan2(z, x); theta -= PI/2 where theta > PI/2,
   else theta += PI/2 (Math.PI / 2 = 0x1.921fb54442d18p+0); the result
   ((radius * sin(theta)) * cos(phi), radius * cos(theta), (radius *
   sin(theta)) * sin(phi)), evaluated left to right in double with V8's
   fdlibm.  Completed (docs/wild-specs/README.md): b1 = that vector through
   Vector3.normalize() (normalizeFromLength(length()): unchanged where the
   length is 0 or 1, else scaled by 1/length), b2 = Vector3.CrossToRef(n,
   b1) (x = n.y b1.z - n.z b1.y, ...).  Handedness +1.  At +-y, atan2(0, 0)
   = 0 gives b1 = (1, cos(PI/2), 0), b1.y = 6.1e-17.  Babylon.js has no
   float path (JavaScript numbers are doubles): onb_babylonf widens n,
   runs the double row and rounds b1 and b2 to float (a Float32Array
   store), as duff_widef does. */
static inline void ONB__K(babylon)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double pio2 = 0x1.921fb54442d18p+0;   /* Math.PI / 2 */
	const double radius = sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
	double theta = onb__fdlibm_acos(n.y / radius);
	const double phi = onb__fdlibm_atan2(n.z, n.x);
	double x, y, z, len;
	if (theta > pio2)
		theta -= pio2;
	else
		theta += pio2;
	x = radius * onb__fdlibm_sin(theta) * onb__fdlibm_cos(phi);
	y = radius * onb__fdlibm_cos(theta);
	z = radius * onb__fdlibm_sin(theta) * onb__fdlibm_sin(phi);
	len = sqrt(x * x + y * y + z * z);
	if (!(ONB__IS0(len) || ONB__IS0(len - 1.0))) {   /* len == 0 or 1 (exact: Sterbenz) */
		const double s = 1.0 / len;
		x *= s; y *= s; z *= s;
	}
	b1->x = x; b1->y = y; b1->z = z;
	b2->x = n.y * z - n.z * y;
	b2->y = n.z * x - n.x * z;
	b2->z = n.x * y - n.y * x;
}
static inline void ONB__K(babylonf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	onb_vec3 nd, d1, d2;
	nd.x = ONB__CAST(double, n.x); nd.y = ONB__CAST(double, n.y); nd.z = ONB__CAST(double, n.z);
	ONB__K(babylon)(nd, &d1, &d2);
	b1->x = ONB__CAST(float, d1.x); b1->y = ONB__CAST(float, d1.y); b1->z = ONB__CAST(float, d1.z);
	b2->x = ONB__CAST(float, d2.x); b2->y = ONB__CAST(float, d2.y); b2->z = ONB__CAST(float, d2.z);
}

/* open3d_fixed (this project's fix of open3d, not shipped code): Open3D's
   lines with the guard comparing n with the unit diagonal
   d = (0, 1, 1)/sqrt(2) = (0, c, c) and its antipode: the cross with
   (1, 0, 1) is taken when |d - n|^2 <= 1e-3 or |d + n|^2 <= 1e-3, so b1 is
   never the zero vector.  The frame at +-x, +-y, +-z is Open3D's.
   Handedness +1.  No singular unit direction.
   Tested bound (tests/test_lib.c): D <= 12u. */
static inline void ONB__K(open3d_fixed)(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2)
{
	const double c = 0x1.6a09e667f3bcdp-1; /* 1/sqrt(2) rounded: d = (0, c, c) */
	onb_vec3 d, e, p, q;
	d.x = 0.0 - n.x; d.y = c - n.y; d.z = c - n.z;
	e.x = 0.0 + n.x; e.y = c + n.y; e.z = c + n.z;
	if ((d.x * d.x + d.y * d.y) + d.z * d.z > 1e-3 && (e.x * e.x + e.y * e.y) + e.z * e.z > 1e-3) {
		p.x = n.y - n.z; p.y = -n.x; p.z = n.x;
	} else {
		p.x = n.y; p.y = n.z - n.x; p.z = -n.y;
	}
	onb__o3d_normalize(&p);
	q.x = n.y * p.z - n.z * p.y;
	q.y = n.z * p.x - n.x * p.z;
	q.z = n.x * p.y - n.y * p.x;
	onb__o3d_normalize(&q);
	*b1 = p;
	*b2 = q;
}
static inline void ONB__K(open3d_fixedf)(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2)
{
	const float c = 0x1.6a09e6p-1f; /* 1/sqrt(2) rounded: d = (0, c, c) */
	onb_vec3f d, e, p, q;
	d.x = 0.0f - n.x; d.y = c - n.y; d.z = c - n.z;
	e.x = 0.0f + n.x; e.y = c + n.y; e.z = c + n.z;
	if (d.x * d.x + (d.y * d.y + d.z * d.z) > 1e-3f && e.x * e.x + (e.y * e.y + e.z * e.z) > 1e-3f) {
		p.x = n.y - n.z; p.y = -n.x; p.z = n.x;
	} else {
		p.x = n.y; p.y = n.z - n.x; p.z = -n.y;
	}
	onb__o3d_normalizef(&p);
	q.x = n.y * p.z - n.z * p.y;
	q.y = n.z * p.x - n.x * p.z;
	q.z = n.x * p.y - n.y * p.x;
	onb__o3d_normalizef(&q);
	*b1 = p;
	*b2 = q;
}

/* Relative tolerance on |n|^2 - 1 under which n is used unchanged. */
#define ONB_CHECK_TOL  1e-12
#define ONB_CHECK_TOLF 1e-6f

/* Checked entry point for renderers: validates n, normalizes it when it is
   not unit (scaling first, so no overflow or underflow), then calls
   method->basis (or basisf).  On ONB_ZERO, ONB_NONFINITE and
   ONB_BAD_METHOD, b1 and b2 are set to (1,0,0) and (0,1,0) and the status
   tells the caller not to trust them.  *n_used (may be NULL) receives the
   normal actually passed to the method. */
onb_status onb_basis_checked (const onb_method *method, onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2, onb_vec3  *n_used);
onb_status onb_basis_checkedf(const onb_method *method, onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2, onb_vec3f *n_used);
#if ONB_HAVE_HALF
/* binary16: every rounding of a unit vector to binary16 has | |n|^2 - 1 |
   <= 2^-10 + 2^-22 (each component within u = 2^-11 relative), so
   ONB_CHECK_TOLH = 2^-9 passes them all unchanged (ONB_OK); a vector
   outside it is normalized in float and rounded to binary16 again
   (ONB_RENORMALIZED: *n_used is then such a rounding itself).  The basis
   is method->arrayh's (ONB_BAD_METHOD where the method has none). */
#define ONB_CHECK_TOLH 0x1p-9f
onb_status onb_basis_checkedh(const onb_method *method, onb_vec3h n, onb_vec3h *b1, onb_vec3h *b2, onb_vec3h *n_used);
#endif

/* Out-of-line copies and batch kernels, one set per method.  Declared by
   an X-macro so the list stays in one place; registry.c defines them. */
#define ONB_METHOD_LIST(X) \
	X(naive) X(naive_invsqrt) X(naive_rsqrt) X(naive_rsqrt_nr) X(naive_nonorm) \
	X(hughes_moeller) X(hughes_moeller_invsqrt) X(hughes_moeller_rsqrt) \
	X(hughes_moeller_rsqrt_nr) X(hughes_moeller_nonorm) \
	X(frisvad) X(frisvad_max) X(duff) X(duff_branchless) X(stark) X(stark_fixed) X(pbrt_v3) \
	X(rtow) X(tangent_cross_z) \
	X(q2rtx) X(filament) X(filament_hm) X(capsaicin) X(capsaicin_fixed) X(unity) X(willems) X(gltf_viewer) X(rtao) X(rtao_fixed) X(mitsuba3) X(cycles_cross111) X(cycles_cross111_avx2) X(embree) X(luxcore) \
	X(nori) X(osl_ortho) X(ospray) X(osl_gabornoise) X(cauldron2) X(threejs) X(q2rtx_fixed) X(jolt_arm64) \
	X(jolt) X(jolt_fma) X(bullet) X(mujoco) X(eigen) X(physx) X(rp3d) X(open3d) \
	X(raylib) X(godot) X(directxmath) X(ogre) X(bx) X(blender) X(box3d) X(appleseed) X(babylon) X(godot_fixed) X(bx_fixed) \
	X(physx_fixed) X(open3d_fixed) X(filament_fixed) X(luxcore_fixed)

#define ONB__DECLARE(m) \
	void onb_##m##_outline (onb_vec3  n, onb_vec3  *b1, onb_vec3  *b2); \
	void onb_##m##_outlinef(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2); \
	void onb_##m##_batch (size_t count, const double *nx, const double *ny, const double *nz, \
		double *b1x, double *b1y, double *b1z, double *b2x, double *b2y, double *b2z); \
	void onb_##m##_batchf(size_t count, const float *nx, const float *ny, const float *nz, \
		float *b1x, float *b1y, float *b1z, float *b2x, float *b2y, float *b2z);
ONB_METHOD_LIST(ONB__DECLARE)
#undef ONB__DECLARE

/* The float-only methods (ONB_FLOAT_ONLY), after the others in the
   registry: out-of-line copy and batch kernel in float only. */
#define ONB_FLOAT_METHOD_LIST(X) X(duff_wide) X(duff_comp)
#define ONB__DECLARE_F(m) \
	void onb_##m##_outlinef(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2); \
	void onb_##m##_batchf(size_t count, const float *nx, const float *ny, const float *nz, \
		float *b1x, float *b1y, float *b1z, float *b2x, float *b2y, float *b2z);
ONB_FLOAT_METHOD_LIST(ONB__DECLARE_F)
#undef ONB__DECLARE_F

/* Array entry points, for renderers with their own vector types: n points
   to 3 values (x, y, z) read, b1 and b2 to 3 values each written; none of
   them may overlap.  Plain pointers, not n[3] parameters, so that `&v.x`
   of a renderer's struct { float x, y, z; } compiles without GCC's
   -Wstringop-overread/-overflow (docs/library.md shows that case).  Out of
   line in libonb.a, so they keep the studied bits whatever the caller's
   flags: onb_NAME_array[f](n, b1, b2) per method, or by registry entry. */
#define ONB__DECLARE_ARRAY(m) \
	void onb_##m##_array (const double *n, double *b1, double *b2); \
	void onb_##m##_arrayf(const float  *n, float  *b1, float  *b2);
ONB_METHOD_LIST(ONB__DECLARE_ARRAY)
#undef ONB__DECLARE_ARRAY
/* method->array(f) (or, for a table of your own without it, method->basis(f))
   on arrays (3 values each, as above); a NULL method (or function: a
   float-only method in double) leaves b1, b2 untouched and returns
   ONB_BAD_METHOD, else ONB_OK (no check of n: see onb_basis_checked). */
onb_status onb_basis_array (const onb_method *method, const double *n, double *b1, double *b2);
onb_status onb_basis_arrayf(const onb_method *method, const float  *n, float  *b1, float  *b2);
/* The same, inline, so that a method chosen at run time costs one indirect
   call (method->array[f]) more than onb_NAME_array[f].  Through a second
   call level, the methods whose branches mispredict (stark) cost 1.7x the
   array entry, not 1.1x (results/clients/entries.md).  No arithmetic here:
   the client's flags change nothing.  (onb_basis_array)(...) and
   &onb_basis_array still name the library's functions. */
static inline onb_status onb__basis_array(const onb_method *method, const double *n, double *b1, double *b2)
{
	if (!method || !method->basis || !method->array)
		return onb_basis_array(method, n, b1, b2);
	method->array(n, b1, b2);
	return ONB_OK;
}
static inline onb_status onb__basis_arrayf(const onb_method *method, const float *n, float *b1, float *b2)
{
	if (!method || !method->basisf || !method->arrayf)
		return onb_basis_arrayf(method, n, b1, b2);
	method->arrayf(n, b1, b2);
	return ONB_OK;
}
#define onb_basis_array(method, n, b1, b2) onb__basis_array(method, n, b1, b2)
#define onb_basis_arrayf(method, n, b1, b2) onb__basis_arrayf(method, n, b1, b2)
#define ONB__DECLARE_ARRAY_F(m) \
	void onb_##m##_arrayf(const float *n, float *b1, float *b2);
ONB_FLOAT_METHOD_LIST(ONB__DECLARE_ARRAY_F)
#undef ONB__DECLARE_ARRAY_F

/* binary16 (ONB_HAVE_HALF): onb_NAMEh(n, &b1, &b2) for every method of
   both lists, out of line, each operation rounded to binary16 (see
   ONB_HAVE_HALF above); onb_NAME_arrayh the same on bit patterns (the
   registry's arrayh).  Constants are the float kernel's, rounded to
   binary16 as a mediump literal is: Frisvad's and Max's thresholds, Quake
   II RTX's and Filament's all become -1 (so Listing 2 has no fallback left
   in half: n = -z gives 1 + n.z = 0 and a NaN basis), PhysX's 0.9999f
   becomes 1, MuJoCo's 1e-15 becomes 0; Eigen's precision is its
   NumTraits<half>::dummy_precision(), 1e-2.  The approximate
   normalizations run on the input widened to float (exact): _invsqrt the
   float bit trick's seed rounded to binary16 and Listing 3's Newton step
   in half, _rsqrt rsqrtss rounded to binary16 (+ the Newton step in half
   for _rsqrt_nr), Listing 3's rsqrt (double)1/sqrt rounded once; embree
   the same estimate and its Newton step in half.  pbrt_v3's cross and
   duff_wide compute in double and round each output once, as their float
   kernels do.  fma (cycles_cross111_avx2, jolt_fma, duff_comp) is the
   double fma rounded once, which is the correctly rounded binary16 fma
   (half.c gives the argument). */
#if ONB_HAVE_HALF
#define ONB__DECLARE_H(m) \
	void onb_##m##h(onb_vec3h n, onb_vec3h *b1, onb_vec3h *b2); \
	void onb_##m##_arrayh(const uint16_t *n, uint16_t *b1, uint16_t *b2);
ONB_METHOD_LIST(ONB__DECLARE_H)
ONB_FLOAT_METHOD_LIST(ONB__DECLARE_H)
#undef ONB__DECLARE_H
#define ONB_FRISVAD_TH ((onb_half)ONB_FRISVAD_TF) /* -1 in binary16 */
void onb_frisvad_thresholdh(onb_vec3h n, onb_half t, onb_vec3h *b1, onb_vec3h *b2);
onb_vec3h onb_frisvad_rotateh(onb_vec3h n, onb_half x, onb_half y, onb_half z);
/* How the half kernels convert between binary16 and float: "f16c" (x86-64
   with GCC: an F16C copy of every kernel, chosen at load time where the
   CPU has it), "soft" (libgcc's conversion routines) or "inline" (a build
   whose flags convert with instructions: -mf16c, arm64).  Same bits in
   every case; the arithmetic is emulated in float either way (no native
   half instructions, AVX512-FP16 or arm64 FP16, are used). */
const char *onb_half_isa(void);
#endif

/* The tools out of line, for callers whose flags could change their bits. */
void onb_frisvad_threshold_outline (onb_vec3  n, double t, onb_vec3  *b1, onb_vec3  *b2);
void onb_frisvad_threshold_outlinef(onb_vec3f n, float  t, onb_vec3f *b1, onb_vec3f *b2);
onb_vec3  onb_frisvad_rotate_outline (onb_vec3  n, double x, double y, double z);
onb_vec3f onb_frisvad_rotate_outlinef(onb_vec3f n, float  x, float  y, float  z);

/* Out of line (ONB__INLINE 0, see the top): the method names call
   libonb.a's copies, so the caller gets the studied bits.  With GCC and
   clang each name is declared as the copy itself (an asm label: a call of
   onb_NAME is a call of the symbol onb_NAME_outline, &onb_NAME its
   address).  Through an inline wrapper, GCC at -O3 -march=native (C and
   C++) first copied n into a local and then into the call's argument:
   two more stores per call, and in float a reload of n.z through the
   store buffer, and a call by the name cost 1.1-1.2x the same call of
   onb_NAME_outline[f] (results/clients/entries.md, "name (out of line)").
   Other compilers get the wrappers. */
#if !ONB__INLINE && defined(__GNUC__)
#define ONB__SYM_(p, s) #p s
#define ONB__SYM(p, s) ONB__SYM_(p, s)
#define ONB__LABEL(s) __asm__(ONB__SYM(__USER_LABEL_PREFIX__, s))
#define ONB__WRAP(m) \
	void onb_##m(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2) ONB__LABEL("onb_" #m "_outline"); \
	void onb_##m##f(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) ONB__LABEL("onb_" #m "_outlinef");
ONB_METHOD_LIST(ONB__WRAP)
#undef ONB__WRAP
#define ONB__WRAP_F(m) \
	void onb_##m##f(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) ONB__LABEL("onb_" #m "_outlinef");
ONB_FLOAT_METHOD_LIST(ONB__WRAP_F)
#undef ONB__WRAP_F
void onb_frisvad_threshold(onb_vec3 n, double t, onb_vec3 *b1, onb_vec3 *b2) ONB__LABEL("onb_frisvad_threshold_outline");
void onb_frisvad_thresholdf(onb_vec3f n, float t, onb_vec3f *b1, onb_vec3f *b2) ONB__LABEL("onb_frisvad_threshold_outlinef");
onb_vec3 onb_frisvad_rotate(onb_vec3 n, double x, double y, double z) ONB__LABEL("onb_frisvad_rotate_outline");
onb_vec3f onb_frisvad_rotatef(onb_vec3f n, float x, float y, float z) ONB__LABEL("onb_frisvad_rotate_outlinef");
#elif !ONB__INLINE
#define ONB__WRAP(m) \
	static inline void onb_##m(onb_vec3 n, onb_vec3 *b1, onb_vec3 *b2) \
	{ onb_##m##_outline(n, b1, b2); } \
	static inline void onb_##m##f(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) \
	{ onb_##m##_outlinef(n, b1, b2); }
ONB_METHOD_LIST(ONB__WRAP)
#undef ONB__WRAP
#define ONB__WRAP_F(m) \
	static inline void onb_##m##f(onb_vec3f n, onb_vec3f *b1, onb_vec3f *b2) \
	{ onb_##m##_outlinef(n, b1, b2); }
ONB_FLOAT_METHOD_LIST(ONB__WRAP_F)
#undef ONB__WRAP_F
static inline void onb_frisvad_threshold(onb_vec3 n, double t, onb_vec3 *b1, onb_vec3 *b2)
{ onb_frisvad_threshold_outline(n, t, b1, b2); }
static inline void onb_frisvad_thresholdf(onb_vec3f n, float t, onb_vec3f *b1, onb_vec3f *b2)
{ onb_frisvad_threshold_outlinef(n, t, b1, b2); }
static inline onb_vec3 onb_frisvad_rotate(onb_vec3 n, double x, double y, double z)
{ return onb_frisvad_rotate_outline(n, x, y, z); }
static inline onb_vec3f onb_frisvad_rotatef(onb_vec3f n, float x, float y, float z)
{ return onb_frisvad_rotate_outlinef(n, x, y, z); }
#endif

#ifdef __cplusplus
}
#endif

#if ONB__FP_PRAGMAS == 1
#pragma float_control(pop)
#endif

#endif /* LIBONB_ONB_H */
