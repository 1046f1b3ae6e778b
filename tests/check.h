/*
 * check.h - the counting check of every C test (tests/test_*.c), the C
 * side of tests/lib.sh:
 *   CHECK(cond, fmt, ...)  count a pass, or count a failure and print
 *                          "FAIL file:line: " and the message (printf's)
 *   check_finish(name)     print "[name: ]P passed, F failed" and return
 *                          main's exit status: 0 when no check failed
 * Define CHECK_MAX_REPORTS before the include to print only the first N
 * failures (they are all counted).
 */
#ifndef ONB_TESTS_CHECK_H
#define ONB_TESTS_CHECK_H
#include <limits.h>
#include <stdio.h>

#ifndef CHECK_MAX_REPORTS
#define CHECK_MAX_REPORTS INT_MAX
#endif

static int passed, failed;

#define CHECK(cond, ...) do { \
	if (cond) \
		passed++; \
	else if (++failed <= CHECK_MAX_REPORTS) { \
		printf("FAIL %s:%d: ", __FILE__, __LINE__); \
		printf(__VA_ARGS__); \
		printf("\n"); \
	} \
} while (0)

static inline int check_finish(const char *name)
{
	if (name)
		printf("%s: ", name);
	printf("%d passed, %d failed\n", passed, failed);
	return failed != 0;
}
#endif
