/*
 * q2rtx.glsl - docs/wild.md's row `q2rtx` in its own lines on the driver
 * (onbstudy-gpu wild; src/gpu/wild.comp runs it, gpu_wild.c compares it
 * with the row's C method).  Licence of the quoted lines: GPL-2.0-or-later; a few
 * lines, quoted for study (docs/gpu.md).
 */
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

void wild_basis(vec3 n, out vec3 b1, out vec3 b2)
{
	mat3 r = construct_ONB_frisvad(n);   /* columns (b1, n, b2) */
	b1 = r[0];
	b2 = r[2];
}
