#!/bin/sh
# styles.sh SUMMARY_CSV - how every chart draws each method of a run (or of
# one precision: plots.sh passes the rows of one), one line per method in
# drawing order:
#   method panel colour dash point width group
# Families come from the registry (`onbstudy list`; a method outside it,
# such as frisvad_rotate, joins the family whose name is its longest
# prefix; NAME+fma rows join NAME's).  A family whose name is another
# family's followed by "_" (duff_branchless after duff, stark_fixed after
# stark) joins that family's hue group, so that the variants of one formula
# sit side by side in one hue.  A method's colour is its row of
# scripts/palette.txt, the same in every chart (scripts/palette.sh: related
# hues within a group, every colour far from every other); only a method
# the table lacks gets a shade computed here (its group's hue, Okabe-Ito,
# spread in CIELAB lightness: palette.sh --check names such methods).  Its
# dash type and point type are its palette.txt row's too.  The
# headline methods (frisvad, frisvad_max, duff) are drawn wide and first,
# so that each thin variant drawn over them stays visible where the two
# coincide.  Groups are packed, in registry order and never split, into
# panels of at most PANEL_MAX (5) series, so small multiples never crowd.
# Nothing here names a method except the headline list: new methods of the
# registry get a group, hue, shade and panel on their own.
set -eu
summary=$1
HERE=$(cd "$(dirname "$0")" && pwd)
list=$(mktemp); trap 'rm -f "$list"' EXIT
ONBSTUDY=${ONBSTUDY:-$HERE/../onbstudy}
"$ONBSTUDY" list --format csv 2>/dev/null | awk -F, 'NR > 1 { print $1, $2 }' > "$list" || true
awk -F, -v L="$list" -v PAL="${PALETTE:-$HERE/palette.txt}" -v MAX="${PANEL_MAX:-5}" -v HEAD="${HEADLINE:-frisvad frisvad_max duff}" -f "$HERE/lab.awk" -f "$HERE/styles.awk" "$summary"
