/*
 * fuzz_gltf.c - libFuzzer harness for the glTF 2.0 reader (src/mesh/gltf.c,
 * through meshio's content detection).
 *
 * The bytes are read as given and, so that most inputs reach the glTF
 * reader whatever their first bytes, also behind a GLB header whose JSON
 * chunk holds them: each in object space, and in world space in float and
 * in double (--world).  On failure the reader must leave a one-line
 * message and an empty result; on success the normals are classified in
 * both precisions and located.  External buffers are refused from memory,
 * so the harness never opens a file.
 * Built by scripts/fuzz.sh (clang -fsanitize=fuzzer,address,undefined) and,
 * as a plain program with tests/fuzz/replay.c, by tests/fuzz_regress.sh.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "mesh/meshio.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void one(const char *name, const uint8_t *data, size_t size, int world, int prec)
{
	mesh_normals m;
	mesh_stats st;
	mesh_opts o;
	char err[512], where[160];
	size_t i;
	memset(&o, 0, sizeof o);
	o.world = world;
	o.prec = prec;
	err[0] = '\0';
	if (mesh_read_mem_opts(name, data, size, &o, &m, NULL, err, sizeof err) != 0) {
		if (err[0] == '\0' || strchr(err, '\n') || m.count != 0 || m.x || m.y || m.z || m.where || m.index)
			abort();
		return;
	}
	if (!m.count || !m.x || !m.y || !m.z || !m.where || !m.index)
		abort();
	if (mesh_classify(&m, PREC_FLOAT, 0, &st) == 0 && st.total != m.count)
		abort();
	if (mesh_classify(&m, PREC_DOUBLE, 0, &st) == 0 && st.total != m.count)
		abort();
	for (i = 0; i < m.count && i < 16; i++)
		mesh_where(&m, i, where, sizeof where);
	mesh_where(&m, m.count - 1, where, sizeof where);
	mesh_free(&m);
}

static void put32(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); p[2] = (uint8_t)(v >> 16); p[3] = (uint8_t)(v >> 24);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	uint8_t *g;
	one("fuzz.gltf", data, size, 0, PREC_FLOAT);
	one("fuzz.gltf", data, size, 1, PREC_FLOAT);
	one("fuzz.gltf", data, size, 1, PREC_DOUBLE);
	/* the same bytes as the JSON chunk of a .glb without a BIN chunk */
	if (size < 65536 && (g = malloc(size + 20)) != NULL) {
		memcpy(g, "glTF", 4);
		put32(g + 4, 2);
		put32(g + 8, (uint32_t)(size + 20));
		put32(g + 12, (uint32_t)size);
		put32(g + 16, 0x4E4F534Au);
		memcpy(g + 20, data, size);
		one("fuzz.glb", g, size + 20, 0, PREC_FLOAT);
		free(g);
	}
	return 0;
}
