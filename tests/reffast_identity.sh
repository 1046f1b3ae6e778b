#!/bin/sh
# reffast_identity.sh - issue 14: the fast reference (--ref fast) and MPFR
# alone (--ref mpfr) write byte-identical data, on the default sweep at a
# reduced size (every distribution, both precisions, every method, the FMA
# copies when the CPU has them) and on an exhaustive float run at the south
# pole (every float n.z in [-1, -0.9999], heavy cancellation in 1 + n.z);
# the fast run states its fallback rate in the log, the provenance and
# reference.csv.
set -u
cd "$(dirname "$0")/.."
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0; fail=0
ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }
data() { grep -v '^#' "$1"; }

if ./onbstudy sweep --ref fast --methods frisvad --samples 8 --dists uniform --quiet --out "$T/probe" 2>&1 >/dev/null |
   grep -q 'the reference is MPFR only'; then
	echo "reffast_identity: SKIP (this build or CPU cannot run the fast reference)"
	exit 0
fi
FMA=""
./onbstudy sweep --fma --methods frisvad --samples 8 --dists uniform --quiet --out "$T/fmaprobe" >/dev/null 2>&1 && FMA="--fma"

compare() { # $1 $2: run dirs, $3: label
	for f in summary.csv by_nz.csv worst.csv grid.csv; do
		[ -f "$1/$f" ] || continue
		data "$1/$f" > "$T/a"; data "$2/$f" > "$T/b"
		if [ -s "$T/a" ] && cmp -s "$T/a" "$T/b"; then ok; else bad "$3: $f differs between --ref fast and --ref mpfr"; fi
	done
}

# 1. the default sweep, reduced
SMALL="--samples 2048 --exhaustive-count 2048 --grid 12x24 --seed 7 --quiet $FMA"
./onbstudy sweep $SMALL --ref fast --out "$T/f" >/dev/null 2>"$T/ef" || bad "sweep --ref fast failed: $(cat "$T/ef")"
./onbstudy sweep $SMALL --ref mpfr --out "$T/m" >/dev/null 2>"$T/em" || bad "sweep --ref mpfr failed: $(cat "$T/em")"
[ -s "$T/f/grid.csv" ] && ok || bad "no grid.csv from the fast run"
compare "$T/f" "$T/m" "default sweep"
grep -q 'reference: fast .*fell back to MPFR on [0-9]* of [0-9]* evaluations' "$T/ef" && ok || bad "the log does not state the fallback rate"
grep -q '^# reference: fast .*fell back to MPFR' "$T/f/summary.csv" && ok || bad "summary.csv provenance lacks the fallback rate"
grep -q '^# reference: MPFR only' "$T/m/summary.csv" && ok || bad "summary.csv of --ref mpfr does not say MPFR only"
n=$(data "$T/f/reference.csv" | tail -n +2 | wc -l)
[ "$n" -gt 20 ] && ok || bad "reference.csv has $n rows (one per method and precision expected)"
[ ! -e "$T/m/reference.csv" ] && ok || bad "--ref mpfr wrote reference.csv"

# 2. exhaustive south pole, float: every n.z in [-1, -0.9999], 8 azimuths
POLE="--dists exhaustive --precision float --exhaustive-range -1:-0.9999 --azimuths 8 --quiet $FMA"
./onbstudy sweep $POLE --ref fast --out "$T/pf" >/dev/null 2>"$T/epf" || bad "pole --ref fast failed: $(cat "$T/epf")"
./onbstudy sweep $POLE --ref mpfr --out "$T/pm" >/dev/null 2>"$T/epm" || bad "pole --ref mpfr failed: $(cat "$T/epm")"
compare "$T/pf" "$T/pm" "exhaustive south pole"

# 3. bad value
./onbstudy sweep --ref quad --out "$T/bad" >/dev/null 2>"$T/eb"; rc=$?
[ "$rc" -eq 2 ] && grep -q "expected fast or mpfr" "$T/eb" && [ ! -e "$T/bad" ] && ok || bad "--ref quad: exit $rc, $(cat "$T/eb")"

echo "reffast_identity: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
