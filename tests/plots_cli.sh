#!/bin/sh
# plots_cli.sh - every chart script on a small fixture run:
# `make plots` (with a tiny pole-cap run) and scripts/poles.sh, every chart
# as PNG and SVG, gnuplot without a warning (plots.sh fails on one), and
# scripts/chart-check.awk on every SVG, gnuplot's own output:
#   - no text (title, axis label, tick label, key entry, label) leaves the
#     canvas or overlaps another;
#   - every graph has an x and a y label (the small-multiple maps: their
#     one shared axis note);
#   - no series with a key title draws nothing unless its title says
#     "no finite point".
#   - no text lies over a drawn line segment or marker of a series;
#   - every accuracy-floor band names methods drawn in its own panel;
#   - no two series of one plot share a colour, nor two floor bands a
#     colour and fill; (line charts) no two methods of a plot share a
#     dash and a marker;
# that the tradeoff chart's Pareto circles are onbstudy table's (a file
# whose pareto column breaks the table's rule is refused);
# and the colours of scripts/styles.sh: within a hue group every two
# shades differ by a CIELAB delta-E of at least 15, none is near-black,
# duff and duff_branchless share a group and sit side by side; the
# palette (scripts/palette.sh --check: any two methods 10 apart, none
# near-black, each with a dash and point pair of its own, fails on broken
# tables) and a method's colour the same in runs that hold different
# methods.
# Not checked mechanically, and why:
#   - a text over a filled area or an image (a map's cells): only lines
#     and markers are data paths in gnuplot's SVG;
#   - text widths are estimated from the font size (0.56 em a character):
#     SVG has no metrics, so a near miss of a pixel or two can pass;
#   - diagonal texts (the bar chart's method names) are checked against the
#     canvas only: their bounding boxes overlap by construction;
#   - colours (colour-blind safety, contrast) are a property of the palette
#     in styles.sh and style.gp, not of one run;
#   - the difference renders (examples/aorender.c) are checked for size in
#     tests/render_obj.sh; their legend is drawn in pixels, not text.
# A hand-made defective chart checks that the checker catches each defect.
. "$(dirname "$0")/lib.sh"
T=$tmp
if ! command -v gnuplot >/dev/null 2>&1; then
	echo "plots_cli: gnuplot missing: scripts/install-deps.sh --test must install it"; exit 1
fi
# without a run's data, `make plots` says so at once (exit 2), building and
# installing nothing (B= a fresh build directory stays absent)
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory plots RUN="$T/none" B="$T/nob" > "$T/log" 2>&1
rc=$?
[ $rc -eq 2 ] && grep -q 'run a sweep first' "$T/log" && [ ! -e "$T/nob" ] && ok ||
	bad "make plots without a run: exit $rc, $(cat "$T/log")"
./onbstudy sweep --samples 2000 --exhaustive-count 1024 --azimuths 2 --grid 8x16 --quiet --out "$T/run" >/dev/null 2>&1 || bad "small sweep failed"
./onbstudy threshold --logspaced 300 --consecutive 256 --azimuths 4 --out "$T/run" >/dev/null 2>&1 || bad "threshold failed"
if [ -x ./onbstudy ] && ./onbstudy bench --help >/dev/null 2>&1; then
	# the table joins the committed reference bench, not this run's: the
	# chart check's label layout must not depend on a shared machine's
	# timings (a live bench once put two front labels on one spot); the
	# live bench is still run, and its table made, to check they work
	./onbstudy bench --quick --out "$T/bench" >/dev/null 2>&1 && ./onbstudy table --bench "$T/bench/bench.csv" --summary "$T/run/summary.csv" --out "$T/bench" >/dev/null 2>&1 || bad "bench/table failed"
	./onbstudy table --bench results/reference/bench.csv --summary "$T/run/summary.csv" --out "$T/run" >/dev/null 2>&1 || bad "table of the committed bench failed"
fi
NZ=6 AZ=4 sh scripts/polecap.sh "$T/pc" >/dev/null 2>&1 || bad "polecap.sh failed"
PCDIR="$T/pc" FIGS="$T/fig" make plots RUN="$T/run" > "$T/log" 2>&1 || bad "make plots failed: $(cat "$T/log")"
grep -qi warning "$T/log" && bad "gnuplot warned: $(grep -i warning "$T/log")" || ok
for P in float double; do
	for c in error_vs_nz error_vs_nz_rms south_pole maps continuity nonunit threshold; do
		for ext in png svg; do
			[ -s "$T/run/${c}_$P.$ext" ] && ok || bad "missing or empty ${c}_$P.$ext"
		done
	done
	if [ -f "$T/run/tradeoff.csv" ]; then
		[ -s "$T/run/tradeoff_$P.png" ] && ok || bad "missing tradeoff_$P.png"
	fi
done
for f in "$T/pc/polecap_float.svg" "$T/fig/polecap_frisvad_duff.svg" "$T/fig/south_pole_frisvad_duff_float.svg" "$T/fig/threshold_minimax_float.svg"; do
	[ -s "$f" ] && ok || bad "missing $f"
done
# the poles charts, on two tiny exhaustive runs
./onbstudy sweep --dists exhaustive --precision float --exhaustive-count 512 --azimuths 2 --quiet --out "$T/poles/south" >/dev/null 2>&1 &&
./onbstudy sweep --dists exhaustive --precision float --exhaustive-range 0.99999:1 --azimuths 2 --quiet --out "$T/poles/north" >/dev/null 2>&1 &&
SAMPLED="$T/none" sh scripts/poles.sh "$T/poles" >/dev/null 2>&1 && ok || bad "poles.sh failed"
# the chart check, on every SVG
n=0
for f in "$T"/run/*.svg "$T"/fig/*.svg "$T"/pc/*.svg "$T"/poles/*.svg; do
	[ -f "$f" ] || continue
	n=$((n + 1))
	case $(basename "$f") in maps_*) nl=1;; *) nl=0;; esac
	out=$(awk -v nolabels=$nl -f scripts/chart-check.awk "$f" 2>&1) && ok || bad "chart check: $out"
done
[ $n -ge 22 ] && ok || bad "chart check saw $n SVGs, expected at least 22"
# the checker catches each defect of a hand-made chart
printf '1 1\n2 2\n' > "$T/d.dat"
gnuplot -e "set terminal svg size 400,300; set output '$T/bad.svg'; set xlabel 'x label here'; \
	set label 1 'off the canvas on the right' at screen 0.9, screen 0.5; \
	set label 2 'overlapping one' at screen 0.2, screen 0.7; set label 3 'overlapping two' at screen 0.22, screen 0.7; \
	plot '$T/d.dat' using 1:2 with lines title 'drawn', '$T/d.dat' using 1:(1/0) with lines title 'empty'" 2>/dev/null
out=$(awk -f scripts/chart-check.awk "$T/bad.svg")
for want in "leaves the" "overlap" "no y label" "\"empty\" draws nothing"; do
	echo "$out" | grep -q "$want" && ok || bad "chart check missed: $want (it said: $out)"
done
echo "$out" | grep -q "no x label" && bad "chart check: a false x-label defect: $out" || ok
# a label over data, and floor bands that are another method's or nobody's
printf '1 1e-7\n2 1e-7\n' > "$T/f.dat"
gnuplot -e "set terminal svg size 500,400; set output '$T/bad2.svg'; set xlabel 'x label here'; set ylabel 'y label here'; set logscale y; \
	set label 1 'a label on the line' at 1.2, 1.25 front; set key outside top; \
	plot '$T/d.dat' using 1:2 with lines title 'frisvad', \
	'$T/f.dat' using 1:2:(\$2*2) with filledcurves title 'floor of duff_branchless' noenhanced, \
	'$T/f.dat' using 1:2:(\$2*2) with filledcurves title 'accuracy floor (RMS to max)', \
	'$T/f.dat' using 1:2:(\$2*2) with filledcurves title 'floor of all 3'" 2>/dev/null
out=$(awk -f scripts/chart-check.awk "$T/bad2.svg")
for want in "\"a label on the line\" lies over data (frisvad)" "floor of duff_branchless\" is the floor of duff_branchless, which its plot does not draw" \
	"\"accuracy floor (RMS to max)\" does not name whose floor" "\"floor of all 3\": its plot draws 1 methods"; do
	echo "$out" | grep -qF "$want" && ok || bad "chart check missed: $want (it said: $out)"
done
# the Pareto circles are onbstudy table's: tradeoff-data.sh redraws the
# front by the table's rule and refuses a file whose pareto column differs
if [ -f "$T/run/tradeoff.csv" ]; then
	: > "$T/cols"
	sh scripts/tradeoff-data.sh "$T/run/tradeoff.csv" float "$T" "$T/cols" && ok || bad "tradeoff-data.sh refused the table's own front"
	awk -F, 'BEGIN { OFS = "," } /^method,/ { for (i = 1; i <= NF; i++) if ($i == "pareto") c = i; print; next }
		!/^#/ && $2 == "float" && !done && $c == "0" { $c = "1"; done = 1 } { print }' "$T/run/tradeoff.csv" > "$T/bad_tradeoff.csv"
	sh scripts/tradeoff-data.sh "$T/bad_tradeoff.csv" float "$T" "$T/cols" 2>/dev/null && bad "tradeoff-data.sh drew a front that is not the table's" || ok
fi
# the shades: delta-E >= 15 within a group, nothing near-black, duff and
# duff_branchless adjacent in one group
sh scripts/styles.sh results/reference/summary.csv > "$T/sty" && ok || bad "styles.sh failed"
out=$(awk -f scripts/lab.awk -f /dev/stdin "$T/sty" <<'EOF2'
{ c[NR] = $3; g[NR] = $7; m[NR] = $1; if ($1 == "duff") dg = NR; if ($1 == "duff_branchless") db = NR }
END { for (i = 1; i <= NR; i++) { lab_of(c[i]); if (LAB_L < 25) printf "%s is near-black (L* %.0f)\n", m[i], LAB_L
		for (j = i + 1; j <= NR; j++) if (g[i] == g[j] && delta_e(c[i], c[j]) < 15) printf "%s and %s: delta-E %.1f\n", m[i], m[j], delta_e(c[i], c[j]) }
	if (!dg || !db || g[dg] != g[db] || db - dg != 1) print "duff and duff_branchless not adjacent in one group" }
EOF2
)
[ -z "$out" ] && ok || bad "shades: $out"
# the palette (scripts/palette.txt, one colour per method in every chart):
# any two colours apart by a delta-E of 10 and none near-black, or
# palette.sh --check fails: a table giving duff_wide duff's colour, one
# without jolt, one with a near-black row
out=$(sh scripts/palette.sh --check 2>&1) && ok || bad "$out"
sed 's/^duff_wide .*/duff_wide #0072b2/' scripts/palette.txt > "$T/p1.txt"
grep -v '^jolt ' scripts/palette.txt > "$T/p2.txt"
sed 's/^jolt .*/jolt #1a1a1a/' scripts/palette.txt > "$T/p3.txt"
# (and a method's line style, dash and point, its own: a table giving
# duff_wide duff's pair, one where jolt has no dash and point)
set -- $(awk '$1 == "duff" { print $3, $4 }' scripts/palette.txt)
sed "s/^\(duff_wide [^ ]*\) .*/\1 $1 $2/" scripts/palette.txt > "$T/p4.txt"
sed 's/^\(jolt [^ ]*\) .*/\1/' scripts/palette.txt > "$T/p5.txt"
cmp -s "$T/p4.txt" scripts/palette.txt && bad "p4: duff_wide's row not changed"
for p in p1 p2 p3 p4 p5; do PALETTE="$T/$p.txt" sh scripts/palette.sh --check > /dev/null 2>&1 && bad "palette.sh --check passed a broken table ($p)" || ok; done
# every method of the reference run drawn in its own dash and point
# (styles.sh column 4 and 5): no two share both
out=$(awk '{ k = $4 " " $5; b = $1; sub(/\+fma$/, "", b) } (k in s) && s[k] != b { printf "%s and %s: dash and point %s; ", s[k], $1, k } !(k in s) { s[k] = b }' "$T/sty")
[ -z "$out" ] && ok || bad "line styles shared: $out"
# a method keeps its colour whatever else a run holds: duff's in the whole
# reference run and in a run of duff and jolt alone is its palette row
awk -F, '/^#/ || $1 == "method" || $1 == "duff" || $1 == "jolt"' results/reference/summary.csv results/wild/summary.csv > "$T/two.csv"
sh scripts/styles.sh "$T/two.csv" > "$T/sty2"
p=$(awk '$1 == "duff" { print $2 }' scripts/palette.txt)
for f in sty sty2; do c=$(awk '$1 == "duff" { print $3 }' "$T/$f")
	[ -n "$c" ] && [ "$c" = "$p" ] && ok || bad "duff drawn in $c ($f), its palette colour is $p"; done
# bad input
sh scripts/plots.sh "$T/nothing" >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "plots.sh on a missing run must exit 2"
NZ=x sh scripts/polecap.sh "$T/pc2" >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "polecap.sh with NZ=x must exit 2"
finish plots_cli
