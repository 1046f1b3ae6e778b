#!/bin/sh
# test-run.sh JOBS DIR TEST[:ARGUMENT]... - `make test`'s runner: the tests,
# JOBS at a time (xargs -P), each with its output in DIR/N.log, printed
# whole and in the order given as each one ends, so the log reads as a
# serial run's: "== TEST[ ARGUMENT]", then its output.  A shell test
# (*.sh) runs under sh, a program with its ARGUMENT.  DIR/times.tsv gets
# a row per test: its name, wall seconds, CPU seconds (user + system of
# the test and its children, the shell's `times`).  Exits 1 when any
# test failed.  JOBS 1 is the old serial run; the tests share nothing but
# the built tree (each works in its own mktemp directory, tests/lib.sh),
# so any two can run at once.
#   sh scripts/test-run.sh 2 build/test-logs build/tests/test_lib tests/mpi.sh
set -u
if [ "${1:-}" = --one ]; then
	# one test: --one DIR N SPEC (xargs calls this)
	D=$2; n=$3; spec=$4; t=${spec%%:*}; a=
	[ "$spec" != "$t" ] && a=${spec#*:}
	s=$(date +%s.%N)
	(
		case $t in *.sh) sh "$t";; *) "$t" $a;; esac
		echo $? > "$D/$n.rc"
		times > "$D/$n.cpu"
	) > "$D/$n.log" 2>&1 < /dev/null
	e=$(date +%s.%N)
	awk -v s="$s" -v e="$e" 'NR == 2 { c = 0; for (i = 1; i <= 2; i++) { split($i, a, /[ms]/); c += a[1] * 60 + a[2] } }
		END { printf "%.1f\t%.1f\n", e - s, c }' "$D/$n.cpu" > "$D/$n.t"
	mv "$D/$n.t" "$D/$n.done"
	exit 0
fi
[ $# -ge 2 ] || { echo "usage: test-run.sh JOBS DIR TEST[:ARGUMENT]..." >&2; exit 2; }
jobs=$1; D=$2; shift 2
case $jobs in ''|*[!0-9]*|0) echo "test-run: JOBS must be a positive integer, not '$jobs'" >&2; exit 2;; esac
self=$(cd "$(dirname "$0")" && pwd)/test-run.sh
rm -rf "$D"; mkdir -p "$D"
i=0
for t in "$@"; do i=$((i + 1)); printf '%d %s\n' "$i" "$t"; done > "$D/list"
xargs -P "$jobs" -n 2 sh "$self" --one "$D" < "$D/list" &
xpid=$!
fail=0
: > "$D/times.tsv"
while read -r n spec; do
	while [ ! -f "$D/$n.done" ]; do
		# xargs gone with no result: a test was killed before it wrote one
		kill -0 "$xpid" 2> /dev/null || [ -f "$D/$n.done" ] || { echo "test-run: $spec did not finish"; fail=1; continue 2; }
		sleep 0.2
	done
	t=${spec%%:*}; a=
	[ "$spec" != "$t" ] && a=${spec#*:}
	echo "== $t${a:+ $a}"
	cat "$D/$n.log"
	[ "$(cat "$D/$n.rc" 2> /dev/null)" = 0 ] || fail=1
	printf '%s\t%s\n' "$t" "$(cat "$D/$n.done")" >> "$D/times.tsv"
done < "$D/list"
wait "$xpid"
exit $fail
