#!/bin/sh
# mpi-scaling.sh - the MPI driver's scaling figures, written to
# results/mpi-scaling/ with provenance:
#   scaling.csv     strong scaling of one exhaustive float sweep (every
#                   method, 16 azimuths) on 1 and 2 ranks x 1 thread,
#                   REPEATS runs each, alternating; the median times and
#                   their ratio;
#   projection.csv  the full domain - every float n.z in [-1, 1] x 16
#                   azimuths x every method that runs in float - as counted
#                   by `onbstudy sweep --dry-run`, and its wall time on 1, 64
#                   and 1024 cores from the measured 1-rank per-core rate
#                   (ideal scaling; the measured 2-rank efficiency beside it);
#   domain.csv      that count alone (methods, n.z values, azimuths,
#                   evaluations), which docs/sweep.md quotes;
#   load.csv        the load average before and after the timed runs.
# About a minute on 2 cores.  The rate is only as good as the machine is
# quiet: the load average is recorded.
#   sh scripts/mpi-scaling.sh [COUNT] [REPEATS]   (default 4096 n.z values, 3)
set -eu
cd "$(dirname "$0")/.."
COUNT=${1:-4096}
REPEATS=${2:-3}
OUT=results/mpi-scaling
command -v mpirun > /dev/null || { echo "mpi-scaling: no mpirun (scripts/install-deps.sh --mpi installs Open MPI)" >&2; exit 1; }
make -s all mpi
mkdir -p "$OUT"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
export OMPI_MCA_rmaps_base_oversubscribe=1
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
ARGS="--dists exhaustive --precision float --exhaustive-count $COUNT --azimuths 16 --threads 1 --quiet --format csv"

# run N I: one run on N ranks; prints "seconds evaluations cpu_seconds" (the
# driver's own timing of the sweep, without MPI start-up and file writing;
# CPU seconds summed over the ranks)
run() {
	mpirun --oversubscribe -n "$1" ./onbstudy-mpi sweep $ARGS --out "$TMP/r$1-$2" > /dev/null 2> "$TMP/e$1-$2"
	sed -n 's/^onbstudy-mpi: \([0-9]*\) referenced evaluations in \([0-9.]*\) s.* \([0-9.]*\) CPU seconds.*/\2 \1 \3/p' "$TMP/e$1-$2"
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

LOAD0=$(cut -d' ' -f1-3 /proc/loadavg)
: > "$TMP/t1"; : > "$TMP/t2"
i=1
while [ $i -le "$REPEATS" ]; do
	run 1 $i >> "$TMP/t1"
	run 2 $i >> "$TMP/t2"
	i=$((i + 1))
done
EVALS=$(awk 'NR == 1 { print $2 }' "$TMP/t1")
T1=$(awk '{ print $1 }' "$TMP/t1" | median)
T2=$(awk '{ print $1 }' "$TMP/t2" | median)
C1=$(awk '{ print $3 }' "$TMP/t1" | median)
C2=$(awk '{ print $3 }' "$TMP/t2" | median)
for d in "$TMP"/r*; do   # every run must write the same data, or the timing means nothing
	for f in summary by_nz worst; do
		grep -v '^#' "$TMP/r1-1/$f.csv" > "$TMP/a"; grep -v '^#' "$d/$f.csv" > "$TMP/b"
		cmp -s "$TMP/a" "$TMP/b" || { echo "mpi-scaling: $d/$f.csv differs from the first 1-rank run" >&2; exit 1; }
	done
done

# the full domain, as the plan counts it
./onbstudy sweep --dry-run --dists exhaustive --precision float --exhaustive-range -1:1 --azimuths 16 --threads 1 > "$TMP/plan"
FULL=$(sed -n 's/^plan: \([0-9]*\) referenced evaluations.*/\1/p' "$TMP/plan")
NZ=$(sed -n 's/^plan: exhaustive: \([0-9]*\) consecutive n.z.*/\1/p' "$TMP/plan")
NM=$(sed -n 's/^plan: \([0-9]*\) methods:.*/\1/p' "$TMP/plan")

prov() {
	echo "# onbstudy mpi-scaling: scripts/mpi-scaling.sh $COUNT $REPEATS"
	echo "# revision: $(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)$(git diff --quiet HEAD -- . ':(exclude)results' 2>/dev/null || echo -dirty)"
	echo "# compiler: $(${CC:-cc} --version | head -1); mpi: $(mpirun --version 2>&1 | head -1)"
	echo "# cpu: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores"
	echo "# date: $(date -u +%Y-%m-%dT%H:%M:%SZ); load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
	echo "# sweep: $ARGS (every method that runs in float; 1 thread per rank)"
}
{
	prov
	echo "ranks,threads_per_rank,evaluations,runs,median_seconds,seconds_each,median_cpu_seconds,evals_per_cpu_second,speedup_vs_1"
	for n in 1 2; do
		t=$(eval echo \$T$n); c=$(eval echo \$C$n)
		awk -v n=$n -v e="$EVALS" -v t="$t" -v c="$c" -v t1="$T1" -v r="$REPEATS" -v each="$(awk '{ printf "%s%s", s, $1; s = " " }' "$TMP/t$n")" \
			'BEGIN { printf "%d,1,%.0f,%d,%.3f,%s,%.3f,%.0f,%.3f\n", n, e, r, t, each, c, e / c, t1 / t }'
	done
} > "$OUT/scaling.csv.tmp"
mv "$OUT/scaling.csv.tmp" "$OUT/scaling.csv"
# the per-core rate: evaluations per CPU second of the 1-rank runs (on a
# shared machine the wall-clock rate measures the load as much as the code)
RATE=$(awk -v e="$EVALS" -v c="$C1" 'BEGIN { printf "%.0f", e / c }')
WRATE=$(awk -v e="$EVALS" -v t="$T1" 'BEGIN { printf "%.0f", e / t }')
SPEED2=$(awk -v t1="$T1" -v t2="$T2" 'BEGIN { printf "%.2f", t1 / t2 }')
{
	prov
	echo "# full domain: $NZ float n.z in [-1, 1] x 16 azimuths x $NM methods = $FULL referenced evaluations (onbstudy sweep --dry-run)"
	echo "# rate: $RATE evaluations per CPU second on 1 rank x 1 thread (median of $REPEATS; wall clock: $WRATE per second); 2 ranks ran ${SPEED2}x faster than 1"
	echo "# ideal scaling assumed: cores x the 1-core rate (no start-up, no imbalance)"
	echo "cores,evaluations,evals_per_s_per_core,ideal_seconds,ideal_hours,ideal_days"
	for c in 1 64 1024; do
		awk -v c=$c -v f="$FULL" -v r="$RATE" 'BEGIN { s = f / (r * c); printf "%d,%.0f,%.0f,%.0f,%.2f,%.3f\n", c, f, r, s, s / 3600, s / 86400 }'
	done
} > "$OUT/projection.csv.tmp"
mv "$OUT/projection.csv.tmp" "$OUT/projection.csv"
{
	prov
	echo "# the full float domain as \`onbstudy sweep --dry-run --dists exhaustive --precision float --exhaustive-range -1:1 --azimuths 16\` counts it (docs/sweep.md quotes it; tests/findings.sh compares it with a fresh dry run)"
	echo "what,value"
	echo "methods,$NM"
	echo "nz_values,$NZ"
	echo "azimuths,16"
	echo "evaluations,$FULL"
} > "$OUT/domain.csv.tmp"
mv "$OUT/domain.csv.tmp" "$OUT/domain.csv"
{
	prov
	echo "# the load average (1, 5, 15 minutes) before the timed runs and after them: the README quotes it with the times"
	echo "when,load_1min,load_5min,load_15min"
	echo "start,$LOAD0" | tr ' ' ,
	echo "end,$(cut -d' ' -f1-3 /proc/loadavg)" | tr ' ' ,
} > "$OUT/load.csv.tmp"
mv "$OUT/load.csv.tmp" "$OUT/load.csv"
cat "$OUT/scaling.csv" "$OUT/projection.csv" | grep -v '^# \(compiler\|cpu\)'
