#!/bin/sh
# fastref.sh [DIR] - the fast reference's speed figures, each
# from a run of the project's own commands, into DIR (default
# results/fastref):
#   bench-reference.csv          ./onbstudy bench --reference (one core, both
#                                paths alternating, median of 7)
#   default-sweep.txt            the default sweep with --ref fast, then with
#                                --ref mpfr: wall times, rate lines, and whether
#                                the data lines of every CSV are identical
#   default-sweep-reference.csv  the fast run's reference.csv (fallbacks per
#                                method and precision)
#   pole-subset.txt              every float n.z in [-1, -0.999] at 64 azimuths
#                                (the 64-azimuth pole run's first hundredth),
#                                both paths, times and identity
# Run it on a quiet machine: every line records the load average.  Takes
# about 3 minutes on 2 cores.
set -eu
DIR=${1:-results/fastref}
B=./onbstudy
[ -x "$B" ] || { echo "fastref: build ./onbstudy first (make)" >&2; exit 2; }
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
mkdir -p "$DIR"
now() { date -u +%Y-%m-%dT%H:%M:%SZ; }
load() { cut -d' ' -f1-3 /proc/loadavg; }
secs() { date +%s.%N; }
rev=$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)

# 1. referenced evaluations per second per core
$B bench --reference --out "$W/bench" > "$W/bench.txt"
cp "$W/bench/bench-reference.csv" "$DIR/bench-reference.csv"

# one run of each path, one after the other: $1 label, $2 out file, rest: sweep options
both() {
	label=$1; out=$2; shift 2
	{
		echo "# the fast reference against MPFR: $label, --ref fast then --ref mpfr, one after the other (scripts/fastref.sh)"
		echo "# revision: $rev; cpu: $cpu; $(nproc) cores"
		echo "# command: $B sweep $* --ref R --quiet --out DIR"
		for r in fast mpfr; do
			echo "# $r start $(now) load $(load)"
			t0=$(secs)
			$B sweep "$@" --ref $r --quiet --out "$W/$r" > /dev/null 2> "$W/$r.log"
			t1=$(secs)
			echo "# $r end $(now) load $(load)"
			grep 'referenced evaluations in' "$W/$r.log" | sed 's/^/# /'
			echo "$r,$(echo "$t1 $t0" | awk '{ printf "%.2f", $1 - $2 }')"
		done | awk '/^#/ { print; next } { rows = rows $0 "\n" } END { printf "path,wall_seconds\n%s", rows }'
		for f in summary.csv by_nz.csv worst.csv grid.csv reference.csv; do
			[ -f "$W/fast/$f" ] && [ -f "$W/mpfr/$f" ] || continue
			grep -v '^#' "$W/fast/$f" > "$W/a"; grep -v '^#' "$W/mpfr/$f" > "$W/b"
			if cmp -s "$W/a" "$W/b"; then echo "# $f: data identical"; else echo "# $f: DATA DIFFER"; fi
		done
	} > "$out.tmp"
	mv "$out.tmp" "$out"
}

# 2. the default sweep
both "the default sweep (2 threads)" "$DIR/default-sweep.txt"
cp "$W/fast/reference.csv" "$DIR/default-sweep-reference.csv"

# 3. the pole run's first hundredth
both "every float n.z in [-1, -0.999], 64 azimuths, every float method (the first hundredth of results/poles/south)" \
	"$DIR/pole-subset.txt" --dists exhaustive --precision float --exhaustive-range -1:-0.999 --azimuths 64 --threads 2

if grep -q 'DATA DIFFER' "$DIR/default-sweep.txt" "$DIR/pole-subset.txt"; then
	echo "fastref: the two paths' data differ (see $DIR)" >&2
	exit 1
fi
cat "$W/bench.txt"
echo "fastref: wrote $DIR/bench-reference.csv, default-sweep.txt, default-sweep-reference.csv, pole-subset.txt"
