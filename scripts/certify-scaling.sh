#!/bin/sh
# certify-scaling.sh TIMES.csv - on paper: the time of a certify run on P
# ranks that take the next region as they come free (in the file's
# order), from a run's certify-times.csv (each region's CPU seconds per
# phase); a barrier before the images pass and before the refinement
# (taken as one pass).  Prints ranks, time, speed-up and efficiency for
# P = 1, 2, 4, ..., 64.
set -eu
[ $# -eq 1 ] && [ -r "$1" ] || { echo "usage: sh scripts/certify-scaling.sh DIR/certify-times.csv" >&2; exit 2; }
grep -v '^#' "$1" | awk -F, '
NR > 1 { a[++n] = $7 + $8 + $9 + $10; b[n] = $11; c[n] = $12; tot += $7 + $8 + $9 + $10 + $11 + $12 }
function span(v, p,   q, i, j, m, best) {
	for (j = 1; j <= p; j++) q[j] = 0
	for (i = 1; i <= n; i++) {
		if (v[i] <= 0) continue
		m = 1
		for (j = 2; j <= p; j++) if (q[j] < q[m]) m = j
		q[m] += v[i]
	}
	best = 0
	for (j = 1; j <= p; j++) if (q[j] > best) best = q[j]
	return best
}
END {
	print "ranks,time_s,speedup,efficiency"
	for (p = 1; p <= 64; p *= 2) {
		t = span(a, p) + span(b, p) + span(c, p)
		printf "%d,%.1f,%.2f,%.2f\n", p, t, tot / t, tot / t / p
	}
}'
