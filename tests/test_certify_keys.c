/*
 * test_certify_keys.c - certify's keys (src/certify/keys.c) follow the
 * model: the same method gives the same key twice; its model with another
 * registry row (frisvad with frisvad_max's parameters), with another
 * family's operations (frisvad's row run by duff's model), contracted, or
 * in the other precision gives another key; and so does its kernel
 * replaced by another's with the model kept (the found side's measure).
 * The code keys (scripts/code-keys.sh): every method has a checksum of
 * its compiled kernel in each precision it runs and of its family's
 * model, distinct between methods and precisions; a key takes them (the
 * same kernel and model under another method's code checksums, kernel or
 * family, give another key).  tests/certify_resume.sh shows that --reuse
 * recomputes a method whose key changed and re-uses the others, and that
 * a kernel compiled anew with one constant changed makes exactly its
 * method stale.
 */
#include <stdio.h>
#include <string.h>
#include "certify/keys.h"
#include "check.h"

/* Every method's code checksums, and a key that follows them. */
static void code_checks(cert_ctx *x, const study_kernel *fk, const cm_method *fr, uint64_t key)
{
	static study_kernel all[256];
	study_kernel k = *fk;
	study_family fam;
	onb_method om;
	int n = kernels_select("all", 0, all, 256), i, p;
	CHECK(n > 10, "kernels_select(all): %d", n);
	for (i = 0; i < n; i++) {
		const char *fn = all[i].fam ? all[i].fam->name : all[i].name;
		CHECK(cert_code_sum("family", fn, 0) != 0, "%s: no checksum of its family %s's model", all[i].name, fn);
		for (p = PREC_FLOAT; p <= PREC_DOUBLE && all[i].m; p++)
			if (kernel_runs(&all[i], p))
				CHECK(cert_code_sum("kernel", all[i].m->name, p) != 0, "%s %s: no checksum of its kernel",
				      all[i].name, prec_name(p));
	}
	CHECK(cert_code_sum("direction", "", 0) != 0 && cert_code_sum("fma", "", 0) != 0, "no direction or fma checksum");
	CHECK(cert_code_sum("kernel", "frisvad", PREC_FLOAT) != cert_code_sum("kernel", "rtow", PREC_FLOAT),
	      "frisvad and rtow: the same kernel checksum");
	CHECK(cert_code_sum("kernel", "rtow", PREC_FLOAT) != cert_code_sum("kernel", "rtow", PREC_DOUBLE),
	      "rtow: the same kernel checksum in float and double");
	CHECK(cert_code_sum("family", "frisvad", 0) != cert_code_sum("family", "duff", 0), "frisvad and duff: the same model checksum");
	om = *k.m;   /* frisvad's kernel and model, rtow's kernel checksum */
	om.name = "rtow";
	k.m = &om;
	CHECK(cert_method_key(x, &k, fr, PREC_FLOAT) != key, "frisvad with rtow's kernel checksum: the same key");
	k = *fk;     /* ... duff's family checksum */
	fam = *k.fam;
	fam.name = "duff";
	k.fam = &fam;
	CHECK(cert_method_key(x, &k, fr, PREC_FLOAT) != key, "frisvad with duff's model checksum: the same key");
	k = *fk;
	CHECK(cert_method_key(x, &k, fr, PREC_FLOAT) == key, "frisvad's key changed on a copy of its kernel");
}

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
	code_checks(x, &k[0], fr, key);
	cert_ctx_free(x);
	return check_finish("test_certify_keys");
}
