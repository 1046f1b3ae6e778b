#!/bin/sh
# mpi.sh - the MPI driver: `mpirun -n N onbstudy-mpi sweep` writes
# the same data as `onbstudy sweep` for N = 1, 2, 3 ranks with 1 and 2
# threads; a rank killed with SIGKILL mid-run, then --resume, gives the same
# files and redoes at most the batches in flight; a cancelled run (SIGTERM)
# resumes too; --resume DIR before any checkpoint (a rank killed at its
# start) starts from the beginning, so the same command line restarts any
# job; a bad option, other options on one rank, and a checkpoint of other
# options are refused with one message and no hang.
# Skipped (with a clear line) when Open MPI is not installed.
. "$(dirname "$0")/lib.sh"
# `make mpi` installs Open MPI itself on a fresh machine, as `make` and
# `make plots` install theirs (checked before the skip: it needs no MPI)
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory -n -B mpi B="$tmp/nob" 2>/dev/null |
	grep -q 'install-deps\.sh --mpi' && ok || bad "make mpi does not run scripts/install-deps.sh --mpi"
mpi_start

# same DIR1 DIR2 WHAT: the data (every line but the '#' provenance) and stdout
same() {
	for f in summary by_nz worst grid; do
		grep -v '^#' "$1/$f.csv" > "$tmp/a.data" 2> /dev/null || { bad "$3: no data in $1/$f.csv"; return; }
		grep -v '^#' "$2/$f.csv" > "$tmp/b.data" 2> /dev/null || { bad "$3: no data in $2/$f.csv"; return; }
		cmp -s "$tmp/a.data" "$tmp/b.data" || { bad "$3: $f.csv differs from the single-process run"; return; }
	done
	cmp -s "$1.out" "$2.out" || { bad "$3: stdout differs"; return; }
	ok
}

# bad starts: exit non-zero, our message once, no hang (timeout 600 -> 124)
refuse() { # WHAT WORD ARGS...
	what=$1; word=$2; shift 2
	"$@" > "$tmp/bad.out" 2> "$tmp/bad.err"
	rc=$?
	n=$(grep -c "^onbstudy: .*$word" "$tmp/bad.err")
	if [ $rc -ne 0 ] && [ $rc -ne 124 ] && [ "$n" -eq 1 ]; then ok
	else bad "$what: exit $rc, $n messages with '$word': $(grep -v '^-\|^$' "$tmp/bad.err" | head -3)"; fi
}

A="--samples 1024 --exhaustive-count 512 --grid 4x8 --methods duff,frisvad,naive,frisvad_rotate --quiet"
./onbstudy sweep $A --threads 2 --out "$tmp/ref" > "$tmp/ref.out" 2> "$tmp/ref.err" || bad "the single-process sweep failed: $(cat "$tmp/ref.err")"
for n in 1 2 3; do
	for t in 1 2; do
		d="$tmp/n$n-t$t"
		$MPIRUN -n $n ./onbstudy-mpi sweep $A --threads $t --out "$d" > "$d.out" 2> "$d.err"
		rc=$?
		[ $rc -eq 0 ] && ok || bad "mpirun -n $n, $t threads: exit $rc: $(head -3 "$d.err")"
		same "$tmp/ref" "$d" "mpirun -n $n, $t threads"
		grep -q "^# mpi: $n ranks x $t threads" "$d/summary.csv" && ok || bad "-n $n: no '# mpi: $n ranks x $t threads' provenance"
	done
done
# the fast reference path through the same engine: the same data,
# and the same evaluation and fallback counts in reference.csv (the count of
# MPFR calls for worst rows depends on the chunking, so only the log has it)
./onbstudy sweep $A --ref fast --threads 2 --out "$tmp/fref" > "$tmp/fref.out" 2> /dev/null || bad "sweep --ref fast failed"
$MPIRUN -n 2 ./onbstudy-mpi sweep $A --ref fast --threads 1 --out "$tmp/fmpi" > "$tmp/fmpi.out" 2> "$tmp/fmpi.err" || bad "mpirun --ref fast: $(head -3 "$tmp/fmpi.err")"
same "$tmp/fref" "$tmp/fmpi" "--ref fast on 2 ranks"
if [ -f "$tmp/fref/reference.csv" ]; then
	grep -v '^#' "$tmp/fref/reference.csv" > "$tmp/a.ref"
	grep -v '^#' "$tmp/fmpi/reference.csv" > "$tmp/b.ref" 2> /dev/null
	cmp -s "$tmp/a.ref" "$tmp/b.ref" && ok || bad "--ref fast on 2 ranks: reference.csv counts differ"
fi
grep -q "PARTIAL\|checkpoint" "$tmp/n3-t1/summary.csv" && bad "a finished run mentions a checkpoint" || ok
[ ! -e "$tmp/n3-t1/sweep-checkpoint.bin" ] && ok || bad "the checkpoint is left after a finished run"

# SIGKILL one rank mid-run, then --resume: the same files, at most the
# in-flight batches (one per rank) redone
# big enough that a loaded machine cannot finish it between two polls
K="--samples 65536 --exhaustive-count 4096 --grid 8x16 --methods duff,frisvad,naive,stark --quiet --threads 1"
BATCH=8
./onbstudy sweep $K --out "$tmp/kref" > "$tmp/kref.out" 2> /dev/null || bad "the reference of the kill test failed"
$MPIRUN -n 2 ./onbstudy-mpi sweep $K --batch $BATCH --out "$tmp/kill" > /dev/null 2> "$tmp/kill.err" &
mp=$!
i=0
while [ ! -f "$tmp/kill/sweep-checkpoint.bin" ] && [ $i -lt 1200 ]; do sleep 0.1; i=$((i + 1)); done
sleep 0.5
victim=""
i=0
while [ -z "$victim" ] && [ $i -lt 50 ]; do
	# this run's ranks alone (its --out names them): another mpi.sh at once
	# (make test runs two tests at a time; other checkouts) has its own
	for p in $(pgrep -f "onbstudy-mpi sweep $K --batch $BATCH --out $tmp/kill"); do
		r=$(tr '\0' '\n' < /proc/$p/environ 2> /dev/null | sed -n 's/^OMPI_COMM_WORLD_RANK=//p')
		[ "$r" = 1 ] && victim=$p
	done
	[ -n "$victim" ] || sleep 0.1
	i=$((i + 1))
done
if [ -n "$victim" ]; then kill -KILL "$victim"; ok; else bad "no rank 1 to kill (the run ended too soon?)"; fi
wait $mp; rc=$?
[ $rc -ne 0 ] && ok || bad "mpirun exited 0 after a rank was killed"
[ -f "$tmp/kill/sweep-checkpoint.bin" ] && ok || bad "no checkpoint after the kill"
[ ! -f "$tmp/kill/summary.csv" ] && ok || bad "the killed run wrote summary.csv"
refuse "a checkpoint of other options" "other options" $MPIRUN -n 2 ./onbstudy-mpi sweep $K --seed 7 --resume "$tmp/kill"
$MPIRUN -n 3 ./onbstudy-mpi sweep $K --resume "$tmp/kill" > "$tmp/kill.out" 2> "$tmp/resume.err"
rc=$?
[ $rc -eq 0 ] && ok || bad "--resume: exit $rc: $(head -3 "$tmp/resume.err")"
same "$tmp/kref" "$tmp/kill" "kill rank 1 + --resume"
# Rank 0 says, when the job ends, how many evaluations its checkpoint holds:
# all it had received (the rest, one batch per rank at most, was in flight)
held=$(sed -n 's/.*every batch finished so far (\([0-9]*\) of.*/\1/p' "$tmp/kill.err")
from=$(sed -n 's/.*(\([0-9]*\) from the checkpoint).*/\1/p' "$tmp/resume.err")
if [ -n "$from" ] && [ "$from" -gt 0 ] && [ "$from" = "${held:-$from}" ]; then ok
else bad "--resume started from ${from:-?} evaluations; rank 0 held ${held:-?} when the job ended"; fi
[ -n "$held" ] || echo "note: rank 0 was killed before it could report what the checkpoint holds: $(grep -v "^-" "$tmp/kill.err" | head -5)"
grep -q '^# mpi: 3 ranks.*resumed from a checkpoint' "$tmp/kill/summary.csv" && ok || bad "no 'resumed' provenance"

# cancel (SIGTERM to mpirun, as a scheduler does), then resume
$MPIRUN -n 2 ./onbstudy-mpi sweep $K --batch $BATCH --out "$tmp/cancel" > /dev/null 2> "$tmp/cancel.err" &
mp=$!
i=0
while [ ! -f "$tmp/cancel/sweep-checkpoint.bin" ] && [ $i -lt 1200 ]; do sleep 0.1; i=$((i + 1)); done
kill -TERM $mp
wait $mp
$MPIRUN -n 2 ./onbstudy-mpi sweep $K --resume "$tmp/cancel" > "$tmp/cancel.out" 2> "$tmp/cancel2.err"
rc=$?
[ $rc -eq 0 ] && ok || bad "--resume after SIGTERM: exit $rc: $(head -3 "$tmp/cancel2.err")"
same "$tmp/kref" "$tmp/cancel" "SIGTERM + --resume"

refuse "bad option on 3 ranks" "unknown option" $MPIRUN -n 3 ./onbstudy-mpi sweep --bogus
refuse "bad value on 2 ranks" "--samples" $MPIRUN -n 2 ./onbstudy-mpi sweep --samples 0
refuse "other options on one rank" "other options" $MPIRUN -n 1 ./onbstudy-mpi sweep $A --out "$tmp/x" : -n 1 ./onbstudy-mpi sweep $A --seed 2 --out "$tmp/x"
cp onbstudy-mpi "$tmp/other-mpi" && printf 'x' >> "$tmp/other-mpi"   # another build: other bytes, same code
refuse "another binary on one rank" "different binary" $MPIRUN -n 1 ./onbstudy-mpi sweep $A --out "$tmp/x" : -n 1 "$tmp/other-mpi" sweep $A --out "$tmp/x"

# One command line for the first start and every restart (a requeued
# job): --resume DIR with no checkpoint there yet starts from the
# beginning and says so.  Rank 1 is killed as soon as it runs, before rank
# 0 has added a batch (one batch of every chunk: the first checkpoint would
# come at the end), then the same command line runs again.
early() { $MPIRUN -n 2 ./onbstudy-mpi sweep $K --batch 1000000 --resume "$tmp/early"; }
early > /dev/null 2> "$tmp/early1.err" &
mp=$!
victim=""
i=0
while [ -z "$victim" ] && [ $i -lt 600 ]; do
	for p in $(pgrep -f "onbstudy-mpi sweep $K --batch 1000000 --resume $tmp/early"); do
		r=$(tr '\0' '\n' < /proc/$p/environ 2> /dev/null | sed -n 's/^OMPI_COMM_WORLD_RANK=//p')
		[ "$r" = 1 ] && victim=$p
	done
	[ -n "$victim" ] || sleep 0.05
	i=$((i + 1))
done
if [ -n "$victim" ]; then kill -KILL "$victim"; ok; else bad "no rank 1 to kill before the first checkpoint"; fi
wait $mp; rc=$?
[ $rc -ne 0 ] && ok || bad "mpirun exited 0 after rank 1 was killed at its start"
[ ! -f "$tmp/early/sweep-checkpoint.bin" ] && ok || bad "a checkpoint exists after a kill before the first batch"
early > "$tmp/early.out" 2> "$tmp/early2.err"
rc=$?
[ $rc -eq 0 ] && ok || bad "--resume with no checkpoint yet: exit $rc: $(head -3 "$tmp/early2.err")"
grep -q 'no checkpoint there yet.*starting from the beginning' "$tmp/early2.err" && ok || bad "--resume with no checkpoint: no 'starting from the beginning' message"
same "$tmp/kref" "$tmp/early" "rank killed before the first checkpoint + the same command line"
grep -q '^# mpi: 2 ranks' "$tmp/early/summary.csv" && ! grep -q 'resumed from a checkpoint' "$tmp/early/summary.csv" && ok ||
	bad "a run started from the beginning says 'resumed from a checkpoint'"
refuse "not sweep" "sweep" $MPIRUN -n 2 ./onbstudy-mpi eval 0 0 1
finish mpi
