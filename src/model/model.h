/*
 * model.h - the rounding model of every libonb kernel.
 *
 * Each method is written once more here, as a straight sequence of
 * operations on value handles (cv), in the order and format in which the
 * kernel in include/libonb/onb.h performs them.  The same model function runs on
 * two back ends:
 *
 *   CM_EXEC  every operation is performed in its format with IEEE rounding
 *            to nearest: the model must then give the kernel's bits
 *            (tests/test_certify.c checks 10^6 inputs per method and
 *            precision).  Branches take the side the values say.
 *   CM_MVF   every operation is the exact operation times (1 + e) plus an
 *            absolute term where the result can underflow; the values are
 *            intervals over a box of real unit vectors and of every e, and
 *            each carries its gradient in the e's (mvf.c).  Branches take
 *            the side the caller's path says; a side that no point of the
 *            box can take marks the path infeasible.
 *
 * So a model that runs bit-exact in CM_EXEC is the kernel's sequence of
 * roundings, and the bound that CM_MVF proves is a bound for the kernel:
 * a model that drops a rounding the kernel performs, or performs one in the
 * wrong format, gives other bits and fails that test.  CM_MVF may still
 * prove an operation exact where it is (Sterbenz's lemma, a product by 0 or
 * by a power of two that cannot underflow): then it adds no error term.
 */
#ifndef ONB_CERTIFY_MODEL_H
#define ONB_CERTIFY_MODEL_H

#include "seeds.h"
#include "common/prec.h"   /* the formats of an operation's result: PREC_FLOAT, PREC_DOUBLE */
/* Back ends. */
enum { CM_EXEC = 0, CM_MVF = 1 };

typedef int cv;          /* a value handle: an index into the context */
typedef struct cm cm;    /* a model context (one per thread)          */

/* Comparisons of the branch points. */
enum { CM_LT = 0, CM_GT };

/* Context, inputs, outputs. */
cm  *cm_new(int backend);
void cm_free(cm *c);
int  cm_backend(const cm *c);
/* Failure of the current run (CM_MVF: a division by an interval holding 0,
   an interval that is not finite, a path that no point can take). */
int  cm_failed(const cm *c);

/* Operations.  Each rounds once to format f (PREC_FLOAT, PREC_DOUBLE or
   PREC_HALF: CM_EXEC rounds to binary16 through MPFR at 11 bits with its
   range and subnormals; CM_MVF bounds a rounding to any of the three with
   the format's u, smallest normal and subnormal step from prec_fmt, and
   fails the run where a value may exceed the format's largest finite). */
cv cm_cst(cm *c, double v);              /* exact constant                  */
cv cm_add(cm *c, int f, cv a, cv b);
cv cm_sub(cm *c, int f, cv a, cv b);
cv cm_mul(cm *c, int f, cv a, cv b);
cv cm_div(cm *c, int f, cv a, cv b);
cv cm_sqrt(cm *c, int f, cv a);
cv cm_fma(cm *c, int f, cv a, cv b, cv d); /* a*b + d, rounded once          */
cv cm_cvt(cm *c, int f, cv a);           /* conversion to f (exact widening) */
cv cm_neg(cm *c, cv a);                  /* exact                           */
/* The seed of an approximate reciprocal square root: (1 + e)/sqrt(a) with
   |e| <= the bound seeds.c proves, in float (rsqrtss and Listing 3's
   bit trick) or double (Lomont's constant). */
cv cm_seed(cm *c, seed_kind k, cv a);
/* Listing 3's Newton step on a seed y of 1/sqrt(x): y (1.5 - 0.5 x y y),
   i.e. h = 0.5 x, then h y, (h y) y, 1.5 - that, y times that, each
   rounded in f.  CM_MVF bounds the result's relative error as a whole
   (mvf.c), where x cancels. */
cv cm_newton(cm *c, int f, cv x, cv y);
/* Embree's form of the step: 1.5 y + ((x (-0.5)) y)(y y), each operation
   rounded in f; CM_MVF bounds its relative error as a whole where y is a
   seed of x, else runs the operations one by one. */
cv cm_newton_embree(cm *c, int f, cv x, cv y);
/* the same steps as -mfma -ffp-contract=fast compiles them (model.c) */
cv cm_newton_fused(cm *c, int f, cv x, cv y);
cv cm_newton_embree_fused(cm *c, int f, cv x, cv y);

/* A function of V8's fdlibm (src/lib/fdlibm.c: Node.js's Math.acos,
   atan2(a, b), sin, cos), in double; b is used by CM_ATAN2 alone.  CM_EXEC
   calls it, so a model with it is bit-exact; CM_MVF has no enclosure of it
   (fdlibm documents < 1 ulp for each, which this back end does not carry):
   the run fails and no bound is proven (the babylon family). */
enum { CM_ACOS = 0, CM_ATAN2, CM_SIN, CM_COS };
cv cm_libm(cm *c, int fn, cv a, cv b);

/* Branch point number `id` of the model: a OP b on the values as computed,
   and |a| OP |b| for cm_branch_abs.  Returns the side taken (0 or 1). */
int cm_branch(cm *c, int id, int op, cv a, cv b);
int cm_branch_abs(cm *c, int id, int op, cv a, cv b);
/* The sign bit of a (copysign): 1 when it is set. */
int cm_branch_sign(cm *c, int id, cv a);

/* v rounded to format f as CM_EXEC rounds an operation's result (the
   models' constants, K() in model_kit.h). */
double cm_round(cm *c, int f, double v);
/* CM_EXEC: the value of handle v (in its format, widened to double). */
double cm_value(const cm *c, cv v);

/* Arithmetic profiles (arith.h).  cm_set_arith: the profile of the runs to
   come (NULL or ieee: the IEEE model, unchanged).  Under another profile,
   CM_MVF widens every operation's enclosure by the profile's allowance
   (mvf.c), and cm_unbounded_op names the operation kind (AR_*) whose
   allowance left the last run without a bound (-1: none), cm_lost_op the
   first operation whose operand's enclosure reached its pole or whose
   result may overflow (arith.h's AR_AT_POLE, AR_OVERFLOW; -1: none).  CM_EXEC then
   emulates a conforming implementation: each operation takes its
   round-to-nearest result (CM_EMU_NEAREST), a random allowed result
   (CM_EMU_RANDOM, from seed), or the choice given for it (CM_EMU_CHOICE:
   choice[k] for the k-th operation of the run, 0 beyond n): CM_CH_LO the
   lowest allowed result, CM_CH_HI the highest, both a random one; operands
   (FLUSH_IN) or the result (FLUSH_OUT) flushed where subnormal; a product
   read exact in the sum it feeds (FUSE: a contraction); a zero's sign
   read the other way (ZSIGN, at a sign test).  cm_emu_avail: the bits
   that made a difference to operation k of the last run. */
#include "arith.h"
void cm_set_arith(cm *c, const arith_profile *p);
const arith_profile *cm_arith(const cm *c);
int  cm_unbounded_op(const cm *c);
int  cm_lost_op(const cm *c);
enum { CM_EMU_NEAREST = 0, CM_EMU_RANDOM, CM_EMU_CHOICE };
#define CM_CH_LO        1u
#define CM_CH_HI        2u
#define CM_CH_FLUSH_IN  4u
#define CM_CH_FLUSH_OUT 8u
#define CM_CH_FUSE      16u
#define CM_CH_ZSIGN     32u
#define CM_EMU_MAXOP    512
void cm_set_emu(cm *c, int mode, unsigned long long seed, const unsigned char *choice, int n);
int  cm_emu_ops(const cm *c);
unsigned cm_emu_avail(const cm *c, int k);

#endif
