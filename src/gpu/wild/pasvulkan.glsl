/*
 * pasvulkan.glsl - docs/wild.md's row `pasvulkan` in its own lines on the driver
 * (onbstudy-gpu wild; src/gpu/wild.comp runs it, gpu_wild.c compares it
 * with the row's C method).  Licence of the quoted lines: Zlib; a few
 * lines, quoted for study (docs/gpu.md).
 */
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

void wild_basis(vec3 n, out vec3 b1, out vec3 b2)
{
	getTangentSpaceBasisFromNormal(n, b1, b2);
}
