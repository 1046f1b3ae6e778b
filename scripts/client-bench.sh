#!/bin/sh
# Per-call cost of onb.h's method names in other people's builds:
# for each of six client builds (the issue's) and four more (the defines
# that change the choice), whether the names inline, the ns per call,
# and whether the bits equal libonb.a's out-of-line copies (the studied
# bits).  Writes results/clients/percall.txt (every method and precision)
# and results/clients/summary.md (the table of docs/library.md).
#   sh scripts/client-bench.sh [OUTDIR] [ROUNDS]     (default results/clients, 3)
# Each build's driver runs ROUNDS times, the builds taking turns; each run
# times 7 runs of 200 passes over 4096 inputs (tests/client/percall_main.c)
# and prints their median and fastest; the tables give the median of the
# ROUNDS medians and, in parentheses, the fastest of all runs.  Inlined: from the client object's symbols (nm): "call" when it
# references onb_NAME_outline (a call into libonb.a), "copy" when it holds
# a local onb_NAME (called, not inlined), else "inline".
set -eu
cd "$(dirname "$0")/.."
out=${1:-results/clients}
rounds=${2:-3}
command -v clang >/dev/null 2>&1 || { echo "client-bench: clang not installed (scripts/install-deps.sh --test)" >&2; exit 1; }
[ -f libonb.a ] || make -s lib
mkdir -p "$out"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
LIBFP="-std=c99 -O2 -ffp-contract=off -fno-math-errno -fno-trapping-math"
cc $LIBFP -Wall -Wextra -Iinclude -Itests/client -c tests/client/percall_main.c -o "$tmp/main.o"
i=0
while IFS='|' read -r name cc flags; do
	i=$((i + 1))
	$cc $flags -Wall -Wextra -Iinclude -Itests/client -c tests/client/percall_kern.c -o "$tmp/k$i.o"
	cc "$tmp/main.o" "$tmp/k$i.o" libonb.a -lm -o "$tmp/p$i"
	nm "$tmp/k$i.o" > "$tmp/nm$i"
	echo "$name|$cc $flags" > "$tmp/name$i"
done <<'B'
gcc -O2|gcc|-O2
gcc -O3 -march=native|gcc|-O3 -march=native
gcc -O2 -ffast-math|gcc|-O2 -ffast-math
clang -O2|clang|-O2
clang -O3 -march=native|clang|-O3 -march=native
clang -O2 -ffast-math|clang|-O2 -ffast-math
gcc -O3 -march=native -std=c11|gcc|-O3 -march=native -std=c11
gcc -O3 -march=native -ffp-contract=off -DONB_FP_CONTRACT_OFF|gcc|-O3 -march=native -ffp-contract=off -DONB_FP_CONTRACT_OFF
gcc -O2 -ffast-math -DONB_INLINE_FOLLOWS_CLIENT_FP|gcc|-O2 -ffast-math -DONB_INLINE_FOLLOWS_CLIENT_FP
clang -O3 -march=native -ffast-math -DONB_INLINE_FOLLOWS_CLIENT_FP|clang|-O3 -march=native -ffast-math -DONB_INLINE_FOLLOWS_CLIENT_FP
B
n=$i
r=0
while [ $r -lt "$rounds" ]; do
	r=$((r + 1)); i=0
	while [ $i -lt "$n" ]; do i=$((i + 1)); "$tmp/p$i" > "$tmp/r$i.$r"; done
done
rev=$(git rev-parse --short=12 HEAD)$(git diff --quiet HEAD -- include src/lib tests/client || echo -dirty)
{
	echo "# scripts/client-bench.sh $out $rounds at $rev, $(date -u +%Y-%m-%dT%H:%MZ)"
	echo "# cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg) (shared machine: noisy)"
	echo "# gcc: $(gcc --version | head -1); clang: $(clang --version | head -1)"
	echo "# driver and libonb.a: cc $LIBFP; inputs: 4096 unit vectors (LCG, the six poles first)"
	echo "# columns (|-separated): build|method|precision|ns_per_call (median of the $rounds medians)|ns_per_call (fastest of all $((rounds * 7)) runs)|inlined|differing inputs of 4096"
} > "$tmp/head"
cp "$tmp/head" "$out/percall.txt"
i=0
while [ $i -lt "$n" ]; do
	i=$((i + 1))
	name=$(cut -d'|' -f1 "$tmp/name$i")
	cat "$tmp"/r$i.* | awk -v b="$name" -v nmf="$tmp/nm$i" '
		BEGIN { while ((getline l < nmf) > 0) { k = split(l, f, " "); s = f[k]; t = f[k - 1]; if (t == "U") u[s] = 1; else if (t == "t") loc[s] = 1 } }
		{ key = $1 " " $2; v[key, ++c[key]] = $3; d[key] = $6; if (!(key in seen)) { seen[key] = 1; o[++no] = key; mn[key] = $4 }
		  if ($4 < mn[key]) mn[key] = $4 }
		END {
			for (j = 1; j <= no; j++) {
				key = o[j]; split(key, kk, " "); fn = kk[1] (kk[2] == "float" ? "f" : "")
				m = c[key]; for (a = 1; a <= m; a++) x[a] = v[key, a]
				for (a = 1; a <= m; a++) for (bb = a + 1; bb <= m; bb++) if (x[bb] < x[a]) { t = x[a]; x[a] = x[bb]; x[bb] = t }
				inl = (("onb_" kk[1] "_outline" (kk[2] == "float" ? "f" : "")) in u) ? "call" : ((("onb_" fn) in loc) ? "copy" : "inline")
				printf "%s|%s|%s|%.2f|%.2f|%s|%d\n", b, kk[1], kk[2], x[int((m + 1) / 2)], mn[key], inl, d[key]
			}
		}' >> "$out/percall.txt"
done
# The summary: per build, how many of the 40 names inlined and gave the
# studied bits, and the ns of four methods.
{
	sed 's/^# /<!-- /; s/$/ -->/' "$tmp/head"
	echo
	echo "ns per call: median of the $rounds rounds' medians (fastest run)"
	echo
	echo "| client build | inlined | studied bits | duff_branchless f / d (ns) | hughes_moeller f | pbrt_v3 f | frisvad f |"
	echo "|---|---|---|---|---|---|---|"
	grep -v '^#' "$out/percall.txt" | awk -F'|' '
		{ b = $1; if (!(b in seen)) { seen[b] = 1; o[++n] = b }
		  tot[b]++; if ($6 == "inline") inl[b]++; if ($7 == 0) eq[b]++; ns[b, $2 " " $3] = $4 " (" $5 ")" }
		END { for (i = 1; i <= n; i++) { b = o[i]
			printf "| %s | %d of %d | %d of %d | %s / %s | %s | %s | %s |\n", b, inl[b], tot[b], eq[b], tot[b],
				ns[b, "duff_branchless float"], ns[b, "duff_branchless double"], ns[b, "hughes_moeller float"],
				ns[b, "pbrt_v3 float"], ns[b, "frisvad float"] } }'
} > "$out/summary.md"
cat "$out/summary.md"
