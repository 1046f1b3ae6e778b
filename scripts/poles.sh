#!/bin/sh
# poles.sh [DIR] - charts and the worst-input table of the exhaustive float
# run near both poles (default DIR results/poles, holding south/
# and north/ from `onbstudy sweep --dists exhaustive --precision float
# --exhaustive-range -1:-0.9` and `0.9:1`):
#   DIR/south_pole_float.{png,svg}  max and RMS per-input error against 1 + n.z
#   DIR/north_pole_float.{png,svg}  the same against 1 - n.z
#   DIR/worst.csv                   per method, the worst input at each pole
#                                   (hex floats) next to the worst of a sampled
#                                   sweep's random unit inputs (uniform, south,
#                                   north of SAMPLED, default results/reference)
# Uses scripts/lines.gp and scripts/styles.sh as plots.sh does.
set -eu
DIR=${1:-results/poles}
SAMPLED=${SAMPLED:-results/reference}
HERE=$(cd "$(dirname "$0")" && pwd)
command -v gnuplot >/dev/null 2>&1 || { echo "poles: gnuplot is not installed" >&2; exit 2; }
for s in south north; do
	[ -f "$DIR/$s/by_nz.csv" ] || { echo "poles: $DIR/$s/by_nz.csv not found" >&2; exit 2; }
done
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
P=float; FLOOR=1e-12; CEIL=10; ZX=7.5e-9
awk -F, -v p="$P" '/^#/ || $1 == "method" || $2 == p' "$DIR/south/summary.csv" > "$W/summary.csv"
sh "$HERE/styles.sh" "$W/summary.csv" > "$W/styles"
sty() { awk -v m="$1" -v c="$2" '$1 == m { print $c }' "$W/styles"; }
methods=$(awk '{ print $1 }' "$W/styles")
ptitles=$(awk '{ if (!(($2, $7) in s)) { s[$2, $7] = 1; t[$2] = t[$2] (t[$2] == "" ? "" : ",") $7 } if ($2 > np) np = $2 }
	END { for (p = 1; p <= np; p++) printf "%s%s", (p > 1 ? " " : ""), t[p] }' "$W/styles")
range() { # FILES COL: "xmin xmax ymin ymax"
	# shellcheck disable=SC2086
	cat $1 | awk -v c="$2" 'NF >= c { x = $1 + 0; y = $c + 0
		if (!n++ || x < x0) x0 = x; if (n == 1 || x > x1) x1 = x
		if (y > 0 && (!m++ || y < y0)) y0 = y; if (y > 0 && (m == 1 || y > y1)) y1 = y }
		END { x0 /= 1.4; x1 *= 1.4; if (!m) { y0 = 1e-20; y1 = 10 } printf "%g %g %g %g\n", x0, x1, y0 / 4, y1 * 4 }'
}
for s in south north; do
	if [ $s = south ]; then axis=log10_1pnz; zl=-z; xl='1 + n.z of the input (-z: n.z = -1 exactly)'; else axis=log10_1mnz; zl=+z; xl='1 - n.z of the input (+z: n.z = 1 exactly)'; fi
	files=""; names=""; colors=""; dashes=""; points=""; widths=""; panels=""
	for m in $methods; do
		f="$W/${s}_$m.dat"
		# x, max, RMS, non-finite per bin (the pole bin, from -17, at ZX)
		awk -F, -v m="$m" -v p="$P" -v ds=exhaustive -v ax="$axis" -v sc=log -v fl="$FLOOR" -v ce="$CEIL" -v zx="$ZX" \
			-f "$HERE/series.awk" "$DIR/$s/by_nz.csv" "$DIR/$s/by_nz.csv" | sort -g > "$f"
		files="$files $f"; names="$names $m"; colors="$colors $(sty "$m" 3)"; dashes="$dashes $(sty "$m" 4)"
		points="$points $(sty "$m" 5)"; widths="$widths $(sty "$m" 6)"; panels="$panels $(sty "$m" 2)"
	done
	awk -v files="$files" -v names="$names" -v panels="$panels" -v col=2 -v ce="$CEIL" -f "$HERE/series-titles.awk" > "$W/titles_$s"
	# shellcheck disable=SC2086
	nf=$(cat $files | awk -v ce="$CEIL" '$4 > 0 || $2 + 0 >= ce + 0 { f = 1 } END { print f + 0 }')
	# the accuracy-floor bands: each method's own (scripts/floor-bands.awk)
	awk -F, -v p="$P" -v ds=exhaustive -v ax="$axis" -v sc=log -v zx="$ZX" -v methods="$names" -v panels="$panels" -v colors="$colors" \
		-v out="$W/floor_$s" -f "$HERE/floor-bands.awk" "$DIR/$s/by_nz.csv" > "$W/floor_$s.bands"
	band=""; [ -s "$W/floor_$s.bands" ] && band="bands='$W/floor_$s.bands';"
	inputs=$(awk -F, '!/^#/ && $3 == "exhaustive" { print $4; exit }' "$DIR/$s/summary.csv")
	az=$(sed -n 's/^# exhaustive: .* \([0-9]*\) azimuths.*/\1/p' "$DIR/$s/summary.csv" | head -1)
	common="here='$HERE'; nosvg=${NOSVG:-0}; colors='$colors'; dashes='$dashes'; points='$points'; widths='$widths'; panels='$panels'; ptitles='$ptitles'; floor=$FLOOR; ceil=$CEIL; wide='$(awk -v n="$names" -v w="$widths" 'BEGIN { k = split(n, a, " "); split(w, b, " "); lo = hi = b[1]
		for (i = 1; i <= k; i++) { if (b[i] + 0 < lo + 0) lo = b[i]; if (b[i] + 0 > hi + 0) hi = b[i] }
		if (lo + 0 == hi + 0) exit
		for (i = 1; i <= k; i++) if (b[i] + 0 == hi + 0) { m = a[i]; gsub(/_/, "\\\\_", m); s = s (s == "" ? "" : ", ") m }
		print s }')'"
	set -- $(range "$files" 2)
	gnuplot -e "$band $common; files='$files'; titles='$W/titles_$s'; nf=$nf; out='$DIR/${s}_pole_float'; col=2; logx=1; xmin=$1; xmax=$2; ymin=$3; ymax=$4; zero_x=$ZX; zero_label='$zl'; xl='$xl'; yl_key='YL_ERROR'; ttl='float, every n.z within 0.1 of the $s pole, $az azimuths ($inputs inputs per method; frisvad\\_rotate: its direction error)'" "$HERE/lines.gp"
	# (a line chart: full colour, no pngquant; plots.sh's gp() says why)
done

# The worst input per method at each pole, next to the sampled sweep's worst
# (float, uniform, south and north: random unit inputs).
{
	echo "# the worst input per float method: at each pole (every float n.z within 0.1, $(basename "$DIR")), and in the sampled sweep $SAMPLED (float, its random unit inputs: uniform, south, north); error: the per-input defect (frisvad_rotate: direction error); inputs as C99 hex floats"
	echo "# poles: $(grep -m1 '^# revision:' "$DIR/south/summary.csv"); sampled: $(grep -m1 '^# revision:' "$SAMPLED/summary.csv" 2>/dev/null || echo none)"
	echo "method,where,distribution,error,nx,ny,nz"
	for m in $methods; do
		for s in south north; do
			awk -F, -v m="$m" -v s="$s" '!/^#/ && $1 == m && $2 == "float" && $3 == "exhaustive" && !done {
				for (i = 1; i <= NF; i++) if (h[i] == "error") e = $i
				print m "," s "_pole,exhaustive," e "," $(c["nx"]) "," $(c["ny"]) "," $(c["nz"]); done = 1 }
				/^method,/ { for (i = 1; i <= NF; i++) { h[i] = $i; c[$i] = i } }' "$DIR/$s/worst.csv"
		done
		[ -f "$SAMPLED/worst.csv" ] && awk -F, -v m="$m" '/^method,/ { for (i = 1; i <= NF; i++) c[$i] = i; next }
			!/^#/ && $1 == m && $2 == "float" && ($3 == "uniform" || $3 == "south" || $3 == "north") && $(c["rank"]) + 0 <= 1 {
				e = $(c["error"]); x = (e == "inf" || e == "nan") ? 1e300 : e + 0
				if (!n++ || x > bx) { bx = x; best = m ",sampled," $3 "," e "," $(c["nx"]) "," $(c["ny"]) "," $(c["nz"]) } }
			END { if (n) print best }' "$SAMPLED/worst.csv"
	done
} > "$DIR/worst.csv.tmp"
mv "$DIR/worst.csv.tmp" "$DIR/worst.csv"
echo "poles: wrote $DIR/south_pole_float.png, north_pole_float.png ($([ "${NOSVG:-0}" = 1 ] && echo 'no SVG: NOSVG=1' || echo 'and .svg')), worst.csv"
