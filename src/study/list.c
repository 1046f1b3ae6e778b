/*
 * list.c - `onbstudy list`: the registry, as a table or CSV.
 */
#include <string.h>
#include "study.h"

int cmd_list(int argc, char **argv)
{
	size_t n, i;
	const onb_method *m = onb_methods(&n);
	int csv = 0, k;
	for (k = 0; k < argc; k++) {
		if (strcmp(argv[k], "--format=csv") == 0 || (strcmp(argv[k], "--format") == 0 && k + 1 < argc && strcmp(argv[k + 1], "csv") == 0)) {
			csv = 1;
			if (argv[k][8] != '=')
				k++;
		} else if (strcmp(argv[k], "--format=table") == 0) {
			csv = 0;
		} else if (strcmp(argv[k], "--format") == 0 && k + 1 < argc && strcmp(argv[k + 1], "table") == 0) {
			csv = 0;
			k++;
		} else if (strcmp(argv[k], "--format") == 0 || strncmp(argv[k], "--format=", 9) == 0) {
			const char *v = argv[k][8] == '=' ? argv[k] + 9 : k + 1 < argc ? argv[k + 1] : NULL;
			if (v)
				study_error("list: --format must be table or csv, got '%s'", v);
			else
				study_error("list: --format needs a value (table or csv)");
			return ONB_EXIT_USAGE;
		} else if (strcmp(argv[k], "--help") == 0 || strcmp(argv[k], "-h") == 0) {
			printf("usage: onbstudy list [--format table|csv]\n"
			       "  The methods in the registry: name, handedness, singular directions, source.\n");
			return 0;
		} else {
			study_error("list: unknown argument '%s' (try --format table|csv)", argv[k]);
			return ONB_EXIT_USAGE;
		}
	}
	if (csv) {
		printf("name,family,handedness,flags,threshold,source,singular,thresholds\n");
		for (i = 0; i < n; i++)
			printf("%s,%s,%+d,%u,%a,\"%s\",\"%s\",\"%s\"\n", m[i].name, m[i].family, m[i].handedness,
			       m[i].flags, m[i].threshold, m[i].source, m[i].singular, m[i].thresholds);
		return 0;
	}
	printf("# %zu methods; batch kernels run %s; hardware rsqrt: %s\n", n, onb_batch_isa(),
	       ONB_HAVE_HW_RSQRT ? "rsqrtss/rsqrtps" : "absent (the _rsqrt variants fell back to 1/sqrt)");
	printf("%-24s %4s  %-52s %s\n", "name", "hand", "singular directions", "source");
	for (i = 0; i < n; i++)
		printf("%-24s %+4d  %-52s %s%s\n", m[i].name, m[i].handedness, m[i].singular, m[i].source,
		       (m[i].flags & ONB_FELL_BACK) ? " [FELL BACK: no hardware rsqrt]" :
		       (m[i].flags & ONB_FLOAT_ONLY) ? " [float only]" : "");
	return 0;
}
