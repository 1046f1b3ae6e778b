/*
 * threejs.glsl - docs/wild.md's row `threejs` on the driver (onbstudy-gpu
 * wild; src/gpu/wild.comp runs it, gpu_wild.c compares it with the row's
 * C method).
 *
 * three.js, github.com/mrdoob/three.js
 * afbc335b0a2c60f11033227544a227b821dd7fa3,
 * src/nodes/pmrem/PMREMUtils.js:355-357 (ggxConvolution), MIT.  A TSL
 * node shader; our GLSL transliteration of the GLSL that TSL emits for
 * these three lines: select(c, a, b) -> c ? a : b, lessThan -> <, and
 * TSL's abs, cross and normalize are GLSL's.  The sample direction
 * tangent * H.x + bitangent * H.y + N * H.z makes b1 = tangent,
 * b2 = bitangent.
 */
void wild_basis(vec3 N, out vec3 b1, out vec3 b2)
{
	vec3 up = abs(N.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
	vec3 tangent = normalize(cross(up, N));
	vec3 bitangent = cross(N, tangent);
	b1 = tangent;
	b2 = bitangent;
}
