#!/bin/sh
# reffast_identity.sh - the fast reference (--ref fast) and MPFR
# alone (--ref mpfr) write byte-identical data, on the default sweep at a
# reduced size (every distribution, both precisions, every method, the FMA
# copies when the CPU has them) and on an exhaustive float run at the south
# pole (every float n.z in [-1, -0.9999], heavy cancellation in 1 + n.z);
# the fast run states its fallback rate in the log, the provenance and
# reference.csv.
. "$(dirname "$0")/lib.sh"
data() { grep -v '^#' "$1"; }

if ./onbstudy sweep --ref fast --methods frisvad --samples 8 --dists uniform --quiet --out "$tmp/probe" 2>&1 >/dev/null |
   grep -q 'the reference is MPFR only'; then
	skip "reffast_identity: this build or CPU cannot run the fast reference"
fi
FMA=""
./onbstudy sweep --fma --methods frisvad --samples 8 --dists uniform --quiet --out "$tmp/fmaprobe" >/dev/null 2>&1 && FMA="--fma"

compare() { # $1 $2: run dirs, $3: label
	for f in summary.csv by_nz.csv worst.csv grid.csv; do
		[ -f "$1/$f" ] || continue
		data "$1/$f" > "$tmp/a"; data "$2/$f" > "$tmp/b"
		if [ -s "$tmp/a" ] && cmp -s "$tmp/a" "$tmp/b"; then ok; else bad "$3: $f differs between --ref fast and --ref mpfr"; fi
	done
}

# under a sanitizer, one method of each family (the same fast-path code
# per family; test_reffast runs every kernel under the sanitizer)
M=""
[ -n "$SAN" ] && M="--methods $(family_methods)"

# 1. the default sweep, reduced
SMALL="--samples 2048 --exhaustive-count 2048 --grid 12x24 --seed 7 --quiet $FMA $M"
./onbstudy sweep $SMALL --ref fast --out "$tmp/f" >/dev/null 2>"$tmp/ef" || bad "sweep --ref fast failed: $(cat "$tmp/ef")"
./onbstudy sweep $SMALL --ref mpfr --out "$tmp/m" >/dev/null 2>"$tmp/em" || bad "sweep --ref mpfr failed: $(cat "$tmp/em")"
[ -s "$tmp/f/grid.csv" ] && ok || bad "no grid.csv from the fast run"
compare "$tmp/f" "$tmp/m" "default sweep"
grep -q 'reference: fast .*fell back to MPFR on [0-9]* of [0-9]* evaluations' "$tmp/ef" && ok || bad "the log does not state the fallback rate"
grep -q '^# reference: fast .*fell back to MPFR' "$tmp/f/summary.csv" && ok || bad "summary.csv provenance lacks the fallback rate"
grep -q '^# reference: MPFR only' "$tmp/m/summary.csv" && ok || bad "summary.csv of --ref mpfr does not say MPFR only"
n=$(data "$tmp/f/reference.csv" | tail -n +2 | wc -l)
[ "$n" -gt 20 ] && ok || bad "reference.csv has $n rows (one per method and precision expected)"
[ ! -e "$tmp/m/reference.csv" ] && ok || bad "--ref mpfr wrote reference.csv"

# 2. exhaustive south pole, float: every n.z in [-1, -0.9999], 8 azimuths
POLE="--dists exhaustive --precision float --exhaustive-range -1:-0.9999 --azimuths 8 --quiet $FMA $M"
./onbstudy sweep $POLE --ref fast --out "$tmp/pf" >/dev/null 2>"$tmp/epf" || bad "pole --ref fast failed: $(cat "$tmp/epf")"
./onbstudy sweep $POLE --ref mpfr --out "$tmp/pm" >/dev/null 2>"$tmp/epm" || bad "pole --ref mpfr failed: $(cat "$tmp/epm")"
compare "$tmp/pf" "$tmp/pm" "exhaustive south pole"

# 3. bad value
./onbstudy sweep --ref quad --out "$tmp/bad" >/dev/null 2>"$tmp/eb"; rc=$?
[ "$rc" -eq 2 ] && grep -q "expected fast or mpfr" "$tmp/eb" && [ ! -e "$tmp/bad" ] && ok || bad "--ref quad: exit $rc, $(cat "$tmp/eb")"

finish reffast_identity
