/*
 * unity.glsl - docs/wild.md's row `unity` on the driver (onbstudy-gpu
 * wild; src/gpu/wild.comp runs it, gpu_wild.c compares it with the row's
 * C method).  Until the registry holds a row named unity this file is
 * compiled and not run.
 *
 * Unity SRP core, github.com/Unity-Technologies/Graphics
 * 0c658a0ca9e3b0230a21342a0448d1bbedd880ca,
 * Packages/com.unity.render-pipelines.core/ShaderLibrary/CommonLighting.hlsl:451-468
 * (GetLocalFrame) with FastSign/CopySign of Common.hlsl; HLSL under the
 * Unity Companion License, so its lines are not quoted here: this is our
 * GLSL of its arithmetic as docs/wild-specs/unity.md states it, operation
 * for operation, in float (`real` = float on desktop): sz = FastSign(z) =
 * z >= 0 ? 1 : -1 (CopySign(1, z) with ignoreNegZero: -0 takes +1, NaN
 * -1); a = 1/(sz + z); ya = y*a; b = x*ya; c = x*sz; localX =
 * ((c*x)*a - 1, sz*b, c), localY = (b, y*ya - sz, y); b1 = localX,
 * b2 = localY.
 */
float unity_FastSign(float s)
{
	return s >= 0.0 ? abs(1.0) : -abs(1.0);
}

void unity_GetLocalFrame(vec3 localZ, out vec3 localX, out vec3 localY)
{
	float x = localZ.x, y = localZ.y, z = localZ.z;
	float sz = unity_FastSign(z);
	float a = 1.0 / (sz + z);
	float ya = y * a;
	float b = x * ya;
	float c = x * sz;
	localX = vec3(c * x * a - 1.0, sz * b, c);
	localY = vec3(b, y * ya - sz, y);
}

void wild_basis(vec3 n, out vec3 b1, out vec3 b2)
{
	unity_GetLocalFrame(n, b1, b2);
}
