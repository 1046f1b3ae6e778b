# tests/lib.sh - the harness every shell test sources first:
#	. "$(dirname "$0")/lib.sh"
# It stops on unset variables, moves to the top of the checkout (so paths
# read ./onbstudy, tests/..., build/...), and gives:
#   root           the checkout's absolute path
#   tmp            a fresh temporary directory, removed on exit (a test that
#                  needs more cleanup sets its own EXIT trap, removing $tmp too)
#   ok             count one passed check
#   bad MESSAGE    count one failed check and print "FAIL: MESSAGE"
#   finish [NAME]  print "[NAME: ]P passed, F failed" and exit 0 when no check
#                  failed, 1 otherwise (scripts/robustness.sh counts the
#                  lines without a NAME in the sanitized run's log)
#   skip MESSAGE   print "SKIP: MESSAGE" and exit 0 (a tool is not installed)
#   family_methods [NAME...]  the first method of each family (onbstudy
#                  list) and the NAMEs, comma separated, each once: under SAN
#                  a test's loop over every method can run these alone (each
#                  family's code once under the sanitizer; the C tests run
#                  every method there)
#   mpi_start      the MPI tests' start: skip without Open MPI, `make mpi`,
#                  Open MPI's settings for root (CI), shared memory only and
#                  more ranks than cores, and MPIRUN (mpirun under a hang guard)
# Under `make test SANITIZE=...` the Makefile passes the sanitizer flags in
# $ONB_SANFLAGS; SAN holds them (empty otherwise) for tests that compile.
set -u
cd "$(dirname "$0")/.." || exit 1
root=$(pwd)
SAN=${ONB_SANFLAGS:-}
pass=0; fail=0
ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }
finish() {
	echo "${1:+$1: }$pass passed, $fail failed"
	[ "$fail" -eq 0 ]
	exit
}
skip() { echo "SKIP: $*"; exit 0; }
family_methods() {
	./onbstudy list --format csv | awk -F, -v extra="$*" 'NR > 1 && !seen[$2]++ { pick[$1] = 1; order[++n] = $1 }
		END { k = split(extra, e, " "); for (i = 1; i <= k; i++) if (!(e[i] in pick)) { pick[e[i]] = 1; order[++n] = e[i] }
		      for (i = 1; i <= n; i++) printf "%s%s", (i > 1 ? "," : ""), order[i] }'
}
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

mpi_start() {
	if ! command -v mpirun > /dev/null 2>&1 || ! command -v mpicc > /dev/null 2>&1; then
		skip "no mpirun/mpicc (Open MPI: scripts/install-deps.sh --mpi installs it)"
	fi
	make -s mpi > "$tmp/make.log" 2>&1 || { cat "$tmp/make.log"; echo "FAIL: make mpi"; exit 1; }
	# as root (CI) and without a network: shared memory only
	export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
	export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
	# Under ASan (make test SANITIZE=...), Open MPI's own allocations that it
	# never frees (its component tables, dlopen'd modules) would fail every
	# run at exit: leak detection is off for the MPI runs only; ASan's other
	# checks and UBSan stay on.
	if [ -n "$SAN" ]; then export ASAN_OPTIONS="detect_leaks=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"; fi
	# the timeout is a hang guard, not a speed limit: generous, for loaded machines
	MPIRUN="timeout 600 mpirun --oversubscribe"
}
