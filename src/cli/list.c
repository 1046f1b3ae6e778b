/*
 * list.c - `onbstudy list`: the registry, as a table or CSV.
 */
#include <string.h>
#include "cli/list.h"
#include "cli/cli.h"

int cmd_list(int argc, char **argv)
{
	static const struct option lo[] = {
		{ "format", required_argument, NULL, 'f' }, CLI_HELP_OPTION, { NULL, 0, NULL, 0 }
	};
	size_t n, i;
	const onb_method *m = onb_methods(&n);
	int csv = 0, v, rc = 0;
	cli_args c;
	if (cli_begin(&c, "list", argc, argv))
		return 1;
	while (rc == 0 && (v = cli_next(&c, lo)) != -1) {
		if (v == CLI_HELP) {
			printf("usage: onbstudy list [--format table|csv]\n"
			       "  The methods in the registry: name, handedness, singular directions, source.\n");
			rc = -1;
		} else if (v != 'f' || (csv = cli_format("--format", c.arg, 0)) < 0) {
			rc = ONB_EXIT_USAGE;
		}
	}
	if (rc == 0 && cli_no_rest(&c) != 0)
		rc = ONB_EXIT_USAGE;
	cli_end(&c);
	if (rc)
		return rc < 0 ? 0 : rc;
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
