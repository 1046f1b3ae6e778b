#version 450
/*
 * half.comp - the binary16 kernel of `onbstudy-gpu half`: the method that
 * specialization constant 0 names (half_methods.inc) in explicit
 * binary16 arithmetic (float16_t, GL_EXT_shader_explicit_arithmetic_types_float16;
 * the device's shaderFloat16), on every input n, its six outputs written
 * back as float bits.  Each function is src/lib/half.c's kernel of the
 * same name, operation for operation: every value `precise`
 * (NoContraction), every literal a float16_t (`hf`: an unsuffixed
 * literal would promote the operation to 32 bits), every constant the C
 * kernel's binary16 constant given by its bits (hb), so that on a device
 * that rounds each binary16 operation as IEEE does the outputs are the C
 * half kernels' bits.  Inputs and outputs travel as floats: every
 * binary16 value is a float, and the conversions both ways are exact.
 * Kernel 99 is deliberately broken (duff_branchless with GLSL's sign()
 * for copysign: at n.z = +-0 it divides by 0): tests/gpu.sh shows the bit
 * comparison and the envelope check catching it.  Kernel 98 is frisvad
 * with its a = 1/(1 + n.z) and the products that use it done in 32 bits
 * and rounded once (what a compiler that evaluates half in float and
 * rounds late gives): the bit comparison must catch it.
 */
#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require
#extension GL_GOOGLE_include_directive : require

layout(local_size_x = 64) in;
layout(constant_id = 0) const int METHOD = 0;
layout(std430, binding = 0) readonly buffer In { uint v[]; } inp;
layout(std430, binding = 1) writeonly buffer Out { uint v[]; } outp;

#define H float16_t
#define V f16vec3

/* a binary16 constant from its bits (exact: unpackHalf2x16 widens) */
H hb(uint bits) { return H(unpackHalf2x16(bits).x); }

H hdot(V p, V q) { precise H r = p.x * q.x + p.y * q.y + p.z * q.z; return r; }
V hcross(V p, V q)
{
	precise V r = V(p.y * q.z - p.z * q.y, p.z * q.x - p.x * q.z, p.x * q.y - p.y * q.x);
	return r;
}
/* C's copysign(1, z) on the sign bit (z widened exactly) */
H hsign1(H z) { return (floatBitsToUint(float(z)) & 0x80000000u) != 0u ? -1.0hf : 1.0hf; }
/* onb.h's default normalization: 1/sqrt in double, rounded once */
H hrsq_d(H x) { precise double r = 1.0lf / sqrt(double(x)); return H(r); }
/* Listing 3's InvSqrt: the seed on x widened to float, rounded to binary16, Newton in half */
H hinvsqrt(H x)
{
	precise H y = H(uintBitsToFloat(0x5f3759dfu - (floatBitsToUint(float(x)) >> 1)));
	precise H h = 0.5hf * x;
	precise H r = y * (1.5hf - h * y * y);
	return r;
}
V hnormalize_div(V v) { precise H l = sqrt(hdot(v, v)); precise V r = V(v.x / l, v.y / l, v.z / l); return r; }

/* Frisvad 2012 Listing 2 with threshold t (frisvad, frisvad_max, q2rtx: every t is -1 in binary16) */
void frisvad_t(V n, H t, precise out V b1, precise out V b2)
{
	if (n.z < t) { b1 = V(0.0hf, -1.0hf, 0.0hf); b2 = V(-1.0hf, 0.0hf, 0.0hf); return; }
	precise H a = 1.0hf / (1.0hf + n.z);
	precise H b = -n.x * n.y * a;
	b1 = V(1.0hf - n.x * n.x * a, b, -n.x);
	b2 = V(b, 1.0hf - n.y * n.y * a, -n.y);
}
void duff(V n, precise out V b1, precise out V b2)
{
	if (n.z < 0.0hf) {
		precise H a = 1.0hf / (1.0hf - n.z);
		precise H b = n.x * n.y * a;
		b1 = V(1.0hf - n.x * n.x * a, -b, n.x);
		b2 = V(b, n.y * n.y * a - 1.0hf, -n.y);
	} else {
		precise H a = 1.0hf / (1.0hf + n.z);
		precise H b = -n.x * n.y * a;
		b1 = V(1.0hf - n.x * n.x * a, b, -n.x);
		b2 = V(b, 1.0hf - n.y * n.y * a, -n.y);
	}
}
void duff_branchless(V n, H sg, precise out V b1, precise out V b2)
{
	precise H a = -1.0hf / (sg + n.z);
	precise H b = n.x * n.y * a;
	b1 = V(1.0hf + sg * n.x * n.x * a, sg * b, -sg * n.x);
	b2 = V(b, sg + n.y * n.y * a, -n.y);
}
void mitsuba3(V n, precise out V b1, precise out V b2)
{
	precise H sg = hsign1(n.z);
	precise H a = -(1.0hf / (sg + n.z));
	precise H b = n.x * n.y * a;
	b1 = V(sg * (n.x * n.x * a) + 1.0hf, sg * b, -sg * n.x);
	b2 = V(b, n.y * (n.y * a) + sg, -n.y);
}
/* Hughes & Moller; norm 0: 1/sqrt in double rounded once, 1: InvSqrt, 4: none */
void hughes_moeller(V n, precise out V b1, precise out V b2, int norm)
{
	precise V v;
	if (abs(n.x) > abs(n.z)) v = V(-n.y, n.x, 0.0hf);
	else                     v = V(0.0hf, -n.z, n.y);
	precise H l2 = hdot(v, v);
	precise H s = norm == 0 ? hrsq_d(l2) : norm == 1 ? hinvsqrt(l2) : 1.0hf;
	v = V(v.x * s, v.y * s, v.z * s);
	b2 = v;
	b1 = hcross(v, n);
}
void naive(V n, precise out V b1, precise out V b2)
{
	precise V b = n.x > hb(0x3b33u) /* 0.9 */ ? V(0.0hf, 1.0hf, 0.0hf) : V(1.0hf, 0.0hf, 0.0hf);
	precise H d = hdot(b, n);
	b = V(b.x - n.x * d, b.y - n.y * d, b.z - n.z * d);
	precise H s = hrsq_d(hdot(b, b));
	b1 = V(b.x * s, b.y * s, b.z * s);
	b2 = hcross(n, b1);
}
void stark(V n, precise out V b1, precise out V b2, bool fixed_)
{
	precise H ax = abs(n.x), ay = abs(n.y), az = abs(n.z);
	precise H dxy = ax - ay, dxz = ax - az, dyz = ay - az;
	bool xm = dxy < 0.0hf && dxz < 0.0hf;
	bool ym = dyz < 0.0hf && !xm;
	bool zm = fixed_ ? !(xm || ym) : !(xm && ym);
	V e = V(xm ? 1.0hf : 0.0hf, ym ? 1.0hf : 0.0hf, zm ? 1.0hf : 0.0hf);
	precise V p = hcross(n, e);
	precise H s = 1.0hf / sqrt(hdot(p, p));
	b1 = V(p.x * s, p.y * s, p.z * s);
	b2 = hcross(n, b1);
}
void pbrt_v3(V n, precise out V b1, precise out V b2)
{
	precise H inv;
	if (abs(n.x) > abs(n.y)) {
		inv = 1.0hf / sqrt(n.x * n.x + n.z * n.z);
		b1 = V(-n.z * inv, 0.0hf * inv, n.x * inv);
	} else {
		inv = 1.0hf / sqrt(n.y * n.y + n.z * n.z);
		b1 = V(0.0hf * inv, n.z * inv, -n.y * inv);
	}
	precise dvec3 v = dvec3(n), w = dvec3(b1);
	precise double cx = v.y * w.z - v.z * w.y, cy = v.z * w.x - v.x * w.z, cz = v.x * w.y - v.y * w.x;
	b2 = V(H(cx), H(cy), H(cz));
}
void rtow(V w, precise out V b1, precise out V b2)
{
	precise H inv = 1.0hf / sqrt(hdot(w, w));
	precise V uw = V(inv * w.x, inv * w.y, inv * w.z);
	V a = abs(uw.x) > hb(0x3b33u) /* 0.9 */ ? V(0.0hf, 1.0hf, 0.0hf) : V(1.0hf, 0.0hf, 0.0hf);
	precise V c = hcross(uw, a);
	precise H il = 1.0hf / sqrt(hdot(c, c));
	precise V v = V(il * c.x, il * c.y, il * c.z);
	b1 = hcross(uw, v);
	b2 = v;
}
void tangent_cross_z(V n, precise out V b1, precise out V b2)
{
	precise V t = V(n.x, n.y, n.z + 1.0hf);
	precise V c = hcross(n, t);
	precise H l = sqrt(hdot(c, c));
	c = V(c.x / l, c.y / l, c.z / l);
	b2 = c;
	b1 = hcross(n, c);
}
void capsaicin(V n, precise out V b1, precise out V b2)
{
	if (abs(n.z) > 0.0hf) {
		precise H k = 1.0hf / sqrt(n.z * n.z + n.y * n.y);
		b1 = V(0.0hf, -n.z * k, n.y * k);
	} else {
		precise H k = 1.0hf / sqrt(n.x * n.x + n.y * n.y);
		b1 = V(n.y * k, -n.x * k, 0.0hf);
	}
	b2 = hcross(n, b1);
}
void unity(V n, precise out V b1, precise out V b2)
{
	precise H sz = n.z >= 0.0hf ? 1.0hf : -1.0hf;
	precise H a = 1.0hf / (sz + n.z);
	precise H ya = n.y * a, b = n.x * ya, c = n.x * sz;
	b1 = V(c * n.x * a - 1.0hf, sz * b, c);
	b2 = V(b, n.y * ya - sz, n.y);
}
void willems(V n, precise out V b1, precise out V b2)
{
	V up = abs(n.z) < hb(0x3bfeu) /* 0.999 */ ? V(0.0hf, 0.0hf, 1.0hf) : V(1.0hf, 0.0hf, 0.0hf);
	b1 = hnormalize_div(hcross(up, n));
	b2 = hnormalize_div(hcross(n, b1));
}
void gltf_viewer(V n, precise out V b1, precise out V b2)
{
	precise H d = n.x * 0.0hf + n.y * 1.0hf + n.z * 0.0hf;
	V up = V(0.0hf, 1.0hf, 0.0hf);
	precise H e = 1.0hf - abs(d);
	if (e <= hb(0x0002u) /* 1e-7: 2^-23 */)
		up = V(0.0hf, 0.0hf, d > 0.0hf ? 1.0hf : -1.0hf);
	b1 = hnormalize_div(hcross(up, n));
	b2 = hcross(n, b1);
}
void rtao(V n, precise out V b1, precise out V b2)
{
	precise H k = hb(0x34cdu); /* 0.3 */
	precise V r = V(k * n.x + hb(0xb9c3u), k * n.y + hb(0x387bu), k * n.z + hb(0xb571u)); /* -0.72, 0.56, -0.34 */
	b2 = hnormalize_div(hcross(n, r));
	b1 = hcross(b2, n);
}
/* 98: frisvad's a and its products in 32 bits, rounded once at the end */
void broken_frisvad_f32(V n, precise out V b1, precise out V b2)
{
	if (n.z < -1.0hf) { b1 = V(0.0hf, -1.0hf, 0.0hf); b2 = V(-1.0hf, 0.0hf, 0.0hf); return; }
	precise float a = 1.0 / (1.0 + float(n.z));
	precise H b = H(-float(n.x) * float(n.y) * a);
	b1 = V(H(1.0 - float(n.x) * float(n.x) * a), b, -n.x);
	b2 = V(b, H(1.0 - float(n.y) * float(n.y) * a), -n.y);
}

void main()
{
	uint i = gl_GlobalInvocationID.x;
	if (3u * i + 2u >= uint(inp.v.length()))
		return;
	V n = V(uintBitsToFloat(uvec3(inp.v[3u * i], inp.v[3u * i + 1u], inp.v[3u * i + 2u])));
	V b1 = V(0.0hf), b2 = V(0.0hf);
	switch (METHOD) {
#define ONB_GPU_HALF(id, m, f64, call) case id: call; break;
#include "gpu/half_methods.inc"
	case 98: broken_frisvad_f32(n, b1, b2); break;
	case 99: duff_branchless(n, sign(n.z), b1, b2); break;
	default: break;
	}
	uvec3 o1 = floatBitsToUint(vec3(b1)), o2 = floatBitsToUint(vec3(b2));
	outp.v[6u * i] = o1.x; outp.v[6u * i + 1u] = o1.y; outp.v[6u * i + 2u] = o1.z;
	outp.v[6u * i + 3u] = o2.x; outp.v[6u * i + 4u] = o2.y; outp.v[6u * i + 5u] = o2.z;
}
