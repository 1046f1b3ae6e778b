/*
 * arith.c - the arithmetic profiles (arith.h) as data, each row with the
 * specification section it comes from.  docs/gpu.md prints this table
 * (`onbstudy list --arith`) and says what each reading assumes.
 *
 * Readings (each a choice; docs/gpu.md gives the reasons):
 *  - "Correctly rounded" without a fixed rounding mode (Vulkan without
 *    RoundingModeRTE, Direct3D 11's "truncation allowed") is read as
 *    either neighbouring float: |r - v| < 1 ulp.
 *  - An ulp is that of the exact result's binade, 2^(E - p + 1) for
 *    2^E <= |v| < 2^(E+1), E at least the format's smallest normal exponent.
 *  - Vulkan's "the precision of double-precision instructions is at least
 *    that of single precision": a double operation may err by the float
 *    allowance in float ulps (ulp_bits 24), with double's exponent range.
 *  - Flushing (Vulkan without DenormPreserve, Direct3D 11, CUDA -ftz,
 *    OpenCL single precision without CL_FP_DENORM) may happen at every
 *    operand and result, independently at each use.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "arith.h"
#include "model_int.h"
#include "common/prec.h"

#define RN    { AR_RN, 0.0 }
#define ULP(x) { AR_ULP, (x) }
#define REL(x) { AR_REL, (x) }
#define SPLIT { AR_SPLIT, 0.0 }
#define NONE  { AR_NONE, 0.0 }

/*                          add     sub     mul     div        rcp        sqrt      rsqrt     fma    cvt */
#define IEEE_OPS      { RN,     RN,     RN,     RN,        RN,        RN,       RN,       RN,    RN }
#define VK_OPS        { ULP(1), ULP(1), ULP(1), ULP(2.5),  ULP(2.5),  SPLIT,    ULP(2),   SPLIT, ULP(1) }
#define D3D_OPS       { ULP(1), ULP(1), ULP(1), SPLIT,     REL(0x1p-21), REL(0x1p-21), REL(0x1p-21), SPLIT, ULP(1) }
#define D3D_D_OPS     { ULP(1), ULP(1), ULP(1), ULP(1),    ULP(1),    NONE,     NONE,     ULP(1), ULP(1) }
#define CL_F_OPS      { RN,     RN,     RN,     ULP(2.5),  ULP(2.5),  ULP(3),   ULP(2),   RN,    RN }
#define CL_D_OPS      { RN,     RN,     RN,     RN,        RN,        RN,       ULP(2),   RN,    RN }
#define CUDA_F_OPS    { RN,     RN,     RN,     ULP(2),    ULP(2),    ULP(3),   ULP(2),   RN,    RN }
#define CL_H_OPS      { ULP(1), ULP(1), ULP(1), ULP(1),    ULP(1),    ULP(1.5), ULP(1),   ULP(1), RN }
#define CUDA_H_OPS    { RN,     RN,     RN,     NONE,      NONE,      NONE,     NONE,     RN,    RN }
#define NONE_OPS      { NONE,   NONE,   NONE,   NONE,      NONE,      NONE,     NONE,     NONE,  NONE }

/* Vulkan's half-precision column (Float16 arithmetic, shaderFloat16): the
   same rules in binary16, division's range [2^-14, 2^14].  An operation
   decorated RelaxedPrecision (GLSL mediump) on 32-bit values is in
   neither column: Vulkan grants it no precision at all. */
#define VK_HALF_NOTE "Float16 (shaderFloat16): OpFAdd/OpFSub/OpFMul/conversions correctly rounded; OpFDiv 2.5 ulp for |y| in [2^-14, 2^14]; InverseSqrt 2 ulp; Sqrt from 1.0/InverseSqrt; Fma from OpFMul then OpFAdd (the table's half-precision column). RelaxedPrecision (mediump) on 32-bit values: no precision required (the single-precision column excludes it)"

static const arith_profile profiles[] = {
	{ "ieee", "IEEE 754 binary32/binary64, round to nearest, no contraction, subnormals kept (the C kernels as built)", 1,
	  { { IEEE_OPS, 24, 0, 0.0, INFINITY, "IEEE 754-2019 section 4.3.1 (roundTiesToEven)" },
	    { IEEE_OPS, 53, 0, 0.0, INFINITY, "IEEE 754-2019 section 4.3.1" },
	    { IEEE_OPS, 11, 0, 0.0, INFINITY, "IEEE 754-2019 section 4.3.1" } },
	  0, 0, 0, "IEEE 754-2019; ISO C99 F.3 (FP_CONTRACT off: the Makefile's -ffp-contract=off)",
	  "dot, cross, normalize, length: the C source's own operations; copysign exact" },
	{ "vulkan", "Vulkan 1.3 / SPIR-V without NoContraction, RoundingModeRTE, DenormPreserve or SignedZeroInfNanPreserve", 0,
	  { { VK_OPS, 24, 1, 0x1p-126, 0x1p126,
	      "OpFAdd/OpFSub/OpFMul/OpFConvert correctly rounded (rounding mode not fixed: < 1 ulp); OpFDiv 2.5 ulp for |y| in [2^-126, 2^126]; InverseSqrt 2 ulp; Sqrt inherited from 1.0/InverseSqrt; Fma inherited from OpFMul then OpFAdd" },
	    { VK_OPS, 24, 1, 0x1p-126, 0x1p126,
	      "\"the precision of double-precision instructions is at least that of single precision\": the float allowances, in float ulps" },
	    { VK_OPS, 11, 1, 0x1p-14, 0x1p14, VK_HALF_NOTE } },
	  1, 1, 1, "Vulkan 1.3 spec, Appendix A (Vulkan Environment for SPIR-V): Precision and Operation of SPIR-V Instructions; SPIR-V 1.6 section 3.20 (NoContraction), 3.6 (DenormPreserve, SignedZeroInfNanPreserve); GLSL 4.60 section 4.7.1",
	  "dot: OpFMul and OpFAdd; cross: OpFMul and OpFSub; length: Sqrt(Dot); normalize: x * InverseSqrt(Dot(x, x)); FAbs, FSign exact (GLSL sign(0) = 0); no copysign in GLSL" },
	{ "vulkan-precise", "Vulkan 1.3 / SPIR-V with NoContraction on every operation (GLSL precise): no fusion, no reassociation", 0,
	  { { VK_OPS, 24, 1, 0x1p-126, 0x1p126, "as vulkan, NoContraction on every operation" },
	    { VK_OPS, 24, 1, 0x1p-126, 0x1p126, "as vulkan: single-precision allowances" },
	    { VK_OPS, 11, 1, 0x1p-14, 0x1p14, VK_HALF_NOTE } },
	  0, 0, 1, "as vulkan; SPIR-V 1.6 section 3.20 NoContraction: no fusing into one operation, no reassociation",
	  "as vulkan; an explicit fma() is still Fma, inherited from OpFMul then OpFAdd (two roundings)" },
	{ "d3d11", "Direct3D 11 floating-point rules (HLSL without precise)", 0,
	  { { D3D_OPS, 24, 1, 0.0, INFINITY,
	      "add/sub/mul 0.5 ulp \"truncation allowed\" (read: < 1 ulp); rcp, rsq 2^-21 relative; x/y as x * rcp(y); sqrt read as rsq's 2^-21 (no separate figure); mad fused or two roundings; denormals flushed to sign-preserved zero" },
	    { D3D_D_OPS, 53, 0, 0.0, INFINITY,
	      "doubles (optional: DoublePrecisionFloatShaderOps) \"follow IEEE 754R\" (dadd, dmul: read, as the 32-bit rules read 0.5 ULP, as < 1 ulp), denormals kept; ddiv 0.5 ULP, drcp 1.0 ULP, dfma 0.5 ULP fused (Direct3D 11.1 ExtendedDoublesShaderInstructions: without it no double division exists); no double sqrt or rsq in Shader Model 5: none" },
	    { NONE_OPS, 11, 0, 0.0, INFINITY, "16-bit floats are a storage format (16-bit floating-point rules: conversions); min16float gives no operation precision: none" } },
	  1, 1, 0, "Direct3D 11 Programming Guide, Floating-point rules (32-bit, 64-bit (double precision) and 16-bit floating-point rules); Shader Model 5 assembly reference: ddiv, drcp, dfma (Direct3D 11.1, ExtendedDoublesShaderInstructions)",
	  "dot, cross, normalize, length: mul and add/mad; rsqrt: rsq; sign, abs exact" },
	{ "opencl", "OpenCL C 3.0 full profile, default build options (FP_CONTRACT on, no -cl-fast-relaxed-math)", 0,
	  { { CL_F_OPS, 24, 1, 0.0, INFINITY,
	      "x+y, x-y, x*y, fma correctly rounded; x/y and 1/x 2.5 ulp; sqrt 3 ulp; rsqrt 2 ulp; denormals optional (CL_FP_DENORM): may flush" },
	    { CL_D_OPS, 53, 0, 0.0, INFINITY, "x+y, x-y, x*y, x/y, 1/x, sqrt, fma correctly rounded; rsqrt 2 ulp; denormals supported" },
	    { CL_H_OPS, 11, 1, 0.0, INFINITY,
	      "cl_khr_fp16, full profile (table \"ULP Values for Half-Precision Floating-Point Arithmetic Operations\"): x+y, x-y, x*y, fma correctly rounded in the device's mode, which may be round to zero (CL_DEVICE_HALF_FP_CONFIG's minimum is CL_FP_ROUND_TO_ZERO): < 1 ulp; x/y and 1.0/x 1 ulp; sqrt 1.5 ulp; rsqrt 1 ulp; conversions to half round to nearest even (the default _rte); denormals optional (CL_FP_DENORM): may flush" } },
	  1, 0, 2, "OpenCL C 3.0 section 7.4 (Relative Error as ULPs; its half-precision table with cl_khr_fp16), 7.5 (Edge Case Behavior in Flush To Zero Mode), 6.13.2 (FP_CONTRACT), 6.4.3 (conversions: default rounding _rte); OpenCL 3.0 API 4.2 (CL_DEVICE_HALF_FP_CONFIG)",
	  "dot, cross, length, normalize built-ins have their own ulp bounds (normalize 2 + n ulp); the C kernels use +, *, /, sqrt" },
	{ "cuda-fast", "CUDA with --use_fast_math (-ftz=true -prec-div=false -prec-sqrt=false -fmad=true)", 0,
	  { { CUDA_F_OPS, 24, 1, 0x1p-126, 0x1p126,
	      "x/y 2 ulp for |y| in [2^-126, 2^126]; sqrtf 3 ulp; rsqrtf 2 ulp; +, -, *, fmaf IEEE; flushed to zero (NVIDIA: bounds tested, not guaranteed)" },
	    { IEEE_OPS, 53, 0, 0.0, INFINITY, "fast math does not change double precision (but -fmad=true contracts it)" },
	    { CUDA_H_OPS, 11, 0, 0.0, INFINITY,
	      "__half (cuda_fp16.h; CUDA Math API, Half Precision Intrinsics): every operation is documented as done \"in round-to-nearest-even mode\" and none with an error figure; __hadd, __hsub, __hmul, __hfma (fused), single IEEE operations, are read as correctly rounded, and so are __float2half and __double2half; __hdiv (Half Arithmetic Functions) and hsqrt, hrsqrt, hrcp (Half Math Functions, worded as hsin and hexp, which are not correctly rounded) have no figure: none, so a method that divides or takes a square root in half is unbounded; -ftz is single precision's: half denormals kept" } },
	  1, 0, 0, "CUDA C++ Programming Guide, Mathematical Functions appendix (single-precision functions, intrinsic functions) and nvcc --use_fast_math; CUDA Math API, Half Precision Intrinsics (Half Arithmetic Functions, Half Math Functions, conversions)",
	  "no dot/normalize built-ins in C++: the source's own operations" },
	{ "contract-any", "IEEE rounding, every a*b + c may be fused or not (GCC -ffp-contract=fast, clang's default on arm64, shader compilers)", 0,
	  { { IEEE_OPS, 24, 0, 0.0, INFINITY, "IEEE round to nearest; contraction per ISO C99 6.5 paragraph 8 and beyond" },
	    { IEEE_OPS, 53, 0, 0.0, INFINITY, "the same" },
	    { IEEE_OPS, 11, 0, 0.0, INFINITY, "the same" } },
	  1, 0, 0, "ISO C99 6.5 paragraph 8 and 7.12.2 (FP_CONTRACT); GCC -ffp-contract=fast",
	  "the C source's own operations, any product fused into any sum it feeds" },
};

#define NPROF ((int)(sizeof profiles / sizeof profiles[0]))

int arith_count(void) { return NPROF; }
const arith_profile *arith_at(int i) { return i >= 0 && i < NPROF ? &profiles[i] : NULL; }
const arith_profile *arith_ieee(void) { return &profiles[0]; }
int arith_is_ieee(const arith_profile *p) { return !p || p->ieee; }

int arith_has_format(const arith_profile *p, int f)
{
	int op;
	for (op = 0; p && f >= 0 && f < PREC_COUNT && op < AR_NOPS; op++)
		if (p->fmt[f].op[op].how != AR_NONE)
			return 1;
	return 0;
}

const arith_profile *arith_find(const char *s)
{
	int i;
	for (i = 0; s && i < NPROF; i++)
		if (strcmp(s, profiles[i].name) == 0)
			return &profiles[i];
	return NULL;
}

void arith_names(char *buf, size_t n)
{
	size_t used = 0;
	int i;
	if (n)
		buf[0] = '\0';
	for (i = 0; i < NPROF && used < n; i++)
		used += (size_t)snprintf(buf + used, n - used, "%s%s", i ? ", " : "", profiles[i].name);
}

const char *arith_op_name(int op)
{
	static const char *const names[AR_NOPS] = { "add", "sub", "mul", "div", "rcp", "sqrt", "rsqrt", "fma", "cvt" };
	return op >= 0 && op < AR_NOPS ? names[op] : "?";
}

const char *arith_cause_name(int cause)
{
	static const char *const pole[AR_NOPS] = { "add:0", "sub:0", "mul:0", "div:0", "rcp:0", "sqrt:0", "rsqrt:0", "fma:0", "cvt:0" };
	static const char *const over[AR_NOPS] = { "add:overflow", "sub:overflow", "mul:overflow", "div:overflow",
	                                           "rcp:overflow", "sqrt:overflow", "rsqrt:overflow", "fma:overflow",
	                                           "cvt:overflow" };
	const int op = cause & 0xff;
	if (cause < 0)
		return "";
	if (op >= AR_NOPS || (cause & AR_LOST))
		return cause & AR_OVERFLOW ? "overflow" : "enclosure";
	return cause & AR_AT_POLE ? pole[op] : cause & AR_OVERFLOW ? over[op] : arith_op_name(op);
}

int arith_kind(int op)
{
	switch (op) {
	case MVF_ADD: return AR_ADD;
	case MVF_SUB: return AR_SUB;
	case MVF_MUL: return AR_MUL;
	case MVF_DIV: return AR_DIV;
	case MVF_SQRT: return AR_SQRT;
	case MVF_FMA: return AR_FMA;
	default: return AR_CVT;
	}
}

int arith_bits(int f) { return prec_fmt(f)->bits; }
int arith_emin(int f) { return prec_fmt(f)->emin; }
double arith_normal_min(int f) { return prec_fmt(f)->normal_min; }
double arith_unit(int f) { return prec_fmt(f)->u; }

static double up(double x) { return x * (1.0 + 0x1p-50) + 0x1p-1074; }

double arith_err_abs(const arith_profile *p, int op, int f, double vmin, double vmax)
{
	const ar_format *af = &p->fmt[f];
	const ar_allow *a = &af->op[op];
	const int emin = arith_emin(f);
	double h;
	int e;
	if (a->how == AR_NONE || a->how == AR_SPLIT)
		return INFINITY;
	if (!(vmax > 0.0))
		return vmax == 0.0 ? 0.0 : INFINITY;
	frexp(vmax, &e);
	e -= 1;                         /* 2^e <= vmax < 2^(e+1) */
	if (e < emin)
		e = emin;
	if (a->how == AR_RN)
		h = ldexp(1.0, e - arith_bits(f));
	else if (a->how == AR_ULP)
		h = a->x * ldexp(1.0, e - af->ulp_bits + 1);
	else   /* AR_REL; below the smallest normal also half a subnormal step */
		h = a->x * vmax + (vmin < arith_normal_min(f) ? ldexp(1.0, emin - arith_bits(f)) : 0.0);
	if (af->flush && vmin < arith_normal_min(f))
		h += arith_normal_min(f);   /* a subnormal result may be flushed */
	return up(h);
}

double arith_err_rel(const arith_profile *p, int op, int f)
{
	const ar_format *af = &p->fmt[f];
	const ar_allow *a = &af->op[op];
	switch (a->how) {
	case AR_RN: return arith_unit(f);
	case AR_ULP: return a->x * ldexp(1.0, 1 - af->ulp_bits);
	case AR_REL: return a->x;
	default: return INFINITY;
	}
}

arith_profile arith_widen(const arith_profile *p, double k)
{
	arith_profile w = *p;
	int f, op;
	for (f = 0; f < PREC_COUNT; f++)
		for (op = 0; op < AR_NOPS; op++)
			if (w.fmt[f].op[op].how == AR_ULP || w.fmt[f].op[op].how == AR_REL)
				w.fmt[f].op[op].x *= k;
	return w;
}

static void allow_text(const arith_profile *p, int f, int op, char *b, size_t n)
{
	const ar_allow *a = &p->fmt[f].op[op];
	switch (a->how) {
	case AR_RN: snprintf(b, n, "RN"); break;
	case AR_ULP:
		if (p->fmt[f].ulp_bits != arith_bits(f))
			snprintf(b, n, "%gulp%d", a->x, p->fmt[f].ulp_bits);
		else
			snprintf(b, n, "%gulp", a->x);
		break;
	case AR_REL: {
		int e;
		if (frexp(a->x, &e) == 0.5)
			snprintf(b, n, "rel2^%d", e - 1);
		else
			snprintf(b, n, "rel%g", a->x);
		break;
	}
	case AR_SPLIT:
		snprintf(b, n, "%s", op == AR_FMA ? "mul+add" : op == AR_SQRT ? "1/rsqrt" : op == AR_DIV ? "x*rcp" : "split");
		break;
	default: snprintf(b, n, "none"); break;
	}
}

void arith_describe(const arith_profile *p, char *buf, size_t n)
{
	size_t used;
	int f, op;
	used = (size_t)snprintf(buf, n, "%s: contract %s, reassociation %s, signed zeros %s;", p->name,
	                        p->contract ? "any a*b+c" : "no",
	                        p->reassoc ? "allowed by the spec (proven: the source's order, every contraction choice)" : "no",
	                        p->zero_sign == 2 ? "undefined where flushed (may be lost)"
	                        : p->zero_sign ? "may be lost" : "kept");
	for (f = 0; f < PREC_COUNT && used < n; f++) {
		used += (size_t)snprintf(buf + used, n - used, " %s:", prec_name(f));
		for (op = 0; op < AR_NOPS && used < n; op++) {
			char t[32];
			allow_text(p, f, op, t, sizeof t);
			used += (size_t)snprintf(buf + used, n - used, " %s %s", arith_op_name(op), t);
		}
		if (used < n)
			used += (size_t)snprintf(buf + used, n - used, ", flush %s%s", p->fmt[f].flush ? "yes" : "no",
			                         f + 1 < PREC_COUNT ? ";" : "");
	}
}

void arith_print_table(void)
{
	int i, f, op;
	printf("%-15s %-6s", "profile", "format");
	for (op = 0; op < AR_NOPS; op++)
		printf(" %-10s", arith_op_name(op));
	printf(" %-5s %-8s %-7s %-5s\n", "flush", "contract", "reassoc", "-0");
	for (i = 0; i < NPROF; i++)
		for (f = 0; f < PREC_COUNT; f++) {
			const arith_profile *p = &profiles[i];
			printf("%-15s %-6s", p->name, prec_name(f));
			for (op = 0; op < AR_NOPS; op++) {
				char t[32];
				allow_text(p, f, op, t, sizeof t);
				printf(" %-10s", t);
			}
			printf(" %-5s %-8s %-7s %-5s\n", p->fmt[f].flush ? "yes" : "no", p->contract ? "yes" : "no",
			       p->reassoc ? "yes" : "no", p->zero_sign == 2 ? (p->fmt[f].flush ? "flush" : "kept") : p->zero_sign ? "lost" : "kept");
		}
}
