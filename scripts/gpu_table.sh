#!/bin/sh
# gpu_table.sh [--check] - docs/gpu.md's table of findings, its list of
# full-budget runs and the README's GPU headline, from the committed runs
# results/gpu/PROFILE/certify.csv (made by `onbstudy certify --quick --arith
# PROFILE --methods ...`) and results/gpu/full/PROFILE/certify.csv (the full
# budget, where run; run.txt beside it: wall, CPU, load); their headers say
# how.  Writes all three between their markers, or with --check exits 1 when
# one differs from what the runs give.  Either way it exits 1 when a region
# of a full run has a looser bound than the --quick region that holds it
# (the full budget must never prove less).  GPU_RESULTS=DIR reads DIR in
# place of results/gpu (tests/arith.sh).  docs/gpu.md's binary16 table comes
# from DIR/half/PROFILE/certify-half.csv (`certify --quick --precision half
# --arith PROFILE`).
set -eu
cd "$(dirname "$0")/.."
P="ieee vulkan vulkan-precise d3d11 opencl cuda-fast contract-any"
ONBSTUDY=${ONBSTUDY:-./onbstudy}
R=${GPU_RESULTS:-results/gpu}
# the whole-sphere row of each method and precision: bound, found (in u), status, unbounded_by, found input
rows() { rows_of "$R/$1/certify.csv" "$1"; }
# the same of the full-budget run, nothing where there is none
frows() { [ -f "$R/full/$1/certify.csv" ] || return 0; rows_of "$R/full/$1/certify.csv" "$1"; }
rows_of() { grep -v '^#' "$1" | awk -F, -v p="$2" 'NR > 1 && $3 == -1 && $4 == 1 && $5 == 0 && $6 == 360 {
	u = $2 == "float" ? 2^-24 : 2^-53
	b = $7 == "inf" ? ($12 == "unbounded" ? "unbounded (" $17 ")" : ($12 == "singular" ? "singular" : "inf")) : sprintf("%.3g", $7 / u)
	printf "%s|%s|%s|%s|%.3g|%s\n", $1, $2, p, b, $8 / u, ($9 == "" ? "" : "(" $9 ", " $10 ", " $11 ")") }'; }
table() {
	echo "Whole-sphere bound / found defect in units of u (2^-24 float, 2^-53 double), --quick runs"
	echo "(40 boxes per region: brackets are wide; a bound is proven for every input, found is a"
	echo "defect an emulated conforming implementation or the IEEE kernel reached).  **full:** the"
	echo "same at the full budget (results/gpu/full/PROFILE: 6000 boxes per region, the committed"
	echo "IEEE run's options), where that run exists ([below](#full-budget-runs))."
	echo
	printf '| method | prec |'; for p in $P; do printf ' %s |' "$p"; done; echo
	printf '|---|---|'; for p in $P; do printf -- '---|'; done; echo
	for p in $P; do rows "$p" | sed 's/^/q|/'; frows "$p" | sed 's/^/f|/'; done | sort -t'|' -k2,2 -k3,3 -s | awk -F'|' -v P="$P" '
		function c(b, f) { return b ~ /^[0-9]/ ? b " / " f : b }
		{ k = $2 "|" $3; if (!(k in seen)) { seen[k] = 1; order[n++] = k }
		  if ($1 == "q") cell[k "|" $4] = c($5, $6); else full[k "|" $4] = c($5, $6) }
		END { np = split(P, ps, " "); for (i = 0; i < n; i++) { split(order[i], a, "|"); printf "| %s | %s |", a[1], a[2]
			for (j = 1; j <= np; j++) { x = order[i] "|" ps[j]; printf " %s%s |", (x in cell) ? cell[x] : "-", (x in full) ? "; **full:** " full[x] : "" }
			printf "\n" } }'
}
# the whole-sphere bound of method $2, precision $3 under profile $1 for the
# headline: the full run's where it has the row ("12 u (full budget; --quick: 18.8 u)"),
# else the --quick run's
hb() {
	q=$(rows "$1" | awk -F'|' -v m="$2" -v x="$3" '$1 == m && $2 == x { print $4 }')
	f=$(frows "$1" | awk -F'|' -v m="$2" -v x="$3" '$1 == m && $2 == x { print $4 }')
	if [ -n "$f" ]; then echo "$f u (full budget; --quick: $q u)"; else echo "$q u (--quick)"; fi
}
# binary16: each method's regions of results/gpu/half/PROFILE/certify-half.csv
# (certify --precision half writes no whole-sphere row) into one cell:
# the largest bound / found in u = 2^-11, or why there is no bound
PH="ieee vulkan vulkan-precise opencl cuda-fast contract-any"
hrows() { [ -f "$R/half/$1/certify-half.csv" ] || return 0; grep -v '^#' "$R/half/$1/certify-half.csv" | awk -F, -v p="$1" 'NR > 1 {
	m = $1; if (!(m in seen)) { seen[m] = 1; order[n++] = m; b[m] = 0; f[m] = 0 }
	if ($7 == "inf") inf[m] = 1; else if ($7 + 0 > b[m]) b[m] = $7 + 0
	if ($8 != "inf" && $8 + 0 > f[m]) f[m] = $8 + 0
	if ($12 == "non-finite") nf[m] = 1
	if ($12 == "overflow") ov[m] = 1
	if ($12 == "unbounded" && NF >= 15 && $15 != "" && !(m in op)) op[m] = $15 }
	END { u = 2^-11; for (i = 0; i < n; i++) { m = order[i]
		c = nf[m] ? "non-finite" : ov[m] ? "overflow" : inf[m] ? "unbounded" (m in op ? " (" op[m] ")" : "") : sprintf("%.3g / %.3g", b[m] / u, f[m] / u)
		printf "%s|%s|%s\n", m, p, c } }'; }
htable() {
	echo "Binary16: the largest bound / found defect over each method's regions, in u = 2^-11,"
	echo "\`onbstudy certify --quick --precision half --arith PROFILE\` (results/gpu/half/; found: the"
	echo "IEEE half kernel's scan).  non-finite: the IEEE half kernel returns a NaN or an infinity on"
	echo "a rounded unit input; unbounded (OP): the profile gives operation OP no bound there;"
	echo "unbounded: an enclosure reaches a division by 0 or a pole (an underflowing or flushed"
	echo "squared length).  d3d11 has no binary16 row (min16float: no operation precision)."
	echo
	printf '| method |'; for p in $PH; do printf ' %s |' "$p"; done; echo
	printf '|---|'; for p in $PH; do printf -- '---|'; done; echo
	for p in $PH; do hrows "$p"; done | sort -t'|' -k1,1 -s | awk -F'|' -v P="$PH" '
		{ if (!($1 in seen)) { seen[$1] = 1; order[n++] = $1 } cell[$1 "|" $2] = $3 }
		END { np = split(P, ps, " "); for (i = 0; i < n; i++) { printf "| %s |", order[i]
			for (j = 1; j <= np; j++) printf " %s |", cell[order[i] "|" ps[j]]; printf "\n" } }'
}
headline() {
	d=$(rows ieee | awk -F'|' '$1 == "duff" && $2 == "float" { print $4 }')
	h=$(rows ieee | awk -F'|' '$1 == "hughes_moeller" && $2 == "float" { print $4 }')
	v=$(hb vulkan duff float); hv=$(hb vulkan hughes_moeller float); dd=$(hb vulkan duff double); d3=$(hb d3d11 duff double)
	echo "- **On every conforming Vulkan device** (docs/gpu.md: each operation anywhere within the spec's allowance, flushing, contraction): Duff's float basis is proven within ${v} (IEEE, --quick: ${d} u), Hughes-Möller's within ${hv} (IEEE, --quick: ${h} u), and a double kernel only to float accuracy (Duff: ${dd}, in units of double); Direct3D 11, whose Shader Model 5 has no double square root, leaves every kernel with a double sqrt unbounded (Duff's double basis: ${d3}, in units of double) (\`onbstudy certify --arith PROFILE\`, results/gpu/)."
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
# the same at the full budget, "bound / found" or "not run"
ffull() { frows "$1" | awk -F'|' -v m="$2" '$1 == m && $2 == "float" { print ($4 ~ /^[0-9]/ ? $4 " u / " $5 " u" : $4); f = 1 } END { if (!f) print "not run" }'; }
# lavapipe's largest defect D on unit inputs for the engine's own lines (results/lavapipe/report.md)
lvp() { awk -F'|' -v e="\`$1\`" -v e0="$1" '$2 ~ "^ " e " $" && $4 ~ /`/ && NF >= 12 && $11 ~ /inside|outside/ { gsub(/ /, "", $11); gsub(/ /, "", $9); if ($9 ~ /inf/) printf "D = inf at its singular inputs; %s of its regions\x27 bounds\n", $11; else printf "D = %.3g u (%s)\n", $9 / 2^-24, $11; f = 1; exit } END { if (!f) print "not run (no src/gpu/wild/" e0 ".glsl)" }' results/lavapipe/report.md; }
engines() {
	echo "Every shader engine of docs/wild.md (the registry's rows in GLSL, HLSL or Slang) under the"
	echo "profile of its language (GLSL: vulkan; HLSL: d3d11; Slang, which targets both: each), float,"
	echo "whole-sphere bound / found in u = 2^-24 (results/gpu, --quick; results/gpu/full, the full budget), and its own lines on lavapipe"
	echo "(results/lavapipe/report.md, \`onbstudy-gpu wild\`: the largest defect D on unit inputs, in u,"
	echo "and whether every unit input is inside the C row's IEEE bound at that input)."
	echo
	echo "| engine | its code | C row | profile | IEEE bound | bound under the profile | found under the profile | full budget: bound / found | lavapipe, its own lines |"
	echo "|---|---|---|---|---|---|---|---|---|"
	shader_rows | sort | while IFS='|' read -r e row lang code; do
		for p in vulkan d3d11; do
			case "$p/$lang" in vulkan/*GLSL*|vulkan/*Slang*|d3d11/*HLSL*|d3d11/*Slang*) ;; *) continue ;; esac
			printf '| `%s` | %s (%s) | `%s` | `%s` | %s | %s | %s | %s | %s |\n' "$e" "$code" "$lang" "$row" "$p" \
				"$(fbound ieee "$row")" "$(fbound "$p" "$row")" "$(ffound "$p" "$row")" "$(ffull "$p" "$row")" "$(lvp "$e")"
		done
	done
}
# the methods of a run, in its order
methods_of() { grep -v '^#' "$1" | awk -F, 'NR > 1 && !($1 in s) { s[$1] = 1; printf "%s%s", n++ ? "," : "", $1 } END { print "" }'; }
# the methods a full run of profile $1 should hold: its --quick run's, and
# the C rows of the shader engines of its language (vulkan: GLSL and Slang,
# d3d11: HLSL and Slang)
planned() {
	{ methods_of "$R/$1/certify.csv" | tr , '\n'
	  case $1 in vulkan) l='GLSL|Slang' ;; d3d11) l='HLSL|Slang' ;; *) l='^$' ;; esac
	  shader_rows | awk -F'|' -v l="$l" '$3 ~ l { print $2 }'; } | awk 'NF && !($0 in s) { s[$0] = 1; printf "%s%s", n++ ? "," : "", $0 } END { print "" }'
}
# one line of results/gpu/full/PROFILE/run.txt ("wall: 1234 s")
runinfo() { sed -n "s/^$2: //p" "$R/full/$1/run.txt" | head -1; }
fulls() {
	echo "Full-budget runs (\`onbstudy certify --arith PROFILE --starts results/certify/starts.csv\`,"
	echo "the committed IEEE run's budget: 6000 boxes, 1000 samples, 8 sectors per band), one"
	echo "process (ranks 1, threads 2) on the shared 2-core machine; CPU is user + system"
	echo "seconds, wall and load say how busy the machine was.  The same command line with"
	echo "\`--resume DIR\` starts a run and continues it after a kill; \`--reuse\` takes the committed"
	echo "methods whose keys are current (same model, kernel and certify engine) and computes only the rest."
	echo
	for p in $P; do
		want=$(planned "$p")
		if [ "$p" = ieee ] && [ ! -f "$R/full/$p/certify.csv" ]; then
			echo "- \`ieee\`: every method at this budget is results/certify/certify.csv, the committed IEEE run (docs/certify.md; an older revision than the --quick runs, so not in the table)."
		elif [ -f "$R/full/$p/certify.csv" ]; then
			have=$(methods_of "$R/full/$p/certify.csv")
			todo=$(echo "$want" | tr , '\n' | awk -v h=",$have," 'NF && index(h, "," $0 ",") == 0' | paste -sd, -)
			echo "- \`$p\`: **run**, $(echo "$have" | tr , '\n' | wc -l | tr -d ' ') methods ($have), both precisions, at revision $(runinfo "$p" revision):"
			echo "  wall $(runinfo "$p" wall), CPU $(runinfo "$p" cpu), ranks $(runinfo "$p" ranks), threads $(runinfo "$p" threads), load $(runinfo "$p" load) (results/gpu/full/$p/run.txt)."
			if [ -n "$todo" ]; then
				echo "  Still to run: $todo.  To add them: \`./onbstudy certify --arith $p --methods $have,$todo --starts results/certify/starts.csv --reuse results/gpu/full/$p --resume /tmp/full-$p\`"
			fi
		else
			echo "- \`$p\`: **not run**.  To run (and to resume, the same command): \`./onbstudy certify --arith $p --methods $want --starts results/certify/starts.csv --resume /tmp/full-$p\`"
		fi
	done
}
# the whole-sphere brackets of the full runs still wider than 1.25x, and
# which side is loose, from the region data: the region that sets the
# bound (its band and sector), how many sectors of its band stop at exactly
# that bound (all of them: a floor of the profile's error model, which
# more boxes do not lower), and how bound and found moved from the --quick
# run (40 boxes, 150 samples) to the full one (6000 boxes, 1000 samples)
brackets() {
	echo "Whole-sphere brackets of the full runs still above 1.25x (bound / found > 1.25), in u;"
	echo "*region*: the region that sets the bound (the first in the file), its own bound / found and"
	echo "status; *floor*: how many sectors of its band stop at exactly that bound; *moved*: bound and"
	echo "found from the --quick run to the full one.  *Loose side*, read from these: **floor** where"
	echo "every sector of the band stops at one value: the bound has converged to the profile's"
	echo "first-order worst case (each operation's allowance times its weight, an ulp counted as 2u"
	echo "relative), so no budget lowers it; the gap is that model's slack (the ulp of the exact"
	echo "result's binade read at its widest, every allowance at its extreme at once) and the found"
	echo "side's (one greedy adversarial pass at 4 inputs per region), which a larger budget cannot"
	echo "separate.  **bound** where the bound still fell by more than 2% while found stayed within"
	echo "2%; **found** where found still rose by more than 10% while the bound stood within 2%;"
	echo "**both** otherwise.  A --quick bound of inf (no finite bound at 40 boxes) counts as a fall of 100%."
	echo
	echo "| profile | method | prec | full: bound / found | ratio | quick ratio | region: nz, phi | its bound / found, status | floor | moved: bound, found | loose side |"
	echo "|---|---|---|---|---|---|---|---|---|---|---|"
	for p in $P; do
		[ -f "$R/full/$p/certify.csv" ] || continue
		{ rows "$p" | sed 's/^/q|/'; grep -v '^#' "$R/full/$p/certify.csv" | tr , '|' | sed 's/^/f|/'; } | awk -F'|' -v p="$p" '
			$1 == "q" { qb[$2 "|" $3] = $5; qf[$2 "|" $3] = $6; next }
			$2 == "method" { next }
			{ k = $2 "|" $3 }
			$4 == -1 && $5 == 1 && $6 == 0 && $7 == 360 { wb[k] = $8; wf[k] = $9; ws[k] = $13; order[n++] = k; next }
			{ m++; rk[m] = k; rlo[m] = $4; rhi[m] = $5; rpl[m] = $6; rph[m] = $7; rb[m] = $8; rf[m] = $9; rs[m] = $13 }
			END { for (i = 0; i < n; i++) { k = order[i]; split(k, a, "|"); u = a[2] == "float" ? 2^-24 : 2^-53
				if (wb[k] == "inf" || wf[k] + 0 <= 0 || wb[k] / wf[k] <= 1.25) continue
				for (j = 1; j <= m; j++) if (rk[j] == k && rb[j] == wb[k]) break
				eq = 0; nb = 0; for (l = 1; l <= m; l++) if (rk[l] == k && rlo[l] == rlo[j] && rhi[l] == rhi[j]) { nb++; if (rb[l] == wb[k]) eq++ }
				q = qb[k] ~ /^[0-9]/; qi = qb[k] == "inf"; db = q ? (wb[k] / u - qb[k]) / qb[k] : (qi ? -1 : 0); df = q || qi ? (wf[k] / u - qf[k]) / qf[k] : 0
				side = eq == nb && nb > 1 ? "floor" : (!q && !qi ? "not read (no --quick run)" : (db < -0.02 && df < 0.02 ? "bound" : (df > 0.1 && db > -0.02 ? "found" : "both")))
				mv = q ? sprintf("%+.0f%%, %+.0f%%", 100 * db, 100 * df) : (qi ? sprintf("from inf, %+.0f%%", 100 * df) : "no --quick run")
				printf "| `%s` | %s | %s | %.3g / %.3g | %.2f | %s | [%.6g, %.6g], [%s, %s] | %.3g / %.3g, %s | %d of %d | %s | %s |\n", p, a[1], a[2], wb[k] / u, wf[k] / u, wb[k] / wf[k],
					q ? sprintf("%.2f", qb[k] / qf[k]) : (qb[k] != "" ? qb[k] : "-"), rlo[j], rhi[j], rpl[j], rph[j], rb[j] / u, rf[j] / u, rs[j], eq, nb, mv, side } }'
	done
}
# every region of a full run against the --quick region that holds it (the
# same band, the sector that contains its own): a looser full bound is a bug,
# unless the full region is proven: its branch and bound stopped as soon as
# the bound was within 1.25x of its found (a higher found than --quick's, so
# often at fewer, larger boxes than --quick split into), and a looser bound
# there is that stop, marked "(proven: stopped at its target)"
looser() {
	for p in $P; do
		[ -f "$R/full/$p/certify.csv" ] || continue
		{ grep -v '^#' "$R/$p/certify.csv" | sed 's/^/q,/'; grep -v '^#' "$R/full/$p/certify.csv" | sed 's/^/f,/'; } | awk -F, -v p="$p" '
			$2 == "method" { next }
			$1 == "q" { k = $2 SUBSEP $3 SUBSEP $4 SUBSEP $5; n[k]++; lo[k, n[k]] = $6; hi[k, n[k]] = $7; b[k, n[k]] = $8; next }
			{ k = $2 SUBSEP $3 SUBSEP $4 SUBSEP $5
			  for (i = 1; i <= n[k]; i++) if (lo[k, i] + 0 <= $6 + 0 && $7 + 0 <= hi[k, i] + 0) {
				if (b[k, i] != "inf" && ($8 == "inf" || $8 + 0 > b[k, i] + 0))
					printf "gpu_table.sh: %s %s %s nz [%s, %s] phi [%s, %s]: full-budget bound %s looser than the --quick bound %s%s\n", p, $2, $3, $4, $5, $6, $7, $8, b[k, i],
					       $13 == "proven" && $8 != "inf" ? " (proven: stopped at its target)" : ""
				break } }'
	done
}
replace() { # FILE BEGIN END TEXTFILE
	awk -v b="$2" -v e="$3" -v t="$4" '$0 == b { print; while ((getline l < t) > 0) print l; skip = 1; next } $0 == e { skip = 0 } !skip' "$1"
}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
table > "$T/table"; headline > "$T/head"; engines > "$T/engines"; fulls > "$T/fulls"; htable > "$T/half"; brackets > "$T/brackets"
looser > "$T/looser"
replace docs/gpu.md '<!-- gpu-table: begin (scripts/gpu_table.sh) -->' '<!-- gpu-table: end -->' "$T/table" > "$T/gpu0.md"
replace "$T/gpu0.md" '<!-- gpu-engines: begin (scripts/gpu_table.sh) -->' '<!-- gpu-engines: end -->' "$T/engines" > "$T/gpu1.md"
replace "$T/gpu1.md" '<!-- gpu-half: begin (scripts/gpu_table.sh) -->' '<!-- gpu-half: end -->' "$T/half" > "$T/gpu2.md"
replace "$T/gpu2.md" '<!-- gpu-full: begin (scripts/gpu_table.sh) -->' '<!-- gpu-full: end -->' "$T/fulls" > "$T/gpu3.md"
replace "$T/gpu3.md" '<!-- gpu-brackets: begin (scripts/gpu_table.sh) -->' '<!-- gpu-brackets: end -->' "$T/brackets" > "$T/gpu.md"
# the looser regions already reported (results/gpu/full/known-looser.txt, one
# line each as printed here) are listed in docs/gpu.md; any other fails
K="$R/full/known-looser.txt"; touch "$T/known"; [ -f "$K" ] && grep -v '^#' "$K" > "$T/known" || true
grep -v -x -F -f "$T/known" "$T/looser" | grep -v ' (proven: stopped at its target)$' > "$T/new" || true
if [ -s "$T/new" ]; then cat "$T/new" >&2; echo "gpu_table.sh: a full-budget bound looser than the --quick one (a bug in certify or a stale run)" >&2; exit 1; fi
{ echo "Full-budget regions with a looser bound than the --quick region holding it (a looser region with status budget fails this script unless results/gpu/full/known-looser.txt lists it as an open finding; a proven one stopped at its target, bound <= 1.25 found, with fewer boxes than --quick split into: allowed, below):"; echo
  if [ -s "$T/looser" ]; then sed 's/^gpu_table.sh: /- /' "$T/looser"; else echo "- none"; fi; } > "$T/anom"
replace "$T/gpu.md" '<!-- gpu-looser: begin (scripts/gpu_table.sh) -->' '<!-- gpu-looser: end -->' "$T/anom" > "$T/gpu4.md"; mv "$T/gpu4.md" "$T/gpu.md"
replace README.md '<!-- gpu-headline: begin (scripts/gpu_table.sh) -->' '<!-- gpu-headline: end -->' "$T/head" > "$T/README.md"
if [ "${1:-}" = --check ]; then
	cmp -s "$T/gpu.md" docs/gpu.md && cmp -s "$T/README.md" README.md && { echo "gpu_table.sh: docs/gpu.md and README.md match results/gpu"; exit 0; }
	echo "gpu_table.sh: docs/gpu.md or README.md differs from results/gpu (run sh scripts/gpu_table.sh)" >&2; exit 1
fi
cp "$T/gpu.md" docs/gpu.md; cp "$T/README.md" README.md
echo "gpu_table.sh: wrote docs/gpu.md's table and README.md's headline"
