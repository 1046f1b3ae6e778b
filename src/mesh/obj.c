/*
 * obj.c - the Wavefront OBJ normal reader (see meshio.h for what counts as a
 * normal).  Bounded by the buffer length everywhere (no NUL termination is
 * assumed); every count is checked before anything is allocated.
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
#include "mesh/obj.h"

#define fail mio_fail
#define xcalloc mio_calloc
#define alloc_normals mio_alloc_normals
#define compute_normals mio_compute_normals

/* ------------------------------------------------------------------ */
/* OBJ                                                                 */
/* ------------------------------------------------------------------ */

/* Resolve one OBJ index (1-based, or negative relative to n so far). */
static int obj_index(mctx *c, uint64_t line, const char *what, const unsigned char *t, size_t tl,
                     size_t n, size_t *out)
{
	long long v;
	char sb[64];
	if (!mio_tok_ll(t, tl, &v))
		return fail(c, "line %llu: bad %s index '%s'", (unsigned long long)line, what, mio_tok_show(t, tl, sb, sizeof sb));
	if (v > 0 && (unsigned long long)v <= n) { *out = (size_t)(v - 1); return 0; }
	if (v < 0 && (unsigned long long)(-(v + 1)) < n) { *out = n - (size_t)(-(v + 1)) - 1; return 0; }
	return fail(c, "line %llu: %s index %lld out of range (%zu defined so far)", (unsigned long long)line, what, v, n);
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
	while (mio_next_tok(&q, le, &t, &tl)) {
		if (k == (isn ? 3 : 7))
			return fail(c, "line %llu: too many numbers in '%s' (at most %d)", (unsigned long long)st->line, isn ? "vn" : "v", isn ? 3 : 7);
		if (!mio_tok_double(t, tl, &v[k]))
			return fail(c, "line %llu: bad number '%s'", (unsigned long long)st->line, mio_tok_show(t, tl, sb, sizeof sb));
		k++;
	}
	if (k < 3)
		return fail(c, "line %llu: '%s' needs 3 numbers, got %d", (unsigned long long)st->line, isn ? "vn" : "v", k);
	if (mio_gvec_push(isn ? &st->vn : &st->pos, v) != 0 || mio_gvec_push(isn ? &st->vnwhere : &st->vwhere, &st->line) != 0)
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
	while (mio_next_tok(&q, le, &t, &tl)) {
		if (!mio_tok_double(t, tl, &v) || ++k > 3)
			return fail(st->c, "line %llu: bad texture coordinate '%s'", (unsigned long long)st->line, mio_tok_show(t, tl, sb, sizeof sb));
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
		return fail(c, "line %llu: bad face vertex '%s'", (unsigned long long)st->line, mio_tok_show(t, tl, sb, sizeof sb));
	if (obj_index(c, st->line, "vertex", t, s1 ? (size_t)(s1 - t) : tl, st->pos.n, &vi) != 0)
		return -1;
	if (s1) {
		const unsigned char *b = s1 + 1, *be = s2 ? s2 : t + tl;
		if (be > b && obj_index(c, st->line, "texture", b, (size_t)(be - b), st->nvt, &other) != 0)
			return -1;
		if (!s2 && be == b)
			return fail(c, "line %llu: bad face vertex '%s'", (unsigned long long)st->line, mio_tok_show(t, tl, sb, sizeof sb));
		if (s2 && obj_index(c, st->line, "normal", s2 + 1, (size_t)(t + tl - s2 - 1), st->vn.n, &other) != 0)
			return -1;
		if (s2)
			un = (uint32_t)other;
	}
	u = (uint32_t)vi;
	if (mio_gvec_push(&st->corners, &u) != 0 || (st->want_cnorm && mio_gvec_push(&st->cnorm, &un) != 0))
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
	while (mio_next_tok(&q, le, &t, &tl)) {
		if (obj_corner(st, t, tl) != 0)
			return -1;
		fr.count++;
	}
	if (fr.count < 3)
		return fail(st->c, "line %llu: a face needs at least 3 vertices, got %zu", (unsigned long long)st->line, fr.count);
	if (mio_gvec_push(&st->faces, &fr) != 0)
		return fail(st->c, "line %llu: too many faces, or out of memory", (unsigned long long)st->line);
	return 0;
}

/* One logical line [q, le), its comment cut off. */
static int obj_statement(obj_st *st, const unsigned char *q, const unsigned char *le)
{
	const unsigned char *t;
	size_t tl;
	if (!mio_next_tok(&q, le, &t, &tl))
		return 0;
	if (mio_tok_eq(t, tl, "v") || mio_tok_eq(t, tl, "vn"))
		return obj_vertex(st, tl == 2, q, le);
	if (mio_tok_eq(t, tl, "vt"))
		return obj_texcoord(st, q, le);
	if (mio_tok_eq(t, tl, "f"))
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

int mio_read_obj(mctx *c, const unsigned char *buf, size_t len, mesh_normals *m, mesh_geom *geom)
{
	unsigned char *joined = NULL;
	const unsigned char *p = buf, *end = buf + len;
	obj_st st;
	int rc = -1;
	st.c = c;
	st.line = st.pending = 0;
	st.nvt = 0;
	st.want_cnorm = geom != NULL;
	mio_gvec_init(&st.pos, 3 * sizeof(double)); mio_gvec_init(&st.vwhere, sizeof(uint64_t));
	mio_gvec_init(&st.vn, 3 * sizeof(double)); mio_gvec_init(&st.vnwhere, sizeof(uint64_t));
	mio_gvec_init(&st.corners, sizeof(uint32_t)); mio_gvec_init(&st.faces, sizeof(face_rec));
	mio_gvec_init(&st.cnorm, sizeof(uint32_t));
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
	mio_gvec_free(&st.pos); mio_gvec_free(&st.vwhere); mio_gvec_free(&st.vn); mio_gvec_free(&st.vnwhere);
	mio_gvec_free(&st.corners); mio_gvec_free(&st.cnorm); mio_gvec_free(&st.faces);
	free(joined);
	return rc;
}
