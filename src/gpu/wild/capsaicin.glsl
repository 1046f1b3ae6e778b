/*
 * capsaicin.glsl - docs/wild.md's row `capsaicin` on the driver
 * (onbstudy-gpu wild; src/gpu/wild.comp runs it, gpu_wild.c compares it
 * with the row's C method).
 *
 * AMD Capsaicin, github.com/GPUOpen-LibrariesAndSDKs/Capsaicin
 * 5a3bf2a2b9b736bf660a6f4da17a6959ab4fc836, src/core/src/math/sampling.hlsl:118-126
 * (GetOrthoVectors) with squared() of math.hlsl:63-66; HLSL, MIT.  Our
 * GLSL transliteration of its arithmetic (docs/wild-specs/capsaicin.md),
 * statement for statement: float3 -> vec3; the int 0 of `abs(n.z) > 0`
 * written 0.0 (HLSL converts it to float); the swizzles and the select
 * of a vector by a bool as in HLSL; HLSL's cross(a, b) = a.yzx*b.zxy -
 * a.zxy*b.yzx is GLSL's cross (the same products, the same differences).
 */
float squared(float x)
{
	return x * x;
}

void GetOrthoVectors(in vec3 n, out vec3 b1, out vec3 b2)
{
	bool sel = abs(n.z) > 0.0;
	vec3 p2 = sel ? n : n.zyx;
	float k = 1.0f / sqrt(squared(p2.z) + squared(n.y));
	b1 = vec3(0.0f, -p2.z * k, n.y * k);
	b1 = sel ? b1 : b1.zyx;
	b2 = cross(n, b1);
}

void wild_basis(vec3 n, out vec3 b1, out vec3 b2)
{
	GetOrthoVectors(n, b1, b2);
}
