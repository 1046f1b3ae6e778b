# floor-bands.awk - the accuracy-floor bands of a line chart: each method's
# own floor (its exact formula rounded once: by_nz.csv's floor_rms and
# floor_max, the largest over the chart's distributions per bin), merged
# within a panel where two methods' floors agree (floor_max within 1.3x in
# every bin), so that a panel shows one band per distinct floor, in the
# colour of its methods (grey when they differ), the first band of a panel
# solid and the next ones hatched, titled with the methods whose floor it is.
# awk -F, -v p=PREC -v ds="DIST ..." -v ax=AXIS -v sc=lin|log [-v zx=X]
#     -v methods="M1 M2 ..." -v panels="P1 P2 ..." -v colors="C1 C2 ..."
#     -v out=PREFIX -f floor-bands.awk by_nz.csv
# writes PREFIX_K.dat (x rms max, by x) per band and prints one line per
# band: "PREFIX_K.dat panel colour fill title" (fill: 0 solid, else a
# gnuplot hatch pattern).  In a long title, a name that extends the first
# is written "+SUFFIX" ("floor of cycles_cross111, +_avx2").  Titles: "floor of A", "floor
# of A, B", "floor of all N" (every method of a panel of 3 or more), "floor of the
# other N" (the N methods of the panel that no other band names);
# scripts/chart-check.awk checks that each names methods of its own panel
# and that the counts add up.  Prints nothing when the run has no floor
# columns (it predates them).
BEGIN {
	n = split(methods, M, " "); split(panels, PN, " "); split(colors, CO, " ")
	for (i = 1; i <= n; i++) idx[M[i]] = i
	nd = split(ds, a, " "); for (i = 1; i <= nd; i++) want[a[i]] = 1
}
/^#/ { next }
$1 == "method" { for (i = 1; i <= NF; i++) h[$i] = i; next }
!("floor_max" in h) { exit }
$2 == p && ($3 in want) && $4 == ax && ($1 in idx) && $(h["floor_max"]) != "nan" && $(h["floor_max"]) + 0 > 0 {
	i = idx[$1]; k = $5
	x = (sc == "log") ? ((k + 0 <= -17 && zx != "") ? zx : 10 ^ ((k + $6) / 2)) : (k + $6) / 2
	if (!((i, k) in hi)) { nb[i]++; bins[i, nb[i]] = k; X[i, k] = x }
	if (!((i, k) in hi) || $(h["floor_max"]) + 0 > hi[i, k]) hi[i, k] = $(h["floor_max"]) + 0
	if (!((i, k) in lo) || $(h["floor_rms"]) + 0 > lo[i, k]) lo[i, k] = $(h["floor_rms"]) + 0
}
function same(i, j,   b, k, r) {
	if (nb[i] != nb[j]) return 0
	for (b = 1; b <= nb[i]; b++) {
		k = bins[i, b]
		if (!((j, k) in hi)) return 0
		r = hi[i, k] / hi[j, k]
		if (r > 1.3 || r < 1 / 1.3) return 0
	}
	return 1
}
END {
	for (i = 1; i <= n; i++) { if (nb[i]) np[PN[i]]++; else continue
		g[i] = i
		for (j = 1; j < i; j++) if (nb[j] && PN[j] == PN[i] && g[j] == j && same(j, i)) { g[i] = j; break }
		cnt[g[i]]++
	}
	nbands = 0
	for (i = 1; i <= n; i++) {
		if (!nb[i] || g[i] != i) continue
		nbands++; f = out "_" nbands ".dat"
		# the band: the lowest RMS to the largest max of its methods, per bin
		for (b = 1; b <= nb[i]; b++) { k = bins[i, b]; L = lo[i, k]; H = hi[i, k]
			for (j = i + 1; j <= n; j++) if (g[j] == i && (j, k) in hi) { if (lo[j, k] < L) L = lo[j, k]; if (hi[j, k] > H) H = hi[j, k] }
			printf "%.10g %.6g %.6g\n", X[i, k], (L > 0 ? L : H), H | ("sort -g > " f) }
		close("sort -g > " f)
		names = ""; others = ""; no = 0
		for (j = 1; j <= n; j++) if (nb[j] && PN[j] == PN[i]) {
			if (g[j] == i) names = names (names == "" ? "" : ", ") M[j]
			else { others = others (others == "" ? "" : ", ") M[j]; no++ }
		}
		# a long list whose later names extend the first (cycles_cross111,
		# cycles_cross111_avx2) says the extensions alone: "+_avx2"
		if (length(names) > 26) { k = split(names, nn, /, /); ab = nn[1]
			for (j = 2; j <= k; j++) ab = ab ", " (index(nn[j], nn[1]) == 1 && length(nn[j]) > length(nn[1]) ? "+" substr(nn[j], length(nn[1]) + 1) : nn[j])
			names = ab }
		if (cnt[i] > 2 && no == 0) t = "floor of all " cnt[i]
		else if (cnt[i] > 2 && !(PN[i] in other)) { t = "floor of the other " cnt[i]; other[PN[i]] = 1 }
		else t = "floor of " names
		# the colour: its methods' when they share one, else grey; the fill:
		# the first band of a panel solid, the next ones hatched (4, 5, 6, 7),
		# so that bands in shades of one hue stay apart
		c = CO[i]; for (j = i + 1; j <= n; j++) if (g[j] == i && CO[j] != c) c = "#9a9a9a"
		fill = kp[PN[i]]++ ? 3 + (kp[PN[i]] - 2) % 4 + 1 : 0
		print f, PN[i], c, fill, t
	}
}
