#!/bin/sh
# Install what onbstudy needs on Debian or Ubuntu.  Does nothing when
# everything is present; without root it prints the exact command to run.
set -eu
# clang + libclang-rt-dev: libFuzzer (-fsanitize=fuzzer) for scripts/fuzz.sh.
#   Debian 12's clang (clang-14) only *recommends* the runtime libraries, and
#   we install without recommends, so libclang-rt-dev (-> libclang-rt-14-dev,
#   which holds libclang_rt.fuzzer-x86_64.a) is named explicitly.
# valgrind: memcheck of a short sweep and scene run in .ci/run.
# cppcheck: static analysis of src/lib in .ci/run.
# libcjson-dev: the glTF 2.0 reader parses JSON with cJSON (issue 12).
# libopenmpi-dev, openmpi-bin: `make mpi` builds onbstudy-mpi (issue 13).
PKGS="gcc make libc6-dev libmpfr-dev libgmp-dev gnuplot-nox pkg-config assimp-testmodels clang libclang-rt-dev valgrind cppcheck libomp-dev libcjson-dev libopenmpi-dev openmpi-bin"
PKGS="$PKGS help2man man-db"  # man pages: man/onbstudy.1 from --help (scripts/man.sh), `man` in tests/man_pages.sh (issue 23)
PKGS="$PKGS procps g++"  # pgrep in tests/mpi.sh; g++ for the C++17 check of tests/lib_client.sh (issue 25)
PKGS="$PKGS gcc-aarch64-linux-gnu libc6-dev-arm64-cross gcc-s390x-linux-gnu libc6-dev-s390x-cross qemu-user"  # make cross-check (issue 25)
PKGS="$PKGS pngquant"  # quantizes committed charts to palette PNGs, keeping results/reference/ under 5 MB (issue 24)
PKGS="$PKGS libmpfi-dev"  # certified seed bounds: interval arithmetic (issue 22)
PKGS="$PKGS gappa"  # Gappa cross-check of duff_branchless, scripts/gappa.sh (issue 22)
missing=""
for p in $PKGS; do
	if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
		missing="$missing $p"
	fi
done
if [ -z "$missing" ]; then
	echo "install-deps: all present ($PKGS)"
	exit 0
fi
cmd="apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends$missing"
if [ "$(id -u)" -ne 0 ]; then
	if command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
		exec sudo -n sh -c "$cmd"
	fi
	echo "install-deps: missing:$missing" >&2
	echo "install-deps: run as root:  $cmd" >&2
	exit 1
fi
echo "install-deps: installing:$missing"
apt-get update -q
DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $missing
