#!/bin/sh
# gpu.sh - libonb's shader kernels on a real Vulkan driver (Mesa's
# lavapipe; docs/gpu.md, "On a real driver: lavapipe"):
#   - the device is created: no lavapipe is a failure, not a skip
#     (scripts/install-deps.sh --test installs mesa-vulkan-drivers);
#   - include/libonb/onb.hlsl is scripts/onb-hlsl.sh's output of onb.glsl;
#   - `onbstudy-gpu compare`: every method of onb.glsl and onb.hlsl, as
#     written and all precise, on the sweep's distributions and the
#     extremes, gives the C kernel's bits but where the driver's own
#     rounding (its fma, its signed zeros and NaNs) explains it, and every
#     result on a rounded unit input lies within certify's bound;
#   - the checks can fail: the deliberately broken kernel (GLSL's sign()
#     in Duff's formula) is caught by both, and a bound tightened below
#     the found defect is reported outside;
#   - the shader engines' own lines (wild: every GLSL, HLSL and Slang row
#     of the registry, src/gpu/wild/NAME.glsl) lie within their C rows'
#     bounds, and a missing file or a bound below the defect fails;
#   - binary16 (`onbstudy-gpu half`): the kernels of src/gpu/half.comp in
#     explicit float16_t arithmetic give the C half kernels' bits but the
#     sign of a zero, NaN/inf (the driver's folding) and the double ->
#     binary16 conversion done through float, and every result on a
#     binary16 rounding of a unit vector lies within certify --arith vulkan
#     --precision half's bound at that input; gltf_viewer built with
#     `precision mediump float` carries RelaxedPrecision and gives its
#     float build's bits on this driver; the checks can fail (a frisvad
#     evaluated in 32 bits, GLSL's sign() in Duff's formula, duff's bounds
#     divided by 10);
#   - bad usage exits 2, an absent device 3, with a message.
. "$(dirname "$0")/lib.sh"
# Under ASan, the driver's own allocations that it never frees (LLVM's
# JIT, Mesa's caches) would fail every run at exit: leak detection is off
# for onbstudy-gpu only (as tests/mpi.sh does for Open MPI); ASan's other
# checks and UBSan stay on for the harness's code.
if [ -n "$SAN" ]; then export ASAN_OPTIONS="detect_leaks=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"; fi
make -s gpu > "$tmp/make.log" 2>&1 || { cat "$tmp/make.log"; bad "make gpu"; finish gpu; }
G=./onbstudy-gpu

$G info > "$tmp/info" 2>&1 && grep -q 'device: llvmpipe' "$tmp/info" && ok ||
	{ cat "$tmp/info"; bad "no lavapipe device (scripts/install-deps.sh --test installs mesa-vulkan-drivers)"; finish gpu; }

sh scripts/onb-hlsl.sh include/libonb/onb.glsl "$tmp/onb.hlsl" && cmp -s "$tmp/onb.hlsl" include/libonb/onb.hlsl && ok ||
	bad "include/libonb/onb.hlsl is stale: run sh scripts/onb-hlsl.sh"

$G ops --count 20000 > "$tmp/ops" 2>&1 && grep -q '^| `a / b` | IEEE | 20000 |' "$tmp/ops" && ok ||
	{ cat "$tmp/ops"; bad "ops: the driver's division is not IEEE on every operand, or ops failed"; }

$G compare --per 2000 > "$tmp/cmp" 2>&1; rc=$?
[ $rc -eq 0 ] && [ "$(grep -c '^| `' "$tmp/cmp")" -eq 34 ] && ! grep -q 'outside' "$tmp/cmp" && ok ||
	{ cat "$tmp/cmp"; bad "compare: exit $rc (want 0 and 34 methods inside their envelopes)"; }
grep -q '^| `duff_branchless` | `duff_branchless` | all [0-9]* (NaN payloads aside) | all' "$tmp/cmp" && ok ||
	bad "compare: duff_branchless is not bit-identical to C in GLSL and GLSL precise"

# The checks can fail: a broken kernel, and a bound below the defect found.
$G compare --per 500 --methods broken_duff_sign > "$tmp/broken" 2>&1; rc=$?
[ $rc -eq 1 ] && grep -q '^| `broken_duff_sign` .*\*\*value: [1-9].*\*\*outside\*\*' "$tmp/broken" && ok ||
	{ cat "$tmp/broken"; bad "the broken kernel was not caught (exit $rc)"; }
grep -v '^duff_branchless,float,-1,1,0,360,' results/certify/certify.csv > "$tmp/tight.csv"
echo 'duff_branchless,float,-1,1,0,360,1e-7,0,0,0,0,proven,0,,,' >> "$tmp/tight.csv"
$G compare --per 500 --methods duff_branchless --bounds "$tmp/tight.csv" > "$tmp/tight" 2>&1; rc=$?
[ $rc -eq 1 ] && grep -q '1e-07 (duff_branchless) | \*\*outside\*\*' "$tmp/tight" && ok ||
	{ cat "$tmp/tight"; bad "a bound of 1e-7 for duff_branchless was not reported outside (exit $rc)"; }

# wild: every shader row of the registry (GLSL, HLSL, Slang) runs from its
# src/gpu/wild/NAME.glsl and is inside its C row's bound
rows=$(./onbstudy list --format csv | awk -F, 'NR > 1' | grep -c -e ',"\{0,1\}GLSL' -e ',"\{0,1\}HLSL' -e ',"\{0,1\}Slang' || true)
rows=$((rows + $(./onbstudy list --aliases --format csv | awk -F, 'NR > 1' | grep -c -e ',"\{0,1\}GLSL' -e ',"\{0,1\}HLSL' -e ',"\{0,1\}Slang' || true)))
$G wild --per 2000 > "$tmp/wild" 2>&1; rc=$?
n=$(grep -c '| inside |' "$tmp/wild")
[ $rc -eq 0 ] && [ "$n" -eq "$rows" ] && [ "$n" -ge 6 ] && grep -q '^| `capsaicin` ' "$tmp/wild" && grep -q '^| `rtxdi` ' "$tmp/wild" && ok ||
	{ cat "$tmp/wild"; bad "wild: exit $rc, $n engines inside (want 0 and all $rows shader rows of the registry)"; }
# ... and the wild checks can fail: a shader row without its file, and a bound below the defect
mkdir -p "$tmp/spv/wild" && cp build/gpu/ops.spv "$tmp/spv/" && cp build/gpu/wild/*.spv "$tmp/spv/wild/" && rm "$tmp/spv/wild/rtxdi.spv"
$G wild --per 100 --spv "$tmp/spv" > "$tmp/wild1" 2>&1; rc=$?
[ $rc -eq 1 ] && grep -q '^| `rtxdi` .*not run: no src/gpu/wild/ENGINE.glsl' "$tmp/wild1" && ok ||
	{ cat "$tmp/wild1"; bad "wild without rtxdi.spv: exit $rc (want 1, rtxdi not run)"; }
{ grep -v '^duff,float,-1,1,0,360,' results/certify/certify.csv; echo 'duff,float,-1,1,0,360,1e-7,0,0,0,0,proven,0,,,'
  grep -h '^capsaicin,float,-1,1,0,360,' results/wild/add/*/certify.csv | head -1; } > "$tmp/wtight.csv"
$G wild --per 100 --bounds "$tmp/wtight.csv" > "$tmp/wild2" 2>&1; rc=$?
[ $rc -eq 1 ] && [ "$(grep -c '| `duff` .*| 1e-07; .*| \*\*outside\*\* |' "$tmp/wild2")" -eq 3 ] && ok ||
	{ cat "$tmp/wild2"; bad "wild with duff's bound 1e-7: exit $rc (want 1, pasvulkan, falcor and rtxdi outside)"; }
# capsaicin's whole-sphere bound is inf (singular near +-x): its inputs are
# held to their regions' bounds, which halved must be crossed
f=$(grep -l '^capsaicin,float,-1,1,0,360,' results/wild/add/*/certify.csv | head -1)
{ grep -v '^capsaicin,' results/certify/certify.csv; grep '^capsaicin,float,' "$f" | awk -F, -v OFS=, '$7 != "inf" { $7 = $7 / 2 } 1'; } > "$tmp/whalf.csv"
$G wild --per 100 --bounds "$tmp/whalf.csv" > "$tmp/wild3" 2>&1; rc=$?
[ $rc -eq 1 ] && grep -q '^| `capsaicin` .*| \*\*outside\*\* |' "$tmp/wild3" && [ "$(grep -c '| \*\*outside\*\* |' "$tmp/wild3")" -eq 1 ] && ok ||
	{ cat "$tmp/wild3"; bad "wild with capsaicin's region bounds halved: exit $rc (want 1, capsaicin alone outside)"; }

# half: explicit binary16 on the driver (no shaderFloat16 is a failure: exit 1)
$G half --per 1000 > "$tmp/half" 2>&1; rc=$?
n=$(grep -c '| inside |$' "$tmp/half")
[ $rc -eq 0 ] && [ "$n" -eq 18 ] && ! grep -q '\*\*value' "$tmp/half" && grep -q 'shaderFloat16 on' "$tmp/half" && ok ||
	{ cat "$tmp/half"; bad "half: exit $rc, $n binary16 kernels inside (want 0 and 18, no value difference)"; }
# mediump: RelaxedPrecision decorations, and on lavapipe the float build's bits on every input
awk -F'|' '$2 ~ /gltf_viewer`, mediump/ { split($6, a, " "); ok = $3 + 0 > 0 && a[1] == a[3] && a[1] > 0 } END { exit !ok }' "$tmp/half" && ok ||
	{ grep -A3 RelaxedPrecision "$tmp/half"; bad "half: the mediump gltf_viewer has no RelaxedPrecision or other bits than its float build"; }
# ... and its checks can fail
$G half --per 300 --methods broken_frisvad_f32 > "$tmp/h1" 2>&1; rc=$?
[ $rc -eq 1 ] && grep -q '^| `broken_frisvad_f32` | `frisvad` | .*\*\*value: [1-9]' "$tmp/h1" && ok ||
	{ cat "$tmp/h1"; bad "half: frisvad in 32 bits not caught by the bit comparison (exit $rc)"; }
$G half --per 300 --methods broken_duff_sign > "$tmp/h2" 2>&1; rc=$?
[ $rc -eq 1 ] && grep -q '^| `broken_duff_sign` .*| \*\*outside\*\* |$' "$tmp/h2" && ok ||
	{ cat "$tmp/h2"; bad "half: GLSL's sign() in Duff's formula not outside its envelope (exit $rc)"; }
awk -F, -v OFS=, '$1 == "duff" && $2 == "half" && $7 != "inf" { $7 = $7 / 10 } 1' results/gpu/half/vulkan/certify-half.csv > "$tmp/h10.csv"
$G half --per 300 --methods duff --bounds "$tmp/h10.csv" > "$tmp/h3" 2>&1; rc=$?
[ $rc -eq 1 ] && grep -q '^| `duff` | `duff` | .*| \*\*outside\*\* |$' "$tmp/h3" && ok ||
	{ cat "$tmp/h3"; bad "half: duff's bounds divided by 10 not crossed (exit $rc)"; }
$G half --methods duff,nosuch > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 2 ] && grep -q 'valid:.*broken_frisvad_f32' "$tmp/err" && ok || bad "half --methods nosuch: exit $rc, $(cat "$tmp/err")"
$G half --per 10 --bounds "$tmp/none.csv" > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 1 ] && grep -q 'cannot open the binary16 bounds' "$tmp/err" && ok || bad "half without its bounds: exit $rc, $(cat "$tmp/err")"

$G frobnicate > /dev/null 2>&1; [ $? -eq 2 ] && ok || bad "an unknown command does not exit 2"
$G compare --methods duff,nosuch > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 2 ] && grep -q 'valid:.*duff_branchless' "$tmp/err" && ok || bad "--methods nosuch: exit $rc, $(cat "$tmp/err")"
$G info --device 'no such device' > /dev/null 2> "$tmp/err"; rc=$?
[ $rc -eq 3 ] && grep -q 'no Vulkan device named like' "$tmp/err" && ok || bad "--device absent: exit $rc, $(cat "$tmp/err")"
finish gpu
