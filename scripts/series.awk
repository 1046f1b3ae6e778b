# series.awk - one method's series of a line chart from by_nz.csv, with the
# non-finite outputs each bin dropped (the study's bins keep only
# finite errors, so a bin's non-finite count is the largest count any
# method has in that bin, on the same inputs, minus this method's).
# awk -F, -v m=METHOD -v p=PREC -v ds="DIST ..." -v ax=AXIS -v sc=lin|log
#     -v fl=FLOOR -v ce=CEIL [-v zx=X] -f series.awk by_nz.csv by_nz.csv
# prints "x max rms nonfinite" per bin, by x: lin: x the bin's middle; log:
# 10^middle, and the pole bin (from -17) at zx.  A zero error is drawn at
# fl; a non-finite max (or a bin this method has no finite output in) at ce.
function v(x) { return (x == "inf" || x == "nan" || x == "-nan") ? ce : (x + 0 == 0 ? fl : x + 0) }
BEGIN { n = split(ds, a, " "); for (i = 1; i <= n; i++) want[a[i]] = 1 }
/^#/ { next }
$1 == "method" { next }
$2 != p || !($3 in want) || $4 != ax { next }
FNR == NR { k = $3 SUBSEP $5; if ($7 + 0 > most[k]) most[k] = $7 + 0; lo[k] = $5; hi[k] = $6; next }
$1 == m { hasd[$3] = 1; k = $3 SUBSEP $5; cnt[k] = $7 + 0; mx[k] = v($9); rms[k] = v($8) }
END {
	for (k in most) {
		split(k, b, SUBSEP); bin = b[2]
		if (!(b[1] in hasd)) continue
		x = (sc == "log") ? ((lo[k] + 0 <= -17 && zx != "") ? zx : 10 ^ ((lo[k] + hi[k]) / 2)) : (lo[k] + hi[k]) / 2
		nf = most[k] - cnt[k]
		X[bin] = x
		if (k in mx) { if (mx[k] > M[bin]) M[bin] = mx[k]; if (rms[k] > R[bin]) R[bin] = rms[k] }
		else { M[bin] = ce; if (!(bin in R)) R[bin] = ce }
		N[bin] += nf
	}
	for (bin in X) printf "%.10g %.6g %.6g %d\n", X[bin], M[bin], (R[bin] > 0 ? R[bin] : ce), N[bin]
}
