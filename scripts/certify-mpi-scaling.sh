#!/bin/sh
# certify-mpi-scaling.sh [OUTDIR] - the measured scaling of `onbstudy-mpi
# certify`: one run (OPTS below) on 1, 2 and 4 ranks x 1 thread each (4
# ranks oversubscribe a 2-core machine: said in the file), REPEATS rounds
# that each run every rank count once in turn (so a change of load
# touches all of them); the median wall seconds per rank count, the
# speed-up over 1 rank and the efficiency (speed-up / ranks), the CPU
# seconds of all ranks, the regions each rank computed, and the load
# average before and after every run.  Every run's certify.csv rows are
# checked identical to the first's.  Writes OUTDIR/scaling.csv (default
# results/certify/mpi) with provenance, and prints it.
# Needs `make mpi` (Open MPI).  As root it passes --allow-run-as-root.
set -eu
cd "$(dirname "$0")/.."
OUT=${1:-results/certify/mpi}
OPTS=${OPTS:---quiet --precision float --methods frisvad,rtow,open3d_fixed --budget 400 --samples 300 --sectors 4}
REPEATS=${REPEATS:-3}
RANKS=${RANKS:-1 2 4}
[ -x ./onbstudy-mpi ] || { echo "certify-mpi-scaling.sh: no ./onbstudy-mpi (make mpi)" >&2; exit 2; }
ROOT=""
[ "$(id -u)" = 0 ] && ROOT=--allow-run-as-root
REV=$(git describe --always --dirty 2> /dev/null || echo unknown)   # before the runs: the code they ran
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$OUT"
: > "$tmp/runs"
r=1
while [ $r -le "$REPEATS" ]; do
	for n in $RANKS; do
		l0=$(cut -d' ' -f1 /proc/loadavg)
		mpirun $ROOT --oversubscribe -n "$n" -x OMP_NUM_THREADS=1 ./onbstudy-mpi certify $OPTS --out "$tmp/n$n-$r" \
			> /dev/null 2> "$tmp/err"
		l1=$(cut -d' ' -f1 /proc/loadavg)
		line=$(grep '^onbstudy-mpi: certify on' "$tmp/err") || { cat "$tmp/err" >&2; exit 1; }
		grep -v '^#' "$tmp/n$n-$r/certify.csv" > "$tmp/rows"
		[ -f "$tmp/rows1" ] || cp "$tmp/rows" "$tmp/rows1"
		cmp -s "$tmp/rows" "$tmp/rows1" || { echo "certify-mpi-scaling.sh: $n ranks, round $r: other rows" >&2; exit 1; }
		# "... N ranks x 1 threads: W s wall, C CPU seconds in all ranks; regions ...: a b c"
		echo "$line" | awk -v n="$n" -v r="$r" -v l0="$l0" -v l1="$l1" '{
			for (i = 1; i <= NF; i++) { if ($i == "wall,") w = $(i - 2); if ($i == "CPU") c = $(i - 1) }
			split($0, a, "pass\\): "); gsub(/ /, "/", a[2])
			print n "," r "," w "," c "," a[2] "," l0 "," l1 }' >> "$tmp/runs"
		rm -rf "$tmp/n$n-$r"
	done
	r=$((r + 1))
done
{
	echo "# onbstudy-mpi certify scaling (scripts/certify-mpi-scaling.sh)"
	echo "# revision: $REV"
	echo "# date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
	echo "# machine: $(nproc) cores, $(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -1); $(mpirun --version 2>&1 | head -1)"
	echo "# command: mpirun --oversubscribe -n N -x OMP_NUM_THREADS=1 ./onbstudy-mpi certify $OPTS"
	echo "# 1 thread per rank; ranks above $(nproc) oversubscribe the cores (ideal speed-up: $(nproc)x at most)"
	echo "# rows: every run (round r runs every rank count once); load1_before/after: /proc/loadavg's 1-minute figure"
	echo "ranks,round,wall_s,cpu_s_all_ranks,regions_per_rank,load1_before,load1_after"
	cat "$tmp/runs"
	echo "# medians over the rounds: ranks,median_wall_s,speedup,efficiency,median_cpu_s"
	for n in $RANKS; do
		w=$(awk -F, -v n="$n" '$1 == n { print $3 }' "$tmp/runs" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
		c=$(awk -F, -v n="$n" '$1 == n { print $4 }' "$tmp/runs" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
		[ "$n" = "$(echo $RANKS | cut -d' ' -f1)" ] && w1=$w
		awk -v n="$n" -v w="$w" -v w1="$w1" -v c="$c" 'BEGIN { printf "# median,%d,%.2f,%.2f,%.2f,%.2f\n", n, w, w1 / w, w1 / w / n, c }'
	done
} > "$OUT/scaling.csv"
cat "$OUT/scaling.csv"
