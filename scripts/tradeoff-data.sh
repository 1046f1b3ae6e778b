#!/bin/sh
# tradeoff-data.sh TRADEOFF_CSV PREC DIR COLORS - the data of tradeoff.gp,
# from `onbstudy table`'s tradeoff.csv (columns found by name), for one
# precision:
#   DIR/tradeoff_PREC.dat  speed, error, colour (integer), method, on the front (0/1), RMS on uniform,
#                          on the RMSE's own front (0/1: the same rule on speed and RMSE)
#   DIR/stairs_PREC.dat, stairs_rms_PREC.dat  the boundary of the region the front's rule dominates
#   DIR/rule_PREC.txt      the rule in words, with its tolerance
# speed = batch_mbases_1t; error = max_defect_worst, drawn at 10 when a
# method gave non-finite output on those inputs (the table counts that as
# infinite), and at the chart's floor when it is zero.  Methods without
# accuracy (pareto = na) are left out.
# The front is `onbstudy table`'s (src/bench/table.c): B beats A when
# speed_B >= (1 - tol) speed_A and err_B <= err_A, and err_B < err_A or
# speed_B > (1 + tol) speed_A, with tol from the file's "# pareto:" line
# (speeds within 5% counted equal).  Each method B so dominates every
# point left of speed_B / (1 - tol) and above err_B; the staircase is the
# edge of the union of those regions, over every method, so that a point
# strictly inside it is dominated and the circled points lie on its edge.
# The circles are tradeoff.csv's own pareto column; this script recomputes
# the front by the same rule and exits 1 when the two differ (a chart that
# would contradict its table), or when nothing is left.
set -eu
csv=$1; P=$2; W=$3; colors=$4
if [ "$P" = float ]; then floor=1e-12; else floor=1e-20; fi
tol=$(sed -n 's/^# pareto:.*speeds within \([0-9.]*\)% counted equal.*/\1/p' "$csv" | head -1)
[ -n "$tol" ] || { echo "tradeoff-data: $csv has no '# pareto: ... speeds within N% counted equal' line" >&2; exit 1; }
awk -F, -v p="$P" -v C="$colors" -v fl="$floor" '
	BEGIN { while ((getline l < C) > 0) { split(l, a, /[ \t]+/); if (a[1] !~ /^#/) col[a[1]] = a[2] } }
	function hex(s,   i, v, c) { v = 0; s = tolower(substr(s, 2)); for (i = 1; i <= 6; i++) { c = index("0123456789abcdef", substr(s, i, 1)) - 1; v = v * 16 + c } return v }
	/^#/ { next }
	$1 == "method" { for (i = 1; i <= NF; i++) h[$i] = i; next }
	$(h["precision"]) == p && $(h["pareto"]) != "na" && $(h["batch_mbases_1t"]) != "nan" {
		w = $(h["max_defect_worst"]); r = $(h["rmse_uniform"])
		e = ($(h["nonfinite"]) + 0 > 0 || w == "nan" || w == "inf") ? 10 : (w + 0 == 0 ? fl : w)
		b = $1; sub(/\+fma$/, "", b)
		r = (r == "nan" || r == "inf") ? 10 : (r + 0 == 0 ? fl : r)
		print $(h["batch_mbases_1t"]), e, hex(col[b] ? col[b] : "#000000"), $1, $(h["pareto"]), r, (e == 10 ? "inf" : w), (r == 10 ? "inf" : r) }' "$csv" > "$W/tradeoff_$P.all"
[ -s "$W/tradeoff_$P.all" ] || exit 1
# the front by the rule (front.awk COL: 1 for each row on the front of
# speed and column COL, "inf" the worst), against the file's column
front() {
	awk -v tol="$tol" -v c="$1" '{ s[NR] = $1 + 0; e[NR] = ($c == "inf") ? 1e300 : $c + 0 }
		END { t = tol / 100
			for (i = 1; i <= NR; i++) { on = 1
				for (j = 1; j <= NR; j++) if (j != i && s[j] >= (1 - t) * s[i] && e[j] <= e[i] && (e[j] < e[i] || s[j] > (1 + t) * s[i])) on = 0
				print on } }' "$W/tradeoff_$P.all"
}
front 7 > "$W/front_w_$P"
front 8 > "$W/front_r_$P"
paste -d' ' "$W/front_w_$P" "$W/tradeoff_$P.all" | awk -v tol="$tol" '$1 != $6 + 0 { printf "tradeoff-data: %s: pareto %s in the file, %d by the rule (speeds within %s%%)\n", $5, $6, $1, tol > "/dev/stderr"; bad = 1 }
	END { exit bad }' || exit 1
# tradeoff_P.dat: speed, worst, colour, method, on the worst-case front,
# RMSE, on the RMSE front (the same rule, its own front)
paste -d' ' "$W/tradeoff_$P.all" "$W/front_r_$P" | cut -d' ' -f1-6,9 > "$W/tradeoff_$P.dat"
# the staircase: err_min(x) = the least error of the methods whose reach
# s / (1 - tol) is at least x, from the left edge to the last reach
stairs() {
	awk -v tol="$tol" -v c="$1" '$c < 10 { print $1 / (1 - tol / 100), $c }' "$W/tradeoff_$P.dat" | sort -g | awk '
		{ x[NR] = $1; e[NR] = $2 }
		END { if (!NR) exit 0
			for (i = NR; i >= 1; i--) { m = (i == NR || e[i] < m) ? e[i] : m; mn[i] = m }
			print x[1] / 100, mn[1]
			for (i = 1; i <= NR; i++) { print x[i], mn[i]; if (i < NR && mn[i + 1] != mn[i]) print x[i], mn[i + 1] }
			print x[NR], 1e6 }'
}
stairs 2 > "$W/stairs_$P.dat"
stairs 6 > "$W/stairs_rms_$P.dat"
[ -s "$W/stairs_$P.dat" ] || exit 1
{ echo "circled: the Pareto front: no other method is at least as accurate and at most $tol% slower, and better in one"
  echo "(speeds within $tol% count as equal); grey staircase: the edge of the region that rule dominates"; } > "$W/rule_$P.txt"
