/*
 * cauldron2.glsl - docs/wild.md's row `cauldron2` on the driver
 * (onbstudy-gpu wild; src/gpu/wild.comp runs it, gpu_wild.c compares it
 * with the row's C method).
 *
 * AMD FidelityFX SDK, github.com/GPUOpen-LibrariesAndSDKs/FidelityFX-SDK
 * f4c1da8e92f3fe563b5c28c44e6267ce6b6b8eb2,
 * Kits/Cauldron2/dx12/framework/shaders/raytracingcommon.hlsl:130-140
 * (CreateTangentVectors); HLSL, MIT.  Our GLSL transliteration of its
 * lines, statement for statement: float3 -> vec3, the float2x3 rows
 * tangents[0], tangents[1] -> b1, b2; HLSL's abs, cross and normalize are
 * GLSL's (the same definitions).  MapToCone's n + uv.x * tangents[0] +
 * uv.y * tangents[1] makes b1 = tangents[0], b2 = tangents[1].
 */
void wild_basis(vec3 normal, out vec3 b1, out vec3 b2)
{
	vec3 up = abs(normal.z) < 0.99999f ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);

	b1 = normalize(cross(up, normal));
	b2 = cross(normal, b1);
}
