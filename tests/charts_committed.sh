#!/bin/sh
# charts_committed.sh - the chart check on the inputs of every committed
# chart, not only on fixtures: the reference run (with the pole-cap map and
# the README figures), the wild run, the exhaustive pole runs, the
# certify run and the binary16 sweep and proofs are redrawn from their committed CSV files by the project's
# own scripts, as SVG, and scripts/chart-check.awk checks each (the checks
# are listed in tests/plots_cli.sh); then
#   - no chart's text names a method of the registry that its run does not
#     have (a title naming frisvad in a run without it);
#   - the README pole figure's title (scripts/pole-title.awk) claims
#     "fails" and "on its own floor" only where summary.csv shows them;
#   - a run with a single method and no frisvad still draws every chart,
#     each passing the check;
#   - a line chart's panel has the non-finite band exactly when one of its
#     series is non-finite (chart-check.awk -v nfband=1: the north pole
#     chart once reserved the band in all five panels for one series),
#     and the check fails on a chart with the band in the wrong panel;
#   - a map panel of a method with no rows in that precision keeps its
#     name and says so ("no rows in double"), not a silent gap;
#   - the README pole-cap figure's title (scripts/polecap-title.awk) says
#     "fails" only where polecap.csv has a defect of 0.1 or more;
#   - the render charts' texts (scripts/ao.gp, brushed.gp) fit their
#     canvas, drawn on fixture images.
#   - scripts/palette.sh --check: every method of the registry and of the
#     committed runs has its colour in scripts/palette.txt, any two apart;
#     chart-check.awk's check 7 on every committed chart: no two series of
#     one panel in one colour (and it fails on a chart with duff_wide
#     drawn in duff's colour); check 8 on every committed line chart: no
#     two methods of one panel in one dash and marker (it fails on
#     duff_wide drawn in duff's dash and marker);
# Not checked here: the PNGs themselves (the same gnuplot scripts draw
# them; they are looked at by eye before each commit).
. "$(dirname "$0")/lib.sh"
command -v gnuplot >/dev/null 2>&1 || { echo "charts_committed: gnuplot missing: scripts/install-deps.sh --test must install it"; exit 1; }
T=$tmp
out=$(sh scripts/palette.sh --check 2>&1) && ok || bad "$out"
./onbstudy list --format csv | awk -F, 'NR > 1 { print $1 }' > "$T/registry"
# check DIR RUN_SUMMARY...: chart-check every SVG of DIR, and no registry
# method in any text of it that the run's summary (or certify) files lack
check() {
	dir=$1; shift
	awk -F, 'FNR > 1 && !/^#/ { print $1 }' "$@" | sed 's/+fma$//' | sort -u > "$T/have"
	n=0
	for f in "$dir"/*.svg; do
		[ -f "$f" ] || continue
		n=$((n + 1))
		case $(basename "$f") in maps_*) nl=1;; *) nl=0;; esac
		case $(basename "$f") in error_vs_nz*|south_pole*|north_pole*|nonunit*) nb=1;; *) nb=0;; esac
		out=$(awk -v nolabels=$nl -v nfband=$nb -f scripts/chart-check.awk "$f" 2>&1) && ok || bad "chart check: $out"
		# the texts of the chart, tags dropped, as words
		sed -n 's/<[^>]*>/ /g; s/\\_/_/g; p' "$f" | tr -c 'a-z0-9_\n' ' ' | tr ' ' '\n' | sort -u > "$T/words"
		absent=$(grep -Fxf "$T/registry" "$T/words" | grep -Fxvf "$T/have" | tr '\n' ' ')
		[ -z "$absent" ] && ok || bad "$(basename "$f") names methods its run does not have: $absent"
	done
	[ "$n" -gt 0 ] && ok || bad "no SVG drawn in $dir"
}
# the reference run and its README figures, the pole-cap map
mkdir -p "$T/ref" "$T/pc" "$T/fig"
cp results/reference/*.csv "$T/ref/"; cp results/polecap/polecap.csv "$T/pc/"
FIGS="$T/fig" PCDIR="$T/pc" sh scripts/plots.sh "$T/ref" > "$T/log" 2>&1 || bad "plots.sh on the reference run failed: $(cat "$T/log")"
check "$T/ref" results/reference/summary.csv
check "$T/fig" results/reference/summary.csv
check "$T/pc" results/reference/summary.csv
# the wild run (no frisvad, no threshold.csv)
mkdir -p "$T/wild" "$T/wfig"
cp results/wild/*.csv "$T/wild/"
FIGS="$T/wfig" PCDIR="$T/wild" sh scripts/plots.sh "$T/wild" > "$T/log" 2>&1 || bad "plots.sh on the wild run failed: $(cat "$T/log")"
check "$T/wild" results/wild/summary.csv
check "$T/wfig" results/wild/summary.csv
# the exhaustive pole runs
mkdir -p "$T/poles/south" "$T/poles/north"
cp results/poles/south/*.csv "$T/poles/south/"; cp results/poles/north/*.csv "$T/poles/north/"
sh scripts/poles.sh "$T/poles" > "$T/log" 2>&1 || bad "poles.sh failed: $(cat "$T/log")"
check "$T/poles" results/poles/south/summary.csv
# the non-finite band: the north pole chart has it in tangent_cross_z's
# panel alone; moved (that series' count dropped, or another series given
# one) the check must fail, and so must a floor band naming a method its
# panel lacks (the multi-panel series checks run: gnuplot's ids there end
# in a letter)
n=$(grep -c "fill = 'rgb(251, 227, 212)'" "$T/poles/north_pole_float.svg")
[ "$n" -eq 1 ] && ok || bad "north_pole_float: $n non-finite bands, expected 1 (tangent_cross_z's panel)"
sed 's/(31 non-finite)<\/title>/<\/title>/' "$T/poles/north_pole_float.svg" > "$T/m1.svg"
sed 's/<title>duff<\/title>/<title>duff (2 non-finite)<\/title>/' "$T/poles/north_pole_float.svg" > "$T/m2.svg"
sed '0,/floor of the other 4/s//floor of naive, zzz/' "$T/poles/north_pole_float.svg" > "$T/m3.svg"
# two series of one panel in one colour (check 7): duff_wide drawn in duff's
cw() { awk -v t="$1" 'index($0, "<title>" t "</title>") { f = 1; next } f && match($0, /stroke=\047rgb\([ 0-9,]+\)\047/) { print substr($0, RSTART + 8, RLENGTH - 9); exit }' "$T/poles/north_pole_float.svg"; }
c1=$(cw duff); c2=$(cw duff_wide)
[ -n "$c1" ] && [ -n "$c2" ] && [ "$c1" != "$c2" ] && ok || bad "north_pole_float: duff ($c1) and duff_wide ($c2) not found in distinct colours"
sed "s/$c2/$c1/g" "$T/poles/north_pole_float.svg" > "$T/m4.svg"
# two methods of one panel in one dash and marker (check 8): duff_wide
# drawn in duff's dash pattern and point symbol
dw() { awk -v t="$1" -v w="$2" 'index($0, "<title>" t "</title>") { f = 1; next } f && w == "d" && /<path stroke=/ { print (match($0, /stroke-dasharray=\047[^\047]*\047/) ? substr($0, RSTART, RLENGTH) : ""); exit } f && w == "p" && match($0, /#gpPt[0-9]+/) { print substr($0, RSTART, RLENGTH); exit }' "$T/poles/north_pole_float.svg"; }
d1=$(dw duff d); d2=$(dw duff_wide d); p1=$(dw duff p); p2=$(dw duff_wide p)
[ "$d1 $p1" != "$d2 $p2" ] && [ -n "$p1" ] && [ -n "$p2" ] && ok || bad "north_pole_float: duff ($d1 $p1) and duff_wide ($d2 $p2) not found in distinct line styles"
awk -v t=duff_wide -v d1="$d1" -v p1="$p1" -v p2="$p2" '/<g id="gnuplot_plot_/ { f = 0 } index($0, "<title>" t "</title>") { f = 1 }
	f { gsub(/ stroke-dasharray=\047[^\047]*\047/, ""); if (d1 != "") sub(/<path stroke=\047[^\047]*\047/, "& " d1); gsub(p2 "\047", p1 "\047") } { print }' "$T/poles/north_pole_float.svg" > "$T/m5.svg"
for m in m1 m2 m3 m4 m5; do
	cmp -s "$T/$m.svg" "$T/poles/north_pole_float.svg" && bad "$m: the broken chart is not broken (the SVG changed form?)"
	awk -v nfband=1 -f scripts/chart-check.awk "$T/$m.svg" > /dev/null 2>&1 && bad "chart check passed a broken chart ($m)" || ok
done
# a map panel with no rows: named, and saying so (float-only methods in double)
fo=$(awk -F, '!/^#/ && $1 != "method" { p[$1] = p[$1] " " $2 } END { for (m in p) if (p[m] !~ /double/) n++; print n + 0 }' results/reference/summary.csv)
n=$(grep -c '>no rows in double<' "$T/ref/maps_double.svg")
[ "$n" -eq "$fo" ] && ok || bad "maps_double: $n panels say 'no rows in double', $fo methods have no double rows"
# the pole-cap figure's title: "fails" only at a defect of 0.1 or more
t=$(awk -F, -v methods="frisvad duff" -f scripts/polecap-title.awk results/polecap/polecap.csv)
case "$t" in *"frisvad fails (defect >= 0.1) at 1 + n.z from "*", duff stays below "*) ok;; *) bad "pole-cap title: $t";; esac
awk -F, 'BEGIN { OFS = "," } $1 == "one_plus_nz" { for (i = 1; i <= NF; i++) if ($i == "frisvad") c = i } !/^#/ && c && $1 != "one_plus_nz" && $c + 0 > 0.05 { $c = 0.05 } { print }' results/polecap/polecap.csv > "$T/pc2.csv"
t=$(awk -F, -v methods="frisvad duff" -f scripts/polecap-title.awk "$T/pc2.csv")
case "$t" in *"frisvad fails"*) bad "a pole-cap defect of 0.05 titled a failure: $t";; *"frisvad stays below 5e-02"*) ok;; *) bad "unexpected pole-cap title: $t";; esac
grep -q 'frisvad fails (defect' "$T/fig/polecap_frisvad_duff.svg" && ok || bad "the pole-cap figure's title is not polecap-title.awk's"
# the render charts (scripts/ao.gp, brushed.gp: make render draws them from
# aorender's images, too slow for make test) on fixture images of
# aorender's sizes, with the longest captions: no text leaves the canvas
# or overlaps another; a name too long for the title must fail
gnuplot -e "set terminal pngcairo size 480,360; set output '$T/g.png'; unset key; plot sin(x)" 2>/dev/null
gnuplot -e "set terminal pngcairo size 480,418; set output '$T/d.png'; unset key; plot cos(x)" 2>/dev/null
awk 'BEGIN { for (y = 0; y < 120; y++) { for (x = 0; x < 160; x++) print x, y, x / 160, (x == 3 ? "nan" : y / 120); print "" } }' > "$T/b.dat"
rc() { # rc SCRIPT OUT VARS: draw a render chart as SVG, then chart-check its texts
	gnuplot -e "here='scripts'; nosvg=0; out='$T/$2'; $3" "scripts/$1" > "$T/log" 2>&1 || { echo "gnuplot failed: $(cat "$T/log")"; return 1; }
	awk -v images=1 -f scripts/chart-check.awk "$T/$2.svg"
}
for v in "grey='$T/g.png'; name='duff\\_branchless'; prec='double'; maxd=0; over=0; nan=0" \
	"grey='$T/g.png'; diff='$T/d.png'; name='tangent\\_cross\\_z'; prec='float'; maxd=0.02; over=0; nan=3860" \
	"diff='$T/d.png'; name='hughes\\_moeller\\_rsqrt\\_nr'; prec='float'; maxd=0.02; over=0; nan=0" \
	"diff='$T/d.png'; name='frisvad'; prec='float'; maxd=0.156; over=1056; nan=0"; do
	out=$(rc ao.gp ao "$v" 2>&1) && ok || bad "ao.gp ($v): $out"
done
for m in duff hughes_moeller frisvad_max; do
	out=$(rc brushed.gp br "file='$T/b.dat'; name='$(echo $m | sed 's/_/\\_/g')'; prec='float'; maxd=0.362; nan=4176" 2>&1) && ok || bad "brushed.gp ($m): $out"
done
rc ao.gp ao "diff='$T/d.png'; name='$(printf '%0150d' 0)'; prec='float'; maxd=0; over=0; nan=0" > /dev/null 2>&1 && bad "a render title of 150 characters passed the chart check" || ok
# the certify run and its README figure
mkdir -p "$T/cert" "$T/cfig"
cp results/certify/certify.csv "$T/cert/"
FIGS="$T/cfig" sh scripts/certify-plot.sh "$T/cert" > "$T/log" 2>&1 || bad "certify-plot.sh failed: $(cat "$T/log")"
grep -qi warning "$T/log" && bad "certify-plot: gnuplot warned: $(grep -i warning "$T/log" | head -3)" || ok
check "$T/cert" results/certify/certify.csv
check "$T/cfig" results/certify/certify.csv
# the binary16 sweep (half rows alone: only the _half charts, with the
# "half eps" line) and the binary16 proofs (certify-half.csv: certify_half)
mkdir -p "$T/half" "$T/hcert"
cp results/half/sweep/*.csv "$T/half/"
FIGS="$T/half/fig" PCDIR="$T/half" sh scripts/plots.sh "$T/half" > "$T/log" 2>&1 || bad "plots.sh on the half sweep failed: $(cat "$T/log")"
check "$T/half" results/half/sweep/summary.csv
for c in error_vs_nz_half error_vs_nz_rms_half south_pole_half nonunit_half; do
	[ -s "$T/half/$c.svg" ] && grep -q '>half eps<' "$T/half/$c.svg" && ok || bad "the half sweep drew no $c with its half eps line"
done
[ -f "$T/half/error_vs_nz_float.svg" ] && bad "the half sweep drew a float chart" || ok
cp results/half/certify/certify-half.csv "$T/hcert/"
sh scripts/certify-plot.sh "$T/hcert" > "$T/log" 2>&1 || bad "certify-plot.sh on the half certify run failed: $(cat "$T/log")"
grep -qi warning "$T/log" && bad "certify-plot (half): gnuplot warned: $(grep -i warning "$T/log" | head -3)" || ok
check "$T/hcert" results/half/certify/certify-half.csv
grep -q 'u = 2' "$T/hcert/certify_half.svg" && grep -q '>-11<' "$T/hcert/certify_half.svg" && ok || bad "certify_half.svg does not say u = 2^-11"
# the pole figure's title claims only what summary.csv shows
t=$(awk -F, -v p=float -v ds="south exhaustive uniform" -v methods="frisvad frisvad_max duff" -f scripts/pole-title.awk results/wild/summary.csv)
case "$t" in *"frisvad "*|*"frisvad,"*) bad "the wild pole title names frisvad: $t";; *) ok;; esac
t=$(awk -F, -v p=float -v ds="south exhaustive uniform" -v methods="frisvad frisvad_max duff" -f scripts/pole-title.awk results/reference/summary.csv)
case "$t" in *"frisvad fails on its own floor"*) ok;; *) bad "the reference pole title lost frisvad's failure: $t";; esac
# frisvad's floor made 10x smaller: no longer "on its own floor"; its
# defect made 0.05: no longer "fails"
awk -F, 'BEGIN { OFS = "," } /^method,/ { for (i = 1; i <= NF; i++) h[$i] = i } $1 == "frisvad" && $2 == "float" { $h["max_floor"] = $h["max_floor"] / 10 } { print }' results/reference/summary.csv > "$T/s1.csv"
t=$(awk -F, -v p=float -v ds="south exhaustive uniform" -v methods="frisvad duff" -f scripts/pole-title.awk "$T/s1.csv")
case "$t" in *"frisvad fails,"*|*"frisvad fails") ok;; *) bad "a floor 10x below frisvad's defect still titled on its floor: $t";; esac
awk -F, 'BEGIN { OFS = "," } /^method,/ { for (i = 1; i <= NF; i++) h[$i] = i } $1 == "frisvad" && $2 == "float" && $(h["max_defect"]) + 0 > 0.05 { $h["max_defect"] = 0.05 } { print }' results/reference/summary.csv > "$T/s2.csv"
t=$(awk -F, -v p=float -v ds="south exhaustive uniform" -v methods="frisvad duff" -f scripts/pole-title.awk "$T/s2.csv")
case "$t" in *"frisvad fails"*) bad "a defect of 0.05 titled a failure: $t";; *"frisvad reaches 0.05"*) ok;; *) bad "unexpected title: $t";; esac
# a run with one method, no frisvad, no floor band to merge, no non-finite row
./onbstudy sweep --methods duff --samples 2000 --exhaustive-count 1024 --azimuths 2 --grid 8x16 --quiet --out "$T/one" >/dev/null 2>&1 || bad "a one-method sweep failed"
FIGS="$T/one/fig" PCDIR="$T/one" sh scripts/plots.sh "$T/one" > "$T/log" 2>&1 || bad "plots.sh on a one-method run failed: $(cat "$T/log")"
for c in error_vs_nz_float south_pole_float nonunit_float maps_float continuity_float error_vs_nz_double; do
	[ -s "$T/one/$c.svg" ] && ok || bad "a one-method run drew no $c"
done
check "$T/one" "$T/one/summary.csv"
check "$T/one/fig" "$T/one/summary.csv"
finish charts_committed
