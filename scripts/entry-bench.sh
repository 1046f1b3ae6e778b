#!/bin/sh
# What one basis costs through each libonb entry, per method and precision.
#   sh scripts/entry-bench.sh [ROUNDS] [BASE] [OUT]
#   (default 7 rounds, no BASE, results/clients/entries.md)
# Two parts, each round running every driver once (taking turns); a cell is
# the median of the ROUNDS rounds, each round's figure the median of 7
# timed runs (thread CPU time).  The target: every out-of-line way of
# calling at most 1.5x the array entry, or at most 1.5 ns more.
#  1. Entries (tests/client/entries.c, built with the library's flags):
#     the method name inlined, onb_NAME_outline[f] (by value, out of line),
#     onb_NAME_array[f] and the registry's onb_basis_array[f], each storing
#     its results straight into arrays.
#  2. Callers (tests/client/callers.c, built as each client builds it:
#     gcc, g++, clang, clang++ at -O2 and -O3 -march=native): the array
#     entry, and the out-of-line entries with their results stored straight
#     into arrays, kept in locals and copied as structs, read member by
#     member, the array entry into local arrays then copied, and the method
#     name itself (inline or a call, as onb.h decides for that build).  The
#     full medians go to OUT's folder as callers.txt.
# With BASE (a revision), the same drivers are also linked against BASE's
# libonb.a and its figures are shown beside ("before").  CALLERS_PASSES
# (default 50) sets the passes over the 4096 inputs per timed run of part 2.
set -eu
cd "$(dirname "$0")/.."
rounds=${1:-7}
base=${2:-}
out=${3:-results/clients/entries.md}
passes=${CALLERS_PASSES:-50}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
LIBFP="-std=c99 -O2 -ffp-contract=off -fno-math-errno -fno-trapping-math"
make -s lib >/dev/null
# The caller builds of part 2: name|compiler|flags (C++: the file as C++).
cat > "$tmp/builds" <<'B'
gcc -O2|gcc|-O2
gcc -O3 -march=native|gcc|-O3 -march=native
g++ -O2|g++|-O2 -x c++
g++ -O3 -march=native|g++|-O3 -march=native -x c++
clang -O2|clang|-O2
clang -O3 -march=native|clang|-O3 -march=native
clang++ -O2|clang++|-O2 -x c++
clang++ -O3 -march=native|clang++|-O3 -march=native -x c++
B
# drivers TAG INCLUDE LIB: part 1's entries and part 2's callers, one
# program per build, into $tmp/TAG.*; $tmp/TAG.names lists the builds made
drivers() {
	cc $LIBFP -Wall -Wextra -I"$2" -Itests/client tests/client/entries.c "$3" -lm -o "$tmp/$1.entries"
	: > "$tmp/$1.names"
	j=0
	while IFS='|' read -r name c flags; do
		j=$((j + 1))
		if ! command -v "$c" >/dev/null 2>&1; then
			[ "$1" = new ] && echo "entry-bench: $c not installed, build '$name' skipped (scripts/install-deps.sh --test)" >&2
			continue
		fi
		$c $flags -Wall -Wextra -I"$2" -Itests/client tests/client/callers.c -x none "$3" -lm -o "$tmp/$1.c$j"
		echo "$j|$name" >> "$tmp/$1.names"
	done < "$tmp/builds"
}
drivers new include libonb.a
tags=new
if [ -n "$base" ]; then
	mkdir -p "$tmp/base"
	git archive "$base" | tar -x -C "$tmp/base"
	make -s -C "$tmp/base" libonb.a >/dev/null
	# the header's path: include/libonb/onb.h, or include/onb.h before
	hdr="$tmp/base/include"
	if [ ! -f "$hdr/libonb/onb.h" ]; then mkdir -p "$tmp/basehdr/libonb"; cp "$hdr/onb.h" "$tmp/basehdr/libonb/"; hdr="$tmp/basehdr"; fi
	drivers base "$hdr" "$tmp/base/libonb.a"
	tags="new base"
fi
load0=$(cut -d' ' -f1-3 /proc/loadavg)
# the niceness it ran at (a shared machine runs it under nice -n 10)
niced=$(nice); [ "$niced" -gt 0 ] && niced="nice -n $niced " || niced=
r=0
while [ $r -lt "$rounds" ]; do
	r=$((r + 1))
	for t in $tags; do
		"$tmp/$t.entries" > "$tmp/$t.e.$r"
		while IFS='|' read -r j name; do "$tmp/$t.c$j" "$passes" > "$tmp/$t.c$j.$r"; done < "$tmp/$t.names"
	done
done
load1=$(cut -d' ' -f1-3 /proc/loadavg)
# med FILES NF: the median of each cell over the rounds; key = fields 1-2
# (method precision), cells 3..NF
med() { cat $1 | awk -v nf="$2" '
	/^#/ { next }
	{ k = $1 " " $2; if (!(k in seen)) { seen[k] = 1; o[++n] = k } c[k]++
	  for (f = 3; f <= nf; f++) v[k, f, c[k]] = $f }
	END { for (i = 1; i <= n; i++) { k = o[i]; printf "%s", k
		for (f = 3; f <= nf; f++) { m = c[k]; for (a = 1; a <= m; a++) x[a] = v[k, f, a]
			for (a = 1; a <= m; a++) for (b = a + 1; b <= m; b++) if (x[b] < x[a]) { t = x[a]; x[a] = x[b]; x[b] = t }
			printf " %s", x[int((m + 1) / 2)] }
		printf "\n" } }'; }
for t in $tags; do
	med "$tmp/$t.e.*" 6 > "$tmp/$t.e.med"
	while IFS='|' read -r j name; do
		med "$tmp/$t.c$j.*" 8 > "$tmp/$t.c$j.med"
	done < "$tmp/$t.names"
done
[ -n "$base" ] || : > "$tmp/base.e.med"
rev=$(git rev-parse --short=12 HEAD)$(git diff --quiet HEAD -- include src/lib Makefile tests/client || echo -dirty)
cpu="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores"
ccs="$(cc --version | head -1); $(g++ --version | head -1)$(command -v clang >/dev/null 2>&1 && echo "; $(clang --version | head -1)")"
# summary NAME J: part 2's rows of one build, per pattern: the median and
# the largest ratio to the array entry, and how many rows meet the target
summary() {
	ia=$(sed -n 's/^# inline_active //p' "$tmp/new.c$2.1")
	for f in 4 5 6 7 8; do
		bf=/dev/null; [ -n "$base" ] && bf="$tmp/base.c$2.med"
		awk -v f="$f" -v name="$1" -v ia="$ia" -v hasbase="$base" '
		function met(a, x) { return x <= 1.5 * a || x <= a + 1.5 }
		function stats(arr, n,   i, j, t) { for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (arr[j] < arr[i]) { t = arr[i]; arr[i] = arr[j]; arr[j] = t } return arr[int((n + 1) / 2)] }
		FILENAME == ARGV[1] { br = $f / $3; bn++; bq[bn] = br; if (br > bw) bw = br; bm += met($3, $f); next }
		{ r = $f / $3; n++; q[n] = r; ok += met($3, $f)
		  if (r > w) { w = r; wk = $1 " " $2 ": " $f " vs " $3 } }
		END {
			split("- - - out copy members acopy name", pn, " ")
			ent = (f == 8) ? (ia == 1 ? "name (inline)" : "name (out of line)") : pn[f]
			okk = (f == 8 && ia == 1) ? "(inline: no target)" : ok " of " n
			printf "| %s | %s | %.2fx | %.2fx (%s) | %s |", name, ent, stats(q, n), w, wk, okk
			if (hasbase != "") printf " %.2fx | %.2fx | %d of %d |", stats(bq, bn), bw, bm, bn
			printf "\n" }' "$bf" "$tmp/new.c$2.med"
	done
}
# headline NAME J: the issue's methods in one build
headline() {
	bf=/dev/null; [ -n "$base" ] && bf="$tmp/base.c$2.med"
	awk -v name="$1" -v hasbase="$base" '
	FILENAME == ARGV[1] { b[$1 " " $2] = $5 " | " $7; next }
	$1 == "frisvad" || $1 == "q2rtx" || $1 == "duff_branchless" || $1 == "stark_fixed" {
		w = 0; for (f = 4; f <= 8; f++) if ($f / $3 > w) w = $f / $3
		printf "| %s | %s | %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2fx |", name, $1, $2, $3, $4, $5, $6, $7, $8, w
		if (hasbase != "") printf " %s |", b[$1 " " $2]
		printf "\n" }' "$bf" "$tmp/new.c$2.med"
}
{
	echo "<!-- CALLERS_PASSES=$passes scripts/entry-bench.sh $rounds $base at $rev, $(date -u +%Y-%m-%dT%H:%MZ) -->"
	echo "<!-- cpu: $cpu; load $load0 at the start, $load1 at the end (shared machine) -->"
	echo "<!-- $ccs; libonb.a: its Makefile's flags; entries driver: cc $LIBFP; callers: each build's flags; 4096 unit vectors, entries 100 passes, callers $passes passes, 7 runs per round -->"
	echo
	echo "# Out-of-line entries against the array entry"
	echo
	echo "Made by \`CALLERS_PASSES=$passes ${niced}sh scripts/entry-bench.sh $rounds $base\`. ns per basis (thread CPU time, the"
	echo "median of $rounds rounds, each the median of 7 runs; the rounds and"
	echo "drivers take turns). Target: every out-of-line way of calling within 1.5x"
	echo "of the array entry, or within 1.5 ns of it."
	[ -z "$base" ] || echo "\"before\": the same drivers against libonb.a at $base ($(git rev-parse --short=12 "$base"))."
	echo
	echo "## Callers"
	echo
	echo "\`tests/client/callers.c\`, built as each client builds it and linked to"
	echo "libonb.a. Patterns, each against \`onb_NAME_array[f](&n[i].x, &b1[i].x, &b2[i].x)\`"
	echo "(array) in the same build and run:"
	echo "- out: \`onb_NAME_outline[f](n[i], &b1[i], &b2[i])\`, results stored straight into arrays;"
	echo "- copy: \`onb_vec3f u, v; onb_NAME_outlinef(n[i], &u, &v); b1[i] = u; b2[i] = v;\`, results kept in locals and copied as structs;"
	echo "- members: the same locals read member by member (\`b1x[i] = u.x; b1y[i] = u.y; ...\`);"
	echo "- acopy: \`float u[3], v[3]; onb_NAME_arrayf(&n[i].x, u, v);\` then \`b1[i].x = u[0]; ...\`;"
	echo "- name: \`onb_NAMEf(n[i], &u, &v); b1[i] = u; b2[i] = v;\`, the method name, inline or a call of"
	echo "  \`onb_NAME_outline[f]\` as onb.h decides for the build (no target where inline)."
	echo
	echo "Per build and pattern, over every method and precision ($(wc -l < "$tmp/new.c1.med") rows): the median"
	echo "and the largest ratio to the array entry (that row's ns against the array's), and the rows"
	echo "within the target."
	echo
	if [ -n "$base" ]; then
		echo "| caller build | pattern | median ratio | largest ratio | target met | median before | largest before | met before |"
		echo "|---|---|---|---|---|---|---|---|"
	else
		echo "| caller build | pattern | median ratio | largest ratio | target met |"
		echo "|---|---|---|---|---|"
	fi
	while IFS='|' read -r j name; do summary "$name" "$j"; done < "$tmp/new.names"
	echo
	echo "The issue's methods (and stark_fixed, whose branches mispredict), ns per basis; \"largest\" is the"
	echo "largest ratio of the row's five patterns to its array entry. Every row: [callers.txt](callers.txt)."
	echo
	if [ -n "$base" ]; then
		echo "| caller build | method | precision | array | out | copy | members | acopy | name | largest | copy before | acopy before |"
		echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
	else
		echo "| caller build | method | precision | array | out | copy | members | acopy | name | largest |"
		echo "|---|---|---|---|---|---|---|---|---|---|"
	fi
	while IFS='|' read -r j name; do headline "$name" "$j"; done < "$tmp/new.names"
	echo
	echo "## Entries"
	echo
	echo "\`tests/client/entries.c\`, built with the library's flags: each entry's results stored"
	echo "straight into arrays (the \"out\" pattern above)."
	echo
	if [ -n "$base" ]; then
		echo "| method | precision | inline | outline | array | registry | outline/array | registry/array | target met | outline before | registry before | array before |"
		echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
	else
		echo "| method | precision | inline | outline | array | registry | outline/array | registry/array | target met |"
		echo "|---|---|---|---|---|---|---|---|---|"
	fi
	awk -v hasbase="$base" 'FILENAME == ARGV[1] { b[$1 " " $2] = $4 " | " $6 " | " $5; next }
		{ k = $1 " " $2; ro = $4 / $5; rr = $6 / $5
		  okk = (($4 <= 1.5 * $5 || $4 <= $5 + 1.5) && ($6 <= 1.5 * $5 || $6 <= $5 + 1.5)) ? "yes" : "**no**"
		  printf "| %s | %s | %.2f | %.2f | %.2f | %.2f | %.2fx | %.2fx | %s |", $1, $2, $3, $4, $5, $6, ro, rr, okk
		  if (hasbase != "") printf " %s |", b[k]
		  printf "\n" }' "$tmp/base.e.med" "$tmp/new.e.med"
} > "$out"
# every row of part 2
{
	echo "# scripts/entry-bench.sh $rounds $base at $rev, $(date -u +%Y-%m-%dT%H:%MZ); cpu: $cpu; load $load0 .. $load1"
	echo "# $ccs; tests/client/callers.c, $passes passes over 4096 inputs, median of $rounds rounds of medians of 7 runs, ns per basis"
	echo "# build|inline_active|method precision array out copy members acopy name${base:+ | before: the same at $base}"
	while IFS='|' read -r j name; do
		ia=$(sed -n 's/^# inline_active //p' "$tmp/new.c$j.1")
		bf=/dev/null; [ -n "$base" ] && bf="$tmp/base.c$j.med"
		awk -v name="$name" -v ia="$ia" 'FILENAME == ARGV[1] { b[$1 " " $2] = $0; next }
			{ k = $1 " " $2; printf "%s|%s|%s", name, ia, $0; if (k in b) printf " | %s", b[k]; printf "\n" }' "$bf" "$tmp/new.c$j.med"
	done < "$tmp/new.names"
} > "$(dirname "$out")/callers.txt"
cat "$out"
