#!/bin/sh
# Fuzz the OBJ/PLY readers, the glTF reader and the command-line parsers
# with libFuzzer.
#   sh scripts/fuzz.sh [SECONDS]     (default 60)
# Builds tests/fuzz/fuzz_{mesh,gltf,cli}.c and the study sources with
#   clang -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
# into build/fuzz/, then runs the mesh and gltf harnesses at once (one
# process each, one per core) for SECONDS, then the cli harness (which runs
# about 10 times as many inputs per second) for SECONDS/4, each from the
# committed seeds in tests/fuzz/corpus/<harness>/
# (new inputs go to build/fuzz/corpus-<harness>/, never into the repository
# corpus).  A crash, leak, sanitizer report or timeout input is copied into
# tests/fuzz/regressions/<harness>/ (commit it: tests/fuzz_regress.sh replays
# it in `make test` from then on) and the script exits 1.
# Logs, with libFuzzer's final statistics (stat::number_of_executed_units),
# go to build/fuzz/<harness>.log, and one line per harness to
# build/fuzz/summary.tsv; scripts/robustness.sh reads that.
set -eu
cd "$(dirname "$0")/.."
root=$(pwd)
secs=${1:-60}
case "$secs" in ''|*[!0-9]*) echo "fuzz.sh: SECONDS must be a whole number, got '$secs'" >&2; exit 2;; esac
CLANG=${CLANG:-clang}
if ! command -v "$CLANG" >/dev/null 2>&1; then
	echo "fuzz.sh: $CLANG not found; run scripts/install-deps.sh --test (clang, libclang-rt-dev)" >&2
	exit 1
fi
out=build/fuzz
rm -rf "$out/obj" "$out/artifacts" "$out/scratch"
HARNESSES="mesh gltf cli"
for h in $HARNESSES; do mkdir -p "$out/artifacts/$h" "$out/scratch/$h"; done
mkdir -p "$out/obj"
# -fsanitize=fuzzer on the harness only; fuzzer-no-link (coverage) on the rest
SAN="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
CFL="-std=c99 -O1 -g -fopenmp -ffp-contract=off -fno-math-errno -fno-trapping-math -Iinclude -Isrc -D_POSIX_C_SOURCE=200809L -Wno-unknown-pragmas"
objs=""
for src in src/*/*.c; do
	case "$src" in src/cli/main.c|src/mpi/*|src/gpu/*) continue;; esac  # the MPI and Vulkan tools are binaries of their own
	o="$out/obj/$(echo "$src" | tr / _ | sed 's/\.c$/.o/')"
	extra=""
	case "$src" in src/methods/fma_kernels.c) [ "$(uname -m)" = x86_64 ] && extra="-mfma -ffp-contract=fast";; esac
	# shellcheck disable=SC2086
	if [ "$src" = src/families/families.c ]; then # the family list, as the Makefile gives it
		$CLANG $CFL $SAN -fsanitize=fuzzer-no-link "-DSTUDY_FAMILY_LIST(X)=$(sh scripts/family-list.sh)" -c "$src" -o "$o"
	else
		$CLANG $CFL $SAN -fsanitize=fuzzer-no-link $extra -c "$src" -o "$o"
	fi
	objs="$objs $o"
	# a family file's other passes (src/families/family.h, the Makefile)
	case "$src" in src/families/families.c) continue;; src/families/*) ;; *) continue;; esac
	# (pass 1 as fma_kernels.c above, the pair passes as reffast.c)
	for pass in 1 2 3; do
		extra=""; [ $pass -eq 1 ] && { extra="-ffp-contract=fast"; [ "$(uname -m)" = x86_64 ] && extra="-mfma $extra"; }
		# shellcheck disable=SC2086
		$CLANG $CFL $SAN -fsanitize=fuzzer-no-link $extra -DFAMILY_PASS=$pass -c "$src" -o "${o%.o}_$pass.o"
		objs="$objs ${o%.o}_$pass.o"
	done
done
for h in $HARNESSES; do
	# shellcheck disable=SC2086
	$CLANG $CFL $SAN -fsanitize=fuzzer -o "$out/fuzz_$h" "tests/fuzz/fuzz_$h.c" $objs \
		-Wl,-Bstatic -lmpfi -lmpfr -lgmp -Wl,-Bdynamic -lcjson -fopenmp -lm
done
echo "fuzz.sh: built $out/fuzz_mesh, $out/fuzz_gltf and $out/fuzz_cli with $($CLANG --version | head -1)"

run() { # harness seconds
	h=$1
	mkdir -p "$out/corpus-$h"
	# an empty scratch directory as the working directory: the cli harness
	# can reach only names in it (see tests/fuzz/fuzz_cli.c)
	(cd "$out/scratch/$h" && "$root/$out/fuzz_$h" -max_total_time="$2" -timeout=10 -rss_limit_mb=2048 \
		-max_len=65536 -close_fd_mask=3 -print_final_stats=1 -artifact_prefix="$root/$out/artifacts/$h/" \
		"$root/$out/corpus-$h" "$root/tests/fuzz/corpus/$h") > "$out/$h.log" 2>&1
}
csecs=$(( (secs + 3) / 4 ))
run mesh "$secs" & pm=$!
run gltf "$secs" & pg=$!
rm_=0; wait $pm || rm_=$?
rg_=0; wait $pg || rg_=$?
rc_=0; run cli "$csecs" || rc_=$?
fail=0
printf 'harness\tseconds\texecutions\texit\tcrash_inputs\tcoverage\tcorpus\n' > "$out/summary.tsv"
for h in $HARNESSES; do
	case $h in mesh) st=$rm_; hs=$secs;; gltf) st=$rg_; hs=$secs;; *) st=$rc_; hs=$csecs;; esac
	execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/$h.log" | tail -1)
	found=0
	for a in "$out/artifacts/$h"/*; do
		[ -f "$a" ] || continue
		found=$((found + 1))
		cp "$a" "tests/fuzz/regressions/$h/"
		echo "fuzz.sh: $h: kept $(basename "$a") in tests/fuzz/regressions/$h/" >&2
	done
	cov=$(sed -n 's/.*DONE *cov: \([0-9]*\).*/\1/p' "$out/$h.log" | tail -1)
	corp=$(sed -n 's/.*DONE .* corp: \([0-9]*\)\/.*/\1/p' "$out/$h.log" | tail -1)
	printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$h" "$hs" "${execs:-?}" "$st" "$found" "${cov:-?}" "${corp:-?}" >> "$out/summary.tsv"
	echo "fuzz.sh: $h: ${execs:-?} executions in ${hs} s, exit $st, $found crash input(s), coverage ${cov:-?} edges, corpus ${corp:-?}"
	if [ "$st" -ne 0 ] || [ "$found" -ne 0 ] || [ -z "$execs" ]; then
		fail=1
		echo "fuzz.sh: $h FAILED; the end of $out/$h.log:" >&2
		tail -40 "$out/$h.log" >&2
	fi
done
[ -z "$(ls -A "$out/scratch/cli")" ] || { echo "fuzz.sh: the cli harness wrote files: $(ls -A "$out/scratch/cli")" >&2; fail=1; }
exit $fail
