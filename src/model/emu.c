/*
 * emu.c - CM_EXEC under an arithmetic profile (model.h, cm_set_emu): each
 * operation returns one result the profile allows, chosen by the caller
 * (src/certify/emulate.c: at random, or adversarially one operation at a
 * time).  The exact result v is carried as a double-double (hi + lo, to
 * 2^-100 or so); the allowed results are the format values within the
 * allowance of v, shrunk by 2^-20 of itself to absorb the double-double's
 * own error, so every result taken is allowed (a subset of the allowed
 * set, not all of it).  "Correctly rounded" in an unfixed rounding mode
 * (an allowance of 1 ulp on +, -, *, conversion) takes the two neighbours
 * of v: an exact v stays exact.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "model_int.h"

static double fmt_round(int f, double v)
{
	if (f == PREC_FLOAT) {
		volatile float r = (float)v;
		return r;
	}
	return f == PREC_HALF ? prec_half_round(v) : v;
}

/* A monotone integer of a format value, and back (binary16: its
   encoding, common/prec.h's prec_half_bits). */
static int64_t ord(int f, double x)
{
	if (f == PREC_HALF) {
		const uint16_t i = prec_half_bits(x);
		return (i & 0x8000u) ? -(int64_t)(i & 0x7fffu) : (int64_t)i;
	} else if (f == PREC_FLOAT) {
		float v = (float)x;
		int32_t i;
		memcpy(&i, &v, sizeof i);
		return i < 0 ? -(int64_t)(i & 0x7fffffff) : i;
	} else {
		int64_t i;
		memcpy(&i, &x, sizeof i);
		return i < 0 ? -(i & INT64_MAX) : i;
	}
}

static double unord(int f, int64_t k)
{
	if (f == PREC_HALF) {
		return prec_half_value((uint16_t)(k < 0 ? (-k) | 0x8000 : k));
	} else if (f == PREC_FLOAT) {
		int32_t i = k < 0 ? (int32_t)((-k) | 0x80000000) : (int32_t)k;
		float v;
		memcpy(&v, &i, sizeof v);
		return v;
	} else {
		int64_t i = k < 0 ? ((-k) | INT64_MIN) : k;
		double v;
		memcpy(&v, &i, sizeof v);
		return v;
	}
}

/* The next format value from x toward dir (nextafter in format f). */
static double step(int f, double x, double dir)
{
	if (f == PREC_HALF) {
		if (isnan(x) || isnan(dir) || x == dir)
			return isnan(x) || isnan(dir) ? NAN : x;
		if (x == 0.0)
			return dir > 0.0 ? 0x1p-24 : -0x1p-24;
		return unord(f, ord(f, x) + (dir > x ? 1 : -1));
	}
	return f == PREC_FLOAT ? (double)nextafterf((float)x, (float)dir) : nextafter(x, dir);
}

/* fma(a, b, d) correctly rounded to format f: binary16 from the exact
   sum hi + lo of the (exact, 22-bit) product and d, the one case where
   rounding hi alone can be wrong (hi a binary16 midpoint, lo not 0) set
   right. */
static double fma_rn(int f, double a, double b, double d)
{
	double ph, pl, hi, lo, r;
	if (f == PREC_FLOAT)
		return (double)fmaf((float)a, (float)b, (float)d);
	if (f != PREC_HALF)
		return fma(a, b, d);
	ph = a * b;
	pl = fma(a, b, -ph);
	hi = ph + d;
	lo = (ph - (hi - (hi - ph))) + (d - (hi - ph)) + pl;
	r = prec_half_round(hi);
	if (isfinite(r) && lo != 0.0 && fabs(hi - r) == 0.5 * fabs(step(f, r, hi) - r) && (lo > 0.0) == (hi > r))
		r = step(f, r, hi);
	return r;
}

static unsigned long long rnd(cm *c)
{
	unsigned long long z = (c->emu_rng += 0x9e3779b97f4a7c15ull);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
	return z ^ (z >> 31);
}

/* The choice bits of the next operation; its index in *k. */
static unsigned next_choice(cm *c, int *k)
{
	*k = c->emu_k++;
	if (c->emu_mode == CM_EMU_RANDOM)
		return (unsigned)(rnd(c) & 0x3fu);
	if (c->emu_mode == CM_EMU_CHOICE && *k < c->emu_nchoice)
		return c->emu_choice[*k];
	return 0u;
}

static void note(cm *c, int k, unsigned bits)
{
	if (k < CM_EMU_MAXOP)
		c->emu_avail[k] = (unsigned char)bits;
}

static int subnormal(int f, double x) { return x != 0.0 && fabs(x) < arith_normal_min(f); }

/* v = hi + lo exactly (to 2^-100 relative) for the operation on doubles. */
static void two_sum(double a, double b, double *hi, double *lo)
{
	double s = a + b, bb = s - a;
	*hi = s;
	*lo = (a - (s - bb)) + (b - bb);
}

static void exact_dd(int k, double a, double b, double *hi, double *lo)
{
	double q, r, s;
	switch (k) {
	case AR_ADD: two_sum(a, b, hi, lo); return;
	case AR_SUB: two_sum(a, -b, hi, lo); return;
	case AR_MUL: *hi = a * b; *lo = fma(a, b, -*hi); return;
	case AR_DIV: q = a / b; *hi = q; *lo = isfinite(q) ? fma(-q, b, a) / b : 0.0; return;
	case AR_RCP: q = 1.0 / b; *hi = q; *lo = isfinite(q) ? fma(-q, b, 1.0) / b : 0.0; return;
	case AR_SQRT: s = sqrt(a); *hi = s; *lo = s > 0.0 && isfinite(s) ? fma(-s, s, a) / (2.0 * s) : 0.0; return;
	case AR_RSQRT:
		s = sqrt(a);
		r = s > 0.0 && isfinite(s) ? fma(-s, s, a) / (2.0 * s) : 0.0;   /* sqrt(a) = s + r */
		q = 1.0 / s;
		*hi = q;
		*lo = isfinite(q) && q != 0.0 ? q * (fma(-q, s, 1.0) - q * r) : 0.0;
		return;
	default: *hi = a; *lo = 0.0; return;   /* AR_CVT */
	}
}

/* The lowest (dir < 0) or highest allowed format value within A of
   v = hi + lo: from the format value nearest v -+ A, a few steps. */
static double edge(int f, double hi, double lo, double A, double dir)
{
	double x = fmt_round(f, dir > 0 ? hi + A : hi - A);
	int i;
	for (i = 0; i < 64 && !(fabs((x - hi) - lo) <= A); i++)   /* inside first */
		x = step(f, x, -dir);
	for (i = 0; i < 64; i++) {
		double y = step(f, x, dir);
		if (!isfinite(y) || fabs((y - hi) - lo) > A)
			break;
		x = y;
	}
	return x;
}

/* The result of operation kind k with choice ch: rn the round-to-nearest
   result; v = hi + lo the exact one.  *avail gets the bits that matter. */
static double choose(cm *c, int k, int f, double rn, double hi, double lo, unsigned ch, unsigned *avail)
{
	const ar_format *af = &c->ar->fmt[f];
	const ar_allow *al = &af->op[k];
	double A, lo_v, hi_v;
	if (!isfinite(rn) || !isfinite(hi) || al->how == AR_RN || al->how == AR_NONE || al->how == AR_SPLIT)
		return rn;
	if (al->how == AR_ULP && al->x <= 1.0 && (k == AR_ADD || k == AR_SUB || k == AR_MUL || k == AR_CVT)) {
		double e = (rn - hi) - lo;   /* either neighbour of v */
		if (e == 0.0)
			return rn;
		lo_v = e > 0.0 ? step(f, rn, -INFINITY) : rn;
		hi_v = e > 0.0 ? rn : step(f, rn, INFINITY);
	} else {
		A = arith_err_abs(c->ar, k, f, arith_normal_min(f), fabs(hi)) * (1.0 - 0x1p-20);
		lo_v = edge(f, hi, lo, A, -INFINITY);
		hi_v = edge(f, hi, lo, A, INFINITY);
		if (!(lo_v <= rn && rn <= hi_v))   /* A below half an ulp: none but the nearest */
			lo_v = hi_v = rn;
	}
	if (lo_v != hi_v)
		*avail |= CM_CH_LO | CM_CH_HI;
	switch (ch & (CM_CH_LO | CM_CH_HI)) {
	case CM_CH_LO: return lo_v;
	case CM_CH_HI: return hi_v;
	case CM_CH_LO | CM_CH_HI: {
		int64_t a = ord(f, lo_v), b = ord(f, hi_v);
		return unord(f, a + (int64_t)(rnd(c) % (unsigned long long)(b - a + 1)));
	}
	default: return rn;
	}
}

static double flush_in(cm *c, int f, double x, unsigned ch, unsigned *avail)
{
	if (!c->ar->fmt[f].flush || !subnormal(f, x))
		return x;
	*avail |= CM_CH_FLUSH_IN;
	return ch & CM_CH_FLUSH_IN ? copysign(0.0, x) : x;
}

/* x/y with |y| outside the range where the allowance holds: nothing is
   specified (the proof says unbounded); the emulation keeps the nearest. */
static int af_div_out(const cm *c, int k, int f, double y)
{
	const ar_format *af = &c->ar->fmt[f];
	return (k == AR_DIV || k == AR_RCP) && af->div_lo > 0.0 && !(fabs(y) >= af->div_lo && fabs(y) <= af->div_hi);
}

/* One rounded operation of kind k in format f on values a, b (and, for a
   contraction, the exact product pa*pb in place of b or a). */
static cv emu_round(cm *c, int k, int f, cv ia, cv ib)
{
	const int fin = k == AR_CVT ? (f == PREC_FLOAT ? PREC_DOUBLE : PREC_FLOAT) : f;
	unsigned avail = 0, ch;
	int idx, fused = 0;
	double a = ia >= 0 ? c->x[ia] : 0.0, b = ib >= 0 ? c->x[ib] : 0.0, rn, hi, lo;
	cv r;
	ch = next_choice(c, &idx);
	a = flush_in(c, fin, a, ch, &avail);
	b = flush_in(c, fin, b, ch, &avail);
	if ((k == AR_ADD || k == AR_SUB) && c->ar->contract && (c->pa[ia] >= 0 || c->pa[ib] >= 0)) {
		avail |= CM_CH_FUSE;
		fused = (ch & CM_CH_FUSE) != 0;
	}
	if (fused) {   /* fma(p, q, +-other): the product exact */
		const int first = c->pa[ia] >= 0;
		const double p = c->x[first ? c->pa[ia] : c->pa[ib]], q = c->x[first ? c->pb[ia] : c->pb[ib]];
		double other = first ? b : a, ph, pl, s, t;
		double sg = !first && k == AR_SUB ? -1.0 : 1.0;   /* a - p q = a + (-p) q */
		if (first && k == AR_SUB)
			other = -other;
		rn = fma_rn(f, sg * p, q, other);
		ph = sg * p * q;
		pl = fma(sg * p, q, -ph);
		two_sum(ph, other, &s, &t);
		hi = s;
		lo = t + pl;
	} else {
		exact_dd(k, a, b, &hi, &lo);
		/* float, half: hi is v to 2^-53, and its rounding the nearest
		   float or half (53 >= 2p + 2, as model.c's fmt); double: hi
		   itself is the nearest double */
		rn = fmt_round(f, hi);
	}
	if (af_div_out(c, k, f, b))
		ch &= ~(CM_CH_LO | CM_CH_HI);
	rn = choose(c, k, f, rn, hi, lo, ch, &avail);
	if (c->ar->fmt[f].flush && subnormal(f, rn)) {
		avail |= CM_CH_FLUSH_OUT;
		if (ch & CM_CH_FLUSH_OUT)
			rn = copysign(0.0, rn);
	}
	note(c, idx, avail);
	r = cm__put(c, rn);
	if (k == AR_MUL && !c->failed) {
		c->pa[r] = (short)ia;
		c->pb[r] = (short)ib;
	}
	return r;
}

/* An fma the profile keeps fused: its one rounding (operands as read). */
static cv emu_fma(cm *c, int f, cv ia, cv ib, cv id)
{
	unsigned avail = 0, ch;
	int idx;
	double a, b, d, r;
	ch = next_choice(c, &idx);
	a = flush_in(c, f, c->x[ia], ch, &avail);
	b = flush_in(c, f, c->x[ib], ch, &avail);
	d = flush_in(c, f, c->x[id], ch, &avail);
	r = fma_rn(f, a, b, d);
	if (c->ar->fmt[f].flush && subnormal(f, r)) {
		avail |= CM_CH_FLUSH_OUT;
		if (ch & CM_CH_FLUSH_OUT)
			r = copysign(0.0, r);
	}
	note(c, idx, avail);
	return cm__put(c, r);
}

cv cm__emu_op(cm *c, int op, int f, cv a, cv b, cv d)
{
	const int k = arith_kind(op);
	const ar_allow *al = &c->ar->fmt[f].op[k];
	if (al->how == AR_SPLIT) {
		if (op == MVF_FMA)
			return cm__emu_op(c, MVF_ADD, f, cm__emu_op(c, MVF_MUL, f, a, b, -1), d, -1);
		if (op == MVF_SQRT)   /* 1.0/inversesqrt(a) */
			return cm__emu_op(c, MVF_DIV, f, cm__put(c, 1.0), emu_round(c, AR_RSQRT, f, a, -1), -1);
		if (op == MVF_DIV)    /* a * rcp(b) */
			return cm__emu_op(c, MVF_MUL, f, a, emu_round(c, AR_RCP, f, -1, b), -1);
	}
	if (op == MVF_FMA)
		return emu_fma(c, f, a, b, d);
	return emu_round(c, k, f, a, b);
}

/* Comparison operands as read: flushed where subnormal in the kernel's
   format (one choice for both). */
void cm__emu_read2(cm *c, cv *a, cv *b)
{
	unsigned avail = 0, ch;
	int idx;
	double x, y;
	if (c->backend != CM_EXEC) {
		*a = mvf_read(c->m, *a);
		*b = mvf_read(c->m, *b);
		return;
	}
	ch = next_choice(c, &idx);
	x = flush_in(c, c->exec_f, c->x[*a], ch, &avail);
	y = flush_in(c, c->exec_f, c->x[*b], ch, &avail);
	note(c, idx, avail);
	if (x != c->x[*a])
		*a = cm__put(c, x);
	if (y != c->x[*b] || signbit(y) != signbit(c->x[*b]))
		*b = cm__put(c, y);
}

/* The sign test (copysign): a flushed operand keeps its sign; where the
   profile may lose a zero's sign, a zero's sign may read either way, and
   where it loses only a flushed zero's (OpenCL), a flushed operand's. */
int cm__emu_sign(cm *c, cv a)
{
	unsigned avail = 0, ch;
	int idx, s;
	double x;
	ch = next_choice(c, &idx);
	x = flush_in(c, c->exec_f, c->x[a], ch, &avail);
	s = signbit(x) != 0;
	if (x == 0.0 && (c->ar->zero_sign == 1 || (c->ar->zero_sign == 2 && x != c->x[a]))) {
		avail |= CM_CH_ZSIGN;
		if (ch & CM_CH_ZSIGN)
			s = !s;
	}
	note(c, idx, avail);
	return s;
}
