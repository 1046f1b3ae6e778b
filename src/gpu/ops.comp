#version 450
/*
 * ops.comp - one GLSL operation per kernel (specialization constant 0),
 * applied to every (a, b, c) of the input: how the driver rounds each
 * operation the methods use, compared in gpu_ops.c with the correctly
 * rounded result.  Operands and results travel as bits (uint), so no load
 * or store can change them.  The list is gpu_ops.c's ops[].
 */
#ifdef ONB_PRESERVE  /* SignedZeroInfNanPreserve: ops_preserve.spv */
#extension GL_EXT_spirv_intrinsics : require
spirv_execution_mode(extensions = ["SPV_KHR_float_controls"], capabilities = [4466], 4461, 32);
#endif
layout(local_size_x = 64) in;
layout(constant_id = 0) const int OP = 0;
layout(std430, binding = 0) readonly buffer In { uint v[]; } inp;
layout(std430, binding = 1) writeonly buffer Out { uint v[]; } outp;

void main()
{
	uint i = gl_GlobalInvocationID.x;
	if (3u * i + 2u >= uint(inp.v.length()))
		return;
	float a = uintBitsToFloat(inp.v[3u * i]);
	float b = uintBitsToFloat(inp.v[3u * i + 1u]);
	float c = uintBitsToFloat(inp.v[3u * i + 2u]);
	precise float r;
	if (OP == 9) {  /* not precise: the driver may fuse a*b + c */
		outp.v[i] = floatBitsToUint(a * b + c);
		return;
	}
	switch (OP) {
	case 0:  r = a + b; break;
	case 1:  r = a * b; break;
	case 2:  r = a / b; break;
	case 3:  r = 1.0 / a; break;
	case 4:  r = sqrt(a); break;
	case 5:  r = inversesqrt(a); break;
	case 6:  r = 1.0 / sqrt(a); break;
	case 7:  r = fma(a, b, c); break;
	case 8:  r = a * b + c; break;           /* precise: two roundings */
	case 10: r = sign(a); break;
	case 11: r = a - b; break;
	case 12: r = abs(a); break;
	case 13: r = -a; break;
	case 14: r = 0.0 - a; break;
	case 15: r = a * 0.0; break;
	case 16: r = a + 0.0; break;
	default: r = 0.0; break;
	}
	outp.v[i] = floatBitsToUint(r);
}
