#!/bin/sh
# quickstart-times.sh [OUT] - how long the README's quick-start commands
# take, from a fresh clone of this checkout's HEAD in a temporary directory
# (nothing built there yet), one after the other:
#   make                          the study's build (install-deps.sh finds
#                                 its packages present: downloads not timed;
#                                 the README gives their sizes)
#   ./onbstudy sweep              the full default study
#   make test                     every test (docs/testing.md)
#   ./onbstudy certify --quick    the proven extremes' quick run (docs/certify.md)
#   ./onbstudy bench --quick, ./onbstudy bench   the speed runs (docs/bench.md)
# Each gets its wall-clock time, the CPU seconds of it and its children (the
# shell's `times`), and the load average (/proc/loadavg) before and after: on
# a shared machine the wall clock measures the load as much as the code, so
# the README quotes both, with the machine.  Writes OUT (default
# results/quickstart/times.csv) with provenance, and make test's seconds
# per test beside it (test-times.csv); README.md, docs/bench.md and
# docs/certify.md quote it (scripts/quotes.in, scripts/findings.sh --quotes).
# Takes what the commands take: about 20 minutes on 2 idle cores.
#   [STEPS="make sweep ..."] sh scripts/quickstart-times.sh [OUT]
set -eu
cd "$(dirname "$0")/.."
out=${1:-results/quickstart/times.csv}
rev=$(git rev-parse --short=12 HEAD)
dirty=$(git diff --quiet HEAD -- . ':(exclude)results' 2>/dev/null || echo " (the working tree differs from HEAD; the clone is HEAD)")
T=$(mktemp -d /tmp/onb-quickstart.XXXXXX)
trap 'rm -rf "$T"' EXIT
trap 'exit 1' INT TERM
git clone -q --shared . "$T/onb"
git -C "$T/onb" checkout -q "$rev"
load() { cut -d' ' -f1-3 /proc/loadavg; }
# cpu: user + system seconds of the children so far (the second line of `times`)
# (`times` runs in this shell, not in a command substitution, whose fork
# would start its own count at 0)
cpu() { times > "$T/times"; CPU=$(awk 'NR == 2 { s = 0; for (i = 1; i <= 2; i++) { split($i, a, /[ms]/); s += a[1] * 60 + a[2] } printf "%.1f", s }' "$T/times"); }
now() { date +%s.%N; }
# step KEY COMMAND: run COMMAND in the clone, append its row
step() {
	l0=$(load); cpu; c0=$CPU; t0=$(now)
	(cd "$T/onb" && sh -c "$2") > "$T/$1.log" 2>&1 || { tail -20 "$T/$1.log" >&2; echo "quickstart-times: '$2' failed" >&2; exit 1; }
	t1=$(now); cpu; c1=$CPU; l1=$(load)
	awk -v k="$1" -v c="$2" -v t0="$t0" -v t1="$t1" -v c0="$c0" -v c1="$c1" -v l0="$l0" -v l1="$l1" 'BEGIN {
		w = t1 - t0; u = c1 - c0
		printf "%s,%s,%.0f,%.1f,%.0f,%.1f,%s,%s\n", k, c, w, w / 60, u, u / 60, l0, l1 }' >> "$T/rows"
	echo "quickstart-times: $2: $(tail -1 "$T/rows")" >&2
}
: > "$T/rows"
start=$(date -u +%Y-%m-%dT%H:%MZ)
# write OUT with what has run so far (a run cut short keeps its rows)
write() {
	mkdir -p "$(dirname "$out")"
	{
		echo "# scripts/quickstart-times.sh: the README's quick-start commands in a fresh clone, one after the other (STEPS: $STEPS)"
		echo "# revision: $rev$dirty"
		echo "# compiler: $(${CC:-cc} --version | head -1)"
		echo "# cpu: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores, $(awk '/MemTotal/ { printf "%.0f GB", $2 / 1048576 }' /proc/meminfo) RAM"
		echo "# started $start, last row $(date -u +%Y-%m-%dT%H:%MZ); the load average (1, 5, 15 min) before and after each command is in its row"
		echo "# the packages were installed before (downloads not timed); ./onbstudy sweep ran with --out into the temporary directory"
		[ ! -f "$T/sweep.log" ] || echo "# $(grep '^onbstudy: .* referenced evaluations in' "$T/sweep.log" | head -1)"
		echo "key,command,wall_seconds,wall_minutes,cpu_seconds,cpu_minutes,load_before,load_after"
		cat "$T/rows"
	} > "$out.tmp"
	mv "$out.tmp" "$out"
}
# STEPS: which commands, in this order (default all; make comes first
# whenever another step needs the build)
STEPS=${STEPS:-make sweep make-test certify-quick bench-quick bench}
for s in $STEPS; do
	case $s in
	make) step make "make" ;;
	sweep) step sweep "./onbstudy sweep --out $T/run" ;;
	make-test) step make-test "make test"
		grep -q '^make test: all passed' "$T/make-test.log" || { echo "quickstart-times: make test did not pass" >&2; exit 1; } ;;
	certify-quick) step certify-quick "./onbstudy certify --quick --out $T/cert" ;;
	bench-quick) step bench-quick "./onbstudy bench --quick --out $T/benchq" ;;
	bench) step bench "./onbstudy bench --out $T/bench" ;;
	*) echo "quickstart-times: unknown step '$s'" >&2; exit 2 ;;
	esac
	write
done
# make test's own seconds per test (build/test-times.tsv), e.g. tests/mpi.sh's
if [ -f "$T/onb/build/test-times.tsv" ]; then
	{
		echo "# make test's seconds per test in the same run (its build/test-times.tsv); revision $rev; load in times.csv"
		echo "test,seconds"
		tr '\t' , < "$T/onb/build/test-times.tsv"
	} > "$(dirname "$out")/test-times.csv"
fi
cat "$out"
