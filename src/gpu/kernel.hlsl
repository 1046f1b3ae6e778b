/*
 * kernel.hlsl - the HLSL kernel of onbstudy-gpu: kernel.comp for
 * include/libonb/onb.hlsl, compiled by glslang's HLSL front end
 * (glslangValidator -D -V -e main).  Kernel 99: the same deliberately
 * broken duff_branchless (HLSL's sign(), 0 at n.z = +-0).
 */
#include "libonb/onb.hlsl"

[[vk::constant_id(0)]] const int METHOD = 0;
[[vk::binding(0, 0)]] StructuredBuffer<uint> inp;
[[vk::binding(1, 0)]] RWStructuredBuffer<uint> outp;

void broken_duff_sign(float3 n, ONB_PRECISE out float3 b1, ONB_PRECISE out float3 b2)
{
	precise float sg = sign(n.z);   /* 0 at n.z = +-0: the bug */
	precise float a = -1.0 / (sg + n.z);
	ONB_PRECISE float b = n.x * n.y * a;
	b1 = float3(1.0 + sg * n.x * n.x * a, sg * b, -sg * n.x);
	b2 = float3(b, sg + n.y * n.y * a, -n.y);
}

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
	uint count, stride;
	inp.GetDimensions(count, stride);
	uint i = id.x;
	if (3u * i + 2u >= count)
		return;
	float3 n = asfloat(uint3(inp[3u * i], inp[3u * i + 1u], inp[3u * i + 2u]));
	float3 b1 = float3(0.0, 0.0, 0.0), b2 = float3(0.0, 0.0, 0.0);
	switch (METHOD) {
#define ONB_GPU_METHOD(id, m, twin) case id: onb_##m(n, b1, b2); break;
#ifdef ONB_FLOAT64
#define ONB_GPU_METHOD64(id, m, twin) ONB_GPU_METHOD(id, m, twin)
#define ONB_GPU_METHOD64S(id, m, twin)  /* HLSL: no double sqrt */
#else
#define ONB_GPU_METHOD64(id, m, twin)
#define ONB_GPU_METHOD64S(id, m, twin)
#endif
#include "gpu/methods.inc"
	case 99: broken_duff_sign(n, b1, b2); break;
	default: break;
	}
	uint3 o1 = asuint(b1), o2 = asuint(b2);
	outp[6u * i] = o1.x; outp[6u * i + 1u] = o1.y; outp[6u * i + 2u] = o1.z;
	outp[6u * i + 3u] = o2.x; outp[6u * i + 4u] = o2.y; outp[6u * i + 5u] = o2.z;
}
