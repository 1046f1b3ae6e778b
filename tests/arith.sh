#!/bin/sh
# arith.sh - arithmetic profiles (src/model/arith.c, docs/gpu.md) through
# `onbstudy certify --arith`: ieee is byte for byte the plain run; every
# profile's --quick run on a few methods keeps found <= bound wherever a
# bound is claimed and names the cause of every row without a bound (the
# operation the profile gives none, or the one whose enclosure was lost:
# gltf_viewer under vulkan, rsqrt:0); the
# profile's whole-sphere bound is never below the defect ieee found; bad input
# exits 2 with the list of profiles; docs/gpu.md's tables are results/gpu's,
# the full-budget runs' column included, and a full-budget bound looser than
# the --quick one fails.  (tests/test_arith.c checks the
# emulated implementations against the bounds.)
. "$(dirname "$0")/lib.sh"
T=$tmp
data() { grep -v '^#' "$1"; }
M=frisvad,duff,hughes_moeller,gltf_viewer
Q="--quick --quiet --methods $M --samples 60 --budget 24"

# 1. ieee: the plain model, byte for byte (provenance lines aside)
./onbstudy certify $Q --out "$T/plain" >/dev/null 2>&1 || bad "certify --quick failed"
./onbstudy certify $Q --arith ieee --out "$T/ieee" >/dev/null 2>&1 || bad "certify --arith ieee failed"
# the seconds of '# images:' and '# refine:' depend on the load
strip() { grep -v -e '^# date:' -e '^# command:' -e '^# profile:' "$1" | sed 's/ ([0-9.]* s)$//'; }
[ "$(strip "$T/plain/certify.csv")" = "$(strip "$T/ieee/certify.csv")" ] && ok || bad "--arith ieee differs from the plain run"

# 2. every profile: the header names it, found <= bound where a bound is
#    claimed, an unbounded row names its operation, and a profile's
#    whole-sphere bound is never below the defect ieee found (every profile
#    allows the IEEE results, flushing aside)
for p in vulkan vulkan-precise d3d11 opencl cuda-fast contract-any; do
	C="$T/$p/certify.csv"
	./onbstudy certify $Q --arith $p --out "$T/$p" >"$T/$p.out" 2>&1 || { bad "certify --arith $p failed: $(tail -2 "$T/$p.out")"; continue; }
	grep -q "^# arith: $p " "$C" && ok || bad "$p: no '# arith' provenance line"
	[ "$(data "$C" | head -1)" = "method,precision,nz_lo,nz_hi,phi_lo,phi_hi,bound,found,found_nx,found_ny,found_nz,status,evaluated,found_lx,found_ly,found_lz,unbounded_by" ] \
		&& ok || bad "$p: header $(data "$C" | head -1)"
	data "$C" | awk -F, 'NR > 1 && $12 != "singular" && $12 != "unbounded" && !($7 + 0 >= $8 + 0) { n++; print } END { exit n > 0 }' > "$T/inv" \
		&& ok || bad "$p: found above bound: $(head -2 "$T/inv")"
	data "$C" | awk -F, 'NR > 1 && $12 == "unbounded" && $17 == "" { n++ } END { exit n > 0 }' && ok || bad "$p: an unbounded row without its operation"
	# every row without a bound (inf, not singular) says why; no other row does
	data "$C" | awk -F, 'NR > 1 && ($7 == "inf" && $12 != "singular") != ($17 != "") { n++; print } END { exit n > 0 }' > "$T/why" \
		&& ok || bad "$p: a row with bound inf and an empty unbounded_by, or a cause beside a bound: $(head -2 "$T/why")"
	data "$C" | awk -F, 'NR > 1 && $12 == "unbounded" && $7 != "inf" { n++ } END { exit n > 0 }' && ok || bad "$p: an unbounded row with a number"
	whole() { data "$1" | awk -F, -v c="$2" 'NR > 1 && $3 == -1 && $4 == 1 && $5 == 0 && $6 == 360 { print $1 "/" $2 "," $c }' | sort; }
	whole "$T/ieee/certify.csv" 8 > "$T/w0"
	whole "$C" 7 > "$T/w1"
	join -t, "$T/w0" "$T/w1" | awk -F, '$3 != "inf" && $3 + 0 < $2 + 0 { n++; print } END { exit n > 0 }' > "$T/less" \
		&& ok || bad "$p: a whole-sphere bound below ieee's found: $(head -2 "$T/less")"
done
# d3d11's doubles: dadd, dmul, ddiv within an ulp give duff and frisvad a
# number; Shader Model 5 has no double sqrt, so hughes_moeller (a double
# sqrt in both precisions) is unbounded by sqrt, never a number
data "$T/d3d11/certify.csv" | awk -F, '$3 == -1 && $4 == 1 && $5 == 0 && $6 == 360 { w[$1 "/" $2] = $7 "," $12 "," $17 }
	END { exit !(w["duff/double"] ~ /^[0-9.e+-]+,(proven|budget),$/ && w["frisvad/double"] ~ /^[0-9.e+-]+,/ &&
	             w["hughes_moeller/double"] == "inf,unbounded,sqrt" && w["hughes_moeller/float"] == "inf,unbounded,sqrt") }' \
	&& ok || bad "d3d11 doubles: duff/frisvad not bounded or hughes_moeller not unbounded by sqrt: $(data "$T/d3d11/certify.csv" | grep -e '^duff,double,-1,1,0,360' -e '^hughes_moeller,[a-z]*,-1,1,0,360')"
# gltf_viewer under vulkan: its +-y poles (n.z in [-0.3, 0.3]) have no
# finite bound, and the row names inversesqrt (Vulkan's sqrt, 1/inversesqrt)
# of an enclosure of |up x n|^2 that reaches 0 (docs/gpu.md)
data "$T/vulkan/certify.csv" | awk -F, '$1 == "gltf_viewer" && $2 == "float" && $3 == -1 && $4 == 1 && $5 == 0 { w = $7 "," $12 "," $17 }
	END { exit w != "inf,budget,rsqrt:0" }' && ok || bad "gltf_viewer float under vulkan: $(data "$T/vulkan/certify.csv" | grep '^gltf_viewer,float,-1,1,0,360')"
# the double under vulkan is only as precise as float: far above ieee's
a=$(data "$T/ieee/certify.csv" | awk -F, '$1 == "duff" && $2 == "double" && $3 == -1 && $4 == 1 && $5 == 0 { print $7 }')
b=$(data "$T/vulkan/certify.csv" | awk -F, '$1 == "duff" && $2 == "double" && $3 == -1 && $4 == 1 && $5 == 0 { print $7 }')
awk -v a="$a" -v b="$b" 'BEGIN { exit !(b > 1000 * a) }' && ok || bad "vulkan's double bound $b not far above ieee's $a"

# 3. bad input: exit 2, the valid profiles listed, nothing written
./onbstudy certify --arith metal --quick --out "$T/bad" >/dev/null 2>"$T/err"; rc=$?
[ $rc -eq 2 ] && ok || bad "unknown profile: exit $rc"
grep -q "ieee, vulkan, vulkan-precise, d3d11, opencl, cuda-fast, contract-any" "$T/err" && ok || bad "unknown profile: $(cat "$T/err")"
[ ! -e "$T/bad/certify.csv" ] && ok || bad "unknown profile: a file was written"
./onbstudy certify --arith vulkan --fma --quick --out "$T/bad" >/dev/null 2>&1; rc=$?
[ $rc -eq 2 ] && ok || bad "--arith with --fma: exit $rc"
./onbstudy certify --arith >/dev/null 2>&1; rc=$?
[ $rc -eq 2 ] && ok || bad "--arith without a profile: exit $rc"
./onbstudy list --arith > "$T/list" 2>&1 && ok || bad "list --arith failed"
[ "$(grep -c -e "^vulkan " -e "^d3d11 " "$T/list")" -eq 6 ] && ok || bad "list --arith: $(head -3 "$T/list")"
# 4. binary16 under a profile (certify --precision half --arith): CUDA
#    documents no accuracy for __hdiv, so duff is unbounded by div, named in
#    the row, never a number; a profile without a half row is refused
./onbstudy certify --precision half --arith cuda-fast --methods duff --sectors 1 --depth 1 --azimuths 1 --quiet --out "$T/h" > /dev/null 2>&1 &&
	grep -q '^# arith: cuda-fast ' "$T/h/certify-half.csv" && ok || bad "certify --precision half --arith cuda-fast failed"
data "$T/h/certify-half.csv" | awk -F, 'NR == 1 { ok = $NF == "unbounded_by" } NR > 1 && $12 == "unbounded" { u++; ok = ok && $15 == "div" && $7 == "inf" }
	NR > 1 && $12 == "proven" && $13 > 0 { ok = 0 } END { exit !(ok && u > 0) }' && ok || bad "cuda-fast half: duff not unbounded by div: $(data "$T/h/certify-half.csv" | head -3)"
# naive in binary16 under vulkan: its equator bands (a flushed or
# underflowing squared length) are unbounded, and every such row says why
./onbstudy certify --precision half --arith vulkan --methods naive --sectors 1 --depth 1 --azimuths 1 --quiet --out "$T/hv" > /dev/null 2>&1 &&
	data "$T/hv/certify-half.csv" | awk -F, 'NR > 1 && $12 == "unbounded" { u++; if ($15 == "") e++ } NR > 1 && $12 != "unbounded" && $15 != "" { e++ }
		END { exit !(u > 0 && e == 0) }' && ok || bad "vulkan half: naive's unbounded rows without a cause: $(data "$T/hv/certify-half.csv" | grep unbounded | head -2)"
./onbstudy certify --precision half --arith d3d11 --methods duff --quick --out "$T/bad" > /dev/null 2> "$T/err"; rc=$?
[ $rc -eq 2 ] && grep -q 'gives binary16 no precision' "$T/err" && [ ! -e "$T/bad/certify-half.csv" ] && ok || bad "certify --precision half --arith d3d11: exit $rc, $(cat "$T/err")"
./onbstudy certify --precision half --arith metal --quick > /dev/null 2> "$T/err"; rc=$?
[ $rc -eq 2 ] && grep -q "ieee, vulkan, vulkan-precise, d3d11, opencl, cuda-fast, contract-any" "$T/err" && ok || bad "half, unknown profile: exit $rc"
# docs/gpu.md's table and the README's headline are those results/gpu gives
sh scripts/gpu_table.sh --check > /dev/null 2>&1 && ok || bad "scripts/gpu_table.sh --check: docs/gpu.md or README.md differs from results/gpu"
# the full-budget column: duff's float whole-sphere bound under vulkan from
# results/gpu/full/vulkan (read here apart from gpu_table.sh) is in its row
F=results/gpu/full/vulkan/certify.csv
fb=$(data "$F" | awk -F, '$1 == "duff" && $2 == "float" && $3 == -1 && $4 == 1 && $5 == 0 && $6 == 360 { printf "%.3g", $7 / 2^-24 }')
[ -n "$fb" ] && grep "^| duff | float |" docs/gpu.md | grep -q "full:\*\* $fb / " && ok || bad "docs/gpu.md: no full-budget bound '$fb' in duff's float row"
grep -q "^- \`vulkan\`: \*\*run\*\*" docs/gpu.md && ok || bad "docs/gpu.md: the full vulkan run not listed"
# a full-budget region looser than the --quick region that holds it makes
# gpu_table.sh fail, naming it: duff float's band [-0.3, 0] sector [0, 45]
# made 1e-3 (the quick bound of [0, 180] there is ~1e-6)
mkdir -p "$T/gpu" && cp -r results/gpu/* "$T/gpu/"
GPU_RESULTS="$T/gpu" sh scripts/gpu_table.sh --check > /dev/null 2>&1 && ok || bad "gpu_table.sh --check on a copy of results/gpu failed"
awk -F, -v OFS=, '$1 == "duff" && $2 == "float" && $3 == -0.29999999999999999 && $4 == 0 && $5 == 0 && $6 == 45 { $7 = "0.001" } 1' "$F" > "$T/gpu/full/vulkan/certify.csv"
cmp -s "$F" "$T/gpu/full/vulkan/certify.csv" && bad "the looser-bound mutation changed nothing"
GPU_RESULTS="$T/gpu" sh scripts/gpu_table.sh --check > /dev/null 2> "$T/looser"; rc=$?
[ $rc -eq 1 ] && grep -q "vulkan duff float nz \[-0.29999999999999999, 0\] phi \[0, 45\]: full-budget bound 0.001 looser" "$T/looser" && ok || bad "a looser full-budget bound not caught (exit $rc): $(head -2 "$T/looser")"
finish arith.sh
