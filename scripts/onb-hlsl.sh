#!/bin/sh
# onb-hlsl.sh - write include/libonb/onb.hlsl from include/libonb/onb.glsl:
# the same kernels, token for token, in HLSL's names (float3, asfloat,
# asuint, mad for fma, the l suffix for double literals).  The two files
# perform the same arithmetic by construction; onbstudy-gpu compare runs
# both on lavapipe (tests/gpu.sh), and tests/gpu.sh fails when onb.hlsl
# is not this script's output (run `sh scripts/onb-hlsl.sh` after editing
# onb.glsl).
#   sh scripts/onb-hlsl.sh [IN [OUT]]
set -eu
in=${1:-include/libonb/onb.glsl}
out=${2:-include/libonb/onb.hlsl}
tmp=$out.tmp.$$
trap 'rm -f "$tmp"' EXIT
{
	printf '%s\n' '/* libonb/onb.hlsl - GENERATED from include/libonb/onb.glsl by scripts/onb-hlsl.sh: do not edit.'
	printf '%s\n' '   HLSL (compiled for Vulkan through glslang'"'"'s HLSL front end: glslangValidator -D -V -e main).'
	printf '%s\n' '   Names: vec3 -> float3, dvec3 -> double3, uintBitsToFloat -> asfloat, floatBitsToUint -> asuint,'
	printf '%s\n' '   fma -> mad (neither need be fused on Vulkan), 1.0lf -> 1.0l.  The documentation below is onb.glsl'"'"'s. */'
	printf '%s\n' '#ifndef ONB_HLSL' '#define ONB_HLSL 1 /* onb.glsl'"'"'s GLSL-only parts left out */' '#endif'
	sed -e 's/\bdvec3\b/double3/g' -e 's/\bvec3\b/float3/g' \
	    -e 's/\buintBitsToFloat\b/asfloat/g' -e 's/\bfloatBitsToUint\b/asuint/g' \
	    -e 's/\bfma(/mad(/g' -e 's/\([0-9]\)lf\b/\1l/g' \
	    -e 's/LIBONB_ONB_GLSL/LIBONB_ONB_HLSL/g' "$in"
} > "$tmp"
mv "$tmp" "$out"
trap - EXIT
