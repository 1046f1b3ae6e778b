# tradeoff-labels.awk - labels of tradeoff.gp that never overprint:
# points that coincide on the chart share one label ("a ≈ b", an
# almost-equal sign: the markers overlap, the methods need not be
# bit-for-bit the same, which "=" says elsewhere); each label
# goes right of its point, or, when that spot is taken, up or down to the
# nearest free spot, joined to its point by a grey leader line.  A group
# of more than three names is set on lines of three (a 50-method run had
# eight coinciding markers, one label wider than any free spot).
# awk -v col=2|6 -v xmin= -v xmax= -v ymin= -v ymax= -v gw= -v gh= -f tradeoff-labels.awk tradeoff_P.dat
# (gw, gh: the graph's width and height in pixels; labels are 10-point)
# prints gnuplot commands (set label / set arrow).  Coordinates are
# fractions of the graph, from the log axes.
function fx(x) { return (log(x) - log(xmin)) / (log(xmax) - log(xmin)) }
function fy(y) { return (log(y) - log(ymin)) / (log(ymax) - log(ymin)) }
function free(x0, y0, w, hh,   k) {
	if (x0 < 0 || x0 + w > 0.99 || y0 - hh + H < 0.02 || y0 + hh - H > 0.98) return 0
	for (k = 1; k <= nl; k++)
		if (x0 < lx[k] + lw[k] && lx[k] < x0 + w && y0 - hh < ly[k] + lh[k] && ly[k] - lh[k] < y0 + hh) return 0
	for (k = 1; k < ns; k++) # and off the staircase (axis-parallel segments between its corners)
		if ((sx[k] < sx[k + 1] ? sx[k] : sx[k + 1]) < x0 + w && (sx[k] > sx[k + 1] ? sx[k] : sx[k + 1]) > x0 && \
		    (sy[k] < sy[k + 1] ? sy[k] : sy[k + 1]) < y0 + hh && (sy[k] > sy[k + 1] ? sy[k] : sy[k + 1]) > y0 - hh) return 0
	for (k = 1; k <= n; k++) # keep off the markers too (up to the front's circles, 9 px)
		if (px[k] > x0 - MX && px[k] < x0 + w + MX && py[k] > y0 - hh - MY && py[k] < y0 + hh + MY) return 0
	return 1
}
BEGIN { CW = 7.4 / gw; H = 8.5 / gh; MX = 9 / gw; MY = 5 / gh # width of a character, half a label's height (fractions)
	# the staircase (stairs: "x y" corners), clamped to the graph
	if (stairs != "") while ((getline l < stairs) > 0) { split(l, c, " "); ns++
		sx[ns] = c[1] + 0 < xmin ? 0 : (c[1] + 0 > xmax ? 1 : fx(c[1] + 0)); sy[ns] = c[2] + 0 > ymax ? 1 : (c[2] + 0 < ymin ? 0 : fy(c[2] + 0)) } }
{ n++; px[n] = fx($1); py[n] = fy($col); name[n] = $4; X[n] = $1; Y[n] = $col }
END {
	# coincident points: one label
	for (i = 1; i <= n; i++) {
		if (gone[i]) continue
		t = name[i]; g = 1; wl = length(t); lines[i] = 1; cur = length(t)
		for (j = i + 1; j <= n; j++)
			if (!gone[j] && (px[i] - px[j]) ^ 2 + ((py[i] - py[j]) * 0.5) ^ 2 < 0.005 ^ 2) {
				gone[j] = 1
				if (g++ % 3 == 0) { t = t " \342\211\210\\n" name[j]; lines[i]++; cur = length(name[j]) }
				else { t = t " \342\211\210 " name[j]; cur += 3 + length(name[j]) }
				if (cur > wl) wl = cur
			}
		text[i] = t; tlen[i] = wl
	}
	# place, from the top down
	m = 0
	for (i = 1; i <= n; i++) if (!gone[i]) ord[++m] = i
	for (a = 1; a <= m; a++) for (b = a + 1; b <= m; b++) if (py[ord[b]] > py[ord[a]]) { t = ord[a]; ord[a] = ord[b]; ord[b] = t }
	for (a = 1; a <= m; a++) {
		i = ord[a]; w = tlen[i] * CW + 0.01; hh = lines[i] * H
		placed = 0
		# up and down in steps of a label's height, right then left of the
		# point; in a crowd (a second pass), further up and down and further
		# right or left, behind a leader line
		for (k = 0; k <= 24 + 60 && !placed; k++) {
			dy = (k % 2 ? 1 : -1) * int(((k > 24 ? k - 25 : k) + 1) / 2) * 2.2 * H
			for (side = 0; side < (k > 24 ? 4 : 2) && !placed; side++) {
				x0 = side % 2 ? px[i] - MX - 0.004 - w : px[i] + MX + 0.004
				if (side >= 2) x0 += (side == 2 ? 1 : -1) * 0.08
				y0 = py[i] + dy
				if (free(x0, y0, w, hh)) placed = 1
			}
		}
		if (!placed) # any free spot of the graph, nearest the point first, behind a leader line
			for (d = 0; d <= 1 && !placed; d += 0.02)
				for (yy = 0.03; yy <= 0.97 && !placed; yy += 2.2 * H)
					for (xx = 0; xx + w <= 0.99 && !placed; xx += 0.02)
						if ((xx - px[i]) ^ 2 + (yy - py[i]) ^ 2 <= d * d && free(xx, yy, w, hh)) { x0 = xx; y0 = yy; placed = 1; side = 3 }
		if (!placed) { # give up: right of the point, or as far right as the canvas lets it
			x0 = px[i] + 0.012; y0 = py[i]
			if (x0 + w > 0.99) x0 = 0.99 - w
			if (x0 < 0) x0 = 0
		}
		nl++; lx[nl] = x0; ly[nl] = y0; lw[nl] = w; lh[nl] = hh
		printf "set label %d \"%s\" at graph %.4f, graph %.4f left font \",10\" noenhanced front\n", nl, text[i], x0, y0
		if (k > 1 || (k == 1 && dy != 0) || x0 < px[i] || side > 2)
			printf "set arrow %d from first %g, first %g to graph %.4f, graph %.4f nohead lc rgb \"#777777\" lw 0.8 back\n", nl, X[i], Y[i], (x0 < px[i] ? x0 + w - 0.004 : x0 - 0.002), y0
	}
}
