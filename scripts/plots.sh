#!/bin/sh
# plots.sh [RUNDIR] - every chart of a run (default results/latest), as
# PNG (pngcairo) and SVG beside its CSV files:
#   error_vs_nz_P     the per-input defect against n.z, max and RMS per bin
#   south_pole_P      the same near n.z = -1, log-log in 1 + n.z
#   maps_P            error maps over the sphere (equal-area), one panel per method
#   continuity_P      the largest jump of b1 between neighbouring grid cells
#   nonunit_P         error against | |n| - 1 | of non-unit input
#   threshold_P       Max's threshold analysis (when threshold.csv is there)
#   tradeoff_P        speed against accuracy (when tradeoff.csv is there)
# for P in float and double, and half where the run has binary16 rows
# (sweep --precision half: results/half/sweep).  The gnuplot scripts are
# scripts/*.gp.
set -eu
RUN=${1:-results/latest}
HERE=$(cd "$(dirname "$0")" && pwd)
if ! command -v gnuplot >/dev/null 2>&1; then
	echo "plots: gnuplot is not installed (scripts/install-deps.sh --plots installs gnuplot-nox)" >&2
	exit 2
fi
if [ ! -f "$RUN/summary.csv" ] || [ ! -f "$RUN/by_nz.csv" ]; then
	echo "plots: $RUN/summary.csv or by_nz.csv not found (run ./onbstudy sweep first)" >&2
	exit 2
fi
# the README's single-panel figures go to FIGS, the pole-cap map's data
# and full chart live in PCDIR (results/reference: FIGS=results/figures
# PCDIR=results/polecap, so that the committed run stays under 5 MB)
FIGS=${FIGS:-$RUN/figures}
PCDIR=${PCDIR:-$RUN}
W=$(mktemp -d)
# frisvad_rotate's rows are its direction error, not the defect: say so in
# the titles of a run that has it
FRD=''; FRP=''
if grep -q '^frisvad_rotate,' "$RUN/summary.csv"; then
	FRD='; frisvad\_rotate: its direction error'; FRP='(frisvad\_rotate: its direction error)'
fi
trap 'rm -rf "$W"' EXIT
LOG="$W/gnuplot.log"
: > "$LOG"
made=0
skipped=""
skip() { skipped="$skipped
  $1: $2"; }

gp() { # gp SCRIPT VARS...: run gnuplot, keeping its messages
	script=$1; shift
	gnuplot -e "here='$HERE'; nosvg=${NOSVG:-0}; $*" "$HERE/$script" >>"$LOG" 2>&1 || { cat "$LOG" >&2; echo "plots: gnuplot failed on $script" >&2; exit 1; }
	made=$((made + 1))
	# a palette PNG (pngquant, when installed): a third of the size, for
	# the charts of flat fills and markers (maps, bars, tradeoff: at most
	# 0.11% of their non-white pixels moved by a CIELAB delta-E above 5,
	# scripts/png-shift.py); not for the line charts (lines.gp,
	# threshold.gp): 256 entries cannot hold the anti-aliased edges of 20
	# thin lines, and pngquant moved 2.3-5.9% of their non-white pixels by
	# more than 5, a thin series' own colour by up to 45 (eigen in
	# wild/nonunit_float; --nofs: the same), so they stay full-colour, at
	# three times the size (docs/chart-grading.md)
	o=$(echo "$*" | sed -n "s/.*out='\([^']*\)'.*/\1/p")
	case $script in lines.gp|threshold.gp) o='';; esac
	if [ -n "$o" ] && command -v pngquant >/dev/null 2>&1; then
		pngquant --force --skip-if-larger --speed 1 --output "$o.png" 256 "$o.png" 2>>"$LOG" || true
	fi
}

# Methods in drawing order, with their panel, hue, dash, point type and
# width (scripts/styles.sh: one hue per family, small multiples), per
# precision (the float-only methods have no double rows).
sty() { awk -v m="$1" -v c="$2" '$1 == m { print $c }' "$W/styles"; }
samples() { # samples METHOD PREC DIST
	awk -F, -v m="$1" -v p="$2" -v d="$3" '!/^#/ && $1 == m && $2 == p && $3 == d { print $4; exit }' "$RUN/summary.csv"
}
# range FILES COL LOGX: "xmin xmax ymin ymax" of the data (y: with margins;
# x: where the data start and end)
range() {
	# shellcheck disable=SC2086
	cat $1 | awk -v c="$2" -v lx="$3" 'NF >= c { x = $1 + 0; y = $c + 0
		if (!n++ || x < x0) x0 = x; if (n == 1 || x > x1) x1 = x
		if (y > 0 && (!m++ || y < y0)) y0 = y; if (y > 0 && (m == 1 || y > y1)) y1 = y }
		END { if (lx) { x0 /= 1.4; x1 *= 1.4 } if (!m) { y0 = 1e-20; y1 = 10 } printf "%g %g %g %g\n", x0, x1, y0 / 4, y1 * 4 }'
}

# bands NAME "DISTS" AXIS lin|log "METHODS" "PANELS" "COLORS": the
# accuracy-floor bands of a chart (scripts/floor-bands.awk: each method's
# own floor, merged where floors agree), their list in W/NAME.bands
bands() {
	awk -F, -v p="$P" -v ds="$2" -v ax="$3" -v sc="$4" -v zx="$ZX" -v methods="$5" -v panels="$6" -v colors="$7" \
		-v out="$W/$1" -f "$HERE/floor-bands.awk" "$RUN/by_nz.csv" > "$W/$1.bands"
	[ -s "$W/$1.bands" ] && echo "bands='$W/$1.bands';" || true
}

# series METHOD "DISTS" AXIS lin|log CEIL: x, max, RMS, non-finite per bin
series() {
	awk -F, -v m="$1" -v p="$P" -v ds="$2" -v ax="$3" -v sc="$4" -v fl="$FLOOR" -v ce="$5" -v zx="$ZX" \
		-f "$HERE/series.awk" "$RUN/by_nz.csv" "$RUN/by_nz.csv" | sort -g
}
# wide_of "NAMES" "WIDTHS": the names of the wide series (the headline
# methods, styles.awk), escaped for gnuplot's enhanced text; nothing when
# all or none of the series drawn are wide
wide_of() {
	awk -v n="$1" -v w="$2" 'BEGIN { k = split(n, a, " "); split(w, b, " "); lo = hi = b[1]
		for (i = 1; i <= k; i++) { if (b[i] + 0 < lo + 0) lo = b[i]; if (b[i] + 0 > hi + 0) hi = b[i] }
		if (lo + 0 == hi + 0) exit
		for (i = 1; i <= k; i++) if (b[i] + 0 == hi + 0) { m = a[i]; gsub(/_/, "\\\\_", m); s = s (s == "" ? "" : ", ") m }
		print s }'
}
# titles "FILES" COL CEIL: the key titles (scripts/series-titles.awk)
titles() { awk -v files="$1" -v names="$names" -v panels="$panels" -v col="$2" -v ce="$3" -f "$HERE/series-titles.awk"; }
# nonfinite "FILES" CEIL: 1 when any bin holds a non-finite output
nonfinite() {
	# shellcheck disable=SC2086
	cat $1 | awk -v ce="$2" '$4 > 0 || $2 + 0 >= ce + 0 { f = 1 } END { print f + 0 }'
}
# ceil_of "DISTS" AXIS: where a chart draws non-finite output: 10, or two
# decades above its largest finite error when that reaches 1 (non-unit
# input: frisvad's defect of 2157 is finite and must not read as non-finite)
ceil_of() {
	awk -F, -v p="$P" -v ds="$1" -v ax="$2" 'BEGIN { n = split(ds, a, " "); for (i = 1; i <= n; i++) w[a[i]] = 1 }
		!/^#/ && $2 == p && ($3 in w) && $4 == ax && $9 != "nan" && $9 != "inf" && $9 + 0 > mx { mx = $9 + 0 }
		END { c = 10; if (mx >= 1) c = 10 ^ (int(log(mx) / log(10)) + 2); printf "%g\n", c }' "$RUN/by_nz.csv"
}

# polecap: the pole-cap map (scripts/polecap.sh's polecap.csv in PCDIR),
# every method of it (PCDIR/polecap_float) and, for the README, frisvad
# beside duff (FIGS/polecap_frisvad_duff)
polecap() {
	pc="$PCDIR/polecap.csv"
	mkdir -p "$FIGS"
	pcm=$(awk -F, '$1 == "one_plus_nz" { for (i = 3; i <= NF; i++) printf "%s ", $i; exit }' "$pc")
	pcf=""; c=3
	for m in $pcm; do
		awk -F, -v c=$c '!/^#/ && $1 != "one_plus_nz" { d = log($1) / log(10); if (!(d in sd)) { sd[d] = 1; nd++ } if (!($2 in sa)) { sa[$2] = 1; na++ }
			if (!n++ || d < lo) lo = d; if (n == 1 || d > hi) hi = d
			r[n] = $2 " " d " " ($c == "nan" || $c == "-nan" || $c == "inf" ? "nan" : ($c + 0 > 0 ? log($c) / log(10) : -12)) }
			END { hw = 180 / na * 1.03; hh = (hi - lo) / (nd - 1) / 2 * 1.03; for (i = 1; i <= n; i++) { split(r[i], a, " "); print a[1], a[2], hw, hh, a[3] } }' \
			"$pc" > "$W/pc_$m.dat"
		pcf="$pcf $W/pc_$m.dat"; c=$((c + 1))
	done
	# shellcheck disable=SC2086
	set -- $(cat $pcf | awk '{ if (!n++ || $2 < lo) lo = $2; if (n == 1 || $2 > hi) hi = $2; if ($5 != "nan" && (!m++ || $5 < cl)) cl = $5 }
		END { printf "%g %g %d\n", lo - 0.04, hi + 0.04, (cl < -8 ? -9 : int(cl) - 1) }')
	tf=$(sed -n 's/^# published Frisvad 2012: .*one_plus_t \([-0-9.e+]*\),.*/\1/p' "$RUN/threshold.csv" 2>/dev/null | head -1)
	tm=$(sed -n 's/^# published Max 2017: .*one_plus_t \([-0-9.e+]*\),.*/\1/p' "$RUN/threshold.csv" 2>/dev/null | head -1)
	prov=$(sed -n 's/^# grid: \([0-9]*\) values.* x \([0-9]*\) azimuths.*/\1 values of 1 + n.z x \2 azimuths/p' "$pc")
	# the thresholds in the axis's coordinates: the axis is 1 + n.z before
	# rounding to float, the test n.z < t is on the float n.z, and near -1
	# floats are u = 2^-24 apart, so n.z rounds below t = -1 + k u exactly
	# when 1 + n.z < (k - 1/2) u
	tf=$(echo "${tf:-0}" | awk '{ u = 2 ^ -24; k = int($1 / u + 0.5); print (k > 0 ? (k - 0.5) * u : 0) }')
	tm=$(echo "${tm:-0}" | awk '{ u = 2 ^ -24; k = int($1 / u + 0.5); print (k > 0 ? (k - 0.5) * u : 0) }')
	pcv="cbmin=$3; cbmax=0; ymin=$1; ymax=$2; tfris=${tf:-0}; tmax=${tm:-0}"
	gp polecap.gp "$pcv; files='$pcf'; names='$pcm'; out='$PCDIR/polecap_float'; ttl='float: the southern cap, $prov (unit inputs rounded to float; polecap.csv)'"
	two=$(for m in frisvad duff; do [ -s "$W/pc_$m.dat" ] && printf '%s ' "$m"; done; true)
	[ -n "$two" ] && gp polecap.gp "$pcv; single=1; files='$(for m in $two; do printf '%s ' "$W/pc_$m.dat"; done)'; names='$two'; out='$FIGS/polecap_frisvad_duff'; ttl='$(awk -F, -v methods="$two" -f "$HERE/polecap-title.awk" "$pc")'"
}

for P in float double half; do
	grep -q "^[^#].*,$P," "$RUN/summary.csv" || continue
	# ZX: the "-z" slot, 2^-3 of the format's u (binary16's first n.z
	# above -1 is -1 + 2^-11: the slot sits a decade and more left of it)
	case $P in
	float) FLOOR=1e-12; ZX=7.5e-9 ;;
	double) FLOOR=1e-20; ZX=1.33e-17 ;;
	half) FLOOR=1e-8; ZX=6.1e-5 ;;
	esac
	CEIL=10
	awk -F, -v p="$P" '/^#/ || $1 == "method" || $2 == p' "$RUN/summary.csv" > "$W/summary_$P.csv"
	# styles from both precisions, so that the panels group the same
	# families in float and double; then this precision's methods
	sh "$HERE/styles.sh" "$RUN/summary.csv" > "$W/styles_all"
	awk -F, 'NR == FNR { if ($1 !~ /^#/ && $1 != "method") have[$1] = 1; next } $1 in have' \
		"$W/summary_$P.csv" FS=' ' "$W/styles_all" > "$W/styles"
	pmethods=$(awk '{ print $1 }' "$W/styles")
	awk '{ print $1, $3 }' "$W/styles" > "$W/colors.txt"   # for bars and tradeoff
	ptitles=$(awk '{ if (!(($2, $7) in s)) { s[$2, $7] = 1; t[$2] = t[$2] (t[$2] == "" ? "" : ",") $7 } if ($2 > np) np = $2 }
		END { for (p = 1; p <= np; p++) printf "%s%s", (p > 1 ? " " : ""), (p in t ? t[p] : "-") }' "$W/styles_all")
	first=$(echo "$pmethods" | head -1)

	# 1. error against n.z (uniform), max and RMS
	# 2. near the south pole, max over south, exhaustive and uniform
	# 6. against | |n| - 1 | (nonunit)
	# (x, max, RMS, non-finite count per bin: scripts/series.awk)
	files1=""; files2=""; files6=""; names=""; colors=""; dashes=""; points=""; widths=""; panels=""
	C1=$(ceil_of uniform nz); C2=$(ceil_of "south exhaustive uniform" log10_1pnz); C6=$(ceil_of nonunit log10_absnorm)
	for m in $pmethods; do
		f1="$W/nz_${P}_$m.dat"; f2="$W/sp_${P}_$m.dat"; f6="$W/nu_${P}_$m.dat"
		series "$m" uniform nz lin "$C1" > "$f1"
		series "$m" "south exhaustive uniform" log10_1pnz log "$C2" > "$f2"
		series "$m" nonunit log10_absnorm log "$C6" > "$f6"
		files1="$files1 $f1"; files2="$files2 $f2"; files6="$files6 $f6"
		names="$names $m"; colors="$colors $(sty "$m" 3)"; dashes="$dashes $(sty "$m" 4)"
		points="$points $(sty "$m" 5)"; widths="$widths $(sty "$m" 6)"; panels="$panels $(sty "$m" 2)"
	done
	# the accuracy-floor bands: each method's own (floor-bands.awk)
	b1=$(bands fb1_$P uniform nz lin "$names" "$panels" "$colors")
	b2=$(bands fb2_$P "south exhaustive uniform" log10_1pnz log "$names" "$panels" "$colors")
	b6=$(bands fb6_$P nonunit log10_absnorm log "$names" "$panels" "$colors")
	common="here='$HERE'; colors='$colors'; dashes='$dashes'; points='$points'; widths='$widths'; panels='$panels'; ptitles='$ptitles'; floor=$FLOOR; wide='$(wide_of "$names" "$widths")'"
	n=$(samples "$first" "$P" uniform)
	if [ -n "$n" ]; then
		titles "$files1" 2 "$C1" > "$W/t1.txt"; titles "$files1" 3 "$C1" > "$W/t1r.txt"
		set -- $(range "$files1" 2 0)
		gp lines.gp "$b1 $common; files='$files1'; titles='$W/t1.txt'; ceil=$C1; nf=$(nonfinite "$files1" "$C1"); out='$RUN/error_vs_nz_$P'; col=2; logx=0; xmin=-1; xmax=1; ymin=$3; ymax=$4; xl='n.z of the input'; yl_key='YL_ERROR'; ttl='$P: largest error against n.z, uniform inputs, $n per method (the defect$FRD)'"
		set -- $(range "$files1" 3 0)
		gp lines.gp "$b1 $common; files='$files1'; titles='$W/t1r.txt'; ceil=$C1; nf=$(nonfinite "$files1" "$C1"); out='$RUN/error_vs_nz_rms_$P'; col=3; logx=0; xmin=-1; xmax=1; ymin=$3; ymax=$4; xl='n.z of the input'; yl_key='YL_ERROR_RMS'; ttl='$P: RMS error against n.z, uniform inputs, $n per method (the defect$FRD)'"
	else
		e="xl='n.z of the input'; note='this run has no uniform inputs (sweep --dists with uniform)'"
		gp empty.gp "$e; out='$RUN/error_vs_nz_$P'; yl_key='YL_ERROR'; ttl='$P: largest error against n.z, uniform inputs'"
		gp empty.gp "$e; out='$RUN/error_vs_nz_rms_$P'; yl_key='YL_ERROR_RMS'; ttl='$P: RMS error against n.z, uniform inputs'"
	fi
	# the distributions this run has near the pole, named in the title
	# ("south (N), exhaustive and uniform inputs" when it has all three)
	spd=$(for d in south exhaustive uniform; do n=$(samples "$first" "$P" "$d"); [ -n "$n" ] && printf '%s %s\n' "$d" "$n"; done; true)
	spd=$(echo "$spd" | awk 'NF { d[++k] = $1 (($1 == "south") ? " (" $2 ")" : "") } END { for (i = 1; i <= k; i++) s = s (i == 1 ? "" : (i == k ? " and " : ", ")) d[i]; print s }')
	# (the "-z" slot named only when some input is n.z = -1 exactly)
	sxl="1 + n.z of the input (distance from the south pole$(cat $files2 | awk -v z="$ZX" '$1 + 0 < z * 1.5 { f = 1 } END { if (f) printf "; -z: n.z = -1 exactly" }'))"
	if [ -z "$(cat $files2)" ]; then
		# no input near the pole in this run: the chart says so
		gp empty.gp "out='$RUN/south_pole_$P'; xl='$sxl'; yl_key='YL_ERROR'; ttl='$P: near n.z = -1'; note='no input of this run lies near n.z = -1 (it has no south, exhaustive or uniform inputs: sweep --dists)'"
	else
	titles "$files2" 2 "$C2" > "$W/t2.txt"
	set -- $(range "$files2" 2 1)
	gp lines.gp "$b2 $common; files='$files2'; titles='$W/t2.txt'; ceil=$C2; nf=$(nonfinite "$files2" "$C2"); out='$RUN/south_pole_$P'; col=2; logx=1; xmin=$1; xmax=$2; ymin=$3; ymax=$4; zero_x=$ZX; xl='$sxl'; yl_key='YL_ERROR'; ttl='$P: near n.z = -1: $spd inputs $FRP'"
	fi
	# the README's figure (float): frisvad, frisvad_max and duff alone (those
	# of them in the run), one panel, titled from the data (pole-title.awk)
	sel=$(for m in frisvad frisvad_max duff; do echo "$pmethods" | grep -qx "$m" && printf '%s ' "$m"; done; true)
	sf=""; for m in $sel; do sf="$sf $W/sp_${P}_$m.dat"; done
	if [ "$P" = float ] && [ -n "$sel" ] && [ -z "$(cat $sf)" ]; then
		mkdir -p "$FIGS"
		gp empty.gp "single=1; out='$FIGS/south_pole_frisvad_duff_$P'; xl='1 + n.z of the input'; yl_key='YL_DEFECT'; ttl='$P near n.z = -1: $(echo $sel | sed 's/ /, /g')'; note='no input of this run lies near n.z = -1 (sweep --dists with south, exhaustive or uniform)'"
	elif [ "$P" = float ] && [ -n "$sel" ]; then
		mkdir -p "$FIGS"
		sf=""; sc=""; sd=""; sp=""; sw=""
		for m in $sel; do sf="$sf $W/sp_${P}_$m.dat"; sc="$sc $(sty "$m" 3)"; sd="$sd $(sty "$m" 4)"; sp="$sp $(sty "$m" 5)"; sw="$sw $(sty "$m" 6)"; done
		awk -v files="$sf" -v names="$sel" -v panels="$(echo $sel | sed 's/[^ ]*/1/g')" -v col=2 -v ce="$C2" -f "$HERE/series-titles.awk" > "$W/t2s.txt"
		bs=$(bands fbs_$P "south exhaustive uniform" log10_1pnz log "$sel" "$(echo $sel | sed 's/[^ ]*/1/g')" "$sc")
		set -- $(range "$sf" 2 1)
		gp lines.gp "$bs here='$HERE'; single=1; files='$sf'; titles='$W/t2s.txt'; colors='$sc'; dashes='$sd'; points='$sp'; widths='$sw'; panels='$(echo $sel | sed 's/[^ ]*/1/g')'; ptitles='-'; floor=$FLOOR; ceil=$C2; nf=$(nonfinite "$sf" "$C2"); out='$FIGS/south_pole_frisvad_duff_$P'; col=2; logx=1; xmin=$1; xmax=$2; ymin=$3; ymax=$4; zero_x=$ZX; xl='1 + n.z of the input$(cat $sf | awk -v z="$ZX" '$1 + 0 < z * 1.5 { f = 1 } END { if (f) printf " (-z: n.z = -1 exactly)" }')'; yl_key='YL_DEFECT'; ttl='$(awk -F, -v p="$P" -v ds="south exhaustive uniform" -v methods="$sel" -f "$HERE/pole-title.awk" "$RUN/summary.csv")'"
	fi
	if [ -s "$(echo "$files6" | awk '{print $1}')" ]; then
		n=$(samples "$first" "$P" nonunit)
		titles "$files6" 2 "$C6" > "$W/t6.txt"
		set -- $(range "$files6" 2 1)
		gp lines.gp "$b6 $common; files='$files6'; titles='$W/t6.txt'; ceil=$C6; nf=$(nonfinite "$files6" "$C6"); out='$RUN/nonunit_$P'; col=2; logx=1; xmin=$1; xmax=$2; ymin=$3; ymax=$4; xl='| |n| - 1 | of the input (unitless)'; yl='largest error per bin, against n/|n| (unitless)'; ttl='$P: non-unit input, $n inputs per method $FRP'"
	else gp empty.gp "out='$RUN/nonunit_$P'; xl='| |n| - 1 | of the input (unitless)'; yl='largest error per bin, against n/|n| (unitless)'; ttl='$P: non-unit input'; note='this run has no nonunit inputs (sweep --dists with nonunit)'"
	fi

	# 3. maps and continuity, from grid.csv
	if [ -f "$RUN/grid.csv" ]; then
		# one panel per method of either precision, in the same place in
		# float and double (a method with no rows in this one: "-", a
		# blank panel); the colour: the defect in units of u (2^-24 float,
		# 2^-53 double), log2, from 1/4 u to 64 u, so that the seams of
		# the accurate methods show; a larger defect saturates, zero sits
		# at the bottom
		U=$(awk -v p="$P" 'BEGIN { print (p == "float") ? 2 ^ -24 : (p == "half" ? 2 ^ -11 : 2 ^ -53) }')
		mfiles=""; mnames=""; k=0; have=0
		for m in $(awk '{ print $1 }' "$W/styles_all"); do
			f="$W/map_${P}_$m.dat"
			awk -F, -v m="$m" -v p="$P" -v u="$U" '
				!/^#/ && $1 == m && $2 == p { if ($3 != last && NR > 1 && started) print ""; last = $3; started = 1
					x = $7; v = (x == "inf" || x == "nan" || x == "-nan") ? "nan" : (x + 0 <= u / 4 ? -2 : log(x / u) / log(2))
					if (v != "nan" && v > 6) v = 6
					print $6 * 57.29577951308232, $5, v }' "$RUN/grid.csv" > "$f"
			if [ -s "$f" ]; then have=$((have + 1)); else f=-; fi
			mfiles="$mfiles $f"; mnames="$mnames $m"; k=$((k + 1))
		done
		if [ $have -gt 0 ]; then
			ncols=6; [ $k -lt 6 ] && ncols=$k
			nrows=$(( (k + ncols - 1) / ncols ))
			gres=$(grep -m1 '^# exhaustive' "$RUN/summary.csv" | sed -n 's/.*grid: \([0-9]*x[0-9]*\).*/\1/p')
			# the note names failures near -z only when the run has some (a
			# method whose largest defect on south inputs is above 1e-4 and
			# 10x its largest on the grid, what the map shows), and blank
			# panels only when drawn
			mnote="one input per cell of a ${gres:-?} grid: the inputs of its lowest row sit at 1 + n.z = $(echo "${gres%x*}" | awk '{ printf "%.2g", 1 / $1 }')"
			fails=$(awk -F, -v p="$P" '!/^#/ && $2 == p && $3 == "south" { s[$1] = $6 + 0 } !/^#/ && $2 == p && $3 == "grid" { u[$1] = $6 + 0 }
				END { for (m in s) if (s[m] > 1e-4 && s[m] > 10 * u[m]) n++; print n + 0 }' "$RUN/summary.csv")
			[ "$fails" -gt 0 ] && mnote="$mnote, so it cannot show the failures within 1e-4 of -z (the $([ -f "$PCDIR/polecap.csv" ] && echo pole-cap map || echo pole chart) shows them)"
			gp map.gp "blank='no rows in $P'; dirnames='$(grep -q '^frisvad_rotate,' "$RUN/summary.csv" && echo frisvad_rotate)'; files='$mfiles'; names='$mnames'; ncols=$ncols; nrows=$nrows; cbmin=-2; cbmax=6; uname='$(case $P in float) echo "u = 2^{-24}";; half) echo "u = 2^{-11}";; *) echo "u = 2^{-53}";; esac)'; out='$RUN/maps_$P'; ttl='$P: the orthonormality defect over the sphere, in units of u (equal-area: x azimuth, y n.z$FRD)'; note='$mnote'"
		fi
		awk -F, -v p="$P" -v H="$W/colors.txt" '
			BEGIN { while ((getline l < H) > 0) { split(l, a, /[ \t]+/); if (a[1] !~ /^#/) col[a[1]] = a[2] } }
			function hex(s,   i, v, c) { v = 0; s = tolower(substr(s, 2)); for (i = 1; i <= 6; i++) { c = index("0123456789abcdef", substr(s, i, 1)) - 1; v = v * 16 + c } return v }
			!/^#/ && $2 == p && $3 == "grid" && $18 != "nan" { b = $1; sub(/\+fma$/, "", b); print $1, $18, hex(col[b] ? col[b] : "#000000") }' \
			"$RUN/summary.csv" > "$W/bars_$P.unsorted"
		# in the order of the panels of the other charts (styles.sh), not
		# of summary.csv, so that a family's bars stand together
		awk 'NR == FNR { o[$1] = FNR; next } { b = $1; sub(/\+fma$/, "", b); print (b in o ? o[b] : 9999), FNR, $0 }' \
			"$W/styles" "$W/bars_$P.unsorted" | sort -n -k1,1 -k2,2 | cut -d' ' -f3- > "$W/bars_$P.dat"
		if [ -s "$W/bars_$P.dat" ]; then
			rows=$(grep -m1 '^# exhaustive' "$RUN/summary.csv" | sed 's/.*grid: \([0-9]*\)x\([0-9]*\).*/\1 \2/')
			cell=$(echo "$rows" | awk '{ r = $1; c = $2; dz = 2 / r; dphi = 6.283185307 / c; print (dz > dphi ? dz : dphi) }')
			gp bars.gp "file='$W/bars_$P.dat'; cell=${cell:-0.1}; yl='largest |b1 - b1''| between neighbouring cells (unitless)'; out='$RUN/continuity_$P'; ttl='$P: continuity of the frame field on the ${rows% *}x${rows#* } equal-area grid'"
		fi
	else skip "maps_$P, continuity_$P" "no grid.csv (sweep --dists with grid)"
	fi

	# 5. threshold
	if [ -f "$RUN/threshold.csv" ] && grep -q "^$P," "$RUN/threshold.csv"; then
		# the finite rows; the non-finite ones (t = -1: no fallback, so n = -z
		# divides by zero) counted and drawn in the non-finite band
		awk -F, -v p="$P" '!/^#/ && $1 == p && $5 !~ /inf|nan/ && $6 !~ /inf|nan/ { print $4, $5, $6, $7 }' "$RUN/threshold.csv" > "$W/th_$P.dat"
		thnf=$(awk -F, -v p="$P" '!/^#/ && $1 == p && ($5 ~ /inf|nan/ || $6 ~ /inf|nan/) { n++; t = t (t == "" ? "" : ", ") $3 } END { printf "%d %s", n, t }' "$RUN/threshold.csv")
		# the published thresholds and the minimax, as vertical lines with
		# their error in the key; marks at one t share one line
		awk -v p="$P" -v F="$RUN/threshold.csv" -v W="$W/thm_$P" 'BEGIN { sect = ""
			while ((getline l < F) > 0) {
				if (l ~ /^[a-z]/) { split(l, a, ","); sect = a[1]; continue }
				if (sect != p || (l !~ /^# minimax both/ && l !~ /^# published/)) continue
				# one_plus_t, not 1 + the rounded decimal t (which reads -1 in double)
				match(l, /one_plus_t [-0-9.e+]+/); x = substr(l, RSTART + 11, RLENGTH - 11) + 0
				match(l, /max_both [-0-9.e+]+/); v = substr(l, RSTART + 9, RLENGTH - 9) + 0
				match(l, /\([-0-9.e]+\)/); t = substr(l, RSTART + 1, RLENGTH - 2)
				lab = (l ~ /minimax/) ? "minimax" : (l ~ /Frisvad/ ? "Frisvad 2012" : "Max 2017")
				for (k = 1; k <= n; k++) if (X[k] == x) break
				if (k > n) { n = k; X[k] = x; V[k] = v; T[k] = t; L[k] = lab } else L[k] = L[k] " = " lab
			}
			for (k = 1; k <= n; k++) {
				printf "%.9g 1e-300\n%.9g 1e300\n", X[k], X[k] > (W "_" k ".dat")
				printf "%s: t = -1 + %.3g, largest error %#.3g\n", L[k], X[k], V[k] > (W ".titles")
			} }'
		thfiles=$(ls "$W"/thm_"$P"_*.dat 2>/dev/null | sort | tr '\n' ' ')
		thv="file='$W/th_$P.dat'; mfiles='$thfiles'; mtitles='$W/thm_$P.titles'; nfrows=${thnf%% *}; nft='${thnf#* }'"
		[ "$P" = float ] && mkdir -p "$FIGS" && gp threshold.gp "$thv; out='$FIGS/threshold_minimax_$P'; ttl='$P: the threshold t of Frisvad Listing 2 (Max 2017): error against 1 + t'"
		gp threshold.gp "$thv; out='$RUN/threshold_$P'; ttl='$P: Frisvad Listing 2 with threshold t (Max 2017); $(awk -F, -v p=$P '$1 == p { n++ } END { print n }' "$RUN/threshold.csv") n.z near -1 x $(grep -m1 '^# inputs' "$RUN/threshold.csv" | sed 's/.* \([0-9]*\) azimuths.*/\1/') azimuths'"
	elif [ -f "$RUN/threshold.csv" ]; then skip "threshold_$P" "threshold.csv has no $P section"
	else skip "threshold_$P" "no threshold.csv (run ./onbstudy threshold)"
	fi

	# 7. the southern cap (scripts/polecap.sh's polecap.csv, float only)
	if [ -f "$PCDIR/polecap.csv" ] && [ "$P" = float ]; then
		polecap
	elif [ "$P" = float ]; then skip "polecap_float" "no $PCDIR/polecap.csv (run sh scripts/polecap.sh $PCDIR)"
	fi

	# 4. speed against accuracy
	if [ -f "$RUN/tradeoff.csv" ] && [ -f "$HERE/tradeoff.gp" ]; then
		sh "$HERE/tradeoff-data.sh" "$RUN/tradeoff.csv" "$P" "$W" "$W/colors.txt" && \
		gp tradeoff.gp "dir='$W'; prec='$P'; out='$RUN/tradeoff_$P'; floor=$FLOOR; ceil=$CEIL" && \
		if [ "$P" = float ]; then mkdir -p "$FIGS"; gp tradeoff.gp "dir='$W'; prec='$P'; single=1; out='$FIGS/tradeoff_front_$P'; floor=$FLOOR; ceil=$CEIL"; fi
	elif [ -f "$RUN/bench.csv" ]; then skip "tradeoff_$P" "no tradeoff.csv (run ./onbstudy table)"
	else skip "tradeoff_$P" "no bench.csv or tradeoff.csv (run ./onbstudy bench --quick && ./onbstudy table)"
	fi
done

if grep -qi "warning" "$LOG"; then
	cat "$LOG" >&2
	echo "plots: gnuplot warned (above)" >&2
	exit 1
fi
echo "plots: $made charts ($([ "${NOSVG:-0}" = 1 ] && echo "PNG only: NOSVG=1" || echo "PNG and SVG")) in $RUN"
[ -z "$skipped" ] || echo "plots: skipped, for want of data:$skipped"
