#!/bin/sh
# palette.sh [--update | --check] - one colour and one line style per
# method, in every chart: scripts/palette.txt, "method colour dash point"
# per line, read by scripts/styles.sh
# (so by every chart script: plots.sh, poles.sh, certify-plot.sh, the
# tradeoff and bar charts).  A method keeps its colour everywhere, whatever
# else a run holds; NAME+fma rows take NAME's colour (dashed).
#   (none)    print the table the registry needs: palette.txt's rows, then
#             a row for each method it lacks
#   --update  write that table to scripts/palette.txt
#   --check   exit 1, naming them, when a method of a committed run
#             (results/*/summary.csv, certify.csv) has no row (a method of
#             the registry alone is named, not failed: no committed chart
#             draws it yet),
#             when two rows' colours differ by a CIELAB delta-E below 10, or
#             when a colour is near-black (L* < 25: it reads as the axes'),
#             when a row has no dash (1-7) and point (1-15), or two rows
#             share both (the pair is a method's own, as its colour is)
# PALETTE=FILE reads and writes FILE instead of scripts/palette.txt.
# A new row's colour (scripts/palette.awk): the families of one hue group
# (duff_branchless after duff) keep related hues, within 30 degrees of the
# group's first colour (Okabe-Ito for the first twelve groups), and each
# new colour is the one that lies farthest, in CIELAB delta-E, from every
# colour of the table, so that any two methods differ and no two series of
# one panel share a colour (scripts/chart-check.awk checks each committed
# chart).  Rows already in the table are never changed: adding a method
# moves no other method's colour.
set -eu
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/.." && pwd)
ONBSTUDY=${ONBSTUDY:-$ROOT/onbstudy}
TABLE=${PALETTE:-$HERE/palette.txt}
mode=${1:-}
case $mode in ""|--update|--check) ;; *) echo "usage: palette.sh [--update | --check]" >&2; exit 2;; esac
[ -x "$ONBSTUDY" ] || { echo "palette: $ONBSTUDY not built (make)" >&2; exit 2; }
list=$(mktemp); new=$(mktemp); runs=$(mktemp); trap 'rm -f "$list" "$new" "$runs"' EXIT
"$ONBSTUDY" list --format csv | awk -F, 'NR > 1 { print $1, $2 }' > "$list"
# the methods of the committed runs (charted), and those of them outside
# the registry (frisvad_rotate)
for f in "$ROOT"/results/*/summary.csv "$ROOT"/results/*/*/summary.csv "$ROOT"/results/certify/certify.csv; do
	[ -f "$f" ] && awk -F, '!/^#/ && $1 != "method" { sub(/\+fma$/, "", $1); print $1 }' "$f"
done | sort -u > "$runs"
awk 'NR == FNR { have[$1] = 1; next } !($1 in have) { print $1, "-" }' "$list" "$runs" >> "$list"
[ -f "$TABLE" ] || : > "$TABLE"
awk -v T="$TABLE" -f "$HERE/lab.awk" -f "$HERE/palette.awk" "$list" > "$new"
missing=$(awk 'NR == FNR { if (!/^#/) have[$1] = 1; next } !($1 in have) { printf "%s ", $1 }' "$TABLE" "$new")
case $mode in
--check)
	close=$(awk -f "$HERE/lab.awk" -f /dev/stdin "$TABLE" <<'EOF'
!/^#/ && NF >= 2 { m[++n] = $1; c[n] = $2
	if ($3 !~ /^[1-7]$/ || $4 !~ /^([1-9]|1[0-5])$/) printf "%s has no dash (1-7) and point (1-15): \"%s\"; ", $1, $0
	else if (($3, $4) in ds) printf "%s and %s share dash %s and point %s; ", ds[$3, $4], $1, $3, $4
	else ds[$3, $4] = $1 }
END { for (i = 1; i <= n; i++) { lab_of(c[i]); if (LAB_L < 25) printf "%s %s is near-black (L* %.0f); ", m[i], c[i], LAB_L
	for (j = i + 1; j <= n; j++) if (delta_e(c[i], c[j]) < 10) printf "%s and %s: delta-E %.1f; ", m[i], m[j], delta_e(c[i], c[j]) } }
EOF
)
	# (a registry method no committed chart draws yet is only named: its
	# charts use a fallback shade until --update gives it a row; a method of
	# a committed run without a row fails)
	drawn=$(echo "$missing" | tr ' ' '\n' | grep -Fx -f "$runs" | tr '\n' ' ' || true)
	[ -z "$missing" ] || echo "palette: no colour in $TABLE for: $missing(sh scripts/palette.sh --update adds them)" >&2
	[ -z "$close" ] || echo "palette: colours too close in $TABLE: $close" >&2
	[ -z "$drawn$close" ];;
--update)
	{ sed -n '/^#/p' "$TABLE"; grep -v '^#' "$new"; } > "$TABLE.tmp" && mv "$TABLE.tmp" "$TABLE"
	echo "palette: $(grep -vc '^#' "$TABLE") methods in scripts/palette.txt${missing:+; added: $missing}";;
*) cat "$new";;
esac
