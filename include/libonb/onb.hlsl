/* libonb/onb.hlsl - GENERATED from include/libonb/onb.glsl by scripts/onb-hlsl.sh: do not edit.
   HLSL (compiled for Vulkan through glslang's HLSL front end: glslangValidator -D -V -e main).
   Names: vec3 -> float3, dvec3 -> double3, uintBitsToFloat -> asfloat, floatBitsToUint -> asuint,
   fma -> mad (neither need be fused on Vulkan), 1.0lf -> 1.0l.  The documentation below is onb.glsl's. */
#ifndef ONB_HLSL
#define ONB_HLSL 1 /* onb.glsl's GLSL-only parts left out */
#endif
/*
 * libonb/onb.glsl - orthonormal bases {b1, b2, n} from a unit vector n,
 * for GLSL shaders (Vulkan, #version 450).  libonb's float kernels
 * (include/libonb/onb.h) written in GLSL, operation for operation: the
 * same operations in the same order on the same rounded values, so that
 * on a device that rounds each operation as IEEE binary32 does, every
 * output is the C kernel's bits.  include/libonb/onb.hlsl is this file
 * for HLSL (generated: scripts/onb-hlsl.sh).
 *
 * Checked, not generated: onbstudy-gpu (make gpu; docs/gpu.md, "On a real
 * driver") runs every function below on Mesa's lavapipe over the sweep's
 * input distributions and the extremes, and compares the bits with
 * libonb's C float kernels; tests/gpu.sh fails on any difference that
 * the driver's own rounding (its operations probe) does not explain.
 *
 * Index (float; the C names without the `f`)
 *   onb_naive_invsqrt, onb_naive_nonorm           Frisvad 2012 Listing 1 (+ Listing 3 InvSqrt)
 *   onb_hughes_moeller_invsqrt, _nonorm           Hughes & Moller 1999 (Frisvad's Listing 1)
 *   onb_frisvad, onb_frisvad_max                  Frisvad 2012 Listing 2, Max 2017 threshold
 *   onb_frisvad_threshold(n, t, b1, b2)           Listing 2 with t as a parameter
 *   onb_duff, onb_duff_branchless                 Duff et al. 2017 Listings 2 and 3
 *   onb_stark, onb_stark_fixed                    Stark 2009, Hill 2011's fix
 *   onb_rtow, onb_tangent_cross_z                 RTTROYL onb, blog get_onb
 *   engines: onb_q2rtx, onb_filament, onb_mitsuba3, onb_cycles_cross111,
 *     onb_cycles_cross111_avx2, onb_luxcore, onb_jolt, onb_jolt_fma,
 *     onb_bullet, onb_mujoco, onb_eigen, onb_physx, onb_rp3d, onb_open3d
 *   this project's fixes: onb_physx_fixed, onb_filament_fixed, onb_open3d_fixed
 *   this project, float only: onb_duff_comp (needs a fused fma, below)
 *   with ONB_FLOAT64 defined (the device's shaderFloat64 feature; the
 *   source rounds in double): onb_naive, onb_hughes_moeller (Listing 3's
 *   rsqrt is 1/sqrt in double, rounded once; GLSL only: HLSL has no
 *   double sqrt, and glslang's HLSL front end quietly takes the float
 *   one), onb_pbrt_v3 (its Cross widens to double), onb_duff_wide
 *
 * Left out, and why
 *   - the _rsqrt and _rsqrt_nr variants of naive and hughes_moeller, and
 *     embree: they run x86's rsqrtss, whose bits are the CPU's; GLSL has
 *     no such instruction (inversesqrt is another approximation, 2 ulp in
 *     Vulkan), so a shader cannot compute these methods.
 *   - frisvad_rotate: a rotation of a direction, not a basis.
 *
 * Conventions (as onb.h's; docs/library.md)
 *   - Private helpers are onbp_*: GLSL reserves names with "__".
 *   - Precondition: n is a unit vector as received in float.  Non-unit,
 *     zero and non-finite n give defined, garbage outputs.
 *   - Handedness is det(b1, b2, n) and is each method's in onb.h.
 *   - Each function's comment is the short form of onb.h's, whose comment
 *     above the C kernel of the same name gives the source, the branch
 *     thresholds and the singular set in full; the proven bounds are in
 *     onb.h's table (IEEE) and docs/gpu.md (per arithmetic profile).
 *   - Constants whose bits matter are written as bits
 *     (asfloat(0x...u)): a decimal float literal goes through the
 *     compiler's own decimal conversion.
 *   - No GLSL sign(): sign(0) is 0 in GLSL, while Duff's copysign(1, z) is
 *     +-1 with the sign bit of z (-0 -> -1); onbp_copysign1 keeps the C
 *     semantics with bit operations.
 *
 * precise (SPIR-V NoContraction)
 *   Without `precise`, a Vulkan compiler may fuse a*b + c into one fma
 *   and reassociate (SPIR-V, "NoContraction"), so the bits, and the IEEE
 *   proofs, hold only under `precise`.  This file marks `precise`:
 *     - every value a branch or a sign test reads (the thresholds of
 *       every method, Stark's SIGNBIT differences, the guards of open3d
 *       and mujoco): a contraction there moves the branch off the one the
 *       source decides, and a fused x*y - y*x is not 0;
 *     - Frisvad's and Duff's a = 1/(1 +- n.z) and Duff's sign: the
 *       threshold analyses (Frisvad, Max) and the proofs rest on the one
 *       rounding of 1 +- n.z, and Duff's -1/(sign + n.z) on sign + n.z
 *       being 1 + |n.z| exactly as rounded;
 *     - duff_comp's error-free transformations (each is exact only as
 *       written).
 *   The rest may contract: the `vulkan` and `contract-any` profiles of
 *   `onbstudy certify --arith` bound every such choice.  Define
 *   ONB_PRECISE as `precise` before including this file to make every
 *   operation NoContraction (the `vulkan-precise` reading: each output
 *   then rounds as the C kernel's wherever the device rounds +, -, *, /
 *   and sqrt as IEEE does; lavapipe does, see docs/gpu.md).
 *
 * fma: Vulkan does not require mad() to be fused (it may round twice;
 * lavapipe does).  onb_jolt_fma and onb_cycles_cross111_avx2 are then
 * onb_jolt's and onb_cycles_cross111's bits, and onb_duff_comp loses its
 * compensation: its IEEE bound needs a fused fma.
 */
#ifndef LIBONB_ONB_HLSL
#define LIBONB_ONB_HLSL

#ifndef ONB_PRECISE
#define ONB_PRECISE
#endif

/* copysign(1, z): +1 or -1 with z's sign bit (-0 -> -1, NaN by its bit). */
float onbp_copysign1(float z)
{
	return asfloat((asuint(z) & 0x80000000u) | 0x3f800000u);
}

/* Frisvad 2012 Listing 3 InvSqrt: the bit trick and one Newton step. */
float onbp_invsqrt(float x)
{
	ONB_PRECISE float xhalf = 0.5 * x;
	ONB_PRECISE float y = asfloat(0x5f3759dfu - (asuint(x) >> 1)); /* rsqrt seed */
	ONB_PRECISE float r = y * (1.5 - xhalf * y * y);
	return r;
}

/* naive (Frisvad 2012 Listing 1): b1 = e - n (e.n), e = y-axis when
   n.x > 0.9 else x-axis; b1 *= s(|b1|^2); b2 = n x b1.  Handedness +1.
   Singular: n = -x.  norm: 1 InvSqrt, 4 none (onb.h's ONB__NORM_*), 0
   (ONB_FLOAT64 only) Listing 3's rsqrt, 1/sqrt in double rounded once. */
void onbp_naive(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2, int norm)
{
	ONB_PRECISE float bx, by, bz, d, l2, s;
	if (n.x > asfloat(0x3f666666u) /* 0.9f */) { bx = 0.0; by = 1.0; bz = 0.0; }
	else                                               { bx = 1.0; by = 0.0; bz = 0.0; }
	d = bx * n.x + by * n.y + bz * n.z;
	bx -= n.x * d;
	by -= n.y * d;
	bz -= n.z * d;
	l2 = bx * bx + by * by + bz * bz;
#if defined(ONB_FLOAT64) && !defined(ONB_HLSL)
	if (norm == 0) s = float(1.0l / sqrt(double(l2)));
	else
#endif
	if (norm == 1) s = onbp_invsqrt(l2);
	else s = 1.0;
	bx *= s; by *= s; bz *= s;
	b1 = float3(bx, by, bz);
	b2 = float3(n.y * bz - n.z * by, n.z * bx - n.x * bz, n.x * by - n.y * bx);
}
void onb_naive_invsqrt(float3 n, out float3 b1, out float3 b2) { onbp_naive(n, b1, b2, 1); }
void onb_naive_nonorm (float3 n, out float3 b1, out float3 b2) { onbp_naive(n, b1, b2, 4); }

/* hughes_moeller (Hughes & Moller 1999 as in Frisvad 2012 Listing 1):
   b2 = (-n.y, n.x, 0) if |n.x| > |n.z| else (0, -n.z, n.y); b2 *= s(|b2|^2);
   b1 = b2 x n.  Handedness +1.  No singular unit direction. */
void onbp_hughes_moeller(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2, int norm)
{
	ONB_PRECISE float bx, by, bz, l2, s;
	if (abs(n.x) > abs(n.z)) { bx = -n.y; by = n.x;  bz = 0.0; }
	else                     { bx = 0.0;  by = -n.z; bz = n.y; }
	l2 = bx * bx + by * by + bz * bz;
#if defined(ONB_FLOAT64) && !defined(ONB_HLSL)
	if (norm == 0) s = float(1.0l / sqrt(double(l2)));
	else
#endif
	if (norm == 1) s = onbp_invsqrt(l2);
	else s = 1.0;
	bx *= s; by *= s; bz *= s;
	b2 = float3(bx, by, bz);
	b1 = float3(by * n.z - bz * n.y, bz * n.x - bx * n.z, bx * n.y - by * n.x);
}
void onb_hughes_moeller_invsqrt(float3 n, out float3 b1, out float3 b2) { onbp_hughes_moeller(n, b1, b2, 1); }
void onb_hughes_moeller_nonorm (float3 n, out float3 b1, out float3 b2) { onbp_hughes_moeller(n, b1, b2, 4); }
#if defined(ONB_FLOAT64) && !defined(ONB_HLSL)
void onb_naive         (float3 n, out float3 b1, out float3 b2) { onbp_naive(n, b1, b2, 0); }
void onb_hughes_moeller(float3 n, out float3 b1, out float3 b2) { onbp_hughes_moeller(n, b1, b2, 0); }
#endif

/* frisvad (Frisvad 2012 Listing 2): when n.z < t, b1 = (0, -1, 0),
   b2 = (-1, 0, 0); else a = 1/(1 + n.z), b = -n.x*n.y*a,
   b1 = (1 - n.x*n.x*a, b, -n.x), b2 = (b, 1 - n.y*n.y*a, -n.y).
   Handedness +1.  Loses all precision as n.z -> -1 above t (published). */
void onb_frisvad_threshold(float3 n, float t, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	if (n.z < t) {
		b1 = float3(0.0, -1.0, 0.0);
		b2 = float3(-1.0, 0.0, 0.0);
		return;
	}
	precise float a = 1.0 / (1.0 + n.z);
	ONB_PRECISE float b = -n.x * n.y * a;
	b1 = float3(1.0 - n.x * n.x * a, b, -n.x);
	b2 = float3(b, 1.0 - n.y * n.y * a, -n.y);
}
/* t = -0.9999999f (Frisvad), -0.99998796f (Max 2017), as bits */
void onb_frisvad    (float3 n, out float3 b1, out float3 b2) { onb_frisvad_threshold(n, asfloat(0xbf7ffffeu), b1, b2); }
void onb_frisvad_max(float3 n, out float3 b1, out float3 b2) { onb_frisvad_threshold(n, asfloat(0xbf7fff36u), b1, b2); }

/* duff (Duff et al. 2017 Listing 2): Frisvad's formula for n.z >= 0 (-0
   included), its mirror a = 1/(1 - n.z) below.  Handedness +1.  No
   singular unit direction. */
void onb_duff(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	if (n.z < 0.0) {
		precise float a = 1.0 / (1.0 - n.z);
		ONB_PRECISE float b = n.x * n.y * a;
		b1 = float3(1.0 - n.x * n.x * a, -b, n.x);
		b2 = float3(b, n.y * n.y * a - 1.0, -n.y);
	} else {
		precise float a = 1.0 / (1.0 + n.z);
		ONB_PRECISE float b = -n.x * n.y * a;
		b1 = float3(1.0 - n.x * n.x * a, b, -n.x);
		b2 = float3(b, 1.0 - n.y * n.y * a, -n.y);
	}
}

/* duff_branchless (Duff et al. 2017 Listing 3; pbrt-v4): sign =
   copysign(1, n.z) (not GLSL's sign(): n.z = -0 takes -1, as in C),
   a = -1/(sign + n.z), b = n.x*n.y*a, b1 = (1 + sign*n.x*n.x*a, sign*b,
   -sign*n.x), b2 = (b, sign + n.y*n.y*a, -n.y).  Handedness +1. */
void onb_duff_branchless(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	precise float sg = onbp_copysign1(n.z);
	precise float a = -1.0 / (sg + n.z);
	ONB_PRECISE float b = n.x * n.y * a;
	b1 = float3(1.0 + sg * n.x * n.x * a, sg * b, -sg * n.x);
	b2 = float3(b, sg + n.y * n.y * a, -n.y);
}

/* stark (Stark 2009), stark_fixed (Hill 2011's zm = 1^(xm | ym)):
   p = n x e, e from the SIGNBITs of |x|-|y|, |x|-|z|, |y|-|z|;
   b1 = p / |p| (1/sqrt), b2 = n x b1.  Handedness +1. */
void onbp_stark(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2, bool hill)
{
	precise float ax = abs(n.x), ay = abs(n.y), az = abs(n.z);
	precise float dxy = ax - ay, dxz = ax - az, dyz = ay - az;
	bool xm = (dxy < 0.0) && (dxz < 0.0);
	bool ym = (dyz < 0.0) && !xm;
	bool zm = hill ? !(xm || ym) : !(xm && ym);
	float ex = xm ? 1.0 : 0.0, ey = ym ? 1.0 : 0.0, ez = zm ? 1.0 : 0.0;
	ONB_PRECISE float3 p = float3(n.y * ez - n.z * ey, n.z * ex - n.x * ez, n.x * ey - n.y * ex);
	ONB_PRECISE float s = 1.0 / sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
	p *= s;
	b1 = p;
	b2 = float3(n.y * p.z - n.z * p.y, n.z * p.x - n.x * p.z, n.x * p.y - n.y * p.x);
}
void onb_stark      (float3 n, out float3 b1, out float3 b2) { onbp_stark(n, b1, b2, false); }
void onb_stark_fixed(float3 n, out float3 b1, out float3 b2) { onbp_stark(n, b1, b2, true); }

#ifdef ONB_FLOAT64
/* pbrt_v3 (pbrt-v3 CoordinateSystem): b1 = (-z, 0, x) * (1/sqrt(x^2 +
   z^2)) if |x| > |y| else (0, z, -y) * (1/sqrt(y^2 + z^2)); b2 = n x b1
   in double (pbrt-v3's Cross widens its operands), rounded to float.
   Handedness +1.  Needs ONB_FLOAT64. */
void onb_pbrt_v3(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	ONB_PRECISE float inv;
	ONB_PRECISE float3 u;
	if (abs(n.x) > abs(n.y)) {
		inv = 1.0 / sqrt(n.x * n.x + n.z * n.z);
		u = float3(-n.z * inv, 0.0 * inv, n.x * inv);
	} else {
		inv = 1.0 / sqrt(n.y * n.y + n.z * n.z);
		u = float3(0.0 * inv, n.z * inv, -n.y * inv);
	}
	b1 = u;
	double3 v = double3(n), w = double3(u);
	ONB_PRECISE double3 c = double3(v.y * w.z - v.z * w.y, v.z * w.x - v.x * w.z, v.x * w.y - v.y * w.x);
	b2 = float3(c);
}
#endif

/* rtow (RTTROYL onb::build_from_w): w normalized by 1/sqrt, a = y-axis if
   |w.x| > 0.9 else x-axis, v = unit(w x a), b1 = w x v, b2 = v.
   Handedness -1.  Normalizes its input (the only method that does). */
void onb_rtow(float3 w, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	precise float inv = 1.0 / sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
	precise float3 uw = float3(inv * w.x, inv * w.y, inv * w.z);
	float3 a = abs(uw.x) > asfloat(0x3f666666u) /* 0.9f */ ? float3(0.0, 1.0, 0.0) : float3(1.0, 0.0, 0.0);
	ONB_PRECISE float3 c = float3(uw.y * a.z - uw.z * a.y, uw.z * a.x - uw.x * a.z, uw.x * a.y - uw.y * a.x);
	ONB_PRECISE float il = 1.0 / sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
	ONB_PRECISE float3 v = float3(il * c.x, il * c.y, il * c.z);
	b1 = float3(uw.y * v.z - uw.z * v.y, uw.z * v.x - uw.x * v.z, uw.x * v.y - uw.y * v.x);
	b2 = v;
}

/* tangent_cross_z (blog get_onb): t = (n.x, n.y, n.z + 1), b2 =
   normalize(n x t) with a division by the length, b1 = n x b2.
   Handedness -1.  Singular: n = +-z (0/0). */
void onb_tangent_cross_z(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	ONB_PRECISE float tz = n.z + 1.0;
	ONB_PRECISE float3 c = float3(n.y * tz - n.z * n.y, n.z * n.x - n.x * tz, n.x * n.y - n.y * n.x);
	ONB_PRECISE float l = sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
	c = float3(c.x / l, c.y / l, c.z / l);
	b2 = c;
	b1 = float3(n.y * c.z - n.z * c.y, n.z * c.x - n.x * c.z, n.x * c.y - n.y * c.x);
}

/* q2rtx (Quake II RTX construct_ONB_frisvad): Listing 2 with
   t = -0.999805696f, under `precise` in its source.  Handedness +1. */
void onb_q2rtx(float3 n, out float3 b1, out float3 b2) { onb_frisvad_threshold(n, asfloat(0xbf7ff344u), b1, b2); }

/* filament (Filament frisvadKernel): Listing 2 rotated to y-up, the
   fallback below n.y < -1 + FLT_EPSILON.  Handedness +1. */
void onb_filament(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	if (n.y < asfloat(0xbf7ffffeu) /* -1 + FLT_EPSILON */) {
		b1 = float3(-1.0, 0.0, 0.0);
		b2 = float3(0.0, 0.0, -1.0);
		return;
	}
	precise float va = 1.0 / (1.0 + n.y);
	ONB_PRECISE float vb = -n.z * n.x * va;
	b1 = float3(vb, -n.z, 1.0 - n.z * n.z * va);
	b2 = float3(1.0 - n.x * n.x * va, -n.x, vb);
}

/* filament_fixed (this project): Filament's formula for n.y >= 0, Duff's
   lower-hemisphere formula (turned a quarter) below.  Handedness +1. */
void onb_filament_fixed(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	if (n.y < 0.0) {
		precise float a = 1.0 / (1.0 - n.y);
		ONB_PRECISE float b = n.z * n.x * a;
		b1 = float3(n.x * n.x * a - 1.0, -n.x, b);
		b2 = float3(b, -n.z, -(1.0 - n.z * n.z * a));
		return;
	}
	precise float a = 1.0 / (1.0 + n.y);
	ONB_PRECISE float b = -n.z * n.x * a;
	b1 = float3(b, -n.z, 1.0 - n.z * n.z * a);
	b2 = float3(1.0 - n.x * n.x * a, -n.x, b);
}

/* mitsuba3 (Mitsuba 3 coordinate_system): Duff's Listing 3 with Dr.Jit's
   product order: b1.x = sign*(x*x*a) + 1, b2.y = y*(y*a) + sign.
   Handedness +1. */
void onb_mitsuba3(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	precise float sg = onbp_copysign1(n.z);
	precise float a = -(1.0 / (sg + n.z));
	ONB_PRECISE float b = n.x * n.y * a;
	b1 = float3(sg * (n.x * n.x * a) + 1.0, sg * b, -sg * n.x);
	b2 = float3(b, n.y * (n.y * a) + sg, -n.y);
}

/* cycles_cross111 (Blender Cycles make_orthonormals): a = (1,1,1) x n,
   or (-1,1,1) x n when n.x = n.y = n.z; b1 = a / |a| (three divisions),
   b2 = n x b1.  _avx2: the cross through mad(p, q, -(r s)) (Cycles' AVX2
   msub; on a device whose fma rounds twice, cycles_cross111's bits).
   Handedness +1. */
float3 onbp_cycles111_b1(float3 n)
{
	ONB_PRECISE float3 a;
	if (!(n.x <= n.y && n.x >= n.y && n.x <= n.z && n.x >= n.z)) a = float3(n.z - n.y, n.x - n.z, n.y - n.x);
	else                                                         a = float3(n.z - n.y, n.x + n.z, -n.y - n.x);
	ONB_PRECISE float l = sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
	a = float3(a.x / l, a.y / l, a.z / l);
	return a;
}
void onb_cycles_cross111(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	ONB_PRECISE float3 a = onbp_cycles111_b1(n);
	b1 = a;
	b2 = float3(n.y * a.z - n.z * a.y, n.z * a.x - n.x * a.z, n.x * a.y - n.y * a.x);
}
void onb_cycles_cross111_avx2(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	ONB_PRECISE float3 a = onbp_cycles111_b1(n);
	b1 = a;
	b2 = float3(mad(n.y, a.z, -(n.z * a.y)), mad(n.z, a.x, -(n.x * a.z)), mad(n.x, a.y, -(n.y * a.x)));
}

/* luxcore (LuxCoreRender CoordinateSystem): len = sqrt(x^2 + y^2); when
   len < 1e-5 (a double literal: for a float len the same test as
   len < 0x1.4f8b5ap-17) v = (1, 0, 0), else (-y/len, x/len, 0);
   b1 = n x v, b2 = v.  Handedness -1. */
void onb_luxcore(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	precise float len = sqrt(n.x * n.x + n.y * n.y);
	ONB_PRECISE float3 v;
	if (len < asfloat(0x3727c5adu)) v = float3(1.0, 0.0, 0.0);
	else                                    v = float3(-n.y / len, n.x / len, 0.0);
	b2 = v;
	b1 = float3(n.y * v.z - n.z * v.y, n.z * v.x - n.x * v.z, n.x * v.y - n.y * v.x);
}

/* jolt, jolt_fma (Jolt GetNormalizedPerpendicular, b2 = n x b1): if
   x*x > y*y, b1 = (z, 0, 0 - x) / sqrt(xx + zz), else (0, z, 0 - y) /
   sqrt(yy + zz), lane by lane; _fma fuses the cross as Jolt's x86 build
   (mad(b1[i+2], n[i+1], -(n[i+2]*b1[i+1]))).  Handedness +1. */
float3 onbp_jolt_perp(float3 n)
{
	precise float xx = n.x * n.x, yy = n.y * n.y;
	ONB_PRECISE float zz = n.z * n.z, len;
	ONB_PRECISE float3 p;
	if (xx > yy) { len = sqrt(xx + zz); p = float3(n.z / len, 0.0 / len, (0.0 - n.x) / len); }
	else         { len = sqrt(yy + zz); p = float3(0.0 / len, n.z / len, (0.0 - n.y) / len); }
	return p;
}
void onb_jolt(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	ONB_PRECISE float3 p = onbp_jolt_perp(n);
	b1 = p;
	b2 = float3(n.y * p.z - n.z * p.y, n.z * p.x - n.x * p.z, n.x * p.y - n.y * p.x);
}
void onb_jolt_fma(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	ONB_PRECISE float3 p = onbp_jolt_perp(n);
	b1 = p;
	b2 = float3(mad(p.z, n.y, -(n.z * p.y)), mad(p.x, n.z, -(n.x * p.z)), mad(p.y, n.x, -(n.y * p.x)));
}

/* bullet (Bullet btPlaneSpace1 = ODE dPlaneSpace): if |z| > SIMDSQRT12,
   a = y*y + z*z, k = 1/sqrt(a), b1 = (0, -z*k, y*k), b2 = (a*k, -x*b1.z,
   x*b1.y); else the same about z.  Handedness +1. */
void onb_bullet(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	if (abs(n.z) > asfloat(0x3f3504f3u) /* SIMDSQRT12 */) {
		ONB_PRECISE float a = n.y * n.y + n.z * n.z, k = 1.0 / sqrt(a);
		ONB_PRECISE float3 u = float3(0.0, -n.z * k, n.y * k);
		b1 = u;
		b2 = float3(a * k, -n.x * u.z, n.x * u.y);
	} else {
		ONB_PRECISE float a = n.x * n.x + n.y * n.y, k = 1.0 / sqrt(a);
		ONB_PRECISE float3 u = float3(-n.y * k, n.x * k, 0.0);
		b1 = u;
		b2 = float3(-n.z * u.y, n.z * u.x, a * k);
	}
}

/* mujoco (MuJoCo mju_makeFrame): m = n normalized (s < 1e-15 gives
   (1, 0, 0)), e = y-axis if |m.y| < 1/2 else z-axis, e -= m (m.e),
   normalized the same way; b1 = e, b2 = m x e.  Handedness +1. */
float3 onbp_mj_normalize(float3 v)
{
	precise float s = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
	ONB_PRECISE float3 r;
	if (s < asfloat(0x26901d7du) /* 1e-15f */) {
		r = float3(1.0, 0.0, 0.0);
	} else {
		ONB_PRECISE float inv = 1.0 / s;
		r = float3(v.x * inv, v.y * inv, v.z * inv);
	}
	return r;
}
void onb_mujoco(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	precise float3 m = onbp_mj_normalize(n);
	ONB_PRECISE float3 e = float3(0.0, 0.0, 0.0);
	if (m.y < 0.5 && m.y > -0.5) e.y = 1.0; else e.z = 1.0;
	ONB_PRECISE float d = m.x * e.x + m.y * e.y + m.z * e.z;
	e = float3(e.x - m.x * d, e.y - m.y * d, e.z - m.z * d);
	e = onbp_mj_normalize(e);
	b1 = e;
	b2 = float3(m.y * e.z - m.z * e.y, m.z * e.x - m.x * e.z, m.x * e.y - m.y * e.x);
}

/* eigen (Eigen unitOrthogonal, b2 = n x b1): unless |x| <= |z| 1e-5f and
   |y| <= |z| 1e-5f, r = 1/sqrt(x*x + y*y), b1 = (-y*r, x*r, 0); else
   r = 1/sqrt(y*y + z*z), b1 = (0, -z*r, y*r).  Handedness +1. */
void onb_eigen(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	precise float zp = abs(n.z) * asfloat(0x3727c5acu) /* 1e-5f */;
	ONB_PRECISE float r;
	ONB_PRECISE float3 p;
	if (!(abs(n.x) <= zp) || !(abs(n.y) <= zp)) { r = 1.0 / sqrt(n.x * n.x + n.y * n.y); p = float3(-n.y * r, n.x * r, 0.0); }
	else                                        { r = 1.0 / sqrt(n.y * n.y + n.z * n.z); p = float3(0.0, -n.z * r, n.y * r); }
	b1 = p;
	b2 = float3(n.y * p.z - n.z * p.y, n.z * p.x - n.x * p.z, n.x * p.y - n.y * p.x);
}

/* physx (PhysX PxComputeBasisVectors): if |y| <= 0.9999f, r = (z, 0, -x)
   normalized (if |r| > 0), b2 = (y*r.z, z*r.x - x*r.z, -y*r.x); else
   b1 = (1, 0, 0), b2 = (0, z, -y) normalized: b1.n = x there (the flaw,
   as shipped).  Handedness +1. */
float3 onbp_px_normalize(float3 v)
{
	ONB_PRECISE float m = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
	ONB_PRECISE float3 r = v;
	if (m > 0.0) {
		ONB_PRECISE float f = 1.0 / m;
		r = float3(v.x * f, v.y * f, v.z * f);
	}
	return r;
}
void onb_physx(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	if (abs(n.y) <= asfloat(0x3f7ff972u) /* 0.9999f */) {
		ONB_PRECISE float3 r = onbp_px_normalize(float3(n.z, 0.0, -n.x));
		b1 = r;
		b2 = float3(n.y * r.z, n.z * r.x - n.x * r.z, -n.y * r.x);
	} else {
		b1 = float3(1.0, 0.0, 0.0);
		b2 = onbp_px_normalize(float3(0.0, n.z, -n.y));
	}
}
/* physx_fixed (this project): the fallback's right = up x dir, so b1 is
   perpendicular to n there too.  Handedness +1. */
void onb_physx_fixed(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	if (abs(n.y) <= asfloat(0x3f7ff972u) /* 0.9999f */) {
		onb_physx(n, b1, b2);
		return;
	}
	ONB_PRECISE float3 u = onbp_px_normalize(float3(0.0, n.z, -n.y));
	b1 = float3(u.y * n.z - u.z * n.y, u.z * n.x - u.x * n.z, u.x * n.y - u.y * n.x);
	b2 = u;
}

/* rp3d (ReactPhysics3D getOneUnitOrthogonalVector, b2 = n x b1): k = the
   axis of the smallest |n_i| (ties to the later axis), b1 = e_k x n
   divided by its length lane by lane.  Handedness +1. */
void onb_rp3d(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	float ax = abs(n.x), ay = abs(n.y), az = abs(n.z);
	int k = ax < ay ? (ax < az ? 0 : 2) : (ay < az ? 1 : 2);
	ONB_PRECISE float l;
	ONB_PRECISE float3 p;
	if (k == 0)      { l = sqrt(n.y * n.y + n.z * n.z); p = float3(0.0 / l, -n.z / l, n.y / l); }
	else if (k == 1) { l = sqrt(n.x * n.x + n.z * n.z); p = float3(-n.z / l, 0.0 / l, n.x / l); }
	else             { l = sqrt(n.x * n.x + n.y * n.y); p = float3(-n.y / l, n.x / l, 0.0 / l); }
	b1 = p;
	b2 = float3(n.y * p.z - n.z * p.y, n.z * p.x - n.x * p.z, n.x * p.y - n.y * p.x);
}

/* open3d, open3d_fixed (Open3D ConstructOrthogonalBasis; this project's
   guard against the unit diagonal (0, 1, 1)/sqrt(2) and its antipode):
   p = n x (0,1,1) = (y - z, -x, x) unless n is near the guard's point,
   else n x (1,0,1); b1 = p normalized as Eigen's normalized() (x^2 +
   (y^2 + z^2) for a Vector3f; unchanged if 0), b2 = n x b1 normalized.
   open3d: singular on the line through (0, 1, 1) (b1 = b2 = 0).
   Handedness +1. */
float3 onbp_o3d_normalize(float3 v)
{
	precise float s2 = v.x * v.x + (v.y * v.y + v.z * v.z);
	ONB_PRECISE float3 r = v;
	if (s2 > 0.0) {
		ONB_PRECISE float s = sqrt(s2);
		r = float3(v.x / s, v.y / s, v.z / s);
	}
	return r;
}
void onbp_open3d(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2, bool diag)
{
	bool alt;
	if (diag) {
		float c = asfloat(0x3f3504f3u); /* 1/sqrt(2) rounded */
		precise float3 d = float3(0.0 - n.x, c - n.y, c - n.z), e = float3(0.0 + n.x, c + n.y, c + n.z);
		precise float dd = d.x * d.x + (d.y * d.y + d.z * d.z), ee = e.x * e.x + (e.y * e.y + e.z * e.z);
		alt = !(dd > asfloat(0x3a83126fu) && ee > asfloat(0x3a83126fu)); /* 1e-3f */
	} else {
		precise float3 d = float3(0.0 - n.x, 1.0 - n.y, 1.0 - n.z);
		precise float dd = d.x * d.x + (d.y * d.y + d.z * d.z);
		alt = !(dd > asfloat(0x3a83126fu)); /* 1e-3f */
	}
	ONB_PRECISE float3 p = alt ? float3(n.y, n.z - n.x, -n.y) : float3(n.y - n.z, -n.x, n.x);
	p = onbp_o3d_normalize(p);
	ONB_PRECISE float3 q = float3(n.y * p.z - n.z * p.y, n.z * p.x - n.x * p.z, n.x * p.y - n.y * p.x);
	b1 = p;
	b2 = onbp_o3d_normalize(q);
}
void onb_open3d      (float3 n, out float3 b1, out float3 b2) { onbp_open3d(n, b1, b2, false); }
void onb_open3d_fixed(float3 n, out float3 b1, out float3 b2) { onbp_open3d(n, b1, b2, true); }

/* duff_comp (this project, float): duff_branchless with every rounding
   before the output compensated by error-free transformations (Fast2Sum,
   the division's residual mad(a, h, 1), products split by fma).  All
   `precise`: each transformation is exact only as written.  Its accuracy
   (and its IEEE bound) needs mad() fused, which Vulkan does not promise:
   on a device whose fma rounds twice it is duff_branchless-like at best. */
void onb_duff_comp(float3 n, precise out float3 b1, precise out float3 b2)
{
	float x = n.x, y = n.y, z = n.z;
	precise float s = onbp_copysign1(z);
	precise float h = s + z, hl = (s - h) + z;
	precise float a = -1.0 / h;
	precise float e = mad(a, h, 1.0);
	precise float al = a * (e + a * hl);
	precise float xx = x * x, xxl = mad(x, x, -xx);
	precise float xy = x * y, xyl = mad(x, y, -xy);
	precise float yy = y * y, yyl = mad(y, y, -yy);
	precise float p = xx * a, pl = mad(xx, a, -p) + (xx * al + xxl * a);
	precise float b = xy * a, bl = mad(xy, a, -b) + (xy * al + xyl * a);
	precise float q = yy * a, ql = mad(yy, a, -q) + (yy * al + yyl * a);
	precise float sp = s * p;
	precise float t1 = 1.0 + sp, t1l = (1.0 - t1) + sp;
	precise float t2 = s + q, t2l = (s - t2) + q;
	precise float bb = b + bl;
	b1 = float3(t1 + (t1l + s * pl), s * bb, -s * x);
	b2 = float3(bb, t2 + (t2l + ql), -y);
}

#ifdef ONB_FLOAT64
/* duff_wide (this project, float): duff_branchless's formula in double on
   the widened input, each output rounded once to float.  Needs
   ONB_FLOAT64. */
void onb_duff_wide(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	double x = double(n.x), y = double(n.y), z = double(n.z);
	precise double sg = double(onbp_copysign1(n.z));
	precise double a = -1.0l / (sg + z);
	ONB_PRECISE double b = x * y * a;
	ONB_PRECISE double3 r1 = double3(1.0l + sg * x * x * a, sg * b, -sg * x);
	ONB_PRECISE double3 r2 = double3(b, sg + y * y * a, -y);
	b1 = float3(r1);
	b2 = float3(r2);
}
#endif

#endif /* LIBONB_ONB_HLSL */
