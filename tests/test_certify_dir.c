/*
 * test_certify_dir.c - frisvad_rotate's certified direction error.
 *
 * 1. The model is the kernel: the basis its model forms (CM_EXEC) and
 *    w_i = fl(fl(fl(x b1_i) + fl(y b2_i)) + fl(z n_i)), or (-y, -x, -z)
 *    on the model's n.z = -1 path, give onb_frisvad_rotate's bits on
 *    argv[1] inputs per precision (uniform, both poles down to
 *    1 + n.z = 1e-18, the axes with signed zeros), loc random.
 * 2. Soundness: in regions across the sphere (small boxes between the
 *    poles, next to -z, at the exact axes +x, +y, -x, the bands that hold
 *    -z and +z), many inputs (n, loc), n a rounding of a unit vector of
 *    the region (the exact axes and n.z = -1 among them), loc over the
 *    whole sphere (random, and where the error can be largest), measured
 *    by the reference as `onbstudy eval --local` measures them, never
 *    exceed the region's certified bound (cert_region_run, as certify).
 * 3. The checks can fail: in the small boxes the same inputs exceed the
 *    bound of bound_box_ablate with the dot products' rounding left out
 *    (BOUND_DROP_DOT), and somewhere they exceed half the bound.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "libonb/onb.h"
#include "certify/models.h"
#include "certify/search.h"
#include "certify/found.h"
#include "inputs/inputs.h"
#include "inputs/rng.h"
#include "model/model_int.h"

static double unif(uint64_t *r) { return (double)(rng_mix64((*r)++) >> 11) * 0x1p-53; }

/* The kernel's w on (n, loc), widened to double. */
static void kernel_w(int prec, const double n[3], const double l[3], double w[3])
{
	if (prec == PREC_FLOAT) {
		const onb_vec3f nf = { (float)n[0], (float)n[1], (float)n[2] };
		const onb_vec3f r = onb_frisvad_rotatef(nf, (float)l[0], (float)l[1], (float)l[2]);
		w[0] = r.x; w[1] = r.y; w[2] = r.z;
	} else {
		const onb_vec3 nd = { n[0], n[1], n[2] };
		const onb_vec3 r = onb_frisvad_rotate(nd, l[0], l[1], l[2]);
		w[0] = r.x; w[1] = r.y; w[2] = r.z;
	}
}

/* w from the model's basis b (CM_EXEC values), in the format. */
static void model_w(int prec, const double b[6], const double n[3], const double l[3], double w[3])
{
	int i;
	if (b[0] == 0.0 && b[2] == 0.0) {   /* the special path: b1 = (0, -1, 0) (the formula's b1.x is 1 there) */
		w[0] = -l[1]; w[1] = -l[0]; w[2] = -l[2];
		return;
	}
	for (i = 0; i < 3; i++) {
		if (prec == PREC_FLOAT) {
			const float x = (float)l[0], y = (float)l[1], z = (float)l[2];
			const float p = x * (float)b[i], q = y * (float)b[3 + i], s = p + q, r = z * (float)n[i];
			w[i] = s + r;
		} else {
			const double p = l[0] * b[i], q = l[1] * b[3 + i], s = p + q, r = l[2] * n[i];
			w[i] = s + r;
		}
	}
}

static int same(double a, double b, int prec)
{
	if (prec == PREC_FLOAT) {
		const float fa = (float)a, fb = (float)b;
		return memcmp(&fa, &fb, sizeof fa) == 0;
	}
	return memcmp(&a, &b, sizeof a) == 0;
}

/* 1: model + dot products = kernel, bit for bit. */
static long check_bits(const cm_method *m, int prec, long count)
{
	cm *c = cm_new(CM_EXEC);
	uint64_t r = 12345;
	long i, bad = 0;
	if (!c)
		return -1;
	for (i = 0; i < count; i++) {
		double u[3], n[3], l[3], b[6], kw[3], mw[3], z, ph = 6.283185307179586 * unif(&r), rr;
		cv in[3], out[6];
		int k;
		z = i % 4 == 0 ? 2 * unif(&r) - 1 : i % 4 == 1 ? -1 + pow(10.0, -18 * unif(&r)) : 1 - pow(10.0, -18 * unif(&r));
		rr = sqrt((1 - z) * (1 + z));
		u[0] = rr * cos(ph); u[1] = rr * sin(ph); u[2] = z;
		if (i % 16 == 3) {   /* an axis, signed zeros */
			u[0] = u[1] = u[2] = (i & 32) ? -0.0 : 0.0;
			u[(i >> 6) % 3] = (i & 64) ? -1.0 : 1.0;
		}
		for (k = 0; k < 3; k++) {
			n[k] = fmt_round(u[k], prec);
			l[k] = fmt_round(unif(&r) - 0.5, prec);
		}
		cm_exec_begin(c, prec, n, in);
		cm_run(c, m, prec, in, out);
		for (k = 0; k < 6; k++)
			b[k] = cm_value(c, out[k]);
		kernel_w(prec, n, l, kw);
		model_w(prec, b, n, l, mw);
		if (!(same(kw[0], mw[0], prec) && same(kw[1], mw[1], prec) && same(kw[2], mw[2], prec)) && bad++ < 3)
			printf("  %s: n = (%a, %a, %a) loc = (%a, %a, %a): kernel w.x %a, model %a\n", prec_name(prec),
			       n[0], n[1], n[2], l[0], l[1], l[2], kw[0], mw[0]);
	}
	cm_free(c);
	return bad;
}

/* v scaled to unit length, two components rounded, the largest completed
   (a rounding of a unit vector); 0 when none could be made. */
static int domain_vec(cert_ctx *x, int prec, const double v[3], double jit, double o[3])
{
	const double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
	int i, b, sure;
	double c;
	if (!(len > 0.0))
		return 0;
	for (i = 0; i < 3; i++)
		o[i] = v[i] / len;
	b = cert_biggest(o);
	o[(b + 1) % 3] *= 1.0 + jit;   /* see draw_n */
	for (i = 0; i < 3; i++)
		if (i != b)
			o[i] = fmt_round(o[i], prec);
	c = cert_complete(x, prec, o[(b + 1) % 3], o[(b + 2) % 3], &sure);
	if (isnan(c))
		return 0;
	o[b] = copysign(c, o[b]);
	return sure || cert_in_domain(o, prec, -1.0);
}

typedef struct {
	cert_region r;
	int tiny;   /* small enough for one box: also bounded without the dot's rounding */
} dregion;

/* The screened direction error of (n, loc) (double-double). */
static double screen(int prec, const double n[3], const double l[3])
{
	double w[3], s2;
	kernel_w(prec, n, l, w);
	s2 = found_dot_dd(w, w, 1.0);
	return fmax(fabs(s2 / (1.0 + sqrt(1.0 + s2))), fabs(found_dot_dd(w, n, l[2])));
}

/* An input n of region r: random, or (every 16th) an exact axis or
   n.z = -1 with |(x, y)| tiny when the region holds one. */
static int draw_n(cert_ctx *x, int prec, const cert_region *r, uint64_t *rng, long i, double n[3])
{
	static const double axes[6][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
	double v[3], z, ph = (r->phi_lo + (r->phi_hi - r->phi_lo) * unif(rng)) * 3.14159265358979323846 / 180, rr;
	if (i % 16 == 0) {
		memcpy(n, axes[(i / 16) % 6], sizeof axes[0]);
		return cert_in_region(r, n);
	}
	if (r->nz_lo == -1.0 && i % 4 == 1) {   /* n.z = -1 or next to it: |(x, y)| log-uniform */
		rr = pow(10.0, -30 + 27 * unif(rng));
		v[0] = rr * cos(ph); v[1] = rr * sin(ph); v[2] = -1.0;
	} else {
		z = r->nz_lo + (r->nz_hi - r->nz_lo) * unif(rng);
		if (r->nz_lo <= -0.99 && i % 2)   /* log-spaced in 1 + z */
			z = -1 + (1 + r->nz_hi) * pow(10.0, -8 * unif(rng));
		rr = sqrt((1 - z) * (1 + z));
		v[0] = rr * cos(ph); v[1] = rr * sin(ph); v[2] = z;
	}
	/* in double the completed largest component would land within a tiny
	   part of an ulp of v's (v is unit in double), leaving | |n| - 1 | far
	   below its range near the poles: one other component is moved by a
	   random relative 2^-27 first (as found.c does) */
	return domain_vec(x, prec, v, prec == PREC_DOUBLE ? (unif(rng) - 0.5) * 0x1p-26 : 0.0, n) && cert_in_region(r, n);
}

/* The decomposition certify's bound rests on, checked on one input
   (n, loc) away from the n.z = -1 path: with b1, b2 the kernel's basis
   and w* = x b1 + y b2 + z n exactly, every component obeys
   |w_i - w*_i| <= E_i = (1 + u)^2 (u A_i + 3 eta) + u (1 + u) C_i + u |w*_i|
   (bound.c), so | |w| - 1 | <= | |w*| - 1 | + |E| and
   |w.n - z| <= |w*.n - z| + |E| |n|.  w* - w in double-double (products
   of format values exact), compared with a relative 2^-40 margin.
   Returns 1 when violated; *beyond counts the inputs whose error exceeds
   the part without E (the decomposition with the dot's rounding left
   out, which these inputs show unsound). */
static int pointwise(int prec, const double n[3], const double l[3], long *beyond)
{
	const double u = prec == PREC_FLOAT ? 0x1p-24 : 0x1p-53, eta = prec == PREC_FLOAT ? 0x1p-150 : 0x1p-1074;
	double b[6], w[3], d[3], e2 = 0.0, s2, dn, dc, ws2, wsn;
	int i;
	if (prec == PREC_FLOAT) {
		const onb_vec3f nf = { (float)n[0], (float)n[1], (float)n[2] };
		onb_vec3f b1, b2;
		onb_frisvad_thresholdf(nf, -INFINITY, &b1, &b2);
		b[0] = b1.x; b[1] = b1.y; b[2] = b1.z; b[3] = b2.x; b[4] = b2.y; b[5] = b2.z;
	} else {
		const onb_vec3 nd = { n[0], n[1], n[2] };
		onb_vec3 b1, b2;
		onb_frisvad_threshold(nd, -INFINITY, &b1, &b2);
		b[0] = b1.x; b[1] = b1.y; b[2] = b1.z; b[3] = b2.x; b[4] = b2.y; b[5] = b2.z;
	}
	kernel_w(prec, n, l, w);
	for (i = 0; i < 3; i++) {
		const double q[3] = { b[i], b[3 + i], n[i] };
		const double A = fabs(l[0] * b[i]) + fabs(l[1] * b[3 + i]) + fabs(l[2] * n[i]);
		const double C = fabs(l[0] * b[i] + l[1] * b[3 + i]);
		double E;
		d[i] = found_dot_dd(l, q, w[i]);   /* w*_i - w_i */
		E = (1 + u) * (1 + u) * (u * A + 3 * eta) + u * (1 + u) * C + u * fabs(w[i] + d[i]);
		if (!(fabs(d[i]) <= E * (1 + 0x1p-40) + 0x1p-1060))
			return 1;
		e2 += E * E;
	}
	/* |w*|^2 - 1 = |w|^2 - 1 + 2 w.d + |d|^2, w*.n - z = w.n - z + d.n */
	s2 = found_dot_dd(w, w, 1.0);
	ws2 = s2 + 2 * (w[0] * d[0] + w[1] * d[1] + w[2] * d[2]) + (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
	wsn = found_dot_dd(w, n, l[2]) + (d[0] * n[0] + d[1] * n[1] + d[2] * n[2]);
	dn = fabs(s2 / (1 + sqrt(1 + s2)));
	dc = fabs(found_dot_dd(w, n, l[2]));
	ws2 = fabs(ws2 / (1 + sqrt(1 + ws2)));
	*beyond += dn > ws2 * (1 + 0x1p-30) || dc > fabs(wsn) * (1 + 0x1p-30);
	return !(dn <= (ws2 + sqrt(e2)) * (1 + 0x1p-40) && dc <= (fabs(wsn) + sqrt(e2) * sqrt(found_dot_dd(n, n, 0))) * (1 + 0x1p-40));
}

/* The largest measured direction error over `count` inputs n of r, each
   with the loc of largest screened error among the candidates and random
   ones; *at receives the input. */
static long pw_bad, pw_beyond, pw_checked;

static double worst_of(cert_ctx *x, const study_kernel *k, int prec, const cert_region *r, long count, double at[6])
{
	uint64_t rng = 99 + (uint64_t)(1e6 * (r->nz_lo + 2)) + (uint64_t)r->phi_lo;
	double worst = 0.0;
	long i;
	for (i = 0; i < count; i++) {
		double n[3], c[FOUND_DIR_CAND + 4][3], l[3], bl[3], d, best = -1;
		int j, nc;
		sample_metrics m;
		if (!draw_n(x, prec, r, &rng, i, n))
			continue;
		nc = found_dir_candidates(prec, n, &rng, c);
		for (j = 0; j < 4; j++, nc++) {
			c[nc][0] = unif(&rng) - 0.5; c[nc][1] = unif(&rng) - 0.5; c[nc][2] = unif(&rng) - 0.5;
		}
		for (j = 0; j < nc; j++)
			if (domain_vec(x, prec, c[j], 0.0, l)) {
				if (n[2] != -1.0 && ++pw_checked && pointwise(prec, n, l, &pw_beyond) && pw_bad++ < 3)
					printf("  decomposition violated at n = (%a, %a, %a), loc = (%a, %a, %a)\n", n[0], n[1], n[2],
					       l[0], l[1], l[2]);
				if ((d = screen(prec, n, l)) > best) {
					best = d;
					memcpy(bl, l, sizeof l);
				}
			}
		if (best < 0)
			continue;
		ref_eval(x->rc, k, prec, n, bl, 0, &m);
		d = m.nonfinite ? INFINITY : fmax(m.dir_norm, m.dir_cos);
		if (!(d <= worst)) {
			worst = d;
			memcpy(at, n, 3 * sizeof *n);
			memcpy(at + 3, bl, sizeof bl);
		}
	}
	return worst;
}

/* 2 and 3 on region d in precision prec; returns the failures.  *over_half
   and *over_drop count the regions whose worst input exceeds half the
   bound, and (small boxes) the bound without the dot's rounding. */
static int check_region(cert_ctx *x, const study_kernel *k, const cm_method *m, int prec, const dregion *d,
                        long count, int *over_half, int *over_drop)
{
	cert_opts o;
	cert_result res;
	double at[6] = { 0, 0, 0, 0, 0, 0 }, worst, box = -1, drop = -1;
	mvf_box b;
	memset(&o, 0, sizeof o);
	o.budget = 200; o.samples = 40; o.target = 1.25; o.tolerance = -1.0; o.seed = 1;
	cert_region_run(x, k, m, prec, &d->r, &o, &res);
	worst = worst_of(x, k, prec, &d->r, count, at);
	if (d->tiny) {
		region_box(&d->r, prec, -1.0, &b);
		box = bound_box(x->b, m, &b);
		drop = bound_box_ablate(x->b, m, &b, BOUND_DROP_DOT);
		*over_drop += worst > drop;
	}
	*over_half += worst > 0.5 * res.bound;
	printf("%s %-6s n.z [%.17g, %.17g] phi [%g, %g]: worst %.4g u (found %.4g u) <= bound %.4g u%s", 
	       worst <= res.bound && (box < 0 || worst <= box) ? "ok  " : "FAIL", prec_name(prec), d->r.nz_lo, d->r.nz_hi,
	       d->r.phi_lo, d->r.phi_hi, worst / (prec == PREC_FLOAT ? 0x1p-24 : 0x1p-53),
	       res.found / (prec == PREC_FLOAT ? 0x1p-24 : 0x1p-53), res.bound / (prec == PREC_FLOAT ? 0x1p-24 : 0x1p-53),
	       d->tiny ? "" : "\n");
	if (d->tiny)
		printf("; one box %.4g u, without the dot's rounding %.4g u\n", box / (prec == PREC_FLOAT ? 0x1p-24 : 0x1p-53),
		       drop / (prec == PREC_FLOAT ? 0x1p-24 : 0x1p-53));
	if (!(worst <= res.bound && (box < 0 || worst <= box))) {
		printf("  at n = (%a, %a, %a), loc = (%a, %a, %a)\n", at[0], at[1], at[2], at[3], at[4], at[5]);
		return 1;
	}
	return 0;
}

int main(int argc, char **argv)
{
	const long count = argc > 1 ? atol(argv[1]) : 100000;
	const long per = argc > 2 ? atol(argv[2]) : 1000;
	const cm_method *m = cm_find("frisvad_rotate");
	study_kernel k;
	cert_ctx *x = cert_ctx_new();
	int prec, fail = 0, over_half = 0, over_drop = 0;
	size_t i;
	if (!m || !m->direction || !x || kernels_select("frisvad_rotate", 0, &k, 1) != 1) {
		printf("FAIL: no frisvad_rotate model, kernel or context\n");
		return 1;
	}
	for (prec = PREC_FLOAT; prec <= PREC_DOUBLE; prec++) {
		const double e = prec == PREC_FLOAT ? 2e-7 : 1e-12, bot = prec == PREC_FLOAT ? 1e-7 : 1e-15;
		const dregion rs[] = {
			{ { 0.2, 0.2001, 10, 10.01 }, 1 }, { { -0.6, -0.5999, 200, 200.01 }, 1 },
			{ { -0.3, 0, 0, 90 }, 0 }, { { -1 + e, -1 + 2 * e, 30, 31 }, 0 },
			{ { -1e-4, 1e-4, 0, 0.01 }, 1 }, { { -1e-4, 1e-4, 90, 90.01 }, 1 }, { { -1e-4, 1e-4, 180, 180.01 }, 1 },
			{ { -1, -1 + bot, 0, 360 }, 0 }, { { 1 - 1e-6, 1, 0, 360 }, 0 },
		};
		const long bad = check_bits(m, prec, count);
		printf("%s frisvad_rotate %-6s %ld inputs, %ld not bit-identical\n", bad ? "FAIL" : "ok  ", prec_name(prec), count, bad);
		fail |= bad != 0;
		for (i = 0; i < sizeof rs / sizeof rs[0]; i++)
			fail |= check_region(x, &k, m, prec, &rs[i], per, &over_half, &over_drop);
	}
	printf("%s: %d regions with an input above half their bound (want > 0); %d small boxes with one above the bound without the dot's rounding\n",
	       over_half ? "ok  " : "FAIL", over_half, over_drop);
	printf("%s: the decomposition on %ld inputs: %ld violated; %ld exceed it with the dot's rounding left out (want > 0)\n",
	       !pw_bad && pw_beyond ? "ok  " : "FAIL", pw_checked, pw_bad, pw_beyond);
	fail |= !over_half || pw_bad || !pw_beyond;
	cert_ctx_free(x);
	printf("%s: frisvad_rotate's direction error bounds\n", fail ? "FAIL" : "ok");
	return fail;
}
