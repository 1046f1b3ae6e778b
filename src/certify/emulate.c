/*
 * emulate.c - conforming implementations of a profile, emulated
 * (emulate.h).  The adversary is a greedy coordinate search: it does not
 * prove that its result is the worst the profile allows (the bound of
 * `certify --arith` is what holds for all), it finds a bad one cheaply.
 */
#include <math.h>
#include <string.h>
#include "emulate.h"
#include "model/model_int.h"
#include "bound.h"

void emu_run(cm *c, ref_ctx *rc, const cm_method *m, int prec, const double n[3], const arith_profile *p,
             int mode, unsigned long long seed, const unsigned char *choice, int nchoice, emu_eval *r)
{
	cv in[3], out[6];
	int i, finite = 1;
	cm_set_arith(c, p);
	cm_set_emu(c, mode, seed, choice, nchoice);
	cm_exec_begin(c, prec, n, in);
	cm_run(c, m, prec, in, out);
	for (i = 0; i < 6; i++) {
		r->out[i] = cm_value(c, out[i]);
		finite &= isfinite(r->out[i]) != 0;
	}
	r->ops = cm_emu_ops(c);
	if (!finite || cm_failed(c)) {
		for (i = 0; i < NDEF; i++)
			r->d[i] = NAN;
		r->defect = INFINITY;
		return;
	}
	ref_defects(rc, n, r->out, r->d);
	r->defect = 0.0;
	for (i = 0; i < NDEF; i++)
		if (fabs(r->d[i]) > r->defect)
			r->defect = fabs(r->d[i]);
}

/* The alternatives to try at an operation whose applicable bits are a. */
static int alternatives(unsigned a, unsigned char *alt)
{
	static const unsigned char rnd[3] = { 0, CM_CH_LO, CM_CH_HI };
	int n = 0, r, x;
	const unsigned extra = a & (CM_CH_FLUSH_IN | CM_CH_FLUSH_OUT | CM_CH_FUSE | CM_CH_ZSIGN);
	for (r = 0; r < ((a & (CM_CH_LO | CM_CH_HI)) ? 3 : 1); r++)
		for (x = 0; x < 64; x++)
			if ((x & ~extra) == 0)
				alt[n++] = (unsigned char)(rnd[r] | (unsigned)x);
	return n;
}

double emu_adversarial(cm *c, ref_ctx *rc, const cm_method *m, int prec, const double n[3], const arith_profile *p,
                       int passes, unsigned char *ch, emu_eval *best)
{
	unsigned char avail[CM_EMU_MAXOP], alt[64];
	emu_eval t;
	int pass, k, j, na, ops;
	memset(ch, 0, CM_EMU_MAXOP);
	emu_run(c, rc, m, prec, n, p, CM_EMU_CHOICE, 0, ch, CM_EMU_MAXOP, best);
	ops = best->ops < CM_EMU_MAXOP ? best->ops : CM_EMU_MAXOP;
	for (k = 0; k < ops; k++)
		avail[k] = (unsigned char)cm_emu_avail(c, k);
	for (pass = 0; pass < passes && isfinite(best->defect); pass++) {
		int improved = 0;
		for (k = 0; k < ops; k++) {
			const unsigned char keep = ch[k];
			unsigned char pick = keep;
			na = alternatives(avail[k], alt);
			for (j = 0; j < na; j++) {
				if (alt[j] == keep)
					continue;
				ch[k] = alt[j];
				emu_run(c, rc, m, prec, n, p, CM_EMU_CHOICE, 0, ch, CM_EMU_MAXOP, &t);
				if (t.defect > best->defect) {
					int i;
					*best = t;
					pick = alt[j];
					improved = 1;
					ops = t.ops < CM_EMU_MAXOP ? t.ops : CM_EMU_MAXOP;
					for (i = 0; i < ops; i++)
						avail[i] = (unsigned char)cm_emu_avail(c, i);
				}
			}
			ch[k] = pick;
		}
		if (!improved)
			break;
	}
	return best->defect;
}

/* The proven bound over the box of unit vectors within about 8u of
   n/|n| (bound_box); INFINITY when none. */
double emu_point_bound(const cm_method *m, const arith_profile *p, int prec, const double n[3], int *unb)
{
	const double w = 8.0 * prec_fmt(prec)->u, l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
	double z, r, phi, dphi, b;
	mvf_box x;
	bound_ctx *bc;
	*unb = -1;
	if (!(l > 0.0) || !isfinite(l) || !(bc = bound_new()))
		return INFINITY;
	z = n[2] / l;
	r = sqrt(fmax(0.0, 1.0 - z * z));
	phi = atan2(n[1], n[0]);
	dphi = r > w ? fmin(3.141592653589793, 2.0 * w / r) : 3.141592653589793;
	memset(&x, 0, sizeof x);
	x.z_lo = fmax(-1.0, z - w);
	x.z_hi = fmin(1.0, z + w);
	x.phi_lo = dphi >= 3.141592653589793 ? -3.141592653589793 : phi - dphi;
	x.phi_hi = dphi >= 3.141592653589793 ? 3.141592653589793 : phi + dphi;
	x.nz_lo = x.nz_hi = n[2];
	x.prec = prec;
	x.tolerance = -1.0;
	bound_set_arith(bc, p);
	b = bound_box(bc, m, &x);
	*unb = bound_unbounded_op(bc);
	bound_free(bc);
	return b;
}

