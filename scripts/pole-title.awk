# pole-title.awk - the title of the README's south-pole figure, built from
# the methods it draws and what summary.csv says of them, so that it claims
# nothing the data do not show.  Per method, over the chart's distributions
# (the row with the largest max_defect):
#   non-finite outputs           "M gives N non-finite outputs"
#   max_defect >= 0.1            "M fails" (a basis off by a tenth of a unit)
#   else, max_defect < 16 eps    "M stays at its floor" when max_defect <=
#                                1.5 max_floor, else "M stays below D"
#   else                         "M reaches D"
# and, for "fails" and "reaches", " on its own floor" when max_defect <=
# 1.5 max_floor (the exact formula rounded once does as badly: the
# formula's failure, not the arithmetic's).  The phrase "on its own floor"
# is dropped from "reaches" when the title would pass 100 characters.
# awk -F, -v p=PREC -v ds="DIST ..." -v methods="M1 M2 ..." -f pole-title.awk summary.csv
# prints "PREC near n.z = -1: PHRASE, PHRASE, ..." or, when no method has
# rows, "PREC near n.z = -1: no rows".
BEGIN { nd = split(ds, a, " "); for (i = 1; i <= nd; i++) want[a[i]] = 1
	nm = split(methods, M, " "); for (i = 1; i <= nm; i++) idx[M[i]] = i
	eps = (p == "float") ? 2 ^ -23 : 2 ^ -52 }
/^#/ { next }
$1 == "method" { for (i = 1; i <= NF; i++) h[$i] = i; next }
$2 == p && ($3 in want) && ($1 in idx) {
	i = idx[$1]; has[i] = 1; nf[i] += $(h["nonfinite"])
	d = $(h["max_defect"]); f = ("max_floor" in h) ? $(h["max_floor"]) : "nan"
	if (d != "nan" && d != "inf" && (!(i in mx) || d + 0 > mx[i])) { mx[i] = d + 0; fl[i] = (f == "nan" ? -1 : f + 0) }
}
function num(x,   s) { s = sprintf("%.2g", x); sub(/e-0/, "e-", s); return s }
function phrase(i, long,   d, on) {
	if (nf[i] > 0) return sprintf("%s gives %d non-finite outputs", M[i], nf[i])
	if (!(i in mx)) return M[i] " has no finite output"
	d = mx[i]; on = (fl[i] > 0 && d <= 1.5 * fl[i])
	if (d >= 0.1) return M[i] " fails" (on ? " on its own floor" : "")
	if (d < 16 * eps) return M[i] (on ? " stays at its floor" : " stays below " num(d))
	return M[i] " reaches " num(d) (on && long ? " on its own floor" : "")
}
END {
	for (long = 1; long >= 0; long--) {
		t = p " near n.z = -1: "; k = 0
		for (i = 1; i <= nm; i++) if (i in has) t = t (k++ ? ", " : "") phrase(i, long)
		if (length(t) <= 100) break
	}
	if (!k) t = t "no rows"
	gsub(/_/, "\\\\_", t)
	print t
}
