#!/bin/sh
# test-times.sh [--out FILE] NAME... - how long single shell tests take in
# this checkout (the figures docs/testing.md quotes): each tests/NAME.sh in
# turn, its wall clock, the CPU seconds of it and its children (the
# shell's `times`) and the load average (/proc/loadavg) before and after;
# on a shared machine the wall clock measures the load as much as the test,
# so both are kept, with the machine.  Build first (`make test-build`, or
# what the tests need); a test that fails stops the run (exit 1).
# Writes FILE (default results/quickstart/test-times.csv) with provenance.
#   sh scripts/test-times.sh mpi certify_mpi gpu charts_committed
set -eu
cd "$(dirname "$0")/.."
out=results/quickstart/test-times.csv
if [ "${1:-}" = --out ]; then out=${2:?usage: test-times.sh [--out FILE] NAME...}; shift 2; fi
[ $# -ge 1 ] || { echo "usage: test-times.sh [--out FILE] NAME..." >&2; exit 2; }
for n in "$@"; do [ -f "tests/$n.sh" ] || { echo "test-times: no tests/$n.sh" >&2; exit 2; }; done
rev=$(git rev-parse --short=12 HEAD)
git diff --quiet HEAD -- src include tests scripts Makefile 2>/dev/null || rev="$rev-dirty"
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
load() { cut -d' ' -f1-3 /proc/loadavg; }
# user + system seconds of the children so far (`times` in this shell)
cpu() { times > "$T/times"; CPU=$(awk 'NR == 2 { s = 0; for (i = 1; i <= 2; i++) { split($i, a, /[ms]/); s += a[1] * 60 + a[2] } printf "%.1f", s }' "$T/times"); }
start=$(date -u +%Y-%m-%dT%H:%MZ)
: > "$T/rows"
for n in "$@"; do
	l0=$(load); cpu; c0=$CPU; t0=$(date +%s.%N)
	sh "tests/$n.sh" > "$T/$n.log" 2>&1 || { tail -20 "$T/$n.log" >&2; echo "test-times: tests/$n.sh failed" >&2; exit 1; }
	t1=$(date +%s.%N); cpu; c1=$CPU; l1=$(load)
	res=$(tail -1 "$T/$n.log" | tr , ";")
	awk -v k="$n" -v r="$res" -v t0="$t0" -v t1="$t1" -v c0="$c0" -v c1="$c1" -v l0="$l0" -v l1="$l1" \
		'BEGIN { printf "%s,%.0f,%.0f,%s,%s,%s\n", k, t1 - t0, c1 - c0, l0, l1, r }' >> "$T/rows"
	echo "test-times: $(tail -1 "$T/rows")" >&2
done
mkdir -p "$(dirname "$out")"
{
	echo "# scripts/test-times.sh $*: each tests/NAME.sh run alone in the checkout, one after the other"
	echo "# revision: $rev"
	echo "# cpu: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores; shared with other jobs: the load average (1, 5, 15 min) before and after each test is in its row"
	echo "# started $start, ended $(date -u +%Y-%m-%dT%H:%MZ)"
	echo "test,wall_seconds,cpu_seconds,load_before,load_after,result"
	cat "$T/rows"
} > "$out.tmp"
mv "$out.tmp" "$out"
cat "$out"
