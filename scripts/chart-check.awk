# chart-check.awk - mechanical checks of a chart from gnuplot's own SVG
# output, one SVG at a time:
#   awk -f chart-check.awk CHART.svg   prints one line per defect, exit 1 if any
# 1. every text (titles, axis and tick labels, key entries, labels) lies
#    on the canvas, and no two texts overlap;
# 2. every graph (a bordered rectangle at least 100 px each way) has a
#    y label (a text turned 90 degrees left of it, beside its middle
#    third) and an x label (a level text under its tick labels);
# 3. every series with a key title has at least one drawn point, line
#    segment or filled area off its key sample, unless its title says "no
#    finite point" or "A = B" (drawn as B's: certify's coinciding
#    brackets, said once);
# 4. no text lies over data: no text box (shrunk by 1.5 px) is crossed by
#    a line segment of a plotted series or holds one of its markers (key
#    samples excepted: a key title may sit beside its own sample, never
#    over another series' data);
# 5. every accuracy-floor band names the methods of its own panel: a
#    series titled "floor of A, B" needs series A and B in the same plot
#    ("floor of A, +_x": A and A_x);
#    "floor of all N" needs N method series there, "floor of the other N"
#    needs N that no other floor title of the plot names (a floor band
#    titled without names, or with a method the panel does not draw, is
#    a floor from another method).
# 6. (with nfband=1: the line charts of lines.gp) a plot has the
#    non-finite band (its fill, style.gp's C_NONFINITE) exactly when a
#    series of that plot counts non-finite outputs in its key title: no
#    band reserved where nothing is non-finite, none missing where
#    something is.
# 7. no two series of one plot share a colour: a method's line (its
#    stroke or marker colour) differs from every other method's of that
#    plot, NAME+fma excepted (drawn dashed in NAME's colour), and no two
#    floor bands of a plot share a colour and a fill (solid, or the same
#    hatch); the colours come from scripts/palette.txt, whose any two
#    differ by a CIELAB delta-E of at least 10 (tests/plots_cli.sh), so a
#    colour shared is a method missing from it or a band drawn twice.
# 8. (with nfband=1: the line charts) no two methods of one plot are
#    drawn alike in dash and marker together: each has its own pair in
#    scripts/palette.txt (palette.sh --check), as it has its own colour,
#    so a pair shared is a method missing from the table or a style
#    assigned by place rather than by method (NAME+fma excepted).  The
#    dash is the series' stroke-dasharray divided by its smallest entry.
# 9. (with leadcheck=1: a diagnostic, not run on the committed charts,
#    whose tradeoff charts it fails: docs/chart-grading.md) a label's
#    leader line (the tradeoff charts': grey, rgb(119, 119,
#    119), drawn outside any series) crosses no other leader, passes
#    through no text but, at its end, its own label's edge, and passes
#    no marker closer than 5 pixels but those within 9 of its start (its
#    own point's, and markers that overlap it).
# A text's box is estimated from gnuplot's font size (width 0.56 em per
# character, height 1 em, on the baseline), so "overlap" means boxes
# that share more than 1.5 px each way.  Texts turned by other than 0 or
# 90 degrees (the bar chart's diagonal method names) are checked against
# the canvas only: their bounding boxes overlap by construction, their
# strokes do not.  Charts with no per-graph axis labels (small-multiple
# maps with one shared note) pass nolabels=1, which checks for the note;
# the renders (scripts/ao.gp, brushed.gp: images without axes, drawn with
# an off-range point for their colour bars) pass images=1, which checks
# only the texts (1).
function fail(msg) { bad++; printf "%s: %s\n", FILENAME, msg }
function ent(s) { gsub(/&lt;/, "<", s); gsub(/&gt;/, ">", s); gsub(/&amp;/, "\\&", s); gsub(/&apos;/, "'", s); gsub(/&quot;/, "\"", s); return s }
/^<svg/ { insvg = 1 }
insvg && /width="[0-9.]+"/ && !cw { match($0, /width="[0-9.]+"/); cw = substr($0, RSTART + 7, RLENGTH - 8) + 0 }
insvg && /height="[0-9.]+"/ && !ch { match($0, /height="[0-9.]+"/); ch = substr($0, RSTART + 8, RLENGTH - 9) + 0 }
/<g id="gnuplot_plot_[0-9]+[a-z]*" ><title>/ {
	ns++; st[ns] = $0; sub(/.*<title>/, "", st[ns]); sub(/<\/title>.*/, "", st[ns]); st[ns] = ent(st[ns])
	if (st[ns] ~ /^gnuplot_plot_/) st[ns] = ""
	# plot ids restart at 1 in each plot of a multiplot: one panel each
	match($0, /gnuplot_plot_[0-9]+/); pid = substr($0, RSTART + 13, RLENGTH - 13) + 0
	if (pid <= lastpid || ns == 1) { npl++; pband[npl] = nfpend; nfpend = 0 }
	lastpid = pid; spl[ns] = npl
	cur = ns; keyy[ns] = -1e9; npts[ns] = 0
}
# a series' style (check 7): its first line or marker colour, or for a
# band its fill colour with its opacity or hatch
function rgb(s) { gsub(/ /, "", s); return s }
cur && st[cur] != "" && !(cur in sty) && match($0, /stroke:rgb\([ 0-9,]+\)' d='[^']*'/) { sty[cur] = "hatch " rgb(substr($0, RSTART + 7, RLENGTH - 7)) }
cur && st[cur] != "" && !(cur in sty) && match($0, /fill = 'rgb\([ 0-9,]+\)' fill-opacity = '[0-9.]+'/) { sty[cur] = "solid " rgb(substr($0, RSTART + 8, RLENGTH - 8)) }
cur && st[cur] != "" && !(cur in sty) && match($0, /(stroke|color)='rgb\([ 0-9,]+\)'/) { sty[cur] = rgb(substr($0, RSTART, RLENGTH)); sub(/^[a-z]+=/, "", sty[cur]) }
# a series' line style (check 8): its first path's dash pattern and its
# first marker's symbol
function dashkey(s,   a, k, i, lo, r) {
	if (!match(s, /stroke-dasharray='[0-9.,]+'/)) return "solid"
	k = split(substr(s, RSTART + 18, RLENGTH - 19), a, ","); lo = a[1] + 0
	for (i = 2; i <= k; i++) if (a[i] + 0 < lo) lo = a[i] + 0
	for (i = 1; i <= k; i++) r = r (i > 1 ? "," : "") sprintf("%.2g", a[i] / lo)
	return r
}
cur && st[cur] != "" && !(cur in sdash) && /<path stroke=/ { sdash[cur] = dashkey($0) }
cur && st[cur] != "" && !(cur in spt) && match($0, /xlink:href='#gpPt[0-9]+'/) { spt[cur] = substr($0, RSTART + 17, RLENGTH - 18) }
# a leader line (check 9): its segments (gnuplot writes one path for all
# of a plot's arrows, over several lines)
!cur && /<path stroke='rgb\(119, 119, 119\)'/ { inlead = 1; ld = "" }
inlead { ld = ld " " $0; if ($0 !~ /'\/>/) next; inlead = 0
	d = ld; sub(/.*d='/, "", d); sub(/'.*/, "", d); gsub(/[\t ]+/, " ", d); m = split(d, p, / +/); have = 0
	for (i = 1; i <= m; i++) {
		if (p[i] !~ /,/) continue
		mv = (p[i] ~ /^M/); t = p[i]; sub(/^[ML]/, "", t); split(t, q, ",")
		if (!mv && have) { nld++; DX0[nld] = px; DY0[nld] = py; DX1[nld] = q[1] + 0; DY1[nld] = q[2] + 0 }
		px = q[1] + 0; py = q[2] + 0; have = 1
	}
}
# a non-finite band (drawn behind, before its plot's series)
/<polygon fill = 'rgb\(251, 227, 212\)'/ { nfpend = 1 }
# the end of a plot's group (a text's group ends in the rule below)
cur && !intext && /^\t<\/g>$/ { cur = 0; next }
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
	TS[n] = cur
	next
}
function offkey(y) { return y - keyy[cur] > 0.6 || keyy[cur] - y > 0.6 }
cur && /<path / && !/ Z  '/ {
	d = $0; sub(/.*d='/, "", d); sub(/'.*/, "", d); m = split(d, p, / +/); have = 0
	for (i = 1; i <= m; i++) {
		if (p[i] !~ /,/) continue
		mv = (p[i] ~ /^M/); t = p[i]; sub(/^[ML]/, "", t); split(t, q, ","); x = q[1] + 0; y = q[2] + 0
		if (offkey(y)) npts[cur]++
		# a segment of data: not the key sample (both ends on the key's row)
		if (!mv && have && (offkey(y) || offkey(py))) { nseg++; SX0[nseg] = px; SY0[nseg] = py; SX1[nseg] = x; SY1[nseg] = y; SS[nseg] = cur }
		px = x; py = y; have = 1
	}
}
cur && /<use xlink:href=/ {
	u = $0; if (match(u, /translate\([-0-9.]+,[-0-9.]+\)/)) { xy = substr(u, RSTART + 10, RLENGTH - 11); split(xy, c, ",")
		if (offkey(c[2] + 0)) { npts[cur]++; nmk++; MKX[nmk] = c[1] + 0; MKY[nmk] = c[2] + 0; MKS[nmk] = cur } }
}
# an image (a map panel) draws: gnuplot's ids lose their letter after the
# 26th panel of a multiplot, which then reads as a titled series here
cur && /<image / { npts[cur]++ }
cur && /<polygon / && match($0, /points = '[^']*'/) {
	d = substr($0, RSTART + 10, RLENGTH - 11); m = split(d, p, / +/)
	for (i = 1; i <= m; i++) if (p[i] ~ /,/) { split(p[i], q, ","); if (offkey(q[2] + 0)) npts[cur]++ }
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
	if (images) exit bad > 0
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
		if (tot[t] == 0 && t !~ /no finite point/ && t !~ /^[^ ]+ = [^ ]+$/)
			fail(sprintf("series \"%s\" draws nothing and does not say so", t))
	overdata()
	if (leadcheck) leaders()
	floors()
	if (nfband) { nfbands(); linestyles() }
	colours()
	exit bad > 0
}
# cross(i, s): 1 when segment s passes through text box i (shrunk 1.5 px):
# Liang-Barsky clipping of the segment to the box
function cross(i, s,   x0, y0, dx, dy, t0, t1, k, pp, qq, r, bx0, bx1, by0, by1) {
	bx0 = X0[i] + 1.5; bx1 = X1[i] - 1.5; by0 = Y0[i] + 1.5; by1 = Y1[i] - 1.5
	x0 = SX0[s]; y0 = SY0[s]; dx = SX1[s] - x0; dy = SY1[s] - y0; t0 = 0; t1 = 1
	for (k = 1; k <= 4; k++) {
		if (k == 1) { pp = -dx; qq = x0 - bx0 } else if (k == 2) { pp = dx; qq = bx1 - x0 }
		else if (k == 3) { pp = -dy; qq = y0 - by0 } else { pp = dy; qq = by1 - y0 }
		if (pp == 0) { if (qq < 0) return 0; continue }
		r = qq / pp
		if (pp < 0) { if (r > t1) return 0; if (r > t0) t0 = r }
		else { if (r < t0) return 0; if (r < t1) t1 = r }
	}
	return 1
}
function overdata(   i, s, k, hit, lo, hi) {
	for (i = 1; i <= n; i++) {
		if (K[i] == "d") continue
		hit = ""
		for (s = 1; s <= nseg && hit == ""; s++) {
			if ((SX0[s] < X0[i] && SX1[s] < X0[i]) || (SX0[s] > X1[i] && SX1[s] > X1[i]) || (SY0[s] < Y0[i] && SY1[s] < Y0[i]) || (SY0[s] > Y1[i] && SY1[s] > Y1[i])) continue
			if (cross(i, s)) hit = st[SS[s]] != "" ? st[SS[s]] : "an untitled series"
		}
		for (k = 1; k <= nmk && hit == ""; k++)
			if (MKX[k] > X0[i] + 1.5 && MKX[k] < X1[i] - 1.5 && MKY[k] > Y0[i] + 1.5 && MKY[k] < Y1[i] - 1.5)
				hit = "a marker of " (st[MKS[k]] != "" ? st[MKS[k]] : "an untitled series")
		if (hit != "") fail(sprintf("text \"%s\" lies over data (%s)", T[i], hit))
	}
}
# floors(): the floor bands of each plot name methods of that plot
function floors(   s, t, a, k, nm, pl, named, other, cntm, x) {
	for (s = 1; s <= ns; s++) if (st[s] != "" && st[s] !~ /floor/) { t = st[s]; sub(/ .*/, "", t); inpl[spl[s], t] = 1; nmeth[spl[s]]++ }
	for (s = 1; s <= ns; s++) {
		if (st[s] !~ /floor/) continue
		pl = spl[s]; t = st[s]
		if (t ~ /^floor of all [0-9]+$/) { x = t; sub(/.* /, "", x); if (x + 0 != nmeth[pl]) fail(sprintf("floor band \"%s\": its plot draws %d methods", t, nmeth[pl])); continue }
		if (t ~ /^floor of the other [0-9]+$/) { otherc[pl] = t; continue }
		if (t !~ /^floor of [^ ]/) { fail(sprintf("floor band \"%s\" does not name whose floor it is", t)); continue }
		sub(/^floor of /, "", t); k = split(t, a, /, /)
		for (x = 2; x <= k; x++) if (a[x] ~ /^\+/) a[x] = a[1] substr(a[x], 2)
		for (x = 1; x <= k; x++) {
			if (!((pl, a[x]) in inpl)) fail(sprintf("floor band \"%s\" is the floor of %s, which its plot does not draw", st[s], a[x]))
			else named[pl]++
		}
	}
	for (pl in otherc) { x = otherc[pl]; sub(/.* /, "", x)
		if (x + named[pl] != nmeth[pl]) fail(sprintf("floor band \"%s\": %d methods of its plot are not named by another floor band", otherc[pl], nmeth[pl] - named[pl])) }
}
# nfbands(): the non-finite band in a plot exactly when a series of it
# counts non-finite outputs
function nfbands(   s, pl) {
	for (s = 1; s <= ns; s++) if (st[s] ~ /non-finite/) pnf[spl[s]] = 1
	for (pl = 1; pl <= npl; pl++) {
		if (pband[pl] && !pnf[pl]) fail(sprintf("plot %d reserves a non-finite band, but none of its series is non-finite", pl))
		if (!pband[pl] && pnf[pl]) fail(sprintf("plot %d has a non-finite series but no non-finite band", pl))
	}
}
# colours(): no two series of a plot in one colour (check 7)
function colours(   s, t, b, k, seen2) {
	for (s = 1; s <= ns; s++) {
		if (st[s] == "" || !(s in sty) || ((spl[s], st[s]) in seen2)) continue
		seen2[spl[s], st[s]] = 1
		t = st[s]; sub(/ .*/, "", t); b = t; sub(/\+fma$/, "", b)
		k = (st[s] ~ /^floor/) ? "band " sty[s] : "line " sty[s]
		if ((spl[s], k) in owner && !(st[s] !~ /^floor/ && owner[spl[s], k] == b))
			fail(sprintf("\"%s\" and \"%s\" share the colour %s in one plot", own[spl[s], k], st[s], sty[s]))
		if (!((spl[s], k) in owner)) { owner[spl[s], k] = (st[s] ~ /^floor/) ? st[s] : b; own[spl[s], k] = st[s] }
	}
}
# linestyles(): no two methods of a plot in one dash and marker (check 8)
function linestyles(   s, t, b, k, seen3) {
	for (s = 1; s <= ns; s++) {
		if (st[s] == "" || st[s] ~ /^floor/ || !((s in sdash) || (s in spt)) || ((spl[s], st[s]) in seen3)) continue
		seen3[spl[s], st[s]] = 1
		t = st[s]; sub(/ .*/, "", t); b = t; sub(/\+fma$/, "", b)
		k = "dash " ((s in sdash) ? sdash[s] : "none") ", marker " ((s in spt) ? spt[s] : "none")
		if ((spl[s], k) in lsown && lsown[spl[s], k] != b)
			fail(sprintf("\"%s\" and \"%s\" share the line style (%s) in one plot", lsname[spl[s], k], st[s], k))
		if (!((spl[s], k) in lsown)) { lsown[spl[s], k] = b; lsname[spl[s], k] = st[s] }
	}
}
# leaders(): no two leader lines cross, none passes through a text (check 9)
function ori(ax, ay, bx, by, cx, cy,   v) { v = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax); return v > 0.01 ? 1 : (v < -0.01 ? -1 : 0) }
function leaders(   a, b, i) {
	for (a = 1; a <= nld; a++) for (b = a + 1; b <= nld; b++)
		if (ori(DX0[a], DY0[a], DX1[a], DY1[a], DX0[b], DY0[b]) * ori(DX0[a], DY0[a], DX1[a], DY1[a], DX1[b], DY1[b]) < 0 && \
		    ori(DX0[b], DY0[b], DX1[b], DY1[b], DX0[a], DY0[a]) * ori(DX0[b], DY0[b], DX1[b], DY1[b], DX1[a], DY1[a]) < 0)
			fail(sprintf("two leader lines cross (%.0f,%.0f-%.0f,%.0f and %.0f,%.0f-%.0f,%.0f)", DX0[a], DY0[a], DX1[a], DY1[a], DX0[b], DY0[b], DX1[b], DY1[b]))
	for (a = 1; a <= nld; a++) { nseg++; SX0[nseg] = DX0[a]; SY0[nseg] = DY0[a]; SX1[nseg] = DX1[a]; SY1[nseg] = DY1[a]
		for (i = 1; i <= n; i++) if (K[i] != "d" && cross(i, nseg)) fail(sprintf("a leader line passes through the text \"%s\"", T[i]))
		nseg--
		for (i = 1; i <= nmk; i++) if ((MKX[i] - DX0[a]) ^ 2 + (MKY[i] - DY0[a]) ^ 2 > 81 && pdist2(MKX[i], MKY[i], DX0[a], DY0[a], DX1[a], DY1[a]) < 25)
			fail(sprintf("a leader line (%.0f,%.0f-%.0f,%.0f) passes over a marker at %.0f,%.0f", DX0[a], DY0[a], DX1[a], DY1[a], MKX[i], MKY[i])) }
}
function pdist2(qx, qy, x0, y0, x1, y1,   dx, dy, t) {
	dx = x1 - x0; dy = y1 - y0; t = (dx * dx + dy * dy > 0) ? ((qx - x0) * dx + (qy - y0) * dy) / (dx * dx + dy * dy) : 0
	if (t < 0) t = 0; if (t > 1) t = 1
	return (qx - x0 - t * dx) ^ 2 + (qy - y0 - t * dy) ^ 2
}
