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

/* The binary16 entry (src/lib/half.c), or NULL in a build without _Float16. */
#if ONB_HAVE_HALF
#define ONB__HALF(m) onb_##m##_arrayh
#else
#define ONB__HALF(m) NULL
#endif
#define ONB__PTRS(m) onb_##m##_outline, onb_##m##_outlinef, onb_##m##_batch, onb_##m##_batchf, \
	onb_##m##_array, onb_##m##_arrayf, ONB__HALF(m)
#define ONB__PTRS_F(m) NULL, onb_##m##_outlinef, NULL, onb_##m##_batchf, NULL, onb_##m##_arrayf, ONB__HALF(m)

#define SRC_L1 "Frisvad 2012, JGT 16(3), Listing 1"
#define SRC_HM "Hughes & Moller 1999, JGT 4(4), as Frisvad 2012 Listing 1"
#define SING_NAIVE "n = -x (b1 cancels to 0; precision lost as n.x -> -1)"
#define THR_NAIVE "n.x > 0.9"
#define THR_HM "|n.x| > |n.z|"

/* Where the engines' methods come from (onb_method.prov); each kernel's
   comment in include/libonb/onb.h gives the arithmetic. */
/* The physics engines' and math libraries' provenance (read at these commits). */
static const onb_provenance P_JOLT = { "github.com/jrouwe/JoltPhysics", "3b47ec390cb9b933769183eff599f72195c5873c",
	"Jolt/Math/Vec3.inl:1119-1159", "MIT", "C++17 (SSE)", "float",
	"source-level IEEE, the SSE path (x86 with -ffp-contract=off: CROSS_PLATFORM_DETERMINISTIC or USE_FMADD off; non-x86 builds get -ffp-contract=on and the scalar path: jolt_arm64); b2 = n.Cross(b1), Vec3.inl:855-891" };
static const onb_provenance P_JOLT_FMA = { "github.com/jrouwe/JoltPhysics", "3b47ec390cb9b933769183eff599f72195c5873c",
	"Jolt/Math/Vec3.inl:1119-1159", "MIT", "C++17 (SSE)", "float",
	"the default x86 build: USE_FMADD, -mfma -ffp-contract=fast (Build/CMakeLists.txt:263-272): Cross's t1 - t2 fused" };
static const onb_provenance P_BULLET = { "github.com/bulletphysics/bullet3", "6c888f4abd7b46f572587360cc214985f02e5c6b",
	"src/LinearMath/btVector3.h:1250-1279", "Zlib", "C++", "btScalar: float, double with BT_USE_DOUBLE_PRECISION",
	"source-level IEEE (no -ffp-contract, no -mfma in Bullet's CMake)" };
static const onb_provenance P_MUJOCO = { "github.com/google-deepmind/mujoco", "a7255075b003506ff5f34b512d88e02df12a73c6",
	"src/engine/engine_util_spatial.c:512-538", "Apache-2.0", "C", "mjtNum: double, float with mjUSESINGLE",
	"source-level IEEE (-mavx, no -mfma, no contraction)" };
static const onb_provenance P_EIGEN = { "github.com/eigen-mirror/eigen", "12c9c14bc5d4c4ba28cf41102ea99b7f83f30d04",
	"Eigen/src/Geometry/OrthoMethods.h:196-229", "MPL-2.0", "C++ template", "the scalar: float (prec 1e-5) and double (prec 1e-12)",
	"header-only: the user's flags; modelled as source-level IEEE; b2 = n.cross(b1), OrthoMethods.h:24-43" };
static const onb_provenance P_PHYSX = { "github.com/NVIDIA-Omniverse/PhysX", "a3d8a641de4c3014fd56704af0f50b8be7e9778b",
	"physx/include/foundation/PxMathUtils.h:297-316", "BSD-3-Clause", "C++", "float",
	"source-level IEEE (no -ffast-math, no -mfma in the Linux CMake)" };
static const onb_provenance P_RP3D = { "github.com/DanielChappuis/reactphysics3d", "7000610a244ea85377e4f4c9bcdf68af0159b595",
	"src/mathematics/Vector3.cpp:46-64", "Zlib", "C++", "decimal: float, double with IS_RP3D_DOUBLE_PRECISION_ENABLED",
	"source-level IEEE" };
static const onb_provenance P_OPEN3D = { "github.com/isl-org/Open3D", "22a6a307b9b7d88604895f79c0ceeecef2fc6538",
	"cpp/open3d/geometry/PointCloudPlanarPatchDetection.cpp:697-717", "MIT", "C++ (Eigen)", "double",
	"source-level IEEE (no -ffast-math, no FMA target by default on x86-64)" };
static const onb_provenance P_RAYLIB = { "github.com/raysan5/raylib", "abe23bf82dcab18a618067843aed4eec2b24ba97",
	"src/raymath.h:696-722", "Zlib", "C", "float (raylib has no double build; the double row is the same operations in double)",
	"source-level IEEE; completed with Vector3Normalize (raymath.h:804-819) and Vector3CrossProduct(n, b1) (:688-693)" };
static const onb_provenance P_GODOT = { "github.com/godotengine/godot", "2a520db456c6da98f0f1a499cba25c73a0699125",
	"core/math/vector3.h:380-388", "MIT", "C++", "real_t: float, double with precision=double",
	"source-level IEEE; normalized() (Vector3::normalize, lengthsq == 0 -> zeros, else divide by sqrt) and b2 = n.cross(b1) (vector3.h:244-251)" };
static const onb_provenance P_DIRECTXMATH = { "github.com/microsoft/DirectXMath", "d33ba2f150aeb6d3cf62d10f454652ee83672200",
	"Inc/DirectXMathVector.inl:10195-10215", "MIT", "C++ (SSE intrinsics)", "float (XMVECTOR; the double row is the same operations in double)",
	"the default x64 build (_XM_SSE_INTRINSICS_, no FMA); completed with XMVector3Normalize (:9880-9994, SSE path: divides) and XMVector3Cross(n, b1) (:9529-9575)" };
static const onb_provenance P_OGRE = { "github.com/OGRECave/ogre", "3e955a168617aa13edd418c8a2e4a9a72b6a0247",
	"OgreMain/include/OgreVector.h:748-755", "MIT", "C++", "Real: float, double with OGRE_DOUBLE_PRECISION",
	"source-level IEEE; normalisedCopy (:494-519: 1/length, multiplied, skipped when length is 0; dotProduct :423-429) and b2 = n.crossProduct(b1) (:757-763)" };
static const onb_provenance P_BX = { "github.com/bkaradzic/bx", "43bfe2940275ef7fa5bc362814883d5252715122",
	"include/bx/inline/math.inl:1327-1349", "BSD-2-Clause", "C++", "float (bx has no double build; the double row is the same operations and constants in double)",
	"x86 with BX_SIMD_SUPPORTED: sqrt = sqrtSimd (:857-875, 0 below kFloatSmallest), rcpSafe (:264-267), cross (:1221-1229); source-level IEEE" };
static const onb_provenance P_BLENDER = { "github.com/blender/blender", "0c0030fb125ce559fb5a28b320f490be049c0a95",
	"source/blender/blenlib/intern/math_vector.cc:568-591", "GPL-2.0-or-later", "C++", "float (BLI's float[3]; the double row is the same operations and FLT_EPSILON in double)",
	"source-level IEEE (x86-64 builds: no FMA); len_squared_v2 = x*x + y*y (BLI_math_vector_inline.c)" };
static const onb_provenance P_BOX3D = { "github.com/erincatto/box3d", "30c67b5e6d0a3a66f0f506c69ce9e9e0587e3b7c",
	"include/box3d/math_functions.h:306-322", "MIT", "C", "float (Box3D has no double build; the double row is the same operations and 1000*FLT_MIN in double)",
	"-ffp-contract=off (CMakeLists.txt:79-89); b3Normalize (:276-288: 0 at or below 1000*FLT_MIN), b2 = b3Cross(b1, n) (:350-357) as src/contact_solver.c:175-176" };
static const onb_provenance P_APPLESEED = { "github.com/appleseedhq/appleseed", "022c1590d9dae40773df8c5000385889d3f893d0",
	"src/appleseed/foundation/math/basis.h:175-236", "MIT", "C++", "T: Basis3f (float) and Basis3d (double) both ship",
	"source-level IEEE (no FMA target); foundation/math/vector.h (read at 95b801be): normalize = v * (1/sqrt(dot)), dot a loop from 0, cross(u, n)" };
static const onb_provenance P_BABYLON = { "github.com/BabylonJS/Babylon.js", "141e38dddee1ac94408a53bacf22508973697532",
	"packages/dev/core/src/Maths/math.vector.ts, Vector3.getNormalToRef (characters 58482-59850 of the 350247; normalize, length :74700-76500)", "Apache-2.0", "TypeScript -> JavaScript", "double only (JavaScript numbers; Babylon.js has no float path: the float kernel rounds the double row's b1, b2 to float, and the table gives no float figure)",
	"Node.js 20.20.2 (V8 11.3.244.8): Math.acos, atan2, sin, cos are V8's fdlibm port (src/base/ieee754.cc, src/lib/fdlibm.c, bit for bit); completed with normalize() (unchanged at length 0 or 1, else times 1/length) and b2 = Vector3.CrossToRef(n, b1)" };
static const onb_provenance P_Q2RTX = { "github.com/NVIDIA/Q2RTX", "f2526e9a165949f66e91e82f0d63aa7bb2567b4d",
	"src/refresh/vkpt/shader/utils.glsl:241-257", "GPL-2.0-or-later", "GLSL", "float",
	"IEEE: `precise` forbids contraction; Vulkan's 2.5-ulp division read as correctly rounded" };
static const onb_provenance P_FILAMENT = { "github.com/google/filament", "e91b6eb2016b9c47f196936a6489434ff15084aa",
	"libs/geometry/src/TangentSpaceMesh.cpp:169-183", "Apache-2.0", "C++", "float",
	"IEEE (x86-64: no contraction; arm64 clang's within-expression fma not modelled)" };
static const onb_provenance P_FILAMENT_HM = { "github.com/google/filament", "e91b6eb2016b9c47f196936a6489434ff15084aa",
	"libs/geometry/src/TangentSpaceMesh.cpp:219-227", "Apache-2.0", "C++", "float",
	"IEEE (x86-64: no contraction; arm64 clang's within-expression fma not modelled); abs(float) read as std::abs" };
static const onb_provenance P_CAPSAICIN = { "github.com/GPUOpen-LibrariesAndSDKs/Capsaicin", "5a3bf2a2b9b736bf660a6f4da17a6959ab4fc836",
	"src/core/src/math/sampling.hlsl:118-126", "MIT", "HLSL", "float",
	"IEEE (source level: 1.0f / sqrt read as a division by a correctly rounded sqrt; DXC may emit rsqrt or mad: not modelled)" };
static const onb_provenance P_UNITY = { "github.com/Unity-Technologies/Graphics", "0c658a0ca9e3b0230a21342a0448d1bbedd880ca",
	"Packages/com.unity.render-pipelines.core/ShaderLibrary/CommonLighting.hlsl:451-468", "LicenseRef-Unity-Companion-License", "HLSL",
	"real: float (half where the platform defines real as half: not modelled)",
	"IEEE (source level; FastSign from Common.hlsl: CopySign(1, z, true) = z >= 0 ? 1 : -1; a shader compiler may form mad: not modelled)" };
static const onb_provenance P_WILLEMS = { "github.com/SaschaWillems/Vulkan", "9c8e787f96af0ea3a22791d8f70edb96246efe6c",
	"shaders/glsl/pbribl/prefilterenvmap.frag:48-54", "MIT", "GLSL (the HLSL and Slang copies are the same)", "float",
	"IEEE (source level: normalize(v) = v / sqrt(dot(v, v)), no contraction; GPU arithmetic is issue 42's)" };
static const onb_provenance P_GLTF_VIEWER = { "github.com/KhronosGroup/glTF-Sample-Viewer", "b3a7e6680032ab858036e98792c90f9664963053",
	"source/shaders/ibl_filtering.frag:91-114", "MIT", "GLSL (precision mediump float)", "mediump read as float",
	"IEEE (source level: normalize(v) = v / sqrt(dot(v, v)), no contraction; another stored version, 06cfd88d, has the 1e-7 guard commented out)" };
static const onb_provenance P_RTAO = { "github.com/microsoft/DirectX-Graphics-Samples", "357ade6ec6ff0d9dcadc48f35c7a28e37c0cdf7a",
	"Samples/Desktop/D3D12Raytracing/src/D3D12RaytracingRealTimeDenoisedAmbientOcclusion/RTAO/Shaders/RayGen.hlsli:19-25", "MIT", "HLSL", "float",
	"IEEE (source level: normalize(v) = v / sqrt(dot(v, v)), 0.3f*w + c two roundings; DXC may form mad: not modelled)" };
static const onb_provenance P_MITSUBA3 = { "github.com/mitsuba-renderer/mitsuba3", "b45b0a930275114de0f8c34e8cf52775e176ca9a",
	"include/mitsuba/core/vector.h:117-138", "BSD-3-Clause", "C++ (Dr.Jit dfccdd7967547efce49fb4a929c39e4474ea73e2)",
	"Float: float (scalar_rgb), double (scalar_*_double)",
	"scalar variants without FMA (x86-64 baseline): fmadd = a*b + c; with FMA (aarch64, AVX2 builds) fmadd fuses: not this method" };
static const onb_provenance P_CYCLES = { "github.com/blender/cycles", "97dbe6f57cdf4ede2d2b75ebdda507c8712edb7a",
	"src/util/math_float3.h:724-750", "Apache-2.0", "C++", "float",
	"the SSE4.2 CPU kernel (dpps, lane-wise division): the source's IEEE arithmetic; the AVX2 kernel's fmsub cross not modelled" };
static const onb_provenance P_CYCLES_AVX2 = { "github.com/blender/cycles", "97dbe6f57cdf4ede2d2b75ebdda507c8712edb7a",
	"src/util/math_float3.h:724-750", "Apache-2.0", "C++", "float",
	"the AVX2 CPU kernel (-mavx2 -mfma): cross = msub = _mm_fmsub_ps (src/util/math_float4.h:253-263), the rest as the SSE4.2 kernel" };
static const onb_provenance P_EMBREE = { "github.com/embree/embree", "0c236df6f31a8e9c8a48803dada333e9ea0029a6",
	"common/math/linearspace3.h:117-124", "Apache-2.0", "C++ (SSE intrinsics)", "float (Vec3fa)",
	"the SSE4.2 kernel: dpps dots, rsqrtss estimate (this CPU's bits) and emath.h:129-151's Newton step, no FMA" };
static const onb_provenance P_NORI = { "github.com/wjakob/nori", "092f581b8664cb7f6b7e73fb5b1e3de24365ea91",
	"src/common.cpp:248-257", "none stated since 50ba652 (2021; GPL-3.0 before)", "C++ (Eigen)", "float (Vector3f)",
	"source-level IEEE (CMakeLists.txt sets no -ffast-math or -ffp-contract; x86-64 baseline: no FMA); Frame(n) = coordinateSystem(n, s, t), include/nori/frame.h:36-38" };
static const onb_provenance P_OSL_ORTHO = { "github.com/AcademySoftwareFoundation/OpenShadingLanguage", "ad63273a0b0fb4d46c2d2e34bf2323f6cb69c3aa",
	"src/testrender/raytracer.h:39-46", "BSD-3-Clause", "C++ (Imath)", "float (Vec3 = Imath::Vec3<Float>, Float = float)",
	"source-level IEEE (compiler.cmake adds -ffp-contract=off with -mfma); Imath Vec3::normalize/length/lengthTiny and cross at Imath d0a0b115 src/Imath/ImathVec.h:1746-1749, 1892-1960; the OptiX build not modelled" };
static const onb_provenance P_OSPRAY = { "github.com/ospray/rkcommon", "f1641061fd910939b2f686d09b9a55c61719f594",
	"rkcommon/math/LinearSpace.ih:188-195", "Apache-2.0", "ISPC", "float (vec3f)",
	"source-level IEEE (the ISPC sse4 target without fast-math); normalize vec.ih:498-501 (v * (1.f/sqrt(dot(v,v)))), dot :423-426, cross :449-456; OSPRay's ISPC_FAST_MATH (contract, reassoc, nsz, arcp) and the FMA targets' fusion not modelled; used by OSPRay f2a61c2e modules/cpu/render/Material.ih" };
static const onb_provenance P_OSL_GABOR = { "github.com/AcademySoftwareFoundation/OpenShadingLanguage", "ad63273a0b0fb4d46c2d2e34bf2323f6cb69c3aa",
	"src/liboslnoise/gabornoise.h:208-220", "BSD-3-Clause", "C++ (Imath)", "float (Vec3 = Imath::Vec3<Float>, Float = float)",
	"source-level IEEE (compiler.cmake adds -ffp-contract=off with -mfma); Imath Vec3::normalize/length/lengthTiny and cross at Imath d0a0b115 src/Imath/ImathVec.h:1746-1749, 1892-1960; the frame (t, b, n) of gabornoise.cpp:239-242" };
static const onb_provenance P_CAULDRON2 = { "github.com/GPUOpen-LibrariesAndSDKs/FidelityFX-SDK", "f4c1da8e92f3fe563b5c28c44e6267ce6b6b8eb2",
	"Kits/Cauldron2/dx12/framework/shaders/raytracingcommon.hlsl:130-140", "MIT", "HLSL", "float",
	"IEEE (source level: normalize(v) = v / sqrt(dot(v, v)), no mad contraction; GPU arithmetic is issue 42's); the same lines at d7531ae4 (SDK 1.0) framework/cauldron/framework/inc/shaders/raytracingcommon.hlsl:130-140; called by MapToCone (:142-)" };
static const onb_provenance P_THREEJS = { "github.com/mrdoob/three.js", "afbc335b0a2c60f11033227544a227b821dd7fa3",
	"src/nodes/pmrem/PMREMUtils.js:355-357", "MIT", "GLSL (three.js TSL node shader, emitted as GLSL or WGSL)", "float",
	"IEEE (source level: normalize(v) = v / sqrt(dot(v, v)), no contraction; GPU arithmetic is issue 42's); ggxConvolution, the PMREM GGX prefilter of PMREMGenerator (WebGPU renderer)" };
static const onb_provenance P_JOLT_ARM64 = { "github.com/jrouwe/JoltPhysics", "3b47ec390cb9b933769183eff599f72195c5873c",
	"Jolt/Math/Vec3.inl:1119-1159", "MIT", "C++17 (NEON)", "float",
	"the non-SSE path (Vec3.inl:1147-1157, JPH_CROSS_PLATFORM_DETERMINISTIC off) and NEON Cross (865-871); Build/CMakeLists.txt:263-272 gives non-x86 -ffp-contract=on, which fuses nothing here (aarch64-linux-gnu-gcc 12 -O2 under qemu-aarch64: these bits)" };
static const onb_provenance P_LUXCORE = { "github.com/LuxCoreRender/LuxCore", "d624e0445924c766c32fd9a08df56d3264cbd33f",
	"include/luxrays/core/geometry/vector.h:169-177", "Apache-2.0", "C++", "float",
	"IEEE, the CPU path (the OpenCL twin's -cl-fast-relaxed-math not modelled)" };

static const onb_method onb__table[] = {
	{ "naive", "naive", SRC_L1 " naive, rsqrt = (float)(1.0/sqrt(x))",
	  SING_NAIVE, THR_NAIVE, +1, 0, NAN, ONB__NORM_LIBM, ONB__PTRS(naive), NULL },
	{ "naive_invsqrt", "naive", SRC_L1 " naive + Listing 3 InvSqrt (0x5f3759df, 1 Newton step)",
	  SING_NAIVE, THR_NAIVE, +1, ONB_APPROX_NORM, NAN, ONB__NORM_INVSQRT, ONB__PTRS(naive_invsqrt), NULL },
	{ "naive_rsqrt", "naive", SRC_L1 " naive + Listing 3 SSE_rsqrt (rsqrtss)",
	  SING_NAIVE, THR_NAIVE, +1, ONB_APPROX_NORM | ONB__HW, NAN, ONB__NORM_RSQRT, ONB__PTRS(naive_rsqrt), NULL },
	{ "naive_rsqrt_nr", "naive", SRC_L1 " naive + Listing 3 SSE_rsqrt_1N (rsqrtss + 1 Newton step)",
	  SING_NAIVE, THR_NAIVE, +1, ONB_APPROX_NORM | ONB__HW, NAN, ONB__NORM_RSQRT_NR, ONB__PTRS(naive_rsqrt_nr), NULL },
	{ "naive_nonorm", "naive", SRC_L1 " naive, no normalization (Table 1)",
	  SING_NAIVE, THR_NAIVE, +1, ONB_APPROX_NORM, NAN, ONB__NORM_NONE, ONB__PTRS(naive_nonorm), NULL },
	{ "hughes_moeller", "hughes_moeller", SRC_HM ", rsqrt = (float)(1.0/sqrt(x))",
	  "none", THR_HM, +1, 0, NAN, ONB__NORM_LIBM, ONB__PTRS(hughes_moeller), NULL },
	{ "hughes_moeller_invsqrt", "hughes_moeller", SRC_HM " + Listing 3 InvSqrt",
	  "none", THR_HM, +1, ONB_APPROX_NORM, NAN, ONB__NORM_INVSQRT, ONB__PTRS(hughes_moeller_invsqrt), NULL },
	{ "hughes_moeller_rsqrt", "hughes_moeller", SRC_HM " + Listing 3 SSE_rsqrt",
	  "none", THR_HM, +1, ONB_APPROX_NORM | ONB__HW, NAN, ONB__NORM_RSQRT, ONB__PTRS(hughes_moeller_rsqrt), NULL },
	{ "hughes_moeller_rsqrt_nr", "hughes_moeller", SRC_HM " + Listing 3 SSE_rsqrt_1N",
	  "none", THR_HM, +1, ONB_APPROX_NORM | ONB__HW, NAN, ONB__NORM_RSQRT_NR, ONB__PTRS(hughes_moeller_rsqrt_nr), NULL },
	{ "hughes_moeller_nonorm", "hughes_moeller", SRC_HM ", no normalization (Table 1)",
	  "none", THR_HM, +1, ONB_APPROX_NORM, NAN, ONB__NORM_NONE, ONB__PTRS(hughes_moeller_nonorm), NULL },
	{ "frisvad", "frisvad", "Frisvad 2012, JGT 16(3), Listing 2 (t = -0.9999999)",
	  "none exactly; error ~ eps/(1+n.z) just above t (O(1) in float)", "n.z < -0.9999999",
	  +1, 0, ONB_FRISVAD_T, 0, ONB__PTRS(frisvad), NULL },
	{ "frisvad_max", "frisvad", "Max 2017, JCGT 6(1): Frisvad Listing 2 with t = -0.99998796",
	  "none exactly; error ~ eps/(1+n.z) just above t", "n.z < -0.99998796",
	  +1, 0, ONB_FRISVAD_MAX_T, 0, ONB__PTRS(frisvad_max), NULL },
	{ "duff", "duff", "Duff et al. 2017, JCGT 6(1), Listing 2 (revisedONB, branch on n.z < 0)",
	  "none", "n.z < 0 (-0 takes the upper branch)", +1, 0, NAN, 0, ONB__PTRS(duff), NULL },
	{ "duff_branchless", "duff_branchless", "Duff et al. 2017, JCGT 6(1), Listing 3 (branchlessONB; pbrt-v4 bit for bit)",
	  "none", "signbit(n.z) (-0 takes the lower branch)", +1, 0, NAN, 0, ONB__PTRS(duff_branchless), NULL },
	{ "stark", "stark", "Stark 2009, JGT 14(1): branch-free perpendicular as published (zm = 1^(xm & ym)), then 1/sqrt normalize and cross",
	  "none", "|n.x| = |n.y|, |n.x| = |n.z|, |n.y| = |n.z|", +1, 0, NAN, 0, ONB__PTRS(stark), NULL },
	{ "stark_fixed", "stark_fixed", "Stark 2009 with Hill 2011's fix zm = 1^(xm | ym) (axis of the smallest |component|)",
	  "none", "|n.x| = |n.y|, |n.x| = |n.z|, |n.y| = |n.z|", +1, 0, NAN, 0, ONB__PTRS(stark_fixed), NULL },
	{ "pbrt_v3", "pbrt_v3", "pbrt-v3 CoordinateSystem (src/core/geometry.h)",
	  "none", "|n.x| > |n.y|", +1, 0, NAN, 0, ONB__PTRS(pbrt_v3), NULL },
	{ "rtow", "rtow", "Shirley, Ray Tracing: The Rest of Your Life, onb::build_from_w",
	  "n = 0 only (normalizes its input)", "|n.x| > 0.9", -1, ONB_NORMALIZES_N, NAN, 0, ONB__PTRS(rtow), NULL },
	{ "tangent_cross_z", "tangent_cross_z", "sydneyzh blog, Vector transformation using projection between ONBs, get_onb",
	  "n = +z and n = -z (0/0 = NaN); float n.x^2+n.y^2 underflow", "none", -1, 0, NAN, 0, ONB__PTRS(tangent_cross_z), NULL },
	/* Engines' shipped code, each read at the commit of its provenance. */
	{ "q2rtx", "frisvad", "Quake II RTX construct_ONB_frisvad: Frisvad Listing 2 with t = -0.999805696f",
	  "none exactly; error ~ eps/(1+n.z) just above t, and a 1.1-degree tilt below it", "n.z < -0.999805696f",
	  +1, 0, (double)-0.999805696f, 0, ONB__PTRS(q2rtx), &P_Q2RTX },
	{ "filament", "filament", "Filament TangentSpaceMesh frisvadKernel: Frisvad Listing 2 rotated to y-up, t = -1 + FLT_EPSILON",
	  "none exactly; error ~ eps/(1+n.y) just above t (O(1) in float)", "n.y < -1 + FLT_EPSILON",
	  +1, 0, (double)(-0x1.fffffcp-1f), 0, ONB__PTRS(filament), &P_FILAMENT },
	{ "filament_hm", "filament_hm", "Filament TangentSpaceMesh hughesMollerMethod: t = (-y, x, 0) if abs(x) > abs(z) + FLT_EPSILON else (0, -z, y), normalized; b = n x t",
	  "none", "|n.x| = |n.z| + FLT_EPSILON", +1, 0, NAN, 0, ONB__PTRS(filament_hm), &P_FILAMENT_HM },
	{ "capsaicin", "capsaicin", "AMD Capsaicin GetOrthoVectors: b1 = (0, -z, y)/len if abs(z) > 0 else (y, -x, 0)/len, b2 = n x b1",
	  "none exactly; z*z + y*y underflows near +-x with n.z != 0 (NaN at (1, 0, 1e-25) in float)", "n.z = +-0",
	  +1, 0, NAN, 0, ONB__PTRS(capsaicin), &P_CAPSAICIN },
	{ "capsaicin_fixed", "capsaicin", "onbstudy, not shipped: Capsaicin GetOrthoVectors with sel = abs(z) > abs(x) (the length squared >= 1/2)",
	  "none", "|n.z| = |n.x|", +1, 0, NAN, ONB__WILD_FIXED, ONB__PTRS(capsaicin_fixed), NULL },
	{ "unity", "unity", "Unity SRP core GetLocalFrame: Reynolds' form of Duff's basis turned by 180 degrees, sz = FastSign(z), x*(y*a) grouping",
	  "none", "n.z < 0 (FastSign: -0 takes +1)", +1, 0, NAN, 0, ONB__PTRS(unity), &P_UNITY },
	{ "willems", "willems", "Sascha Willems' Vulkan pbribl importanceSample_GGX: up = z if abs(z) < 0.999 else x, b1 = normalize(cross(up, n)), b2 = normalize(cross(n, b1))",
	  "none", "|n.z| = 0.999", +1, 0, NAN, 0, ONB__PTRS(willems), &P_WILLEMS },
	{ "gltf_viewer", "gltf_viewer", "Khronos glTF-Sample-Viewer generateTBN: up = y, or +-z where 1 - abs(n.y) <= 1e-7; b1 = normalize(cross(up, n)), b2 = cross(n, b1)",
	  "none", "1 - |n.y| = 1e-7", +1, 0, NAN, 0, ONB__PTRS(gltf_viewer), &P_GLTF_VIEWER },
	{ "rtao", "rtao", "DirectX-Graphics-Samples RTAO GetRandomRayDirection: b2 = normalize(cross(n, 0.3 n + (-0.72, 0.56, -0.34))), b1 = cross(b2, n)",
	  "n parallel to (-0.72, 0.56, -0.34): cross = 0 exactly, O(1) defect near it", "none", +1, 0, NAN, 0, ONB__PTRS(rtao), &P_RTAO },
	{ "rtao_fixed", "rtao", "onbstudy, not shipped: RTAO with (0.56, 0.72, 0) in place of (-0.72, 0.56, -0.34) where abs(dot(n, that)) > 0.875",
	  "none", "|n . (-0.72, 0.56, -0.34)| = 0.875", +1, 0, NAN, ONB__WILD_FIXED, ONB__PTRS(rtao_fixed), NULL },
	{ "mitsuba3", "duff_branchless", "Mitsuba 3 coordinate_system: Duff Listing 3 through Dr.Jit, b2.y = fmadd(y, y*a, s) unfused",
	  "none", "signbit(n.z) (-0 takes the lower branch)", +1, 0, NAN, ONB__EVAL_MITSUBA3, ONB__PTRS(mitsuba3), &P_MITSUBA3 },
	{ "cycles_cross111", "cycles_cross111", "Blender Cycles make_orthonormals: b1 = normalize((1,1,1) x n), b2 = n x b1",
	  "none", "n.x = n.y = n.z (then (-1,1,1) x n)", +1, 0, NAN, 0, ONB__PTRS(cycles_cross111), &P_CYCLES },
	{ "cycles_cross111_avx2", "cycles_cross111", "Blender Cycles make_orthonormals as its AVX2 kernel runs it: b2 = n x b1 through _mm_fmsub_ps",
	  "none", "n.x = n.y = n.z (then (-1,1,1) x n)", +1, 0, NAN, ONB__EVAL_FMSUB, ONB__PTRS(cycles_cross111_avx2), &P_CYCLES_AVX2 },
	{ "embree", "embree", "Embree frame(N): the longer of (0,z,-y), (-z,0,x), normalized by rsqrtss + Newton; b2 = normalize(n x b1)",
	  "none", "z^2 + y^2 > z^2 + x^2 (rounded)", +1, ONB_APPROX_NORM | ONB__HW, NAN, 0, ONB__PTRS(embree), &P_EMBREE },
	{ "luxcore", "luxcore", "LuxCoreRender CoordinateSystem: b2 = (-y, x, 0)/len, b1 = n x b2; (1,0,0) when len < 1e-5",
	  "none; within 1e-5 of +-z b2 = (1,0,0) is off-orthogonal by |n.x| (by design)", "sqrt(n.x^2 + n.y^2) < 1e-5",
	  -1, 0, NAN, 0, ONB__PTRS(luxcore), &P_LUXCORE },
	{ "nori", "nori", "Nori coordinateSystem (Mitsuba 0.6's is the same): c = (z, 0, -x) or (0, z, -y) times 1/len, b1 = c x n, b2 = c",
	  "none", "|n.x| > |n.y|", +1, 0, NAN, 0, ONB__PTRS(nori), &P_NORI },
	{ "osl_ortho", "osl_ortho", "OpenShadingLanguage testrender ortho: b1 = (z, 0, -x) if abs(x) > .01f else (0, -z, y), Imath-normalized; b2 = n x b1",
	  "none", "|n.x| > .01f", +1, 0, NAN, 0, ONB__PTRS(osl_ortho), &P_OSL_ORTHO },
	{ "ospray", "ospray", "OSPRay (rkcommon ISPC) frame(N): b1 = (0, z, -y) if abs(x) < abs(y) else (-z, 0, x), times 1/sqrt(dot); b2 = cross(N, b1)",
	  "none", "|n.x| < |n.y|", +1, 0, NAN, 0, ONB__PTRS(ospray), &P_OSPRAY },
	{ "osl_gabornoise", "osl_gabornoise", "OpenShadingLanguage gabornoise make_orthonormals: v = n Imath-normalized; b1 = (0, v.z, -v.y) if abs(v.x) < 0.9f else (-v.z, 0, v.x), Imath-normalized; b2 = v x b1",
	  "none", "|unit(n).x| < 0.9f", +1, 0, NAN, 0, ONB__PTRS(osl_gabornoise), &P_OSL_GABOR },
	{ "cauldron2", "cauldron2", "FidelityFX Cauldron2 CreateTangentVectors: up = z if abs(z) < 0.99999f else x, b1 = normalize(cross(up, n)), b2 = cross(n, b1)",
	  "none", "|n.z| = 0.99999f", +1, 0, NAN, 0, ONB__PTRS(cauldron2), &P_CAULDRON2 },
	{ "threejs", "threejs", "three.js PMREM ggxConvolution (TSL): up = z if abs(z) < 0.999 else x, b1 = normalize(cross(up, n)), b2 = cross(n, b1)",
	  "none", "|n.z| = 0.999f", +1, 0, NAN, 0, ONB__PTRS(threejs), &P_THREEJS },
	{ "q2rtx_fixed", "q2rtx_fixed", "this project's fix of q2rtx (and nvpro): Frisvad's formula for n.z >= 0, Duff's lower branch turned a quarter, (b2, -b1), below",
	  "none", "n.z < 0", +1, 0, NAN, 0, ONB__PTRS(q2rtx_fixed), NULL },
	{ "jolt_arm64", "jolt", "Jolt Physics, as jolt, in its non-x86 build: the scalar perpendicular negates with -x (x = +0 gives -0), NEON cross, nothing fused",
	  "none", "x*x > y*y (the rounded squares)", +1, 0, NAN, ONB__WILD_SCALAR, ONB__PTRS(jolt_arm64), &P_JOLT_ARM64 },
	/* Engines' shipped code ("in the wild"): physics engines, geometry and
	   math libraries, read at the commits their provenance names; the
	   double variants of float-only sources are the same code in double. */
	{ "jolt", "jolt", "Jolt Physics Vec3::GetNormalizedPerpendicular (SSE path) + contact tangents b2 = n.Cross(b1)",
	  "none", "x*x > y*y (the rounded squares)", +1, 0, NAN, 0, ONB__PTRS(jolt), &P_JOLT },
	{ "jolt_fma", "jolt", "Jolt Physics, as jolt, in its default x86 build (-mfma -ffp-contract=fast: the cross product fused)",
	  "none", "x*x > y*y (the rounded squares)", +1, 0, NAN, ONB__WILD_FMA, ONB__PTRS(jolt_fma), &P_JOLT_FMA },
	{ "bullet", "bullet", "Bullet Physics btPlaneSpace1 (ODE's dPlaneSpace is the same, bit for bit)",
	  "none", "|n.z| > SIMDSQRT12 (1/sqrt 2 in the format)", +1, 0, NAN, 0, ONB__PTRS(bullet), &P_BULLET },
	{ "mujoco", "mujoco", "MuJoCo mju_makeFrame, a contact's frame (y-axis undefined)",
	  "none (n = 0 gives the x-axis as n)", "|n.y| < 1/2 after normalizing n", +1, ONB_NORMALIZES_N, NAN, 0, ONB__PTRS(mujoco), &P_MUJOCO },
	{ "eigen", "eigen", "Eigen MatrixBase::unitOrthogonal (size 3; normalizes); completed: b2 = n.cross(b1)",
	  "none", "|n.x|, |n.y| <= p |n.z| (p = 1e-5 float, 1e-12 double)", +1, 0, NAN, 0, ONB__PTRS(eigen), &P_EIGEN },
	{ "physx", "physx", "NVIDIA PhysX PxComputeBasisVectors",
	  "none (b1 = (1,0,0) is off by |n.x| <= 0.0141 where |n.y| > 0.9999f)", "|n.y| <= 0.9999f", +1, 0, NAN, 0, ONB__PTRS(physx), &P_PHYSX },
	{ "rp3d", "rp3d", "ReactPhysics3D Vector3::getOneUnitOrthogonalVector, b2 = normal.cross(b1)",
	  "none", "the smallest |n_i| (ties to the later axis)", +1, 0, NAN, 0, ONB__PTRS(rp3d), &P_RP3D },
	{ "open3d", "open3d", "Open3D PlaneDetector::ConstructOrthogonalBasis (Eigen)",
	  "n parallel to (0,1,1): b1 = b2 = 0", "|(0,1,1) - n|^2 > 1e-3 (always on the unit sphere)", +1, 0, NAN, 0, ONB__PTRS(open3d), &P_OPEN3D },
	{ "raylib", "raylib", "raylib Vector3Perpendicular; completed: b1 = Vector3Normalize(p), b2 = Vector3CrossProduct(n, b1)",
	  "none", "the smallest |n_i| (ties to the earlier axis)", +1, 0, NAN, 0, ONB__PTRS(raylib), &P_RAYLIB },
	{ "godot", "godot", "Godot Vector3::get_any_perpendicular (normalizes); completed: b2 = n.cross(b1)",
	  "none exactly; float: b1 = b2 = 0 where |n.x| > |n.z| and n.x^2 + n.z^2 underflows (|n.y| ~ 1)",
	  "|n.x| <= |n.y| and |n.x| <= |n.z| (RIGHT), else UP", +1, 0, NAN, 0, ONB__PTRS(godot), &P_GODOT },
	{ "directxmath", "directxmath", "DirectXMath XMVector3Orthogonal; completed: b1 = XMVector3Normalize(p), b2 = XMVector3Cross(n, b1)",
	  "none", "(n.z < 0) == (n.y < 0): p = (y + z, -x, -x), else (y - z, -x, x)", +1, 0, NAN, 0, ONB__PTRS(directxmath), &P_DIRECTXMATH },
	{ "ogre", "ogre", "Ogre Vector3::perpendicular (Hocevar's vector, normalizes); completed: b2 = n.crossProduct(b1)",
	  "none", "|n.x| > |n.z|: (-y, x, 0), else (0, -z, y)", +1, 0, NAN, 0, ONB__PTRS(ogre), &P_OGRE },
	{ "bx", "bx", "bgfx bx::calcTangentFrame: T = pbrt-v3's vector on |n.x| > |n.z|, rcpSafe(sqrt), B = cross(n, T)",
	  "none exactly; where |n.x| > |n.z| and n.x^2 + n.z^2 < FLT_MIN (|n.y| ~ 1) sqrt flushes to 0 and |T| ~ |n.x| 2^126",
	  "|n.x| > |n.z|", +1, 0, NAN, 0, ONB__PTRS(bx), &P_BX },
	{ "blender", "blender", "Blender BLI ortho_basis_v3v3_v3: b1 = (y, -x, 0)/sqrt(x^2 + y^2), b2 = n x b1; (+-1, 0, 0), (0, 1, 0) when x^2 + y^2 <= FLT_EPSILON",
	  "none; within sqrt(FLT_EPSILON) of +-z b1 = (+-1, 0, 0) is off-orthogonal by |n.x| <= 3.45e-4 (by design)",
	  "n.x^2 + n.y^2 > FLT_EPSILON (2^-23)", +1, 0, NAN, 0, ONB__PTRS(blender), &P_BLENDER },
	{ "box3d", "box3d", "Box3D b3Perp (x < -0.5 or 0.5 < x: (y, -x, 0), else (0, z, -y); b3Normalize) and the contact solver's tangent2 = b3Cross(b1, n)",
	  "none", "n.x < -0.5 or 0.5 < n.x", -1, 0, NAN, 0, ONB__PTRS(box3d), &P_BOX3D },
	{ "appleseed", "appleseed", "appleseed Basis3<T>::build(normal): u = Hughes-Moller's perpendicular (smallest |n_i| zeroed), normalized; v = cross(u, n); (b1, b2) = (u, v)",
	  "none", "|n.x| < |n.y| ? (|n.x| < |n.z| ? x : z) : (|n.y| < |n.z| ? y : z) (ties to z, then y)", -1, 0, NAN, 0, ONB__PTRS(appleseed), &P_APPLESEED },
	{ "babylon", "babylon", "Babylon.js Vector3.getNormalToRef (theta = acos(y/r) +- PI/2, phi = atan2(z, x), JavaScript double, V8's fdlibm); completed: b1 = normalize(), b2 = Vector3.CrossToRef(n, b1)",
	  "none (finite on the unit sphere; at +-y atan2(0, 0) = 0 gives b1 = (1, 6.1e-17, 0)); near +-y acos(y/r) loses the angle (|b1.n| up to ~1e-8 in double)",
	  "acos(y/r) > PI/2 (theta - PI/2), else theta + PI/2: b1 flips at y = 0", +1, 0, NAN, 0, ONB__PTRS(babylon), &P_BABYLON },
	{ "godot_fixed", "godot", "onbstudy, not shipped: Godot get_any_perpendicular with BACK (0,0,1) where |n.z| < |n.y| is the smallest",
	  "none", "|n.x| <= |n.y|, |n.x| <= |n.z| (RIGHT); |n.y| <= |n.z| (UP); else BACK", +1, 0, NAN, ONB__WILD_FIXED, ONB__PTRS(godot_fixed), NULL },
	{ "bx_fixed", "bx", "onbstudy, not shipped: bx::calcTangentFrame with pbrt-v3's branch |n.x| > |n.y|",
	  "none", "|n.x| > |n.y|", +1, 0, NAN, ONB__WILD_FIXED, ONB__PTRS(bx_fixed), NULL },
	/* This project's fixes of three of them, not shipped code: one change each
	   to the engine's lines, keeping its frame at +-x, +-y, +-z. */
	{ "physx_fixed", "physx", "onbstudy, not shipped: PhysX PxComputeBasisVectors with right = up.cross(dir) in the |y| > 0.9999f branch",
	  "none", "|n.y| <= 0.9999f", +1, 0, NAN, ONB__WILD_FIXED, ONB__PTRS(physx_fixed), NULL },
	{ "open3d_fixed", "open3d", "onbstudy, not shipped: Open3D ConstructOrthogonalBasis with the guard against +-(0,1,1)/sqrt 2",
	  "none", "|d - n|^2 > 1e-3 and |d + n|^2 > 1e-3, d = (0,1,1)/sqrt 2", +1, 0, NAN, ONB__WILD_FIXED, ONB__PTRS(open3d_fixed), NULL },
	{ "filament_fixed", "filament", "onbstudy, not shipped: Filament frisvadKernel with Duff et al.'s branch on the sign of n.y (lower formula turned to keep the -y frame)",
	  "none", "n.y < 0 (-0 takes the upper branch)", +1, 0, NAN, ONB__WILD_FIXED, ONB__PTRS(filament_fixed), NULL },
	{ "luxcore_fixed", "luxcore", "onbstudy, not shipped: LuxCoreRender CoordinateSystem with v3 = Normalize((1 - x*x, -x*y, -x*z)) in the len < 1e-5 branch",
	  "none", "sqrt(n.x^2 + n.y^2) < 1e-5", -1, 0, NAN, ONB__WILD_FIXED, ONB__PTRS(luxcore_fixed), NULL },
	/* This project's own methods, float only: Duff's formula at
	   the accuracy floor.  Their MPFR reference is duff_branchless's. */
	{ "duff_wide", "duff_branchless", "onbstudy (issue 16), not published: Duff et al. 2017 Listing 3 on float input, evaluated in double, rounded once",
	  "none", "signbit(n.z) (-0 takes the lower branch)", +1, ONB_FLOAT_ONLY, NAN, ONB__EVAL_WIDE, ONB__PTRS_F(duff_wide), NULL },
	{ "duff_comp", "duff_branchless", "onbstudy (issue 16), not published: Duff et al. 2017 Listing 3 in float, fma-compensated products and sums",
	  "none", "signbit(n.z) (-0 takes the lower branch)", +1, ONB_FLOAT_ONLY, NAN, ONB__EVAL_COMP, ONB__PTRS_F(duff_comp), NULL },
};

/* One row for every method of ONB_METHOD_LIST and ONB_FLOAT_METHOD_LIST
   (include/libonb/onb.h): a list entry without a row stops the build here (a
   negative array size); tests/test_parts.c checks the rows' names. */
#define ONB__ONE(m) + 1
typedef char onb__one_row_per_listed_method[
	sizeof onb__table / sizeof onb__table[0] == 0 ONB_METHOD_LIST(ONB__ONE) ONB_FLOAT_METHOD_LIST(ONB__ONE) ? 1 : -1];
#undef ONB__ONE

/* Aliases: engines' code that is an existing method bit for bit, in the
   precisions named.  Each row's independent transliteration (tests/indep_wild.h)
   is compared with its target, bit for bit, by tests/test_indep.c on the
   same inputs as the methods (10^6 uniform, poles, every threshold +-8 ulps,
   signed zeros, subnormals, the axes).  The notes under each row say why
   the arithmetic agrees; docs/wild.md has the rest. */
static const onb_alias onb__aliases[] = {
	/* dxPlaneSpace: Bullet's btPlaneSpace1 operation for operation (both descend from the same code) */
	{ "ode", "bullet", "float and double", "ODE dPlaneSpace (dxPlaneSpace)", "",
	  { "github.com/odedevs/ode", "624b1c174f41f8f52a92478e929c7e3ff50fb062", "ode/src/odemath.cpp:224-251",
	    "BSD-3-Clause or LGPL-2.1+", "C++ (C style)", "dReal: double (CMake default), float (autotools default)",
	    "source-level IEEE" } },
	/* copysign(1, z) as Listing 3; Sqr(x) = x*x then times sign: exact for sign = +-1 */
	{ "pbrt_v4", "duff_branchless", "float and double", "pbrt-v4 CoordinateSystem (Vector3 and Normal3 overloads)", "",
	  { "github.com/mmp/pbrt-v4", "5f7a606806a4ac7b939131ded9d7a30ebd02416e", "src/pbrt/util/vecmath.h:1006-1022",
	    "Apache-2.0", "C++", "Float: float, double with PBRT_FLOAT_AS_DOUBLE",
	    "CPU, no contraction (clang >= 14 gets -ffp-contract=off; the x86-64 baseline has no FMA); nvcc's --use_fast_math build not modelled" } },
	/* Frisvad Listing 2 with Max's threshold, term for term */
	{ "nvpro", "frisvad_max", "float", "nvpro_core nvvkhl orthonormalBasis (GLSL and C++)",
	  "float only: the float literal -0.99998796F widened is not frisvad_max's double threshold",
	  { "github.com/nvpro-samples/nvpro_core", "ba24b73e3a918adfe6ca932a6bf749a1d874d9b0", "nvvkhl/shaders/func.h:102-114",
	    "Apache-2.0", "GLSL and C++ (glm)", "float", "IEEE, the C++ path (a GLSL driver may contract into fma: not modelled)" } },
	/* signf(z) = z < 0 ? -1 : 1 picks Listing 2's branch; Listing 3's arithmetic equals Listing 2's up to exact sign flips */
	{ "cycles_duff", "duff", "float", "Blender Cycles make_orthonormals, the Duff copy (May-Oct 2023, reverted by cb18628fd)", "",
	  { "github.com/blender/cycles", "9056d818a18b5f148f1d8f1e987b6ce14d0cfffb", "src/util/math.h:569-579",
	    "Apache-2.0", "C++", "float",
	    "IEEE as the SSE kernels run it; the AVX2 kernel (-mfma, GCC's default contraction) may fuse, and -fno-signed-zeros may drop zero signs: not modelled" } },
	/* sign = z >= 0 ? 1 : -1: Listing 2's branch except for NaN z */
	{ "falcor", "duff", "float", "Falcor branchlessONB (MathHelpers.slang and MathHelpers.h)",
	  "NaN z excepted: z >= 0 is false for NaN, so Falcor takes the lower branch and b1.z = +x where duff gives -x",
	  { "github.com/NVIDIAGameWorks/Falcor", "eb540f6748774680ce0039aaf3ac9279266ec521", "Source/Falcor/Utils/Math/MathHelpers.slang:559-567",
	    "BSD-3-Clause", "Slang and C++", "float", "IEEE (source level; the host copy MathHelpers.h:62-70 is the same)" } },
	/* sign = z >= 0.0f ? 1.0f : -1.0f, Listing 3's body term for term: Falcor's function, so Listing 2's branch except for NaN z */
	{ "rtxdi", "duff", "float", "RTXDI branchlessONB (shaders/HelperFunctions.hlsli)",
	  "NaN z excepted: z >= 0 is false for NaN, so RTXDI takes the lower branch and b1.z = +x where duff gives -x",
	  { "github.com/NVIDIAGameWorks/RTXDI", "4a21ce6593e830987f2c1d5db179b3df18cf0225", "shaders/HelperFunctions.hlsli:143-150",
	    "LicenseRef-NVIDIA-RTX-SDKs", "HLSL", "float", "IEEE (source level; DXC/SPIR-V may contract into mad: not modelled)" } },
	/* GLSL sign(0) = 0, so sign(sign(z) + 0.5) = +1 for +-0: Listing 2's branch */
	{ "pasvulkan", "duff", "float", "PasVulkan getTangentSpaceBasisFromNormal, s = sign(sign(n.z) + 0.5)", "",
	  { "github.com/BeRo1985/pasvulkan", "bc6681f3198632210c4382464c40a9ab163d1bc7", "src/assets/shaders/scene3d/tangentspacebasis.glsl:4-11",
	    "Zlib", "GLSL", "float", "IEEE; sign(NaN) read as 0 (GLSL leaves it undefined); a driver may contract into fma: not modelled" } },
	/* Duff et al. Listing 3 term for term in float: copysignf(1.0f, z), -1 / (sign + z) (the int literal
	   converted), products left to right; b1 = u, b2 = v (the frame's first two columns) */
	{ "osl_testrender", "duff_branchless", "float", "OpenShadingLanguage testrender TangentFrame::from_normal (sampling.h)", "",
	  { "github.com/AcademySoftwareFoundation/OpenShadingLanguage", "ad63273a0b0fb4d46c2d2e34bf2323f6cb69c3aa", "src/testrender/sampling.h:17-26",
	    "BSD-3-Clause", "C++", "float (Vec3 = Imath::Vec3<Float>, Float = float)",
	    "source-level IEEE (src/cmake/compiler.cmake adds -ffp-contract=off with -mfma; the OptiX/CUDA build (-ffast-math) not modelled)" } },
	/* TangentFrame(n) since dd587677 (2018): Duff et al. Listing 3 term for term in float; b1 = tangent, b2 = bitangent */
	{ "tungsten", "duff_branchless", "float", "Tungsten TangentFrame(const Vec3f &n) (Duff et al. 2017)", "",
	  { "github.com/tunabrain/tungsten", "88ea02044dbaf20472a8173b6752460b50c096d8", "src/core/math/TangentFrame.hpp:22-31",
	    "Zlib", "C++", "float (Vec3f)", "source-level IEEE; CMakeLists.txt adds Vc's architecture flags (-mfma on FMA hosts) and no -ffp-contract, so a GCC build there may fuse sign*x*x*a + 1: not modelled" } },
	/* Mitsuba 0.6's coordinateSystem is Nori's text (Nori descends from it), its cross product TVector3's */
	{ "mitsuba06", "nori", "float and double", "Mitsuba 0.6 coordinateSystem (Frame(n) = (s, t, n))", "",
	  { "github.com/mitsuba-renderer/mitsuba", "10af06f365886c1b6dd8818e0a3841078a62f283", "src/libcore/util.cpp:592-601",
	    "GPL-3.0-only", "C++", "Float: float (SINGLE_PRECISION, the shipped configs), double with DOUBLE_PRECISION",
	    "source-level IEEE; the shipped SCons configs (build/config-linux-gcc.py) add -funsafe-math-optimizations (signed zeros and reassociation not guaranteed): not modelled" } },
	/* Cycles' arm64 kernel (sse2neon): dp_ps as FADDP pairs = the SSE4.2 sum order, vsqrtq/vdivq correctly rounded,
	   msub = vfmaq_f32(vnegq_f32(c), a, b) = the AVX2 kernel's _mm_fmsub_ps */
	{ "cycles_neon", "cycles_cross111_avx2", "float", "Blender Cycles make_orthonormals, the arm64 (NEON, sse2neon) kernel", "",
	  { "github.com/blender/cycles", "97dbe6f57cdf4ede2d2b75ebdda507c8712edb7a", "src/util/math_float3.h:724-750",
	    "Apache-2.0", "C++ (SSE code through sse2neon)", "float",
	    "arm64: optimization.h:30-44 (__KERNEL_NEON__ with __KERNEL_SSE42__), msub math_float4.h:253-266 (vfmaq_f32); -ffp-contract=on fuses nothing more; -fno-signed-zeros not modelled" } },
};

const onb_alias *onb_aliases(size_t *count)
{
	if (count)
		*count = sizeof onb__aliases / sizeof onb__aliases[0];
	return onb__aliases;
}

const onb_alias *onb_find_alias(const char *name)
{
	size_t i;
	if (!name)
		return NULL;
	for (i = 0; i < sizeof onb__aliases / sizeof onb__aliases[0]; i++)
		if (strcmp(onb__aliases[i].name, name) == 0)
			return &onb__aliases[i];
	return NULL;
}

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
