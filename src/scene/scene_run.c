/*
 * scene_run.c - every method on a scene's normals, measured (scene_run.h;
 * the metrics are those of scene.c's file comment): the batch kernel and
 * the scalar out-of-line function on the same inputs, metrics from the
 * batch outputs in long double against n/|n| of the input the method
 * received, and the count of inputs where the two differ in any bit.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "scene/scene_run.h"
#include "common/prec.h"
#include "bench/bench_core.h"
#include "bench/bench_calls.h"

/* The size of one component in the working precision: binary16 buffers
   hold bit patterns (uint16_t), as libonb's onb_NAME_arrayh takes them. */
static size_t elem_size(int prec)
{
	return prec == PREC_DOUBLE ? sizeof(double) : prec == PREC_HALF ? sizeof(uint16_t) : sizeof(float);
}

double scene_round(int prec, double x)
{
	if (prec == PREC_FLOAT)
		return (float)x;
	if (prec == PREC_HALF)
		return prec_half_round((float)x);   /* the file's float, rounded to nearest binary16 */
	return x;
}

/* One operation of binary16 arithmetic: done in float (exact for one
   +, -, x, / or sqrt of binary16 values, rounded once) and rounded to
   binary16, as libonb's half kernels and a GPU's mediump do it. */
static double h16(float x) { return prec_half_round(x); }

void scene_buf_free(scene_buf *b)
{
	int k;
	for (k = 0; k < 3; k++) free(b->in[k]);
	for (k = 0; k < 6; k++) { free(b->bo[k]); free(b->so[k]); }
	free(b->src);
	memset(b, 0, sizeof *b);
}

int scene_buf_alloc(scene_buf *b, size_t n, int prec)
{
	size_t es = elem_size(prec), cnt = n ? n : 1;
	int k, bad = 0;
	memset(b, 0, sizeof *b);
	b->n = n;
	b->prec = prec;
	for (k = 0; k < 3; k++) bad |= !(b->in[k] = calloc(cnt, es));
	for (k = 0; k < 6; k++) { bad |= !(b->bo[k] = calloc(cnt, es)); bad |= !(b->so[k] = calloc(cnt, es)); }
	bad |= !(b->src = calloc(cnt, sizeof *b->src));
	if (bad) {
		scene_buf_free(b);
		return -1;
	}
	return 0;
}

static long double getv(const void *a, int prec, size_t i)
{
	if (prec == PREC_HALF)
		return (long double)prec_half_value(((const uint16_t *)a)[i]);
	return prec == PREC_FLOAT ? (long double)((const float *)a)[i] : (long double)((const double *)a)[i];
}

/* binary16: the batch is libonb's onb_NAME_arrayh once per basis over the
   SoA bit patterns (libonb has no half batch; bench's half "batch" rows
   time the same loop, bench_soa_kernel). */
static void run_batch_half(const onb_method *m, const scene_buf *b)
{
	bench_soa s;
	int k;
	memset(&s, 0, sizeof s);
	s.prec = PREC_HALF;
	s.n = b->n;
	s.arrayh = m->arrayh;
	for (k = 0; k < 3; k++) s.in[k] = b->in[k];
	for (k = 0; k < 6; k++) s.out[k] = b->bo[k];
	if (m->arrayh)
		bench_soa_kernel(&s, 0, b->n);
}

/* binary16: the scalar is libonb's out-of-line onb_NAMEh on onb_vec3h
   (bench_calls.c's loop over it), in chunks of SCALAR_CHUNK. */
#define SCALAR_CHUNK 256
static void run_scalar_half(const onb_method *m, const scene_buf *b)
{
	const bench_call *c = bench_call_find(m->name);
	uint16_t in[3 * SCALAR_CHUNK], out[6 * SCALAR_CHUNK];
	const uint16_t *const *x = (const uint16_t *const *)b->in;
	uint16_t *const *o = (uint16_t *const *)b->so;
	size_t i, j, n;
	if (!c || !c->tph)
		return;
	for (i = 0; i < b->n; i += n) {
		n = b->n - i < SCALAR_CHUNK ? b->n - i : SCALAR_CHUNK;
		for (j = 0; j < n; j++) {
			in[3 * j] = x[0][i + j]; in[3 * j + 1] = x[1][i + j]; in[3 * j + 2] = x[2][i + j];
		}
		c->tph(n, in, out);
		for (j = 0; j < n; j++) {
			int k;
			for (k = 0; k < 6; k++)
				o[k][i + j] = out[6 * j + k];
		}
	}
}

static void run_batch(const onb_method *m, const scene_buf *b)
{
	if (b->prec == PREC_HALF)
		run_batch_half(m, b);
	else if (b->prec == PREC_FLOAT)
		m->batchf(b->n, b->in[0], b->in[1], b->in[2], b->bo[0], b->bo[1], b->bo[2], b->bo[3], b->bo[4], b->bo[5]);
	else
		m->batch(b->n, b->in[0], b->in[1], b->in[2], b->bo[0], b->bo[1], b->bo[2], b->bo[3], b->bo[4], b->bo[5]);
}

static void run_scalar(const onb_method *m, const scene_buf *b)
{
	size_t i;
	if (b->prec == PREC_HALF) {
		run_scalar_half(m, b);
	} else if (b->prec == PREC_FLOAT) {
		const float *x = b->in[0], *y = b->in[1], *z = b->in[2];
		float **o = (float **)b->so;
		for (i = 0; i < b->n; i++) {
			onb_vec3f n, b1, b2;
			n.x = x[i]; n.y = y[i]; n.z = z[i];
			m->basisf(n, &b1, &b2);
			o[0][i] = b1.x; o[1][i] = b1.y; o[2][i] = b1.z;
			o[3][i] = b2.x; o[4][i] = b2.y; o[5][i] = b2.z;
		}
	} else {
		const double *x = b->in[0], *y = b->in[1], *z = b->in[2];
		double **o = (double **)b->so;
		for (i = 0; i < b->n; i++) {
			onb_vec3 n, b1, b2;
			n.x = x[i]; n.y = y[i]; n.z = z[i];
			m->basis(n, &b1, &b2);
			o[0][i] = b1.x; o[1][i] = b1.y; o[2][i] = b1.z;
			o[3][i] = b2.x; o[4][i] = b2.y; o[5][i] = b2.z;
		}
	}
}

/* Metrics of the batch outputs in b (see the file comment). */
static void measure(const onb_method *m, const scene_buf *b, scene_res *r)
{
	size_t i;
	long double sum2 = 0;
	size_t nfin = 0;
	const size_t es = elem_size(b->prec);
	memset(r, 0, sizeof *r);
	for (i = 0; i < b->n; i++) {
		long double n[3], u[3], v[3], l, e, d, det;
		int k;
		for (k = 0; k < 3; k++) {
			n[k] = getv(b->in[k], b->prec, i);
			u[k] = getv(b->bo[k], b->prec, i);
			v[k] = getv(b->bo[k + 3], b->prec, i);
		}
		for (k = 0; k < 6; k++)
			if (memcmp((const char *)b->bo[k] + i * es, (const char *)b->so[k] + i * es, es) != 0) {
				r->mismatch++;
				break;
			}
		if (!isfinite(u[0]) || !isfinite(u[1]) || !isfinite(u[2]) || !isfinite(v[0]) || !isfinite(v[1]) || !isfinite(v[2])) {
			if (r->nonfinite++ == 0)
				r->first_nonfinite = i;
			continue;
		}
		l = sqrtl(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		n[0] /= l; n[1] /= l; n[2] /= l;
		e = fabsl(sqrtl(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) - 1);
		d = fabsl(sqrtl(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) - 1);
		if (d > e) e = d;
		if (e > r->max_norm) r->max_norm = (double)e;
		d = fabsl(u[0] * n[0] + u[1] * n[1] + u[2] * n[2]);
		l = fabsl(v[0] * n[0] + v[1] * n[1] + v[2] * n[2]);
		if (l > d) d = l;
		l = fabsl(u[0] * v[0] + u[1] * v[1] + u[2] * v[2]);
		if (l > d) d = l;
		if (d > r->max_dot) r->max_dot = (double)d;
		if (d > e) e = d;
		if (e > r->max_defect || nfin == 0) {
			if (e > r->max_defect) r->max_defect = (double)e;
			r->worst = i;
		}
		sum2 += e * e;
		nfin++;
		det = (u[1] * v[2] - u[2] * v[1]) * n[0] + (u[2] * v[0] - u[0] * v[2]) * n[1] + (u[0] * v[1] - u[1] * v[0]) * n[2];
		if (m->handedness != 0 && (det > 0 ? 1 : -1) != m->handedness)
			r->wrong_hand++;
	}
	r->rms_defect = nfin ? (double)sqrtl(sum2 / (long double)nfin) : 0.0;
}

/* Fill b with the non-degenerate normals, permuted for `up`, rounded to
   the working precision, and renormalized when asked.  Returns the number
   dropped because renormalizing under- or overflowed. */
/* n / sqrt(n.n) in binary16, each operation rounded (h16), as a
   mediump normalize() computes it: the squares of components below 2^-12
   underflow to 0, so a normal whose every component is that small has
   length 0 and n / 0 is not finite, and one with a component of 256 or
   more overflows n.n, and n / inf is 0.  0, or -1 for either (the normal
   is dropped, as float drops a non-finite one). */
static int half_normalize(double p[3])
{
	const float x = (float)p[0], y = (float)p[1], z = (float)p[2];
	const float s = (float)h16((float)h16(x * x) + (float)h16(y * y)) + (float)h16(z * z);
	const float l = (float)h16(sqrtf((float)h16(s)));
	int j;
	for (j = 0; j < 3; j++)
		p[j] = h16((float)p[j] / l);
	if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
		return -1;
	return p[0] != 0 || p[1] != 0 || p[2] != 0 ? 0 : -1;   /* n.n overflowed: n / inf = 0 */
}

size_t scene_fill(const mesh_normals *mn, int prec, char up, int renorm, scene_buf *b)
{
	size_t i, k = 0, dropped = 0;
	int j;
	for (i = 0; i < mn->count; i++) {
		double x = scene_round(prec, mn->x[i]), y = scene_round(prec, mn->y[i]), z = scene_round(prec, mn->z[i]), p[3];
		if (!isfinite(x) || !isfinite(y) || !isfinite(z) || (x == 0 && y == 0 && z == 0))
			continue;
		if (up == 'y') { p[0] = z; p[1] = x; p[2] = y; }
		else if (up == 'x') { p[0] = y; p[1] = z; p[2] = x; }
		else { p[0] = x; p[1] = y; p[2] = z; }
		if (prec == PREC_HALF) {
			if (renorm && half_normalize(p) != 0) { dropped++; continue; }
			for (j = 0; j < 3; j++)
				((uint16_t *)b->in[j])[k] = prec_half_bits(p[j]);
		} else if (prec == PREC_FLOAT) {
			float f[3];
			f[0] = (float)p[0]; f[1] = (float)p[1]; f[2] = (float)p[2];
			if (renorm) {
				float l = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
				f[0] = f[0] / l; f[1] = f[1] / l; f[2] = f[2] / l;
				if (!isfinite(f[0]) || !isfinite(f[1]) || !isfinite(f[2])) { dropped++; continue; }
			}
			((float *)b->in[0])[k] = f[0]; ((float *)b->in[1])[k] = f[1]; ((float *)b->in[2])[k] = f[2];
		} else {
			if (renorm) {
				double l = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
				p[0] = p[0] / l; p[1] = p[1] / l; p[2] = p[2] / l;
				if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2])) { dropped++; continue; }
			}
			((double *)b->in[0])[k] = p[0]; ((double *)b->in[1])[k] = p[1]; ((double *)b->in[2])[k] = p[2];
		}
		b->src[k++] = i;
	}
	b->n = k;
	return dropped;
}

void scene_run_all(const onb_method *ms, size_t nm, const scene_buf *b, double tol, scene_res *r)
{
	size_t i;
	for (i = 0; i < nm; i++) {
		run_batch(&ms[i], b);
		run_scalar(&ms[i], b);
		measure(&ms[i], b, &r[i]);
		r[i].worst = b->n ? b->src[r[i].worst] : 0;
		r[i].first_nonfinite = b->n ? b->src[r[i].first_nonfinite] : 0;
		r[i].ok = b->n > 0 && r[i].nonfinite == 0 && r[i].wrong_hand == 0 && r[i].max_defect <= tol;
	}
}

/* Each method's max defect on 4096 uniform directions (seed 1) in the
   working precision; INFINITY for a non-finite or wrong-handed output. */
int scene_uniform_defects(const onb_method *ms, size_t nm, int prec, double *out)
{
	const size_t n = 4096;
	scene_buf b;
	double *x = malloc(3 * n * sizeof *x);
	size_t i;
	if (!x || scene_buf_alloc(&b, n, prec) != 0) {
		free(x);
		return -1;
	}
	bench_fill_uniform(n, 1, x, x + n, x + 2 * n);
	for (i = 0; i < n; i++) {
		int k;
		for (k = 0; k < 3; k++) {
			if (prec == PREC_HALF)   /* the directions rounded to binary16 (via float, as the scene's) */
				((uint16_t *)b.in[k])[i] = prec_half_bits(scene_round(prec, x[k * n + i]));
			else if (prec == PREC_FLOAT)
				((float *)b.in[k])[i] = (float)x[k * n + i];
			else
				((double *)b.in[k])[i] = x[k * n + i];
		}
		b.src[i] = i;
	}
	for (i = 0; i < nm; i++) {
		scene_res r;
		run_batch(&ms[i], &b);
		run_scalar(&ms[i], &b);
		measure(&ms[i], &b, &r);
		out[i] = r.nonfinite || r.wrong_hand ? INFINITY : r.max_defect;
	}
	scene_buf_free(&b);
	free(x);
	return 0;
}

static int cmp3(const void *a, const void *b)
{
	const double *x = a, *y = b;
	int k;
	for (k = 0; k < 3; k++)
		if (x[k] != y[k])
			return (x[k] > y[k]) - (x[k] < y[k]);
	return 0;
}

int scene_shape_of(const mesh_normals *mn, int prec, scene_shape *s)
{
	double *v = malloc((mn->count ? mn->count : 1) * 3 * sizeof *v);
	size_t i, n = 0;
	memset(s, 0, sizeof *s);
	if (!v)
		return -1;
	for (i = 0; i < mn->count; i++) {
		double p[3];
		int k, zeros = 0;
		p[0] = mn->x[i]; p[1] = mn->y[i]; p[2] = mn->z[i];
		for (k = 0; k < 3; k++) {
			p[k] = scene_round(prec, p[k]);
			if (!isfinite(p[k]))
				break;
			zeros += p[k] == 0;
		}
		if (k < 3 || zeros == 3)
			continue;
		s->on_axes += zeros == 2;
		memcpy(&v[3 * n++], p, sizeof p);
	}
	qsort(v, n, 3 * sizeof *v, cmp3);
	for (i = 0; i < n; i++)
		s->distinct += i == 0 || cmp3(&v[3 * i], &v[3 * (i - 1)]) != 0;
	s->used = n;
	free(v);
	return 0;
}
