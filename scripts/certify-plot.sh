#!/bin/sh
# certify-plot.sh [DIR] - the charts of `onbstudy certify`, from
# DIR/certify.csv (columns found by name; DIR default results/certify):
#   DIR/certify_P.png        per band of n.z, each method's bracket: the
#                            largest defect found (solid) <= the true
#                            maximum <= the proven bound (dashed), shaded
#                            between; a singular band has no bound and is
#                            drawn as a marker in the "no bound" strip
#   DIR/certify_ratio_P.png  bound / found per band: where the proof is
#                            tight (near 1) and where it is loose
#   FIGS/certify_frisvad_duff_float.png  (when FIGS is set: results/figures)
#                            the brackets of frisvad, frisvad_max and duff
#                            in one panel, the README's figure
# for P in float and double (and SVG beside each).  The x axis gives every
# band the same width, from -z to +z: the log bands near each pole (1 + n.z
# near -z, 1 - n.z near +z) and the linear bands between, so that the
# seam at n.z = 0 and the north get the room the south gets.  Methods are
# grouped into panels and coloured as in every other chart
# (scripts/styles.sh); the style is scripts/style.gp.
set -eu
DIR=${1:-results/certify}
HERE=$(cd "$(dirname "$0")" && pwd)
# DIR/certify.csv (float, double), or DIR/certify-half.csv (certify
# --precision half: DIR/certify_half.png and certify_ratio_half.png, u =
# 2^-11; the bands that hold no binary16 input, scanned 0, left out)
CSV=$DIR/certify.csv
[ -f "$CSV" ] || CSV=$DIR/certify-half.csv
[ -f "$CSV" ] || { echo "certify-plot: $DIR/certify.csv not found (run ./onbstudy certify --out $DIR)" >&2; exit 2; }
command -v gnuplot >/dev/null 2>&1 || { echo "certify-plot: gnuplot is not installed" >&2; exit 2; }
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
# (panels of at most three methods, not five: where the engines' brackets
# lay within 2x of each other, five translucent shades and hatches
# stacked into one band no colour told apart; three stay readable: one
# shade and two hatches of different angles)
PANEL_MAX=${PANEL_MAX:-3} sh "$HERE/styles.sh" "$CSV" > "$W/styles"
made=""
# keys "FILES" "NAMES" "PANELS": per method, "DUP FILL TITLE", and a sixth
# column in each file: 1 where the band's bracket (found, bound) is an
# earlier method's of the same panel, said once: drawn for the earlier
# method only, and the key title says "m = other" (every band) or "m (=
# other in N bands)"; DUP 1 when every band repeats.  FILL: 0 for the first
# shade of a panel, a hatch pattern (4-7) for the next ones, so that stacked
# shades keep their own colours.  frisvad_rotate's rows are its direction
# error, and its title says so.
keys() {
	awk -v files="$1" -v names="$2" -v panels="$3" -v ratio="${4:-0}" 'BEGIN {
		n = split(files, f, " "); split(names, nm, " "); split(panels, pa, " ")
		for (i = 1; i <= n; i++) { nl[i] = 0
			while ((getline l < f[i]) > 0) { split(l, c, " "); nl[i]++; L[i, nl[i]] = c[1] " " c[2] " " c[3] " " c[4] " " c[5]; B[i, c[1]] = c[2] " " c[3] " " c[5] }
			close(f[i]) }
		for (i = 1; i <= n; i++) {
			t = nm[i]; nd = 0; split("", with)
			# (an earlier method of the panel with every band the same comes
			# first: "jolt = jolt_arm64", not 12 bands of one and 4 of another)
			full = 0
			for (j = 1; j < i && !full; j++) if (pa[j] == pa[i]) { same = nl[i] > 0
				for (r = 1; r <= nl[i] && same; r++) { split(L[i, r], c, " "); if (!((j, c[1]) in B) || B[j, c[1]] != c[2] " " c[3] " " c[5]) same = 0 }
				if (same) full = j }
			for (r = 1; r <= nl[i]; r++) { split(L[i, r], c, " "); d = full
				for (j = 1; j < i && !d; j++) if (pa[j] == pa[i] && ((j, c[1]) in B) && B[j, c[1]] == c[2] " " c[3] " " c[5]) d = j
				if (d) with[d]++
				D[i, r] = d ? 1 : 0; nd += d ? 1 : 0 }
			best = 0; for (j in with) if (!best || with[j] > with[best]) best = j
			if (nd == nl[i] && nd > 0 && with[best] == nd) t = t " = " nm[best]
			else if (nd > 0) t = t sprintf(" (= %s in %d band%s)", nm[best], with[best], with[best] == 1 ? "" : "s")
			if (nm[i] == "frisvad_rotate") t = t " (its direction error)"
			# (the ratio chart: a method whose every band is a repeat or has
			# no bound draws no ratio of its own, and its title says so)
			own = 0; for (r = 1; r <= nl[i]; r++) { split(L[i, r], c, " "); own += (!D[i, r] && !(c[5] + 0 > 0)) }
			if (ratio && own == 0 && nl[i] > 0 && nd < nl[i]) t = t (nd ? "; " : " ") "no finite point"
			all = (nd == nl[i] && nd > 0)
			fill = all ? 0 : (k[pa[i]]++ ? 3 + (k[pa[i]] - 2) % 4 + 1 : 0)
			for (r = 1; r <= nl[i]; r++) print L[i, r], D[i, r] > f[i]
			close(f[i])
			print (all ? 1 : 0), fill, t } }'
}
for p in float double half; do
	# (a precision the file has no row of: nothing to draw, nothing to say)
	grep -v '^#' "$CSV" | awk -F, -v p="$p" '$2 == p { f = 1; exit } END { exit !f }' || continue
	# the bands of this precision, in order, each a slot k (0, 1, ...); per
	# method and band: k found bound ratio (bound and ratio "nan" where
	# singular: no bound), and the x tics
	grep -v '^#' "$CSV" | awk -F, -v p="$p" -v w="$W" '
	NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
	$(h["precision"]) != p { next }
	("scanned" in h) && $(h["scanned"]) == 0 { next }
	{ lo = $(h["nz_lo"]); hi = $(h["nz_hi"]) }
	lo == -1 && hi == 1 { next }
	{ m = $1; b = lo SUBSEP hi
	  if (!(b in seen)) { seen[b] = 1; nb++; L[nb] = lo + 0; Hh[nb] = hi + 0; key[nb] = b }
	  f = $(h["found"]) + 0; bd = $(h["bound"])
	  if (f > 1e300) f = 0   # (half: a non-finite basis found; its band is in the "no bound" strip)
	  sing = ($(h["status"]) == "singular" || bd == "inf")
	  if (!((m, b) in F) || f > F[m, b]) F[m, b] = f
	  if (sing) S[m, b] = 1
	  else if (!((m, b) in B) || bd + 0 > B[m, b]) B[m, b] = bd + 0
	  M[m] = 1 }
	function lab(e,   d, r) {
		if (e == -1) return "-z"
		if (e == 1) return "+z"
		if (e < -0.9 + 1e-9 || e > 0.9 - 1e-9) {
			d = (e < 0) ? 1 + e : 1 - e; r = log(d) / log(10)
			if ((r - int(r - 0.5)) ^ 2 > 1e-8 && ((r - int(r + 0.5)) ^ 2) > 1e-8) return ""
			r = (r < 0) ? int(r - 0.5) : int(r + 0.5)
			if (e > -0.9 - 1e-9 && e < 0.9 + 1e-9) return sprintf("%g", e)
			# (none next to the labels of the -0.9 and 0.9 edges)
			return (r <= -3 && r % (nb > 30 ? 4 : 2) == 0) ? sprintf("10^{%d}", r) : ""
		}
		return (e == 0) ? "0" : ""
	}
	END {
		for (i = 1; i <= nb; i++) for (j = i + 1; j <= nb; j++) if (L[j] < L[i]) {
			t = L[i]; L[i] = L[j]; L[j] = t; t = Hh[i]; Hh[i] = Hh[j]; Hh[j] = t; t = key[i]; key[i] = key[j]; key[j] = t }
		for (m in M) {
			f = w "/" m "." p
			for (i = 1; i <= nb; i++) { b = key[i]; if (!((m, b) in F)) continue
				# (a band with no defect found, or a non-finite one: nothing
				# to draw on the log axis, "nan", and no ratio)
				fo = F[m, b] > 0 ? sprintf("%.6e", F[m, b]) : "nan"
				if ((m, b) in S) printf "%d %s nan nan 1\n", i - 1, fo > f
				else printf "%d %s %.6e %s 0\n", i - 1, fo, B[m, b], (F[m, b] > 0 ? sprintf("%.6e", B[m, b] / F[m, b]) : "nan") > f }
			close(f)
		}
		t = ""
		for (i = 1; i <= nb; i++) { s = lab(L[i]); if (s != "") t = t (t == "" ? "" : ", ") sprintf("\"%s\" %d", s, i - 1) }
		t = t ", \"+z\" " nb
		print "set xtics (" t ")" > (w "/xtics." p)
		# the region boundaries: where the log bands of each pole meet the linear ones, and the seam
		for (i = 1; i <= nb; i++) { if (L[i] > -0.9 - 1e-9 && L[i] < -0.9 + 1e-9) s1 = i - 1; if (L[i] > 0.9 - 1e-9 && L[i] < 0.9 + 1e-9) s3 = i - 1; if (L[i] == 0) s2 = i - 1 }
		printf "nbands = %d; xs1 = %d; xs2 = %d; xs3 = %d\n", nb, s1 + 0, s2 + 0, s3 + 0 > (w "/xtics." p)
	}'
	files=""; names=""; colors=""; dashes=""; points=""; panels=""
	for m in $(awk '{ print $1 }' "$W/styles"); do
		[ -s "$W/$m.$p" ] || continue
		files="$files $W/$m.$p"; names="$names $m"
		colors="$colors $(awk -v m="$m" '$1 == m { print $3 }' "$W/styles")"
		dashes="$dashes $(awk -v m="$m" '$1 == m { print $4 }' "$W/styles")"
		points="$points $(awk -v m="$m" '$1 == m { print $5 }' "$W/styles")"
		panels="$panels $(awk -v m="$m" '$1 == m { print $2 }' "$W/styles")"
	done
	[ -n "$files" ] || { echo "certify-plot: no $p rows in $CSV" >&2; continue; }
	keys "$files" "$names" "$panels" > "$W/keys.$p"
	v="here='$HERE'; nosvg=${NOSVG:-0}; prec='$p'; files='$files'; names='$names'; colors='$colors'; dashes='$dashes'; points='$points'; panels='$panels'; xt='$W/xtics.$p'"
	gnuplot -e "$v; keys='$W/keys.$p'; ratio=0; out='$DIR/certify_$p'" "$HERE/certify.gp"
	keys "$files" "$names" "$panels" 1 > "$W/keysr.$p"
	gnuplot -e "$v; keys='$W/keysr.$p'; ratio=1; out='$DIR/certify_ratio_$p'" "$HERE/certify.gp"
	outs="$DIR/certify_$p $DIR/certify_ratio_$p"
	# the README's figure (FIGS, float): frisvad, frisvad_max and duff in one panel
	sel=""; for m in frisvad frisvad_max duff; do case " $names " in *" $m "*) sel="$sel $m";; esac; done
	if [ -n "${FIGS:-}" ] && [ "$p" = float ] && [ -n "$sel" ]; then
		mkdir -p "$FIGS"
		sv=$(for m in $sel; do awk -v m="$m" '$1 == m { print $3, $4, $5 }' "$W/styles"; done)
		keys "$(for m in $sel; do printf '%s ' "$W/$m.$p"; done)" "$sel" "$(echo $sel | sed 's/[^ ]*/1/g')" > "$W/keys1.$p"
		gnuplot -e "$v; single=1; files='$(for m in $sel; do printf '%s ' "$W/$m.$p"; done)'; names='$sel'; colors='$(echo "$sv" | awk '{ print $1 }' | tr '\n' ' ')'; dashes='$(echo "$sv" | awk '{ print $2 }' | tr '\n' ' ')'; points='$(echo "$sv" | awk '{ print $3 }' | tr '\n' ' ')'; panels='$(echo $sel | sed 's/[^ ]*/1/g')'; keys='$W/keys1.$p'; ratio=0; out='$FIGS/certify_frisvad_duff_$p'" "$HERE/certify.gp"
		outs="$outs $FIGS/certify_frisvad_duff_$p"
	fi
	made="$made $outs"
	# (no pngquant: its 256 colours move the thin brackets' edges, as in the
	# line charts of plots.sh, which see)
done
echo "certify-plot: wrote$(for o in $made; do printf ' %s.png' "$o"; done)"
