#!/bin/sh
# Write results/robustness.md: what was tried against libonb and onbstudy
# and what happened.  Generated, never edited by hand.
#   sh scripts/robustness.sh            after `make` (uses ./onbstudy)
# Reruns itself: the library's bad inputs (tests/robust/lib_cases.c, built
# with the library sources under ASan+UBSan, run under a time limit) and
# the command-line cases (tests/cli_errors.sh).  Reads the logs of the last
# `sh scripts/harden.sh` (build/harden/: sanitized make test, valgrind,
# cppcheck, step durations) and `sh scripts/fuzz.sh` (build/fuzz/summary.tsv);
# a row whose log is missing says "not run" and where the last full run
# of every step is recorded ($NOTRUN).
#   sh scripts/robustness.sh --out FILE   write FILE instead, docs/testing.md untouched
#     (what CI does: CI changes no tracked file)
# Regenerate the committed table and docs/testing.md's copy: make robustness
set -u
cd "$(dirname "$0")/.."
out=results/robustness.md
case "${1:-}" in
--out) out=${2:?usage: robustness.sh [--out FILE]} ;;
"") ;;
*) echo "usage: robustness.sh [--out FILE]" >&2; exit 2 ;;
esac
L=build/harden
NOTRUN="not run in this regeneration (no log in build/harden/ or build/fuzz/); the last full scripts/harden.sh run's outcome: results/quickstart/ci-rehearsal.txt"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
mkdir -p "$(dirname "$out")"
rev=$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- 2>/dev/null || rev="$rev-dirty"
nm=$(./onbstudy list --format csv 2>/dev/null | tail -n +2 | wc -l)

# --- library
libst="crashed or failed to build"
# half.c a second time with F16C conversions, as the Makefile's
# half_f16c.o: the copy that its ifuncs pick (an empty object elsewhere)
rflags="-std=c99 -O2 -ffp-contract=off -fno-math-errno -fno-trapping-math -fsanitize=address,undefined -fno-sanitize-recover=all"
f16c=; [ "$(uname -m)" = x86_64 ] && f16c=-mf16c
if cc $rflags $f16c -DONB__HALF_F16C -Iinclude -c -o "$tmp/half_f16c.o" src/lib/half.c 2> "$tmp/lib_cc" &&
   cc $rflags \
      -Wall -Wextra -Wpedantic -Wshadow -Iinclude \
      -o "$tmp/lib_cases" tests/robust/lib_cases.c src/lib/*.c "$tmp/half_f16c.o" -lm 2>> "$tmp/lib_cc"; then
	timeout 120 "$tmp/lib_cases" > "$tmp/lib.tsv" 2> "$tmp/lib.err"
	rc=$?
	if [ $rc -eq 0 ] && [ ! -s "$tmp/lib.err" ]; then libst=ok
	elif [ $rc -eq 124 ]; then libst="HUNG (killed after 120 s)"; fail=1
	else libst="FAILED (exit $rc): $(head -3 "$tmp/lib.err" | tr '\n' ' ')"; fail=1; fi
else
	libst="FAILED to build: $(head -3 "$tmp/lib_cc" | tr '\n' ' ')"; fail=1
	: > "$tmp/lib.tsv"
fi
grep -v '^(NULL' "$tmp/lib.tsv" > "$tmp/lib_m.tsv"
ncases=$(cut -f2 "$tmp/lib_m.tsv" | sort -u | wc -l)
nmeth=$(cut -f1 "$tmp/lib_m.tsv" | sort -u | wc -l)
calls=$(( $(wc -l < "$tmp/lib_m.tsv") * 6 ))
batchdiff=$(awk -F'\t' '$5 != "yes"' "$tmp/lib_m.tsv" | wc -l)
checkednf=$(awk -F'\t' '$6 ~ /NONFINITE$/ || $7 ~ /NONFINITE$/' "$tmp/lib_m.tsv" | wc -l)
checkedwho=$(awk -F'\t' '$6 ~ /NONFINITE$/ || $7 ~ /NONFINITE$/ { print $1 }' "$tmp/lib_m.tsv" | sort | uniq -c | awk '{ printf "%s%s x%d", (NR > 1 ? ", " : ""), $2, $1 }')
nullst=$(awk -F'\t' '/^\(NULL/ { print $6 }' "$tmp/lib.tsv")

# --- command line
sh tests/cli_errors.sh > "$tmp/cli.log" 2>&1
clirc=$?
clisum=$(tail -1 "$tmp/cli.log")
[ $clirc -eq 0 ] || fail=1
clicases=$(grep -c '^R \|^refuse ' tests/cli_errors.sh)
known=$(grep '^KNOWN' "$tmp/cli.log" | sed 's/^KNOWN (\([^)]*\)).*/\1/' | sort | uniq -c | awk '{ printf "%s%s (%d)", (NR > 1 ? ", " : ""), $2, $1 }')
sigint="not run"
if grep -q 'SIGINT\|interrupted' "$tmp/cli.log"; then sigint="FAILED: $(grep 'SIGINT\|interrupted\|130' "$tmp/cli.log" | head -2 | tr '\n' ' ')"
elif [ $clirc -eq 0 ]; then sigint="passed: exit 130, earlier summary.csv unchanged, summary/by_nz/worst.partial.csv marked '# PARTIAL', no temporary file left"; fi

# --- fuzzing
fz() { # harness column
	awk -F'\t' -v h="$1" -v c="$2" '$1 == h { print $c }' build/fuzz/summary.tsv 2>/dev/null
}
fuzzrow() { # harness, what
	if [ -f build/fuzz/summary.tsv ] && [ -n "$(fz "$1" 3)" ]; then
		printf '| Fuzzing: %s | libFuzzer, clang -fsanitize=fuzzer,address,undefined, %s s from %s seeds | %s executions, %s crashes (exit %s), %s coverage edges, corpus %s |\n' \
			"$2" "$(fz "$1" 2)" "$(find tests/fuzz/corpus/$1 -type f ! -name '.*' | wc -l)" "$(fz "$1" 3)" "$(fz "$1" 5)" "$(fz "$1" 4)" "$(fz "$1" 6)" "$(fz "$1" 7)"
	else
		printf '| Fuzzing: %s | libFuzzer (scripts/fuzz.sh) | %s |\n' "$2" "$NOTRUN"
	fi
}
nreg=$(find tests/fuzz/regressions -type f ! -name '.*' | wc -l)

# --- logs of scripts/harden.sh
stepval() { awk -F'\t' -v s="$1" -v c="$2" '$1 == s { print $c }' "$L/steps.tsv" 2>/dev/null; }
if [ -f "$L/sanitize.log" ]; then
	tests=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$L/sanitize.log" | awk '{ n++; p += $1; f += $3 } END { printf "%d test programs, %d checks passed, %d failed", n, p, f }')
	# outside the KNOWN lines, which quote the report of a known bug
	reports=$(grep -v '^KNOWN' "$L/sanitize.log" | grep -c -E 'ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:')
	if grep -q '^make test: all passed' "$L/sanitize.log"; then san="all passed ($tests), $reports sanitizer reports"
	else san="FAILED ($tests), $reports sanitizer reports"; fi
	sanknown=$(grep '^KNOWN' "$L/sanitize.log" | sed 's/^KNOWN (\([^)]*\)): \(.*\) -- onbstudy .*/\1: \2/' | sort | uniq -c |
		awk '{ c = $1; $1 = ""; sub(/^ /, ""); sub(/ +$/, ""); printf "%s%s (x%d)", (NR > 1 ? "; " : ""), $0, c }')
	[ -n "$sanknown" ] && san="$san; KNOWN cases of tests/cli_errors.sh (bugs reported, not counted): $sanknown"
else san=$NOTRUN; fi
if [ -f "$L/valgrind.log" ]; then
	vg=$(grep -o 'ERROR SUMMARY: [0-9]* errors' "$L/valgrind.log" | awk '{ n++; e += $3 } END { printf "%d runs, %d errors", n, e }')
	[ "$(stepval valgrind 3)" = 0 ] || vg="FAILED (exit $(stepval valgrind 3)): $vg"
else vg=$NOTRUN; fi
if [ -f "$L/cppcheck.log" ]; then
	cpn=$(grep -c -E '^[^ ]+:[0-9]+:[0-9]+: ' "$L/cppcheck.log")
	nsup=$(grep -c -v '^#\|^$' scripts/cppcheck-suppressions.txt)
	cp="$cpn findings ($nsup suppressions, each justified in scripts/cppcheck-suppressions.txt)"
	[ "$(stepval cppcheck 3)" = 0 ] || cp="FAILED: $cp"
else cp=$NOTRUN; fi
# the strict warning set, on both compilers, right now
warn="-std=c99 -O2 -ffp-contract=off -fno-math-errno -fno-trapping-math -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Werror -Iinclude"
wst=""
for c in gcc clang; do
	if ! command -v $c >/dev/null 2>&1; then wst="$wst $c: not installed;"; continue; fi
	ok=1
	for f in src/lib/*.c; do
		# shellcheck disable=SC2086
		$c $warn -c "$f" -o "$tmp/w.o" 2>> "$tmp/warn.log" || ok=0
	done
	if [ $ok -eq 1 ]; then wst="$wst $c: clean;"; else wst="$wst $c: WARNINGS;"; fail=1; fi
done

{
echo "# Robustness of libonb and onbstudy"
echo
echo "Generated by \`sh scripts/robustness.sh\` (revision $rev, $(date -u +%Y-%m-%d)); do not edit."
echo "Regenerate everything with \`sh scripts/harden.sh\` (sanitized tests, fuzzing, valgrind, cppcheck, then this table)."
echo "The library and command-line rows are rerun by the script; the other rows come from the last logs in"
echo "\`build/harden/\` and \`build/fuzz/\`."
echo
echo "| Check | What was tried | Result |"
echo "|---|---|---|"
echo "| Library, bad input | $nmeth methods x $ncases inputs (zero, -0, NaN and Inf in each component, subnormals, \|n\| = 1e-20 and 1e20) x {double, float} x {scalar, batch, onb_basis_checked}: $calls calls, built with -fsanitize=address,undefined, 120 s limit | $libst: no crash, no sanitizer report, no hang; batch and scalar disagree on finiteness in $batchdiff cases; onb_basis_checked[f] returned a non-finite basis in $checkednf cases${checkedwho:+ ($checkedwho: the method's own singular directions, which the checked entry point does not guard)}; NULL method: $nullst |"
echo "| Command line | $clicases bad command lines over list, sweep, merge, scene (tests/cli_errors.sh): unknown options, bad and out-of-range numbers, --samples 1e30, unreadable and damaged files, unwritable --out | $clisum${known:+; known: $known} |"
echo "| SIGINT during a sweep | sweep --samples 2000000 into a directory holding a complete run, SIGINT after 2 s | $sigint |"
fuzzrow mesh "OBJ/PLY readers"
fuzzrow gltf "glTF 2.0 reader"
fuzzrow cli "CLI parsers"
echo "| Fuzz regressions | inputs kept in tests/fuzz/regressions/, replayed with the seed corpus by make test (tests/fuzz_regress.sh) | $nreg kept |"
echo "| make test SANITIZE=address,undefined | the suite under ASan and UBSan (-fno-sanitize-recover=all), less the document checks (SANITIZE_SKIP) | $san |"
echo "| valgrind memcheck | sweep --samples 64 --exhaustive-count 64 --grid 4x8 over every distribution but threshold (all methods, 2 threads) and over threshold (frisvad, duff, hughes_moeller); scene on an OBJ, a big-endian PLY and a glTF (--world) | $vg |"
echo "| cppcheck src/lib | --enable=warning,style,performance,portability --force (every #ifdef configuration) | $cp |"
echo "| Strict warnings | src/lib with -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Werror |$wst |"
echo
echo "## Library: what each input gives"
echo
echo "Output classes of the $nmeth methods' scalar functions (finite: all six components finite; NaN: some component NaN;"
echo "Inf: some infinite, none NaN).  Finite output for a bad input is still garbage: only onb_basis_checked says so."
echo
echo "| Input | double: finite / NaN / Inf | float: finite / NaN / Inf | Methods with NaN or Inf output (double; float if different) | onb_basis_checked (double; float) |"
echo "|---|---|---|---|---|"
cut -f2 "$tmp/lib_m.tsv" | awk '!seen[$0]++' > "$tmp/cases"
while IFS= read -r c; do
	awk -F'\t' -v c="$c" '
	$2 == c { d[$3]++; f[$4]++; if ($3 != "finite") bad = bad (bad ? ", " : "") $1
		if ($4 != "finite") badf = badf (badf ? ", " : "") $1
		cd[$6]++; cf[$7]++ }
	END {
		n = '"$nmeth"'
		for (k in cd) sd = sd (sd ? ", " : "") k (cd[k] < n ? " x" cd[k] : "")
		for (k in cf) sf = sf (sf ? ", " : "") k (cf[k] < n ? " x" cf[k] : "")
		nb = n - d["finite"]; nbf = n - f["finite"]
		if (nb == 0) bad = "none"; else if (nb == n) bad = "all"
		if (nbf == 0) badf = "none"; else if (nbf == n) badf = "all"
		if (badf != bad) bad = bad "; float: " badf
		printf "| %s | %d / %d / %d | %d / %d / %d | %s | %s; %s |\n", c, d["finite"], d["NaN"], d["Inf"], f["finite"], f["NaN"], f["Inf"], bad, sd, sf
	}' "$tmp/lib_m.tsv"
done < "$tmp/cases"
echo
echo "Per method (double/float; F finite, N NaN, I Inf):"
echo
printf '| Method |'; while IFS= read -r c; do printf ' %s |' "$c"; done < "$tmp/cases"; echo
printf '|---|'; while IFS= read -r c; do printf -- '---|'; done < "$tmp/cases"; echo
cut -f1 "$tmp/lib_m.tsv" | awk '!seen[$0]++' | while IFS= read -r m; do
	awk -F'\t' -v m="$m" 'function s(x) { return x == "finite" ? "F" : x == "NaN" ? "N" : "I" }
	$1 == m { row = row " " s($3) "/" s($4) " |" } END { print "| " m " |" row }' "$tmp/lib_m.tsv"
done
if [ -f "$L/steps.tsv" ]; then
	echo
	echo "## Duration of each CI step (last scripts/harden.sh run)"
	echo
	echo "| Step | Seconds | Exit |"
	echo "|---|---|---|"
	tail -n +2 "$L/steps.tsv" | awk -F'\t' 'NF == 3 { printf "| %s | %s | %s |\n", $1, $2, $3 }'
fi
} > "$tmp/robustness.md"
cp "$tmp/robustness.md" "$out.tmp" && mv -f "$out.tmp" "$out"
echo "robustness.sh: wrote $out"
# docs/testing.md carries the summary table (the first one) between its markers.
DOC=docs/testing.md
B='<!-- robustness:begin (generated by scripts/robustness.sh; do not edit) -->'
E='<!-- robustness:end -->'
if [ "$out" = results/robustness.md ] && grep -qF "$B" "$DOC" && grep -qF "$E" "$DOC"; then
	awk '/^\| Check \|/ { on = 1 } on && /^$/ { exit } on { print }' "$out" > "$tmp/table"
	awk -v B="$B" -v E="$E" -v T="$tmp/table" -v R="$rev" '
		$0 == B { print; print ""; print "From the run of revision " R " ([full report](../results/robustness.md)):"; print ""
		          while ((getline l < T) > 0) print l; print ""; skip = 1; next }
		$0 == E { skip = 0 }
		!skip { print }' "$DOC" > "$tmp/doc" && cp "$tmp/doc" "$DOC"
	echo "robustness.sh: updated the table in $DOC"
fi
if [ $fail -ne 0 ]; then
	echo "robustness.sh: some check failed (see $out)" >&2
	exit 1
fi
