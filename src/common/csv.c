/*
 * csv.c - the study's CSV files read back (csv.h).
 */
#include <string.h>
#include "common/csv.h"

int csv_split(char *line, char **f, int maxf, int quotes)
{
	int n = 0;
	char *p = line;
	line[strcspn(line, "\r\n")] = '\0';
	while (n < maxf) {
		if (quotes && *p == '"') {
			char *q = ++p;
			f[n++] = p;
			while (*q && *q != '"')
				q++;
			if (*q == '"')
				*q++ = '\0';
			p = q;
		} else {
			f[n++] = p;
		}
		while (*p && *p != ',')
			p++;
		if (*p != ',')
			break;
		*p++ = '\0';
	}
	return n;
}

int csv_col(char *const *h, int nh, const char *name)
{
	int i;
	for (i = 0; i < nh; i++)
		if (strcmp(h[i], name) == 0)
			return i;
	return -1;
}
