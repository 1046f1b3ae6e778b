# palette.awk - the program of scripts/palette.sh (which see), with
# scripts/lab.awk's colour functions.
#   awk -v T=TABLE -f lab.awk -f palette.awk LIST
# LIST: "method family" per line, in registry order (a method with family
# "-" is outside the registry: it joins the family whose name is its
# longest prefix followed by "_").  TABLE: the committed palette, "method
# colour dash point" per line ('#' comments); its colours, dashes and
# points are kept.  Prints the whole table, old rows first, then a row for
# each method it lacked.
# The line style of a method (columns 3 and 4): a dash type (1-5
# gnuplot's, 6 and 7 style.gp's DT()) and a point type (1-15), a pair no
# other row has, so that two methods of one panel never look alike in
# dash and marker together (before, both followed a method's place in its
# hue group: jolt and duff, first of their groups, were both solid with
# filled circles).  A row without one gets the free pair that shares
# least with the methods of its hue group and the five before it in the
# registry's order, the order in which styles.sh packs panels (a shared
# dash counts twice a shared point).
BEGIN {
	while ((getline l < T) > 0) {
		if (l ~ /^#/ || l !~ /[^ ]/) continue
		split(l, a, " "); col[a[1]] = tolower(a[2]); rows[++nrows] = a[1]; na++; used[na] = tolower(a[2])
		if (a[3] ~ /^[1-7]$/ && a[4] ~ /^([1-9]|1[0-5])$/ && !((a[3], a[4]) in pair)) { DS[a[1]] = a[3]; PS[a[1]] = a[4]; pair[a[3], a[4]] = 1 }
	}
	# points: the filled ones first (they read at the small size of
	# linespoints), then the open ones and the strokes
	NPT = split("7 5 9 11 13 15 6 4 8 10 12 14 1 2 3", PT, " ")
	# the first hue of the first twelve groups: Okabe-Ito (2008) without
	# its yellow and black, then other saturated hues (registry order:
	# naive orange, hughes_moeller green, frisvad vermillion, duff blue)
	nh = split("#E69F00 #009E73 #D55E00 #0072B2 #CC79A7 #56B4E9 #8C6D00 #5C3A92 #E7298A #66A61E #17BECF #BCBD22", hue, " ")
}
NF >= 2 { m[++nm] = $1; f[nm] = $2; if ($2 != "-") isfam[$2] = 1 }
# the family of a method outside the registry: its longest prefix that is a family
function famof(i,   g, best) {
	if (f[i] != "-") return f[i]
	best = ""
	for (g in isfam) if (index(m[i], g "_") == 1 && length(g) > length(best)) best = g
	return best == "" ? m[i] : best
}
# the hue group of a family: the shortest other family whose name,
# followed by "_", begins this one (duff_branchless joins duff)
function group(x,   g, best) {
	best = x
	for (g in isfam) if (g != x && index(x, g "_") == 1 && length(g) < length(best)) best = g
	return best
}
# the smallest delta-E from colour c to every colour of the table so far
function mind(c,   k, d, lo) {
	lo = 1e9
	for (k = 1; k <= na; k++) { d = delta_e(c, used[k]); if (d < lo) lo = d }
	return lo
}
# the best colour for a new member of group g: the largest smallest
# delta-E to every colour so far, within 30 degrees of hue of the group's
# first colour (a group's first colour: Okabe-Ito for the first twelve
# groups, else the best over the whole hue circle), lightness 30 to 68 (lighter lines fade on white)
function pick(g,   L, dh, h0, C, cand, best, bs, s, pen) {
	bs = -1
	if (g in ghex) { lab_of(ghex[g]); h0 = atan2(LAB_B, LAB_A); C = sqrt(LAB_A ^ 2 + LAB_B ^ 2); if (C < 45) C = 45
		for (L = 30; L <= 68; L += 2) for (dh = -30; dh <= 30; dh += 5) {
			cand = hex_of(L, C * cos(h0 + dh * 3.14159265 / 180), C * sin(h0 + dh * 3.14159265 / 180))
			# (ties: the nearer hue)
			s = mind(cand) - (dh < 0 ? -dh : dh) / 1000
			if (s > bs) { bs = s; best = cand } }
		return best }
	for (L = 38; L <= 66; L += 4) for (dh = 0; dh < 360; dh += 6) {
		cand = hex_of(L, 60 * cos(dh * 3.14159265 / 180), 60 * sin(dh * 3.14159265 / 180))
		s = mind(cand)
		if (s > bs) { bs = s; best = cand } }
	return best
}
# style(r): give the r-th method in registry order (O[r], hue group OG[r])
# a dash and point when it has none (above)
function style(r,   d, q, k, c, bc, bd, bq) {
	if (O[r] in DS) return
	bc = -1
	for (d = 1; d <= 7; d++) for (q = 1; q <= NPT; q++) {
		if ((d, PT[q]) in pair) continue
		c = d * 0.01 + q * 0.001 + (d > 5) * 0.5
		for (k = 1; k <= no; k++) if (k != r && (O[k] in DS) && (OG[k] == OG[r] || (k < r && k >= r - 5))) c += 2 * (DS[O[k]] == d) + (PS[O[k]] == PT[q])
		if (bc < 0 || c < bc) { bc = c; bd = d; bq = PT[q] } }
	if (bc < 0) { bd = 1; bq = 7 }   # (all 105 pairs taken: palette.sh --check says so)
	DS[O[r]] = bd; PS[O[r]] = bq; pair[bd, bq] = 1
}
END {
	for (i = 1; i <= nm; i++) { g = group(famof(i)); if (!(g in grank)) grank[g] = ++ng
		if (m[i] in col && !(g in ghex)) ghex[g] = col[m[i]]; gof[m[i]] = g }
	for (i = 1; i <= nrows; i++) { R[i] = rows[i]; RG[i] = (rows[i] in gof) ? gof[rows[i]] : rows[i] }
	nr = nrows
	for (i = 1; i <= nm; i++) {
		gof[m[i]] = group(famof(i))
		if (m[i] in col) continue
		g = group(famof(i))
		if (!(g in ghex) && grank[g] <= nh && mind(hue[grank[g]]) >= 20) c = tolower(hue[grank[g]])
		else c = pick(g)
		if (!(g in ghex)) ghex[g] = c
		col[m[i]] = c; used[++na] = c
		R[++nr] = m[i]; RG[nr] = g
	}
	# (styles in registry order, then the table's rows outside it)
	for (i = 1; i <= nm; i++) if (!(m[i] in inO)) { O[++no] = m[i]; OG[no] = gof[m[i]]; inO[m[i]] = 1 }
	for (i = 1; i <= nr; i++) if (!(R[i] in inO)) { O[++no] = R[i]; OG[no] = RG[i]; inO[R[i]] = 1 }
	for (i = 1; i <= no; i++) style(i)
	for (i = 1; i <= nr; i++) print R[i], col[R[i]], DS[R[i]], PS[R[i]]
}
