#!/bin/sh
# sweep_arith.sh - `onbstudy sweep --arith PROFILE` (src/sweep/emusweep.c,
# docs/gpu.md): the sweep's inputs through the emulated conforming
# implementations stay within the proven bounds (the one at each input and
# the whole-sphere one of results/gpu); the same check FAILS on a mutated
# emulation whose allowances are twice the profile's (--widen 2: exit 1,
# EXCEEDS); the data do not depend on the thread count; bad input exits 2.
# About 2 s of CPU.
. "$(dirname "$0")/lib.sh"
T=$tmp
data() { grep -v '^#' "$1"; }
S="sweep --arith vulkan --methods duff,hughes_moeller --precision float --dists uniform,north --samples 40"

# 1. conforming: exit 0, every unit input checked against its point bound, within it
./onbstudy $S --threads 2 --out "$T/a" > "$T/a.out" 2>&1; rc=$?
[ $rc -eq 0 ] && ok || bad "sweep --arith vulkan: exit $rc: $(tail -3 "$T/a.out")"
C="$T/a/arith-sweep.csv"
grep -q '^# arith: vulkan ' "$C" && ok || bad "no '# arith: vulkan' provenance line"
grep -q '^# whole-sphere bound: results/gpu/vulkan/certify.csv' "$C" && ok || bad "whole-sphere bounds not from results/gpu: $(grep whole-sphere "$C")"
[ "$(data "$C" | head -1 | cut -d, -f1-6)" = "method,precision,distribution,inputs,unit_inputs,checked" ] && ok || bad "header $(data "$C" | head -1)"
data "$C" | awk -F, 'NR > 1 { n++; if ($6 + 0 < 1 || $5 != $6 || $19 != 0 || $21 != 0 || $20 == "") bad++ } END { exit !(n == 4 && bad == 0) }' \
	&& ok || bad "rows not all checked and within: $(data "$C")"
grep -q '^duff .* ok$' "$T/a.out" && ok || bad "no 'ok' line for duff: $(cat "$T/a.out")"
# the thread count changes no byte of the data
./onbstudy $S --threads 1 --out "$T/b" > /dev/null 2>&1
[ "$(data "$C")" = "$(data "$T/b/arith-sweep.csv")" ] && ok || bad "1 and 2 threads differ"

# 2. the mutation: allowances twice vulkan's must exceed a bound (exit 1)
./onbstudy $S --threads 2 --widen 2 --out "$T/w" > "$T/w.out" 2>&1; rc=$?
[ $rc -eq 1 ] && ok || bad "--widen 2: exit $rc (expected 1): $(tail -3 "$T/w.out")"
grep -q 'EXCEEDS' "$T/w.out" && ok || bad "--widen 2: no EXCEEDS: $(cat "$T/w.out")"
data "$T/w/arith-sweep.csv" | awk -F, 'NR > 1 && $19 > 0 { n++ } END { exit !(n > 0) }' && ok || bad "--widen 2: no input above its point bound"
grep -q '^# widen: 2' "$T/w/arith-sweep.csv" && ok || bad "--widen 2: the CSV does not say it is mutated"

# binary16 under vulkan's half column: emulated and measured (no half proof
# model: nothing checked, said so), the nearest never above the adversary
./onbstudy sweep --arith vulkan --methods duff --precision half --dists uniform --samples 20 --out "$T/h" > "$T/h.out" 2>&1; rc=$?
[ $rc -eq 0 ] && grep -q '^duff  *half  *20 .*measured (no binary16 proof model)' "$T/h.out" && ok || bad "sweep --arith vulkan --precision half: exit $rc: $(cat "$T/h.out")"
data "$T/h/arith-sweep.csv" | awk -F, 'NR > 1 && $2 == "half" && $22 == "no-half-model" && $6 == 0 && $9 + 0 > 0 && $11 + 0 >= $9 + 0 { n++ } END { exit n != 1 }' \
	&& ok || bad "sweep half: the CSV row is not measured-only: $(data "$T/h/arith-sweep.csv" | tail -1)"

# 3. bad input: exit 2 and one message, nothing written
for args in "--arith metal" "--arith vulkan --fma" "--arith d3d11 --precision half" "--arith vulkan --shard 0/2" "--widen 2" "--arith vulkan --widen 0.5" \
            "--arith vulkan --bounds results/gpu/d3d11/certify.csv" "--arith vulkan --bounds $T/none.csv"; do
	./onbstudy sweep $args --methods duff --dists uniform --samples 4 --out "$T/bad" > /dev/null 2> "$T/err"; rc=$?
	[ $rc -eq 2 ] && ok || bad "sweep $args: exit $rc (expected 2): $(cat "$T/err")"
	[ "$(wc -l < "$T/err")" -ge 1 ] && ok || bad "sweep $args: no message"
	[ ! -e "$T/bad/arith-sweep.csv" ] && ok || bad "sweep $args: a file was written"
done
./onbstudy sweep --arith metal 2> "$T/err" > /dev/null
grep -q "ieee, vulkan, vulkan-precise, d3d11, opencl, cuda-fast, contract-any" "$T/err" && ok || bad "unknown profile: $(cat "$T/err")"
finish sweep_arith.sh
