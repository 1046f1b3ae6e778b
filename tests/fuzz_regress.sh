#!/bin/sh
# The libFuzzer harnesses (tests/fuzz/fuzz_*.c) as plain programs, built
# with the ordinary compiler and tests/fuzz/replay.c: every seed in
# tests/fuzz/corpus/<harness>/ and every crash input kept in
# tests/fuzz/regressions/<harness>/ must run to the end (no abort, no
# sanitizer report under `make test SANITIZE=...`).  scripts/fuzz.sh does
# the fuzzing itself, with clang.
. "$(dirname "$0")/lib.sh"
CC=${CC:-cc}
for h in mesh gltf cli; do
	bin="$tmp/replay_$h"
	# shellcheck disable=SC2086
	if $CC -std=c99 -O1 -g $SAN -Wall -Wextra -Wpedantic -Wshadow -D_POSIX_C_SOURCE=200809L -Iinclude -Isrc \
	     -o "$bin" tests/fuzz/fuzz_$h.c tests/fuzz/replay.c build/libstudy.a libonb.a \
	     -fopenmp -Wl,-Bstatic -lmpfi -lmpfr -lgmp -Wl,-Bdynamic -lcjson -lm 2> "$tmp/cc_$h"; then
		ok
	else
		bad "cannot build the $h replay: $(cat "$tmp/cc_$h")"; continue
	fi
	[ -s "$tmp/cc_$h" ] && bad "warnings building the $h harness: $(cat "$tmp/cc_$h")"
	nseed=$(find tests/fuzz/corpus/$h -type f ! -name '.*' | wc -l)
	nreg=$(find tests/fuzz/regressions/$h -type f ! -name '.*' | wc -l)
	[ "$nseed" -ge 5 ] && ok || bad "tests/fuzz/corpus/$h has only $nseed seeds"
	# an empty scratch directory: the cli harness reaches only names in it
	mkdir -p "$tmp/cwd_$h"
	(cd "$tmp/cwd_$h" && "$bin" -v "$root/tests/fuzz/corpus/$h" "$root/tests/fuzz/regressions/$h") > "$tmp/out_$h" 2> "$tmp/err_$h"
	rc=$?
	if [ $rc -eq 0 ] && grep -q "^replay: $((nseed + nreg)) inputs, no finding" "$tmp/out_$h"; then
		ok; echo "$h: $nseed seeds, $nreg regressions: $(tail -1 "$tmp/out_$h")"
	else
		bad "$h replay exited $rc; last input and report:"
		grep '^replay: ' "$tmp/err_$h" | tail -1
		grep -v '^onbstudy: ' "$tmp/err_$h" | tail -20
	fi
	[ -z "$(ls -A "$tmp/cwd_$h")" ] && ok || bad "$h harness wrote files: $(ls -A "$tmp/cwd_$h")"
done
finish
