#!/bin/sh
# Install what onbstudy needs on Debian or Ubuntu.  Does nothing when
# everything is present; without root it prints the exact command to run.
#   sh scripts/install-deps.sh          the study: `make && ./onbstudy sweep`
#   sh scripts/install-deps.sh --plots  and the charts: `make plots`, `make render`
#   sh scripts/install-deps.sh --mpi    and Open MPI: `make mpi`
#   sh scripts/install-deps.sh --test   and everything `make test` and CI use
# `make`, `make plots`, `make mpi` and `make test` run it with these options.  From a
# Debian 12 minbase root with gcc, make and git (apt-get install
# --assume-no): the study 18 packages (6.2 MB download, 26 MB on disk),
# --plots 55 more (20 MB, 68 MB), --test 204 more than the study's (273 MB,
# 1.2 GB).  The library alone (`make lib`) needs none: gcc, make, libc6-dev.
set -eu
# The study: the compiler, MPFR/GMP/MPFI (the reference and certify, linked
# statically), cJSON (the glTF reader).  OpenMP comes with gcc.
PKGS="gcc make libc6-dev libmpfr-dev libgmp-dev libmpfi-dev libcjson-dev"
# Charts: gnuplot; pngquant quantizes committed charts to palette PNGs,
# keeping results/reference/ under 5 MB.
PLOTS="gnuplot-nox pngquant"
# MPI: Open MPI's mpicc and mpirun, for onbstudy-mpi (`make mpi`).
MPI="libopenmpi-dev openmpi-bin"
# make test and CI:
# clang + libclang-rt-dev: libFuzzer (-fsanitize=fuzzer) for scripts/fuzz.sh.
#   Debian 12's clang (clang-14) only *recommends* the runtime libraries, and
#   we install without recommends, so libclang-rt-dev (-> libclang-rt-14-dev,
#   which holds libclang_rt.fuzzer-x86_64.a) is named explicitly.
# valgrind: memcheck of a short sweep and scene run in .ci/run.
# cppcheck: static analysis of src/lib in .ci/run.
# $MPI: `make mpi` builds onbstudy-mpi (tests/mpi.sh).
# pkg-config: tests/lib_contract.sh builds a client with onb.pc's flags.
# assimp-testmodels: real-world meshes for the scene readers' tests.
TEST="$PLOTS pkg-config assimp-testmodels clang libclang-rt-dev valgrind cppcheck libomp-dev $MPI"
TEST="$TEST help2man man-db"  # man pages: man/onbstudy.1 from --help (scripts/man.sh), `man` in tests/man_pages.sh
TEST="$TEST procps g++"  # pgrep in tests/mpi.sh; g++ for the C++17 check of tests/lib_client.sh
TEST="$TEST gcc-aarch64-linux-gnu libc6-dev-arm64-cross gcc-s390x-linux-gnu libc6-dev-s390x-cross qemu-user"  # make cross-check
TEST="$TEST gappa"  # Gappa cross-check of duff_branchless, scripts/gappa.sh
# Shaders: lavapipe (a conforming Vulkan 1.3 device on the CPU), the Vulkan
# loader and headers, GLSL/HLSL to SPIR-V (glslang) and spirv-tools.
TEST="$TEST mesa-vulkan-drivers libvulkan-dev glslang-tools spirv-tools"
case "${1:-}" in
"") ;;
--plots) PKGS="$PKGS $PLOTS" ;;
--mpi) PKGS="$PKGS $MPI" ;;
--test) PKGS="$PKGS $TEST" ;;
*) echo "usage: sh scripts/install-deps.sh [--plots | --mpi | --test]" >&2; exit 2 ;;
esac
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
