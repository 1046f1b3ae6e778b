#!/bin/sh
# mutate.sh - mutation testing of include/libonb/onb.h's kernels.
#   sh scripts/mutate.sh [--jobs N] [--out FILE] [--limit SECONDS] [--list FILE]
# Lists every one-token mutation of the kernels (scripts/mutants.awk:
# numeric constants, comparisons, signs, float/double conversions, swapped
# cross-product operands, in every method and precision), and for each one
# builds tests/test_indep.c alone against the mutated header
# (-DINDEP_INLINE_ONLY, the library's floating-point flags; the test's
# driver is compiled once with -DINDEP_SPLIT, and each mutant rebuilds only
# its method table, tests/indep_lib.c, which holds the inline kernels) and
# runs it with --quick.  A mutant
#   changed  when some output bit of some method differs from the
#            unmutated header's on the test's inputs (the test prints a
#            hash of every output; compared with the baseline's);
#            (a mutant whose object file is byte for byte the unmutated
#            one's is the same program: unchanged, and not run);
#   caught   when the test fails (exit non-zero, or killed after 60 s);
#            it stops at the first differing method (INDEP_STOP_EARLY),
#            and runs the mutated function's methods first (INDEP_FIRST),
#            and a caught mutant counts as changed: the unmutated header
#            passes, so the failure means an output bit changed.
# Prints tried / compiled / changed / caught, the survivors (changed and
# not caught) and writes the counts as key: value lines to FILE (default
# stdout only).  Exits 1 when a changed mutant survives, when the
# unmutated build fails, or when the whole run exceeds --limit seconds
# (default 0: no limit).  Mutants run --jobs at a time (default 2).
# --list FILE writes every mutant's row (index, kind, function, line:col,
# compiled, changed, caught, the mutated line): two runs' kill lists
# compare with  awk -F'\t' '$7 == 1 { print $1 }' FILE.
set -u
cd "$(dirname "$0")/.."
JOBS=2; OUT=; LIMIT=0; LIST=
while [ $# -gt 0 ]; do
	case $1 in
	--jobs) JOBS=$2; shift 2 ;;
	--out) OUT=$2; shift 2 ;;
	--limit) LIMIT=$2; shift 2 ;;
	--list) LIST=$2; shift 2 ;;
	--one) shift; break ;;   # internal: one mutant (DIR INDEX)
	*) echo "usage: sh scripts/mutate.sh [--jobs N] [--out FILE] [--limit SECONDS] [--list FILE]" >&2; exit 2 ;;
	esac
done
CC=${CC:-cc}
FLAGS="-std=c99 -O1 -ffp-contract=off -fno-math-errno -fno-trapping-math -DINDEP_INLINE_ONLY -Itests"

# One mutant: DIR INDEX -> DIR/res/INDEX = "index kind where line:col compiled changed caught"
one() {
	d=$1; i=$2
	site=$(sed -n "${i}p" "$d/list")
	ln=$(printf '%s\n' "$site" | cut -f1); col=$(printf '%s\n' "$site" | cut -f2)
	len=$(printf '%s\n' "$site" | cut -f3); rep=$(printf '%s\n' "$site" | cut -f4)
	kind=$(printf '%s\n' "$site" | cut -f5); where=$(printf '%s\n' "$site" | cut -f6)
	w="$d/m$i"; mkdir -p "$w/libonb"
	awk -v L="$ln" -v C="$col" -v N="$len" -v R="$rep" \
		'NR == L { $0 = substr($0, 1, C - 1) R substr($0, C + N) } { print }' include/libonb/onb.h > "$w/libonb/onb.h"
	compiled=0; changed=0; caught=0
	# the mutated function's own methods (onb_duff_compf -> duff_comp,
	# duff...; ONB__OSL_ORTHO -> osl_ortho): they run first below, and a
	# function's (not a macro's: its text is checked only where expanded)
	# are first tried alone: a table of their rows, a sixth of the full
	# table's compile; a failure there is a failure of the full test (the
	# same code on the same inputs), anything else goes on to the full test
	first=$(printf '%s\n' "$where" | sed 's/^[Oo][Nn][Bb]_*//' | tr 'A-Z' 'a-z')
	case $where in
	onb_*) awk -F'\t' -v k="$first" -f scripts/mutate-rows.awk "$d/rows" > "$w/rows" ;;
	*) : > "$w/rows" ;;
	esac
	if [ -s "$w/rows" ] &&
	   { echo '#include "libonb/onb.h"'; echo '#include "indep.h"'; echo 'static const indep_row R[] = {';
	     cat "$w/rows"; echo '};'; echo 'const indep_row *indep_rows(size_t *n);';
	     echo 'const indep_row *indep_rows(size_t *n) { *n = sizeof R / sizeof R[0]; return R; }'; } > "$w/p1.c" &&
	   $CC $FLAGS -I"$w" -c -o "$w/p1.o" "$w/p1.c" 2>/dev/null &&
	   $CC -o "$w/t1" "$d/driver.o" "$w/p1.o" "$d/fdlibm.o" -lm 2>/dev/null &&
	   ! INDEP_PARTIAL=1 INDEP_STOP_EARLY=1 timeout 60 "$w/t1" --quick > "$w/out1" 2>&1; then
		compiled=1; changed=1; caught=1
	elif $CC $FLAGS -I"$w" -c -o "$w/lib.o" tests/indep_lib.c 2>/dev/null && cmp -s "$w/lib.o" "$d/lib.o"; then
		# the same object code as the unmutated header's (0.0f -> 0.0 in
		# a float initializer, an unused enum value): the same program,
		# so the same outputs: unchanged, without running it
		compiled=1
	elif [ -f "$w/lib.o" ] && $CC -o "$w/t" "$d/driver.o" "$w/lib.o" "$d/fdlibm.o" -lm 2>/dev/null; then
		compiled=1
		INDEP_FIRST=$first INDEP_STOP_EARLY=1 timeout 60 "$w/t" --quick > "$w/out" 2>&1; rc=$?
		if [ $rc -ne 0 ]; then
			# the test stops at the first differing method: no hash, but
			# the unmutated header passes, so a failure means some output
			# (the hash's, or a non-finite input's) changed
			caught=1; changed=1
		else
			h=$(sed -n 's/^outputs-hash //p' "$w/out")
			[ "$h" != "$(cat "$d/base.hash")" ] && changed=1
		fi
	fi
	printf '%s\t%s\t%s\t%s:%s\t%s\t%s\t%s\t%s\n' "$i" "$kind" "$where" "$ln" "$col" "$compiled" "$changed" "$caught" \
		"$(sed -n "${ln}p" "$w/libonb/onb.h" | sed 's/^[[:space:]]*//')" > "$d/res/$i"
	rm -rf "$w"
}
if [ "${1:-}" != "" ] && [ -d "${1:-}" ]; then one "$1" "$2"; exit 0; fi

start=$(date +%s)
rev="$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)$(git diff --quiet HEAD -- include tests 2>/dev/null || echo -dirty)"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/res"
awk -f scripts/mutants.awk include/libonb/onb.h > "$tmp/list"
# MUTATE_EVERY=K: only every K-th mutant (a quick check of this script)
if [ "${MUTATE_EVERY:-1}" -gt 1 ]; then awk -v k="$MUTATE_EVERY" 'NR % k == 1' "$tmp/list" > "$tmp/l2" && mv "$tmp/l2" "$tmp/list"; fi
n=$(wc -l < "$tmp/list")
# src/lib/fdlibm.c (V8's Math functions, called by the babylon kernel) is
# not in the header: compiled once, with the unmutated header, and linked
# into every mutant's program
if ! $CC $FLAGS -Iinclude -DINDEP_SPLIT -c -o "$tmp/driver.o" tests/test_indep.c ||
   ! $CC $FLAGS -Iinclude -c -o "$tmp/fdlibm.o" src/lib/fdlibm.c ||
   ! $CC $FLAGS -Iinclude -c -o "$tmp/lib.o" tests/indep_lib.c ||
   ! $CC -o "$tmp/base" "$tmp/driver.o" "$tmp/lib.o" "$tmp/fdlibm.o" -lm || ! "$tmp/base" --quick > "$tmp/base.out"; then
	echo "mutate: the unmutated header fails test_indep" >&2; exit 1
fi
sed -n 's/^outputs-hash //p' "$tmp/base.out" > "$tmp/base.hash"
# the table's rows, one a line (NAME TAB { "NAME", fn, fnf, ID, K }), from
# the preprocessed tests/indep_lib.c: each mutant's first try picks its own
$CC $FLAGS -Iinclude -E -P tests/indep_lib.c | awk '/^static const indep_row T\[\] = \{/ { on = 1; next }
	on && /^\};/ { exit } on { s = s " " $0 }
	END { while (match(s, /\{[^{}]*\}/)) { r = substr(s, RSTART, RLENGTH); s = substr(s, RSTART + RLENGTH)
		n = r; sub(/^\{ *"/, "", n); sub(/".*/, "", n); print n "\t" r } }' > "$tmp/rows"
if [ "$(wc -l < "$tmp/rows")" -ne "$(grep -c '^  [a-z0-9_]* *double .* differ, float' "$tmp/base.out")" ]; then
	echo "mutate: cannot read the method table of tests/indep_lib.c ($(wc -l < "$tmp/rows") rows)" >&2; exit 1
fi
echo "mutate: $n mutants of include/libonb/onb.h, $JOBS at a time"
seq 1 "$n" | xargs -P "$JOBS" -I{} sh scripts/mutate.sh --one "$tmp" {}
cat "$tmp"/res/* | sort -n > "$tmp/all"
tried=$(wc -l < "$tmp/all")
compiled=$(awk -F'\t' '$5 == 1' "$tmp/all" | wc -l)
changed=$(awk -F'\t' '$6 == 1' "$tmp/all" | wc -l)
caught=$(awk -F'\t' '$6 == 1 && $7 == 1' "$tmp/all" | wc -l)
survived=$((changed - caught))
secs=$(( $(date +%s) - start ))
{
	echo "# mutate.sh: one-token mutants of include/libonb/onb.h judged by tests/test_indep.c --quick (inline versions)"
	echo "# revision: $rev (at the start of the run)"
	echo "# compiler: $($CC --version | head -1); flags: $FLAGS"
	echo "tried: $tried"
	echo "compiled: $compiled"
	echo "changed: $changed"
	echo "caught: $caught"
	echo "survived: $survived"
	echo "unchanged: $((tried - changed))"
	for k in const cmp sign conv cross; do
		echo "tried_$k: $(awk -F'\t' -v k=$k '$2 == k' "$tmp/all" | wc -l)"
		echo "changed_$k: $(awk -F'\t' -v k=$k '$2 == k && $6 == 1' "$tmp/all" | wc -l)"
		echo "caught_$k: $(awk -F'\t' -v k=$k '$2 == k && $6 == 1 && $7 == 1' "$tmp/all" | wc -l)"
	done
	echo "seconds: $secs"
} > "$tmp/summary"
grep -v '^#' "$tmp/summary" | tr '\n' ' ' | sed 's/ $/\n/'
if [ "$tried" -ne "$n" ]; then echo "mutate: only $tried of $n mutants reported" >&2; exit 1; fi
[ -n "$LIST" ] && { cp "$tmp/all" "$LIST" || { echo "mutate: cannot write $LIST" >&2; exit 1; }; }
[ -n "$OUT" ] && { cp "$tmp/summary" "$OUT.tmp" && mv "$OUT.tmp" "$OUT" || { echo "mutate: cannot write $OUT" >&2; exit 1; }; }
if [ "$survived" -gt 0 ]; then
	echo "mutate: $survived output-changing mutants survived:"
	awk -F'\t' '$6 == 1 && $7 == 0 { print "  " $2 " " $3 " line " $4 ": " $8 }' "$tmp/all"
	exit 1
fi
if [ "$LIMIT" -gt 0 ] && [ "$secs" -gt "$LIMIT" ]; then echo "mutate: took $secs s, over the limit of $LIMIT s" >&2; exit 1; fi
echo "mutate: every output-changing mutant was caught ($caught of $changed; $((tried - changed)) changed no output bit on the test's inputs, $((tried - compiled)) did not compile)"
