#!/bin/sh
# gpu_table.sh [--check] - docs/gpu.md's table of findings and the
# README's GPU headline, from the committed runs results/gpu/PROFILE/certify.csv
# (made by `onbstudy certify --quick --arith PROFILE --methods ...`, their
# headers say how).  Writes both between their markers, or with --check
# exits 1 when either differs from what the runs give.
set -eu
cd "$(dirname "$0")/.."
P="ieee vulkan vulkan-precise d3d11 opencl cuda-fast contract-any"
# the whole-sphere row of each method and precision: bound, found (in u), status, unbounded_by, found input
rows() { grep -v '^#' "results/gpu/$1/certify.csv" | awk -F, -v p="$1" 'NR > 1 && $3 == -1 && $4 == 1 && $5 == 0 && $6 == 360 {
	u = $2 == "float" ? 2^-24 : 2^-53
	b = $7 == "inf" ? ($12 == "unbounded" ? "unbounded (" $17 ")" : ($12 == "singular" ? "singular" : "inf")) : sprintf("%.3g", $7 / u)
	printf "%s|%s|%s|%s|%.3g|%s\n", $1, $2, p, b, $8 / u, ($9 == "" ? "" : "(" $9 ", " $10 ", " $11 ")") }'; }
table() {
	echo "Whole-sphere bound / found defect in units of u (2^-24 float, 2^-53 double), --quick runs"
	echo "(40 boxes per region: brackets are wide; a bound is proven for every input, found is a"
	echo "defect an emulated conforming implementation or the IEEE kernel reached)."
	echo
	printf '| method | prec |'; for p in $P; do printf ' %s |' "$p"; done; echo
	printf '|---|---|'; for p in $P; do printf -- '---|'; done; echo
	for p in $P; do rows "$p"; done | sort -t'|' -k1,1 -k2,2 -s | awk -F'|' -v P="$P" '
		{ k = $1 "|" $2; if (!(k in seen)) { seen[k] = 1; order[n++] = k } cell[k "|" $3] = ($4 ~ /^[0-9]/ ? $4 " / " $5 : $4) }
		END { np = split(P, ps, " "); for (i = 0; i < n; i++) { split(order[i], a, "|"); printf "| %s | %s |", a[1], a[2]
			for (j = 1; j <= np; j++) printf " %s |", cell[order[i] "|" ps[j]]; printf "\n" } }'
}
headline() {
	d=$(rows ieee | awk -F'|' '$1 == "duff" && $2 == "float" { print $4 }')
	v=$(rows vulkan | awk -F'|' '$1 == "duff" && $2 == "float" { print $4 }')
	h=$(rows ieee | awk -F'|' '$1 == "hughes_moeller" && $2 == "float" { print $4 }')
	hv=$(rows vulkan | awk -F'|' '$1 == "hughes_moeller" && $2 == "float" { print $4 }')
	dd=$(rows vulkan | awk -F'|' '$1 == "duff" && $2 == "double" { print $4 }')
	echo "- **On every conforming Vulkan device** (docs/gpu.md: each operation anywhere within the spec's allowance, flushing, contraction): Duff's float basis is proven within ${v} u (IEEE: ${d} u), Hughes-Möller's within ${hv} u (IEEE: ${h} u), and a double kernel only to float accuracy (Duff: ${dd} u of double); Direct3D 11 leaves every double and every float kernel that computes in double unbounded (\`onbstudy certify --quick --arith PROFILE\`, results/gpu/)."
}
replace() { # FILE BEGIN END TEXTFILE
	awk -v b="$2" -v e="$3" -v t="$4" '$0 == b { print; while ((getline l < t) > 0) print l; skip = 1; next } $0 == e { skip = 0 } !skip' "$1"
}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
table > "$T/table"; headline > "$T/head"
replace docs/gpu.md '<!-- gpu-table: begin (scripts/gpu_table.sh) -->' '<!-- gpu-table: end -->' "$T/table" > "$T/gpu.md"
replace README.md '<!-- gpu-headline: begin (scripts/gpu_table.sh) -->' '<!-- gpu-headline: end -->' "$T/head" > "$T/README.md"
if [ "${1:-}" = --check ]; then
	cmp -s "$T/gpu.md" docs/gpu.md && cmp -s "$T/README.md" README.md && { echo "gpu_table.sh: docs/gpu.md and README.md match results/gpu"; exit 0; }
	echo "gpu_table.sh: docs/gpu.md or README.md differs from results/gpu (run sh scripts/gpu_table.sh)" >&2; exit 1
fi
cp "$T/gpu.md" docs/gpu.md; cp "$T/README.md" README.md
echo "gpu_table.sh: wrote docs/gpu.md's table and README.md's headline"
