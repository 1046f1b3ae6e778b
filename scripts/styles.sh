#!/bin/sh
# styles.sh SUMMARY_CSV - how every chart draws each method of a run (or of
# one precision: plots.sh passes the rows of one), one
# line per method in drawing order:
#   method panel hue dash point width family
# Families come from the registry (`onbstudy list`; a method outside it,
# such as frisvad_rotate, joins the family whose name is its longest
# prefix; NAME+fma rows join NAME's).  One hue per family (Okabe-Ito,
# colour-blind safe; issue 24), and within a family one shade (the hue,
# darker, lighter, ...), dash type and point type per variant; the headline methods (frisvad,
# frisvad_max, duff) are drawn wide and first, so that each thin variant drawn over them
# stays visible where the two coincide.  Families
# are packed, in registry order and never split, into panels of at most
# PANEL_MAX (5) series, so small multiples never crowd.  Nothing here
# names a method except the headline list: new methods of the registry
# get a family, hue and panel on their own.
set -eu
summary=$1
HERE=$(cd "$(dirname "$0")" && pwd)
list=$(mktemp); trap 'rm -f "$list"' EXIT
ONBSTUDY=${ONBSTUDY:-$HERE/../onbstudy}
"$ONBSTUDY" list --format csv 2>/dev/null | awk -F, 'NR > 1 { print $1, $2 }' > "$list" || true
awk -F, -v L="$list" -v MAX="${PANEL_MAX:-5}" -v HEAD="${HEADLINE:-frisvad frisvad_max duff}" '
BEGIN {
	while ((getline l < L) > 0) { split(l, a, " "); fam[a[1]] = a[2]; if (!(a[2] in forder)) forder[a[2]] = ++nf0 }
	# Okabe-Ito (2008) without its yellow, which vanishes on white, then
	# darker stand-ins for more families (registry order: naive orange,
	# hughes_moeller green, frisvad vermillion, duff blue, ...)
	nh = split("#E69F00 #009E73 #D55E00 #0072B2 #CC79A7 #56B4E9 #000000 #8C6D00 #5C3A92 #7A7A7A", hue, " ")
	split("7 5 9 11 13 15", pts, " ")
	for (i = 0; i < 16; i++) hx[substr("0123456789abcdef", i + 1, 1)] = i
	split(HEAD, h, " "); for (i in h) head[h[i]] = 1
}
# the registry family; else the shortest family (or, without a registry,
# other method) whose name is a prefix of this one, followed by "_"
# shade(h, k): variant k of hue h: 1 the hue, then darker and lighter by
# turns (k = 2 darker, 3 lighter, 4 darker still, ...)
function shade(h, k,   r, g, b, t, w) {
	h = tolower(h)
	r = hx[substr(h, 2, 1)] * 16 + hx[substr(h, 3, 1)]
	g = hx[substr(h, 4, 1)] * 16 + hx[substr(h, 5, 1)]
	b = hx[substr(h, 6, 1)] * 16 + hx[substr(h, 7, 1)]
	if (k <= 1) return h
	t = int(k / 2) * 0.3; w = (k % 2) ? 255 : 0
	if (t > (w ? 0.4 : 0.6)) t = w ? 0.4 : 0.6
	return sprintf("#%02x%02x%02x", r + (w - r) * t, g + (w - g) * t, b + (w - b) * t)
}
function family(m,   b, f, best) {
	b = m; sub(/\+fma$/, "", b)
	if (b in fam) return fam[b]
	best = b
	for (f in forder) if (index(b, f "_") == 1 && length(f) < length(best)) best = f
	if (best == b) for (f in allm) if (index(b, f "_") == 1 && length(f) < length(best)) best = f
	return best
}
/^#/ || $1 == "method" || seen[$1]++ { next }
{ b = $1; sub(/\+fma$/, "", b); allm[b] = 1; order[++nm] = $1 }
END {
	for (q = 1; q <= nm; q++) {
	m = order[q]; f = family(m)
	if (!(f in forder)) forder[f] = 1000 + ++nx
	if (!(f in nv)) { nfam++; fams[nfam] = f }
	nv[f]++; mem[f, nv[f]] = m
	}
	# families in registry order
	for (i = 1; i <= nfam; i++) for (j = i + 1; j <= nfam; j++)
		if (forder[fams[j]] < forder[fams[i]]) { t = fams[i]; fams[i] = fams[j]; fams[j] = t }
	p = 1; fill = 0
	for (i = 1; i <= nfam; i++) {
		f = fams[i]
		if (fill > 0 && fill + nv[f] > MAX) { p++; fill = 0 }
		fill += nv[f]
		# the headline methods first, wide, so the thin variants drawn over
		# them stay visible where they coincide (duff = duff_branchless)
		for (pass = 1; pass >= 0; pass--)
			for (k = 1; k <= nv[f]; k++) {
				m = mem[f, k]; b = m; sub(/\+fma$/, "", b)
				if ((b in head) != pass) continue
				d = (m ~ /\+fma$/) ? 2 : ((k - 1) % 5) + 1
				if (m ~ /\+fma$/) { kk = 0; for (q = 1; q <= nv[f]; q++) if (mem[f, q] == b) kk = q; d = 2; pt = pts[((kk > 0 ? kk : k) - 1) % 6 + 1] }
				else pt = pts[(k - 1) % 6 + 1]
				# the hue follows the place of the family in the registry, so it is
				# the same in every chart and precision
				hi = (forder[f] < 1000) ? forder[f] : i
				print m, p, shade(hue[(hi - 1) % nh + 1], (m ~ /\+fma$/) ? (kk > 0 ? kk : k) : k), d, pt, (b in head) ? 3 : 1.5, f
			}
	}
}' "$summary"
