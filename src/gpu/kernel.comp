#version 450
/*
 * kernel.comp - the GLSL kernel of onbstudy-gpu: the method of
 * include/libonb/onb.glsl that specialization constant 0 names
 * (methods.inc) on every input n, its six outputs written as bits.
 * Kernel 99 is deliberately broken (duff_branchless with GLSL's sign()
 * for copysign: at n.z = +-0 it divides by 0): tests/gpu.sh shows the
 * harness's bit comparison and envelope check catching it.
 */
#extension GL_GOOGLE_include_directive : require
#include "libonb/onb.glsl"

layout(local_size_x = 64) in;
layout(constant_id = 0) const int METHOD = 0;
layout(std430, binding = 0) readonly buffer In { uint v[]; } inp;
layout(std430, binding = 1) writeonly buffer Out { uint v[]; } outp;

void broken_duff_sign(vec3 n, ONB_PRECISE out vec3 b1, ONB_PRECISE out vec3 b2)
{
	precise float sg = sign(n.z);   /* 0 at n.z = +-0: the bug */
	precise float a = -1.0 / (sg + n.z);
	ONB_PRECISE float b = n.x * n.y * a;
	b1 = vec3(1.0 + sg * n.x * n.x * a, sg * b, -sg * n.x);
	b2 = vec3(b, sg + n.y * n.y * a, -n.y);
}

void main()
{
	uint i = gl_GlobalInvocationID.x;
	if (3u * i + 2u >= uint(inp.v.length()))
		return;
	vec3 n = uintBitsToFloat(uvec3(inp.v[3u * i], inp.v[3u * i + 1u], inp.v[3u * i + 2u]));
	vec3 b1 = vec3(0.0), b2 = vec3(0.0);
	switch (METHOD) {
#define ONB_GPU_METHOD(id, m, twin) case id: onb_##m(n, b1, b2); break;
#ifdef ONB_FLOAT64
#define ONB_GPU_METHOD64(id, m, twin) ONB_GPU_METHOD(id, m, twin)
#define ONB_GPU_METHOD64S(id, m, twin) ONB_GPU_METHOD(id, m, twin)
#else
#define ONB_GPU_METHOD64(id, m, twin)
#define ONB_GPU_METHOD64S(id, m, twin)
#endif
#include "gpu/methods.inc"
	case 99: broken_duff_sign(n, b1, b2); break;
	default: break;
	}
	uvec3 o1 = floatBitsToUint(b1), o2 = floatBitsToUint(b2);
	outp.v[6u * i] = o1.x; outp.v[6u * i + 1u] = o1.y; outp.v[6u * i + 2u] = o1.z;
	outp.v[6u * i + 3u] = o2.x; outp.v[6u * i + 4u] = o2.y; outp.v[6u * i + 5u] = o2.z;
}
