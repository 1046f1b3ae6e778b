/*
 * test_certify_keys.c - certify's keys (src/certify/keys.c) follow the
 * model: the same method gives the same key twice; its model with another
 * registry row (frisvad with frisvad_max's parameters), with another
 * family's operations (frisvad's row run by duff's model), contracted, or
 * in the other precision gives another key; and so does its kernel
 * replaced by another's with the model kept (the found side's measure).
 * tests/certify_resume.sh shows that --reuse recomputes a method whose
 * key changed and re-uses the others.
 */
#include <stdio.h>
#include <string.h>
#include "certify/keys.h"
#include "check.h"

int main(void)
{
	const cm_method *fr = cm_find("frisvad"), *fm = cm_find("frisvad_max"), *du = cm_find("duff");
	study_kernel k[2];
	cert_ctx *x = cert_ctx_new();
	cm_method m;
	uint64_t key, again;
	if (!fr || !fm || !du || !x || kernels_select("frisvad,duff", 0, k, 2) != 2) {
		printf("FAIL: no frisvad, frisvad_max or duff model, or no context\n");
		return 1;
	}
	key = cert_method_key(x, &k[0], fr, PREC_FLOAT);
	again = cert_method_key(x, &k[0], fr, PREC_FLOAT);
	CHECK(key != 0 && key == again, "frisvad float: %016llx then %016llx", (unsigned long long)key, (unsigned long long)again);
	m = *fr;
	m.m = fm->m;   /* another registry row: the model's parameters */
	CHECK(cert_method_key(x, &k[0], &m, PREC_FLOAT) != key, "frisvad's model with frisvad_max's row: the same key");
	m = *fr;
	m.fam = du->fam;   /* another operation sequence */
	CHECK(cert_method_key(x, &k[0], &m, PREC_FLOAT) != key, "frisvad's row with duff's model: the same key");
	m = *fr;
	m.contract = 1;
	CHECK(cert_method_key(x, &k[0], &m, PREC_FLOAT) != key, "frisvad's model contracted: the same key");
	CHECK(cert_method_key(x, &k[0], fr, PREC_DOUBLE) != key, "frisvad in double: the same key as in float");
	memcpy(k[1].name, k[0].name, sizeof k[1].name);   /* duff's kernel under frisvad's name and model */
	CHECK(cert_method_key(x, &k[1], fr, PREC_FLOAT) != key, "frisvad's model with duff's kernel: the same key");
	cert_ctx_free(x);
	return check_finish("test_certify_keys");
}
