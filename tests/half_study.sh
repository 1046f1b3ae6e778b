#!/bin/sh
# half_study.sh - the study's commands in binary16 (issue 43, item 2):
# `eval --precision half` and `list --axes --precision half`.
#  1. eval rounds the input to binary16, prints its encodings and the
#     roundings, and measures the half kernel against the MPFR reference
#     at that rounded input: duff at (0.6, 0, 0.8) has the defect of the
#     input's own |n| - 1 (the exact formula rounded once has the same:
#     defect / floor 1) and a forward error within half an ulp;
#  2. the branch rules in binary16: frisvad_max's threshold and PhysX's
#     0.9999f round to -1 and 1 in half, so at n = -z and n = +y the half
#     kernels take branch 0 (the formula), where a rule with the float
#     constants would name branch 1; frisvad's basis is NaN there, physx's
#     b1 = b2 = 0 (defect 1);
#  3. list --axes --precision half: six rows per method, the half kernels'
#     frames (frisvad NaN at -z, duff finite everywhere, physx 0 at +-y);
#  4. sweep --precision half: half rows only (the default sweep has none),
#     every input a binary16 value, the reference MPFR on every half
#     evaluation (reference.csv: fallback rate 1), duff within 8u = 2^-8 on
#     uniform with no non-finite basis, frisvad non-finite on threshold
#     (n = -z), physx's defect 1 at +-y; --precision all's float rows equal
#     --precision float's; two shards merge to the unsharded half run;
#  5. certify --precision half: frisvad non-finite at -z, duff proven;
#  6. refusals: --precision float with list --axes, --precision without
#     --axes, eval --arith with a profile without a binary16 row (d3d11);
#     a build without _Float16 refuses
#     --precision half with exit 2 and says why.
. "$(dirname "$0")/lib.sh"

./onbstudy eval --precision half --methods duff 0.6 0 0.8 > "$tmp/e1" 2> "$tmp/err"; rc=$?
if [ $rc -eq 2 ] && grep -q '_Float16' "$tmp/err"; then
	ok; finish half_study
fi
[ $rc -eq 0 ] && ok || bad "eval --precision half failed (exit $rc): $(cat "$tmp/err")"
grep -q '^== half: n = (0x1.334p-1, 0x0p+0, 0x1.998p-1)$' "$tmp/e1" && ok || bad "eval half: input not rounded to binary16: $(grep '^==' "$tmp/e1")"
grep -q 'binary16 encodings: (0x38cd, 0x0000, 0x3a66)' "$tmp/e1" && ok || bad "eval half: encodings"
grep -q 'note: component 2 rounded to half: 0.80000000000000004 -> 0x1.998p-1' "$tmp/e1" && ok || bad "eval half: rounding note"
grep -q 'defect / floor: 1$' "$tmp/e1" && ok || bad "eval half: duff's defect is the input's |n|-1, the floor's: $(grep 'defect' "$tmp/e1")"
awk '/forward: max/ { if ($3 + 0 <= 0.5 && $3 + 0 > 0) ok = 1 } END { exit !ok }' "$tmp/e1" && ok || bad "eval half: duff's forward error: $(grep forward "$tmp/e1")"
grep -q 'ref b1 (0x1.998e38651f40ep-1' "$tmp/e1" && ok || bad "eval half: the reference is not at the rounded input"

./onbstudy eval --precision half --methods frisvad_max,physx 0 0 -1 > "$tmp/e2" && ok || bad "eval half at -z"
grep -q '^frisvad_max (half), branch 0 ' "$tmp/e2" && ok || bad "frisvad_max in half at -z: the threshold rounds to -1, branch 0: $(grep 'frisvad_max (' "$tmp/e2")"
grep -q 'NON-FINITE' "$tmp/e2" && ok || bad "frisvad_max in half at -z must be non-finite"
./onbstudy eval --precision float --methods frisvad_max 0 0 -1 | grep -q '^frisvad_max (float), branch 1 ' && ok || bad "frisvad_max in float at -z: branch 1"
./onbstudy eval --precision half --methods physx 0 1 0 > "$tmp/e3" && ok || bad "eval half at +y"
grep -q '^physx (half), branch 0 ' "$tmp/e3" && ok || bad "physx in half at +y: 0.9999f rounds to 1, branch 0"
grep -q 'defects: .*(max 1)$' "$tmp/e3" && ok || bad "physx in half at +y: defect 1: $(grep defects "$tmp/e3")"
./onbstudy eval --precision all --methods duff 0 0 1 | grep -c '^duff (' | grep -q '^3$' && ok || bad "eval --precision all: float, double and half"

nm=$(./onbstudy list --format csv | tail -n +2 | wc -l)
./onbstudy list --axes --precision half --format csv > "$tmp/a.csv" && ok || bad "list --axes --precision half"
[ "$(tail -n +2 "$tmp/a.csv" | wc -l)" -eq $((6 * nm)) ] && ok || bad "list --axes half: want $((6 * nm)) rows"
grep -q '^frisvad,-z,nan,nan,' "$tmp/a.csv" && ok || bad "list --axes half: frisvad at -z: $(grep '^frisvad,-z' "$tmp/a.csv")"
awk -F, '$1 == "duff" && $2 == "-z" && $3 == 1 && $4 == 0 && $5 == 0 && $6 == 0 && $7 == -1 && $8 == 0 { f = 1 } END { exit !f }' "$tmp/a.csv" && ok || bad "list --axes half: duff at -z: $(grep '^duff,-z' "$tmp/a.csv")"
awk -F, '$1 == "physx" && $2 == "+y" && $3 == 0 && $4 == 0 && $5 == 0 && $6 == 0 && $7 == 0 && $8 == 0 { f = 1 } END { exit !f }' "$tmp/a.csv" && ok || bad "list --axes half: physx at +y: $(grep '^physx,+y' "$tmp/a.csv")"
./onbstudy list --axes --precision half > /dev/null && ok || bad "list --axes --precision half (table)"

S="--methods duff,frisvad,physx --samples 256 --exhaustive-count 32 --grid 4x8 --threads 2 --quiet --seed 3"
./onbstudy sweep --precision half $S --out "$tmp/sh" > /dev/null 2> "$tmp/err" && ok || bad "sweep --precision half: $(cat "$tmp/err")"
sum="$tmp/sh/summary.csv"
data() { grep -v '^#' "$1"; }
[ "$(data "$sum" | tail -n +2 | cut -d, -f2 | sort -u)" = "half" ] && ok || bad "sweep half: precisions $(data "$sum" | tail -n +2 | cut -d, -f2 | sort -u | tr '\n' ' ')"
[ "$(data "$sum" | tail -n +2 | wc -l)" -eq 21 ] && ok || bad "sweep half: want 3 methods x 7 distributions"
col() { data "$sum" | awk -F, -v m="$1" -v d="$2" -v c="$3" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next } $1 == m && $3 == d { print $h[c] }'; }
awk -v v="$(col duff uniform max_defect)" -v n="$(col duff uniform nonfinite)" 'BEGIN { exit !(v > 0 && v <= 8 * 2^-11 && n == 0) }' && ok || bad "sweep half: duff on uniform: max_defect $(col duff uniform max_defect), nonfinite $(col duff uniform nonfinite)"
[ "$(col frisvad threshold nonfinite)" -gt 0 ] && ok || bad "sweep half: frisvad must be non-finite on threshold (n = -z)"
[ "$(col physx threshold max_defect)" = 1 ] && ok || bad "sweep half: physx's defect on threshold: $(col physx threshold max_defect), want 1"
data "$tmp/sh/reference.csv" | awk -F, 'NR > 1 && ($2 != "half" || $5 != 1) { bad = 1 } NR > 1 { n++ } END { exit bad || n != 3 }' && ok || bad "sweep half: reference.csv must say MPFR on every half evaluation: $(data "$tmp/sh/reference.csv")"
# every input of worst.csv is a binary16 value: at most 11 significant bits
data "$tmp/sh/worst.csv" | awk -F, 'NR > 1 { for (i = 11; i <= 13; i++) if ($i !~ /^-?0x(0p\+0|1(\.[0-9a-f]?[0-9a-f]?[048c]?)?p[-+][0-9]+)$/) { print $i; exit 1 } }' > "$tmp/nothalf" && ok || bad "sweep half: an input is not a binary16 value: $(cat "$tmp/nothalf")"
./onbstudy sweep --precision all $S --dists uniform,south,threshold --out "$tmp/sa" > /dev/null 2>&1 && ok || bad "sweep --precision all"
./onbstudy sweep --precision float $S --dists uniform,south,threshold --out "$tmp/sf" > /dev/null 2>&1 && ok || bad "sweep --precision float"
[ "$(data "$tmp/sa/summary.csv" | grep ',float,')" = "$(data "$tmp/sf/summary.csv" | grep ',float,')" ] && ok || bad "sweep --precision all: its float rows differ from --precision float's"
[ "$(data "$tmp/sa/summary.csv" | grep -c ',half,')" -eq 9 ] && ok || bad "sweep --precision all: want 9 half rows"
# table: the half rows beside bench.csv's float and double speeds, accuracy only
./onbstudy table --bench results/reference/bench.csv --summary "$tmp/sa/summary.csv" --out "$tmp/tab" > "$tmp/tab.txt" 2>&1 && ok || bad "table with half rows: $(cat "$tmp/tab.txt")"
data "$tmp/tab/tradeoff.csv" | awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next } $2 == "half" { n++; if ($h["pareto"] != "na" || $h["batch_mbases_1t"] != "nan" || !($h["max_defect_uniform"] > 0)) bad = 1 } END { exit bad || n != 3 }' && ok || bad "table: tradeoff.csv's half rows: $(grep ',half,' "$tmp/tab/tradeoff.csv")"
grep -q '^# binary16 (sweep --precision half' "$tmp/tab.txt" && awk -v u="$(data "$tmp/sa/summary.csv" | awk -F, '$1 == "duff" && $2 == "half" && $3 == "uniform" { print $6 }')" '$1 == "duff" && $2 == "|" && $NF + 0 > 0 { if ($NF - u * 2048 < 0.01 && u * 2048 - $NF < 0.01) f = 1 } END { exit !f }' "$tmp/tab.txt" && ok || bad "table: no binary16 block with duff's max in u: $(tail -5 "$tmp/tab.txt")"
for k in 0 1; do ./onbstudy sweep --precision half $S --shard $k/2 --out "$tmp/shs" > /dev/null 2>&1; done
./onbstudy merge --out "$tmp/shm" "$tmp/shs/sweep-state-0-of-2.bin" "$tmp/shs/sweep-state-1-of-2.bin" > /dev/null 2>&1 && ok || bad "merge of the half shards"
[ "$(data "$sum")" = "$(data "$tmp/shm/summary.csv")" ] && ok || bad "sweep half: two shards do not merge to the unsharded run"

# 5. certify --precision half (tests/test_certify_half.c checks the bounds
#    against a scan): at the pole -z frisvad's basis is NaN (status
#    non-finite, bound inf: no number), duff is proven within a few u; the
#    float options are refused
./onbstudy certify --precision half --methods duff,frisvad --band=-1,-0.999 --sectors 2 --depth 2 --azimuths 2 \
	--quiet --out "$tmp/ch" > /dev/null 2> "$tmp/err" && ok || bad "certify --precision half: $(cat "$tmp/err")"
data "$tmp/ch/certify-half.csv" | awk -F, 'NR > 1 && $1 == "frisvad" && $3 == -1 && $12 == "non-finite" && $7 == "inf" { f = 1 } END { exit !f }' \
	&& ok || bad "certify half: frisvad at -z must be non-finite with no bound: $(grep '^frisvad' "$tmp/ch/certify-half.csv" | head -2)"
data "$tmp/ch/certify-half.csv" | awk -F, 'NR > 1 && $1 == "duff" { n++; if ($12 != "proven" || !($7 <= 8 * 2^-11) || !($8 <= $7)) b = 1 } END { exit b || n == 0 }' \
	&& ok || bad "certify half: duff must be proven within 8u: $(grep '^duff' "$tmp/ch/certify-half.csv" | head -3)"
./onbstudy certify --precision half --fma > /dev/null 2>&1; [ $? -eq 2 ] && ok || bad "certify --precision half --fma must exit 2"
./onbstudy certify --precision float --depth 3 > /dev/null 2>&1; [ $? -eq 2 ] && ok || bad "certify --depth without half must exit 2"

./onbstudy list --axes --precision float > /dev/null 2>&1; [ $? -eq 2 ] && ok || bad "list --axes --precision float must exit 2"
./onbstudy list --precision half > /dev/null 2>&1; [ $? -eq 2 ] && ok || bad "list --precision without --axes must exit 2"
# eval --arith --precision half runs under a profile with a binary16 row (98a47d3), and is refused under one without
./onbstudy eval --arith ieee --precision half 0 0 1 > /dev/null 2>&1 && ok || bad "eval --arith ieee --precision half must run"
./onbstudy eval --arith d3d11 --precision half 0 0 1 > /dev/null 2> "$tmp/err"; [ $? -eq 2 ] && grep -q 'no precision' "$tmp/err" && ok || bad "eval --arith d3d11 --precision half must exit 2: $(cat "$tmp/err")"
finish half_study
