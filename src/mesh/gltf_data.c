/*
 * gltf_data.c - the values of a glTF file (gltf_int.h): its JSON
 * properties checked for type and range, its buffers (GLB chunk, base64
 * data: URIs, external files below the file's directory), buffer views
 * and accessors read byte by byte as little-endian, sparse substitution
 * included.  What the values mean is gltf.c's.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "mesh/gltf_int.h"

/* ---- JSON helpers --------------------------------------------------- */

cJSON *gl_item(const cJSON *o, const char *k)
{
	return cJSON_IsObject(o) ? cJSON_GetObjectItemCaseSensitive(o, k) : NULL;
}

/* An optional integer property in [lo, hi]; def when absent. */
int gl_jint(gltf *g, const cJSON *o, const char *what, long wi, const char *k, long long def, long long lo,
            long long hi, long long *out)
{
	const cJSON *v = gl_item(o, k);
	double d;
	if (!v) {
		if (def < lo)
			return mio_fail(g->c, "%s %ld: '%s' is required", what, wi, k);
		*out = def;
		return 0;
	}
	d = v->valuedouble;
	if (!cJSON_IsNumber(v) || !(d >= (double)lo && d <= (double)hi) || d != floor(d) || (lo == -2 && d < 0)) {
		char at[80] = "";
		if (wi >= 0)
			snprintf(at, sizeof at, " %ld", wi);
		if (lo == -2)
			return mio_fail(g->c, "%s%s: '%s' must be an index (an integer >= 0)", what, at, k);
		return mio_fail(g->c, "%s%s: '%s' must be an integer in [%lld, %lld]", what, at, k, lo, hi);
	}
	*out = (long long)d;
	return 0;
}

/* The array o[k] (NULL when absent); -1 when present but not an array. */
int gl_jarr(gltf *g, const cJSON *o, const char *what, long wi, const char *k, const cJSON **out)
{
	const cJSON *v = gl_item(o, k);
	*out = NULL;
	if (!v)
		return 0;
	if (!cJSON_IsArray(v))
		return wi >= 0 ? mio_fail(g->c, "%s %ld: '%s' must be an array", what, wi, k)
		               : mio_fail(g->c, "%s'%s' must be an array", what, k);
	*out = v;
	return 0;
}

/* Element i of the top-level array k, which must be an object. */
const cJSON *gl_top(gltf *g, const char *k, const char *what, long long i)
{
	const cJSON *a = gl_item(g->root, k), *e;
	int n = cJSON_IsArray(a) ? cJSON_GetArraySize(a) : 0;
	if (i < 0 || i >= n) {
		mio_fail(g->c, "%s %lld does not exist (%d in '%s')", what, i, n, k);
		return NULL;
	}
	e = cJSON_GetArrayItem(a, (int)i);
	if (!cJSON_IsObject(e)) {
		mio_fail(g->c, "%s %lld is not a JSON object", what, i);
		return NULL;
	}
	return e;
}

void gl_warn(gltf *g, const char *fmt, ...)
{
	char *w = g->m->warning;
	size_t l = strlen(w), cap = sizeof g->m->warning;
	va_list ap;
	if (l + 40 >= cap)
		return;
	if (l)
		l += (size_t)snprintf(w + l, cap - l, "; ");
	va_start(ap, fmt);
	vsnprintf(w + l, cap - l, fmt, ap);
	va_end(ap);
	if (l && strstr(w, w + l) < w + l - 2) /* said already (a geometry read) */
		w[l - 2] = '\0';
}

/* ---- buffers ---------------------------------------------------------- */

static int b64v(unsigned char ch)
{
	if (ch >= 'A' && ch <= 'Z') return ch - 'A';
	if (ch >= 'a' && ch <= 'z') return ch - 'a' + 26;
	if (ch >= '0' && ch <= '9') return ch - '0' + 52;
	if (ch == '+' || ch == '-') return 62;
	if (ch == '/' || ch == '_') return 63;
	return -1;
}

static int base64(gltf *g, long bi, const char *s, size_t n, gbuf *b)
{
	size_t i, k = 0;
	unsigned acc = 0;
	int bits = 0;
	while (n && s[n - 1] == '=')
		n--;
	b->data = mio_calloc(n / 4 * 3 + 3, 1);
	if (!b->data)
		return mio_fail(g->c, "buffer %ld: out of memory", bi);
	b->owned = 1;
	for (i = 0; i < n; i++) {
		int v = b64v((unsigned char)s[i]);
		if (v < 0)
			return mio_fail(g->c, "buffer %ld: bad base64 character at %zu of its data: URI", bi, i);
		acc = (acc << 6 | (unsigned)v) & 0xffffffu;
		bits += 6;
		if (bits >= 8) {
			bits -= 8;
			b->data[k++] = (unsigned char)(acc >> bits);
		}
	}
	b->len = k;
	return 0;
}

/* A relative path below the file's directory: percent-decoded, no scheme,
   no "..", not absolute. */
static int external(gltf *g, long bi, const char *uri, gbuf *b)
{
	char rel[1024], path[4096];
	size_t i, k = 0;
	mctx sub;
	if (!g->c->dir)
		return mio_fail(g->c, "buffer %ld: external file '%.200s' (read from memory: external buffers are refused)", bi, uri);
	for (i = 0; uri[i]; i++) {
		int ch = (unsigned char)uri[i];
		if (ch == '%' && uri[i + 1] && uri[i + 2]) {
			char hx[3] = { uri[i + 1], uri[i + 2], 0 }, *e;
			long v = strtol(hx, &e, 16);
			if (*e || v <= 0)
				return mio_fail(g->c, "buffer %ld: bad percent escape in uri '%.200s'", bi, uri);
			ch = (int)v;
			i += 2;
		}
		if (k + 1 >= sizeof rel || ch == 0 || ch == '\\')
			return mio_fail(g->c, "buffer %ld: uri '%.200s' is too long or has a NUL or backslash", bi, uri);
		rel[k++] = (char)ch;
	}
	rel[k] = '\0';
	if (rel[0] == '/' || strchr(rel, ':') || !strcmp(rel, "..") || !strncmp(rel, "../", 3) || strstr(rel, "/../")
	    || (k >= 3 && !strcmp(rel + k - 3, "/..")) || k == 0)
		return mio_fail(g->c, "buffer %ld: uri '%.200s' is not a relative path below the file's directory (refused)", bi, uri);
	if ((size_t)snprintf(path, sizeof path, "%s/%s", g->c->dir, rel) >= sizeof path)
		return mio_fail(g->c, "buffer %ld: path too long", bi);
	sub = *g->c;
	if (mio_slurp(&sub, path, &b->data, &b->len) != 0)
		return -1;
	b->owned = 1;
	g->inbytes += b->len;
	if (g->inbytes > MESH_MAX_FILE)
		return mio_fail(g->c, "buffer %ld: the external buffers total more than %zu bytes", bi, MESH_MAX_FILE);
	return 0;
}

static int buffer(gltf *g, long long bi, const unsigned char **data, size_t *len)
{
	const cJSON *bo = gl_top(g, "buffers", "buffer", bi), *u;
	long long bl;
	gbuf *b;
	if (!bo)
		return -1;
	b = &g->bufs[bi];
	if (gl_jint(g, bo, "buffer", (long)bi, "byteLength", -1, 1, (long long)MESH_MAX_FILE, &bl) != 0)
		return -1;
	if (!b->state) {
		u = gl_item(bo, "uri");
		if (u && !cJSON_IsString(u))
			return mio_fail(g->c, "buffer %lld: 'uri' must be a string", bi);
		if (!u) {
			if (!g->glb || bi != 0)
				return mio_fail(g->c, "buffer %lld has no uri (only buffer 0 of a .glb may refer to its BIN chunk)", bi);
			if (!g->bin)
				return mio_fail(g->c, "buffer 0 refers to the BIN chunk, but the .glb has none");
			b->data = (unsigned char *)g->bin;
			b->len = g->binlen;
		} else if (!strncmp(u->valuestring, "data:", 5)) {
			const char *s = strstr(u->valuestring, ";base64,");
			if (!s || strchr(u->valuestring, ',') < s)
				return mio_fail(g->c, "buffer %lld: a data: URI that is not base64", bi);
			if (base64(g, (long)bi, s + 8, strlen(s + 8), b) != 0)
				return -1;
		} else if (external(g, (long)bi, u->valuestring, b) != 0)
			return -1;
		b->state = 1;
	}
	if ((unsigned long long)bl > b->len)
		return mio_fail(g->c, "buffer %lld: byteLength %lld, but only %zu bytes are there", bi, bl, b->len);
	*data = b->data;
	*len = (size_t)bl;
	return 0;
}

/* bufferView v: its bytes and stride (0 when not given). */
static int view(gltf *g, long long vi, const unsigned char **data, size_t *len, size_t *stride)
{
	const cJSON *vo = gl_top(g, "bufferViews", "bufferView", vi);
	const unsigned char *bd = NULL;
	size_t bl = 0;
	long long b, off, n, st;
	if (!vo || gl_jint(g, vo, "bufferView", (long)vi, "buffer", -1, 0, 1 << 20, &b) != 0
	    || gl_jint(g, vo, "bufferView", (long)vi, "byteOffset", 0, 0, (long long)MESH_MAX_FILE, &off) != 0
	    || gl_jint(g, vo, "bufferView", (long)vi, "byteLength", -1, 1, (long long)MESH_MAX_FILE, &n) != 0
	    || gl_jint(g, vo, "bufferView", (long)vi, "byteStride", 0, 0, 252, &st) != 0)
		return -1;
	if (st && (st < 4 || st % 4))
		return mio_fail(g->c, "bufferView %lld: byteStride %lld (must be a multiple of 4 in [4, 252])", vi, st);
	if (buffer(g, b, &bd, &bl) != 0)
		return -1;
	if ((unsigned long long)off + (unsigned long long)n > bl)
		return mio_fail(g->c, "bufferView %lld: bytes [%lld, %lld) outside buffer %lld (%zu bytes)", vi, off, off + n, b, bl);
	*data = bd + off;
	*len = (size_t)n;
	*stride = (size_t)st;
	return 0;
}

/* ---- accessors ---------------------------------------------------------- */

static size_t csize(long long ct)
{
	return ct == GL_BYTE || ct == GL_UBYTE ? 1 : ct == GL_SHORT || ct == GL_USHORT ? 2 : 4;
}

/* One component, little-endian, converted exactly to double (normalized
   integers decoded per the glTF spec). */
static double comp(const unsigned char *p, long long ct, int norm)
{
	uint32_t u;
	float f;
	switch (ct) {
	case GL_BYTE: {
		int v = p[0] < 128 ? p[0] : (int)p[0] - 256;
		return norm ? fmax(v / 127.0, -1.0) : v;
	}
	case GL_UBYTE: return norm ? p[0] / 255.0 : p[0];
	case GL_SHORT: {
		int v = (int)((unsigned)p[0] | (unsigned)p[1] << 8);
		if (v >= 32768) v -= 65536;
		return norm ? fmax(v / 32767.0, -1.0) : v;
	}
	case GL_USHORT: {
		unsigned v = (unsigned)p[0] | (unsigned)p[1] << 8;
		return norm ? v / 65535.0 : v;
	}
	case GL_UINT:
		return (double)((uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24);
	default:
		u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
		memcpy(&f, &u, sizeof f);
		return (double)f;
	}
}


/* Is componentType ct (normalized or not) allowed for this use? */
static const char *ct_ok(int use, long long ct, int norm)
{
	if (use == ACC_NORMAL)
		return ct == GL_FLOAT || ((ct == GL_BYTE || ct == GL_SHORT) && norm) ? NULL
		       : "NORMAL must be FLOAT, or normalized BYTE or SHORT (KHR_mesh_quantization)";
	if (use == ACC_POSITION)
		return ct == GL_FLOAT || ct == GL_BYTE || ct == GL_UBYTE || ct == GL_SHORT || ct == GL_USHORT ? NULL
		       : "POSITION must be FLOAT, BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT";
	return (ct == GL_UBYTE || ct == GL_USHORT || ct == GL_UINT) && !norm ? NULL
	       : "indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, not normalized";
}

/* Copies count elements of nc components from (data, stride) into out,
   after checking they fit in len bytes from offset. */
static int span(gltf *g, const char *what, long long ai, const unsigned char *data, size_t len, size_t off,
                size_t stride, size_t count, int nc, long long ct, int norm, double *out)
{
	const size_t es = (size_t)nc * csize(ct);
	size_t i;
	int k;
	if (stride == 0)
		stride = es;
	if (stride < es)
		return mio_fail(g->c, "accessor %lld: byteStride %zu is less than its element (%zu bytes)", ai, stride, es);
	if (off > len || count > (len - off) / stride + 1 || (count && off + (count - 1) * stride + es > len))
		return mio_fail(g->c, "accessor %lld: %s of %zu elements from byte %zu does not fit in its bufferView (%zu bytes)",
		                ai, what, count, off, len);
	for (i = 0; i < count; i++)
		for (k = 0; k < nc; k++)
			out[i * (size_t)nc + (size_t)k] = comp(data + off + i * stride + (size_t)k * csize(ct), ct, norm);
	return 0;
}

static int sparse(gltf *g, long long ai, const cJSON *sp, size_t count, int nc, long long ct, int norm, double *out);

/* Accessor ai for `use`: *count elements of 3 (or 1, for indices) doubles
   in *out (malloc'ed).  *ctype: its componentType. */
int gl_accessor(gltf *g, long long ai, int use, double **out, size_t *count, long long *ctype)
{
	static const char *uses[] = { "NORMAL", "POSITION", "indices" };
	const cJSON *ao = gl_top(g, "accessors", "accessor", ai), *ty, *nm, *sp;
	long long bv, off, ct, n;
	int norm, nc = use == ACC_INDEX ? 1 : 3;
	const char *why;
	size_t limit = (size_t)MESH_MAX_ITEMS;
	*out = NULL;
	if (!ao || gl_jint(g, ao, "accessor", (long)ai, "bufferView", -2, -2, 1 << 30, &bv) != 0
	    || gl_jint(g, ao, "accessor", (long)ai, "byteOffset", 0, 0, (long long)MESH_MAX_FILE, &off) != 0
	    || gl_jint(g, ao, "accessor", (long)ai, "componentType", -1, 5120, 5126, &ct) != 0
	    || gl_jint(g, ao, "accessor", (long)ai, "count", -1, 1, (long long)MESH_MAX_ITEMS, &n) != 0)
		return -1;
	ty = gl_item(ao, "type");
	nm = gl_item(ao, "normalized");
	if (nm && !cJSON_IsBool(nm))
		return mio_fail(g->c, "accessor %lld: 'normalized' must be true or false", ai);
	norm = cJSON_IsTrue(nm);
	if (!cJSON_IsString(ty) || strcmp(ty->valuestring, use == ACC_INDEX ? "SCALAR" : "VEC3"))
		return mio_fail(g->c, "accessor %lld (%s): type must be \"%s\"", ai, uses[use], use == ACC_INDEX ? "SCALAR" : "VEC3");
	if ((why = ct_ok(use, ct, norm)) != NULL)
		return mio_fail(g->c, "accessor %lld: componentType %lld%s: %s", ai, ct, norm ? " normalized" : "", why);
	/* memory bounded by the input: at most 16 values per byte read */
	if (g->inbytes < limit / 16)
		limit = 16 * g->inbytes + 4096;
	if ((size_t)n > limit)
		return mio_fail(g->c, "accessor %lld: count %lld is more than this file can hold (%zu)", ai, n, limit);
	*out = mio_calloc((size_t)n, (size_t)nc * sizeof **out);
	if (!*out)
		return mio_fail(g->c, "accessor %lld: out of memory for %lld elements", ai, n);
	if (bv >= 0) {
		const unsigned char *d;
		size_t len, st;
		if (view(g, bv, &d, &len, &st) != 0
		    || span(g, "data", ai, d, len, (size_t)off, st, (size_t)n, nc, ct, norm, *out) != 0)
			goto bad;
	}
	sp = gl_item(ao, "sparse");
	if (sp && sparse(g, ai, sp, (size_t)n, nc, ct, norm, *out) != 0)
		goto bad;
	*count = (size_t)n;
	*ctype = ct;
	return 0;
bad:
	free(*out);
	*out = NULL;
	return -1;
}

static int sparse(gltf *g, long long ai, const cJSON *sp, size_t count, int nc, long long ct, int norm, double *out)
{
	const cJSON *io = gl_item(sp, "indices"), *vo = gl_item(sp, "values");
	long long n, ibv, ioff, ict, vbv, voff;
	const unsigned char *d;
	size_t len, st, i;
	double *idx = NULL, *val = NULL;
	int rc = -1;
	if (!cJSON_IsObject(sp) || !cJSON_IsObject(io) || !cJSON_IsObject(vo))
		return mio_fail(g->c, "accessor %lld: sparse needs objects 'indices' and 'values'", ai);
	if (gl_jint(g, sp, "sparse of accessor", (long)ai, "count", -1, 1, (long long)count, &n) != 0
	    || gl_jint(g, io, "sparse.indices of accessor", (long)ai, "bufferView", -1, 0, 1 << 30, &ibv) != 0
	    || gl_jint(g, io, "sparse.indices of accessor", (long)ai, "byteOffset", 0, 0, (long long)MESH_MAX_FILE, &ioff) != 0
	    || gl_jint(g, io, "sparse.indices of accessor", (long)ai, "componentType", -1, 5120, 5126, &ict) != 0
	    || gl_jint(g, vo, "sparse.values of accessor", (long)ai, "bufferView", -1, 0, 1 << 30, &vbv) != 0
	    || gl_jint(g, vo, "sparse.values of accessor", (long)ai, "byteOffset", 0, 0, (long long)MESH_MAX_FILE, &voff) != 0)
		return -1;
	if (ct_ok(ACC_INDEX, ict, 0))
		return mio_fail(g->c, "accessor %lld: sparse indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT", ai);
	idx = mio_calloc((size_t)n, sizeof *idx);
	val = mio_calloc((size_t)n, (size_t)nc * sizeof *val);
	if (!idx || !val) {
		mio_fail(g->c, "accessor %lld: out of memory", ai);
		goto out;
	}
	/* byteStride does not apply to sparse data: tightly packed */
	if (view(g, ibv, &d, &len, &st) != 0 || span(g, "sparse indices", ai, d, len, (size_t)ioff, 0, (size_t)n, 1, ict, 0, idx) != 0
	    || view(g, vbv, &d, &len, &st) != 0 || span(g, "sparse values", ai, d, len, (size_t)voff, 0, (size_t)n, nc, ct, norm, val) != 0)
		goto out;
	for (i = 0; i < (size_t)n; i++) {
		if (!(idx[i] < (double)count) || (i && !(idx[i] > idx[i - 1]))) {
			mio_fail(g->c, "accessor %lld: sparse index %zu is %.0f (indices must increase and be below count %zu)", ai, i, idx[i], count);
			goto out;
		}
		memcpy(out + (size_t)idx[i] * (size_t)nc, val + i * (size_t)nc, (size_t)nc * sizeof *val);
	}
	rc = 0;
out:
	free(idx);
	free(val);
	return rc;
}
