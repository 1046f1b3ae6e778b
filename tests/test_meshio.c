/*
 * test_meshio.c - the OBJ and PLY normal readers on small files written
 * here: counts, stored values, area-weighted normals with known answers,
 * locations of degenerate normals, and the error line or byte offset of
 * malformed variants.  Ends with every prefix of a binary PLY (each must
 * be refused: no silent partial read) and seeded random byte mutations
 * (each must be read or refused with a message, never crash).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "mesh/meshio.h"

#include "check.h"
#include "common/prec.h"

static int rd(const char *name, const void *buf, size_t len, mesh_normals *m, char *err)
{
	return mesh_read_mem(name, buf, len, m, err, 512);
}
static int rds(const char *name, const char *s, mesh_normals *m, char *err)
{
	return rd(name, s, strlen(s), m, err);
}

/* index of the normal whose vertex index is vi, or -1 */
static long find_vertex(const mesh_normals *m, size_t vi)
{
	size_t i;
	for (i = 0; i < m->count; i++)
		if (m->index[i] == vi)
			return (long)i;
	return -1;
}

static int near3(const mesh_normals *m, long i, double x, double y, double z)
{
	const double t = 4 * DBL_EPSILON;
	return i >= 0 && fabs(m->x[i] - x) <= t && fabs(m->y[i] - y) <= t && fabs(m->z[i] - z) <= t;
}

static void expect_error(const char *name, const void *buf, size_t len, const char *w1, const char *w2)
{
	mesh_normals m;
	char err[512];
	int rc = rd(name, buf, len, &m, err);
	CHECK(rc == -1, "%s: accepted malformed input", name);
	CHECK(m.count == 0 && m.x == NULL, "%s: partial result left behind", name);
	CHECK(strstr(err, w1) != NULL, "%s: error '%s' lacks '%s'", name, err, w1);
	if (w2)
		CHECK(strstr(err, w2) != NULL, "%s: error '%s' lacks '%s'", name, err, w2);
	CHECK(strchr(err, '\n') == NULL, "%s: error is more than one line", name);
}
static void expect_errors(const char *name, const char *s, const char *w1, const char *w2)
{
	expect_error(name, s, strlen(s), w1, w2);
}

static const double r3 = 0.57735026918962576451; /* 1/sqrt(3) */

static void test_obj(void)
{
	mesh_normals m;
	mesh_stats st;
	char err[512];
	/* tetrahedron, no vn: face syntaxes v, v/vt, negative v/vt */
	const char *tet =
		"# tetrahedron\n"
		"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
		"vt 0 0\nvt 1 0\nvt 0 1\n"
		"f 1 3 2\n"
		"f 1/1 2/2 4/3\n"
		"f -4/1 -1/2 -2/3\n"
		"f 2 3 4\n";
	CHECK(rds("tet.obj", tet, &m, err) == 0, "tet.obj: %s", err);
	CHECK(m.count == 4 && m.origin == MESH_COMPUTED && m.nfaces == 4 && m.ntriangles == 4, "tet counts %zu %d %zu", m.count, m.origin, m.nfaces);
	CHECK(near3(&m, find_vertex(&m, 0), -r3, -r3, -r3), "tet vertex 1 normal (%a %a %a)", m.x[0], m.y[0], m.z[0]);
	CHECK(near3(&m, find_vertex(&m, 1), 1, 0, 0), "tet vertex 2 normal");
	CHECK(near3(&m, find_vertex(&m, 2), 0, 1, 0), "tet vertex 3 normal");
	CHECK(near3(&m, find_vertex(&m, 3), 0, 0, 1), "tet vertex 4 normal");
	CHECK(m.where[find_vertex(&m, 3)] == 5, "tet vertex 4 is on line 5, got %llu", (unsigned long long)m.where[3]);
	CHECK(mesh_classify(&m, PREC_DOUBLE, 0, &st) == 0 && st.unit == 4 && st.nonunit == 0, "tet classify unit %zu", st.unit);
	mesh_free(&m);

	/* cube of quads (fan-triangulated): polygon-area weighting gives the
	   corner directions exactly; an unused vertex is skipped and counted */
	{
		const char *cube =
			"v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
			"v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\nv 5 5 5\n"
			"f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 2 3 7 6\nf 1 5 8 4\n";
		int i, ok = 1;
		CHECK(rds("cube.obj", cube, &m, err) == 0, "cube.obj: %s", err);
		CHECK(m.count == 8 && m.unreferenced == 1 && m.ntriangles == 12, "cube counts %zu %zu %zu", m.count, m.unreferenced, m.ntriangles);
		for (i = 0; i < 8 && m.count == 8; i++) {
			double sx = (i == 1 || i == 2 || i == 5 || i == 6) ? r3 : -r3;
			double sy = (i == 2 || i == 3 || i == 6 || i == 7) ? r3 : -r3;
			double sz = i >= 4 ? r3 : -r3;
			ok &= near3(&m, find_vertex(&m, (size_t)i), sx, sy, sz);
		}
		CHECK(ok, "cube corner normals are not (+-1,+-1,+-1)/sqrt(3)");
		mesh_free(&m);
	}

	/* stored vn: v//vn and v/vt/vn faces; a zero, a NaN and a non-unit one */
	{
		const char *vn =
			"v 0 0 0\nv 1 0 0\nv 0 1 0\n"
			"vt 0 0\n"
			"vn 0 0 1\n"
			"vn 0 0 0\n"
			"vn nan 0 1\n"
			"vn 0 0 2\n"
			"vn 0.6 0.8 0\r\n"
			"f 1//1 2//1 3/1/1\n";
		CHECK(rds("vn.obj", vn, &m, err) == 0, "vn.obj: %s", err);
		CHECK(m.count == 5 && m.origin == MESH_STORED, "vn count %zu", m.count);
		CHECK(m.count == 5 && m.where[0] == 5 && m.where[4] == 9, "vn lines %llu %llu", (unsigned long long)m.where[0], (unsigned long long)m.where[4]);
		CHECK(m.count == 5 && m.x[4] == 0.6 && m.y[4] == 0.8, "vn values");
		CHECK(mesh_classify(&m, PREC_DOUBLE, 0, &st) == 0, "classify");
		CHECK(st.zero == 1 && st.nonfinite == 1 && st.nonunit == 1 && st.unit == 2, "vn classes zero %zu nonfinite %zu nonunit %zu unit %zu",
		      st.zero, st.nonfinite, st.nonunit, st.unit);
		CHECK(st.dev_max == 1.0 && st.nbad == 2 && st.bad[0] == 1 && st.bad[1] == 2, "vn deviations %g, bad %zu", st.dev_max, st.nbad);
		{
			char w[160];
			mesh_where(&m, 1, w, sizeof w);
			CHECK(strcmp(w, "line 6") == 0, "where '%s'", w);
		}
		/* in float, 0.6 and 0.8 round so that |n| - 1 is about 3e-8: unit at 4 float ulps */
		CHECK(mesh_classify(&m, PREC_FLOAT, 0, &st) == 0 && st.unit == 2, "float unit %zu", st.unit);
		mesh_free(&m);
	}

	expect_errors("badnum.obj", "v 0 0 0\nv 1 0 0\nv 0 1 x\nf 1 2 3\n", "line 3", "bad number 'x'");
	expect_errors("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 9\n", "line 5", "out of range");
	expect_errors("negrange.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", "line 4", "out of range");
	expect_errors("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "line 4", "out of range");
	expect_errors("vnrange.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n", "line 5", "normal index 2");
	expect_errors("short.obj", "vn 0 1\n", "line 1", "needs 3 numbers");
	expect_errors("long.obj", "vn 0 1 0 1\n", "line 1", "too many");
	expect_errors("twov.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "line 3", "at least 3");
	expect_errors("slash.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", "line 4", "bad face vertex");
	expect_errors("empty.obj", "", "empty", NULL);
	expect_errors("nothing.obj", "# only a comment\nv 1 2 3\n", "no normals", NULL);
	expect_error("utf16.obj", "\xfe\xff\0v\0 \0001", 8, "UTF-16", NULL);
	{
		/* a number longer than any float needs is refused, not truncated */
		char big[300];
		memset(big, '1', sizeof big);
		memcpy(big, "vn 0 0 ", 7);
		big[sizeof big - 1] = '\n';
		expect_error("bignum.obj", big, sizeof big, "line 1", "bad number");
	}
}

/* little-endian writers: bytes assembled from the value's bits, low byte
   first, so the files are the same on a big-endian host (s390x) */
static size_t put_le(unsigned char *p, uint64_t u, size_t n)
{
	size_t i;
	for (i = 0; i < n; i++)
		p[i] = (unsigned char)(u >> (8 * i));
	return n;
}
static size_t putu(unsigned char *p, uint32_t v) { return put_le(p, v, 4); }
static size_t puti(unsigned char *p, int v) { return put_le(p, (uint32_t)v, 4); }
static size_t putf(unsigned char *p, float v) { uint32_t u; memcpy(&u, &v, 4); return put_le(p, u, 4); }
static size_t putd(unsigned char *p, double v) { uint64_t u; memcpy(&u, &v, 8); return put_le(p, u, 8); }

/* big-endian writer: the bytes of put_le reversed */
static size_t put_be(unsigned char *p, uint64_t u, size_t n)
{
	size_t i;
	for (i = 0; i < n; i++)
		p[n - 1 - i] = (unsigned char)(u >> (8 * i));
	return n;
}

/* binary big endian, on any host: float normals, a signed short and a
   signed char before them (their negative values must not shift the
   floats), a face list of int, then a negative index in it */
static void test_ply_big(void)
{
	mesh_normals m;
	char err[512];
	unsigned char b[512];
	const char *hdr = "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty short s\nproperty char c\n"
	                  "property float nx\nproperty float ny\nproperty float nz\n"
	                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
	static const float v[3][3] = { {0.6f, 0.8f, 0}, {0, -1, 0}, {-0.25f, 0, 0.5f} };
	size_t n = strlen(hdr);
	uint32_t w;
	int i, k;
	memcpy(b, hdr, n);
	for (i = 0; i < 3; i++) {
		n += put_be(b + n, (uint16_t)-300, 2);
		b[n++] = 0x80;
		for (k = 0; k < 3; k++) { memcpy(&w, &v[i][k], 4); n += put_be(b + n, w, 4); }
	}
	b[n++] = 3;
	for (i = 0; i < 3; i++)
		n += put_be(b + n, (uint32_t)i, 4);
	CHECK(rd("be.ply", b, n, &m, err) == 0, "be.ply: %s", err);
	CHECK(m.count == 3 && m.ply_binary == 2 && m.x[0] == (double)v[0][0] && m.y[0] == (double)v[0][1]
	      && m.y[1] == -1 && m.x[2] == -0.25 && m.z[2] == 0.5, "be.ply values");
	mesh_free(&m);
	put_be(b + n - 4, (uint32_t)-2, 4);
	expect_error("bebad.ply", b, n, "vertex index -2", "out of range");
}

/* ascii with three normals (one of them zero) and a face */
static void test_ply_ascii(void)
{
	mesh_normals m;
	mesh_stats st;
	char err[512];
	const char *asc =
		"ply\r\n"
		"format ascii 1.0\n"
		"comment three normals, one face\n"
		"element vertex 3\n"
		"property float x\nproperty float y\nproperty float z\n"
		"property float nx\nproperty float ny\nproperty float nz\n"
		"element face 1\n"
		"property list uchar int vertex_indices\n"
		"end_header\n"
		"0 0 0 0 0 1\n"
		"1 0 0 0.6 0.8 0\n"
		"0 1 0 0 0 0\n"
		"3 0 1 2\n";
	CHECK(rds("a.ply", asc, &m, err) == 0, "a.ply: %s", err);
	CHECK(m.count == 3 && m.origin == MESH_STORED && m.stored_type == MESH_T_FLOAT && m.ply_binary == 0, "a.ply counts %zu", m.count);
	CHECK(m.count == 3 && m.x[1] == (double)(float)0.6 && m.y[1] == (double)(float)0.8, "a.ply values are the float roundings");
	CHECK(mesh_classify(&m, PREC_FLOAT, 0, &st) == 0 && st.zero == 1 && st.nbad == 1 && st.bad[0] == 2, "a.ply zero");
	{
		char w[160];
		mesh_where(&m, 2, w, sizeof w);
		CHECK(strstr(w, "vertex 2 at byte") != NULL, "a.ply where '%s'", w);
		CHECK(m.count == 3 && m.where[2] == (uint64_t)(strstr(asc, "0 1 0 0 0 0") - asc), "a.ply offset %llu", (unsigned long long)m.where[2]);
	}
	mesh_free(&m);
}

/* ascii, no normals: tetrahedron from faces, vertex_index spelling */
static void test_ply_tet(void)
{
	mesh_normals m;
	char err[512];
	const char *tet =
		"ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
		"element face 4\nproperty list uint8 int32 vertex_index\nend_header\n"
		"0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
	CHECK(rds("tet.ply", tet, &m, err) == 0, "tet.ply: %s", err);
	CHECK(m.count == 4 && m.origin == MESH_COMPUTED, "tet.ply count %zu", m.count);
	CHECK(near3(&m, find_vertex(&m, 0), -r3, -r3, -r3) && near3(&m, find_vertex(&m, 3), 0, 0, 1), "tet.ply normals");
	mesh_free(&m);
}

/* binary little endian, double normals plus a face list */
static void test_ply_binary(void)
{
	mesh_normals m;
	char err[512];
	unsigned char b[1024];
	const char *hdr = "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
	                  "property double nx\nproperty double ny\nproperty double nz\nproperty uchar flag\n"
	                  "element face 1\nproperty list uchar uint vertex_indices\nend_header\n";
	size_t h = strlen(hdr), n = h, rec = 12 + 24 + 1, cut;
	unsigned char u8 = 3;
	memcpy(b, hdr, h);
	n += putf(b + n, 0); n += putf(b + n, 0); n += putf(b + n, 0);
	n += putd(b + n, 0.0); n += putd(b + n, -0.6); n += putd(b + n, -0.8); b[n++] = 7;
	n += putf(b + n, 1); n += putf(b + n, 0); n += putf(b + n, 0);
	n += putd(b + n, 0.1); n += putd(b + n, 0.2); n += putd(b + n, 0.3); b[n++] = 7;
	b[n++] = u8;
	n += putu(b + n, 0); n += putu(b + n, 1); n += putu(b + n, 0);
	CHECK(rd("b.ply", b, n, &m, err) == 0, "b.ply: %s", err);
	CHECK(m.count == 2 && m.stored_type == MESH_T_DOUBLE && m.ply_binary == 1, "b.ply count %zu", m.count);
	CHECK(m.count == 2 && m.y[0] == -0.6 && m.z[1] == 0.3, "b.ply values");
	CHECK(m.count == 2 && m.where[1] == h + rec, "b.ply offset %llu, expected %zu", m.count == 2 ? (unsigned long long)m.where[1] : 0ULL, h + rec);
	mesh_free(&m);
	/* every proper prefix of the body is refused, never read in part */
	{
		int ok = 1;
		for (cut = h; cut < n; cut++) {
			if (rd("b.ply", b, cut, &m, err) == 0) { ok = 0; mesh_free(&m); }
			else if (!strstr(err, "byte")) ok = 0;
		}
		CHECK(ok, "a truncated binary PLY was accepted or the error named no byte offset");
	}
	expect_error("trunc.ply", b, n - 3, "byte", "truncated");
	/* trailing bytes: a warning (assimp reads such files), not an error */
	b[n] = 0;
	CHECK(rd("extra.ply", b, n + 1, &m, err) == 0 && m.count > 0 && strstr(m.warning, "after the last element")
	      && strstr(m.warning, "1 bytes"), "extra.ply: %s / warning '%s'", err, m.warning);
	mesh_free(&m);
	/* out-of-range face index */
	putu(b + n - 4, 2);
	expect_error("badidx.ply", b, n, "out of range", "byte");
	/* a list count larger than the file */
	b[n - 13] = 255;
	expect_error("biglist.ply", b, n, "count 255", "byte");
}

/* binary cube from faces (the layout of assimp's cube_binary.ply) */
static void test_ply_cube(void)
{
	mesh_normals m;
	char err[512];
	unsigned char b[1024];
	const char *hdr = "ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
	                  "element face 6\nproperty list uchar int vertex_indices\nend_header\n";
	static const int q[6][4] = { {0,3,2,1}, {4,5,6,7}, {0,1,5,4}, {2,3,7,6}, {1,2,6,5}, {0,4,7,3} };
	size_t n = strlen(hdr);
	int i, k, ok = 1;
	memcpy(b, hdr, n);
	for (i = 0; i < 8; i++) {
		n += putf(b + n, (i == 1 || i == 2 || i == 5 || i == 6) ? 1.0f : -1.0f);
		n += putf(b + n, (i == 2 || i == 3 || i == 6 || i == 7) ? 1.0f : -1.0f);
		n += putf(b + n, i >= 4 ? 1.0f : -1.0f);
	}
	for (i = 0; i < 6; i++) {
		b[n++] = 4;
		for (k = 0; k < 4; k++)
			n += puti(b + n, q[i][k]);
	}
	CHECK(rd("cube.ply", b, n, &m, err) == 0, "cube.ply: %s", err);
	for (i = 0; i < 8 && m.count == 8; i++)
		ok &= near3(&m, find_vertex(&m, (size_t)i), (i == 1 || i == 2 || i == 5 || i == 6) ? r3 : -r3,
		            (i == 2 || i == 3 || i == 6 || i == 7) ? r3 : -r3, i >= 4 ? r3 : -r3);
	CHECK(m.count == 8 && ok, "cube.ply normals (count %zu)", m.count);
	mesh_free(&m);
	/* big endian reading of the same bytes is wrong-sized floats: still
	   read in full or refused, never a crash (values are garbage) */
}

/* malformed ascii */
static void test_ply_malformed(void)
{
	expect_errors("nohdr.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float nx\nproperty float ny\nproperty float nz\n0 0 1\n",
	              "end_header", NULL);
	expect_errors("badnum.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float nx\nproperty float ny\nproperty float nz\nend_header\n"
	              "0 0 1\n0 0.5x 1\n", "line 9", "bad number '0.5x'");
	expect_errors("fewrec.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float nx\nproperty float ny\nproperty float nz\nend_header\n"
	              "0 0 1\n0 0 1\n0 0 1 0 0 1 0 0 1\n", "after the last element", NULL);
	expect_errors("manyrec.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float nx\nproperty float ny\nproperty float nz\nend_header\n"
	              "0.0 0.0 1.0\n0.0 0.0 1.0\n0.0 0.0 1.0\n", "file ends", "vertex");
	expect_errors("huge.ply", "ply\nformat ascii 1.0\nelement vertex 4000000000000\nproperty float nx\nproperty float ny\nproperty float nz\nend_header\n0 0 1\n",
	              "count 4000000000000", "byte");
	expect_errors("hugebin.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 9223372036854775807\nproperty double nx\nproperty double ny\nproperty double nz\nend_header\n",
	              "count", "byte");
	expect_errors("idx.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
	              "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "out of range", "byte");
	expect_errors("neg.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
	              "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n", "out of range", NULL);
	expect_errors("fmt.ply", "ply\nformat utf8 1.0\nend_header\n", "unknown format", "line 2");
	expect_errors("magic.ply", "plx\nformat ascii 1.0\nend_header\n", "not a PLY", NULL);
	expect_errors("noprop.ply", "ply\nformat ascii 1.0\nelement vertex 2\nend_header\n1 2\n", "no properties", NULL);
	expect_errors("none.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n",
	              "no normals", NULL);
	expect_errors("u8.ply", "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nproperty float nx\nproperty float ny\nproperty float nz\n"
	              "end_header\n300 0 1 2 0 0 1\n", "bad integer '300'", NULL);
}

static void test_ply(void)
{
	test_ply_ascii();
	test_ply_tet();
	test_ply_binary();
	test_ply_big();
	test_ply_cube();
	test_ply_malformed();
}

/* deterministic xorshift */
static unsigned long long rng = 0x9e3779b97f4a7c15ULL;
static unsigned long long next_rand(void)
{
	rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17;
	return rng;
}

static void test_mutations(void)
{
	static const char *seeds[] = {
		"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvn 0 0 1\nf 1/1/1 3/1/1 2/1/1\nf 1 2 4\nf -4 -1 -2\nf 2 3 4\n",
		"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
		"element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
		"ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float nx\nproperty float ny\nproperty float nz\n"
		"element face 1\nproperty list uchar uchar vertex_indices\nend_header\n\0\0\0\0\0\0\x80?\0\0\x80?\0\0\0\0\0\0\0\0\x03\x00\x01\x01",
	};
	static const size_t lens[] = { 0, 0, 0 };
	int s, it, bad = 0, accepted = 0, refused = 0;
	(void)lens;
	for (s = 0; s < 3; s++) {
		size_t len = s == 2 ? strlen(seeds[s]) + 24 : strlen(seeds[s]);
		for (it = 0; it < 3000; it++) {
			unsigned char buf[512];
			mesh_normals m;
			char err[512];
			int k, nmut = 1 + (int)(next_rand() % 4);
			size_t n = len;
			memcpy(buf, seeds[s], len);
			for (k = 0; k < nmut; k++) {
				size_t at = (size_t)(next_rand() % n);
				switch (next_rand() % 4) {
				case 0: buf[at] = (unsigned char)next_rand(); break;
				case 1: buf[at] ^= (unsigned char)(1u << (next_rand() % 8)); break;
				case 2: n = at + 1; break;
				default: buf[at] = "0123456789-. \n/"[next_rand() % 15]; break;
				}
			}
			if (mesh_read_mem(s ? "m.ply" : "m.obj", buf, n, &m, err, sizeof err) == 0) {
				size_t i;
				accepted++;
				for (i = 0; i < m.count; i++)
					if (m.index[i] >= (m.origin == MESH_COMPUTED ? m.nvertices : (size_t)-1))
						bad++;
				mesh_free(&m);
			} else {
				refused++;
				if (err[0] == '\0' || strchr(err, '\n'))
					bad++;
			}
		}
	}
	CHECK(bad == 0, "%d mutated inputs gave an empty or multi-line error or an inconsistent result", bad);
	CHECK(accepted > 0 && refused > 0, "mutations: %d accepted, %d refused (both kinds expected)", accepted, refused);
	printf("mutations: %d accepted, %d refused\n", accepted, refused);
}

static void test_file(void)
{
	char dir[] = "/tmp/test_meshio.XXXXXX", path[256];
	mesh_normals m;
	char err[512];
	FILE *f;
	if (!mkdtemp(dir)) {
		CHECK(0, "mkdtemp");
		return;
	}
	snprintf(path, sizeof path, "%s/tri.obj", dir);
	f = fopen(path, "w");
	fputs("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3", f); /* no final newline */
	fclose(f);
	CHECK(mesh_read_file(path, &m, err, sizeof err) == 0 && m.count == 3 && near3(&m, 0, 0, 0, 1), "tri.obj from a file: %s", err);
	mesh_free(&m);
	remove(path);
	snprintf(path, sizeof path, "%s/missing.ply", dir);
	CHECK(mesh_read_file(path, &m, err, sizeof err) == -1 && strstr(err, "cannot open"), "missing file: %s", err);
	rmdir(dir);
}

/* The optional geometry (mesh_read_geom_mem): positions, fan triangles,
   per-corner normal indices, and nothing on error. */
static void test_geom(void)
{
	mesh_normals m;
	mesh_geom g;
	char err[512];
	/* a quad (two triangles) with vn per corner, and a triangle without */
	const char *a = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
	                "vn 0 0 1\nvn 0 0 -1\n"
	                "f 1//1 2//1 3//2 4//2\nf 1 2 5\n";
	/* no vn: computed normals, indexed like the positions */
	const char *b = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 9 9 9\nf 1 2 3\n";
	int rc = mesh_read_geom_mem("a.obj", (const unsigned char *)a, strlen(a), &m, &g, err, sizeof err);
	CHECK(rc == 0, "geom a: %s", err);
	if (rc == 0) {
		CHECK(g.nverts == 5 && g.ntris == 3 && g.nnormals == 2 && m.count == 2, "geom a: counts %zu %zu %zu", g.nverts, g.ntris, g.nnormals);
		CHECK(g.tri[0] == 0 && g.tri[1] == 1 && g.tri[2] == 2 && g.tri[3] == 0 && g.tri[4] == 2 && g.tri[5] == 3,
		      "geom a: fan triangulation %u %u %u / %u %u %u", g.tri[0], g.tri[1], g.tri[2], g.tri[3], g.tri[4], g.tri[5]);
		CHECK(g.tri_n[0] == 0 && g.tri_n[1] == 0 && g.tri_n[2] == 1 && g.tri_n[3] == 0 && g.tri_n[4] == 1 && g.tri_n[5] == 1,
		      "geom a: corner normals");
		CHECK(g.tri_n[6] == MESH_NO_NORMAL && g.tri_n[7] == MESH_NO_NORMAL && g.tri_n[8] == MESH_NO_NORMAL, "geom a: corners without vn");
		CHECK(g.pos[3 * 4 + 2] == 1 && g.nrm[3 * 1 + 2] == -1, "geom a: values");
		CHECK(g.tri_line[0] == 8 && g.tri_line[1] == 8 && g.tri_line[2] == 9, "geom a: face lines");
	}
	mesh_geom_free(&g);
	mesh_free(&m);
	rc = mesh_read_geom_mem("b.obj", (const unsigned char *)b, strlen(b), &m, &g, err, sizeof err);
	CHECK(rc == 0, "geom b: %s", err);
	if (rc == 0) {
		CHECK(g.nverts == 4 && g.ntris == 1 && g.nnormals == 4, "geom b: counts");
		CHECK(g.tri_n[0] == 0 && g.tri_n[1] == 1 && g.tri_n[2] == 2, "geom b: normal indices are the vertices");
		CHECK(g.nrm[2] == 1 && g.nrm[5] == 1 && g.nrm[8] == 1 && g.nrm[11] == 0, "geom b: computed normals (+z), unreferenced 0");
	}
	mesh_geom_free(&g);
	mesh_free(&m);
	/* errors: the same messages, nothing left behind */
	rc = mesh_read_geom_mem("c.obj", (const unsigned char *)"v 0 0 0\nf 1 2 3\n", 16, &m, &g, err, sizeof err);
	CHECK(rc == -1 && strstr(err, "line 2") && g.tri == NULL && g.pos == NULL && g.ntris == 0 && m.x == NULL, "geom c: %s", err);
	rc = mesh_read_geom_mem("d.ply", (const unsigned char *)"ply\n", 4, &m, &g, err, sizeof err);
	CHECK(rc == -1 && strstr(err, "byte") && g.tri == NULL, "geom d: %s", err);
}


/* ---- glTF 2.0, detection by content, PLY aliases, OBJ continuation ---- */

static int rdf(const char *path, int world, int prec, mesh_normals *m, char *err)
{
	mesh_opts o;
	memset(&o, 0, sizeof o);
	o.world = world;
	o.prec = prec;
	return mesh_read_file_opts(path, &o, m, NULL, err, 512);
}

/* the glTF spec's decoding of normalized signed integers */
static double dq8(int c) { return fmax(c / 127.0, -1.0); }
static double dq16(int c) { return fmax(c / 32767.0, -1.0); }

static void test_gltf_files(void)
{
	mesh_normals m;
	char err[512];
	int prec;
	/* KHR_mesh_quantization: BYTE and SHORT normalized, strides 4 and 8 */
	CHECK(rdf("tests/data/gltf/quantized.gltf", 0, PREC_FLOAT, &m, err) == 0, "quantized.gltf: %s", err);
	CHECK(m.count == 8 && m.format == MESH_GLTF && m.stored_type == MESH_T_QUANT && m.nprims == 2, "quantized counts %zu %d", m.count, m.stored_type);
	if (m.count == 8) {
		CHECK(m.x[0] == -1.0 && m.x[1] == 1.0 && m.x[2] == dq8(64) && m.y[2] == dq8(-64) && m.z[3] == dq8(3), "byte decoding %a %a %a", m.x[0], m.x[2], m.z[3]);
		CHECK(m.x[4] == -1.0 && m.x[5] == 1.0 && m.x[6] == dq16(12345) && m.y[6] == dq16(-23456) && m.y[7] == dq16(2), "short decoding %a %a", m.x[6], m.y[6]);
		CHECK(m.where[6] >> 32 == 1 && (m.where[6] & 0xffffffffu) == 2, "quantized place of normal 6");
	}
	mesh_free(&m);
	/* interleaved (byteStride 24) float normals; --world through a matrix
	   node and a scaled child: world diag(2, 4, 8), inverse transpose
	   diag(1/2, 1/4, 1/8), exact in both precisions */
	CHECK(rdf("tests/data/gltf/strided.gltf", 0, PREC_FLOAT, &m, err) == 0 && m.count == 4 && m.x[0] == (double)(float)0.6
	      && m.y[0] == (double)(float)0.8 && m.z[1] == 1 && m.y[2] == -1 && m.x[3] == 1 && m.stored_type == MESH_T_FLOAT, "strided.gltf: %s", err);
	mesh_free(&m);
	for (prec = PREC_FLOAT; prec <= PREC_DOUBLE; prec++) {
		CHECK(rdf("tests/data/gltf/strided.gltf", 1, prec, &m, err) == 0 && m.count == 8 && m.world, "strided --world: %s", err);
		if (m.count == 8)
			CHECK(m.x[0] == (double)(float)0.6 * 0.5 && m.y[0] == (double)(float)0.8 * 0.25 && m.z[1] == 1 && m.where[0] >> 40 == 0
			      && m.x[4] == (double)(float)0.6 * 0.5 && m.z[5] == 0.125 && m.y[6] == -0.25 && m.x[7] == 0.5 && m.where[4] >> 40 == 1,
			      "strided --world values (%s): %a %a %a %a", prec_name(prec), m.x[0], m.y[0], m.z[5], m.y[6]);
		mesh_free(&m);
	}
	/* .glb, default scene 1: its node rotates 90 degrees about z, so x -> y;
	   float and double give different roundings of the same rotation */
	{
		double d[9] = { 0 };
		CHECK(rdf("tests/data/gltf/rotated.glb", 0, PREC_FLOAT, &m, err) == 0 && m.count == 3 && m.gltf_binary && m.x[0] == 1, "rotated.glb: %s", err);
		mesh_free(&m);
		CHECK(rdf("tests/data/gltf/rotated.glb", 1, PREC_DOUBLE, &m, err) == 0 && m.count == 3 && m.where[0] >> 40 == 1, "rotated.glb --world double: %s", err);
		if (m.count == 3) {
			CHECK(fabs(m.x[0]) < 1e-15 && fabs(m.y[0] - 1) < 1e-15 && fabs(m.x[1] + 1) < 1e-15 && m.z[2] == 1, "rotated double (%a %a)", m.x[0], m.y[0]);
			d[0] = m.x[0]; d[1] = m.y[0]; d[2] = m.x[1];
		}
		mesh_free(&m);
		CHECK(rdf("tests/data/gltf/rotated.glb", 1, PREC_FLOAT, &m, err) == 0 && m.count == 3, "rotated.glb --world float: %s", err);
		if (m.count == 3) {
			CHECK(fabs(m.x[0]) < 1e-6 && fabs(m.y[0] - 1) < 1e-6 && (double)(float)m.y[0] == m.y[0], "rotated float (%a %a)", m.x[0], m.y[0]);
			CHECK(m.x[0] != d[0] || m.y[0] != d[1] || m.x[1] != d[2], "float and double world transforms agree bit for bit");
		}
		mesh_free(&m);
	}
	/* sparse over a bufferView, sparse over zeros, computed normals */
	CHECK(rdf("tests/data/gltf/sparse.gltf", 0, PREC_FLOAT, &m, err) == 0 && m.count == 12 && m.ncomputed == 4 && m.nprims_computed == 1, "sparse.gltf: %s (%zu, %zu)", err, m.count, m.ncomputed);
	if (m.count == 12) {
		CHECK(m.z[0] == 1 && m.x[1] == 1 && m.z[2] == 1 && m.y[3] == -1, "sparse over a bufferView");
		CHECK(m.x[4] == 0 && m.y[4] == 0 && m.z[4] == 0 && m.x[5] == 1 && m.z[6] == 0 && m.y[7] == -1, "sparse over zeros");
		CHECK(near3(&m, 8, 1 / sqrt(2.0), 0, 1 / sqrt(2.0)) && m.z[9] == 1 && m.x[11] == 1, "computed normals (%a %a %a)", m.x[8], m.y[8], m.z[8]);
	}
	mesh_free(&m);
	/* an external buffer, its name percent-encoded: from the file only */
	CHECK(rdf("tests/data/gltf/external.gltf", 0, PREC_FLOAT, &m, err) == 0 && m.count == 3 && m.x[2] == (double)(float)0.6, "external.gltf: %s", err);
	mesh_free(&m);
	{
		FILE *f = fopen("tests/data/gltf/external.gltf", "rb");
		char buf[4096];
		size_t n = f ? fread(buf, 1, sizeof buf, f) : 0;
		if (f)
			fclose(f);
		expect_error("external.gltf", buf, n, "external", "refused");
	}
}

/* geometry for a renderer from PLY and glTF (aorender --mesh) */
static void test_geom_formats(void)
{
	static const char ply[] = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
	                          "property float nx\nproperty float ny\nproperty float nz\nelement face 1\n"
	                          "property list uchar int vertex_indices\nend_header\n0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0.6 0 0.8\n0 1 0 0 0 1\n4 0 1 2 3\n";
	mesh_normals m;
	mesh_geom g;
	char err[512];
	int rc = mesh_read_geom_mem("quad.ply", (const unsigned char *)ply, strlen(ply), &m, &g, err, sizeof err);
	CHECK(rc == 0 && g.nverts == 4 && g.ntris == 2 && g.nnormals == 4 && g.nrm[6] == (double)(float)0.6 && g.tri[3] == 0
	      && g.tri[4] == 2 && g.tri[5] == 3 && g.tri_n[5] == 3 && g.pos[6] == 1, "PLY geometry: %s", err);
	if (rc == 0) { mesh_geom_free(&g); mesh_free(&m); }
	rc = mesh_read_geom_file("tests/data/gltf/strided.gltf", &m, &g, err, sizeof err);
	CHECK(rc == 0 && g.nverts == 4 && g.ntris == 2 && g.nrm[0] == (double)(float)0.6 && g.tri[3] == 0 && g.tri[4] == 2 && g.tri[5] == 3
	      && g.pos[3] == 1 && g.tri_n[4] == 2, "glTF geometry: %s", err);
	if (rc == 0) { mesh_geom_free(&g); mesh_free(&m); }
	rc = mesh_read_geom_file("tests/data/gltf/sparse.gltf", &m, &g, err, sizeof err);
	CHECK(rc == 0 && g.nverts == 12 && g.ntris == 4 && g.tri[6] == 8 && g.tri[11] == 11 && g.nrm[3 * 9 + 2] == 1
	      && strstr(m.warning, "not a multiple of 3"), "glTF geometry, three primitives: %s (%zu %zu)", err, g.nverts, g.ntris);
	if (rc == 0) { mesh_geom_free(&g); mesh_free(&m); }
}

static void test_gltf_errors(void)
{
	static const char pre[] = "{\"asset\":{\"version\":\"2.0\"},";
	/* one float normal (0,0,1) in a 12-byte data: buffer */
	static const char buf1[] = "\"buffers\":[{\"byteLength\":12,\"uri\":\"data:application/octet-stream;base64,AAAAAAAAAAAAAIA/\"}]";
	char s[2048];
#define G(name, body, w1, w2) do { snprintf(s, sizeof s, "%s%s}", pre, body); expect_errors(name, s, w1, w2); } while (0)
	expect_errors("v1.gltf", "{\"asset\":{\"version\":\"1.0\"}}", "only glTF 2.0", NULL);
	expect_errors("noasset.gltf", "{\"meshes\":[]}", "asset.version", NULL);
	expect_errors("trunc.gltf", "{\"asset\":{\"version\":", "does not parse", NULL);
	expect_errors("array.gltf", "[1,2]", "not an object", NULL);
	G("nomesh.gltf", "\"meshes\":[]", "no normals", NULL);
	G("acc.gltf", "\"meshes\":[{\"primitives\":[{\"attributes\":{\"NORMAL\":5}}]}]", "accessor 5 does not exist", NULL);
	G("negidx.gltf", "\"meshes\":[{\"primitives\":[{\"attributes\":{\"NORMAL\":-1}}]}]", "must be an index", NULL);
	snprintf(s, sizeof s, "%s%s,\"bufferViews\":[{\"buffer\":0,\"byteOffset\":4,\"byteLength\":12}],"
	         "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":1,\"type\":\"VEC3\"}],"
	         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"NORMAL\":0}}]}]}", pre, buf1);
	expect_errors("view.gltf", s, "outside buffer 0", "bufferView 0");
	snprintf(s, sizeof s, "%s%s,\"bufferViews\":[{\"buffer\":0,\"byteLength\":12}],"
	         "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":2,\"type\":\"VEC3\"}],"
	         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"NORMAL\":0}}]}]}", pre, buf1);
	expect_errors("count.gltf", s, "does not fit", "accessor 0");
	snprintf(s, sizeof s, "%s%s,\"bufferViews\":[{\"buffer\":0,\"byteLength\":12,\"byteStride\":6}],"
	         "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":1,\"type\":\"VEC3\"}],"
	         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"NORMAL\":0}}]}]}", pre, buf1);
	expect_errors("stride.gltf", s, "byteStride 6", NULL);
	snprintf(s, sizeof s, "%s%s,\"bufferViews\":[{\"buffer\":0,\"byteLength\":12}],"
	         "\"accessors\":[{\"bufferView\":0,\"componentType\":5121,\"normalized\":true,\"count\":4,\"type\":\"VEC3\"}],"
	         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"NORMAL\":0}}]}]}", pre, buf1);
	expect_errors("ubyte.gltf", s, "NORMAL must be FLOAT", NULL);
	snprintf(s, sizeof s, "%s%s,\"bufferViews\":[{\"buffer\":0,\"byteLength\":12}],"
	         "\"accessors\":[{\"componentType\":5126,\"count\":100000000,\"type\":\"VEC3\"}],"
	         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"NORMAL\":0}}]}]}", pre, buf1);
	expect_errors("huge.gltf", s, "more than this file can hold", NULL);
	/* 24 zero bytes: sparse indices 0, 0 */
	snprintf(s, sizeof s, "%s\"buffers\":[{\"byteLength\":24,\"uri\":\"data:application/octet-stream;base64,"
	         "AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA\"}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":24}],"
	         "\"accessors\":[{\"componentType\":5126,\"count\":4,\"type\":\"VEC3\",\"sparse\":{\"count\":2,"
	         "\"indices\":{\"bufferView\":0,\"componentType\":5121},\"values\":{\"bufferView\":0}}}],"
	         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"NORMAL\":0}}]}]}", pre);
	expect_errors("sparse.gltf", s, "sparse index 1", "increase");
	G("b64.gltf", "\"buffers\":[{\"byteLength\":3,\"uri\":\"data:application/octet-stream;base64,A*A=\"}],"
	  "\"bufferViews\":[{\"buffer\":0,\"byteLength\":3}],\"accessors\":[{\"bufferView\":0,\"componentType\":5120,\"normalized\":true,\"count\":1,\"type\":\"VEC3\"}],"
	  "\"meshes\":[{\"primitives\":[{\"attributes\":{\"NORMAL\":0}}]}]", "base64", NULL);
	G("cycle.gltf", "\"nodes\":[{\"children\":[1]},{\"children\":[0]}]", "cycle", NULL);
	G("parents.gltf", "\"nodes\":[{\"children\":[2]},{\"children\":[2]},{}]", "two parents", NULL);
	G("self.gltf", "\"nodes\":[{\"children\":[0]}]", "own child", NULL);
	G("scene.gltf", "\"scene\":\"x\"", "'scene' must be an index", NULL);
	G("draco.gltf", "\"extensionsRequired\":[\"KHR_draco_mesh_compression\"]", "KHR_draco_mesh_compression", "not supported");
	G("prims.gltf", "\"meshes\":[{\"primitives\":{}}]", "'primitives' must be an array", NULL);
	{
		unsigned char g[40] = "glTF";
		g[4] = 2; g[8] = 40;
		expect_error("short.glb", g, 20, "byte 8", "truncated");
		g[4] = 1;
		expect_error("v1.glb", g, 40, "container version 1", NULL);
	}
#undef G
}

static void test_detect(void)
{
	mesh_normals m;
	char err[512];
	unsigned char b[134];
	static const char ply[] = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float normal_x\nproperty float normal_y\n"
	                          "property float normal_z\nend_header\n0 0.6 0.8\n";
	memset(b, 0, sizeof b);
	b[80] = 1; /* binary STL: 80-byte header, 1 triangle of 50 bytes */
	expect_error("model.obj", b, sizeof b, "STL (binary)", "supported: OBJ, PLY, glTF 2.0");
	expect_errors("model.obj", "solid cube\n facet normal 0 0 1\n", "STL (ascii)", "supported");
	expect_errors("prog", "\x7f" "ELF\x02\x01\x01", "ELF", NULL);
	expect_errors("model.fbx", "Kaydara FBX Binary  \x00\x1a", "FBX", NULL);
	expect_errors("m.dae", "<?xml version=\"1.0\"?>\n<COLLADA xmlns=\"x\">", "Collada", NULL);
	memset(b, 0xee, sizeof b);
	b[3] = 0;
	expect_error("blob.obj", b, sizeof b, "unknown format", NULL);
	/* a PLY named .obj is read as PLY, with a warning; normal_x aliases */
	CHECK(rds("cloud.obj", ply, &m, err) == 0 && m.format == MESH_PLY && m.count == 1 && m.y[0] == (double)(float)0.6
	      && strstr(m.warning, "ends in .obj"), "PLY named .obj: %s / '%s'", err, m.warning);
	mesh_free(&m);
	/* OBJ line continuation; places are the first physical line */
	CHECK(rds("c.obj", "v 0 0 0\nvn 0 \\\n 0 1\nvn 1 \\\r\n0 0\nvn 0 1 0\n", &m, err) == 0 && m.count == 3 && m.z[0] == 1
	      && m.x[1] == 1 && m.where[0] == 2 && m.where[1] == 4 && m.where[2] == 6, "OBJ continuation: %s (%zu; %llu %llu %llu)", err,
	      m.count, m.count == 3 ? (unsigned long long)m.where[0] : 0ULL, m.count == 3 ? (unsigned long long)m.where[1] : 0ULL,
	      m.count == 3 ? (unsigned long long)m.where[2] : 0ULL);
	mesh_free(&m);
	expect_errors("c.obj", "vn 0 \\\n0 1\nvn x 0 0\n", "line 3", "bad number");
}

int main(void)
{
	test_obj();
	test_ply();
	test_mutations();
	test_file();
	test_geom();
	test_gltf_files();
	test_gltf_errors();
	test_geom_formats();
	test_detect();
	return check_finish(NULL);
}
