#!/bin/sh
# certify_mpi.sh - `mpirun -n N onbstudy-mpi certify` at a reduced size
# (--quick, two methods, float):
#  - on 1 rank x 2 threads, 2 ranks x 1 thread and 4 ranks x 1 thread
#    (oversubscribed on 2 cores) certify.csv's rows and stdout are those
#    of `onbstudy certify`, and its provenance names the ranks;
#  - rank 1 killed (ONB_CERT_KILL_RANK=1 ONB_CERT_KILL=PHASE:N: it kills
#    itself after its N-th task of that phase) in the first pass and in
#    the images pass ends the job, non-zero, with the checkpoint and no
#    certify.csv (nor any partial file); rank 0 says that rank 1 died,
#    names the regions in flight (lost) and how to continue; the same
#    command line with --resume DIR redoes what was in flight and writes
#    the same rows and stdout; rank 0 killed in the images pass resumes
#    with the single-process driver (one checkpoint format);
#  - with no checkpoint due (--checkpoint-every 600, and a run with --out
#    and no --resume) rank 0 writes one when the job is ended: the resumed
#    run starts from exactly the regions it said it kept;
#  - with --checkpoint-every 0 rank 0 does not write when the job is
#    ended (its checkpoint already holds every commit), so mpirun's
#    SIGKILL, a second after its SIGTERM, has no write to cut short (with
#    a grace of 0, in the run tried, a .certify-checkpoint.bin.partial.PID
#    was left: the write cut short);
#  - a partial checkpoint left by a writer that was killed is removed by
#    the next run in that directory;
#  - after the end the same command line says the work is done;
#  - --precision half on 1 and 2 ranks: onbstudy certify's rows and stdout;
#  - a bad option is refused once, exit 2, no hang.
# Skipped (with a clear line) when Open MPI is not installed.
. "$(dirname "$0")/lib.sh"
mpi_start
T=$tmp
Q="--quick --quiet --precision float --methods frisvad,rtow"
data() { grep -v '^#' "$1"; }
same() { # DIR WHAT: DIR's rows against the single-process run's
	if data "$1/certify.csv" > "$1.data" 2> /dev/null && cmp -s "$T/ref.data" "$1.data"; then ok
	else bad "$2: certify.csv's rows differ from onbstudy certify's"; fi
}
./onbstudy certify $Q --out "$T/ref" > "$T/ref.out" 2> "$T/ref.err" || bad "onbstudy certify failed: $(cat "$T/ref.err")"
data "$T/ref/certify.csv" > "$T/ref.data"

# 1. 1, 2 and 4 ranks: the same rows and stdout
for nt in 1:2 2:1 4:1; do
	n=${nt%:*}; t=${nt#*:}; d="$T/n$n"
	OMP_NUM_THREADS=$t $MPIRUN -n $n ./onbstudy-mpi certify $Q --out "$d" > "$d.out" 2> "$d.err"
	rc=$?
	[ $rc -eq 0 ] && ok || bad "-n $n x $t threads: exit $rc: $(head -3 "$d.err")"
	same "$d" "-n $n x $t threads"
	cmp -s "$T/ref.out" "$d.out" && ok || bad "-n $n x $t threads: stdout differs"
	grep -q "^# mpi: $n ranks x $t threads" "$d/certify.csv" && ok || bad "-n $n: no '# mpi: $n ranks x $t threads' provenance"
	grep -q "CPU seconds in all ranks; regions computed per rank" "$d.err" && ok || bad "-n $n: no count of regions per rank"
done

# 1b. --precision half (issues 43 x 46): on 1 and 2 ranks, certify-half.csv's
#     rows and stdout are onbstudy certify's, and its provenance names the ranks
H="--quick --precision half --methods duff --sectors 1 --depth 2 --azimuths 2"
./onbstudy certify $H --out "$T/href" > "$T/href.out" 2> "$T/href.err" || bad "onbstudy certify $H: $(cat "$T/href.err")"
grep -v '^wrote ' "$T/href.out" > "$T/href.sum"   # the summary, without the output's path
for n in 1 2; do
	d="$T/h$n"
	OMP_NUM_THREADS=1 $MPIRUN -n $n ./onbstudy-mpi certify $H --out "$d" > "$d.out" 2> "$d.err"
	rc=$?
	data "$d/certify-half.csv" > "$d.data" 2> /dev/null
	[ $rc -eq 0 ] && data "$T/href/certify-half.csv" | cmp -s - "$d.data" && ok ||
		bad "half, -n $n: exit $rc, certify-half.csv's rows differ: $(head -3 "$d.err")"
	grep -v '^wrote ' "$d.out" | cmp -s "$T/href.sum" - && ok || bad "half, -n $n: stdout differs"
	grep -q "^# mpi: $n ranks x 1 threads" "$d/certify-half.csv" && ok || bad "half, -n $n: no '# mpi: $n ranks' provenance"
done

# 2. a rank dies (rank 1 in the first pass and the images pass, rank 0 in
#    the images pass), then the same command line resumes
told() { # FILE WHAT PATTERN...: every pattern in FILE
	tf=$1; tw=$2; shift 2
	for tp in "$@"; do
		grep -q "$tp" "$tf" || { bad "$tw: no line '$tp' in: $(grep -v '^-' "$tf" | head -8)"; return; }
	done
	ok
}
kill_resume() { # RANK PHASE:N RESUMER WHAT
	d="$T/k$1-$2"
	ONB_CERT_KILL_RANK=$1 ONB_CERT_KILL=$2 OMP_NUM_THREADS=1 \
		$MPIRUN -n 2 ./onbstudy-mpi certify $Q --resume "$d" --checkpoint-every 0 > /dev/null 2> "$d.err1"
	rc=$?
	[ $rc -ne 0 ] && [ $rc -ne 124 ] && [ -f "$d/certify-checkpoint.bin" ] && [ "$(ls -A "$d")" = certify-checkpoint.bin ] && ok ||
		bad "$4: exit $rc, in $d: $(ls -A "$d" 2> /dev/null | tr '\n' ' ')"
	if [ $1 -ne 0 ]; then   # rank 0 lives to say what died, what is lost, how to continue
		ph="first pass"; [ "${2%%:*}" = images ] && ph="images pass"
		told "$d.err1" "$4" "^onbstudy-mpi: rank $1 (pid [0-9]*, this node) has died" \
			"^onbstudy-mpi: lost, in flight on rank $1 in the $ph: [a-z_]* float region [0-9]* (n.z in \[" \
			"^onbstudy-mpi: to continue: the same command line (--resume $d redoes only"
	fi
	OMP_NUM_THREADS=1 $3 $Q --resume "$d" --checkpoint-every 0 > "$d.out" 2> "$d.err"
	rc=$?
	[ $rc -eq 0 ] && grep -q 'continuing from its checkpoint' "$d.err" && ok || bad "$4, resumed: exit $rc: $(head -3 "$d.err")"
	same "$d" "$4, resumed"
	cmp -s "$T/ref.out" "$d.out" && ok || bad "$4, resumed: stdout differs"
	[ ! -e "$d/certify-checkpoint.bin" ] && ok || bad "$4: the checkpoint is left after the end"
}
kill_resume 1 run:2 "$MPIRUN -n 2 ./onbstudy-mpi certify" "rank 1 killed in the first pass"
kill_resume 1 images:2 "$MPIRUN -n 2 ./onbstudy-mpi certify" "rank 1 killed in the images pass"
kill_resume 0 images:4 "./onbstudy certify" "rank 0 killed in the images pass, resumed by onbstudy"

# ... with no checkpoint due (the last at the first pass's end): rank 0
#     writes it when the job is ended, with the count the resume reads
#     (here mpirun's SIGKILL 3 s after its SIGTERM, not 1 s: time for the
#     write on a loaded machine; mpirun waits that long in any case)
d="$T/late"
OMPI_MCA_odls_base_sigkill_timeout=3 ONB_CERT_KILL_RANK=1 ONB_CERT_KILL=images:3 OMP_NUM_THREADS=1 \
	$MPIRUN -n 2 ./onbstudy-mpi certify $Q --resume "$d" --checkpoint-every 600 > /dev/null 2> "$d.err1"
kept=$(sed -n 's/.*committed so far (first pass: \([0-9]*\) of \([0-9]*\) regions, images pass: \([0-9]*\),.*/\1 \2 \3/p' "$d.err1")
set -- ${kept:-0 -1 0}   # (none said: a failure below, not an unset $1)
[ $# -eq 3 ] && [ "$1" = "$2" ] && [ "$3" -gt 0 ] && [ "$3" -lt "$2" ] && ok ||
	bad "killed in the images pass, no checkpoint due: kept '$kept': $(grep -v '^-' "$d.err1" | head -8)"
# ... and a partial checkpoint of a writer that is gone (killed while it
#     wrote) beside it: the resumed run removes it, and reads the last
#     complete one
dead=$(sh -c 'echo $$')
echo partial > "$d/.certify-checkpoint.bin.partial.$dead"
OMP_NUM_THREADS=1 $MPIRUN -n 2 ./onbstudy-mpi certify $Q --resume "$d" > "$d.out" 2> "$d.err"
grep -q "continuing from its checkpoint ($1 of $2 regions run)" "$d.err" && ok || bad "the late checkpoint, resumed: $(head -3 "$d.err")"
same "$d" "the late checkpoint, resumed"
ls -A "$d" | grep -q 'partial' && bad "the late checkpoint, resumed: a dead writer's partial checkpoint left: $(ls -A "$d" | tr '\n' ' ')" || ok
# ... a run with --out and no --resume: the checkpoint in its directory,
#     and the message's --resume DIR continues it
d="$T/out"
OMPI_MCA_odls_base_sigkill_timeout=3 ONB_CERT_KILL_RANK=1 ONB_CERT_KILL=run:3 OMP_NUM_THREADS=1 \
	$MPIRUN -n 2 ./onbstudy-mpi certify $Q --out "$d" > /dev/null 2> "$d.err1"
told "$d.err1" "--out, rank 1 killed" "^onbstudy-mpi: lost, in flight on rank 1 in the first pass: " \
	"^onbstudy-mpi: to continue: the same command line with --resume $d in place of --out" \
	"^onbstudy-mpi: kept in $d/certify-checkpoint.bin: every result committed so far (first pass: [1-9]"
[ "$(ls -A "$d")" = certify-checkpoint.bin ] && ok || bad "--out, rank 1 killed: in $d: $(ls -A "$d" | tr '\n' ' ')"
OMP_NUM_THREADS=1 $MPIRUN -n 2 ./onbstudy-mpi certify $Q --resume "$d" > "$d.out" 2> "$d.err"
grep -q 'continuing from its checkpoint' "$d.err" && ok || bad "--out, resumed: $(head -3 "$d.err")"
same "$d" "--out, rank 1 killed, resumed"
cmp -s "$T/ref.out" "$d.out" && ok || bad "--out, rank 1 killed, resumed: stdout differs"

# 3. after the end: done
d="$T/k1-run:2"
$MPIRUN -n 2 ./onbstudy-mpi certify $Q --resume "$d" > /dev/null 2> "$T/done.err"
rc=$?
[ $rc -eq 0 ] && grep -q 'the work is done' "$T/done.err" && ok || bad "after the end: exit $rc: $(cat "$T/done.err")"

# 4. a bad option: one message, exit 2
$MPIRUN -n 2 ./onbstudy-mpi certify --budget 0 > /dev/null 2> "$T/bad.err"
rc=$?
n=$(grep -c '^onbstudy: .*--budget' "$T/bad.err")
[ $rc -eq 2 ] && [ "$n" -eq 1 ] && ok || bad "--budget 0 on 2 ranks: exit $rc, $n messages: $(head -3 "$T/bad.err")"
finish certify_mpi
