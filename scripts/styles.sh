#!/bin/sh
# styles.sh SUMMARY_CSV - how every chart draws each method of a run (or of
# one precision: plots.sh passes the rows of one), one
# line per method in drawing order:
#   method panel hue dash point width family
# Families come from the registry (`onbstudy list`; a method outside it,
# such as frisvad_rotate, joins the family whose name is its longest
# prefix; NAME+fma rows join NAME's).  One hue per family, one dash type
# and point type per variant within it; the headline methods (frisvad,
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
	nh = split("#1f77b4 #2ca02c #d62728 #7b3294 #e66100 #8c564b #c51b7d #4d4d4d #808000 #0e8a96 #b8860b #1a1a80", hue, " ")
	split("7 5 9 11 13 15", pts, " ")
	split(HEAD, h, " "); for (i in h) head[h[i]] = 1
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
				print m, p, hue[(hi - 1) % nh + 1], d, pt, (b in head) ? 3 : 1.5, f
			}
	}
}' "$summary"
