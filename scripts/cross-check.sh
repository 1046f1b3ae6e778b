#!/bin/sh
# make cross-check: libonb and the mesh readers on arm64
# (aarch64) and big-endian s390x, cross-compiled and run under qemu-user.
#   sh scripts/cross-check.sh [OUTDIR] [N]   (default build/cross-check, 1048576)
# For each target:
#   1. libonb.a from src/lib (every file, the library's flags, -Werror);
#   2. tests/test_lib.c and tests/test_indep.c against it, and
#      tests/test_meshio.c with the mesh readers, run under qemu;
#   3. tests/cross/onbhash: every method, both precisions, scalar and batch
#      paths, on N inputs (the six axes, -0 components and near-pole
#      vectors among them), one hash per line (every NaN hashed as one
#      pattern: its sign and payload differ by CPU) and the count of NaN
#      outputs; compared with the same program on this x86-64 host.  Every
#      line must match, NaN counts included, except the
#      hardware-rsqrt methods (ONB_HW_RSQRT): x86-64 runs rsqrtss, the
#      other targets the 1/sqrt fallback (ONB_HAVE_HW_RSQRT 0), and the
#      table shows each one's max defect on both;
#   4. tests/cross/meshhash on binary PLY in both byte orders (written
#      here), tests/data/gltf (.gltf and .glb) and assimp's cube_binary.ply
#      when installed: the same lines as on this host.
# Needs (scripts/install-deps.sh --test): gcc-aarch64-linux-gnu,
# gcc-s390x-linux-gnu, their libc6-dev-*-cross, qemu-user; and cJSON for
# each target, which Debian ships only per architecture:
#   dpkg --add-architecture arm64 && dpkg --add-architecture s390x &&
#   apt-get update && apt-get install libcjson-dev:arm64 libcjson-dev:s390x
# qemu-s390x 7.2 (Debian 12) aborts every dynamically linked s390x program
# at start-up ("stack smashing detected", even a hello world), so the s390x
# programs are linked -static, and cJSON (Debian ships no libcjson.a) is
# compiled into them from Debian's own source of the installed version:
#   apt-get source cjson   (needs a deb-src line), unpacked into
#   CJSON_SRC (default build/cjson-src, the directory holding cJSON.c).
# s390x: GCC there evaluates float expressions in double in ISO C mode
# (FLT_EVAL_METHOD 1), so every s390x program is built with
# -fexcess-precision=fast (binary32 float arithmetic, FLT_EVAL_METHOD 0);
# onb.h refuses to compile the library without it, which step 1 checks.
# The tests run test_indep --quick when N < 1048576 (the full 10^6 inputs
# take about 9 minutes under qemu on a loaded 2-core machine).
# Writes OUTDIR/{x86_64,aarch64,s390x}.{hash,mesh,log} and OUTDIR/summary.txt.
set -u
cd "$(dirname "$0")/.."
out=${1:-build/cross-check}
n=${2:-1048576}
mkdir -p "$out"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
LIBF="-std=c99 -O3 -ffp-contract=off -fno-math-errno -fno-trapping-math"
W="-Wall -Wextra -Wpedantic -Wshadow"
fail=0
for t in aarch64 s390x; do
	for tool in $t-linux-gnu-gcc $t-linux-gnu-ar qemu-$t; do
		command -v $tool >/dev/null 2>&1 || { echo "cross-check: $tool not installed (scripts/install-deps.sh --test)" >&2; exit 1; }
	done
	[ -e /usr/lib/$t-linux-gnu/libcjson.so ] || { echo "cross-check: no cJSON for $t (see the comment at the top of $0)" >&2; exit 1; }
done
cjson_src=${CJSON_SRC:-build/cjson-src}
[ -f "$cjson_src/cJSON.c" ] || { echo "cross-check: no $cjson_src/cJSON.c for the static s390x build (see the comment at the top of $0)" >&2; exit 1; }
ply="$tmp/ply"; mkdir -p "$ply"
meshfiles() { echo "$ply"/*.ply tests/data/gltf/*.gltf tests/data/gltf/*.glb $(ls /usr/share/assimp/models/PLY/cube_binary.ply 2>/dev/null); }

# tflags ARCH: the target's own flags on top of LIBF
tflags() { [ "$1" = s390x ] && echo "-fexcess-precision=fast"; }

# build ARCH CC AR: everything for one machine into $tmp/ARCH
build() {
	a=$1; cc=$2; ar=$3; d="$tmp/$a"; mkdir -p "$d/lib"
	cj=-lcjson
	if [ "$a" = s390x ]; then
		cc="$cc -static"
		$cc -std=c99 -O2 -c "$cjson_src/cJSON.c" -o "$d/cJSON.o" || return 1
		cj="$d/cJSON.o"
		if $cc $LIBF -Iinclude -c src/lib/registry.c -o "$d/refused.o" 2>/dev/null; then
			echo "$a: the library compiled without -fexcess-precision=fast (onb.h's FLT_EVAL_METHOD guard did not fire)"
			return 1
		fi
	fi
	lf="$LIBF $(tflags "$a")"
	for f in src/lib/*.c; do
		$cc $lf $W -Wconversion -Werror -Iinclude -c "$f" -o "$d/lib/$(basename "$f" .c).o" || return 1
	done
	$ar rcs "$d/libonb.a" "$d"/lib/*.o || return 1
	for p in test_lib test_indep; do
		$cc $lf $W -Iinclude -Itests -o "$d/$p" tests/$p.c "$d/libonb.a" -lm || return 1
	done
	$cc $lf $W -D_POSIX_C_SOURCE=200809L -Iinclude -Isrc -o "$d/test_meshio" tests/test_meshio.c \
		src/mesh/*.c $cj -lm || return 1
	$cc $lf $W -Iinclude -Itests/cross -o "$d/onbhash" tests/cross/onbhash.c "$d/libonb.a" -lm || return 1
	$cc $lf $W -D_POSIX_C_SOURCE=200809L -Isrc -Itests/cross -o "$d/meshhash" tests/cross/meshhash.c \
		src/mesh/*.c $cj -lm || return 1
}

# hashes ARCH RUNNER...: the two hash programs
hashes() {
	a=$1; shift; d="$tmp/$a"; log="$out/$a.log"
	: > "$log"
	"$@" "$d/onbhash" "$n" > "$out/$a.hash" 2>> "$log" || { echo "$a: onbhash FAILED"; echo $a >> "$tmp/failed"; }
	"$@" "$d/meshhash" $(meshfiles) > "$out/$a.mesh" 2>> "$log" || { echo "$a: meshhash FAILED"; echo $a >> "$tmp/failed"; }
}
# tests ARCH RUNNER...: the three test programs, slowest last (test_lib
# measures in long double, which both targets emulate in software: 128-bit)
tests() {
	a=$1; shift; d="$tmp/$a"; log="$out/$a.tests.log"
	: > "$log"
	for p in test_meshio test_indep test_lib; do
		s=$(date +%s); q=
		[ "$p" = test_indep ] && [ "$n" -lt 1048576 ] && q=--quick
		if "$@" "$d/$p" $q >> "$log" 2>&1; then echo "$a: $p${q:+ $q} passed ($(( $(date +%s) - s )) s under qemu)"
		else echo "$a: $p FAILED (see $log)"; echo $a >> "$tmp/failed"; fi
	done
}

build x86_64 cc ar || { echo "cross-check: native build failed" >&2; exit 1; }
"$tmp/x86_64/meshhash" --write "$ply" || exit 1
hashes x86_64
# The two targets run at the same time (qemu is single-threaded), each
# writing its own files; a failure leaves a line in $tmp/failed.
for t in aarch64 s390x; do
	(
		if ! build $t $t-linux-gnu-gcc $t-linux-gnu-ar; then echo "$t: build FAILED"; echo $t >> "$tmp/failed"; exit 1; fi
		hashes $t env QEMU_LD_PREFIX=/usr/$t-linux-gnu qemu-$t
	) &
done
wait
[ -s "$tmp/failed" ] && fail=1

# compare with x86-64
{
	echo "# scripts/cross-check.sh $out $n at $(git rev-parse --short=12 HEAD)$(git diff --quiet HEAD -- include src/lib src/mesh tests/cross tests/test_meshio.c tests/test_lib.c tests/test_indep.c scripts/cross-check.sh || echo -dirty), $(date -u +%Y-%m-%dT%H:%MZ)"
	echo "# host: $(uname -m), $(cc --version | head -1); targets: $(aarch64-linux-gnu-gcc --version | head -1), $(s390x-linux-gnu-gcc --version | head -1); $(qemu-aarch64 --version | head -1)"
	echo "# library flags: $LIBF, s390x adds $(tflags s390x) (FLT_EVAL_METHOD 1 in ISO C mode otherwise; onb.h refuses it); s390x linked -static with cJSON $(sed -n 's/^#define CJSON_VERSION_\(MAJOR\|MINOR\|PATCH\) //p' "$cjson_src/cJSON.h" | tr '\n' . | sed 's/\.$//') from $cjson_src (qemu-s390x 7.2 cannot start dynamic s390x programs)"
	for t in aarch64 s390x; do
		[ -s "$out/$t.hash" ] || { echo "$t: no hashes"; fail=1; continue; }
		[ "$t" = s390x ] && echo "s390x: the library without $(tflags s390x) was refused at compile time (onb.h's FLT_EVAL_METHOD guard, checked before the build)"
		same=0; rs=0; other=0; nanl=
		while read -r m p hs hb nn md; do
			case "$m" in \#*) continue;; esac
			x=$(awk -v m="$m" -v p="$p" '$1 == m && $2 == p' "$out/x86_64.hash")
			xs=$(echo "$x" | awk '{print $3}'); xb=$(echo "$x" | awk '{print $4}'); xn=$(echo "$x" | awk '{print $5}'); xd=$(echo "$x" | awk '{print $6}')
			if [ "$hs" != "$hb" ]; then echo "$t: $m $p: scalar and batch differ"; other=$((other + 1)); fi
			if [ "$nn" != "$xn" ]; then echo "$t: $m $p: NaN outputs (scalar/batch) $nn here, $xn on x86-64"; other=$((other + 1)); fi
			case "$nn" in 0/0) ;; *) nanl="$nanl $m/$p:$nn";; esac
			if [ "$hs" = "$xs" ] && [ "$hb" = "$xb" ]; then same=$((same + 1))
			elif [ "$md" != "-" ]; then rs=$((rs + 1)); echo "$t: $m $p differs from x86-64 (hardware rsqrt there): max defect $md here, $xd on x86-64"
			else other=$((other + 1)); echo "$t: $m $p DIFFERS from x86-64"; fi
		done < "$out/$t.hash"
		echo "$t: $same method/precision lines bit-identical to x86-64 (scalar and batch, $n inputs each), $rs hardware-rsqrt lines differ as expected, $other other differences"
		echo "$t: lines with NaN outputs (method/precision:scalar/batch count of $((6 * n)) each):$nanl"
		[ "$other" -eq 0 ] || fail=1
		if cmp -s "$out/x86_64.mesh" "$out/$t.mesh"; then echo "$t: mesh reads identical to x86-64 ($(wc -l < "$out/$t.mesh") files)"
		else echo "$t: mesh reads DIFFER from x86-64"; diff "$out/x86_64.mesh" "$out/$t.mesh"; fail=1; fi
	done
	[ "$fail" -eq 0 ] && echo "bit identity and mesh reads: passed" || echo "bit identity and mesh reads: FAILED"
} | tee "$out/summary.txt"
# Then the tests, both targets at once, each line appended as it ends.
for t in aarch64 s390x; do
	[ -x "$tmp/$t/test_lib" ] && tests $t env QEMU_LD_PREFIX=/usr/$t-linux-gnu qemu-$t | tee -a "$out/summary.txt" &
done
wait
if grep -q 'FAILED' "$out/summary.txt"; then echo "cross-check: FAILED" | tee -a "$out/summary.txt"; exit 1; fi
echo "cross-check: passed" | tee -a "$out/summary.txt"
