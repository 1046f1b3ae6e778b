/*
 * willems.glsl - docs/wild.md's row `willems` on the driver (onbstudy-gpu
 * wild; src/gpu/wild.comp runs it, gpu_wild.c compares it with the row's
 * C method).
 *
 * Sascha Willems' Vulkan samples, github.com/SaschaWillems/Vulkan
 * 9c8e787f96af0ea3a22791d8f70edb96246efe6c,
 * shaders/glsl/pbribl/prefilterenvmap.frag:48-54 (importanceSample_GGX);
 * GLSL 450, MIT ("Copyright (c) 2016 Sascha Willems").  The source's own
 * three lines of the tangent space, unchanged; the world direction
 * tangentX*H.x + tangentY*H.y + normal*H.z makes b1 = tangentX, b2 =
 * tangentY.  normalize() is the driver's, as in the sample.
 */
void wild_basis(vec3 normal, out vec3 b1, out vec3 b2)
{
	// Tangent space
	vec3 up = abs(normal.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
	vec3 tangentX = normalize(cross(up, normal));
	vec3 tangentY = normalize(cross(normal, tangentX));
	b1 = tangentX;
	b2 = tangentY;
}
