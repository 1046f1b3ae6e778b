#!/bin/sh
# function-lengths.sh [MAX [FILE...]] - the C functions longer than MAX
# lines (default 100: a function a reader can hold at once), counted from
# a function's opening brace in column 0 to its closing one.  The files:
# those named, or every .c, .h and .inc file under src/, include/, tests/
# and examples/.  Prints the long ones, then exits 1 if there is any.
# make test runs it (tests/function_lengths.sh).
max=${1:-100}
[ $# -gt 0 ] && shift
if [ $# -gt 0 ]; then
	files="$*"
else
	cd "$(dirname "$0")/.." || exit 2
	files=$(find src include tests examples -type f \( -name '*.c' -o -name '*.h' -o -name '*.inc' \) | LC_ALL=C sort)
fi
[ -n "$files" ] || { echo "function-lengths: no C files found" >&2; exit 2; }
# shellcheck disable=SC2086
awk -v max="$max" '
	FNR == 1 { start = 0 }
	/^[a-zA-Z].*\(/ && !/;[ \t]*$/ { cand = $0; line = FNR }
	/^\{/ { start = FNR; name = cand; at = line }
	/^\}/ && start { n = FNR - start; if (n > max) { printf "%5d lines  %s:%d  %s\n", n, FILENAME, at, name; found = 1 } start = 0 }
	END { exit found }' $files
