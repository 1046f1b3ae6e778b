#!/bin/sh
# function-lengths.sh [MAX] - the C functions in src/ longer than MAX lines
# (default 100; issue 13's "no function longer than about 100 lines"), from
# a function's opening brace in column 0 to its closing one.  Exit 1 if any.
cd "$(dirname "$0")/.."
awk -v max="${1:-100}" '
	/^[a-zA-Z].*\(/ && !/;[ \t]*$/ { cand = $0; line = FNR }
	/^\{/ { start = FNR; name = cand; at = line }
	/^\}/ && start { n = FNR - start; if (n > max) { printf "%5d lines  %s:%d  %s\n", n, FILENAME, at, name; found = 1 } start = 0 }
	END { exit found }' src/*/*.c
