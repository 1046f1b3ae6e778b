/*
 * nvpro.glsl - docs/wild.md's row `nvpro` in its own lines on the driver
 * (onbstudy-gpu wild; src/gpu/wild.comp runs it, gpu_wild.c compares it
 * with the row's C method).  Licence of the quoted lines: Apache-2.0; a few
 * lines, quoted for study (docs/gpu.md).
 */
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

void wild_basis(vec3 n, out vec3 b1, out vec3 b2)
{
	orthonormalBasis(n, b1, b2);
}
