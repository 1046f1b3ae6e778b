#version 450
/*
 * wild.comp - the shader engines of docs/wild.md in their own lines, at
 * the commits docs/wild.md cites, run on the driver by onbstudy-gpu wild
 * and compared with their C rows (gpu_wild.c).  Each function body is
 * the engine's, character for character, except where a comment says.
 * Specialization constant 0: 1 q2rtx, 2 nvpro, 3 pasvulkan, 4 falcor.
 *
 * Licences of the quoted lines: Q2RTX GPL-2.0-or-later, nvpro_core
 * Apache-2.0, PasVulkan Zlib, Falcor BSD-3-Clause; a few lines each,
 * quoted for study (docs/gpu.md).
 */
layout(local_size_x = 64) in;
layout(constant_id = 0) const int ENGINE = 0;
layout(std430, binding = 0) readonly buffer In { uint v[]; } inp;
layout(std430, binding = 1) writeonly buffer Out { uint v[]; } outp;

/* Quake II RTX, github.com/NVIDIA/Q2RTX f2526e9a165949f66e91e82f0d63aa7bb2567b4d,
   src/refresh/vkpt/shader/utils.glsl:241-257 */
mat3
construct_ONB_frisvad(vec3 normal)
{
    precise mat3 ret;
    ret[1] = normal;
    if(normal.z < -0.999805696f) {
        ret[0] = vec3(0.0f, -1.0f, 0.0f);
        ret[2] = vec3(-1.0f, 0.0f, 0.0f);
    }
    else {
        precise float a = 1.0f / (1.0f + normal.z);
        precise float b = -normal.x * normal.y * a;
        ret[0] = vec3(1.0f - normal.x * normal.x * a, b, -normal.x);
        ret[2] = vec3(b, 1.0f - normal.y * normal.y * a, -normal.y);
    }
    return ret;
}

/* nvpro_core, github.com/nvpro-samples/nvpro_core ba24b73e3a918adfe6ca932a6bf749a1d874d9b0,
   nvvkhl/shaders/func.h:102-114, with its GLSL definitions of the file's
   head: OUT_TYPE(T) = out T, inline defined away */
#define OUT_TYPE(T) out T
#define inline
inline void orthonormalBasis(vec3 normal, OUT_TYPE(vec3) tangent, OUT_TYPE(vec3) bitangent)
{
  if(normal.z < -0.99998796F)  // Handle the singularity
  {
    tangent   = vec3(0.0F, -1.0F, 0.0F);
    bitangent = vec3(-1.0F, 0.0F, 0.0F);
    return;
  }
  float a   = 1.0F / (1.0F + normal.z);
  float b   = -normal.x * normal.y * a;
  tangent   = vec3(1.0F - normal.x * normal.x * a, b, -normal.x);
  bitangent = vec3(b, 1.0f - normal.y * normal.y * a, -normal.y);
}
#undef inline

/* PasVulkan, github.com/BeRo1985/pasvulkan bc6681f3198632210c4382464c40a9ab163d1bc7,
   src/assets/shaders/scene3d/tangentspacebasis.glsl:4-11 */
void getTangentSpaceBasisFromNormal(in vec3 n, out vec3 t, out vec3 b){
  // https://graphics.pixar.com/library/OrthonormalB/paper.pdf
  float s = sign(sign(n.z) + 0.5),
        a = -1.0 / (s + n.z),
        c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);  
}

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

void main()
{
	uint i = gl_GlobalInvocationID.x;
	if (3u * i + 2u >= uint(inp.v.length()))
		return;
	vec3 n = uintBitsToFloat(uvec3(inp.v[3u * i], inp.v[3u * i + 1u], inp.v[3u * i + 2u]));
	vec3 b1 = vec3(0.0), b2 = vec3(0.0);
	if (ENGINE == 1) {
		mat3 r = construct_ONB_frisvad(n);   /* columns (b1, n, b2) */
		b1 = r[0];
		b2 = r[2];
	} else if (ENGINE == 2) {
		orthonormalBasis(n, b1, b2);
	} else if (ENGINE == 3) {
		getTangentSpaceBasisFromNormal(n, b1, b2);
	} else if (ENGINE == 4) {
		branchlessONB(n, b1, b2);
	}
	uvec3 o1 = floatBitsToUint(b1), o2 = floatBitsToUint(b2);
	outp.v[6u * i] = o1.x; outp.v[6u * i + 1u] = o1.y; outp.v[6u * i + 2u] = o1.z;
	outp.v[6u * i + 3u] = o2.x; outp.v[6u * i + 4u] = o2.y; outp.v[6u * i + 5u] = o2.z;
}
