#!/bin/sh
# function_lengths.sh - no C function in src/, include/, tests/ or examples/
# is longer than 100 lines (scripts/function-lengths.sh), and the check
# itself sees a function of 101 lines and lets one of 100 pass.
. "$(dirname "$0")/lib.sh"
long=$(sh scripts/function-lengths.sh 100) && ok || bad "functions over 100 lines: $long"
fn() { # NAME BODY_LINES: a C function whose braces are BODY_LINES + 1 lines apart
	printf 'static int %s(void)\n{\n\tint x = 0;\n' "$1"
	i=2; while [ $i -lt "$2" ]; do echo '	x++;'; i=$((i + 1)); done
	printf '\treturn x;\n}\n\n'
}
{ fn fits 99; fn toolong 100; } > "$tmp/probe.c"
out=$(sh scripts/function-lengths.sh 100 "$tmp/probe.c"); rc=$?
[ $rc -eq 1 ] && [ "$(echo "$out" | wc -l)" -eq 1 ] && echo "$out" | grep -q '101 lines .*toolong' && ok ||
	bad "the check on a 100- and a 101-line function: exit $rc, '$out'"
finish function_lengths
