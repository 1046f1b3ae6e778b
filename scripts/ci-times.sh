#!/bin/sh
# ci-times.sh - the step times of one `.ci/run` from its log, as the CSV
# that the README quotes (results/quickstart/ci.csv):
#   CI=true sh .ci/run < /dev/null > LOG 2>&1   (in a fresh clone)
#   sh scripts/ci-times.sh LOG REVISION "LOAD BEFORE" "LOAD AFTER" > results/quickstart/ci.csv
# Every step must have passed: a failed run has no times worth quoting.
set -eu
[ $# -eq 4 ] || { echo "usage: ci-times.sh LOG REVISION LOAD_BEFORE LOAD_AFTER" >&2; exit 2; }
LOG=$1
[ -r "$LOG" ] || { echo "ci-times: cannot read $LOG" >&2; exit 2; }
if grep -q 'FAILED' "$LOG" || ! grep -q '^ci: total ' "$LOG"; then
	echo "ci-times: $LOG is not a complete passing run" >&2; exit 1
fi
echo "# scripts/ci-times.sh: the step times of .ci/run (CI=true, no standard input) in a fresh clone"
echo "# revision: $2"
echo "# $(grep -m1 '^ci: Linux' "$LOG" | sed 's/^ci: //' | cut -d' ' -f1,3)"
echo "# cpu: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores"
echo "# compiler: $(sed -n 's/^ci: \(cc .*\)/\1/p' "$LOG" | head -1)"
echo "# load average (1, 5, 15 min) before: $3; after: $4"
echo "key,seconds"
sed -n 's/^ci: make test: \([0-9]*\) s$/make-test,\1/p' "$LOG"
sed -n 's/^harden: \([a-z_-]*\) passed in \([0-9]*\) s$/\1,\2/p' "$LOG"
sed -n 's/^ci: total \([0-9]*\) s$/total,\1/p' "$LOG"
