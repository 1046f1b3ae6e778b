# styles.awk - the program of scripts/styles.sh (which see), with
# scripts/lab.awk's colour functions.
BEGIN {
	while ((getline l < L) > 0) { split(l, a, " "); fam[a[1]] = a[2]; rix[a[1]] = ++nreg; if (!(a[2] in forder)) forder[a[2]] = ++nf0 }
	# Okabe-Ito (2008) without its yellow, which vanishes on white, and
	# without its black; then other saturated hues for more groups (registry
	# order: naive orange, hughes_moeller green, frisvad vermillion, duff
	# blue, ...)
	nh = split("#E69F00 #009E73 #D55E00 #0072B2 #CC79A7 #56B4E9 #8C6D00 #5C3A92 #E7298A #66A61E #17BECF #BCBD22", hue, " ")
	split("7 5 9 11 13 15", pts, " ")
	split(HEAD, h, " "); for (i in h) head[h[i]] = 1
	# one colour per method in every chart: scripts/palette.txt (a method
	# it lacks falls back to a shade of its group's hue: palette.sh --check)
	if (PAL != "") while ((getline l < PAL) > 0) if (l !~ /^#/ && split(l, a, " ") >= 2) { pal[a[1]] = tolower(a[2])
		# and its own dash and point (columns 3 and 4), as its colour
		if (a[4] != "") { pdash[a[1]] = a[3] + 0; ppt[a[1]] = a[4] + 0 } }
}
# the registry family; else the shortest family (or, without a registry,
# other method) whose name is a prefix of this one, followed by "_"
function family(m,   b, f, best) {
	b = m; sub(/\+fma$/, "", b)
	if (b in fam) return fam[b]
	best = b
	for (f in forder) if (index(b, f "_") == 1 && length(f) < length(best)) best = f
	if (best == b) for (f in allm) if (index(b, f "_") == 1 && length(f) < length(best)) best = f
	return best
}
# the hue group of a family: the shortest other family of the run whose
# name, followed by "_", begins this one
function group(f,   g, best) {
	best = f
	for (g in present) if (g != f && index(f, g "_") == 1 && length(g) < length(best)) best = g
	return best
}
/^#/ || $1 == "method" || seen[$1]++ { next }
{ b = $1; sub(/\+fma$/, "", b); allm[b] = 1; order[++nm] = $1 }
END {
	for (q = 1; q <= nm; q++) { fm[q] = family(order[q]); present[fm[q]] = 1 }
	# each group's hue: its rank among the groups of the whole registry
	# (then of the run), the same in every chart and precision
	for (f in forder) present[f] = 1
	for (r = 1; r <= nf0 + nm; r++) for (f in forder) if (forder[f] == r) { g = group(f); if (!(g in grank)) grank[g] = ++ngr }
	for (q = 1; q <= nm; q++) {
		m = order[q]; f = fm[q]; g = group(f)
		if (!(f in forder)) forder[f] = 1000 + ++nx
		nf1 = 1000 + nx
		if (!(g in gorder) || forder[f] < gorder[g]) gorder[g] = forder[f]
		if (!(g in nv)) { ng++; grs[ng] = g }
		# within a group: by family, then the registry's order, then
		# methods outside it (frisvad_rotate) in the run's order, so that a
		# method's shade is the same in every chart
		b = m; sub(/\+fma$/, "", b)
		k = ++nv[g]; mem[g, k] = m; mfo[g, k] = forder[f] * 100000 + ((b in rix) ? rix[b] * 10 : 50000 + q) + (m != b)
	}
	# groups in registry order; within a group, members by family, then run order
	for (i = 1; i <= ng; i++) for (j = i + 1; j <= ng; j++)
		if (gorder[grs[j]] < gorder[grs[i]]) { t = grs[i]; grs[i] = grs[j]; grs[j] = t }
	for (i = 1; i <= ng; i++) { g = grs[i]
		for (u = 1; u <= nv[g]; u++) for (c = u + 1; c <= nv[g]; c++)
			if (mfo[g, c] < mfo[g, u]) { t = mem[g, u]; mem[g, u] = mem[g, c]; mem[g, c] = t; t = mfo[g, u]; mfo[g, u] = mfo[g, c]; mfo[g, c] = t } }
	p = 1; fill = 0
	for (i = 1; i <= ng; i++) {
		g = grs[i]
		if (fill > 0 && fill + nv[g] > MAX) { p++; fill = 0 }
		fill += nv[g]
		# the hue follows the place of the group in the registry, so it is
		# the same in every chart and precision
		if (!(g in grank)) grank[g] = ++ngr
		hi = grank[g]
		# members that are NAME+fma share NAME's shade (a dashed line)
		nb = 0; split("", slot)
		for (k = 1; k <= nv[g]; k++) { b = mem[g, k]; sub(/\+fma$/, "", b); if (!(b in slot)) slot[b] = ++nb }
		# the headline methods first, wide, so the thin variants drawn over
		# them stay visible where they coincide
		for (pass = 1; pass >= 0; pass--)
			for (k = 1; k <= nv[g]; k++) {
				m = mem[g, k]; b = m; sub(/\+fma$/, "", b)
				if ((b in head) != pass) continue
				s = slot[b]
				# the method's own dash and point (palette.txt); NAME+fma:
				# NAME's point, dashed (dash 2, or 4 where NAME's is 2); a
				# method the table lacks: by its place in its group
				d = (b in pdash) ? pdash[b] : ((s - 1) % 5) + 1
				if (m ~ /\+fma$/) d = (d == 2) ? 4 : 2
				print m, p, (b in pal) ? pal[b] : lab_shade(hue[(hi - 1) % nh + 1], s, nb), d, (b in ppt) ? ppt[b] : pts[(s - 1) % 6 + 1], (b in head) ? 3 : 1.5, g
			}
	}
}
