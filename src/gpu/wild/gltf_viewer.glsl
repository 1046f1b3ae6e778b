/*
 * gltf_viewer.glsl - docs/wild.md's row `gltf_viewer` on the driver
 * (onbstudy-gpu wild; src/gpu/wild.comp runs it, gpu_wild.c compares it
 * with the row's C method).
 *
 * Khronos glTF-Sample-Viewer, github.com/KhronosGroup/glTF-Sample-Viewer
 * b3a7e6680032ab858036e98792c90f9664963053,
 * source/shaders/ibl_filtering.frag:91-114 (generateTBN); GLSL ES 3, MIT
 * ("Copyright (c) 2016-2017 Mohamad Moneimne and Contributors").  The
 * function's lines unchanged but its comments; the file's `precision
 * mediump float;` is not repeated here (it would apply to the harness
 * too): the row is the float reading.  mat3(tangent, bitangent, normal)
 * has the columns b1 = tangent, b2 = bitangent.
 */
mat3 generateTBN(vec3 normal)
{
    vec3 bitangent = vec3(0.0, 1.0, 0.0);

    float NdotUp = dot(normal, vec3(0.0, 1.0, 0.0));
    float epsilon = 0.0000001;
    if (1.0 - abs(NdotUp) <= epsilon)
    {
        if (NdotUp > 0.0)
        {
            bitangent = vec3(0.0, 0.0, 1.0);
        }
        else
        {
            bitangent = vec3(0.0, 0.0, -1.0);
        }
    }

    vec3 tangent = normalize(cross(bitangent, normal));
    bitangent = cross(normal, tangent);

    return mat3(tangent, bitangent, normal);
}

void wild_basis(vec3 n, out vec3 b1, out vec3 b2)
{
	mat3 tbn = generateTBN(n);
	b1 = tbn[0];
	b2 = tbn[1];
}
