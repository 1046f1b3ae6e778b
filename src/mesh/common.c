/*
 * common.c - what the mesh readers share: the error line, growable arrays,
 * overflow-checked allocation, tokens and numbers, area-weighted vertex
 * normals, reading a whole file, and the classification of normals that
 * `onbstudy scene` reports (mesh_classify, mesh_where).
 */
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "mesh/meshio.h"  /* up, for the public types (mesh_normals, mesh_geom, mesh_opts): the folder's face holds them */
#include "mesh/common.h"

#define fail mio_fail
#define xcalloc mio_calloc
#define alloc_normals mio_alloc_normals
#define compute_normals mio_compute_normals
/* ------------------------------------------------------------------ */
/* errors and growable arrays                                          */
/* ------------------------------------------------------------------ */


int mio_fail(mctx *c, const char *fmt, ...)
{
	va_list ap;
	char *p;
	int w;
	if (!c->err || c->errlen == 0)
		return -1;
	w = snprintf(c->err, c->errlen, "%s: ", c->name ? c->name : "(buffer)");
	if (w < 0 || (size_t)w >= c->errlen)
		w = 0;
	va_start(ap, fmt);
	vsnprintf(c->err + w, c->errlen - (size_t)w, fmt, ap);
	va_end(ap);
	/* A message is one line of text even when it quotes the file (a glTF
	   version or uri string may hold a newline or other control bytes):
	   every control byte becomes '?'. */
	for (p = c->err; *p; p++)
		if ((unsigned char)*p < 0x20 || *p == 0x7f)
			*p = '?';
	return -1;
}


void mio_gvec_init(gvec *v, size_t esz) { v->p = NULL; v->n = v->cap = 0; v->esz = esz; }
void mio_gvec_free(gvec *v) { free(v->p); v->p = NULL; v->n = v->cap = 0; }

/* Room for one more element; -1 when past MESH_MAX_ITEMS or out of memory. */
static int gvec_grow(gvec *v)
{
	size_t nc;
	void *q;
	if (v->n < v->cap)
		return 0;
	nc = v->cap ? v->cap * 2 : 64;
	if (nc > MESH_MAX_ITEMS)
		nc = (size_t)MESH_MAX_ITEMS;
	if (v->n >= nc || nc > SIZE_MAX / v->esz)
		return -1;
	q = realloc(v->p, nc * v->esz);
	if (!q)
		return -1;
	v->p = q;
	v->cap = nc;
	return 0;
}
int mio_gvec_push(gvec *v, const void *e)
{
	if (gvec_grow(v) != 0)
		return -1;
	memcpy((char *)v->p + v->n * v->esz, e, v->esz);
	v->n++;
	return 0;
}

/* calloc with an overflow-checked product. */
void *mio_calloc(size_t n, size_t sz)
{
	if (n == 0)
		n = 1;
	if (sz && n > SIZE_MAX / sz)
		return NULL;
	return calloc(n, sz);
}

void mesh_free(mesh_normals *m)
{
	if (!m)
		return;
	free(m->x); free(m->y); free(m->z); free(m->where); free(m->index);
	memset(m, 0, sizeof *m);
}

int mio_alloc_normals(mesh_normals *m, size_t n)
{
	m->x = xcalloc(n, sizeof *m->x);
	m->y = xcalloc(n, sizeof *m->y);
	m->z = xcalloc(n, sizeof *m->z);
	m->where = xcalloc(n, sizeof *m->where);
	m->index = xcalloc(n, sizeof *m->index);
	if (!m->x || !m->y || !m->z || !m->where || !m->index) {
		mesh_free(m);
		return -1;
	}
	return 0;
}

/* ------------------------------------------------------------------ */
/* tokens and numbers                                                  */
/* ------------------------------------------------------------------ */

/* Callers bound OBJ and header lines before tokenizing, so a newline only
   separates tokens inside an ascii PLY body. */
int mio_is_space(unsigned char ch) { return ch == ' ' || ch == '\t' || ch == '\v' || ch == '\f' || ch == '\r' || ch == '\n'; }

/* Next token in [*p, end), whitespace separated. */
int mio_next_tok(const unsigned char **p, const unsigned char *end, const unsigned char **t, size_t *tl)
{
	const unsigned char *q = *p;
	while (q < end && mio_is_space(*q))
		q++;
	if (q >= end) {
		*p = q;
		return 0;
	}
	*t = q;
	while (q < end && !mio_is_space(*q))
		q++;
	*tl = (size_t)(q - *t);
	*p = q;
	return 1;
}

int mio_tok_eq(const unsigned char *t, size_t tl, const char *s)
{
	size_t n = strlen(s);
	return tl == n && memcmp(t, s, n) == 0;
}

/* Copy a token for strtod/strtoll; 0 if it does not fit or holds a NUL. */
static int tok_copy(const unsigned char *t, size_t tl, char *buf, size_t bn)
{
	if (tl == 0 || tl >= bn || memchr(t, '\0', tl))
		return 0;
	memcpy(buf, t, tl);
	buf[tl] = '\0';
	return 1;
}

/* Whole token as a number; non-finite values and overflow to infinity are
   accepted (they are reported as degenerate normals), garbage is not. */
int mio_tok_double(const unsigned char *t, size_t tl, double *v)
{
	char buf[80], *e;
	if (!tok_copy(t, tl, buf, sizeof buf))
		return 0;
	errno = 0;
	*v = strtod(buf, &e);
	return e == buf + tl && e != buf;
}
int mio_tok_float(const unsigned char *t, size_t tl, double *v)
{
	char buf[80], *e;
	float f;
	if (!tok_copy(t, tl, buf, sizeof buf))
		return 0;
	f = strtof(buf, &e);
	*v = f;
	return e == buf + tl && e != buf;
}
int mio_tok_ll(const unsigned char *t, size_t tl, long long *v)
{
	char buf[40], *e;
	if (!tok_copy(t, tl, buf, sizeof buf))
		return 0;
	errno = 0;
	*v = strtoll(buf, &e, 10);
	return e == buf + tl && e != buf && errno == 0;
}

/* Printable excerpt of a token for error messages. */
const char *mio_tok_show(const unsigned char *t, size_t tl, char *buf, size_t bn)
{
	size_t i, k = 0;
	for (i = 0; i < tl && k + 5 < bn; i++) {
		unsigned char ch = t[i];
		if (ch >= 0x20 && ch < 0x7f && ch != '\'')
			buf[k++] = (char)ch;
		else
			k += (size_t)snprintf(buf + k, bn - k, "\\x%02x", ch);
	}
	if (i < tl && k + 4 < bn) { memcpy(buf + k, "...", 3); k += 3; }
	buf[k] = '\0';
	return buf;
}

/* ------------------------------------------------------------------ */
/* area-weighted vertex normals                                        */
/* ------------------------------------------------------------------ */

/* pos: 3*nv doubles; corners: vertex indices (validated); faces: spans.
   Each polygon's area vector (sum of its fan triangles' cross products,
   twice its area times its unit normal when planar) is added to each of
   its vertices; the sums are normalized in long double. */
int mio_compute_normals(mctx *c, mesh_normals *m, const double *pos, size_t nv,
                        const uint64_t *vwhere, const uint32_t *corners,
                        const face_rec *faces, size_t nf)
{
	long double *acc = xcalloc(nv, 3 * sizeof *acc);
	unsigned char *used = xcalloc(nv, 1);
	size_t f, i, k, nused = 0;
	if (!acc || !used) {
		free(acc); free(used);
		return fail(c, "out of memory for %zu vertices", nv);
	}
	for (f = 0; f < nf; f++) {
		const uint32_t *cv = corners + faces[f].first;
		long double sx = 0, sy = 0, sz = 0;
		const double *a = pos + 3 * (size_t)cv[0];
		for (i = 1; i + 1 < faces[f].count; i++) {
			const double *b = pos + 3 * (size_t)cv[i], *d = pos + 3 * (size_t)cv[i + 1];
			long double ux = (long double)b[0] - a[0], uy = (long double)b[1] - a[1], uz = (long double)b[2] - a[2];
			long double vx = (long double)d[0] - a[0], vy = (long double)d[1] - a[1], vz = (long double)d[2] - a[2];
			sx += uy * vz - uz * vy;
			sy += uz * vx - ux * vz;
			sz += ux * vy - uy * vx;
			m->ntriangles++;
		}
		for (i = 0; i < faces[f].count; i++) {
			size_t v = cv[i];
			acc[3 * v] += sx; acc[3 * v + 1] += sy; acc[3 * v + 2] += sz;
			used[v] = 1;
		}
	}
	for (i = 0; i < nv; i++)
		nused += used[i];
	if (alloc_normals(m, nused) != 0) {
		free(acc); free(used);
		return fail(c, "out of memory for %zu normals", nused);
	}
	for (i = 0, k = 0; i < nv; i++) {
		long double x, y, z, l;
		if (!used[i])
			continue;
		x = acc[3 * i]; y = acc[3 * i + 1]; z = acc[3 * i + 2];
		l = sqrtl(x * x + y * y + z * z);
		if (l > 0 && isfinite(l)) { x /= l; y /= l; z /= l; }
		m->x[k] = (double)x; m->y[k] = (double)y; m->z[k] = (double)z;
		m->where[k] = vwhere[i];
		m->index[k] = i;
		k++;
	}
	m->count = nused;
	m->unreferenced = nv - nused;
	m->origin = MESH_COMPUTED;
	free(acc); free(used);
	return 0;
}


void mesh_geom_free(mesh_geom *g)
{
	if (!g)
		return;
	free(g->pos); free(g->nrm); free(g->tri); free(g->tri_n); free(g->tri_line);
	memset(g, 0, sizeof *g);
}

int mio_slurp(mctx *c, const char *path, unsigned char **out, size_t *outlen)
{
	FILE *f;
	unsigned char *buf = NULL;
	size_t len = 0, cap = 0;
	/* the file itself is named once, by the error prefix */
	const char *w = path == c->name ? "" : path, *sep = path == c->name ? "" : ": ";
	*out = NULL;
	*outlen = 0;
	f = fopen(path, "rb");
	if (!f)
		return fail(c, "cannot open%s%s: %s", *w ? " " : "", w, strerror(errno));
	{	/* a directory, or a regular file known to be too large, is refused
		   before anything is read or allocated */
		struct stat st;
		if (fstat(fileno(f), &st) == 0) {
			if (S_ISDIR(st.st_mode)) {
				fclose(f);
				return fail(c, "%s%sis a directory, not a mesh file", w, *w ? " " : "");
			}
			if (S_ISREG(st.st_mode) && (uintmax_t)st.st_size > (uintmax_t)MESH_MAX_FILE) {
				fclose(f);
				return fail(c, "%s%sfile larger than %zu bytes", w, sep, MESH_MAX_FILE);
			}
		}
	}
	for (;;) {
		size_t got;
		if (len == cap) {
			size_t nc = cap ? cap * 2 : 65536;
			unsigned char *q;
			if (cap >= MESH_MAX_FILE) {
				free(buf);
				fclose(f);
				return fail(c, "%s%sfile larger than %zu bytes", w, sep, MESH_MAX_FILE);
			}
			q = realloc(buf, nc);
			if (!q) {
				free(buf);
				fclose(f);
				return fail(c, "out of memory reading %s", *w ? w : "the file");
			}
			buf = q;
			cap = nc;
		}
		got = fread(buf + len, 1, cap - len, f);
		len += got;
		if (got == 0)
			break;
	}
	if (ferror(f)) {
		free(buf);
		fclose(f);
		return fail(c, "read error%s%s", sep, w);
	}
	fclose(f);
	*out = buf;
	*outlen = len;
	return 0;
}

/* ------------------------------------------------------------------ */
/* classification                                                      */
/* ------------------------------------------------------------------ */

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

int mesh_classify(const mesh_normals *m, int prec, double tol, mesh_stats *st)
{
	size_t i, k = 0;
	double *dev;
	memset(st, 0, sizeof *st);
	st->tol = tol > 0 ? tol : prec == PREC_FLOAT ? 4.0 * FLT_EPSILON : prec == PREC_HALF ? 0x1p-8 : 4.0 * DBL_EPSILON;
	st->total = m->count;
	dev = xcalloc(m->count, sizeof *dev);
	if (!dev)
		return -1;
	for (i = 0; i < m->count; i++) {
		long double x = m->x[i], y = m->y[i], z = m->z[i], l, d;
		if (prec == PREC_FLOAT) {
			x = (float)m->x[i]; y = (float)m->y[i]; z = (float)m->z[i];
		} else if (prec == PREC_HALF) {   /* the float, rounded to nearest binary16 */
			x = prec_half_round((float)m->x[i]); y = prec_half_round((float)m->y[i]); z = prec_half_round((float)m->z[i]);
		}
		if (!isfinite(x) || !isfinite(y) || !isfinite(z)) {
			st->nonfinite++;
			goto bad;
		}
		if (x == 0 && y == 0 && z == 0) {
			st->zero++;
			goto bad;
		}
		l = sqrtl(x * x + y * y + z * z);
		d = l - 1;
		if (fabsl(d) <= st->tol) {
			st->unit++;
			continue;
		}
		if (k == 0 || d < st->dev_min) st->dev_min = (double)d;
		if (k == 0 || d > st->dev_max) st->dev_max = (double)d;
		dev[k++] = (double)fabsl(d);
		continue;
bad:
		if (st->nbad < sizeof st->bad / sizeof st->bad[0])
			st->bad[st->nbad++] = i;
	}
	st->nonunit = k;
	if (k) {
		qsort(dev, k, sizeof *dev, cmp_double);
		st->q50 = dev[(k - 1) / 2];
		st->q90 = dev[(size_t)((double)(k - 1) * 0.9)];
		st->q99 = dev[(size_t)((double)(k - 1) * 0.99)];
	}
	free(dev);
	return 0;
}

void mesh_where(const mesh_normals *m, size_t i, char *buf, size_t n)
{
	if (i >= m->count) {
		snprintf(buf, n, "?");
		return;
	}
	if (m->format == MESH_OBJ)
		snprintf(buf, n, "line %llu%s", (unsigned long long)m->where[i],
		         m->origin == MESH_COMPUTED ? " (the 'v' of a vertex with a computed normal)" : "");
	else if (m->format == MESH_GLTF)
		snprintf(buf, n, "%s %llu primitive %llu vertex %llu", m->world ? "node" : "mesh",
		         (unsigned long long)(m->where[i] >> 40), (unsigned long long)((m->where[i] >> 32) & 0xff),
		         (unsigned long long)(m->where[i] & 0xffffffffu));
	else
		snprintf(buf, n, "%s %zu at byte %llu", m->element[0] ? m->element : "element", m->index[i],
		         (unsigned long long)m->where[i]);
}
