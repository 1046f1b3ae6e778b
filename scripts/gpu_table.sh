#!/bin/sh
# gpu_table.sh [--check] - docs/gpu.md's table of findings and the
# README's GPU headline, from the committed runs results/gpu/PROFILE/certify.csv
# (made by `onbstudy certify --quick --arith PROFILE --methods ...`, their
# headers say how).  Writes both between their markers, or with --check
# exits 1 when either differs from what the runs give.
set -eu
cd "$(dirname "$0")/.."
P="ieee vulkan vulkan-precise d3d11 opencl cuda-fast contract-any"
ONBSTUDY=${ONBSTUDY:-./onbstudy}
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
	d3=$(rows d3d11 | awk -F'|' '$1 == "duff" && $2 == "double" { print $4 }')
	echo "- **On every conforming Vulkan device** (docs/gpu.md: each operation anywhere within the spec's allowance, flushing, contraction): Duff's float basis is proven within ${v} u (IEEE: ${d} u), Hughes-Möller's within ${hv} u (IEEE: ${h} u), and a double kernel only to float accuracy (Duff: ${dd} u of double); Direct3D 11, whose Shader Model 5 has no double square root, leaves every kernel with a double sqrt unbounded (Duff's double basis: ${d3} u of double) (\`onbstudy certify --quick --arith PROFILE\`, results/gpu/)."
}
# the registry's shader engines (language GLSL, HLSL or Slang; methods and
# aliases of `onbstudy list --format csv`, `--aliases --format csv`):
# name|C row|language|code
shader_rows() {
	{ "$ONBSTUDY" list --format csv | awk -v kind=method "$CSV"'NR > 1 { split_csv($0, f); print f[1] "|" f[1] "|" f[13] "|" f[9] " " substr(f[10], 1, 8) " " f[11] }'
	  "$ONBSTUDY" list --aliases --format csv | awk -v kind=alias "$CSV"'NR > 1 { split_csv($0, f); print f[1] "|" f[2] "|" f[10] "|" f[6] " " substr(f[7], 1, 8) " " f[8] }'
	} | awk -F'|' '$3 ~ /GLSL|HLSL|Slang/' | sed 's|github.com/||'
}
# a quoted CSV line into f[1..n] (awk has no CSV mode)
CSV='function split_csv(l, f,   n, q, c, i, cur) { n = 0; q = 0; cur = ""
	for (i = 1; i <= length(l); i++) { c = substr(l, i, 1)
		if (c == "\"") q = !q; else if (c == "," && !q) { f[++n] = cur; cur = "" } else cur = cur c }
	f[++n] = cur; return n }
'
# the float whole-sphere bound of method $2 under profile $1, in u: "6.04" or "unbounded (sqrt)"
fbound() { rows "$1" | awk -F'|' -v m="$2" '$1 == m && $2 == "float" { print ($4 ~ /^[0-9]/ ? $4 " u" : $4); f = 1 } END { if (!f) print "not run" }'; }
ffound() { rows "$1" | awk -F'|' -v m="$2" '$1 == m && $2 == "float" { print $5 " u" }'; }
# lavapipe's largest defect D on unit inputs for the engine's own lines (results/lavapipe/report.md)
lvp() { awk -F'|' -v e="\`$1\`" -v e0="$1" '$2 ~ "^ " e " $" && $4 ~ /`/ && NF >= 12 && $11 ~ /inside|outside/ { gsub(/ /, "", $11); gsub(/ /, "", $9); if ($9 ~ /inf/) printf "D = inf at its singular inputs; %s of its regions\x27 bounds\n", $11; else printf "D = %.3g u (%s)\n", $9 / 2^-24, $11; f = 1; exit } END { if (!f) print "not run (no src/gpu/wild/" e0 ".glsl)" }' results/lavapipe/report.md; }
engines() {
	echo "Every shader engine of docs/wild.md (the registry's rows in GLSL, HLSL or Slang) under the"
	echo "profile of its language (GLSL: vulkan; HLSL: d3d11; Slang, which targets both: each), float,"
	echo "whole-sphere bound / found in u = 2^-24 (results/gpu, --quick), and its own lines on lavapipe"
	echo "(results/lavapipe/report.md, \`onbstudy-gpu wild\`: the largest defect D on unit inputs, in u,"
	echo "and whether every unit input is inside the C row's IEEE bound at that input)."
	echo
	echo "| engine | its code | C row | profile | IEEE bound | bound under the profile | found under the profile | lavapipe, its own lines |"
	echo "|---|---|---|---|---|---|---|---|"
	shader_rows | sort | while IFS='|' read -r e row lang code; do
		for p in vulkan d3d11; do
			case "$p/$lang" in vulkan/*GLSL*|vulkan/*Slang*|d3d11/*HLSL*|d3d11/*Slang*) ;; *) continue ;; esac
			printf '| `%s` | %s (%s) | `%s` | `%s` | %s | %s | %s | %s |\n' "$e" "$code" "$lang" "$row" "$p" \
				"$(fbound ieee "$row")" "$(fbound "$p" "$row")" "$(ffound "$p" "$row")" "$(lvp "$e")"
		done
	done
}
replace() { # FILE BEGIN END TEXTFILE
	awk -v b="$2" -v e="$3" -v t="$4" '$0 == b { print; while ((getline l < t) > 0) print l; skip = 1; next } $0 == e { skip = 0 } !skip' "$1"
}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
table > "$T/table"; headline > "$T/head"; engines > "$T/engines"
replace docs/gpu.md '<!-- gpu-table: begin (scripts/gpu_table.sh) -->' '<!-- gpu-table: end -->' "$T/table" > "$T/gpu0.md"
replace "$T/gpu0.md" '<!-- gpu-engines: begin (scripts/gpu_table.sh) -->' '<!-- gpu-engines: end -->' "$T/engines" > "$T/gpu.md"
replace README.md '<!-- gpu-headline: begin (scripts/gpu_table.sh) -->' '<!-- gpu-headline: end -->' "$T/head" > "$T/README.md"
if [ "${1:-}" = --check ]; then
	cmp -s "$T/gpu.md" docs/gpu.md && cmp -s "$T/README.md" README.md && { echo "gpu_table.sh: docs/gpu.md and README.md match results/gpu"; exit 0; }
	echo "gpu_table.sh: docs/gpu.md or README.md differs from results/gpu (run sh scripts/gpu_table.sh)" >&2; exit 1
fi
cp "$T/gpu.md" docs/gpu.md; cp "$T/README.md" README.md
echo "gpu_table.sh: wrote docs/gpu.md's table and README.md's headline"
