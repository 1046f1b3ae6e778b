#!/bin/sh
# charts_small.sh - the charts of small runs tell the truth (issue 45's
# "Bad input"): scripts/plots.sh on fixture-sized sweeps that lack what the
# reference run has (duff, frisvad, the south and exhaustive inputs,
# nonunit inputs, everything near the pole) must
#   - finish with exit 0 and draw every line chart, an empty one as a
#     chart whose note says why (not a missing file, not a silent stop:
#     a run without duff once ended plots.sh after its first three charts);
#   - name in its texts no method, distribution, failure or blank panel
#     the run lacks (the map's note once spoke of failures near -z and
#     blank panels in every run; the
#     pole chart once read "south (0), exhaustive and uniform inputs" for
#     a run of uniform inputs alone, and its axis named a "-z" slot it
#     did not draw);
#   - pass scripts/chart-check.awk (tests/plots_cli.sh lists its checks).
. "$(dirname "$0")/lib.sh"
command -v gnuplot >/dev/null 2>&1 || { echo "charts_small: gnuplot missing: scripts/install-deps.sh --test must install it"; exit 1; }
T=$tmp
Q="--grid 4x8 --samples 600 --exhaustive-count 256 --azimuths 2 --threads 1 --quiet --precision float"
./onbstudy list --format csv | awk -F, 'NR > 1 { print $1 }' > "$T/registry"
# words DIR/CHART: the texts of a chart's SVG, tags dropped, one word a line
words() { sed -n 's/<[^>]*>/ /g; s/\\_/_/g; p' "$1" | tr -c 'a-z0-9_()\n' ' ' | tr ' ' '\n' | sort -u; }
# check DIR: chart-check every SVG; no registry method the run lacks
check() {
	awk -F, 'FNR > 1 && !/^#/ { print $1 }' "$1/summary.csv" | sort -u > "$T/have"
	for f in "$1"/*.svg "$1"/fig/*.svg; do
		[ -f "$f" ] || continue
		case $(basename "$f") in maps_*) nl=1;; *) nl=0;; esac
		out=$(awk -v nolabels=$nl -f scripts/chart-check.awk "$f" 2>&1) && ok || bad "$(basename "$f"): chart check: $out"
		absent=$(words "$f" | grep -Fxf "$T/registry" | grep -Fxvf "$T/have" | tr '\n' ' ')
		[ -z "$absent" ] && ok || bad "$(basename "$f") names methods its run does not have: $absent"
	done
}
plots() { FIGS="$1/fig" PCDIR="$1" sh scripts/plots.sh "$1" > "$T/log" 2>&1 && ok || bad "plots.sh on $(basename "$1") failed (exit $?): $(tail -3 "$T/log")"; }

# 1. one wild engine, no duff and no frisvad, uniform and grid inputs only
./onbstudy sweep --methods jolt --dists uniform,grid $Q --out "$T/a" >/dev/null 2>&1 || bad "sweep a failed"
plots "$T/a"
for c in error_vs_nz error_vs_nz_rms south_pole nonunit maps continuity; do
	[ -s "$T/a/${c}_float.svg" ] && ok || bad "a run without duff drew no ${c}_float"
done
t=$(sed -n 's/.*<title>\(.*\)<\/title>.*/\1/p' "$T/a/south_pole_float.svg" | head -1)
grep -q 'near n.z = -1: uniform inputs' "$T/a/south_pole_float.svg" && ok || bad "pole chart of uniform inputs alone not titled so: $(grep -o 'near n.z = -1[^<]*' "$T/a/south_pole_float.svg" | head -1)"
grep -q 'exhaustive\|south (' "$T/a/south_pole_float.svg" && bad "pole chart names south or exhaustive inputs the run lacks" || ok
grep -q 'no nonunit inputs' "$T/a/nonunit_float.svg" && ok || bad "the empty nonunit chart has no note"
[ ! -e "$T/a/fig/south_pole_frisvad_duff_float.svg" ] && ok || bad "a run without frisvad and duff drew the frisvad/duff figure"
grep -q 'failures within\|blank: no rows' "$T/a/maps_float.svg" && bad "the map of a run without failures or blank panels names them" || ok
check "$T/a"

# 2. frisvad alone, grid inputs only: nothing near the pole, no duff
./onbstudy sweep --methods frisvad --dists grid $Q --out "$T/b" >/dev/null 2>&1 || bad "sweep b failed"
plots "$T/b"
for f in south_pole_float error_vs_nz_float nonunit_float fig/south_pole_frisvad_duff_float; do
	[ -s "$T/b/$f.svg" ] && ok || bad "a grid-only run drew no $f"
done
grep -q 'no input of this run lies near n.z = -1' "$T/b/south_pole_float.svg" && ok || bad "the empty pole chart has no note"
grep -q 'no input of this run lies near n.z = -1' "$T/b/fig/south_pole_frisvad_duff_float.svg" && ok || bad "the empty pole figure has no note"
grep -q 'no uniform inputs' "$T/b/error_vs_nz_float.svg" && ok || bad "the empty error_vs_nz chart has no note"
grep -q -- '-z: n.z = -1 exactly' "$T/b/south_pole_float.svg" && bad "an empty pole chart names the -z slot" || ok
check "$T/b"
finish charts_small
