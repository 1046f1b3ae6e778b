/*
 * fuzz_mesh.c - libFuzzer harness for the OBJ and PLY readers (meshio.c).
 *
 * The same bytes are read three times: named .obj, named .ply, and with no
 * extension (format sniffed from the content).  On success the result is
 * classified in both precisions and every normal located, so the code the
 * scene command runs on a parsed mesh is covered too.  On failure the
 * reader must have left an error message and an empty result.
 * Built by scripts/fuzz.sh (clang -fsanitize=fuzzer,address,undefined) and,
 * as a plain program with tests/fuzz/replay.c, by tests/fuzz_regress.sh.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "meshio.h"

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
	if (mesh_classify(&m, 1, 0, &st) == 0 && st.total != m.count)
		abort();
	if (mesh_classify(&m, 0, 0, &st) == 0 && st.total != m.count)
		abort();
	for (i = 0; i < m.count && i < 64; i++)
		mesh_where(&m, i, where, sizeof where);
	if (m.count)
		mesh_where(&m, m.count - 1, where, sizeof where);
	mesh_free(&m);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	one("fuzz.obj", data, size);
	one("fuzz.ply", data, size);
	one("fuzz", data, size);
	return 0;
}
