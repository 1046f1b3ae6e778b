#!/bin/sh
# test-times.sh [--out FILE] [--jobs J] NAME... - how long tests take in
# this checkout (the figures docs/testing.md quotes).  NAME is a shell test
# (tests/NAME.sh) or a C test (build/tests/NAME, NAME:ARGUMENT for its
# argument).  Without --jobs: each in turn, its wall clock, the CPU seconds
# of it and its children (the shell's `times`) and the load average
# (/proc/loadavg) before and after.  With --jobs J: all of them through
# make test's runner (scripts/test-run.sh), J at a time, each row with its
# own wall and CPU seconds and the whole run's load before and after, and a
# last row "all" with the run's wall clock and CPU seconds.  On a shared
# machine the wall clock measures the load as much as the test, so both are
# kept, with the machine.  Build first (`make test-build`, or what the
# tests need); a test that fails stops the run (exit 1).
# Writes FILE (default results/quickstart/test-times.csv) with provenance.
#   sh scripts/test-times.sh mpi certify_mpi gpu charts_committed
#   sh scripts/test-times.sh --jobs 2 --out /tmp/t.csv test_lib mpi gpu
set -eu
cd "$(dirname "$0")/.."
out=results/quickstart/test-times.csv
jobs=
usage="usage: test-times.sh [--out FILE] [--jobs J] NAME..."
while [ $# -gt 0 ]; do
	case $1 in
	--out) out=${2:?$usage}; shift 2;;
	--jobs) jobs=${2:?$usage}; shift 2
		case $jobs in ''|*[!0-9]*|0) echo "test-times: --jobs takes a positive integer, not '$jobs'" >&2; exit 2;; esac;;
	*) break;;
	esac
done
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
# the runnable of NAME: tests/NAME.sh, or build/tests/NAME[:ARGUMENT]
path() { if [ -f "tests/$1.sh" ]; then echo "tests/$1.sh"; elif [ -x "build/tests/${1%%:*}" ]; then echo "build/tests/$1"; fi; }
for n in "$@"; do [ -n "$(path "$n")" ] || { echo "test-times: no tests/$n.sh and no build/tests/${n%%:*}" >&2; exit 2; }; done
rev=$(git rev-parse --short=12 HEAD)
git diff --quiet HEAD -- src include tests scripts Makefile 2>/dev/null || rev="$rev-dirty"
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
load() { cut -d' ' -f1-3 /proc/loadavg; }
# user + system seconds of the children so far (`times` in this shell)
cpu() { times > "$T/times"; CPU=$(awk 'NR == 2 { s = 0; for (i = 1; i <= 2; i++) { split($i, a, /[ms]/); s += a[1] * 60 + a[2] } printf "%.1f", s }' "$T/times"); }
start=$(date -u +%Y-%m-%dT%H:%MZ)
: > "$T/rows"
if [ -n "$jobs" ]; then
	l0=$(load); cpu; c0=$CPU; t0=$(date +%s.%N)
	sh scripts/test-run.sh "$jobs" "$T/run" $(for n in "$@"; do path "$n"; done) > "$T/run.log" 2>&1 ||
		{ tail -20 "$T/run.log" >&2; echo "test-times: a test failed (the log: $T/run.log, removed on exit)" >&2; exit 1; }
	t1=$(date +%s.%N); cpu; c1=$CPU; l1=$(load)
	i=0
	for n in "$@"; do
		i=$((i + 1))
		res=$(tail -1 "$T/run/$i.log" | tr , ";")
		awk -v k="$n" -v r="$res" -v l0="$l0" -v l1="$l1" '{ printf "%s,%.0f,%.0f,%s,%s,%s\n", k, $1, $2, l0, l1, r }' "$T/run/$i.done" >> "$T/rows"
	done
	awk -v t0="$t0" -v t1="$t1" -v c0="$c0" -v c1="$c1" -v l0="$l0" -v l1="$l1" -v j="$jobs" \
		'BEGIN { printf "all,%.0f,%.0f,%s,%s,the tests above %d at a time (scripts/test-run.sh)\n", t1 - t0, c1 - c0, l0, l1, j }' >> "$T/rows"
	cat "$T/rows" >&2
else
for n in "$@"; do
	l0=$(load); cpu; c0=$CPU; t0=$(date +%s.%N)
	p=$(path "$n")
	case $p in *.sh) sh "$p";; *) ${p%%:*} $(case $p in *:*) echo "${p#*:}";; esac);; esac > "$T/$n.log" 2>&1 ||
		{ tail -20 "$T/$n.log" >&2; echo "test-times: $p failed" >&2; exit 1; }
	t1=$(date +%s.%N); cpu; c1=$CPU; l1=$(load)
	res=$(tail -1 "$T/$n.log" | tr , ";")
	awk -v k="$n" -v r="$res" -v t0="$t0" -v t1="$t1" -v c0="$c0" -v c1="$c1" -v l0="$l0" -v l1="$l1" \
		'BEGIN { printf "%s,%.0f,%.0f,%s,%s,%s\n", k, t1 - t0, c1 - c0, l0, l1, r }' >> "$T/rows"
	echo "test-times: $(tail -1 "$T/rows")" >&2
done
fi
mkdir -p "$(dirname "$out")"
{
	if [ -n "$jobs" ]; then echo "# scripts/test-times.sh --jobs $jobs $*: the tests run $jobs at a time by scripts/test-run.sh (make test's runner)"
	else echo "# scripts/test-times.sh $*: each test run alone in the checkout, one after the other"; fi
	echo "# revision: $rev"
	echo "# cpu: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores; shared with other jobs: the load average (1, 5, 15 min) before and after each test is in its row"
	echo "# started $start, ended $(date -u +%Y-%m-%dT%H:%MZ)"
	echo "test,wall_seconds,cpu_seconds,load_before,load_after,result"
	cat "$T/rows"
} > "$out.tmp"
mv "$out.tmp" "$out"
cat "$out"
