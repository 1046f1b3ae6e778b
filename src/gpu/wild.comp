#version 450
#extension GL_GOOGLE_include_directive : require
/*
 * wild.comp - the harness of `onbstudy-gpu wild`: one shader engine of
 * docs/wild.md in its own lines, src/gpu/wild/ENGINE.glsl, on the
 * driver.  The Makefile compiles it once per engine file, with that file
 * copied to build/gpu/wild/ENGINE/engine.glsl and that folder on the
 * include path, into build/gpu/wild/ENGINE.spv; gpu_wild.c runs every
 * registry row whose language is GLSL, HLSL or Slang from its .spv and
 * compares it with the row's C method.  An engine file defines
 *     void wild_basis(vec3 n, out vec3 b1, out vec3 b2)
 * around the engine's own function (docs/adding-a-method.md, "A shader
 * row on the driver").  With ONB_MEDIUMP defined, every float is
 * `precision mediump float` (SPIR-V RelaxedPrecision): the Makefile builds
 * gltf_viewer so, as its source declares it (build/gpu/relaxed/, run by
 * `onbstudy-gpu half`).
 */
#ifdef ONB_MEDIUMP
precision mediump float;
#endif
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { uint v[]; } inp;
layout(std430, binding = 1) writeonly buffer Out { uint v[]; } outp;

#include "engine.glsl"

void main()
{
	uint i = gl_GlobalInvocationID.x;
	if (3u * i + 2u >= uint(inp.v.length()))
		return;
	vec3 n = uintBitsToFloat(uvec3(inp.v[3u * i], inp.v[3u * i + 1u], inp.v[3u * i + 2u]));
	vec3 b1 = vec3(0.0), b2 = vec3(0.0);
	wild_basis(n, b1, b2);
	uvec3 o1 = floatBitsToUint(b1), o2 = floatBitsToUint(b2);
	outp.v[6u * i] = o1.x; outp.v[6u * i + 1u] = o1.y; outp.v[6u * i + 2u] = o1.z;
	outp.v[6u * i + 3u] = o2.x; outp.v[6u * i + 4u] = o2.y; outp.v[6u * i + 5u] = o2.z;
}
