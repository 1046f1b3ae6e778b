#!/bin/sh
# tradeoff-data.sh TRADEOFF_CSV PREC DIR COLORS - the data of tradeoff.gp,
# from `onbstudy table`'s tradeoff.csv, for one precision:
#   DIR/tradeoff_PREC.dat  speed, error, colour (integer), method, on the front (0/1), RMSE on uniform
#   DIR/front_PREC.dat     the Pareto front, by speed
#   DIR/stairs_PREC.dat    its staircase, from the left edge to the top edge
# speed = batch_mbases_1t; error = max_defect_worst, drawn at 10 when a
# method gave non-finite output on those inputs (the table counts that as
# infinite), and at the chart's floor when it is zero.  Methods without
# accuracy (pareto = na) are left out.  Exits 1 when nothing is left.
set -eu
csv=$1; P=$2; W=$3; colors=$4
if [ "$P" = float ]; then floor=1e-12; else floor=1e-20; fi
awk -F, -v p="$P" -v C="$colors" -v fl="$floor" '
	BEGIN { while ((getline l < C) > 0) { split(l, a, /[ \t]+/); if (a[1] !~ /^#/) col[a[1]] = a[2] } }
	function hex(s,   i, v, c) { v = 0; s = tolower(substr(s, 2)); for (i = 1; i <= 6; i++) { c = index("0123456789abcdef", substr(s, i, 1)) - 1; v = v * 16 + c } return v }
	/^#/ || $1 == "method" { next }
	$2 == p && $12 != "na" && $3 != "nan" {
		e = ($11 + 0 > 0 || $10 == "nan" || $10 == "inf") ? 10 : ($10 + 0 == 0 ? fl : $10)
		b = $1; sub(/\+fma$/, "", b)
		r = ($7 == "nan" || $7 == "inf") ? 10 : ($7 + 0 == 0 ? fl : $7)
		print $3, e, hex(col[b] ? col[b] : "#000000"), $1, $12, r }' "$csv" > "$W/tradeoff_$P.dat"
[ -s "$W/tradeoff_$P.dat" ] || exit 1
awk '$5 == 1' "$W/tradeoff_$P.dat" | sort -g > "$W/front_$P.dat"
[ -s "$W/front_$P.dat" ] || exit 1
awk 'NR == 1 { print $1 / 100, $2 } { print $1, $2; x = $1 } END { print x, 1e6 }' "$W/front_$P.dat" > "$W/stairs_$P.dat"
