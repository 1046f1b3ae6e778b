#!/bin/sh
# lavapipe-report.sh - results/lavapipe/report.md: onbstudy-gpu report
# (the device and driver, how the driver rounds each operation, every
# method of onb.glsl and onb.hlsl against libonb's C kernels with the
# envelope check, the shader engines' own lines) and what this build of
# the driver can say of its compilation: the packages, whether its debug
# dumps (GALLIVM_DEBUG, LP_DEBUG, NIR_DEBUG) exist, and the SPIR-V each
# kernel variant hands it.  lavapipe runs on the CPU: no timings.
#   sh scripts/lavapipe-report.sh [OUT]   (make gpu first; ~1 min)
set -eu
out=${1:-results/lavapipe/report.md}
mkdir -p "$(dirname "$out")"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rc=0
./onbstudy-gpu report --per 20000 --out "$tmp/report.md" || rc=$?
[ -s "$tmp/report.md" ] || { echo "lavapipe-report: onbstudy-gpu report wrote nothing (exit $rc)" >&2; exit 1; }
dumps() { # VAR: does the driver print a list of its values for VAR=help?
	n=$(env "$1=help" ./onbstudy-gpu info 2>&1 | grep -c '^|' || true)
	if [ "$n" -gt 0 ]; then echo "- \`$1=help\`: lists $n values (the variable exists in this build)"
	else echo "- \`$1=help\`: prints nothing (the variable is compiled out of this build)"; fi
}
{
	awk -v l="- made by: sh scripts/lavapipe-report.sh $out (the command line below is its onbstudy-gpu run)" 'NR == 3 { print l } { print }' "$tmp/report.md"
	printf '\n- exit status of onbstudy-gpu report: %s (0: every difference explained, every result inside)\n' "$rc"
	printf '\n### Packages\n\n'
	dpkg-query -W -f '- ${Package} ${Version}\n' mesa-vulkan-drivers libvulkan1 glslang-tools spirv-tools 2>/dev/null || echo "- (dpkg-query unavailable)"
	printf -- '- lavapipe links: %s\n' "$(ldd /usr/lib/*/libvulkan_lvp.so 2>/dev/null | grep -o 'libLLVM[^ ]*' | head -1)"
	printf '\n### What the driver compiles each operation to\n\n'
	echo "Its own dumps of NIR, LLVM IR and machine code need these variables:"
	echo
	for v in GALLIVM_DEBUG LP_DEBUG NIR_DEBUG GALLIVM_PERF; do dumps "$v"; done
	echo
	echo "So the operations table above, which compares every operation with its IEEE (or modelled) result bit for bit, is what this build tells; the SPIR-V each kernel hands the driver (spirv-dis, instructions counted):"
	echo
	echo "| SPIR-V | OpFAdd | OpFSub | OpFMul | OpFDiv | Sqrt | InverseSqrt | Fma | NoContraction |"
	echo "|---|---|---|---|---|---|---|---|---|"
	for s in onb_glsl onb_glsl_precise onb_hlsl onb_hlsl_precise $(cd build/gpu && ls wild/*.spv | sed 's/\.spv$//') ops; do
		spirv-dis "build/gpu/$s.spv" > "$tmp/dis"
		printf '| %s |' "$s.spv"
		for p in '= OpFAdd ' '= OpFSub ' '= OpFMul ' '= OpFDiv ' ' Sqrt ' ' InverseSqrt ' ' Fma ' 'NoContraction'; do
			printf ' %s |' "$(grep -c -- "$p" "$tmp/dis" || true)"
		done
		echo
	done
} > "$out.tmp"
mv "$out.tmp" "$out"
echo "lavapipe-report: wrote $out (onbstudy-gpu report exit $rc)"
