/*
 * arith.h - arithmetic profiles: what a GPU API (or a compiler mode) lets
 * an implementation return for each operation, written down as data
 * (arith.c holds the table, with the specification section of each row).
 *
 * A profile is a parameter of the one rounding model (model.h), beside the
 * format of each operation: the format gives u, the smallest normal and the
 * subnormal step; the profile says how far from the exact result an
 * operation may land (in ulps of a p-bit format, or relative), whether
 * subnormal operands and results may be flushed to zero, whether a*b + c
 * may be fused, whether fma may be split, and whether the sign of a zero
 * may be lost.  CM_MVF widens each operation's enclosure by that much
 * (mvf.c); CM_EXEC can pick any allowed result (model.c's emulation hook),
 * which src/certify/emulate.c drives at random or adversarially.
 *
 * `ieee` is the model as it has always been (IEEE round to nearest, no
 * contraction, subnormals kept): with it nothing changes, byte for byte.
 */
#ifndef ONB_MODEL_ARITH_H
#define ONB_MODEL_ARITH_H

#include <stddef.h>
#include "common/prec.h"

/* Operation kinds (each C operation of a model is one of these). */
enum { AR_ADD = 0, AR_SUB, AR_MUL, AR_DIV, AR_RCP, AR_SQRT, AR_RSQRT, AR_FMA, AR_CVT, AR_NOPS };

/* Why a bound under a profile is infinite, beside an operation kind: the
   profile gives it no bound (the kind alone), or the enclosure of its
   operand reaches the operation's pole or edge of domain (a division by,
   an inversesqrt or a sqrt of an enclosure that holds 0: AR_AT_POLE), or
   its result may overflow (AR_OVERFLOW); AR_LOST alone: the mean value
   form lost the enclosure elsewhere (a gradient, a quantity). */
#define AR_AT_POLE  0x100
#define AR_OVERFLOW 0x200
#define AR_LOST     0x400
/* "div", "rsqrt:0", "mul:overflow", "enclosure" ("" for -1): the
   unbounded_by column of certify --arith (a static string). */
const char *arith_cause_name(int cause);

/* How an operation's result r may differ from the exact result v. */
enum {
	AR_NONE = 0, /* the specification gives no bound: nothing is proven
	                (0: a format a profile's row leaves out is unbounded)  */
	AR_RN,       /* IEEE round to nearest: r = fl(v)                        */
	AR_ULP,      /* |r - v| <= x ulp(v), ulp(v) = 2^(E - p + 1) for
	                2^E <= |v| < 2^(E+1), E >= emin, p = ulp_bits          */
	AR_REL,      /* |r - v| <= x |v| (plus the flush term)                  */
	AR_SPLIT     /* performed as other operations: fma as a product then a
	                sum, sqrt as 1/inversesqrt, x/y as x * (1/y)            */
};

typedef struct {
	int how;       /* AR_RN ... AR_NONE                                     */
	double x;      /* AR_ULP: ulps; AR_REL: the relative error              */
} ar_allow;

/* One format's rules under a profile (index PREC_FLOAT, PREC_DOUBLE,
   PREC_HALF; the format's own parameters are common/prec.h's prec_fmt). */
typedef struct {
	ar_allow op[AR_NOPS];
	int ulp_bits;       /* the p of AR_ULP (24 in float; Vulkan's doubles
	                       are only as precise as single precision: 24)     */
	int flush;          /* subnormal operands and results may read as 0     */
	double div_lo, div_hi;  /* x/y's allowance holds for div_lo <= |y| <=
	                           div_hi; outside, nothing is specified        */
	const char *note;   /* what the specification says of this format      */
} ar_format;

typedef struct {
	const char *name;
	const char *title;
	int ieee;           /* 1: the IEEE model itself                          */
	ar_format fmt[PREC_COUNT];
	int contract;       /* a*b + c may be fused (a product into any sum)     */
	int reassoc;        /* the specification also allows reassociation: not
	                       modelled; proven for the source's operation order,
	                       every contraction choice                          */
	int zero_sign;      /* 1: the sign of a zero may be lost (-0 read as +0);
	                       2: only where an operand or result is flushed
	                       (OpenCL C 7.5.3: "if an operand or result is
	                       flushed to zero, the sign of the zero is
	                       undefined"); 0: kept                              */
	const char *spec;   /* the sections the rows come from                   */
	const char *compose;/* dot, cross, normalize, length, sign, abs, copysign */
} arith_profile;

/* The profiles, in table order; ieee first. */
int arith_count(void);
const arith_profile *arith_at(int i);
const arith_profile *arith_ieee(void);
/* The profile named s, or NULL. */
const arith_profile *arith_find(const char *s);
/* "ieee, vulkan, ..." into buf (for error messages). */
void arith_names(char *buf, size_t n);
/* 1 when the profile bounds some operation of format f (not every one none). */
int arith_has_format(const arith_profile *p, int f);
/* A profile that changes nothing: NULL or ieee. */
int arith_is_ieee(const arith_profile *p);
const char *arith_op_name(int op);
/* The AR_* kind of a model operation (model_int.h's MVF_ADD ... MVF_CVT):
   the one mapping that the widening (mvf.c) and the emulation (emu.c)
   share. */
int arith_kind(int op);

/* The allowance of operation op in format f (PREC_FLOAT or PREC_DOUBLE),
   after AR_SPLIT is resolved by the caller.  The bound on |r - v| for
   every exact result v with |v| <= vmax (and |v| >= vmin for the flush
   term), rounded up: the place where the format (precision, smallest
   normal, subnormal step) and the profile meet.  INFINITY for AR_NONE. */
double arith_err_abs(const arith_profile *p, int op, int f, double vmin, double vmax);
/* The same as a relative bound on a normal result (1 for AR_NONE). */
double arith_err_rel(const arith_profile *p, int op, int f);
/* The format's side (common/prec.h's prec_fmt): smallest normal, unit
   roundoff, precision p, smallest normal exponent. */
double arith_normal_min(int f);
double arith_unit(int f);
int arith_bits(int f);
int arith_emin(int f);

/* A copy of p with every ulp or relative allowance k times wider (k >= 1):
   a NONCONFORMING profile, for the emulation only, the mutation that the
   bound checks must catch (tests/test_arith.c, sweep --arith --widen). */
arith_profile arith_widen(const arith_profile *p, double k);

/* A one-line description of the profile's assumptions (CSV provenance). */
void arith_describe(const arith_profile *p, char *buf, size_t n);
/* The table `onbstudy list --arith` prints. */
void arith_print_table(void);

#endif
