/*
 * test_lib.c - libonb: orthonormality within a per-method bound, faithful
 * published failures, batch/scalar/inline bit identity, handedness, and
 * special inputs.
 *
 * Defects are measured in long double (64-bit significand): the products
 * of two doubles carry a relative error of 2^-64, 1/2048 of the double
 * eps, so the measurement error is far below every bound checked.
 *
 * Bounds.  Let u be the unit roundoff of the format (2^-24 or 2^-53) and
 * D(b1, b2, n) = max(| |b1|-1 |, | |b2|-1 |, |b1.n|, |b2.n|, |b1.b2|).
 * The input n itself is unit only within |n|^2 - 1 = delta, |delta| <= 3u
 * (it is rounded from an exact unit vector), and each method amplifies
 * delta and its own roundings by a condition factor c(n):
 *   - duff, duff_branchless, hughes_moeller, pbrt_v3, stark, rtow,
 *     tangent_cross_z away from +-z: c = 1.  Each output component is a
 *     short chain of at most ~6 roundings, so D <= 12u with margin.
 *   - naive: b1 = e - n (n.e) has length sqrt(1 - (n.e)^2); its absolute
 *     error (~3u) is divided by that length when normalized, so
 *     D <= 12u (1 + 1/sqrt(1 - (n.e)^2)).
 *   - rtao (not rtao_fixed): cross(n, 0.3 n + c) = cross(n, c) exactly,
 *     of length |c| s with s the sine of the angle between n and c; the
 *     rounding residue of 0.3 n x n (a few u) is divided by it:
 *     D <= 12u (1 + 2/s).
 *   - frisvad family above t: |b1|^2 - 1 = nx^2 delta / (1 + nz)^2
 *     (Frisvad's Appendix B redone with |n|^2 = 1 + delta), and
 *     nx^2 <= 2 (1 + nz), so D <= 12u (1 + 2/(1 + nz)).  Below t, the fixed
 *     fallback misses by the dropped components: D <= sqrt(1 - nz^2) + 12u.
 *   - approximate normalizations scale an otherwise exact vector by
 *     (1 + r): InvSqrt with one Newton step |r| <= 1.76e-3 (Lomont 2003:
 *     1.75e-3), rsqrtss |r| <= 1.5 * 2^-12, rsqrtss + Newton
 *     |r| <= 1.5 (1.5 * 2^-12)^2 + 3u.  Lengths get r, orthogonality keeps
 *     the exact method's bound.
 *   - nonorm: lengths are the unnormalized ones, checked against their
 *     exact value; orthogonality as the normalized method.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "libonb/onb.h"

#define CHECK_MAX_REPORTS 60
#include "check.h"

/* The inline functions of the header, compiled here with the test's flags
   (the same FP flags as the library), indexed like the registry. */
typedef struct {
	const char *name;
	onb_basis_fn f;
	onb_basisf_fn ff;
} inline_entry;
#define ONB_T_INLINE(m) { #m, onb_##m, onb_##m##f },
#define ONB_T_INLINE_F(m) { #m, NULL, onb_##m##f },
static const inline_entry inlines[] = { ONB_METHOD_LIST(ONB_T_INLINE) ONB_FLOAT_METHOD_LIST(ONB_T_INLINE_F) };
#define NINLINE (sizeof inlines / sizeof inlines[0])

/* splitmix64 */
static uint64_t rng_state = 0x6f6e6273747564ULL; /* "onbstud", fixed seed */
static uint64_t next_u64(void)
{
	uint64_t z = (rng_state += 0x9e3779b97f4a7c15ULL);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	return z ^ (z >> 31);
}
static double uniform01(void) { return (double)(next_u64() >> 11) * 0x1p-53; }

static onb_vec3 random_unit(void)
{
	const double pi = 3.14159265358979323846;
	double z = 2.0 * uniform01() - 1.0, phi = 2.0 * pi * uniform01();
	double r = sqrt(fmax(0.0, 1.0 - z * z));
	onb_vec3 n;
	n.x = r * cos(phi); n.y = r * sin(phi); n.z = z;
	return n;
}

typedef struct { long double len1, len2, d1n, d2n, d12, det; } defect;

static defect measure(long double b1x, long double b1y, long double b1z,
                      long double b2x, long double b2y, long double b2z,
                      long double nx, long double ny, long double nz)
{
	defect d;
	d.len1 = sqrtl(b1x * b1x + b1y * b1y + b1z * b1z) - 1.0L;
	d.len2 = sqrtl(b2x * b2x + b2y * b2y + b2z * b2z) - 1.0L;
	d.d1n = b1x * nx + b1y * ny + b1z * nz;
	d.d2n = b2x * nx + b2y * ny + b2z * nz;
	d.d12 = b1x * b2x + b1y * b2y + b1z * b2z;
	d.det = (b1y * b2z - b1z * b2y) * nx + (b1z * b2x - b1x * b2z) * ny + (b1x * b2y - b1y * b2x) * nz;
	return d;
}

static long double ldmax(long double a, long double b) { return a > b ? a : b; }

/* Bounds, as derived in the header comment.  u: unit roundoff. */
typedef struct { long double len, orth; } bound;

static bound method_bound(const onb_method *m, long double nx, long double ny, long double nz, long double u)
{
	bound b;
	long double c = 1.0L, base;
	if (strcmp(m->family, "naive") == 0) {
		long double ne = nx > 0.9L ? ny : nx;
		long double s = 1.0L - ne * ne;
		c = 1.0L + (s > 0 ? 1.0L / sqrtl(s) : 1e30L);
	} else if (strcmp(m->family, "frisvad") == 0) {
		if (nz < (long double)m->threshold) {
			b.len = b.orth = sqrtl(ldmax(0.0L, 1.0L - nz * nz)) + 12.0L * u;
			return b;
		}
		c = 1.0L + 2.0L / (1.0L + nz);
	} else if (strcmp(m->family, "filament") == 0) { /* frisvad's, with n.y the pole axis */
		if (ny < (long double)m->threshold) {
			b.len = b.orth = sqrtl(ldmax(0.0L, 1.0L - ny * ny)) + 12.0L * u;
			return b;
		}
		c = 1.0L + 2.0L / (1.0L + ny);
	} else if (strcmp(m->family, "rtao") == 0 && m->norm != ONB__WILD_FIXED) {
		/* the helper c = (-0.72, 0.56, -0.34): cross(n, 0.3 n + c) has
		   length |c| s, s = |n x c|/|c|, and the residue of 0.3 n x n (~u) */
		const long double cx = -0.72L, cy = 0.56L, cz = -0.34L, cl = sqrtl(cx * cx + cy * cy + cz * cz);
		const long double px = ny * cz - nz * cy, py = nz * cx - nx * cz, pz = nx * cy - ny * cx;
		const long double sn = sqrtl(px * px + py * py + pz * pz) / cl;
		c = 1.0L + (sn > 0 ? 2.0L / sn : 1e30L);
	} else if (strcmp(m->family, "babylon") == 0) {
		/* theta = acos(y/r): the rounding of y/r moves theta by about
		   u |y|/rho (acos' = -1/sqrt(1 - t^2), rho = sqrt(x^2 + z^2)/r),
		   and |b1.n| follows theta's error (docs/wild-specs/babylon.md) */
		const long double rho = sqrtl(nx * nx + nz * nz) / sqrtl(nx * nx + ny * ny + nz * nz);
		c = 1.0L + (rho > 0 ? 2.0L / rho : 1e30L);
	} else if (strcmp(m->family, "physx") == 0 && m->norm != ONB__WILD_FIXED && fabsl(ny) > (long double)0.9999f) {
		/* PhysX's fallback b1 = (1, 0, 0): b1.n = n.x, |n.x| <= sqrt(1 - n.y^2) */
		b.len = b.orth = sqrtl(ldmax(0.0L, 1.0L - ny * ny)) + 12.0L * u;
		return b;
	}
	base = 12.0L * u * c;
	b.len = b.orth = base;
	switch (m->norm) {
	case ONB__NORM_INVSQRT:  b.len = 1.76e-3L + base; break;
	case ONB__NORM_RSQRT:    b.len = 1.5L * 0x1p-12L + base; break;
	case ONB__NORM_RSQRT_NR: b.len = 1.5L * (1.5L * 0x1p-12L) * (1.5L * 0x1p-12L) + 3.0L * u + base; break;
	case ONB__NORM_NONE:     b.len = 1.0L; break; /* checked against the exact length instead */
	default: break;
	}
	if (strcmp(m->family, "embree") == 0) /* rsqrtss and one Newton step, in Embree's order */
		b.len = 1.5L * (1.5L * 0x1p-12L) * (1.5L * 0x1p-12L) + 3.0L * u + base;
	return b;
}

/* Scale-free orthogonality: dot / (|a| |b|). */
static void check_one(const onb_method *m, int prec, long double nx, long double ny, long double nz,
                      const long double b[6], long double u, int *reported)
{
	defect d = measure(b[0], b[1], b[2], b[3], b[4], b[5], nx, ny, nz);
	bound bd = method_bound(m, nx, ny, nz, u);
	long double l1 = d.len1 + 1.0L, l2 = d.len2 + 1.0L, ln = sqrtl(nx * nx + ny * ny + nz * nz);
	long double o1 = fabsl(d.d1n) / (l1 * ln), o2 = fabsl(d.d2n) / (l2 * ln), o12 = fabsl(d.d12) / (l1 * l2);
	long double orth = ldmax(o1, ldmax(o2, o12));
	long double len = ldmax(fabsl(d.len1), fabsl(d.len2));
	int ok = orth <= bd.orth && (m->norm == ONB__NORM_NONE || len <= bd.len);
	int hand_ok = (d.det > 0) == (m->handedness > 0);
	if (m->norm == ONB__NORM_NONE && m->threshold != m->threshold) {
		/* Unnormalized: the length must be the exact length of the
		   unnormalized vector, up to c * 12u relative. */
		long double want;
		if (strcmp(m->family, "naive") == 0) {
			long double ne = nx > 0.9L ? ny : nx;
			want = sqrtl(ldmax(0.0L, 1.0L - ne * ne));
			/* b1 = e - n (n.e): |b1|^2 = 1 - 2 (n.e)^2 + (n.e)^2 |n|^2 */
			want = sqrtl(ldmax(0.0L, 1.0L - 2.0L * ne * ne + ne * ne * (nx * nx + ny * ny + nz * nz)));
			ok = ok && fabsl(l1 - want) <= bd.orth;
		} else { /* hughes_moeller: b2 = (-ny, nx, 0) or (0, -nz, ny), exactly */
			want = fabsl(nx) > fabsl(nz) ? sqrtl(nx * nx + ny * ny) : sqrtl(nz * nz + ny * ny);
			ok = ok && fabsl(l2 - want) <= 2.0L * u;
		}
	}
	if (!ok || !hand_ok) {
		if (*reported < 3)
			printf("  %s/%s n=(%La, %La, %La): len %.3Lg (bound %.3Lg) orth %.3Lg (bound %.3Lg) det %.3Lg (want sign %+d)\n",
			       m->name, prec ? "double" : "float", nx, ny, nz, len, bd.len, orth, bd.orth, d.det, m->handedness);
		(*reported)++;
	}
	CHECK(ok, "%s/%s orthonormal within bound", m->name, prec ? "double" : "float");
	CHECK(hand_ok, "%s/%s handedness %+d", m->name, prec ? "double" : "float", m->handedness);
}

#define NRANDOM 200000

static void test_random_and_axes(void)
{
	size_t count, i, k;
	const onb_method *ms = onb_methods(&count);
	static const double axes[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
	for (i = 0; i < count; i++) {
		const onb_method *m = &ms[i];
		int rep_d = 0, rep_f = 0, p0 = passed, f0 = failed;
		rng_state = 12345;
		for (k = 0; k < NRANDOM + 6; k++) {
			onb_vec3 n, b1, b2;
			onb_vec3f nf, b1f, b2f;
			long double b[6];
			if (k < NRANDOM) {
				n = random_unit();
			} else {
				n.x = axes[k - NRANDOM][0]; n.y = axes[k - NRANDOM][1]; n.z = axes[k - NRANDOM][2];
				/* Published singular axes are tested in test_faithful. */
				if (strcmp(m->family, "naive") == 0 && n.x == -1.0)
					continue;
				if (strcmp(m->family, "tangent_cross_z") == 0 && n.z != 0.0)
					continue;
			}
			if (m->basis) { /* NULL for the float-only methods */
				m->basis(n, &b1, &b2);
				b[0] = b1.x; b[1] = b1.y; b[2] = b1.z; b[3] = b2.x; b[4] = b2.y; b[5] = b2.z;
				check_one(m, 1, n.x, n.y, n.z, b, 0x1p-53L, &rep_d);
			}
			nf.x = (float)n.x; nf.y = (float)n.y; nf.z = (float)n.z;
			m->basisf(nf, &b1f, &b2f);
			b[0] = b1f.x; b[1] = b1f.y; b[2] = b1f.z; b[3] = b2f.x; b[4] = b2f.y; b[5] = b2f.z;
			check_one(m, 0, nf.x, nf.y, nf.z, b, 0x1p-24L, &rep_f);
		}
		printf("  %-24s random+axes: %d checks, %d failed\n", m->name, passed + failed - p0 - f0, failed - f0);
	}
}

/* Value bits, with every NaN as one pattern: IEEE 754 leaves a generated
   NaN's sign and payload open, and arm64's scalar and vector code give
   different ones where x86-64's agree (make cross-check). */
static uint64_t bits64(double x)
{
	uint64_t u;
	memcpy(&u, &x, sizeof u);
	return x != x ? UINT64_C(0x7ff8000000000000) : u;
}
static uint32_t bits32(float x)
{
	uint32_t u;
	memcpy(&u, &x, sizeof u);
	return x != x ? UINT32_C(0x7fc00000) : u;
}

static int same3(onb_vec3 a, onb_vec3 b)
{
	return bits64(a.x) == bits64(b.x) && bits64(a.y) == bits64(b.y) && bits64(a.z) == bits64(b.z);
}
static int same3f(onb_vec3f a, onb_vec3f b)
{
	return bits32(a.x) == bits32(b.x) && bits32(a.y) == bits32(b.y) && bits32(a.z) == bits32(b.z);
}

#define NB 1037

/* The array entry (the registry row's, = onb_NAME_array[f]) gives the
   inline kernel's bits: each entry stores its outputs its own way
   (src/lib/split.h, ONB__STORE3), so each is compared.  Returns 1 when
   they agree. */
static int array_same(const onb_method *m, size_t i, onb_vec3 n, onb_vec3f nf)
{
	double a[6];
	float af[6];
	onb_vec3 c1, c2, w1, w2;
	onb_vec3f c1f, c2f, w1f, w2f;
	int same = 1;
	if (m->array) {
		m->array(&n.x, a, a + 3);
		inlines[i].f(n, &c1, &c2);
		w1.x = a[0]; w1.y = a[1]; w1.z = a[2]; w2.x = a[3]; w2.y = a[4]; w2.z = a[5];
		same = same3(w1, c1) && same3(w2, c2);
	}
	m->arrayf(&nf.x, af, af + 3);
	inlines[i].ff(nf, &c1f, &c2f);
	w1f.x = af[0]; w1f.y = af[1]; w1f.z = af[2]; w2f.x = af[3]; w2f.y = af[4]; w2f.z = af[5];
	return same && same3f(w1f, c1f) && same3f(w2f, c2f);
}

/* onb_frisvad_threshold_outline[f] == the inline tool, bitwise, at the
   published t, at Max's and at -2 (never the fallback). */
static void threshold_identity(const double *nx, const double *ny, const double *nz)
{
	static const double ts[] = { -0.9999999, -0.999805696, -2.0 };
	size_t k, j;
	int bad = 0;
	for (j = 0; j < sizeof ts / sizeof ts[0]; j++)
		for (k = 0; k < NB; k++) {
			onb_vec3 n, b1, b2, c1, c2;
			onb_vec3f nf, b1f, b2f, c1f, c2f;
			n.x = nx[k]; n.y = ny[k]; n.z = nz[k];
			nf.x = (float)n.x; nf.y = (float)n.y; nf.z = (float)n.z;
			onb_frisvad_threshold_outline(n, ts[j], &b1, &b2);
			onb_frisvad_threshold(n, ts[j], &c1, &c2);
			onb_frisvad_threshold_outlinef(nf, (float)ts[j], &b1f, &b2f);
			onb_frisvad_thresholdf(nf, (float)ts[j], &c1f, &c2f);
			bad += !same3(b1, c1) || !same3(b2, c2) || !same3f(b1f, c1f) || !same3f(b2f, c2f);
		}
	CHECK(bad == 0, "frisvad_threshold: inline == out-of-line bitwise (%d differ)", bad);
}

/* Batch, out-of-line, array and inline give the same bits, on random
   inputs and on the special ones, for counts that exercise the vector
   epilogues and the 256-element blocks of the rsqrt loops. */
static void test_bit_identity(void)
{
	size_t count, i, k;
	const onb_method *ms = onb_methods(&count);
	static double nx[NB], ny[NB], nz[NB], o[6][NB];
	static float fx[NB], fy[NB], fz[NB], of[6][NB];
	CHECK(count == NINLINE, "registry has %zu methods, the header lists %zu", count, (size_t)NINLINE);
	rng_state = 777;
	for (k = 0; k < NB; k++) {
		onb_vec3 n = random_unit();
		if (k < 40) { /* specials: axes, signed zeros, near the poles and thresholds */
			static const double sp[][3] = {
				{ 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 },
				{ 0, 0, -0.0 }, { -0.0, -0.0, -1 }, { 0.0, -0.0, 1 }, { 1, -0.0, -0.0 },
				{ 0x1p-12, 0, -0.99999997 }, { 4.8e-4, 0, -0.99999988 }, { 4.9e-3, 0, -0.99998796 },
				{ 0.6, 0.0, 0.8 }, { 0.70710678118654752, 0, 0.70710678118654752 }, { 0.9, 0.43588989435406736, 0 },
			};
			size_t j = k % (sizeof sp / sizeof sp[0]);
			n.x = sp[j][0]; n.y = sp[j][1]; n.z = sp[j][2];
		}
		nx[k] = n.x; ny[k] = n.y; nz[k] = n.z;
		fx[k] = (float)n.x; fy[k] = (float)n.y; fz[k] = (float)n.z;
	}
	for (i = 0; i < count; i++) {
		const onb_method *m = &ms[i];
		int bad_d = 0, bad_f = 0, bad_i = 0, bad_a = 0;
		CHECK(strcmp(m->name, inlines[i].name) == 0, "registry order %s vs header list %s", m->name, inlines[i].name);
		CHECK(!m->basis == !m->batch && !m->basis == !inlines[i].f && !m->basis == !!(m->flags & ONB_FLOAT_ONLY),
		      "%s: float-only methods have neither double scalar nor double batch", m->name);
		if (m->batch)
			m->batch(NB, nx, ny, nz, o[0], o[1], o[2], o[3], o[4], o[5]);
		m->batchf(NB, fx, fy, fz, of[0], of[1], of[2], of[3], of[4], of[5]);
		for (k = 0; k < NB; k++) {
			onb_vec3 n, b1, b2, c1, c2, w1, w2;
			onb_vec3f nf, b1f, b2f, c1f, c2f, w1f, w2f;
			n.x = nx[k]; n.y = ny[k]; n.z = nz[k];
			nf.x = fx[k]; nf.y = fy[k]; nf.z = fz[k];
			if (m->basis) {
				m->basis(n, &b1, &b2);
				inlines[i].f(n, &c1, &c2);
				w1.x = o[0][k]; w1.y = o[1][k]; w1.z = o[2][k]; w2.x = o[3][k]; w2.y = o[4][k]; w2.z = o[5][k];
				if (!same3(b1, w1) || !same3(b2, w2)) {
					if (!bad_d)
						printf("  %s double batch differs at n=(%a,%a,%a): b1.x %a vs %a\n", m->name, n.x, n.y, n.z, w1.x, b1.x);
					bad_d++;
				}
				if (!same3(b1, c1) || !same3(b2, c2))
					bad_i++;
			}
			m->basisf(nf, &b1f, &b2f);
			inlines[i].ff(nf, &c1f, &c2f);
			w1f.x = of[0][k]; w1f.y = of[1][k]; w1f.z = of[2][k]; w2f.x = of[3][k]; w2f.y = of[4][k]; w2f.z = of[5][k];
			if (!same3f(b1f, w1f) || !same3f(b2f, w2f)) {
				if (!bad_f)
					printf("  %s float batch differs at n=(%a,%a,%a): b1.x %a vs %a\n", m->name, nf.x, nf.y, nf.z, w1f.x, b1f.x);
				bad_f++;
			}
			if (!same3f(b1f, c1f) || !same3f(b2f, c2f))
				bad_i++;
			bad_a += !array_same(m, i, n, nf);
		}
		CHECK(bad_d == 0, "%s: double batch == scalar bitwise (%d differ)", m->name, bad_d);
		CHECK(bad_f == 0, "%s: float batch == scalar bitwise (%d differ)", m->name, bad_f);
		CHECK(bad_i == 0, "%s: inline == out-of-line bitwise (%d differ)", m->name, bad_i);
		CHECK(bad_a == 0, "%s: inline == array entry bitwise (%d differ)", m->name, bad_a);
	}
	printf("  bit identity: batch (isa %s) vs scalar vs array vs inline, %d inputs x %zu methods\n", onb_batch_isa(), NB, count);
	threshold_identity(nx, ny, nz);
}

/* The published failures, reproduced, not fixed. */
static void test_faithful(void)
{
	onb_vec3 n, b1, b2;
	onb_vec3f nf, b1f, b2f;
	defect d;

	/* frisvad at n = -z exactly: the fallback of Listing 2. */
	nf.x = 0.0f; nf.y = 0.0f; nf.z = -1.0f;
	onb_frisvadf(nf, &b1f, &b2f);
	CHECK(b1f.x == 0.0f && b1f.y == -1.0f && b1f.z == 0.0f && b2f.x == -1.0f && b2f.y == 0.0f && b2f.z == 0.0f,
	      "frisvad(-z) is the published fallback");

	/* frisvad in float at its threshold.  t = -0.9999999f is the float
	   -0x1.fffffcp-1 = -(1 - 2^-23), and n.z < t is false there, so the
	   formula runs with 1 + n.z = 2^-23.  The input is the float rounding
	   of an exact unit vector with n.z = -1 + 2.4 * 2^-24 at azimuth 1 rad,
	   as a renderer would receive it: rounding n.z moved it by 0.4 * 2^-24,
	   so |n|^2 = 1 + delta with delta ~ 0.8 * 2^-24.  Frisvad's Appendix B,
	   redone without |n| = 1, gives |b1|^2 - 1 = nx^2 delta / (1 + nz)^2,
	   and nx^2 ~ 2 (1 + nz), so ~ 2 delta / 2^-23 ~ 0.8: O(1).  The library
	   must reproduce that failure, through exactly the listing's
	   arithmetic. */
	{
		double ze = -1.0 + 2.4 * 0x1p-24, r = sqrt(1.0 - ze * ze);
		long double delta, pred;
		nf.z = (float)ze;
		nf.x = (float)(r * cos(1.0));
		nf.y = (float)(r * sin(1.0));
		delta = (long double)nf.x * nf.x + (long double)nf.y * nf.y + (long double)nf.z * nf.z - 1.0L;
		pred = (long double)nf.x * nf.x * delta / ((1.0L + nf.z) * (1.0L + nf.z));
		onb_frisvadf(nf, &b1f, &b2f);
		{
			const float a = 1.0f / (1.0f + nf.z), b = -nf.x * nf.y * a;
			const float want = 1.0f - nf.x * nf.x * a;
			CHECK(bits32(b1f.x) == bits32(want) && bits32(b1f.y) == bits32(b) && b1f.z == -nf.x,
			      "frisvadf above t is Listing 2's arithmetic bit for bit");
		}
		d = measure(b1f.x, b1f.y, b1f.z, b2f.x, b2f.y, b2f.z, nf.x, nf.y, nf.z);
		{
			long double got = (d.len1 + 1.0L) * (d.len1 + 1.0L) - 1.0L;
			printf("  frisvadf at n=(%a, %a, %a): delta = %.3Lg, |b1|^2-1 = %.4Lg, predicted %.4Lg\n",
			       nf.x, nf.y, nf.z, delta, got, pred);
			CHECK(fabsl(got) > 1e-2L, "frisvadf just above t: |b1|^2-1 = %.3Lg is the published O(1) failure", got);
			CHECK(fabsl(got - pred) <= 0.05L * fabsl(pred) + 1e-5L, "frisvadf: failure %.4Lg is the one the source implies (%.4Lg)", got, pred);
		}
	}
	/* ...and duff on the same input stays within a few ulps. */
	onb_dufff(nf, &b1f, &b2f);
	d = measure(b1f.x, b1f.y, b1f.z, b2f.x, b2f.y, b2f.z, nf.x, nf.y, nf.z);
	CHECK(fabsl(d.len1) < 8 * 0x1p-24L && fabsl(d.d1n) < 8 * 0x1p-24L, "duff on the same input: %.3Lg, %.3Lg", d.len1, d.d1n);

	/* frisvad_max at the same input takes its fallback (t = -0.99998796). */
	onb_frisvad_maxf(nf, &b1f, &b2f);
	CHECK(b1f.y == -1.0f && b2f.x == -1.0f, "frisvad_max below its threshold takes the fallback");

	/* tangent_cross_z at +-z: cross(n, t) = 0, normalize gives 0/0 = NaN. */
	n.x = 0; n.y = 0; n.z = 1;
	onb_tangent_cross_z(n, &b1, &b2);
	CHECK(isnan(b2.x) && isnan(b1.x), "tangent_cross_z(+z) is NaN, as the source implies");
	n.z = -1;
	onb_tangent_cross_z(n, &b1, &b2);
	CHECK(isnan(b2.x) && isnan(b1.x), "tangent_cross_z(-z) is NaN");
	nf.x = 0; nf.y = 0; nf.z = -1;
	onb_tangent_cross_zf(nf, &b1f, &b2f);
	CHECK(isnan(b2f.y), "tangent_cross_zf(-z) is NaN");

	/* naive at -x: b1 = x - n (n.x) = 0, rsqrt(0) = inf, 0 * inf = NaN. */
	n.x = -1; n.y = 0; n.z = 0;
	onb_naive(n, &b1, &b2);
	CHECK(isnan(b1.x), "naive(-x) is NaN (Listing 1 has no guard)");
	n.x = 0.9; n.y = sqrt(1 - 0.81); n.z = 0; /* n.x > 0.9 is false at 0.9: x-axis branch */
	onb_naive(n, &b1, &b2);
	CHECK(b1.y != 0.0, "naive at n.x = 0.9 takes the x-axis branch (b1.y = %a)", b1.y);
}

/* Every method on every signed-zero axis: finite (except the published
   singular ones), exactly orthogonal, exactly unit (unless the
   normalization is approximate by design), right sign of det. */
static void test_signed_zero_axes(void)
{
	onb_vec3 n, b1, b2;
	size_t count, i;
	const onb_method *ms = onb_methods(&count);

	for (i = 0; i < count; i++) {
		/* Open3D crosses with (0, 1, 1): its frames at the axes are diagonal,
		   (0, c, -c)-like, whose length is 2c^2, not exactly 1; so are
		   DirectXMath's at +-x (p = (0, -x, -x) or (0, -x, x)) */
		const int diagonal = strcmp(ms[i].family, "open3d") == 0 || strcmp(ms[i].family, "directxmath") == 0;
		/* Babylon.js's angles leave cos(PI/2) = 6.1e-17 and sin(PI) =
		   1.2e-16 in its frames at the axes, as its own doubles do: within
		   2^-52, not exact */
		const double tol = strcmp(ms[i].family, "babylon") == 0 ? 0x1p-52 : 0.0;
		int ax, s, zs, bad = 0, irr;
		for (ax = 0; ax < 3; ax++)
			for (s = -1; s <= 1; s += 2)
				for (zs = 0; zs < 4; zs++) {
					double v[3];
					defect d;
					v[0] = (zs & 1) ? -0.0 : 0.0; v[1] = (zs & 2) ? -0.0 : 0.0; v[2] = v[1];
					v[(ax + 1) % 3] = (zs & 1) ? -0.0 : 0.0;
					v[(ax + 2) % 3] = (zs & 2) ? -0.0 : 0.0;
					v[ax] = s;
					n.x = v[0]; n.y = v[1]; n.z = v[2];
					if (strcmp(ms[i].family, "naive") == 0 && n.x == -1.0)
						continue;
					if (strcmp(ms[i].family, "tangent_cross_z") == 0 && fabs(n.z) == 1.0)
						continue;
					if (ms[i].basis) {
						ms[i].basis(n, &b1, &b2);
					} else { /* float only: the float frame, widened */
						onb_vec3f vf, p1, p2;
						vf.x = (float)n.x; vf.y = (float)n.y; vf.z = (float)n.z;
						ms[i].basisf(vf, &p1, &p2);
						b1.x = p1.x; b1.y = p1.y; b1.z = p1.z; b2.x = p2.x; b2.y = p2.y; b2.z = p2.z;
					}
					d = measure(b1.x, b1.y, b1.z, b2.x, b2.y, b2.z, n.x, n.y, n.z);
					/* cycles_cross111's b1 at an axis is (0, -1, 1)/sqrt(2) rounded, rtao's
					   b2 (0, -0.34, -0.56)/|.|-like: exactly orthogonal, not exactly unit */
					irr = strcmp(ms[i].family, "cycles_cross111") == 0 || strcmp(ms[i].family, "rtao") == 0;
					if (!(isfinite(b1.x) && isfinite(b1.y) && isfinite(b1.z) && isfinite(b2.x) && isfinite(b2.y) && isfinite(b2.z)
					      && ((ms[i].flags & ONB_APPROX_NORM) || irr || diagonal || (fabsl(d.len1) <= tol && fabsl(d.len2) <= tol))
					      && fabsl(d.d1n) <= tol && fabsl(d.d2n) <= tol && fabsl(d.d12) <= tol
					      && (d.det > 0) == (ms[i].handedness > 0))) {
						if (!bad)
							printf("  %s at (%g,%g,%g): b1=(%g,%g,%g) b2=(%g,%g,%g)\n", ms[i].name, n.x, n.y, n.z,
							       b1.x, b1.y, b1.z, b2.x, b2.y, b2.z);
						bad++;
					}
				}
		CHECK(bad == 0, "%s: exact frames on the signed-zero axes (%d bad)", ms[i].name, bad);
	}

}

/* Frisvad's Equation 3 against the basis it implies, and its singular
   case (-y, -x, -z); frisvad_threshold with t = -2. */
static void test_frisvad_rotate(void)
{
	onb_vec3 n, b1, b2;
	onb_vec3f nf, b1f, b2f;

	n.x = 0.0; n.y = 0.0; n.z = -1.0;
	{
		onb_vec3 w = onb_frisvad_rotate(n, 0.25, 0.5, 0.75);
		CHECK(w.x == -0.5 && w.y == -0.25 && w.z == -0.75, "frisvad_rotate(-z) = (-y, -x, -z)");
	}
	rng_state = 99;
	{
		int bad = 0, k;
		for (k = 0; k < 10000; k++) {
			onb_vec3 w, v;
			double x = 0.36, y = 0.48, z = 0.8;
			n = random_unit();
			if (n.z < -0.9)
				continue;
			w = onb_frisvad_rotate(n, x, y, z);
			onb_frisvad_threshold(n, -1.0, &b1, &b2);
			v.x = x * b1.x + y * b2.x + z * n.x;
			v.y = x * b1.y + y * b2.y + z * n.y;
			v.z = x * b1.z + y * b2.z + z * n.z;
			if (fabs(w.x - v.x) > 1e-15 || fabs(w.y - v.y) > 1e-15 || fabs(w.z - v.z) > 1e-15)
				bad++;
		}
		CHECK(bad == 0, "frisvad_rotate = x b1 + y b2 + z n within 1e-15 (10 ulps at |w| <= 1) (%d bad)", bad);
	}
	/* onb_frisvad_threshold with t = -2 never takes the fallback; at -z it
	   divides by zero: inf/NaN, not UB (IEEE). */
	nf.x = 0; nf.y = 0; nf.z = -1;
	onb_frisvad_thresholdf(nf, -2.0f, &b1f, &b2f);
	CHECK(!isfinite(b1f.x), "frisvad_threshold(-z, t=-2) runs the formula into 1/0 (b1.x = %g)", b1f.x);
}

/* Exact values at the axes and signed zeros. */
static void test_special(void)
{
	onb_vec3 n, b1, b2, c1, c2;
	onb_vec3f nf, b1f, b2f;

	/* duff and duff_branchless at -z: b1 = (1,0,0), b2 = (0,-1,0). */
	n.x = 0.0; n.y = 0.0; n.z = -1.0;
	onb_duff(n, &b1, &b2);
	onb_duff_branchless(n, &c1, &c2);
	CHECK(b1.x == 1 && b1.y == 0 && b1.z == 0 && b2.x == 0 && b2.y == -1 && b2.z == 0, "duff(-z) = (1,0,0),(0,-1,0)");
	CHECK(same3(b1, c1) && same3(b2, c2), "duff and duff_branchless agree at -z");

	/* n.z = -0: duff's `n.z < 0` is false (upper branch), branchless
	   copysign sees the sign bit (lower branch).  Both are valid frames,
	   mirrored in y: the documented difference. */
	n.x = 1.0; n.y = 0.0; n.z = -0.0;
	onb_duff(n, &b1, &b2);
	onb_duff_branchless(n, &c1, &c2);
	CHECK(b2.y == 1.0 && c2.y == -1.0, "n.z = -0: duff b2.y = %g (upper), branchless b2.y = %g (lower)", b2.y, c2.y);
	nf.x = 1.0f; nf.y = 0.0f; nf.z = -0.0f;
	{
		onb_vec3f c1f, c2f;
		onb_dufff(nf, &b1f, &b2f);
		onb_duff_branchlessf(nf, &c1f, &c2f);
		CHECK(b2f.y == 1.0f && b1f.z == -1.0f && c2f.y == -1.0f && c1f.z == 1.0f,
		      "float, n = (1,0,-0): duff b2.y = %g, branchless b2.y = %g", b2f.y, c2f.y);
	}
	test_signed_zero_axes();
	test_frisvad_rotate();
}

/* The checked entry point. */
static void test_checked(void)
{
	const onb_method *m = onb_find("duff_branchless");
	onb_vec3 n, b1, b2, used;
	onb_vec3f nf, b1f, b2f, usedf;
	n.x = 0; n.y = 0; n.z = 0;
	CHECK(onb_basis_checked(m, n, &b1, &b2, &used) == ONB_ZERO && b1.x == 1.0 && b2.y == 1.0, "checked: zero");
	n.x = NAN;
	CHECK(onb_basis_checked(m, n, &b1, &b2, &used) == ONB_NONFINITE, "checked: NaN");
	n.x = 0; n.z = -INFINITY;
	CHECK(onb_basis_checked(m, n, &b1, &b2, &used) == ONB_NONFINITE, "checked: -inf");
	n.x = 3e300; n.y = 4e300; n.z = 0;
	CHECK(onb_basis_checked(m, n, &b1, &b2, &used) == ONB_RENORMALIZED && fabs(used.x - 0.6) < 1e-15 && fabs(used.y - 0.8) < 1e-15,
	      "checked: huge input renormalized without overflow (%g, %g)", used.x, used.y);
	n.x = 0x1p-1070; n.y = 0; n.z = -0x1p-1070;
	CHECK(onb_basis_checked(m, n, &b1, &b2, &used) == ONB_RENORMALIZED && fabs(used.x - 0.70710678118654752) < 1e-15,
	      "checked: subnormal input renormalized (%a)", used.x);
	n.x = 0; n.y = 0; n.z = 1;
	CHECK(onb_basis_checked(m, n, &b1, &b2, &used) == ONB_OK && b1.x == 1.0, "checked: unit input passes through");
	CHECK(onb_basis_checked(NULL, n, &b1, &b2, &used) == ONB_BAD_METHOD, "checked: NULL method");
	nf.x = 0; nf.y = 2; nf.z = 0;
	CHECK(onb_basis_checkedf(onb_find("frisvad"), nf, &b1f, &b2f, &usedf) == ONB_RENORMALIZED && usedf.y == 1.0f, "checkedf: renormalized");
	CHECK(onb_find("no_such_method") == NULL && onb_find(NULL) == NULL, "onb_find: unknown names give NULL");
}

/* The float-only methods (this project's, not published):
   duff_wide is duff_branchless's formula rounded once from double, so on
   random float input it must match the formula evaluated in long double
   and rounded once, except where a component lies within a few 2^-53 of a
   float rounding boundary; both it and duff_comp must beat float
   duff_branchless's largest defect clearly (the floor is about half of
   it); the double entry points are absent and onb_basis_checked refuses
   them. */
#define NFLOOR 400000
static void test_floor_methods(void)
{
	const onb_method *w = onb_find("duff_wide"), *c = onb_find("duff_comp"), *d0 = onb_find("duff_branchless");
	long double mx[3] = { 0, 0, 0 };
	int k, j, differ = 0, comp_differ = 0;
	CHECK(w && c && d0, "duff_wide, duff_comp in the registry");
	if (!w || !c || !d0)
		return;
	CHECK(!w->basis && !w->batch && !c->basis && !c->batch && (w->flags & ONB_FLOAT_ONLY) && (c->flags & ONB_FLOAT_ONLY)
	      && !strcmp(w->family, "duff_branchless") && !strcmp(c->family, "duff_branchless"),
	      "float-only entries: no double pointers, flag set, Duff's family");
	{
		onb_vec3 n = { 0.0, 0.0, 1.0 }, b1, b2;
		CHECK(onb_basis_checked(w, n, &b1, &b2, NULL) == ONB_BAD_METHOD, "checked: float-only method in double is refused");
	}
	rng_state = 4242;
	for (k = 0; k < NFLOOR; k++) {
		onb_vec3 n = random_unit();
		onb_vec3f nf, b1[3], b2[3];
		long double x, y, z, s, a, want[6];
		float got[6], gotc[6];
		if (k < NFLOOR / 2) { /* half of them crowded near -z, as in the issue */
			const double r = sqrt(fmax(0.0, 1.0 - n.z * n.z));
			n.z = -1.0 + ldexp(uniform01(), -(int)(next_u64() % 24));
			n.x = sqrt(fmax(0.0, 1.0 - n.z * n.z)) * (n.x / (r > 0.0 ? r : 1.0));
			n.y = sqrt(fmax(0.0, 1.0 - n.z * n.z)) * (n.y / (r > 0.0 ? r : 1.0));
		}
		nf.x = (float)n.x; nf.y = (float)n.y; nf.z = (float)n.z;
		d0->basisf(nf, &b1[0], &b2[0]);
		w->basisf(nf, &b1[1], &b2[1]);
		c->basisf(nf, &b1[2], &b2[2]);
		for (j = 0; j < 3; j++) {
			defect e = measure(b1[j].x, b1[j].y, b1[j].z, b2[j].x, b2[j].y, b2[j].z, nf.x, nf.y, nf.z);
			long double m = ldmax(fabsl(e.len1), ldmax(fabsl(e.len2), ldmax(fabsl(e.d1n), ldmax(fabsl(e.d2n), fabsl(e.d12)))));
			mx[j] = ldmax(mx[j], m);
		}
		x = nf.x; y = nf.y; z = nf.z;
		s = signbit(nf.z) ? -1.0L : 1.0L;
		a = -1.0L / (s + z);
		want[0] = 1.0L + s * x * x * a; want[1] = s * x * y * a; want[2] = -s * x;
		want[3] = x * y * a; want[4] = s + y * y * a; want[5] = -y;
		got[0] = b1[1].x; got[1] = b1[1].y; got[2] = b1[1].z; got[3] = b2[1].x; got[4] = b2[1].y; got[5] = b2[1].z;
		gotc[0] = b1[2].x; gotc[1] = b1[2].y; gotc[2] = b1[2].z; gotc[3] = b2[2].x; gotc[4] = b2[2].y; gotc[5] = b2[2].z;
		for (j = 0; j < 6; j++) {
			differ += bits32(got[j]) != bits32((float)want[j]);
			comp_differ += bits32(gotc[j]) != bits32(got[j]);
		}
	}
	printf("  floor methods, %d float inputs: max defect duff_branchless %.3Lg, duff_wide %.3Lg, duff_comp %.3Lg;"
	       " duff_wide != long double rounded once: %d of %d components; duff_comp != duff_wide: %d\n",
	       NFLOOR, mx[0], mx[1], mx[2], differ, 6 * NFLOOR, comp_differ);
	CHECK(differ <= 6 * NFLOOR / 10000, "duff_wide is the formula rounded once but for rare near-ties (%d differ)", differ);
	CHECK(mx[1] <= 0.7L * mx[0], "duff_wide's largest defect %.3Lg well below duff_branchless's %.3Lg", mx[1], mx[0]);
	CHECK(mx[2] <= 0.7L * mx[0], "duff_comp's largest defect %.3Lg well below duff_branchless's %.3Lg", mx[2], mx[0]);
	CHECK(comp_differ <= 6 * NFLOOR / 10000, "duff_comp = duff_wide on all but a few components (%d differ)", comp_differ);
}

/* onb_basis_array[f]'s paths: the header's inline one (through the row's
   array entry), the library's function itself, and its by-value fallback
   for a table of the caller's own without array entries: the same bits;
   a NULL method, or double on a float-only one, touches nothing. */
static void test_basis_array(void)
{
	size_t count, k;
	const onb_method *all = onb_methods(&count);
	const double n[3] = { 0.48, 0.6, -0.64 };
	const float nf[3] = { 0.48f, 0.6f, -0.64f };
	float z[6];
	for (k = 0; k < count; k++) {
		onb_method own = all[k];
		double a[6], b[6], c[6];
		float af[6], bf[6], cf[6];
		int same;
		own.array = NULL;
		own.arrayf = NULL;
		same = onb_basis_arrayf(&all[k], nf, af, af + 3) == ONB_OK && (onb_basis_arrayf)(&all[k], nf, bf, bf + 3) == ONB_OK &&
		       onb_basis_arrayf(&own, nf, cf, cf + 3) == ONB_OK && !memcmp(af, bf, sizeof af) && !memcmp(af, cf, sizeof af);
		if (all[k].basis)
			same = same && onb_basis_array(&all[k], n, a, a + 3) == ONB_OK && (onb_basis_array)(&all[k], n, b, b + 3) == ONB_OK &&
			       onb_basis_array(&own, n, c, c + 3) == ONB_OK && !memcmp(a, b, sizeof a) && !memcmp(a, c, sizeof a);
		else {
			a[0] = 42.0;
			same = same && onb_basis_array(&all[k], n, a, a + 3) == ONB_BAD_METHOD && a[0] == 42.0;
		}
		CHECK(same, "%s: onb_basis_array[f]'s inline, library and by-value paths agree", all[k].name);
	}
	z[0] = 42.0f;
	CHECK(onb_basis_arrayf(NULL, nf, z, z + 3) == ONB_BAD_METHOD && z[0] == 42.0f, "onb_basis_arrayf(NULL) is ONB_BAD_METHOD");
}

int main(void)
{
	printf("test_lib: libonb %s, batch isa %s, hw rsqrt %d\n", ONB_VERSION, onb_batch_isa(), ONB_HAVE_HW_RSQRT);
	test_random_and_axes();
	test_bit_identity();
	test_faithful();
	test_special();
	test_checked();
	test_basis_array();
	test_floor_methods();
	return check_finish(NULL);
}
