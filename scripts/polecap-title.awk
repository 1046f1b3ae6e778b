# polecap-title.awk - the title of the README's pole-cap figure, built from
# the polecap.csv columns it draws, so that it claims nothing the data do
# not show.  Per method (its largest defect over the grid):
#   non-finite outputs     "M gives N non-finite outputs"
#   a defect of 0.1 or more "M fails (defect >= 0.1) at 1 + n.z from A to B"
#                          (the least and the largest 1 + n.z of such a
#                          cell: a basis off by a tenth of a unit fails)
#   else                   "M stays below D" (D: its largest, 2 digits,
#                          rounded up)
# awk -F, -v methods="M1 M2 ..." -f polecap-title.awk polecap.csv
# prints "float near -z: PHRASE, PHRASE" (no apostrophe: plots.sh passes
# it to gnuplot in single quotes).
BEGIN { nm = split(methods, M, " ") }
/^#/ { next }
$1 == "one_plus_nz" { for (i = 1; i <= NF; i++) col[$i] = i; next }
{
	for (k = 1; k <= nm; k++) {
		if (!(M[k] in col)) continue
		v = $(col[M[k]]); has[k] = 1
		if (v == "nan" || v == "-nan" || v ~ /inf/) { nf[k]++; continue }
		v += 0; if (v > mx[k]) mx[k] = v
		if (v >= 0.1) { d = $1 + 0; if (!(k in lo) || d < lo[k]) lo[k] = d; if (!(k in hi) || d > hi[k]) hi[k] = d }
	}
}
function up(x,   e, m) { if (x <= 0) return "0"; e = int(log(x) / log(10)); if (x < 1) e--; m = x / 10 ^ e; m = int(m * 10 + 0.999999) / 10; if (m >= 10) { m = 1; e++ } return sprintf("%se%s%02d", m, e < 0 ? "-" : "+", e < 0 ? -e : e) }
function g(x,   s) { s = sprintf("%.2g", x); return s }
END {
	t = "float near -z: "; n = 0
	for (k = 1; k <= nm; k++) {
		if (!(k in has)) continue
		if (nf[k] > 0) s = M[k] " gives " nf[k] " non-finite outputs"
		else if (k in lo) s = M[k] " fails (defect >= 0.1) at 1 + n.z from " g(lo[k]) " to " g(hi[k])
		else s = M[k] " stays below " up(mx[k])
		t = t (n++ ? ", " : "") s
	}
	if (!n) t = t "no rows"
	gsub(/_/, "\\\\_", t)
	print t
}
