# nf-panels.awk - which panels of a line chart draw a non-finite output,
# and where its finite data end (scripts/lines.gp): prints "YFIN F1 F2 ..."
# with YFIN 4x the largest finite value of column c over all series (0:
# none) and Fp 1 when a series of panel p has a bin with a non-finite count
# (column 4) or a value at ce (where series.awk draws non-finite output).
# awk -v ce=CEIL -v c=COL -v np=PANELS -v single=0|1 -v files="F1 F2 ..."
#     -v panels="P1 P2 ..." -f nf-panels.awk
BEGIN {
	n = split(files, f, " "); split(panels, pa, " ")
	for (i = 1; i <= n; i++) {
		p = single ? 1 : pa[i] + 0
		while ((getline l < f[i]) > 0) {
			split(l, a, " ")
			if (a[4] + 0 > 0 || a[2] + 0 >= ce + 0 || a[c] + 0 >= ce + 0) nf[p] = 1
			else if (a[c] + 0 > y) y = a[c] + 0
		}
		close(f[i])
	}
	printf "%g", (y > 0 ? y * 4 : 0)
	for (p = 1; p <= np; p++) printf " %d", nf[p] + 0
	printf "\n"
}
