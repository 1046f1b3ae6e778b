/*
 * meshhash.c - make cross-check: what the mesh readers read, on
 * any machine, as one line per file:
 *   file count format ply_binary stored_type hash(x, y, z bits)
 *   meshhash --write DIR   writes {le,be}_{float,double}.ply: the same
 *                          1000 normals in binary PLY of both byte orders,
 *                          bytes assembled explicitly (identical files on
 *                          every host)
 *   meshhash FILE...       reads each with mesh_read_file
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "mesh/meshio.h"
#include "hash.h"

#define NV 1000

/* Normal i: exact from integers, not unit (the readers do not care). */
static double comp(int i, int c)
{
	return (double)((i * 37 + c * 101) % 2001 - 1000) / 1024.0;
}

static int write_ply(const char *dir, int big, int dbl)
{
	char path[1024];
	FILE *f;
	int i, c, b, w = dbl ? 8 : 4;
	snprintf(path, sizeof path, "%s/%s_%s.ply", dir, big ? "be" : "le", dbl ? "double" : "float");
	if (!(f = fopen(path, "wb"))) {
		fprintf(stderr, "meshhash: cannot write %s\n", path);
		return 1;
	}
	fprintf(f, "ply\nformat binary_%s_endian 1.0\nelement vertex %d\n", big ? "big" : "little", NV);
	fprintf(f, "property %s nx\nproperty %s ny\nproperty %s nz\nend_header\n", dbl ? "double" : "float",
	        dbl ? "double" : "float", dbl ? "double" : "float");
	for (i = 0; i < NV; i++)
		for (c = 0; c < 3; c++) {
			unsigned char by[8];
			uint64_t u = 0;
			if (dbl) { double x = comp(i, c); memcpy(&u, &x, 8); }
			else { float x = (float)comp(i, c); uint32_t v; memcpy(&v, &x, 4); u = v; }
			for (b = 0; b < w; b++)
				by[big ? w - 1 - b : b] = (unsigned char)(u >> (8 * b));
			fwrite(by, 1, (size_t)w, f);
		}
	return fclose(f) != 0;
}

int main(int argc, char **argv)
{
	int i, rc = 0;
	if (argc == 3 && strcmp(argv[1], "--write") == 0)
		return write_ply(argv[2], 0, 0) | write_ply(argv[2], 1, 0) | write_ply(argv[2], 0, 1) | write_ply(argv[2], 1, 1);
	if (argc < 2) {
		fprintf(stderr, "usage: meshhash --write DIR | meshhash FILE...\n");
		return 2;
	}
	for (i = 1; i < argc; i++) {
		mesh_normals m;
		char err[512];
		uint64_t h = FNV_INIT;
		size_t k;
		const char *base = strrchr(argv[i], '/') ? strrchr(argv[i], '/') + 1 : argv[i];
		if (mesh_read_file(argv[i], &m, err, sizeof err) != 0) {
			printf("%s error %s\n", base, err);
			rc = 1;
			continue;
		}
		for (k = 0; k < m.count; k++)
			h = fnv_d(fnv_d(fnv_d(h, m.x[k]), m.y[k]), m.z[k]);
		printf("%s %zu %d %d %d %016llx\n", base, m.count, m.format, m.ply_binary, m.stored_type, (unsigned long long)h);
		mesh_free(&m);
	}
	return rc;
}
