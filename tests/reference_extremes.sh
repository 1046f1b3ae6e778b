#!/bin/sh
# reference_extremes.sh - the reference's roundings are correct whatever
# its precision (issue 47): every input evaluated again at 191 bits
# (--check-every 1) must agree with 127 bits, on the threshold
# distribution (every method's thresholds, the poles, the exact axes with
# +-0, subnormal and tiny components) of every method, float and double,
# on the issue's two failing runs, and on extreme inputs of our own (eval:
# its two-precision check prints WARNING, an undecided rounding prints
# "cannot decide").  About 15 s of CPU.
. "$(dirname "$0")/lib.sh"

# 1. the threshold and exact-axis inputs of every method, both precisions
./onbstudy sweep --dists threshold --check-every 1 --quiet --out "$tmp/t" >/dev/null 2>"$tmp/et"; rc=$?
[ "$rc" -eq 0 ] && ok || bad "threshold --check-every 1: exit $rc: $(grep -v '^onbstudy: wrote' "$tmp/et" | head -3)"
grep -q "cannot decide" "$tmp/et" && bad "threshold: an undecided rounding: $(grep 'cannot decide' "$tmp/et" | head -2)" || ok
n=$(grep -c '^[a-z]' "$tmp/t/summary.csv")
[ "$n" -gt 60 ] && ok || bad "threshold: summary.csv has $n rows"

# 2. the issue's runs: a floor next to the subnormal midpoint 2^-150, and
#    an exact float midpoint of Frisvad's formula (the bits metric)
./onbstudy sweep --methods duff --dists threshold --check-every 1 --quiet --out "$tmp/d" >/dev/null 2>"$tmp/ed" &&
	ok || bad "duff threshold --check-every 1: $(head -2 "$tmp/ed")"
./onbstudy sweep --methods frisvad --precision float --dists exhaustive --check-every 1 --exhaustive-count 4096 \
	--quiet --out "$tmp/f" >/dev/null 2>"$tmp/ef" && ok || bad "frisvad exhaustive --check-every 1: $(head -2 "$tmp/ef")"

# 3. the grid (both poles, the equator's axes) and the nonunit inputs
./onbstudy sweep --dists grid,nonunit --grid 8x16 --samples 256 --check-every 1 --quiet --out "$tmp/g" \
	>/dev/null 2>"$tmp/eg" && ok || bad "grid,nonunit --check-every 1: $(head -2 "$tmp/eg")"

# 4. extreme inputs, every method, float and double
while read -r x y z why; do
	./onbstudy eval -- "$x" "$y" "$z" > "$tmp/o" 2>&1; rc=$?
	if [ "$rc" -eq 0 ] && ! grep -q "WARNING: the reference\|cannot decide" "$tmp/o"; then ok
	else bad "eval $x $y $z ($why): exit $rc, $(grep -B12 'WARNING: the reference\|cannot decide' "$tmp/o" | grep '^[a-z_]* (\|WARNING\|cannot' | head -4)"; fi
done <<'EOF'
-0x1p-126 0x1p+0 0x1p-149 duff's floor next to 2^-150 (the issue)
-0x1p+0 0x1p-149 -0x1p-149 frisvad_t999's input (the issue)
0x1.65c18cp-8 0x1.65c18cp-8 -0x1.fffc18p-1 an exact float midpoint of 1-x^2/(1+z) (the issue)
-0x1.4e7546p-7 -0x1.4e7546p-7 -0x1.fff258p-1 another one
0x1.8p-22 0x1.bb67a4p-10 -0x1.ffffdp-1 a midpoint made to order: 1+z = 3 2^-21, x = 3 2^-23
0 0 -1 the south pole
-0 -0 -1 the south pole, signed zeros
0 -0 1 the north pole
-1 0 0 naive's singular point
1 -0 0 +x
0 -1 -0 -y
0x1p-149 -0x1p-149 -1 subnormal floats next to -z
0x1p-1074 0x1p-1074 -1 subnormal doubles next to -z
0x1p-1022 -0x1p-1074 0x1.fffffffffffffp-1 the smallest normal and subnormal double
0x1p-12 0 -0x1.fffffep-1 n.z one float step above -1
0x1p-26 0 -0x1.fffffffffffffp-1 n.z one double step above -1
0x1.6a09e6p-1 0x1.6a09e6p-1 0 the equator at 45 degrees (zero components computed inexactly)
0x1p-149 0x1.6a09e6p-1 -0x1.6a09e6p-1 open3d's singular point with a subnormal
EOF

finish reference_extremes
