#!/bin/sh
# certify-plot.sh [DIR] - the charts of `onbstudy certify` (issue 22):
# DIR/certify_float.png and certify_double.png (and SVG), the bracket
# found <= true max <= bound of each method's defect against 1 + n.z (log),
# per band of n.z (the largest over the band's sectors), beside the
# accuracy floor of the committed reference sweep.  DIR: results/certify.
set -eu
DIR=${1:-results/certify}
HERE=$(cd "$(dirname "$0")" && pwd)
REF=${REF:-$HERE/../results/reference/by_nz.csv}
[ -f "$DIR/certify.csv" ] || { echo "certify-plot: $DIR/certify.csv not found (run ./onbstudy certify --out $DIR)" >&2; exit 2; }
command -v gnuplot >/dev/null 2>&1 || { echo "certify-plot: gnuplot is not installed" >&2; exit 2; }
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
for p in float double; do
	# per method and band: x_lo x_hi found bound (bound 1e300 where singular)
	grep -v '^#' "$DIR/certify.csv" | awk -F, -v p="$p" -v w="$W" '
	NR == 1 || $2 != p || ($3 == -1 && $4 == 1) { next }
	{ k = $1 SUBSEP $3 SUBSEP $4
	  b = ($12 == "singular" || $7 == "inf") ? 1e300 : $7 + 0
	  if (!(k in F) || $8 + 0 > F[k]) F[k] = $8 + 0
	  if (!(k in B) || b > B[k]) B[k] = b
	  M[$1] = 1; L[k] = $3 + 0; H[k] = $4 + 0 }
	END { for (k in F) { split(k, a, SUBSEP)
	        lo = 1 + L[k]; hi = 1 + H[k]; if (lo <= 0) lo = hi / 10
	        f = F[k] > 0 ? F[k] : 1e-30
	        printf "%.17g %.17g %.6e %.6e\n", lo, hi, f, (B[k] > f ? B[k] : f) >> (w "/" a[1] "." p) } }'
	for f in "$W"/*."$p"; do [ -f "$f" ] && sort -g -o "$f" "$f"; done
	# the floor: the largest floor defect of duff_branchless per log10(1 + n.z) bin (unit inputs)
	if [ -f "$REF" ]; then
		grep -v '^#' "$REF" | awk -F, -v p="$p" '$1 == "duff_branchless" && $2 == p && $4 == "log10_1pnz" &&
			($3 == "uniform" || $3 == "south" || $3 == "threshold" || $3 == "exhaustive") {
			k = $5; if (!(k in m) || $11 + 0 > m[k]) m[k] = $11 + 0; h[k] = $6 }
			END { for (k in m) if (m[k] > 0) printf "%.6g %.6g\n", 10 ^ ((k + h[k]) / 2), m[k] }' | sort -g > "$W/floor.$p"
	else
		: > "$W/floor.$p"
	fi
	have=" "
	for f in "$W"/*."$p"; do [ -f "$f" ] && have="$have$(basename "$f" ".$p") "; done
	gnuplot -e "dir='$W'; prec='$p'; out='$DIR/certify_$p'; have='$have'" "$HERE/certify.gp"
done
echo "certify-plot: wrote $DIR/certify_float.png and $DIR/certify_double.png"
