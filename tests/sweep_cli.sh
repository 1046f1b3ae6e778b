#!/bin/sh
# sweep_cli.sh - the sweep end to end: byte-identical data with 1 and 2
# threads, shards that merge to the unsharded run, the published failures
# in summary.csv, eval and threshold, and bad input (exit 2, one line,
# nothing written).
set -u
cd "$(dirname "$0")/.."
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0; fail=0
ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }
data() { grep -v '^#' "$1"; }   # the data of a result file, without its provenance lines

SMALL="--samples 3000 --exhaustive-count 2048 --azimuths 2 --grid 8x16 --seed 42 --quiet"

# 1. same seed, 1 and 2 threads: identical data in every file
./onbstudy sweep $SMALL --threads 1 --out "$T/t1" >/dev/null 2>"$T/e1" || bad "sweep --threads 1 failed: $(cat "$T/e1")"
./onbstudy sweep $SMALL --threads 2 --out "$T/t2" >/dev/null 2>"$T/e2" || bad "sweep --threads 2 failed: $(cat "$T/e2")"
for f in summary.csv by_nz.csv worst.csv grid.csv reference.csv; do
	[ -s "$T/t1/$f" ] && [ -s "$T/t2/$f" ] && ok || bad "$f missing with 1 or 2 threads"
	data "$T/t1/$f" > "$T/a"; data "$T/t2/$f" > "$T/b"
	if [ -s "$T/a" ] && cmp -s "$T/a" "$T/b"; then ok; else bad "$f differs between 1 and 2 threads"; fi
done
# the accuracy floor (issue 16): columns by name; duff_wide (the exact formula
# rounded once, through double) sits on it everywhere, duff_comp within 1%,
# float duff_branchless above it on uniform; float-only methods have no double rows
col() { data "$1" | awk -F, -v m="$2" -v p="$3" -v d="$4" -v c="$5" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
	$1 == m && $2 == p && $3 == d { print $(h[c]) }'; }
for d in uniform north south threshold exhaustive nonunit grid; do
	[ "$(col "$T/t1/summary.csv" duff_wide float $d max_floor_ratio)" = 1 ] && [ "$(col "$T/t1/summary.csv" duff_wide float $d at_floor)" = 1 ] && ok ||
		bad "duff_wide float $d: max_floor_ratio $(col "$T/t1/summary.csv" duff_wide float $d max_floor_ratio), want 1"
	r=$(col "$T/t1/summary.csv" duff_comp float $d max_floor_ratio)
	awk -v r="$r" 'BEGIN { exit !(r >= 1 && r <= 1.01) }' && ok || bad "duff_comp float $d: max_floor_ratio $r, want 1 to 1.01"
done
a=$(col "$T/t1/summary.csv" duff_branchless float uniform max_defect); b=$(col "$T/t1/summary.csv" duff_branchless float uniform max_floor)
awk -v a="$a" -v b="$b" 'BEGIN { exit !(b > 0 && a > 1.3 * b) }' && ok || bad "duff_branchless float uniform: max_defect $a not above the floor $b"
[ -z "$(col "$T/t1/summary.csv" duff_wide double uniform max_defect)" ] && ok || bad "duff_wide has double rows"
x=$(col "$T/t1/summary.csv" naive double uniform floor_ratio_nx)
case "$x" in -0x*|0x*) ok ;; *) bad "floor_ratio_nx is not a hex float: '$x'" ;; esac
data "$T/t1/by_nz.csv" | head -1 | grep -q ',floor_rms,floor_max$' && ok || bad "by_nz.csv lacks floor_rms,floor_max"
# provenance header on every file
for f in summary.csv by_nz.csv worst.csv grid.csv; do
	for key in "# revision:" "# compiler:" "# flags:" "# mpfr:" "# seed: 42" "# threads: 1" "# command:" "# mpfr precision: 127 bits"; do
		grep -q "^$key" "$T/t1/$f" && ok || bad "$f lacks '$key'"
	done
done

# 2. shards merge to the unsharded output
for k in 0 1 2; do
	./onbstudy sweep $SMALL --shard $k/3 --out "$T/sh" >/dev/null 2>>"$T/es" || bad "shard $k/3 failed: $(cat "$T/es")"
done
./onbstudy merge --out "$T/merged" "$T/sh/sweep-state-2-of-3.bin" "$T/sh/sweep-state-0-of-3.bin" "$T/sh/sweep-state-1-of-3.bin" >/dev/null 2>"$T/em" \
	|| bad "merge failed: $(cat "$T/em")"
for f in summary.csv by_nz.csv worst.csv grid.csv; do
	data "$T/t1/$f" > "$T/a"; data "$T/merged/$f" > "$T/b"
	if [ -s "$T/a" ] && cmp -s "$T/a" "$T/b"; then ok; else bad "merged $f differs from the unsharded run"; fi
done
./onbstudy merge --out "$T/m2" "$T/sh/sweep-state-0-of-3.bin" "$T/sh/sweep-state-1-of-3.bin" >/dev/null 2>"$T/em2"
[ $? -eq 2 ] && grep -q "missing" "$T/em2" && ok || bad "merge with a missing shard must fail with exit 2"
[ ! -e "$T/m2/summary.csv" ] && ok || bad "a failed merge wrote summary.csv"

# 3. the published failures: frisvad in float fails near -z, duff does not
col() { awk -F, -v m="$1" -v p="$2" -v d="$3" -v c="$4" '!/^#/ && $1==m && $2==p && $3==d { print $c }' "$T/t1/summary.csv"; }
fs=$(col frisvad float south 6); ds=$(col duff float south 6); fm=$(col frisvad_max float south 6)
awk -v v="$fs" 'BEGIN { exit !(v > 0.1) }' && ok || bad "frisvad float south max_defect $fs should exceed 0.1"
awk -v v="$ds" 'BEGIN { exit !(v < 5e-7) }' && ok || bad "duff float south max_defect $ds should stay below 5e-7"
awk -v v="$fm" 'BEGIN { exit !(v > 1e-3 && v < 1e-2) }' && ok || bad "frisvad_max float south max_defect $fm should be Max's ~5e-3"
fd=$(col frisvad double south 6)
awk -v v="$fd" 'BEGIN { exit !(v > 1e-5 && v < 1e-3) }' && ok || bad "frisvad double south max_defect $fd: expected the fallback's ~4.5e-4"
nf=$(col tangent_cross_z float threshold 10)
[ "${nf:-0}" -gt 0 ] && ok || bad "tangent_cross_z must produce non-finite output at +-z (got $nf)"
wh=$(col rtow float uniform 9)
[ "$wh" = "0" ] && ok || bad "rtow (handedness -1 in the registry) must have no wrong-handed basis (got $wh)"
# summary columns
head -n 100 "$T/t1/summary.csv" | grep -v '^#' | head -1 | grep -q '^method,precision,distribution,samples,rmse,max_defect,max_ulp,mean_bits,wrong_handed,nonfinite' \
	&& ok || bad "summary.csv columns"
# worst.csv: inputs as hex floats that eval reads back
line=$(awk -F, '!/^#/ && $1=="frisvad" && $2=="float" && $3=="south" && $4==1' "$T/t1/worst.csv")
x=$(echo "$line" | cut -d, -f11); y=$(echo "$line" | cut -d, -f12); z=$(echo "$line" | cut -d, -f13)
echo "$x" | grep -q '^-\{0,1\}0x' && ok || bad "worst.csv inputs are not hex floats: $x"
./onbstudy eval --precision float --methods frisvad -- "$x" "$y" "$z" > "$T/ev" 2>&1 && ok || bad "eval of the worst input failed: $(cat "$T/ev")"
grep -q "defects:" "$T/ev" && ok || bad "eval prints the defects"
err=$(echo "$line" | cut -d, -f8)
grep -q "(max $err)" "$T/ev" && ok || bad "eval's max defect is not worst.csv's $err"

# 4. threshold: Max's threshold is the minimax of both errors in float
./onbstudy threshold --precision float --out "$T/th" > "$T/tho" 2>&1 || bad "threshold failed"
grep -q "^float   both .*-0x1.fffe6cp-1" "$T/tho" && ok || bad "float minimax of both criteria should be Max's t = -0x1.fffe6cp-1: $(grep both "$T/tho")"
./onbstudy threshold --precision float --logspaced 500 --azimuths 4 --out "$T/th1" >/dev/null 2>&1
for k in 0 1; do ./onbstudy threshold --precision float --logspaced 500 --azimuths 4 --shard $k/2 --out "$T/ths" >/dev/null 2>&1; done
./onbstudy merge --out "$T/thm" "$T/ths/threshold-state-0-of-2.bin" "$T/ths/threshold-state-1-of-2.bin" >/dev/null 2>&1
data "$T/th1/threshold.csv" > "$T/a"; data "$T/thm/threshold.csv" > "$T/b"
[ -s "$T/a" ] && cmp -s "$T/a" "$T/b" && ok || bad "threshold shards do not merge to the unsharded run"

# 5. bad input: one line on stderr, exit 2, nothing written
mkdir -p "$T/keep"; echo "earlier" > "$T/keep/summary.csv"
for args in "--samples 0" "--samples abc" "--samples 1e30" "--precision half" "--dists uniform,bogus" "--methods duff,nope" \
            "--grid 1x1" "--shard 3/3" "--seed -1" "--threads -2" "--format xml" "--frobnicate" "--exhaustive-range 0.5:0.1" \
            "--ref-bits 10" "--methods duff,duff"; do
	./onbstudy sweep $args --out "$T/keep" >/dev/null 2>"$T/err"
	rc=$?
	[ $rc -eq 2 ] && ok || bad "sweep $args: exit $rc, expected 2"
	[ "$(wc -l < "$T/err")" -eq 1 ] && ok || bad "sweep $args: expected one line on stderr, got: $(cat "$T/err")"
done
[ "$(cat "$T/keep/summary.csv")" = "earlier" ] && ok || bad "a refused sweep touched an earlier summary.csv"
[ -z "$(ls "$T/keep" | grep -v '^summary.csv$')" ] && ok || bad "a refused sweep left files: $(ls "$T/keep")"
./onbstudy sweep --out /proc/onbstudy-nope $SMALL >/dev/null 2>"$T/err"; rc=$?
[ $rc -eq 2 ] && ok || bad "unwritable output directory: exit $rc, expected 2"
./onbstudy eval 1 2 >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "eval with two numbers must exit 2"
./onbstudy eval 1 2 x >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "eval with a bad number must exit 2"
./onbstudy threshold --azimuths 0 >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "threshold --azimuths 0 must exit 2"
echo "garbage" > "$T/g.bin"
./onbstudy merge "$T/g.bin" >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "merge of a non-state file must exit 2"
# the MPFR precision check fails loudly when the reference is too coarse
./onbstudy sweep --ref-bits 64 --samples 2000 --dists uniform --quiet --out "$T/rb" >/dev/null 2>"$T/err"; rc=$?
[ $rc -eq 3 ] && grep -q "disagrees" "$T/err" && ok || bad "--ref-bits 64 must fail the two-precision check (exit $rc)"
[ ! -e "$T/rb/summary.csv" ] && ok || bad "a failed precision check wrote summary.csv"

echo "sweep_cli: $pass passed, $fail failed"
[ $fail -eq 0 ]
