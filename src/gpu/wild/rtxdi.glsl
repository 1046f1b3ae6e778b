/*
 * rtxdi.glsl - docs/wild.md's row `rtxdi` on the driver (onbstudy-gpu
 * wild; src/gpu/wild.comp runs it, gpu_wild.c compares it with the row's
 * C method, duff).
 *
 * NVIDIA RTXDI, github.com/NVIDIAGameWorks/RTXDI
 * 4a21ce6593e830987f2c1d5db179b3df18cf0225, shaders/HelperFunctions.hlsli:143-150
 * (branchlessONB); HLSL, the NVIDIA RTX SDKs licence (the file reserves
 * all rights), so its lines are not quoted here: this is our GLSL
 * transliteration of its arithmetic as docs/wild-specs/rtxdi.md states
 * it, operation for operation: sign = n.z >= 0.0f ? 1.0f : -1.0f (-0
 * takes +1, NaN -1); a = -1/(sign + n.z); b = (x*y)*a; b1 = (1 +
 * ((sign*x)*x)*a, sign*b, (-sign)*x), b2 = (b, sign + (y*y)*a, -y), the
 * products grouped left to right as HLSL groups them.  It is Falcor's
 * function (falcor.glsl) operation for operation; a local named sign
 * hides GLSL's sign(), as in the source.
 */
void rtxdi_branchlessONB(in vec3 n, out vec3 b1, out vec3 b2)
{
	float sign = n.z >= 0.0f ? 1.0f : -1.0f;
	float a = -1.0f / (sign + n.z);
	float b = n.x * n.y * a;
	b1 = vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
	b2 = vec3(b, sign + n.y * n.y * a, -n.y);
}

void wild_basis(vec3 n, out vec3 b1, out vec3 b2)
{
	rtxdi_branchlessONB(n, b1, b2);
}
