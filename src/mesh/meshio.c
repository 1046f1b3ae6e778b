/*
 * meshio.c - OBJ and PLY normal readers.  See meshio.h for what counts as
 * a normal.  Parsing is bounded by the buffer length everywhere (no NUL
 * termination is assumed), every count is checked against the bytes that
 * remain before anything is allocated, and every allocation size is
 * checked for overflow.
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
#include "mesh/meshio.h"
#include "mesh/meshio_int.h"

/* ------------------------------------------------------------------ */
/* errors and growable arrays                                          */
/* ------------------------------------------------------------------ */

#define fail mio_fail
#define xcalloc mio_calloc
#define alloc_normals mio_alloc_normals
#define compute_normals mio_compute_normals

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

typedef struct {
	void *p;
	size_t n, cap, esz;
} gvec;

static void gvec_init(gvec *v, size_t esz) { v->p = NULL; v->n = v->cap = 0; v->esz = esz; }
static void gvec_free(gvec *v) { free(v->p); v->p = NULL; v->n = v->cap = 0; }

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
static int gvec_push(gvec *v, const void *e)
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
static int is_space(unsigned char ch) { return ch == ' ' || ch == '\t' || ch == '\v' || ch == '\f' || ch == '\r' || ch == '\n'; }

/* Next token in [*p, end), whitespace separated. */
static int next_tok(const unsigned char **p, const unsigned char *end, const unsigned char **t, size_t *tl)
{
	const unsigned char *q = *p;
	while (q < end && is_space(*q))
		q++;
	if (q >= end) {
		*p = q;
		return 0;
	}
	*t = q;
	while (q < end && !is_space(*q))
		q++;
	*tl = (size_t)(q - *t);
	*p = q;
	return 1;
}

static int tok_eq(const unsigned char *t, size_t tl, const char *s)
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
static int tok_double(const unsigned char *t, size_t tl, double *v)
{
	char buf[80], *e;
	if (!tok_copy(t, tl, buf, sizeof buf))
		return 0;
	errno = 0;
	*v = strtod(buf, &e);
	return e == buf + tl && e != buf;
}
static int tok_float(const unsigned char *t, size_t tl, double *v)
{
	char buf[80], *e;
	float f;
	if (!tok_copy(t, tl, buf, sizeof buf))
		return 0;
	f = strtof(buf, &e);
	*v = f;
	return e == buf + tl && e != buf;
}
static int tok_ll(const unsigned char *t, size_t tl, long long *v)
{
	char buf[40], *e;
	if (!tok_copy(t, tl, buf, sizeof buf))
		return 0;
	errno = 0;
	*v = strtoll(buf, &e, 10);
	return e == buf + tl && e != buf && errno == 0;
}

/* Printable excerpt of a token for error messages. */
static const char *tok_show(const unsigned char *t, size_t tl, char *buf, size_t bn)
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

/* ------------------------------------------------------------------ */
/* OBJ                                                                 */
/* ------------------------------------------------------------------ */

/* Resolve one OBJ index (1-based, or negative relative to n so far). */
static int obj_index(mctx *c, uint64_t line, const char *what, const unsigned char *t, size_t tl,
                     size_t n, size_t *out)
{
	long long v;
	char sb[64];
	if (!tok_ll(t, tl, &v))
		return fail(c, "line %llu: bad %s index '%s'", (unsigned long long)line, what, tok_show(t, tl, sb, sizeof sb));
	if (v > 0 && (unsigned long long)v <= n) { *out = (size_t)(v - 1); return 0; }
	if (v < 0 && (unsigned long long)(-(v + 1)) < n) { *out = n - (size_t)(-(v + 1)) - 1; return 0; }
	return fail(c, "line %llu: %s index %lld out of range (%zu defined so far)", (unsigned long long)line, what, v, n);
}

void mesh_geom_free(mesh_geom *g)
{
	if (!g)
		return;
	free(g->pos); free(g->nrm); free(g->tri); free(g->tri_n); free(g->tri_line);
	memset(g, 0, sizeof *g);
}

/* The geometry of a parsed OBJ (see meshio.h); m holds its normals.
   cnorm: per corner, the `vn` index or MESH_NO_NORMAL. */
static int obj_geom(mctx *c, const mesh_normals *m, const gvec *pos, const gvec *vn,
                    const gvec *corners, const gvec *cnorm, const gvec *faces, mesh_geom *g)
{
	const face_rec *fr = faces->p;
	const uint32_t *cv = corners->p, *cn = cnorm->p;
	size_t f, i, t = 0, nn = vn->n > 0 ? vn->n : pos->n;
	g->nverts = pos->n;
	g->nnormals = nn;
	g->ntris = m->ntriangles;
	g->pos = xcalloc(pos->n, 3 * sizeof *g->pos);
	g->nrm = xcalloc(nn, 3 * sizeof *g->nrm);
	g->tri = xcalloc(g->ntris, 3 * sizeof *g->tri);
	g->tri_n = xcalloc(g->ntris, 3 * sizeof *g->tri_n);
	g->tri_line = xcalloc(g->ntris, sizeof *g->tri_line);
	if (!g->pos || !g->nrm || !g->tri || !g->tri_n || !g->tri_line)
		return fail(c, "out of memory for the geometry (%zu vertices, %zu triangles)", pos->n, g->ntris);
	if (pos->n)
		memcpy(g->pos, pos->p, pos->n * 3 * sizeof *g->pos);
	if (vn->n > 0)
		memcpy(g->nrm, vn->p, vn->n * 3 * sizeof *g->nrm);
	else
		for (i = 0; i < m->count; i++) {
			size_t v = m->index[i];
			g->nrm[3 * v] = m->x[i]; g->nrm[3 * v + 1] = m->y[i]; g->nrm[3 * v + 2] = m->z[i];
		}
	for (f = 0; f < faces->n; f++) {
		size_t a = fr[f].first;
		for (i = 1; i + 1 < fr[f].count; i++, t++) {
			size_t b = a + i, d = a + i + 1;
			g->tri[3 * t] = cv[a]; g->tri[3 * t + 1] = cv[b]; g->tri[3 * t + 2] = cv[d];
			if (vn->n > 0) {
				g->tri_n[3 * t] = cn[a]; g->tri_n[3 * t + 1] = cn[b]; g->tri_n[3 * t + 2] = cn[d];
			} else {
				g->tri_n[3 * t] = cv[a]; g->tri_n[3 * t + 1] = cv[b]; g->tri_n[3 * t + 2] = cv[d];
			}
			g->tri_line[t] = fr[f].where;
		}
	}
	return 0;
}

/* 1 when some line ends in a backslash (then \n or \r\n). */
static int obj_continuations(const unsigned char *buf, size_t len)
{
	size_t i;
	for (i = 0; i + 1 < len; i++)
		if (buf[i] == '\\' && (buf[i + 1] == '\n' || (buf[i + 1] == '\r' && i + 2 < len && buf[i + 2] == '\n')))
			return 1;
	return 0;
}

static unsigned char *obj_join(const unsigned char *buf, size_t len)
{
	unsigned char *j = malloc(len ? len : 1);
	size_t i;
	if (!j)
		return NULL;
	memcpy(j, buf, len);
	for (i = 0; i + 1 < len; i++)
		if (j[i] == '\\') {
			size_t k = i + 1;
			if (j[k] == '\r' && k + 1 < len && j[k + 1] == '\n')
				j[k++] = ' ';
			if (j[k] == '\n') {
				j[i] = ' ';
				j[k] = '\v';
			}
		}
	return j;
}

/* The state of one OBJ parse. */
typedef struct {
	mctx *c;
	gvec pos, vwhere, vn, vnwhere, corners, cnorm, faces;
	uint64_t line;        /* the first physical line of the current logical one */
	uint64_t pending;     /* newlines joined into it by continuations */
	size_t nvt;           /* 'vt' lines so far */
	int want_cnorm;       /* keep each corner's normal index (for the geometry) */
} obj_st;

/* 'v' (up to 7 numbers) or 'vn' (isn; 3): the numbers after the keyword. */
static int obj_vertex(obj_st *st, int isn, const unsigned char *q, const unsigned char *le)
{
	mctx *c = st->c;
	const unsigned char *t;
	size_t tl;
	double v[7];
	int k = 0;
	char sb[64];
	while (next_tok(&q, le, &t, &tl)) {
		if (k == (isn ? 3 : 7))
			return fail(c, "line %llu: too many numbers in '%s' (at most %d)", (unsigned long long)st->line, isn ? "vn" : "v", isn ? 3 : 7);
		if (!tok_double(t, tl, &v[k]))
			return fail(c, "line %llu: bad number '%s'", (unsigned long long)st->line, tok_show(t, tl, sb, sizeof sb));
		k++;
	}
	if (k < 3)
		return fail(c, "line %llu: '%s' needs 3 numbers, got %d", (unsigned long long)st->line, isn ? "vn" : "v", k);
	if (gvec_push(isn ? &st->vn : &st->pos, v) != 0 || gvec_push(isn ? &st->vnwhere : &st->vwhere, &st->line) != 0)
		return fail(c, "line %llu: too many vertices or normals, or out of memory", (unsigned long long)st->line);
	return 0;
}

/* 'vt': 1 to 3 numbers, only counted (face corners may refer to them). */
static int obj_texcoord(obj_st *st, const unsigned char *q, const unsigned char *le)
{
	const unsigned char *t;
	size_t tl;
	double v;
	int k = 0;
	char sb[64];
	while (next_tok(&q, le, &t, &tl)) {
		if (!tok_double(t, tl, &v) || ++k > 3)
			return fail(st->c, "line %llu: bad texture coordinate '%s'", (unsigned long long)st->line, tok_show(t, tl, sb, sizeof sb));
	}
	if (k < 1)
		return fail(st->c, "line %llu: 'vt' needs 1 to 3 numbers", (unsigned long long)st->line);
	st->nvt++;
	return 0;
}

/* One corner of an 'f' line: v, v/vt, v//vn or v/vt/vn. */
static int obj_corner(obj_st *st, const unsigned char *t, size_t tl)
{
	mctx *c = st->c;
	const unsigned char *s1 = memchr(t, '/', tl), *s2 = NULL;
	size_t vi, other;
	uint32_t u, un = MESH_NO_NORMAL;
	char sb[64];
	if (s1)
		s2 = memchr(s1 + 1, '/', tl - (size_t)(s1 + 1 - t));
	if (s2 && memchr(s2 + 1, '/', tl - (size_t)(s2 + 1 - t)))
		return fail(c, "line %llu: bad face vertex '%s'", (unsigned long long)st->line, tok_show(t, tl, sb, sizeof sb));
	if (obj_index(c, st->line, "vertex", t, s1 ? (size_t)(s1 - t) : tl, st->pos.n, &vi) != 0)
		return -1;
	if (s1) {
		const unsigned char *b = s1 + 1, *be = s2 ? s2 : t + tl;
		if (be > b && obj_index(c, st->line, "texture", b, (size_t)(be - b), st->nvt, &other) != 0)
			return -1;
		if (!s2 && be == b)
			return fail(c, "line %llu: bad face vertex '%s'", (unsigned long long)st->line, tok_show(t, tl, sb, sizeof sb));
		if (s2 && obj_index(c, st->line, "normal", s2 + 1, (size_t)(t + tl - s2 - 1), st->vn.n, &other) != 0)
			return -1;
		if (s2)
			un = (uint32_t)other;
	}
	u = (uint32_t)vi;
	if (gvec_push(&st->corners, &u) != 0 || (st->want_cnorm && gvec_push(&st->cnorm, &un) != 0))
		return fail(c, "line %llu: too many face corners, or out of memory", (unsigned long long)st->line);
	return 0;
}

/* 'f': at least 3 corners. */
static int obj_face(obj_st *st, const unsigned char *q, const unsigned char *le)
{
	const unsigned char *t;
	size_t tl;
	face_rec fr;
	fr.first = st->corners.n;
	fr.count = 0;
	fr.where = st->line;
	while (next_tok(&q, le, &t, &tl)) {
		if (obj_corner(st, t, tl) != 0)
			return -1;
		fr.count++;
	}
	if (fr.count < 3)
		return fail(st->c, "line %llu: a face needs at least 3 vertices, got %zu", (unsigned long long)st->line, fr.count);
	if (gvec_push(&st->faces, &fr) != 0)
		return fail(st->c, "line %llu: too many faces, or out of memory", (unsigned long long)st->line);
	return 0;
}

/* One logical line [q, le), its comment cut off. */
static int obj_statement(obj_st *st, const unsigned char *q, const unsigned char *le)
{
	const unsigned char *t;
	size_t tl;
	if (!next_tok(&q, le, &t, &tl))
		return 0;
	if (tok_eq(t, tl, "v") || tok_eq(t, tl, "vn"))
		return obj_vertex(st, tl == 2, q, le);
	if (tok_eq(t, tl, "vt"))
		return obj_texcoord(st, q, le);
	if (tok_eq(t, tl, "f"))
		return obj_face(st, q, le);
	/* every other statement (vp, l, p, g, o, s, usemtl, mtllib, ...)
	   carries no normal and is skipped */
	return 0;
}

/* The newlines in [o, oe). */
static uint64_t obj_newlines(const unsigned char *o, const unsigned char *oe)
{
	const unsigned char *hit;
	uint64_t n = 0;
	while ((hit = memchr(o, '\n', (size_t)(oe - o))) != NULL) {
		n++;
		o = hit + 1;
	}
	return n;
}

/* Every logical line of [p, end).  joined: the copy p and end point into
   when lines were joined (buf is then the original, whose newlines the
   line numbers count), or NULL. */
static int obj_lines(obj_st *st, const unsigned char *buf, const unsigned char *joined,
                     const unsigned char *p, const unsigned char *end)
{
	while (p < end) {
		const unsigned char *eol = memchr(p, '\n', (size_t)(end - p));
		const unsigned char *le = eol ? eol : end, *hash, *q;
		st->line += 1 + st->pending; /* the first physical line of this logical one */
		st->pending = 0;
		if (joined) /* the newlines joined into it */
			st->pending = obj_newlines(buf + (p - joined), buf + (le - joined));
		hash = memchr(p, '#', (size_t)(le - p));
		if (hash)
			le = hash;
		q = p;
		p = eol ? eol + 1 : end;
		if (obj_statement(st, q, le) != 0)
			return -1;
	}
	return 0;
}

/* The counts, and the normals: the 'vn' lines as stored, else computed
   from the faces. */
static int obj_normals(obj_st *st, mesh_normals *m)
{
	mctx *c = st->c;
	const face_rec *fr = st->faces.p;
	size_t f, i, t;
	int rc;
	m->nvertices = st->pos.n;
	m->nfaces = st->faces.n;
	for (f = 0; f < st->faces.n; f++)
		m->ntriangles += fr[f].count - 2;
	if (st->vn.n > 0) {
		const double *v = st->vn.p;
		if (alloc_normals(m, st->vn.n) != 0)
			return fail(c, "out of memory for %zu normals", st->vn.n);
		for (i = 0; i < st->vn.n; i++) {
			m->x[i] = v[3 * i]; m->y[i] = v[3 * i + 1]; m->z[i] = v[3 * i + 2];
			m->where[i] = ((const uint64_t *)st->vnwhere.p)[i];
			m->index[i] = i;
		}
		m->count = st->vn.n;
		m->origin = MESH_STORED;
		m->stored_type = MESH_T_TEXT;
		return 0;
	}
	if (st->faces.n == 0)
		return fail(c, "no normals: no 'vn' lines and no faces to compute them from (%llu lines, %zu vertices)",
		            (unsigned long long)(st->line + st->pending), st->pos.n);
	t = m->ntriangles;
	m->ntriangles = 0;
	rc = compute_normals(c, m, st->pos.p, st->pos.n, st->vwhere.p, st->corners.p, st->faces.p, st->faces.n);
	m->ntriangles = t;
	m->stored_type = MESH_T_TEXT;
	return rc;
}

static int read_obj(mctx *c, const unsigned char *buf, size_t len, mesh_normals *m, mesh_geom *geom)
{
	unsigned char *joined = NULL;
	const unsigned char *p = buf, *end = buf + len;
	obj_st st;
	int rc = -1;
	st.c = c;
	st.line = st.pending = 0;
	st.nvt = 0;
	st.want_cnorm = geom != NULL;
	gvec_init(&st.pos, 3 * sizeof(double)); gvec_init(&st.vwhere, sizeof(uint64_t));
	gvec_init(&st.vn, 3 * sizeof(double)); gvec_init(&st.vnwhere, sizeof(uint64_t));
	gvec_init(&st.corners, sizeof(uint32_t)); gvec_init(&st.faces, sizeof(face_rec));
	gvec_init(&st.cnorm, sizeof(uint32_t));
	m->format = MESH_OBJ;
	if (len >= 2 && ((buf[0] == 0xfe && buf[1] == 0xff) || (buf[0] == 0xff && buf[1] == 0xfe))) {
		fail(c, "line 1: UTF-16 text (byte-order mark %02x %02x) is not supported; convert to UTF-8", buf[0], buf[1]);
		goto out;
	}
	if (len >= 3 && buf[0] == 0xef && buf[1] == 0xbb && buf[2] == 0xbf)
		p += 3; /* UTF-8 byte-order mark */
	/* line continuation: a backslash at the end of a line (before \n or
	   \r\n) joins the next line.  A copy of the same length has each such
	   backslash and newline turned into blanks (\v for the newline, so a
	   line still ends only at a real \n); line numbers count the newlines
	   of the original. */
	if (obj_continuations(buf, len)) {
		joined = obj_join(buf, len);
		if (!joined) {
			fail(c, "out of memory");
			goto out;
		}
		p = joined + (p - buf);
		end = joined + len;
	}
	if (obj_lines(&st, buf, joined, p, end) == 0 && obj_normals(&st, m) == 0)
		rc = geom ? obj_geom(c, m, &st.pos, &st.vn, &st.corners, &st.cnorm, &st.faces, geom) : 0;
out:
	gvec_free(&st.pos); gvec_free(&st.vwhere); gvec_free(&st.vn); gvec_free(&st.vnwhere);
	gvec_free(&st.corners); gvec_free(&st.cnorm); gvec_free(&st.faces);
	free(joined);
	return rc;
}

/* ------------------------------------------------------------------ */
/* PLY                                                                 */
/* ------------------------------------------------------------------ */

enum { PT_NONE = 0, PT_I8, PT_U8, PT_I16, PT_U16, PT_I32, PT_U32, PT_F32, PT_F64 };
static const struct { const char *name; int type; } ply_types[] = {
	{ "char", PT_I8 }, { "int8", PT_I8 }, { "uchar", PT_U8 }, { "uint8", PT_U8 },
	{ "short", PT_I16 }, { "int16", PT_I16 }, { "ushort", PT_U16 }, { "uint16", PT_U16 },
	{ "int", PT_I32 }, { "int32", PT_I32 }, { "uint", PT_U32 }, { "uint32", PT_U32 },
	{ "float", PT_F32 }, { "float32", PT_F32 }, { "double", PT_F64 }, { "float64", PT_F64 },
};
static const size_t pt_size[] = { 0, 1, 1, 2, 2, 4, 4, 4, 8 };

#define PLY_MAX_ELEMS 32
#define PLY_MAX_PROPS 64
#define PLY_NAME 64

typedef struct {
	char name[PLY_NAME];
	int type;       /* scalar type, or the list's item type */
	int list;       /* 1 for a list */
	int ctype;      /* list count type */
} ply_prop;

typedef struct {
	char name[PLY_NAME];
	unsigned long long count;
	int nprop;
	ply_prop prop[PLY_MAX_PROPS];
	int ix, iy, iz, inx, iny, inz, ilist; /* property indices, or -1 */
} ply_elem;

typedef struct {
	mctx *c;
	const unsigned char *buf, *p, *end;
	int fmt;              /* 0 ascii, 1 little, 2 big */
	uint64_t line;        /* ascii: current line */
} ply_rd;

static int pt_lookup(const unsigned char *t, size_t tl)
{
	size_t i;
	for (i = 0; i < sizeof ply_types / sizeof ply_types[0]; i++)
		if (tok_eq(t, tl, ply_types[i].name))
			return ply_types[i].type;
	return PT_NONE;
}

static unsigned long long off(const ply_rd *r) { return (unsigned long long)(r->p - r->buf); }

/* One value of type `type`; is_int tells whether *iv is meaningful. */
static int ply_value(ply_rd *r, int type, const ply_elem *e, unsigned long long ei, const char *pname,
                     double *dv, long long *iv)
{
	mctx *c = r->c;
	if (r->fmt == 0) {
		const unsigned char *t = NULL;
		size_t tl = 0;
		char sb[64];
		unsigned long long at;
		for (;;) {
			while (r->p < r->end && (is_space(*r->p) || *r->p == '\n')) {
				if (*r->p == '\n')
					r->line++;
				r->p++;
			}
			if (r->p >= r->end)
				return fail(c, "byte %llu (line %llu): file ends inside element '%s' %llu of %llu (property '%s')",
				            off(r), (unsigned long long)r->line, e->name, ei, e->count, pname);
			break;
		}
		at = off(r);
		next_tok(&r->p, r->end, &t, &tl);
		if (type == PT_F32 || type == PT_F64) {
			if (!(type == PT_F32 ? tok_float(t, tl, dv) : tok_double(t, tl, dv)))
				return fail(c, "byte %llu (line %llu): bad number '%s' for property '%s' of element '%s' %llu",
				            at, (unsigned long long)r->line, tok_show(t, tl, sb, sizeof sb), pname, e->name, ei);
			*iv = 0;
		} else {
			long long v, lo, hi;
			switch (type) {
			case PT_I8:  lo = -128; hi = 127; break;
			case PT_U8:  lo = 0; hi = 255; break;
			case PT_I16: lo = -32768; hi = 32767; break;
			case PT_U16: lo = 0; hi = 65535; break;
			case PT_I32: lo = -2147483647LL - 1; hi = 2147483647LL; break;
			default:     lo = 0; hi = 4294967295LL; break;
			}
			if (!tok_ll(t, tl, &v) || v < lo || v > hi)
				return fail(c, "byte %llu (line %llu): bad integer '%s' for property '%s' of element '%s' %llu",
				            at, (unsigned long long)r->line, tok_show(t, tl, sb, sizeof sb), pname, e->name, ei);
			*iv = v;
			*dv = (double)v;
		}
		return 0;
	} else {
		unsigned char b[8];
		size_t n = pt_size[type], i;
		if ((size_t)(r->end - r->p) < n)
			return fail(c, "byte %llu: truncated binary data: element '%s' %llu of %llu, property '%s' needs %zu bytes, %zu remain",
			            off(r), e->name, ei, e->count, pname, n, (size_t)(r->end - r->p));
		for (i = 0; i < n; i++)
			b[i] = r->p[r->fmt == 1 ? i : n - 1 - i];
		r->p += n;
		switch (type) {
		case PT_I8:  { int8_t v;   memcpy(&v, b, 1); *iv = v; break; }
		case PT_U8:  { uint8_t v;  memcpy(&v, b, 1); *iv = v; break; }
		case PT_I16: { int16_t v;  memcpy(&v, b, 2); *iv = v; break; }
		case PT_U16: { uint16_t v; memcpy(&v, b, 2); *iv = v; break; }
		case PT_I32: { int32_t v;  memcpy(&v, b, 4); *iv = v; break; }
		case PT_U32: { uint32_t v; memcpy(&v, b, 4); *iv = v; break; }
		case PT_F32: { float v;    memcpy(&v, b, 4); *dv = v; *iv = 0; return 0; }
		default:     { double v;   memcpy(&v, b, 8); *dv = v; *iv = 0; return 0; }
		}
		*dv = (double)*iv;
		return 0;
	}
}

/* A renderer's view of a PLY mesh: positions, fan-triangulated faces, and
   per-vertex normals (the vertex element's own, or the computed ones);
   normals of another element (per face) are not used for shading. */
static int ply_geom(mctx *c, const mesh_normals *m, const double *pos, size_t nv, const ply_elem *el, int vert_e,
                    const gvec *corners, const gvec *faces, mesh_geom *g)
{
	const face_rec *fr = faces->p;
	const uint32_t *cv = corners->p;
	size_t f, i, t = 0, off = 0;
	int j, pervertex = m->origin == MESH_COMPUTED || (el[vert_e].inx >= 0 && el[vert_e].iny >= 0 && el[vert_e].inz >= 0);
	for (f = 0; f < faces->n; f++)
		t += fr[f].count - 2;
	if (t == 0)
		return fail(c, "no geometry: no face has 3 or more vertices");
	g->nverts = nv;
	g->nnormals = pervertex ? nv : 0;
	g->ntris = t;
	g->pos = xcalloc(nv, 3 * sizeof *g->pos);
	g->nrm = xcalloc(nv, 3 * sizeof *g->nrm);
	g->tri = xcalloc(t, 3 * sizeof *g->tri);
	g->tri_n = xcalloc(t, 3 * sizeof *g->tri_n);
	g->tri_line = xcalloc(t, sizeof *g->tri_line);
	if (!g->pos || !g->nrm || !g->tri || !g->tri_n || !g->tri_line)
		return fail(c, "out of memory for the geometry (%zu vertices, %zu triangles)", nv, t);
	memcpy(g->pos, pos, nv * 3 * sizeof *pos);
	for (j = 0; j < vert_e && m->origin == MESH_STORED; j++)
		if (el[j].inx >= 0 && el[j].iny >= 0 && el[j].inz >= 0)
			off += (size_t)el[j].count;
	if (pervertex)
		for (i = 0; i < m->count; i++) {
			size_t v = m->origin == MESH_COMPUTED ? m->index[i] : i - off;
			if (m->origin == MESH_STORED && (i < off || i - off >= nv))
				continue;
			g->nrm[3 * v] = m->x[i]; g->nrm[3 * v + 1] = m->y[i]; g->nrm[3 * v + 2] = m->z[i];
		}
	for (f = 0, t = 0; f < faces->n; f++)
		for (i = 1; i + 1 < fr[f].count; i++, t++) {
			size_t a = fr[f].first, k;
			g->tri[3 * t] = cv[a]; g->tri[3 * t + 1] = cv[a + i]; g->tri[3 * t + 2] = cv[a + i + 1];
			for (k = 0; k < 3; k++)
				g->tri_n[3 * t + k] = pervertex ? g->tri[3 * t + k] : MESH_NO_NORMAL;
			g->tri_line[t] = fr[f].where;
		}
	return 0;
}

/* The state of one PLY parse. */
typedef struct {
	mctx *c;
	ply_elem *el;
	int ne;
	int fmt;                /* -1 none yet, 0 ascii, 1 little, 2 big */
	uint64_t line;          /* header lines read */
	int vert_e, face_e;     /* the 'vertex' and 'face' elements, or -1 */
	int normal_elems;       /* elements with nx, ny, nz */
	unsigned long long nnorm, nvert;
	int positions;          /* read positions and faces (to compute normals, or for a renderer) */
	double *pos;
	uint64_t *vwhere;
	gvec corners, faces;
	size_t kn;              /* normals stored so far */
} ply_st;

static int ply_isn(const ply_elem *e) { return e->inx >= 0 && e->iny >= 0 && e->inz >= 0; }

/* "format ascii|binary_little_endian|binary_big_endian 1.0"; lo: the line's byte offset. */
static int ply_hdr_format(ply_st *s, const unsigned char *q, const unsigned char *le, unsigned long long lo)
{
	const unsigned char *t2, *t3;
	size_t l2, l3;
	char sb[64];
	if (s->fmt >= 0)
		return fail(s->c, "byte %llu (line %llu): second 'format' line", lo, (unsigned long long)s->line);
	if (!next_tok(&q, le, &t2, &l2) || !next_tok(&q, le, &t3, &l3) || !tok_eq(t3, l3, "1.0"))
		return fail(s->c, "byte %llu (line %llu): expected 'format ascii|binary_little_endian|binary_big_endian 1.0'", lo, (unsigned long long)s->line);
	if (tok_eq(t2, l2, "ascii")) s->fmt = 0;
	else if (tok_eq(t2, l2, "binary_little_endian")) s->fmt = 1;
	else if (tok_eq(t2, l2, "binary_big_endian")) s->fmt = 2;
	else
		return fail(s->c, "byte %llu (line %llu): unknown format '%s'", lo, (unsigned long long)s->line, tok_show(t2, l2, sb, sizeof sb));
	return 0;
}

/* "element NAME COUNT" */
static int ply_hdr_element(ply_st *s, const unsigned char *q, const unsigned char *le, unsigned long long lo)
{
	const unsigned char *t, *t2, *t3;
	size_t tl, l2, l3;
	long long cnt;
	ply_elem *e;
	if (s->ne == PLY_MAX_ELEMS)
		return fail(s->c, "byte %llu (line %llu): more than %d elements", lo, (unsigned long long)s->line, PLY_MAX_ELEMS);
	if (!next_tok(&q, le, &t2, &l2) || l2 >= PLY_NAME || !next_tok(&q, le, &t3, &l3)
	    || !tok_ll(t3, l3, &cnt) || cnt < 0 || next_tok(&q, le, &t, &tl))
		return fail(s->c, "byte %llu (line %llu): expected 'element NAME COUNT' with a count >= 0", lo, (unsigned long long)s->line);
	e = &s->el[s->ne++];
	memcpy(e->name, t2, l2);
	e->name[l2] = '\0';
	e->count = (unsigned long long)cnt;
	e->ix = e->iy = e->iz = e->inx = e->iny = e->inz = e->ilist = -1;
	return 0;
}

/* The rest of "property TYPE NAME" or "property list COUNTTYPE ITEMTYPE
   NAME" into pr; 0, or -1 when it is neither (no message). */
static int ply_prop_parse(const unsigned char *q, const unsigned char *le, ply_prop *pr)
{
	const unsigned char *t, *t2, *tn;
	size_t tl, l2, ln;
	memset(pr, 0, sizeof *pr);
	if (!next_tok(&q, le, &t2, &l2))
		return -1;
	if (tok_eq(t2, l2, "list")) {
		const unsigned char *t3, *t4;
		size_t l3, l4;
		if (!next_tok(&q, le, &t3, &l3) || !next_tok(&q, le, &t4, &l4))
			return -1;
		pr->list = 1;
		pr->ctype = pt_lookup(t3, l3);
		pr->type = pt_lookup(t4, l4);
		if (pr->ctype == PT_NONE || pr->type == PT_NONE || pr->ctype == PT_F32 || pr->ctype == PT_F64)
			return -1;
	} else {
		pr->type = pt_lookup(t2, l2);
		if (pr->type == PT_NONE)
			return -1;
	}
	if (!next_tok(&q, le, &tn, &ln) || ln >= PLY_NAME || next_tok(&q, le, &t, &tl))
		return -1;
	memcpy(pr->name, tn, ln);
	pr->name[ln] = '\0';
	return 0;
}

/* The property index slot a scalar property NAME fills, or NULL. */
static int *ply_slot(ply_elem *e, const char *name)
{
	if (!strcmp(name, "x")) return &e->ix;
	if (!strcmp(name, "y")) return &e->iy;
	if (!strcmp(name, "z")) return &e->iz;
	/* normal_x ...: the PCL and Open3D names */
	if (!strcmp(name, "nx") || !strcmp(name, "normal_x")) return &e->inx;
	if (!strcmp(name, "ny") || !strcmp(name, "normal_y")) return &e->iny;
	if (!strcmp(name, "nz") || !strcmp(name, "normal_z")) return &e->inz;
	return NULL;
}

/* "property ..." of the last element */
static int ply_hdr_property(ply_st *s, const unsigned char *q, const unsigned char *le, unsigned long long lo)
{
	unsigned long long ln = (unsigned long long)s->line;
	ply_prop pr;
	ply_elem *e;
	if (s->ne == 0)
		return fail(s->c, "byte %llu (line %llu): 'property' before any 'element'", lo, ln);
	e = &s->el[s->ne - 1];
	if (e->nprop == PLY_MAX_PROPS)
		return fail(s->c, "byte %llu (line %llu): more than %d properties in element '%s'", lo, ln, PLY_MAX_PROPS, e->name);
	if (ply_prop_parse(q, le, &pr) != 0)
		return fail(s->c, "byte %llu (line %llu): expected 'property TYPE NAME' or 'property list COUNTTYPE ITEMTYPE NAME' (integer count type)",
		            lo, ln);
	if (!pr.list) {
		int *slot = ply_slot(e, pr.name);
		if (slot) {
			if (*slot >= 0)
				return fail(s->c, "byte %llu (line %llu): property '%s' twice in element '%s' (nx and normal_x name the same)", lo, ln, pr.name, e->name);
			*slot = e->nprop;
		}
	} else if (!strcmp(pr.name, "vertex_indices") || !strcmp(pr.name, "vertex_index")) {
		if (pr.type == PT_F32 || pr.type == PT_F64)
			return fail(s->c, "byte %llu (line %llu): list '%s' must hold integers", lo, ln, pr.name);
		e->ilist = e->nprop;
	}
	e->prop[e->nprop++] = pr;
	return 0;
}

/* One header statement (t: its keyword; [q, le): the rest; lo: its byte offset). */
static int ply_hdr_statement(ply_st *s, mesh_normals *m, const unsigned char *t, size_t tl,
                             const unsigned char *q, const unsigned char *le, unsigned long long lo)
{
	if (tok_eq(t, tl, "format"))
		return ply_hdr_format(s, q, le, lo);
	if (tok_eq(t, tl, "comment") || tok_eq(t, tl, "obj_info"))
		return 0;
	if (tok_eq(t, tl, "element"))
		return ply_hdr_element(s, q, le, lo);
	if (tok_eq(t, tl, "property"))
		return ply_hdr_property(s, q, le, lo);
	/* not in the PLY grammar (e.g. Blender 2.4's "Created by ..."
	   line): skipped, counted and reported, as most readers do */
	if (m->header_skipped++ == 0)
		m->header_skipped_line = s->line;
	return 0;
}

/* The header: one statement a line, up to end_header; *pp is left after it. */
static int ply_header(ply_st *s, const unsigned char *buf, const unsigned char **pp, const unsigned char *end,
                      mesh_normals *m)
{
	const unsigned char *p = *pp;
	int have_end = 0, magic = 0;
	while (p < end) {
		const unsigned char *eol = memchr(p, '\n', (size_t)(end - p));
		const unsigned char *le = eol ? eol : end, *q = p, *t;
		unsigned long long lo = (unsigned long long)(p - buf);
		size_t tl;
		s->line++;
		p = eol ? eol + 1 : end;
		if (!next_tok(&q, le, &t, &tl)) {
			if (s->line == 1)
				break;
			continue;
		}
		if (s->line == 1) {
			if (!tok_eq(t, tl, "ply") || next_tok(&q, le, &t, &tl))
				break;
			magic = 1;
			continue;
		}
		if (tok_eq(t, tl, "end_header")) {
			have_end = 1;
			break;
		}
		if (ply_hdr_statement(s, m, t, tl, q, le, lo) != 0)
			return -1;
	}
	*pp = p;
	if (!magic)
		return fail(s->c, "byte 0: not a PLY file (first line is not 'ply')");
	if (!have_end)
		return fail(s->c, "byte %llu: header has no 'end_header' line", (unsigned long long)(end - buf));
	if (s->fmt < 0)
		return fail(s->c, "byte 0: header has no 'format' line");
	return 0;
}

/* What to read: each element's count against the `remain` bytes that
   follow the header (at byte `at`); the vertex and face elements; the
   number of normals. */
static int ply_plan(ply_st *s, unsigned long long at, unsigned long long remain)
{
	unsigned long long need = 0;
	int i;
	for (i = 0; i < s->ne; i++) {
		ply_elem *e = &s->el[i];
		unsigned long long rec = 0;
		int k;
		if (e->count == 0)
			continue;
		if (e->nprop == 0)
			return fail(s->c, "byte %llu: element '%s' has %llu records but no properties", at, e->name, e->count);
		for (k = 0; k < e->nprop; k++)
			rec += s->fmt == 0 ? 2 : pt_size[e->prop[k].list ? e->prop[k].ctype : e->prop[k].type];
		/* ascii: each value is at least one character and a separator */
		if (e->count > (remain + 1) / rec || need + e->count * rec > remain + 1)
			return fail(s->c, "byte %llu: element '%s' count %llu needs at least %llu bytes per record, but only %llu bytes follow the header",
			            at, e->name, e->count, rec, remain);
		need += e->count * rec;
		if (ply_isn(e)) {
			s->normal_elems++;
			s->nnorm += e->count;
		}
		if (!strcmp(e->name, "vertex") && s->vert_e < 0)
			s->vert_e = i;
		if (!strcmp(e->name, "face") && s->face_e < 0)
			s->face_e = i;
	}
	for (i = 0; i < s->ne && s->vert_e < 0; i++)
		if (!strcmp(s->el[i].name, "vertex"))
			s->vert_e = i;
	for (i = 0; i < s->ne && s->face_e < 0; i++)
		if (!strcmp(s->el[i].name, "face"))
			s->face_e = i;
	if (s->nnorm > MESH_MAX_ITEMS)
		return fail(s->c, "%llu normals: more than the %llu accepted", s->nnorm, (unsigned long long)MESH_MAX_ITEMS);
	return 0;
}

/* 1 when there is a 'vertex' element with x, y, z and a 'face' element with vertex_indices. */
static int ply_has_mesh(const ply_st *s)
{
	const ply_elem *el = s->el;
	return !(s->vert_e < 0 || el[s->vert_e].ix < 0 || el[s->vert_e].iy < 0 || el[s->vert_e].iz < 0
	         || s->face_e < 0 || el[s->face_e].ilist < 0);
}

/* The type the stored normals all have, or MESH_T_OTHER. */
static int ply_stored_type(const ply_st *s)
{
	int all_f = 1, all_d = 1, i, k;
	for (i = 0; i < s->ne; i++)
		if (ply_isn(&s->el[i])) {
			const ply_elem *e = &s->el[i];
			int ts[3];
			ts[0] = e->prop[e->inx].type; ts[1] = e->prop[e->iny].type; ts[2] = e->prop[e->inz].type;
			for (k = 0; k < 3; k++) {
				all_f &= ts[k] == PT_F32;
				all_d &= ts[k] == PT_F64;
			}
		}
	return all_f ? MESH_T_FLOAT : all_d ? MESH_T_DOUBLE : MESH_T_OTHER;
}

/* Stored normals: room for them in m, and what they are; to be computed:
   checks that they can be. */
static int ply_setup_normals(ply_st *s, int compute, mesh_normals *m)
{
	int i;
	if (compute) {
		if (!ply_has_mesh(s))
			return fail(s->c, "no normals: no element has nx, ny, nz (or normal_x, normal_y, normal_z), and there is no 'vertex' element with x, y, z and 'face' element with vertex_indices to compute them from");
		if (s->nvert > MESH_MAX_ITEMS)
			return fail(s->c, "%llu vertices: more than the %llu accepted", s->nvert, (unsigned long long)MESH_MAX_ITEMS);
		return 0;
	}
	if (alloc_normals(m, (size_t)s->nnorm) != 0)
		return fail(s->c, "out of memory for %llu normals", s->nnorm);
	m->count = (size_t)s->nnorm;
	m->element[0] = '\0';
	for (i = 0; i < s->ne; i++)
		if (ply_isn(&s->el[i]) && s->el[i].count) {
			size_t l = strlen(m->element);
			snprintf(m->element + l, sizeof m->element - l, "%s%s", l ? "," : "", s->el[i].name);
		}
	m->stored_type = ply_stored_type(s);
	m->origin = MESH_STORED;
	return 0;
}

/* Room for the positions (to compute normals, or for a renderer: geom). */
static int ply_alloc_positions(ply_st *s, int geom)
{
	if (geom && !ply_has_mesh(s))
		return fail(s->c, "no geometry: no 'vertex' element with x, y, z and 'face' element with vertex_indices");
	if (s->nvert > MESH_MAX_ITEMS)
		return fail(s->c, "%llu vertices: more than the %llu accepted", s->nvert, (unsigned long long)MESH_MAX_ITEMS);
	s->pos = xcalloc((size_t)s->nvert, 3 * sizeof *s->pos);
	s->vwhere = xcalloc((size_t)s->nvert, sizeof *s->vwhere);
	if (!s->pos || !s->vwhere)
		return fail(s->c, "out of memory for %llu vertices", s->nvert);
	return 0;
}

/* List property k of record ei of element i (the record starts at byte
   at).  The face element's vertex indices are checked whether or not
   normals are computed from them, and kept when positions are read. */
static int ply_list(ply_st *s, ply_rd *r, int i, unsigned long long ei, int k, unsigned long long at)
{
	mctx *c = s->c;
	const ply_elem *e = &s->el[i];
	const ply_prop *pr = &e->prop[k];
	int isidx = i == s->face_e && k == e->ilist, isf = s->positions && i == s->face_e;
	unsigned long long cat = off(r), remain;
	long long cnt, j, iv;
	double dv;
	face_rec fr;
	if (ply_value(r, pr->ctype, e, ei, pr->name, &dv, &cnt) != 0)
		return -1;
	remain = (unsigned long long)(r->end - r->p);
	if (cnt < 0 || (unsigned long long)cnt > (r->fmt == 0 ? remain / 2 + 1 : remain / pt_size[pr->type]))
		return fail(c, "byte %llu: truncated or bad count: list '%s' of element '%s' %llu has count %lld, but only %llu bytes remain",
		            cat, pr->name, e->name, ei, cnt, remain);
	fr.first = s->corners.n;
	fr.count = (size_t)cnt;
	fr.where = at;
	for (j = 0; j < cnt; j++) {
		unsigned long long iat = off(r);
		if (ply_value(r, pr->type, e, ei, pr->name, &dv, &iv) != 0)
			return -1;
		if (isidx) {
			uint32_t u;
			if (iv < 0 || (unsigned long long)iv >= s->nvert)
				return fail(c, "byte %llu: face %llu: vertex index %lld out of range [0, %llu)", iat, ei, iv, s->nvert);
			u = (uint32_t)iv;
			if (isf && gvec_push(&s->corners, &u) != 0)
				return fail(c, "byte %llu: too many face corners, or out of memory", iat);
		}
	}
	if (isf && isidx && cnt >= 3 && gvec_push(&s->faces, &fr) != 0)
		return fail(c, "byte %llu: too many faces, or out of memory", at);
	return 0;
}

/* Record ei of element i: its normal into m, its position into s->pos. */
static int ply_record(ply_st *s, ply_rd *r, mesh_normals *m, int i, unsigned long long ei)
{
	const ply_elem *e = &s->el[i];
	int isn = ply_isn(e), isv = s->positions && i == s->vert_e, k;
	unsigned long long at;
	double nv[3] = { 0, 0, 0 }, dv;
	long long iv;
	/* the record starts at its first value (ascii: after blanks) */
	if (r->fmt == 0)
		while (r->p < r->end && (is_space(*r->p) || *r->p == '\n')) {
			if (*r->p == '\n')
				r->line++;
			r->p++;
		}
	at = off(r);
	for (k = 0; k < e->nprop; k++) {
		const ply_prop *pr = &e->prop[k];
		if (pr->list) {
			if (ply_list(s, r, i, ei, k, at) != 0)
				return -1;
			continue;
		}
		if (ply_value(r, pr->type, e, ei, pr->name, &dv, &iv) != 0)
			return -1;
		if (isn) {
			if (k == e->inx) nv[0] = dv;
			else if (k == e->iny) nv[1] = dv;
			else if (k == e->inz) nv[2] = dv;
		}
		if (isv) {
			if (k == e->ix) s->pos[3 * ei] = dv;
			else if (k == e->iy) s->pos[3 * ei + 1] = dv;
			else if (k == e->iz) s->pos[3 * ei + 2] = dv;
		}
	}
	if (isn) {
		m->x[s->kn] = nv[0]; m->y[s->kn] = nv[1]; m->z[s->kn] = nv[2];
		m->where[s->kn] = at;
		m->index[s->kn] = (size_t)ei;
		s->kn++;
	}
	if (isv)
		s->vwhere[ei] = at;
	return 0;
}

/* The body: every record of every element, then what follows the last. */
static int ply_body(ply_st *s, ply_rd *r, mesh_normals *m)
{
	unsigned long long ei;
	int i;
	for (i = 0; i < s->ne; i++)
		for (ei = 0; ei < s->el[i].count; ei++)
			if (ply_record(s, r, m, i, ei) != 0)
				return -1;
	if (r->fmt == 0) {
		while (r->p < r->end && (is_space(*r->p) || *r->p == '\n' || *r->p == '\0'))
			r->p++;
		if (r->p < r->end)
			return fail(s->c, "byte %llu: data after the last element (the header's counts are wrong?)", off(r));
	} else if (r->p < r->end) {
		/* assimp and others read such files: a warning, not an error */
		snprintf(m->warning, sizeof m->warning, "byte %llu: %llu bytes after the last element ignored (the header's counts are wrong?)",
		         off(r), (unsigned long long)(r->end - r->p));
	}
	return 0;
}

/* Area-weighted vertex normals from the faces read. */
static int ply_compute(ply_st *s, mesh_normals *m)
{
	if (s->faces.n == 0)
		return fail(s->c, "no normals: no element has nx, ny, nz, and no face has 3 or more vertices");
	m->nfaces = s->faces.n;
	if (compute_normals(s->c, m, s->pos, (size_t)s->nvert, s->vwhere, s->corners.p, s->faces.p, s->faces.n) != 0)
		return -1;
	m->stored_type = MESH_T_DOUBLE;
	snprintf(m->element, sizeof m->element, "vertex");
	return 0;
}

static int read_ply(mctx *c, const unsigned char *buf, size_t len, mesh_normals *m, mesh_geom *geom)
{
	const unsigned char *p = buf, *end = buf + len;
	ply_st s;
	ply_rd r;
	int compute, rc = -1;
	memset(&s, 0, sizeof s);
	s.c = c;
	s.fmt = -1;
	s.vert_e = s.face_e = -1;
	gvec_init(&s.corners, sizeof(uint32_t));
	gvec_init(&s.faces, sizeof(face_rec));
	m->format = MESH_PLY;
	s.el = xcalloc(PLY_MAX_ELEMS, sizeof *s.el);
	if (!s.el)
		return fail(c, "out of memory");
	if (ply_header(&s, buf, &p, end, m) != 0)
		goto out;
	m->ply_binary = s.fmt;
	if (ply_plan(&s, (unsigned long long)(p - buf), (unsigned long long)(end - p)) != 0)
		goto out;
	compute = s.normal_elems == 0;
	if (s.vert_e >= 0)
		s.nvert = s.el[s.vert_e].count;
	m->nvertices = (size_t)s.nvert;
	if (ply_setup_normals(&s, compute, m) != 0)
		goto out;
	s.positions = compute || geom;
	if (s.positions && ply_alloc_positions(&s, geom != NULL) != 0)
		goto out;
	r.c = c; r.buf = buf; r.p = p; r.end = end; r.fmt = s.fmt; r.line = s.line + 1;
	if (ply_body(&s, &r, m) != 0)
		goto out;
	if (s.face_e >= 0)
		m->nfaces = (size_t)s.el[s.face_e].count;
	if (compute && ply_compute(&s, m) != 0)
		goto out;
	if (geom && ply_geom(c, m, s.pos, (size_t)s.nvert, s.el, s.vert_e, &s.corners, &s.faces, geom) != 0)
		goto out;
	rc = 0;
out:
	if (rc != 0)
		mesh_free(m);
	free(s.el); free(s.pos); free(s.vwhere);
	gvec_free(&s.corners); gvec_free(&s.faces);
	return rc;
}

/* ------------------------------------------------------------------ */
/* entry points                                                        */
/* ------------------------------------------------------------------ */

static int has_ext(const char *name, const char *ext)
{
	size_t n, e = strlen(ext), i;
	if (!name)
		return 0;
	n = strlen(name);
	if (n < e)
		return 0;
	for (i = 0; i < e; i++) {
		char a = name[n - e + i];
		if (a >= 'A' && a <= 'Z')
			a = (char)(a - 'A' + 'a');
		if (a != ext[i])
			return 0;
	}
	return 1;
}

/* The format from the first bytes (see meshio.h).  Returns MESH_OBJ,
   MESH_PLY or MESH_GLTF, or 0 with *what naming a format that is not read. */
static int detect(const char *name, const unsigned char *b, size_t n, const char **what)
{
	size_t i, k, nul = 0, ctl = 0, look = n < 4096 ? n : 4096;
	*what = NULL;
	if (n >= 4 && !memcmp(b, "ply", 3) && (b[3] == '\n' || b[3] == '\r'))
		return MESH_PLY;
	if (n >= 4 && !memcmp(b, "glTF", 4))
		return MESH_GLTF;
	for (i = 0; i < look && is_space(b[i]); i++)
		;
	if (i < look && b[i] == '{')
		return MESH_GLTF;
	if (n >= 2 && ((b[0] == 0xfe && b[1] == 0xff) || (b[0] == 0xff && b[1] == 0xfe)))
		return MESH_OBJ; /* UTF-16 text: the OBJ reader says so */
	if (n >= 4 && !memcmp(b, "\x7f" "ELF", 4)) { *what = "an ELF executable or library"; return 0; }
	if (n >= 18 && !memcmp(b, "Kaydara FBX Binary", 18)) { *what = "FBX (binary)"; return 0; }
	if (n >= 84) {
		uint32_t cnt = (uint32_t)b[80] | (uint32_t)b[81] << 8 | (uint32_t)b[82] << 16 | (uint32_t)b[83] << 24;
		if ((uint64_t)n == 84 + 50 * (uint64_t)cnt) { *what = "STL (binary)"; return 0; }
	}
	if (n >= 6 && b[0] == 0x4d && b[1] == 0x4d) {
		uint32_t l = (uint32_t)b[2] | (uint32_t)b[3] << 8 | (uint32_t)b[4] << 16 | (uint32_t)b[5] << 24;
		if (l == n) { *what = "3DS (Autodesk 3D Studio)"; return 0; }
	}
	for (k = 0; k < look; k++) {
		nul += b[k] == 0;
		ctl += b[k] < 0x20 && !is_space(b[k]) && b[k] != 0x1a;
	}
	if (look - i >= 5 && !memcmp(b + i, "solid", 5) && (look - i == 5 || is_space(b[i + 5])) && !nul) {
		*what = "STL (ascii)";
		return 0;
	}
	if (look - i >= 5 && !memcmp(b + i, "<?xml", 5)) {
		*what = "XML";
		for (k = i; k + 7 <= look; k++)
			if (!memcmp(b + k, "COLLADA", 7)) {
				*what = "Collada (.dae)";
				break;
			}
		return 0;
	}
	if (look - i >= 5 && (!memcmp(b + i, "; FBX", 5) || !memcmp(b + i, "FBXHe", 5))) { *what = "FBX (ascii)"; return 0; }
	if (nul || ctl * 20 > look) { *what = "binary data of an unknown format"; return 0; }
	if (has_ext(name, ".ply"))
		return MESH_PLY;  /* its reader says what is wrong */
	if (has_ext(name, ".gltf") || has_ext(name, ".glb"))
		return MESH_GLTF;
	return MESH_OBJ;
}

static const char *ext_mismatch(const char *name, int fmt)
{
	static const struct { const char *ext; int fmt; } ex[] = {
		{ ".obj", MESH_OBJ }, { ".ply", MESH_PLY }, { ".gltf", MESH_GLTF }, { ".glb", MESH_GLTF } };
	size_t i;
	for (i = 0; i < sizeof ex / sizeof ex[0]; i++)
		if (has_ext(name, ex[i].ext))
			return ex[i].fmt == fmt ? NULL : ex[i].ext;
	return NULL;
}

int mesh_read_mem(const char *name, const unsigned char *buf, size_t len,
                  mesh_normals *out, char *err, size_t errlen)
{
	return mesh_read_mem_opts(name, buf, len, NULL, out, NULL, err, errlen);
}

int mesh_read_geom_mem(const char *name, const unsigned char *buf, size_t len,
                       mesh_normals *out, mesh_geom *geom, char *err, size_t errlen)
{
	return mesh_read_mem_opts(name, buf, len, NULL, out, geom, err, errlen);
}

static int read_mem(mctx *c, const unsigned char *buf, size_t len, const mesh_opts *o,
                    mesh_normals *out, mesh_geom *geom)
{
	static const mesh_opts defaults;
	const char *what, *bad;
	int rc, fmt;
	memset(out, 0, sizeof *out);
	if (geom)
		memset(geom, 0, sizeof *geom);
	if (!buf && len)
		return fail(c, "no data");
	if (len == 0)
		return fail(c, "empty file");
	fmt = detect(c->name, buf, len, &what);
	if (!fmt)
		return fail(c, "%s, which is not read here; supported: OBJ, PLY, glTF 2.0 (.gltf, .glb)", what);
	rc = fmt == MESH_PLY ? read_ply(c, buf, len, out, geom) : fmt == MESH_GLTF ? mio_read_gltf(c, buf, len, o ? o : &defaults, out, geom)
	     : read_obj(c, buf, len, out, geom);
	if (rc != 0) {
		mesh_free(out);
		mesh_geom_free(geom);
		return rc;
	}
	if ((bad = ext_mismatch(c->name, fmt)) != NULL) {
		size_t l = strlen(out->warning);
		snprintf(out->warning + l, sizeof out->warning - l, "%sthe name ends in %s, but the content is %s", l ? "; " : "", bad,
		         fmt == MESH_PLY ? "PLY" : fmt == MESH_GLTF ? "glTF" : "OBJ");
	}
	return 0;
}

int mesh_read_mem_opts(const char *name, const unsigned char *buf, size_t len, const mesh_opts *o,
                       mesh_normals *out, mesh_geom *geom, char *err, size_t errlen)
{
	mctx c;
	c.err = err; c.errlen = errlen; c.name = name; c.dir = NULL;
	if (err && errlen)
		err[0] = '\0';
	return read_mem(&c, buf, len, o, out, geom);
}

int mesh_read_file(const char *path, mesh_normals *out, char *err, size_t errlen)
{
	return mesh_read_file_opts(path, NULL, out, NULL, err, errlen);
}

int mesh_read_geom_file(const char *path, mesh_normals *out, mesh_geom *geom, char *err, size_t errlen)
{
	return mesh_read_file_opts(path, NULL, out, geom, err, errlen);
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

int mesh_read_file_opts(const char *path, const mesh_opts *o, mesh_normals *out, mesh_geom *geom,
                        char *err, size_t errlen)
{
	mctx c;
	unsigned char *buf;
	size_t len;
	char dir[4096];
	const char *s = strrchr(path, '/');
	int rc;
	c.err = err; c.errlen = errlen; c.name = path; c.dir = dir;
	if (err && errlen)
		err[0] = '\0';
	memset(out, 0, sizeof *out);
	if (geom)
		memset(geom, 0, sizeof *geom);
	if (!s)
		snprintf(dir, sizeof dir, ".");
	else if ((size_t)(s - path) < sizeof dir)
		snprintf(dir, sizeof dir, "%.*s", (int)(s == path ? 1 : s - path), path);
	else
		return fail(&c, "path too long");
	if (mio_slurp(&c, path, &buf, &len) != 0)
		return -1;
	rc = read_mem(&c, buf, len, o, out, geom);
	free(buf);
	return rc;
}

/* ------------------------------------------------------------------ */
/* classification                                                      */
/* ------------------------------------------------------------------ */

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

int mesh_classify(const mesh_normals *m, int use_float, double tol, mesh_stats *st)
{
	size_t i, k = 0;
	double *dev;
	memset(st, 0, sizeof *st);
	st->tol = tol > 0 ? tol : use_float ? 4.0 * FLT_EPSILON : 4.0 * DBL_EPSILON;
	st->total = m->count;
	dev = xcalloc(m->count, sizeof *dev);
	if (!dev)
		return -1;
	for (i = 0; i < m->count; i++) {
		long double x = m->x[i], y = m->y[i], z = m->z[i], l, d;
		if (use_float) {
			x = (float)m->x[i]; y = (float)m->y[i]; z = (float)m->z[i];
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
