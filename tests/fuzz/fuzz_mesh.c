/*
 * fuzz_mesh.c - libFuzzer harness for the OBJ and PLY readers (meshio.c).
 *
 * The same bytes are read three times: named .obj, named .ply, and with no
 * extension (format sniffed from the content).  On success the result is
 * classified in both precisions and every normal located, so the code the
 * scene command runs on a parsed mesh is covered too.  On failure the
 * reader must have left an error message and an empty result.
 * The geometry read (mesh_read_geom_mem, OBJ) must agree with the normals-
 * only read and keep every triangle and normal index in range.
 * Built by scripts/fuzz.sh (clang -fsanitize=fuzzer,address,undefined) and,
 * as a plain program with tests/fuzz/replay.c, by tests/fuzz_regress.sh.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "mesh/meshio.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void one(const char *name, const uint8_t *data, size_t size)
{
	mesh_normals m;
	mesh_stats st;
	char err[512], where[160];
	size_t i;
	memset(&m, 0, sizeof m);
	err[0] = '\0';
	if (mesh_read_mem(name, data, size, &m, err, sizeof err) != 0) {
		/* contract: a message, and nothing returned */
		if (err[0] == '\0' || m.count != 0 || m.x || m.y || m.z)
			abort();
		mesh_free(&m);
		return;
	}
	if (m.count && (!m.x || !m.y || !m.z))
		abort();
	if (mesh_classify(&m, PREC_FLOAT, 0, &st) == 0 && st.total != m.count)
		abort();
	if (mesh_classify(&m, PREC_DOUBLE, 0, &st) == 0 && st.total != m.count)
		abort();
	for (i = 0; i < m.count && i < 64; i++)
		mesh_where(&m, i, where, sizeof where);
	if (m.count)
		mesh_where(&m, m.count - 1, where, sizeof where);
	mesh_free(&m);
}

/* The optional geometry (OBJ): the same verdict as the normals-only read,
   and every index in range. */
static void geom(const uint8_t *data, size_t size)
{
	mesh_normals m, m2;
	mesh_geom g;
	char err[512], err2[512];
	size_t i;
	int rc = mesh_read_geom_mem("fuzz.obj", data, size, &m, &g, err, sizeof err);
	int rc2 = mesh_read_mem("fuzz.obj", data, size, &m2, err2, sizeof err2);
	if (rc != 0 && rc2 == 0 && strstr(err, "no geometry")) {
		/* a PLY or glTF with normals but nothing to draw */
		mesh_free(&m2);
		return;
	}
	if (rc != rc2)
		abort();
	if (rc != 0) {
		if (err[0] == '\0' || m.count || g.ntris || g.pos || g.tri || g.tri_n || g.nrm)
			abort();
		mesh_free(&m2);
		return;
	}
	if (m.count != m2.count || !g.pos || !g.nrm || !g.tri || !g.tri_n)
		abort();
	for (i = 0; i < 3 * g.ntris; i++)
		if (g.tri[i] >= g.nverts || (g.tri_n[i] != MESH_NO_NORMAL && g.tri_n[i] >= g.nnormals))
			abort();
	if (m.format != MESH_OBJ) { /* the checks below are OBJ's */
		mesh_geom_free(&g);
		mesh_free(&m);
		mesh_free(&m2);
		return;
	}
	if (g.ntris != m.ntriangles || g.nverts != m.nvertices)
		abort();
	/* the normals the corners index are the ones read (bit for bit) */
	for (i = 0; i < m.count; i++) {
		size_t k = m.origin == MESH_STORED ? i : m.index[i];
		if (k >= g.nnormals || memcmp(&g.nrm[3 * k], &m.x[i], sizeof(double)) != 0
		    || memcmp(&g.nrm[3 * k + 1], &m.y[i], sizeof(double)) != 0 || memcmp(&g.nrm[3 * k + 2], &m.z[i], sizeof(double)) != 0)
			abort();
	}
	mesh_geom_free(&g);
	mesh_free(&m);
	mesh_free(&m2);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	geom(data, size);
	one("fuzz.obj", data, size);
	one("fuzz.ply", data, size);
	one("fuzz", data, size);
	return 0;
}
