/*
 * falcor.glsl - docs/wild.md's row `falcor` in its own lines on the driver
 * (onbstudy-gpu wild; src/gpu/wild.comp runs it, gpu_wild.c compares it
 * with the row's C method).  Licence of the quoted lines: BSD-3-Clause; a few
 * lines, quoted for study (docs/gpu.md).
 */
/* Falcor, github.com/NVIDIAGameWorks/Falcor eb540f6748774680ce0039aaf3ac9279266ec521,
   Source/Falcor/Utils/Math/MathHelpers.slang:559-567 (Slang).  Our GLSL
   reading: float3 -> vec3, and Slang's `const float` locals as GLSL
   `const`-less locals (GLSL's const needs a constant expression); the
   int literals 1 and -1 of the ternary convert to float as in Slang; the
   local named sign hides GLSL's sign(), as it hides Slang's. */
void branchlessONB(const vec3 n, out vec3 b1, out vec3 b2)
{
    // can't use just `sign` because we need 0 to go into -1/+1, but not 0
    float sign = (n.z >= 0 ? 1 : -1);
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    b1 = vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    b2 = vec3(b, sign + n.y * n.y * a, -n.y);
}

void wild_basis(vec3 n, out vec3 b1, out vec3 b2)
{
	branchlessONB(n, b1, b2);
}
