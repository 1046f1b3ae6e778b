#!/bin/sh
# What one basis costs through each libonb entry, per method and precision:
# the method name inlined, onb_NAME_outline[f] (by value, out of line),
# onb_NAME_array[f] and the registry's onb_basis_array[f], in the same
# throughput loop (tests/client/entries.c, thread CPU time).  The target:
# out of line and registry at most 1.5x the array entry, or at most 1.5 ns
# more.  With BASE (a revision), the same driver is also linked against
# BASE's libonb.a and its out-of-line and registry figures are shown beside.
#   sh scripts/entry-bench.sh [ROUNDS] [BASE] [OUT]
#   (default 5 rounds, no BASE, results/clients/entries.md)
# Each round runs every driver once (taking turns); a cell is the median of
# the ROUNDS rounds, each round's figure the median of 7 timed runs.
set -eu
cd "$(dirname "$0")/.."
rounds=${1:-5}
base=${2:-}
out=${3:-results/clients/entries.md}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
LIBFP="-std=c99 -O2 -ffp-contract=off -fno-math-errno -fno-trapping-math"
make -s lib >/dev/null
cc $LIBFP -Wall -Wextra -Iinclude tests/client/entries.c libonb.a -lm -o "$tmp/new"
progs=new
if [ -n "$base" ]; then
	mkdir -p "$tmp/base"
	git archive "$base" | tar -x -C "$tmp/base"
	make -s -C "$tmp/base" libonb.a >/dev/null
	# the header's path: include/libonb/onb.h, or include/onb.h before
	sed 's|"libonb/onb.h"|"onb.h"|' tests/client/entries.c > "$tmp/entries-old.c"
	hdr="$tmp/base/include"; [ -f "$hdr/libonb/onb.h" ] && cp tests/client/entries.c "$tmp/entries-old.c"
	cc $LIBFP -Wall -Wextra -I"$hdr" -Itests/client "$tmp/entries-old.c" "$tmp/base/libonb.a" -lm -o "$tmp/base/prog"
	progs="new base"
fi
load0=$(cut -d' ' -f1-3 /proc/loadavg)
r=0
while [ $r -lt "$rounds" ]; do
	r=$((r + 1))
	"$tmp/new" > "$tmp/new.$r"
	[ -z "$base" ] || "$tmp/base/prog" > "$tmp/base.$r"
done
load1=$(cut -d' ' -f1-3 /proc/loadavg)
# median of each cell over the rounds: key = method precision, fields 3..6
med() { cat "$tmp/$1".* | awk '
	{ k = $1 " " $2; if (!(k in seen)) { seen[k] = 1; o[++n] = k } c[k]++
	  for (f = 3; f <= 6; f++) v[k, f, c[k]] = $f }
	END { for (i = 1; i <= n; i++) { k = o[i]; printf "%s", k
		for (f = 3; f <= 6; f++) { m = c[k]; for (a = 1; a <= m; a++) x[a] = v[k, f, a]
			for (a = 1; a <= m; a++) for (b = a + 1; b <= m; b++) if (x[b] < x[a]) { t = x[a]; x[a] = x[b]; x[b] = t }
			printf " %s", x[int((m + 1) / 2)] }
		printf "\n" } }'; }
med new > "$tmp/new.med"
if [ -n "$base" ]; then med base > "$tmp/base.med"; else : > "$tmp/base.med"; fi
rev=$(git rev-parse --short=12 HEAD)$(git diff --quiet HEAD -- include src/lib Makefile tests/client || echo -dirty)
{
	echo "<!-- scripts/entry-bench.sh $rounds $base at $rev, $(date -u +%Y-%m-%dT%H:%MZ) -->"
	echo "<!-- cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores; load $load0 at the start, $load1 at the end (shared machine) -->"
	echo "<!-- $(cc --version | head -1); driver and libonb.a: cc $LIBFP; 4096 unit vectors, 100 passes, 7 runs per round -->"
	echo
	echo "ns per basis (thread CPU time, median of $rounds rounds). Target: outline and"
	echo "registry within 1.5x of array, or within 1.5 ns of it."
	[ -z "$base" ] || echo "\"before\": the same driver against libonb.a at $base ($(git rev-parse --short=12 "$base"))."
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
		  printf "\n" }' "$tmp/base.med" "$tmp/new.med"
} > "$out"
cat "$out"
