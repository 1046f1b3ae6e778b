/*
 * meshio.c - the mesh readers' entry points: the format detected from the
 * first bytes (and the name's extension), then the OBJ, PLY or glTF
 * reader (obj.h, ply.h, gltf.h).
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
#include "mesh/common.h"
#include "mesh/obj.h"
#include "mesh/ply.h"
#include "mesh/gltf.h"

#define fail mio_fail
#define xcalloc mio_calloc
#define alloc_normals mio_alloc_normals
#define compute_normals mio_compute_normals

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
	for (i = 0; i < look && mio_is_space(b[i]); i++)
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
		ctl += b[k] < 0x20 && !mio_is_space(b[k]) && b[k] != 0x1a;
	}
	if (look - i >= 5 && !memcmp(b + i, "solid", 5) && (look - i == 5 || mio_is_space(b[i + 5])) && !nul) {
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
	rc = fmt == MESH_PLY ? mio_read_ply(c, buf, len, out, geom) : fmt == MESH_GLTF ? mio_read_gltf(c, buf, len, o ? o : &defaults, out, geom)
	     : mio_read_obj(c, buf, len, out, geom);
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
