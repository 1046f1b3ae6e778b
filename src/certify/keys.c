/*
 * keys.c - the keys of certify's results (keys.h).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <mpfr.h>
#include "keys.h"
#include "common/output.h"
#include "inputs/rng.h"
#include "model/model_int.h"
#include "common/prec.h"

#ifndef ONB_CERT_ENGINE
#define ONB_CERT_ENGINE "unknown"
#endif

/* Inputs per precision the key runs the model and the kernel on. */
#define KEY_INPUTS 96

uint64_t cert_hash_bytes(uint64_t h, const void *p, size_t n)
{
	const unsigned char *c = p;
	size_t i;
	for (i = 0; i < n; i++)
		h = (h ^ c[i]) * UINT64_C(0x100000001b3);
	return h;
}

uint64_t cert_hash_str(uint64_t h, const char *s)
{
	return cert_hash_bytes(h, s, strlen(s) + 1);
}

static uint64_t hash_double(uint64_t h, double v)
{
	return cert_hash_bytes(h, &v, sizeof v);
}

static uint64_t hash_int(uint64_t h, long v)
{
	return cert_hash_bytes(h, &v, sizeof v);
}

/* The checksums of the compiled kernels and models (the Makefile:
   scripts/code-keys.sh writes code_keys.h, -DONB_CODE_KEYS; a build
   without them, scripts/fuzz.sh's, has none: every sum 0). */
typedef struct {
	const char *kind, *name;
	char prec;              /* 'd', 'f'; 0 for a family */
	unsigned long sum;
} code_key;
#define CODE_KEY(kind, name, prec, sum) { kind, name, prec, sum },
static const code_key code_keys[] = {
#ifdef ONB_CODE_KEYS
#include "code_keys.h"
#endif
	{ NULL, NULL, 0, 0 }
};
#undef CODE_KEY

unsigned long cert_code_sum(const char *kind, const char *name, int prec)
{
	const char p = prec == PREC_FLOAT ? 'f' : prec == PREC_DOUBLE ? 'd' : 0;
	const code_key *c;
	for (c = code_keys; c->kind; c++)
		if (strcmp(c->kind, kind) == 0 && strcmp(c->name, name) == 0 && (c->prec == 0 || c->prec == p))
			return c->sum;
	return 0;
}

/* Kernel k's code in precision prec, and its family's model: 0 where
   none is known. */
static uint64_t hash_code(uint64_t h, const study_kernel *k, int prec)
{
	if (k->fma)
		h = hash_int(h, (long)cert_code_sum("fma", "", 0));
	else if (!k->m)
		h = hash_int(h, (long)cert_code_sum("direction", "", 0));
	else
		h = hash_int(h, (long)cert_code_sum("kernel", k->m->name, prec));
	return hash_int(h, (long)cert_code_sum("family", k->fam ? k->fam->name : k->name, 0));
}

const char *cert_engine(void)
{
	static char s[512];
	if (!s[0])
		snprintf(s, sizeof s, "sources %s; %s; %s; mpfr %s", ONB_CERT_ENGINE, ONB_CC, ONB_CFLAGS, mpfr_get_version());
	return s;
}

/* Input i of the key's fixed set, a unit vector before rounding: the six
   axes, each pole's neighbourhood at 1 -+ n.z = 2^-j, then random. */
static void key_input(int i, double u[3])
{
	double z, phi, r;
	if (i < 6) {
		u[0] = u[1] = u[2] = 0.0;
		u[i / 2] = i % 2 ? -1.0 : 1.0;
		return;
	}
	if (i < 6 + 2 * 24) {
		const int j = (i - 6) / 2 + 1;
		z = (i % 2 ? -1.0 : 1.0) * (1.0 - ldexp(1.0, -2 * j));
		phi = 0.7 + 0.37 * j;
	} else {
		z = 2.0 * (double)(rng_mix64(UINT64_C(0x6b657973) + (uint64_t)i) >> 11) * 0x1p-53 - 1.0;
		phi = 6.283185307179586 * (double)(rng_mix64(UINT64_C(0x70686921) + (uint64_t)i) >> 11) * 0x1p-53;
	}
	r = sqrt(fmax(0.0, 1.0 - z * z));
	u[0] = r * cos(phi);
	u[1] = r * sin(phi);
	u[2] = z;
}

/* The model's run on n under CM_EXEC: every value, the flags. */
static uint64_t hash_model_run(uint64_t h, cm *c, const cm_method *m, int prec, const double n[3])
{
	cv in[3], out[6];
	int i;
	c->nonzero = c->zero_n = c->norm_n = c->zero_late = 0;
	c->cross_to = 0;
	cm_exec_begin(c, prec, n, in);
	cm_run(c, m, prec, in, out);
	h = hash_int(h, c->n);
	h = hash_int(h, c->failed);
	for (i = 0; i < c->n; i++)
		h = hash_double(h, c->x[i]);
	for (i = 0; i < 6; i++)
		h = hash_int(h, out[i]);
	h = hash_int(h, (long)c->nonzero);
	h = hash_int(h, (long)c->zero_n);
	h = hash_int(h, (long)c->norm_n);
	h = hash_int(h, (long)c->zero_late);
	return hash_int(h, c->cross_to);
}

uint64_t cert_method_key(cert_ctx *x, const study_kernel *k, const cm_method *m, int prec)
{
	uint64_t h = cert_hash_str(CERT_FNV0, k->name);
	cm *c = cm_new(CM_EXEC);
	int i, j;
	if (!c)
		return 0;
	h = hash_int(h, prec);
	h = hash_int(h, m->nbranch);
	h = hash_int(h, (long)m->zero_any_n);
	h = hash_int(h, m->contract);
	h = hash_int(h, m->direction);
	h = hash_code(h, k, prec);
	for (i = 0; i < KEY_INPUTS; i++) {
		double u[3], n[3], d;
		int nonfinite = 0;
		key_input(i, u);
		for (j = 0; j < 3; j++)
			n[j] = prec == PREC_FLOAT ? (double)(float)u[j] : u[j];
		h = hash_model_run(h, c, m, prec, n);
		d = cert_probe(x, k, prec, n, &nonfinite);
		h = hash_double(h, d);
		h = hash_int(h, nonfinite);
	}
	cm_free(c);
	return h;
}

uint64_t cert_half_key(const study_kernel *k, const cm_method *m)
{
	uint64_t h = cert_hash_str(CERT_FNV0, k->name);
	cm *c = cm_new(CM_EXEC);
	int i, j;
	if (!c)
		return 0;
	if (!k->m || !k->m->arrayh) {
		cm_free(c);
		return 0;
	}
	h = hash_int(h, PREC_HALF);
	h = hash_int(h, m->nbranch);
	h = hash_int(h, (long)m->zero_any_n);
	h = hash_int(h, m->contract);
	h = hash_int(h, (long)cert_code_sum("half", "", 0));
	h = hash_int(h, (long)cert_code_sum("family", k->fam ? k->fam->name : k->name, 0));
	for (i = 0; i < KEY_INPUTS; i++) {
		double u[3], n[3];
		uint16_t in[3], out[6];
		key_input(i, u);
		for (j = 0; j < 3; j++) {
			n[j] = prec_half_round(u[j]);
			in[j] = prec_half_bits(n[j]);
		}
		h = hash_model_run(h, c, m, PREC_HALF, n);
		k->m->arrayh(in, out, out + 3);
		h = cert_hash_bytes(h, out, sizeof out);
	}
	cm_free(c);
	return h;
}
