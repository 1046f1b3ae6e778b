# series-titles.awk - the key title of each series of a line chart, one a
# line: the method's name; "= OTHER" when its column col is, bin for bin,
# the same as an earlier series' of the same panel (coinciding lines, which
# would otherwise read as one); "N non-finite" (the sum of column 4); and
# "no finite point" when no bin holds a finite value below ce.
# awk -v files="F1 F2 ..." -v names="M1 M2 ..." -v panels="P1 P2 ..."
#     -v col=2 -v ce=CEIL -f series-titles.awk
BEGIN {
	n = split(files, f, " "); split(names, nm, " "); split(panels, pa, " ")
	for (i = 1; i <= n; i++) {
		s = ""; nf = 0; fin = 0
		while ((getline l < f[i]) > 0) {
			split(l, c, " "); s = s c[1] ":" c[col] ";"; nf += c[4]
			if (c[col] + 0 < ce + 0) fin++
		}
		close(f[i]); sig[i] = s
		t = nm[i]
		for (j = 1; j < i; j++)
			if (pa[j] == pa[i] && sig[j] == s && s != "") { t = t " = " nm[j]; break }
		if (nf > 0) t = t sprintf(" (%d non-finite)", nf)
		if (fin == 0) t = t " (no finite point)"
		print t
	}
}
