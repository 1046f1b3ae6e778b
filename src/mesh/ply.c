/*
 * ply.c - the PLY normal reader, ascii and binary (see meshio.h).  Every
 * count is checked against the bytes that remain before anything is
 * allocated, and every allocation size for overflow.
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
#include "mesh/ply.h"

#define fail mio_fail
#define xcalloc mio_calloc
#define alloc_normals mio_alloc_normals
#define compute_normals mio_compute_normals

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
		if (mio_tok_eq(t, tl, ply_types[i].name))
			return ply_types[i].type;
	return PT_NONE;
}

static unsigned long long off(const ply_rd *r) { return (unsigned long long)(r->p - r->buf); }

/* One binary value of type `type` (pt_size[type] bytes at r->p, in the
   file's byte order): the bytes are assembled into an integer by shifts,
   so the value is the same on a little- or big-endian host (s390x,
   say); floats take that integer's bits. */
static void ply_binary_value(ply_rd *r, int type, double *dv, long long *iv)
{
	size_t n = pt_size[type], i;
	uint64_t u = 0;
	for (i = 0; i < n; i++)
		u |= (uint64_t)r->p[r->fmt == 1 ? i : n - 1 - i] << (8 * i);
	r->p += n;
	if (type == PT_F32) {
		uint32_t w = (uint32_t)u;
		float f;
		memcpy(&f, &w, sizeof f);
		*dv = f; *iv = 0;
		return;
	}
	if (type == PT_F64) {
		double d;
		memcpy(&d, &u, sizeof d);
		*dv = d; *iv = 0;
		return;
	}
	*iv = (long long)u;
	if ((type == PT_I8 || type == PT_I16 || type == PT_I32) && (u >> (8 * n - 1)) != 0)
		*iv -= (long long)1 << (8 * n); /* two's complement, negative */
	*dv = (double)*iv;
}

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
			while (r->p < r->end && (mio_is_space(*r->p) || *r->p == '\n')) {
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
		mio_next_tok(&r->p, r->end, &t, &tl);
		if (type == PT_F32 || type == PT_F64) {
			if (!(type == PT_F32 ? mio_tok_float(t, tl, dv) : mio_tok_double(t, tl, dv)))
				return fail(c, "byte %llu (line %llu): bad number '%s' for property '%s' of element '%s' %llu",
				            at, (unsigned long long)r->line, mio_tok_show(t, tl, sb, sizeof sb), pname, e->name, ei);
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
			if (!mio_tok_ll(t, tl, &v) || v < lo || v > hi)
				return fail(c, "byte %llu (line %llu): bad integer '%s' for property '%s' of element '%s' %llu",
				            at, (unsigned long long)r->line, mio_tok_show(t, tl, sb, sizeof sb), pname, e->name, ei);
			*iv = v;
			*dv = (double)v;
		}
		return 0;
	} else {
		size_t n = pt_size[type];
		if ((size_t)(r->end - r->p) < n)
			return fail(c, "byte %llu: truncated binary data: element '%s' %llu of %llu, property '%s' needs %zu bytes, %zu remain",
			            off(r), e->name, ei, e->count, pname, n, (size_t)(r->end - r->p));
		ply_binary_value(r, type, dv, iv);
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
	if (!mio_next_tok(&q, le, &t2, &l2) || !mio_next_tok(&q, le, &t3, &l3) || !mio_tok_eq(t3, l3, "1.0"))
		return fail(s->c, "byte %llu (line %llu): expected 'format ascii|binary_little_endian|binary_big_endian 1.0'", lo, (unsigned long long)s->line);
	if (mio_tok_eq(t2, l2, "ascii")) s->fmt = 0;
	else if (mio_tok_eq(t2, l2, "binary_little_endian")) s->fmt = 1;
	else if (mio_tok_eq(t2, l2, "binary_big_endian")) s->fmt = 2;
	else
		return fail(s->c, "byte %llu (line %llu): unknown format '%s'", lo, (unsigned long long)s->line, mio_tok_show(t2, l2, sb, sizeof sb));
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
	if (!mio_next_tok(&q, le, &t2, &l2) || l2 >= PLY_NAME || !mio_next_tok(&q, le, &t3, &l3)
	    || !mio_tok_ll(t3, l3, &cnt) || cnt < 0 || mio_next_tok(&q, le, &t, &tl))
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
	if (!mio_next_tok(&q, le, &t2, &l2))
		return -1;
	if (mio_tok_eq(t2, l2, "list")) {
		const unsigned char *t3, *t4;
		size_t l3, l4;
		if (!mio_next_tok(&q, le, &t3, &l3) || !mio_next_tok(&q, le, &t4, &l4))
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
	if (!mio_next_tok(&q, le, &tn, &ln) || ln >= PLY_NAME || mio_next_tok(&q, le, &t, &tl))
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
	if (mio_tok_eq(t, tl, "format"))
		return ply_hdr_format(s, q, le, lo);
	if (mio_tok_eq(t, tl, "comment") || mio_tok_eq(t, tl, "obj_info"))
		return 0;
	if (mio_tok_eq(t, tl, "element"))
		return ply_hdr_element(s, q, le, lo);
	if (mio_tok_eq(t, tl, "property"))
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
		if (!mio_next_tok(&q, le, &t, &tl)) {
			if (s->line == 1)
				break;
			continue;
		}
		if (s->line == 1) {
			if (!mio_tok_eq(t, tl, "ply") || mio_next_tok(&q, le, &t, &tl))
				break;
			magic = 1;
			continue;
		}
		if (mio_tok_eq(t, tl, "end_header")) {
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
	long long cnt, j, iv = 0;
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
			if (isf && mio_gvec_push(&s->corners, &u) != 0)
				return fail(c, "byte %llu: too many face corners, or out of memory", iat);
		}
	}
	if (isf && isidx && cnt >= 3 && mio_gvec_push(&s->faces, &fr) != 0)
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
		while (r->p < r->end && (mio_is_space(*r->p) || *r->p == '\n')) {
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
		while (r->p < r->end && (mio_is_space(*r->p) || *r->p == '\n' || *r->p == '\0'))
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

int mio_read_ply(mctx *c, const unsigned char *buf, size_t len, mesh_normals *m, mesh_geom *geom)
{
	const unsigned char *p = buf, *end = buf + len;
	ply_st s;
	ply_rd r;
	int compute, rc = -1;
	memset(&s, 0, sizeof s);
	s.c = c;
	s.fmt = -1;
	s.vert_e = s.face_e = -1;
	mio_gvec_init(&s.corners, sizeof(uint32_t));
	mio_gvec_init(&s.faces, sizeof(face_rec));
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
	mio_gvec_free(&s.corners); mio_gvec_free(&s.faces);
	return rc;
}
