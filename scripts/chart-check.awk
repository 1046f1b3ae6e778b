# chart-check.awk - mechanical checks of a chart from gnuplot's own SVG
# output (issue 24), one SVG at a time:
#   awk -f chart-check.awk CHART.svg   prints one line per defect, exit 1 if any
# 1. every text (titles, axis and tick labels, key entries, labels) lies
#    on the canvas, and no two texts overlap;
# 2. every graph (a bordered rectangle at least 100 px each way) has a
#    y label (a text turned 90 degrees left of it, beside its middle
#    third) and an x label (a level text under its tick labels);
# 3. every series with a key title has at least one drawn point or line
#    segment off its key sample, unless its title says "no finite point".
# A text's box is estimated from gnuplot's font size (width 0.56 em per
# character, height 1 em, on the baseline), so "overlap" means boxes
# that share more than 1.5 px each way.  Texts turned by other than 0 or
# 90 degrees (the bar chart's diagonal method names) are checked against
# the canvas only: their bounding boxes overlap by construction, their
# strokes do not.  Charts with no per-graph axis labels (small-multiple
# maps with one shared note) pass nolabels=1, which checks for the note.
function fail(msg) { bad++; printf "%s: %s\n", FILENAME, msg }
function ent(s) { gsub(/&lt;/, "<", s); gsub(/&gt;/, ">", s); gsub(/&amp;/, "\\&", s); gsub(/&apos;/, "'", s); gsub(/&quot;/, "\"", s); return s }
/^<svg/ { insvg = 1 }
insvg && /width="[0-9.]+"/ && !cw { match($0, /width="[0-9.]+"/); cw = substr($0, RSTART + 7, RLENGTH - 8) + 0 }
insvg && /height="[0-9.]+"/ && !ch { match($0, /height="[0-9.]+"/); ch = substr($0, RSTART + 8, RLENGTH - 9) + 0 }
/<g id="gnuplot_plot_[0-9]+" ><title>/ {
	ns++; st[ns] = $0; sub(/.*<title>/, "", st[ns]); sub(/<\/title>.*/, "", st[ns]); st[ns] = ent(st[ns])
	if (st[ns] ~ /^gnuplot_plot_/) st[ns] = ""
	cur = ns; keyy[ns] = -1e9; npts[ns] = 0
}
/<g transform="translate\(/ {
	s = $0; match(s, /translate\([-0-9.]+,[-0-9.]+\)/); xy = substr(s, RSTART + 10, RLENGTH - 11); split(xy, c, ",")
	tx = c[1] + 0; ty = c[2] + 0; rot = 0
	if (match(s, /rotate\([-0-9.]+\)/)) rot = substr(s, RSTART + 7, RLENGTH - 8) + 0
	rot = (rot % 360 + 360) % 360
	fs = 10; if (match(s, /font-size="[0-9.]+"/)) fs = substr(s, RSTART + 11, RLENGTH - 12) + 0
	an = "start"; if (match(s, /text-anchor="[a-z]+"/)) an = substr(s, RSTART + 13, RLENGTH - 14)
	intext = 1; txt = ""; next
}
intext && /<text/ { t = $0; gsub(/<[^>]*>/, "", t); gsub(/^[ \t]+|[ \t]+$/, "", t); txt = txt ent(t) }
intext && /<\/g>/ {
	intext = 0
	if (txt ~ /^[ ]*$/) next
	# a boxed (opaque) label is written twice, its box and its text
	dk = txt SUBSEP tx SUBSEP ty; if (dk in dup) next; dup[dk] = 1
	n++; T[n] = txt; w = 0.56 * fs * length(txt)
	lo = (an == "start") ? 0 : (an == "middle" ? -w / 2 : -w); hi = lo + w
	if (rot == 0) { X0[n] = tx + lo; X1[n] = tx + hi; Y0[n] = ty - 0.8 * fs; Y1[n] = ty + 0.2 * fs; K[n] = "h" }
	else if (rot == 270) { X0[n] = tx - 0.8 * fs; X1[n] = tx + 0.2 * fs; Y0[n] = ty - hi; Y1[n] = ty - lo; K[n] = "v" }
	else if (rot == 90) { X0[n] = tx - 0.2 * fs; X1[n] = tx + 0.8 * fs; Y0[n] = ty + lo; Y1[n] = ty + hi; K[n] = "v" }
	else { a = rot * 3.14159265 / 180; X0[n] = tx + (lo < 0 ? lo : 0) * 0.71 - fs; X1[n] = tx + hi * 0.71 + fs; Y0[n] = ty - fs; Y1[n] = ty + w * 0.71 + fs; K[n] = "d" }
	if (cur && K[n] == "h" && keyy[cur] == -1e9 && st[cur] != "") keyy[cur] = ty - 0.325 * fs
	next
}
cur && /<path / && !/ Z  '/ {
	d = $0; sub(/.*d='/, "", d); sub(/'.*/, "", d); m = split(d, p, /[ML] ?/)
	for (i = 1; i <= m; i++) if (p[i] ~ /,/) { split(p[i], q, ","); if ((q[2] + 0) - keyy[cur] > 0.6 || keyy[cur] - (q[2] + 0) > 0.6) npts[cur]++ }
}
cur && /<use xlink:href=/ {
	u = $0; if (match(u, /translate\([-0-9.]+,[-0-9.]+\)/)) { xy = substr(u, RSTART + 10, RLENGTH - 11); split(xy, c, ",")
		if ((c[2] + 0) - keyy[cur] > 0.6 || keyy[cur] - (c[2] + 0) > 0.6) npts[cur]++ }
}
/<path stroke='black'  d='M[-0-9.]+,[-0-9.]+ L[-0-9.]+,[-0-9.]+ L[-0-9.]+,[-0-9.]+ L[-0-9.]+,[-0-9.]+ L[-0-9.]+,[-0-9.]+ Z/ {
	d = $0; match(d, /stroke='black'  d='M[^']* Z/); d = substr(d, RSTART + 20, RLENGTH - 22); m = split(d, p, / L?/)
	gx0 = 1e9; gx1 = -1e9; gy0 = 1e9; gy1 = -1e9
	for (i = 1; i <= m; i++) { if (p[i] !~ /,/) continue; split(p[i], q, ","); x = q[1] + 0; y = q[2] + 0; if (x < gx0) gx0 = x; if (x > gx1) gx1 = x; if (y < gy0) gy0 = y; if (y > gy1) gy1 = y }
	k = sprintf("%.0f %.0f %.0f %.0f", gx0, gy0, gx1, gy1)
	if (gx1 - gx0 >= 100 && gy1 - gy0 >= 100 && !(k in seen)) { seen[k] = 1; ng++; GX0[ng] = gx0; GX1[ng] = gx1; GY0[ng] = gy0; GY1[ng] = gy1 }
}
END {
	if (!cw || !ch) { fail("no canvas size (not a gnuplot SVG?)"); exit 1 }
	for (i = 1; i <= n; i++)
		if (X0[i] < -1 || Y0[i] < -1 || X1[i] > cw + 1 || Y1[i] > ch + 1)
			fail(sprintf("text \"%s\" leaves the %dx%d canvas (box %.0f,%.0f to %.0f,%.0f)", T[i], cw, ch, X0[i], Y0[i], X1[i], Y1[i]))
	for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) {
		if (K[i] == "d" || K[j] == "d") continue
		ox = (X1[i] < X1[j] ? X1[i] : X1[j]) - (X0[i] > X0[j] ? X0[i] : X0[j])
		oy = (Y1[i] < Y1[j] ? Y1[i] : Y1[j]) - (Y0[i] > Y0[j] ? Y0[i] : Y0[j])
		if (ox > 1.5 && oy > 1.5) fail(sprintf("texts \"%s\" and \"%s\" overlap", T[i], T[j]))
	}
	if (ng == 0) fail("no graph found")
	for (g = 1; g <= ng && !nolabels; g++) {
		yl = 0; xl = 0; mid0 = GY0[g] + (GY1[g] - GY0[g]) / 3; mid1 = GY1[g] - (GY1[g] - GY0[g]) / 3
		for (i = 1; i <= n; i++) {
			cy = (Y0[i] + Y1[i]) / 2; cx = (X0[i] + X1[i]) / 2
			if (K[i] == "v" && X1[i] < GX0[g] && X1[i] > GX0[g] - 140 && cy > mid0 && cy < mid1 && length(T[i]) >= 6) yl = 1
			if (K[i] == "h" && Y0[i] > GY1[g] + 1.2 * 10 && Y0[i] < GY1[g] + 200 && cx > GX0[g] && cx < GX1[g] && length(T[i]) >= 6) xl = 1
		}
		if (!yl) fail(sprintf("graph %d (%.0f,%.0f to %.0f,%.0f) has no y label", g, GX0[g], GY0[g], GX1[g], GY1[g]))
		if (!xl) fail(sprintf("graph %d (%.0f,%.0f to %.0f,%.0f) has no x label", g, GX0[g], GY0[g], GX1[g], GY1[g]))
	}
	if (nolabels) { for (i = 1; i <= n; i++) if (T[i] ~ /^x: /) note = 1; if (!note) fail("no shared axis note (\"x: ...\")") }
	# with an opaque key, gnuplot draws a series' key sample in a group of
	# its own after the data: a title's drawing is summed over its groups
	for (s = 1; s <= ns; s++) if (st[s] != "") tot[st[s]] += npts[s]
	for (t in tot)
		if (tot[t] == 0 && t !~ /no finite point/)
			fail(sprintf("series \"%s\" draws nothing and does not say so", t))
	exit bad > 0
}
