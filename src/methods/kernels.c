/*
 * kernels.c - selecting the kernels a study runs (see kernels.h).
 */
#include <stdio.h>
#include <string.h>
#include "methods/kernels.h"
#include "common/options.h"

/* The branch rule of the kernel's family, plain arithmetic. */
int kernels_branch(const study_kernel *k, int prec, const double n[3])
{
	return k->fam->branch(k->m, prec, n);
}

#define DIR_DEF(d) \
	static onb_vec3  plain_##d   (onb_vec3  n, double x, double y, double z) { return onb_##d(n, x, y, z); } \
	static onb_vec3f plain_##d##f(onb_vec3f n, float x, float y, float z)    { return onb_##d##f(n, x, y, z); }
STUDY_DIRECTION_LIST(DIR_DEF)
#undef DIR_DEF

static const study_direction directions[] = {
#define DIR_ROW(d) { #d, plain_##d, plain_##d##f },
	STUDY_DIRECTION_LIST(DIR_ROW)
#undef DIR_ROW
};

const study_direction *kernels_directions(size_t *count)
{
	*count = sizeof directions / sizeof directions[0];
	return directions;
}

const study_direction *kernels_direction(const char *name)
{
	size_t i;
	for (i = 0; i < sizeof directions / sizeof directions[0]; i++)
		if (strcmp(directions[i].name, name) == 0)
			return &directions[i];
	return NULL;
}

/* The message for an unknown name: every method, then every direction. */
static void unknown_method(const char *name)
{
	char all[2048];
	size_t i, n, len = 0;
	const onb_method *ms = onb_methods(&n);
	all[0] = '\0';
	for (i = 0; i < n && len + 64 < sizeof all; i++)
		len += (size_t)snprintf(all + len, sizeof all - len, "%s, ", ms[i].name);
	for (i = 0; i < sizeof directions / sizeof directions[0] && len + 64 < sizeof all; i++)
		len += (size_t)snprintf(all + len, sizeof all - len, "%s, ", directions[i].name);
	study_error("unknown method '%s' (valid: %san alias of 'onbstudy list --aliases', or all)", name, all);
}

static int add_kernel(const char *name, int fma, study_kernel *out, int cap, int *k)
{
	study_kernel *s;
	const study_direction *dir;
	const onb_method *m = onb_find(name);
	const onb_alias *al = m ? NULL : onb_find_alias(name);
	if (al) { /* an alias runs its target, under the target's name */
		name = al->target;
		m = onb_find(name);
	}
	dir = m ? NULL : kernels_direction(name);
	if (!m && !dir) {
		unknown_method(name);
		return -1;
	}
	if (*k >= cap) {
		study_error("too many methods (at most %d)", cap);
		return -1;
	}
	s = &out[(*k)++];
	memset(s, 0, sizeof *s);
	snprintf(s->name, sizeof s->name, "%s%s", name, fma ? "+fma" : "");
	s->m = m;
	s->fam = family_of(m);
	if (!s->fam) {
		study_error("method '%s': no family file knows its family '%s' (src/families/families.c)", name, m->family);
		return -1;
	}
	s->fma = fma;
	if (fma) {
		if (fma_lookup(name, &s->basis, &s->basisf, &s->rot, &s->rotf) != 0) {
			study_error("no FMA copy of '%s'", name);
			return -1;
		}
		s->branch = fma_branch;
	} else {
		if (m) {
			s->basis = m->basis;
			s->basisf = m->basisf;
		} else {
			s->rot = dir->rot;
			s->rotf = dir->rotf;
		}
		s->branch = kernels_branch;
	}
	return 0;
}

int kernels_select(const char *names, int fma, study_kernel *out, int cap)
{
	int k = 0, pass;
	for (pass = 0; pass < (fma ? 2 : 1); pass++) {
		if (!names || !strcmp(names, "all")) {
			size_t i, n;
			const onb_method *ms = onb_methods(&n);
			for (i = 0; i < n; i++)
				if (add_kernel(ms[i].name, pass, out, cap, &k) != 0)
					return -1;
			for (i = 0; i < sizeof directions / sizeof directions[0]; i++)
				if (add_kernel(directions[i].name, pass, out, cap, &k) != 0)
					return -1;
		} else {
			char buf[2048], *tok, *save = NULL;
			if (strlen(names) >= sizeof buf) {
				study_error("--methods list too long");
				return -1;
			}
			strcpy(buf, names);
			for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save))
				if (add_kernel(tok, pass, out, cap, &k) != 0)
					return -1;
			if (k == 0) {
				study_error("--methods: empty list");
				return -1;
			}
		}
	}
	return k;
}
