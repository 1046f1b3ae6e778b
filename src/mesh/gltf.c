/*
 * gltf.c - the glTF 2.0 reader of meshio (see meshio.h for what it
 * reads): primitives, node transforms, scenes and geometry, from the
 * values gltf_data.c reads.  The JSON is parsed by cJSON; every binary
 * value is read byte by byte as little-endian (so bit-exactly, on any
 * host).
 *
 * Refused, each with one line naming the object: JSON that does not parse;
 * asset.version not 2.x; a required extension that changes the geometry
 * (KHR_draco_mesh_compression, EXT_meshopt_compression); a property of the
 * wrong type; an index out of range (buffer, bufferView, accessor, mesh,
 * node, scene, vertex); an accessor, sparse block or buffer view that does
 * not fit in what holds it; a NORMAL accessor that is not VEC3 FLOAT or
 * normalized BYTE/SHORT VEC3; sparse indices that do not increase; a node
 * with two parents or a cycle; a buffer URI that is not a base64 data: URI
 * or a plain relative path below the file's directory (no "..", no
 * scheme, no absolute path); more normals than MESH_MAX_ITEMS or than 16 per
 * byte of input (so memory stays bounded by the input).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "mesh/meshio.h"  /* up, for the public types (mesh_normals, mesh_geom, mesh_opts): the folder's face holds them */
#include "mesh/common.h"
#include "mesh/gltf.h"
#include "mesh/gltf_int.h"

/* ---- the normals of one primitive ---------------------------------------- */

/* Appends n normals (x, y, z interleaved in v) to g->m with their places. */
static int append(gltf *g, const double *v, size_t n, uint64_t tag, const size_t *vidx)
{
	mesh_normals *m = g->m;
	size_t i, need = m->count + n, limit = (size_t)MESH_MAX_ITEMS;
	if (g->inbytes < limit / 16)
		limit = 16 * g->inbytes + 4096;
	if (need > limit)
		return mio_fail(g->c, "more than %zu normals (at most 16 per byte of input, and %llu)", limit,
		                (unsigned long long)MESH_MAX_ITEMS);
	if (need > g->cap) {
		size_t cap = g->cap ? g->cap : 1024;
		double *p[3];
		uint64_t *w;
		size_t *ix;
		int k;
		while (cap < need)
			cap *= 2;
		for (k = 0; k < 3; k++) {
			double **a = k == 0 ? &m->x : k == 1 ? &m->y : &m->z;
			p[k] = realloc(*a, cap * sizeof **a);
			if (!p[k])
				return mio_fail(g->c, "out of memory for %zu normals", need);
			*a = p[k];
		}
		w = realloc(m->where, cap * sizeof *w);
		if (!w)
			return mio_fail(g->c, "out of memory for %zu normals", need);
		m->where = w;
		ix = realloc(m->index, cap * sizeof *ix);
		if (!ix)
			return mio_fail(g->c, "out of memory for %zu normals", need);
		m->index = ix;
		g->cap = cap;
	}
	for (i = 0; i < n; i++) {
		size_t k = m->count + i, vi = vidx ? vidx[i] : i;
		m->x[k] = v[3 * i]; m->y[k] = v[3 * i + 1]; m->z[k] = v[3 * i + 2];
		m->where[k] = tag | (uint64_t)(vi & 0xffffffffu);
		m->index[k] = vi;
	}
	m->count = need;
	return 0;
}

/* Triangles of a primitive: 3 vertex indices each (mode 4, 5 or 6). */
static size_t triangles(long long mode, const double *idx, size_t n, uint32_t *out)
{
	size_t i, t = 0;
#define V(k) ((uint32_t)(idx ? idx[k] : (double)(k)))
	if (mode == 4)
		for (i = 0; i + 2 < n; i += 3, t++) {
			out[3 * t] = V(i); out[3 * t + 1] = V(i + 1); out[3 * t + 2] = V(i + 2);
		}
	else if (mode == 5)
		for (i = 0; i + 2 < n; i++, t++) { /* the spec's order: odd triangles swap */
			out[3 * t] = V(i); out[3 * t + 1] = V(i + 1 + i % 2); out[3 * t + 2] = V(i + 2 - i % 2);
		}
	else if (mode == 6)
		for (i = 1; i + 1 < n; i++, t++) {
			out[3 * t] = V(i); out[3 * t + 1] = V(i + 1); out[3 * t + 2] = V(0);
		}
#undef V
	return t;
}

/* Area-weighted normals from positions and triangles: *nrm holds one per
   used vertex, vidx their vertex indices. */
static int computed(gltf *g, const double *pos, size_t nv, const uint32_t *tri, size_t nt, double **nrm,
                    size_t **vidx, size_t *n)
{
	mesh_normals t;
	face_rec *f = mio_calloc(nt, sizeof *f);
	uint64_t *vw = mio_calloc(nv, sizeof *vw);
	size_t i;
	int rc = -1;
	memset(&t, 0, sizeof t);
	*nrm = NULL;
	*vidx = NULL;
	if (!f || !vw) {
		mio_fail(g->c, "out of memory");
		goto out;
	}
	for (i = 0; i < nt; i++) {
		f[i].first = 3 * i;
		f[i].count = 3;
	}
	if (mio_compute_normals(g->c, &t, pos, nv, vw, tri, f, nt) != 0)
		goto out;
	*nrm = mio_calloc(t.count, 3 * sizeof **nrm);
	*vidx = mio_calloc(t.count, sizeof **vidx);
	if (!*nrm || !*vidx) {
		mio_fail(g->c, "out of memory");
		goto out;
	}
	for (i = 0; i < t.count; i++) {
		(*nrm)[3 * i] = t.x[i]; (*nrm)[3 * i + 1] = t.y[i]; (*nrm)[3 * i + 2] = t.z[i];
		(*vidx)[i] = t.index[i];
	}
	*n = t.count;
	g->m->ntriangles += t.ntriangles;
	rc = 0;
out:
	if (rc) {
		free(*nrm); free(*vidx);
		*nrm = NULL; *vidx = NULL;
	}
	mesh_free(&t);
	free(f);
	free(vw);
	return rc;
}

typedef struct {
	double *nrm;     /* 3 per normal */
	size_t *vidx;    /* their vertex indices, or NULL (0, 1, ...) */
	size_t n;
	int computed;    /* 1: area-weighted from the faces */
} prim_out;

/* The normals of primitive pi of mesh mi (n == 0: points or lines
   without NORMAL, nothing to read). */
static int primitive(gltf *g, long long mi, long long pi, const cJSON *pr, prim_out *po)
{
	const cJSON *at = gl_item(pr, "attributes"), *ext = gl_item(pr, "extensions");
	long long mode, ni, psi, ii, ct;
	double *pos = NULL, *idx = NULL;
	size_t np = 0, nidx = 0, nv, i;
	uint32_t *tri = NULL;
	int rc = -1;
	memset(po, 0, sizeof po[0]);
	if (!cJSON_IsObject(pr) || !cJSON_IsObject(at))
		return mio_fail(g->c, "mesh %lld primitive %lld: not an object with an 'attributes' object", mi, pi);
	if (gl_item(ext, "KHR_draco_mesh_compression") || gl_item(ext, "EXT_meshopt_compression"))
		return mio_fail(g->c, "mesh %lld primitive %lld: compressed geometry (Draco or meshopt) is not supported", mi, pi);
	if (gl_jint(g, pr, "mesh primitive", (long)pi, "mode", 4, 0, 6, &mode) != 0
	    || gl_jint(g, at, "mesh primitive", (long)pi, "NORMAL", -2, -2, 1 << 30, &ni) != 0
	    || gl_jint(g, at, "mesh primitive", (long)pi, "POSITION", -2, -2, 1 << 30, &psi) != 0
	    || gl_jint(g, pr, "mesh primitive", (long)pi, "indices", -2, -2, 1 << 30, &ii) != 0)
		return -1;
	if (psi >= 0) {
		size_t bad = 0;
		if (gl_accessor(g, psi, ACC_POSITION, &pos, &np, &ct) != 0)
			goto out;
		for (i = 0; i < 3 * np; i++)
			bad += !isfinite(pos[i]);
		if (bad)
			gl_warn(g, "mesh %lld primitive %lld: %zu POSITION values are not finite", mi, pi, bad);
	}
	if (ni >= 0) {
		if (gl_accessor(g, ni, ACC_NORMAL, &po->nrm, &po->n, &ct) != 0)
			goto out;
		g->ntypes |= ct == GL_FLOAT ? 1 : 2;
		if (psi >= 0 && np != po->n) {
			mio_fail(g->c, "mesh %lld primitive %lld: NORMAL has %zu elements but POSITION %zu", mi, pi, po->n, np);
			goto out;
		}
	}
	nv = psi >= 0 ? np : po->n;
	if (ii >= 0) {
		if (gl_accessor(g, ii, ACC_INDEX, &idx, &nidx, &ct) != 0)
			goto out;
		for (i = 0; i < nidx; i++)
			if (!(idx[i] < (double)nv)) {
				mio_fail(g->c, "mesh %lld primitive %lld: index %zu is %.0f, out of range [0, %zu)", mi, pi, i, idx[i], nv);
				goto out;
			}
	}
	g->m->nvertices += nv;
	if (mode == 4 && (ii >= 0 ? nidx : nv) % 3)
		gl_warn(g, "mesh %lld primitive %lld: %zu vertices for TRIANGLES is not a multiple of 3 (the last %zu ignored)", mi, pi,
		     ii >= 0 ? nidx : nv, (ii >= 0 ? nidx : nv) % 3);
	if (ni < 0 && psi >= 0 && mode >= 4) {
		size_t nc = ii >= 0 ? nidx : np, nt;
		tri = mio_calloc(nc, 3 * sizeof *tri);
		if (!tri) {
			mio_fail(g->c, "out of memory");
			goto out;
		}
		nt = triangles(mode, ii >= 0 ? idx : NULL, nc, tri);
		if (nt && computed(g, pos, np, tri, nt, &po->nrm, &po->vidx, &po->n) != 0)
			goto out;
		po->computed = nt > 0;
	}
	rc = 0;
out:
	if (rc) {
		free(po->nrm); free(po->vidx);
		memset(po, 0, sizeof po[0]);
	}
	free(pos); free(idx); free(tri);
	return rc;
}

/* ---- node transforms (in the working precision) ----------------------------- */

static double rd(int prec, double x) { return prec == PREC_FLOAT ? (double)(float)x : x; }

/* Node ni's 3x3 linear part (row-major), from 'matrix' (column-major) or
   rotation and scale (translation does not act on normals). */
static int local(gltf *g, long long ni, const cJSON *no, int prec, double *m)
{
	const cJSON *mt = gl_item(no, "matrix"), *r = gl_item(no, "rotation"), *s = gl_item(no, "scale");
	double q[4] = { 0, 0, 0, 1 }, sc[3] = { 1, 1, 1 }, a[16];
	int k, c;
	const cJSON *arrs[3] = { mt, r, s };
	const int lens[3] = { 16, 4, 3 };
	double *dst[3] = { a, q, sc };
	for (k = 0; k < 3; k++) {
		const cJSON *e;
		int j = 0;
		if (!arrs[k])
			continue;
		if (!cJSON_IsArray(arrs[k]) || cJSON_GetArraySize(arrs[k]) != lens[k])
			return mio_fail(g->c, "node %lld: '%s' must be an array of %d numbers", ni, k == 0 ? "matrix" : k == 1 ? "rotation" : "scale", lens[k]);
		cJSON_ArrayForEach(e, arrs[k]) {
			if (!cJSON_IsNumber(e))
				return mio_fail(g->c, "node %lld: '%s' must hold numbers", ni, k == 0 ? "matrix" : k == 1 ? "rotation" : "scale");
			dst[k][j++] = rd(prec, e->valuedouble);
		}
	}
	if (mt) {
		for (k = 0; k < 3; k++)
			for (c = 0; c < 3; c++)
				m[3 * k + c] = a[4 * c + k];
		return 0;
	}
	{
		const double x = q[0], y = q[1], z = q[2], w = q[3];
#define M(a_, b_) rd(prec, (a_) * (b_))
#define A(a_, b_) rd(prec, (a_) + (b_))
#define S(a_, b_) rd(prec, (a_) - (b_))
		const double xx = M(x, x), yy = M(y, y), zz = M(z, z), xy = M(x, y), xz = M(x, z), yz = M(y, z);
		const double wx = M(w, x), wy = M(w, y), wz = M(w, z);
		double rm[9];
		rm[0] = S(1, M(2, A(yy, zz))); rm[1] = M(2, S(xy, wz)); rm[2] = M(2, A(xz, wy));
		rm[3] = M(2, A(xy, wz)); rm[4] = S(1, M(2, A(xx, zz))); rm[5] = M(2, S(yz, wx));
		rm[6] = M(2, S(xz, wy)); rm[7] = M(2, A(yz, wx)); rm[8] = S(1, M(2, A(xx, yy)));
		for (k = 0; k < 3; k++)
			for (c = 0; c < 3; c++)
				m[3 * k + c] = M(rm[3 * k + c], sc[c]);
	}
	return 0;
}

static void mul3(int prec, const double *a, const double *b, double *o)
{
	int r, c;
	for (r = 0; r < 3; r++)
		for (c = 0; c < 3; c++)
			o[3 * r + c] = A(A(M(a[3 * r], b[c]), M(a[3 * r + 1], b[3 + c])), M(a[3 * r + 2], b[6 + c]));
}

/* The inverse transpose: cofactors over the determinant. */
static void inv_t(int prec, const double *m, double *n)
{
	double cf[9], det;
	int k;
	cf[0] = S(M(m[4], m[8]), M(m[5], m[7])); cf[1] = S(M(m[5], m[6]), M(m[3], m[8])); cf[2] = S(M(m[3], m[7]), M(m[4], m[6]));
	cf[3] = S(M(m[2], m[7]), M(m[1], m[8])); cf[4] = S(M(m[0], m[8]), M(m[2], m[6])); cf[5] = S(M(m[1], m[6]), M(m[0], m[7]));
	cf[6] = S(M(m[1], m[5]), M(m[2], m[4])); cf[7] = S(M(m[2], m[3]), M(m[0], m[5])); cf[8] = S(M(m[0], m[4]), M(m[1], m[3]));
	det = A(A(M(m[0], cf[0]), M(m[1], cf[1])), M(m[2], cf[2]));
	for (k = 0; k < 9; k++)
		n[k] = rd(prec, cf[k] / det);
}

static void apply(int prec, const double *n, double *v, size_t cnt)
{
	size_t i;
	for (i = 0; i < cnt; i++) {
		double x = rd(prec, v[3 * i]), y = rd(prec, v[3 * i + 1]), z = rd(prec, v[3 * i + 2]);
		int r;
		for (r = 0; r < 3; r++)
			v[3 * i + r] = A(A(M(n[3 * r], x), M(n[3 * r + 1], y)), M(n[3 * r + 2], z));
	}
}
#undef M
#undef A
#undef S

/* ---- meshes, nodes, scenes ---------------------------------------------- */

static uint64_t tag_of(long long owner, long long pi)
{
	return (uint64_t)(owner & 0xffffff) << 40 | (uint64_t)(pi & 0xff) << 32;
}

/* The primitives of mesh mi, each transformed by nt (NULL: as stored),
   appended with owner (mesh or node) in their places. */
static int mesh_into(gltf *g, long long mi, const double *nt, long long owner)
{
	const cJSON *mo = gl_top(g, "meshes", "mesh", mi), *ps, *pr;
	long long pi = 0;
	if (!mo || gl_jarr(g, mo, "mesh", (long)mi, "primitives", &ps) != 0)
		return -1;
	if (!ps)
		return mio_fail(g->c, "mesh %lld has no 'primitives'", mi);
	cJSON_ArrayForEach(pr, ps) {
		prim_out po;
		int rc;
		if (primitive(g, mi, pi, pr, &po) != 0)
			return -1;
		if (nt)
			apply(g->o->prec, nt, po.nrm, po.n);
		rc = append(g, po.nrm, po.n, tag_of(owner, pi), po.vidx);
		if (po.n) {
			g->m->nprims++;
			if (po.computed) {
				g->m->ncomputed += po.n;
				g->m->nprims_computed++;
			}
		}
		free(po.nrm);
		free(po.vidx);
		if (rc)
			return -1;
		pi++;
	}
	return 0;
}

/* parent[i] for every node; refuses bad child indices, two parents and
   cycles. */
static int node_graph(gltf *g, const cJSON *nodes, int nn, int *parent)
{
	unsigned char *st = mio_calloc((size_t)nn, 1);
	int i, rc = -1;
	if (!st)
		return mio_fail(g->c, "out of memory");
	for (i = 0; i < nn; i++)
		parent[i] = -1;
	for (i = 0; i < nn; i++) {
		const cJSON *no = cJSON_GetArrayItem(nodes, i), *ch, *e;
		long long mi;
		if (!cJSON_IsObject(no)) {
			mio_fail(g->c, "node %d is not a JSON object", i);
			goto out;
		}
		if (gl_jarr(g, no, "node", i, "children", &ch) != 0 || gl_jint(g, no, "node", i, "mesh", -2, -2, 1 << 30, &mi) != 0)
			goto out;
		cJSON_ArrayForEach(e, ch) {
			double d = e->valuedouble;
			int k;
			if (!cJSON_IsNumber(e) || !(d >= 0 && d < nn) || d != floor(d)) {
				mio_fail(g->c, "node %d: child '%.20s' is not a node index in [0, %d)", i, cJSON_IsNumber(e) ? "(number)" : "(not a number)", nn);
				goto out;
			}
			k = (int)d;
			if (parent[k] >= 0 || k == i) {
				mio_fail(g->c, "node %d has two parents (%d and %d), or is its own child: not a tree", k, parent[k], i);
				goto out;
			}
			parent[k] = i;
		}
	}
	/* each node has one parent at most: walking up either ends at a root
	   or closes a cycle */
	for (i = 0; i < nn; i++) {
		int k = i;
		while (k >= 0 && st[k] == 0) {
			st[k] = 1;
			k = parent[k];
		}
		if (k >= 0 && st[k] == 1) {
			mio_fail(g->c, "node %d is in a cycle of children (a node is its own ancestor)", k);
			goto out;
		}
		for (k = i; k >= 0 && st[k] == 1; k = parent[k])
			st[k] = 2;
	}
	rc = 0;
out:
	free(st);
	return rc;
}

/* Roots of the default scene ('scene', else scene 0; with no scenes, every
   node without a parent) into roots[]; their number in *nr. */
static int scene_roots(gltf *g, int nn, const int *parent, int *roots, int *nr)
{
	const cJSON *scs, *so, *sn, *e;
	long long si;
	int i;
	*nr = 0;
	if (gl_jarr(g, g->root, "", -1, "scenes", &scs) != 0 || gl_jint(g, g->root, "the file", -1, "scene", -2, -2, 1 << 30, &si) != 0)
		return -1;
	if (si < 0 && (!scs || cJSON_GetArraySize(scs) == 0)) {
		for (i = 0; i < nn; i++)
			if (parent[i] < 0)
				roots[(*nr)++] = i;
		return 0;
	}
	so = gl_top(g, "scenes", "scene", si < 0 ? 0 : si);
	if (!so || gl_jarr(g, so, "scene", (long)(si < 0 ? 0 : si), "nodes", &sn) != 0)
		return -1;
	cJSON_ArrayForEach(e, sn) {
		double d = e->valuedouble;
		if (!cJSON_IsNumber(e) || !(d >= 0 && d < nn) || d != floor(d) || parent[(int)d] >= 0)
			return mio_fail(g->c, "scene %lld: a node that is not a root node index in [0, %d)", si < 0 ? 0 : si, nn);
		if (*nr >= nn)
			return mio_fail(g->c, "scene %lld lists more roots than there are nodes", si < 0 ? 0 : si);
		roots[(*nr)++] = (int)d;
	}
	return 0;
}

/* --world: every mesh instance of the default scene, depth first. */
static int world(gltf *g, const cJSON *nodes, int nn, const int *parent, const int *roots, int nr)
{
	int *stk = mio_calloc((size_t)nn, sizeof *stk);
	double *mat = mio_calloc((size_t)nn, 9 * sizeof *mat);
	const int prec = g->o->prec;
	int r, sp, rc = -1;
	if (!stk || !mat) {
		mio_fail(g->c, "out of memory");
		goto out;
	}
	for (r = 0; r < nr; r++) {
		sp = 0;
		stk[sp++] = roots[r];
		while (sp > 0) {
			const int i = stk[--sp];
			const cJSON *no = cJSON_GetArrayItem(nodes, i), *ch = gl_item(no, "children"), *e;
			double loc[9], nt[9];
			long long mi;
			if (local(g, i, no, prec, loc) != 0)
				goto out;
			if (parent[i] >= 0)
				mul3(prec, &mat[9 * (size_t)parent[i]], loc, &mat[9 * (size_t)i]);
			else
				memcpy(&mat[9 * (size_t)i], loc, sizeof loc);
			if (gl_jint(g, no, "node", i, "mesh", -2, -2, 1 << 30, &mi) != 0)
				goto out;
			if (mi >= 0) {
				inv_t(prec, &mat[9 * (size_t)i], nt);
				if (mesh_into(g, mi, nt, i) != 0)
					goto out;
			}
			for (e = ch ? ch->child : NULL; e; e = e->next)
				if (sp < nn)
					stk[sp++] = (int)e->valuedouble;
		}
	}
	rc = 0;
out:
	free(stk); free(mat);
	return rc;
}


/* ---- geometry for a renderer (object space) ---------------------------------- */

typedef struct {
	double *pos, *nrm;
	uint32_t *tri;
	uint64_t *tag;
	size_t nv, nt, capv, capt;
} geo_acc;

static int geo_room(gltf *g, geo_acc *a, size_t nv, size_t nt)
{
	size_t limit = (size_t)MESH_MAX_ITEMS;
	if (g->inbytes < limit / 16)
		limit = 16 * g->inbytes + 4096;
	if (a->nv + nv > limit || a->nt + nt > limit)
		return mio_fail(g->c, "more than %zu vertices or triangles (at most 16 per byte of input)", limit);
	if (a->nv + nv > a->capv) {
		size_t cap = a->capv ? a->capv : 1024;
		double *p, *n;
		while (cap < a->nv + nv)
			cap *= 2;
		if (!(p = realloc(a->pos, cap * 3 * sizeof *p)))
			return mio_fail(g->c, "out of memory");
		a->pos = p;
		if (!(n = realloc(a->nrm, cap * 3 * sizeof *n)))
			return mio_fail(g->c, "out of memory");
		a->nrm = n;
		a->capv = cap;
	}
	if (a->nt + nt > a->capt) {
		size_t cap = a->capt ? a->capt : 1024;
		uint32_t *t;
		uint64_t *w;
		while (cap < a->nt + nt)
			cap *= 2;
		if (!(t = realloc(a->tri, cap * 3 * sizeof *t)))
			return mio_fail(g->c, "out of memory");
		a->tri = t;
		if (!(w = realloc(a->tag, cap * sizeof *w)))
			return mio_fail(g->c, "out of memory");
		a->tag = w;
		a->capt = cap;
	}
	return 0;
}

/* One primitive's positions, per-vertex normals (stored, or computed; 0 0 0
   for a vertex no triangle uses) and triangles, appended to a. */
static int geo_prim(gltf *g, long long mi, long long pi, const cJSON *pr, geo_acc *a)
{
	const cJSON *at = gl_item(pr, "attributes");
	long long mode, psi, ii, ct;
	double *pos = NULL, *idx = NULL;
	size_t np = 0, nidx = 0, nt, i;
	uint32_t *tri = NULL;
	prim_out po;
	int rc = -1;
	if (gl_jint(g, pr, "mesh primitive", (long)pi, "mode", 4, 0, 6, &mode) != 0
	    || gl_jint(g, at, "mesh primitive", (long)pi, "POSITION", -2, -2, 1 << 30, &psi) != 0
	    || gl_jint(g, pr, "mesh primitive", (long)pi, "indices", -2, -2, 1 << 30, &ii) != 0)
		return -1;
	if (psi < 0 || mode < 4)
		return 0; /* nothing to draw */
	if (primitive(g, mi, pi, pr, &po) != 0)
		return -1;
	if (gl_accessor(g, psi, ACC_POSITION, &pos, &np, &ct) != 0 || (ii >= 0 && gl_accessor(g, ii, ACC_INDEX, &idx, &nidx, &ct) != 0))
		goto out;
	tri = mio_calloc(ii >= 0 ? nidx : np, 3 * sizeof *tri);
	if (!tri) {
		mio_fail(g->c, "out of memory");
		goto out;
	}
	nt = triangles(mode, idx, ii >= 0 ? nidx : np, tri);
	if (a->nv + np > UINT32_MAX - 1) {
		mio_fail(g->c, "more than %lu vertices", (unsigned long)(UINT32_MAX - 1));
		goto out;
	}
	if (geo_room(g, a, np, nt) != 0)
		goto out;
	memcpy(a->pos + 3 * a->nv, pos, np * 3 * sizeof *pos);
	memset(a->nrm + 3 * a->nv, 0, np * 3 * sizeof *a->nrm);
	for (i = 0; i < po.n; i++) {
		size_t v = po.vidx ? po.vidx[i] : i;
		if (v < np)
			memcpy(a->nrm + 3 * (a->nv + v), po.nrm + 3 * i, 3 * sizeof *po.nrm);
	}
	for (i = 0; i < 3 * nt; i++)
		a->tri[3 * a->nt + i] = (uint32_t)(a->nv + tri[i]);
	for (i = 0; i < nt; i++)
		a->tag[a->nt + i] = tag_of(mi, pi) | (uint64_t)(i & 0xffffffffu);
	a->nv += np;
	a->nt += nt;
	rc = 0;
out:
	free(po.nrm); free(po.vidx); free(pos); free(idx); free(tri);
	return rc;
}

static int read_geom(gltf *g, mesh_geom *geom)
{
	geo_acc a;
	long long mi;
	memset(&a, 0, sizeof a);
	for (mi = 0; mi < (long long)g->m->nmeshes; mi++) {
		const cJSON *mo = gl_top(g, "meshes", "mesh", mi), *ps, *pr;
		long long pi = 0;
		if (!mo || gl_jarr(g, mo, "mesh", (long)mi, "primitives", &ps) != 0)
			goto bad;
		cJSON_ArrayForEach(pr, ps) {
			if (geo_prim(g, mi, pi++, pr, &a) != 0)
				goto bad;
		}
	}
	if (a.nt == 0) {
		mio_fail(g->c, "no geometry: no triangles to draw (points and lines only, or no POSITION)");
		goto bad;
	}
	geom->nverts = geom->nnormals = a.nv;
	geom->pos = a.pos;
	geom->nrm = a.nrm;
	geom->ntris = a.nt;
	geom->tri = a.tri;
	geom->tri_line = a.tag;
	geom->tri_n = mio_calloc(a.nt, 3 * sizeof *geom->tri_n);
	if (!geom->tri_n) {
		mio_fail(g->c, "out of memory");
		return -1; /* the caller frees geom */
	}
	memcpy(geom->tri_n, a.tri, a.nt * 3 * sizeof *a.tri);
	return 0;
bad:
	free(a.pos); free(a.nrm); free(a.tri); free(a.tag);
	return -1;
}

/* ---- the file ----------------------------------------------------------------- */

static uint32_t le32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* GLB: the JSON chunk and the BIN chunk, if any. */
static int glb(gltf *g, const unsigned char *buf, size_t len, const unsigned char **js, size_t *jl)
{
	size_t off = 12, total;
	if (len < 20)
		return mio_fail(g->c, "byte 0: a .glb of %zu bytes is too short for its header and a chunk", len);
	if (le32(buf + 4) != 2)
		return mio_fail(g->c, "byte 4: .glb container version %lu (only version 2, glTF 2.0, is read)", (unsigned long)le32(buf + 4));
	total = le32(buf + 8);
	if (total > len)
		return mio_fail(g->c, "byte 8: the .glb header says %zu bytes, but the file has %zu (truncated?)", total, len);
	if (total < len)
		snprintf(g->m->warning, sizeof g->m->warning, "%zu bytes after the .glb's declared length ignored", len - total);
	*js = NULL;
	while (off + 8 <= total) {
		size_t cl = le32(buf + off);
		uint32_t ty = le32(buf + off + 4);
		if (cl > total - off - 8)
			return mio_fail(g->c, "byte %zu: chunk of %zu bytes runs past the end (%zu)", off, cl, total);
		if (off == 12 && ty != 0x4E4F534Au)
			return mio_fail(g->c, "byte 16: the first .glb chunk is not JSON");
		if (ty == 0x4E4F534Au && off == 12) {
			*js = buf + off + 8;
			*jl = cl;
		} else if (ty == 0x004E4942u && !g->bin) {
			g->bin = buf + off + 8;
			g->binlen = cl;
		}
		off += 8 + cl;
	}
	if (!*js)
		return mio_fail(g->c, "byte 12: no JSON chunk");
	return 0;
}

/* asset.version 2.x, and no required extension that hides the geometry. */
static int check_asset(gltf *g)
{
	const cJSON *as = gl_item(g->root, "asset"), *v = gl_item(as, "version"), *rq, *e;
	if (!cJSON_IsObject(as) || !cJSON_IsString(v))
		return mio_fail(g->c, "no asset.version: not a glTF 2.0 file (glTF 1.0 files are not read)");
	if (strncmp(v->valuestring, "2.", 2))
		return mio_fail(g->c, "glTF version '%.20s' is not read; only glTF 2.0 is", v->valuestring);
	if (gl_jarr(g, g->root, "", -1, "extensionsRequired", &rq) != 0)
		return -1;
	cJSON_ArrayForEach(e, rq)
		if (cJSON_IsString(e) && (!strcmp(e->valuestring, "KHR_draco_mesh_compression")
		                          || !strcmp(e->valuestring, "EXT_meshopt_compression")))
			return mio_fail(g->c, "requires %s (compressed geometry), which is not supported", e->valuestring);
	return 0;
}

static int read_all(gltf *g)
{
	const cJSON *nodes, *meshes = gl_item(g->root, "meshes"), *bufs;
	int nn, nr, *parent = NULL, *roots = NULL, rc = -1;
	long long mi;
	if (check_asset(g) != 0 || gl_jarr(g, g->root, "", -1, "nodes", &nodes) != 0 || gl_jarr(g, g->root, "", -1, "meshes", &meshes) != 0
	    || gl_jarr(g, g->root, "", -1, "buffers", &bufs) != 0)
		return -1;
	g->nbufs = bufs ? cJSON_GetArraySize(bufs) : 0;
	g->bufs = mio_calloc((size_t)g->nbufs, sizeof *g->bufs);
	nn = nodes ? cJSON_GetArraySize(nodes) : 0;
	parent = mio_calloc((size_t)nn, sizeof *parent);
	roots = mio_calloc((size_t)nn, sizeof *roots);
	if (!g->bufs || !parent || !roots) {
		free(parent);
		free(roots);
		return mio_fail(g->c, "out of memory");
	}
	g->m->nmeshes = meshes ? (size_t)cJSON_GetArraySize(meshes) : 0;
	/* the node tree and the default scene are checked in both modes */
	if (node_graph(g, nodes, nn, parent) != 0 || scene_roots(g, nn, parent, roots, &nr) != 0)
		goto out;
	if (g->o->world) {
		if (world(g, nodes, nn, parent, roots, nr) != 0)
			goto out;
	} else {
		for (mi = 0; mi < (long long)g->m->nmeshes; mi++)
			if (mesh_into(g, mi, NULL, mi) != 0)
				goto out;
	}
	if (g->m->count == 0) {
		mio_fail(g->c, "no normals: %s", g->o->world ? "the default scene instances no mesh with NORMAL or triangles"
		         : g->m->nmeshes ? "no primitive has NORMAL, or triangles to compute them from" : "no meshes");
		goto out;
	}
	rc = 0;
out:
	free(parent);
	free(roots);
	return rc;
}

int mio_read_gltf(mctx *c, const unsigned char *buf, size_t len, const mesh_opts *o, mesh_normals *m, mesh_geom *geom)
{
	gltf g;
	const unsigned char *js = buf;
	size_t jl = len;
	int rc = -1, i;
	memset(&g, 0, sizeof g);
	g.c = c; g.o = o; g.m = m; g.inbytes = len;
	m->format = MESH_GLTF;
	m->world = o->world;
	if (geom && o->world)
		return mio_fail(c, "geometry is read in object space only (no --world)");
	if (len >= 4 && !memcmp(buf, "glTF", 4)) {
		g.glb = m->gltf_binary = 1;
		if (glb(&g, buf, len, &js, &jl) != 0)
			return -1;
	}
	if (jl >= 3 && js[0] == 0xef && js[1] == 0xbb && js[2] == 0xbf) {
		js += 3;
		jl -= 3;
	}
	g.root = cJSON_ParseWithLength((const char *)js, jl);
	if (!g.root) {
		const char *e = cJSON_GetErrorPtr();
		size_t at = e && e >= (const char *)js && e <= (const char *)js + jl ? (size_t)(e - (const char *)js) : 0;
		return mio_fail(c, "the JSON does not parse (near byte %zu of it)", at);
	}
	if (!cJSON_IsObject(g.root))
		mio_fail(c, "the JSON is not an object: not a glTF file");
	else
		rc = read_all(&g);
	if (rc == 0 && geom)
		rc = read_geom(&g, geom);
	if (rc == 0)
		m->stored_type = g.ntypes == 1 ? MESH_T_FLOAT : g.ntypes == 2 ? MESH_T_QUANT : g.ntypes ? MESH_T_OTHER : MESH_T_DOUBLE;
	m->origin = g.ntypes ? MESH_STORED : MESH_COMPUTED;
	for (i = 0; i < g.nbufs; i++)
		if (g.bufs[i].owned)
			free(g.bufs[i].data);
	free(g.bufs);
	cJSON_Delete(g.root);
	return rc;
}
