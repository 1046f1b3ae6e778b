/*
 * rtao.glsl - docs/wild.md's row `rtao` on the driver (onbstudy-gpu wild;
 * src/gpu/wild.comp runs it, gpu_wild.c compares it with the row's C
 * method).
 *
 * DirectX-Graphics-Samples, github.com/microsoft/DirectX-Graphics-Samples
 * 357ade6ec6ff0d9dcadc48f35c7a28e37c0cdf7a,
 * Samples/Desktop/D3D12Raytracing/src/D3D12RaytracingRealTimeDenoisedAmbientOcclusion/RTAO/Shaders/RayGen.hlsli:19-25
 * (GetRandomRayDirection); HLSL, MIT.  Our GLSL transliteration of its
 * frame, statement for statement: float3 -> vec3; HLSL's cross and
 * normalize are GLSL's (the same definitions).  The ray sample.x*u +
 * sample.y*v + sample.z*w makes b1 = u, b2 = v.
 */
void wild_basis(vec3 surfaceNormal, out vec3 b1, out vec3 b2)
{
	vec3 u, v, w;
	w = surfaceNormal;

	// Get a vector that's not parallel to w.
	vec3 right = 0.3f * w + vec3(-0.72f, 0.56f, -0.34f);
	v = normalize(cross(w, right));
	u = cross(v, w);
	b1 = u;
	b2 = v;
}
