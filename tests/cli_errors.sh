#!/bin/sh
# Bad command lines, every subcommand: exit 2, exactly one line on stderr
# ("onbstudy: ..."), no result file and no output directory left behind.
# Also: huge sample counts are refused, and SIGINT during a sweep leaves the
# earlier summary.csv untouched and writes *.partial.csv marked '# PARTIAL'.
# Commands added later (bench, threshold, eval) get the unknown-option
# check when `onbstudy X --help` succeeds, and are skipped otherwise.
# Cases listed in KNOWN are bugs reported to the owner of the code (see the
# comment there): they are run and reported as "KNOWN", not counted as
# failures; a KNOWN case that passes is counted as passed, with a note.
. "$(dirname "$0")/lib.sh"
bin=$root/onbstudy
known=0
mkdir -p "$tmp/cwd"
out="$tmp/out"
: > "$tmp/afile"

# Known bugs in code this test does not own (src/sweep/*.c):
#   merge-noargs      'merge' with no STATE prints the 3-line usage to stderr
#   merge-shard-index a state file whose shard index is out of range is not
#                     rejected by sweep_load_state; cmd_merge writes seen[k]
#                     out of bounds (heap overflow under ASan, sweep.c)
#   range-mkdir       sweep creates --out DIR before it checks
#                     --exhaustive-range, so an empty DIR is left behind
KNOWN=""   # all fixed: merge-noargs, merge-shard-index, range-mkdir (c. 2026-11-23)
is_known() { case " $KNOWN " in *" $1 "*) return 0;; esac; return 1; }

# refuse ID COMMAND ARGS...: exit 2, one line on stderr, nothing written
refuse() {
	id=$1; shift
	rm -rf "$out"
	(cd "$tmp/cwd" && "$bin" "$@") > "$tmp/o" 2> "$tmp/e"
	rc=$?
	why=""
	[ $rc -eq 2 ] || why="exit $rc, expected 2"
	n=$(wc -l < "$tmp/e")
	[ -n "$why" ] || [ "$n" -eq 1 ] || why="$n lines on stderr"
	[ -n "$why" ] || grep -q '^onbstudy: ' "$tmp/e" || why="stderr does not start with 'onbstudy: '"
	[ -n "$why" ] || [ ! -e "$out" ] || why="left the --out directory behind$( [ -n "$(ls -A "$out")" ] && echo " holding $(ls -A "$out" | tr '\n' ' ')")"
	[ -n "$why" ] || [ -z "$(ls -A "$tmp/cwd")" ] || why="wrote into the working directory: $(ls -A "$tmp/cwd")"
	if is_known "$id"; then
		if [ -n "$why" ]; then
			known=$((known + 1))
			san=$(grep -m1 -o 'ERROR: [A-Za-z]*Sanitizer: [A-Za-z-]*\|runtime error: .*' "$tmp/e")
			echo "KNOWN ($id): $why${san:+ [$san]} -- onbstudy $*"
		else ok; echo "note: KNOWN case ($id) passes in this build (a heap overflow may show only under SANITIZE=address): onbstudy $*"; fi
	elif [ -z "$why" ]; then ok
	else bad "onbstudy $*: $why; stderr: $(head -3 "$tmp/e")"; fi
	rm -rf "$out" "$tmp/cwd"; mkdir -p "$tmp/cwd"
}
R() { refuse - "$@"; }

# --- top level
R nosuchcommand
R sweep-typo --help

# --- list
R list --bogus
R list --format xml
R list --format=xml
R list --format
R list extra

# --- sweep: options, numbers, ranges, huge counts
S="--out $out"
R sweep --bogus $S
R sweep -x $S
R sweep --samples $S
R sweep $S --samples
R sweep --samples 1e30 $S
R sweep --samples 68719476737 $S
R sweep --samples 99999999999999999999999 $S
R sweep --samples 0 $S
R sweep --samples -5 $S
R sweep --samples " 5" $S
R sweep --samples 5x $S
R sweep --samples "" $S
R sweep --seed -1 $S
R sweep --seed " -1" $S
R sweep --seed 18446744073709551616 $S
R sweep --exhaustive-count 4294967297 $S
R sweep --exhaustive-from 2 $S
R sweep --exhaustive-from nan $S
R sweep --exhaustive-from inf $S
R sweep --exhaustive-from 1e999 $S
R sweep --azimuths 0 $S
R sweep --azimuths 4097 $S
R sweep --grid 1x1 $S
R sweep --grid 4x $S
R sweep --grid 4x8x2 $S
R sweep --grid 99999x2 $S
R sweep --threads 5000 $S
R sweep --threads -1 $S
R sweep --ref-bits 10 $S
R sweep --ref-bits 100000 $S
R sweep --check-every 0 $S
R sweep --precision quarter $S
R sweep --dists nosuch $S
R sweep --dists , $S
R sweep --methods nosuch $S
R sweep --methods duff,duff $S
R sweep --methods , $S
R sweep --shard 3/2 $S
R sweep --shard 1 $S
R sweep --shard -1/2 $S
R sweep --format xml $S
refuse range-mkdir sweep --exhaustive-range 0.5:0.1 --samples 1 --methods duff $S
refuse range-mkdir sweep --exhaustive-range nan:1 --samples 1 --methods duff $S
refuse range-mkdir sweep --exhaustive-range 0.5 --samples 1 --methods duff $S
# unwritable or impossible output directories
R sweep --samples 1 --methods duff --out "$tmp/afile/sub"
R sweep --samples 1 --methods duff --out "$tmp/afile"
R sweep --samples 1 --methods duff --out /proc/onbstudy-cli-test/x
if [ "$(id -u)" -ne 0 ]; then
	mkdir -p "$tmp/ro"; chmod 555 "$tmp/ro"
	R sweep --samples 1 --methods duff --out "$tmp/ro"
	R sweep --samples 1 --methods duff --out "$tmp/ro/sub"
fi

# --- merge
R merge --bogus
R merge --threads x "$tmp/none.bin"
R merge --format xml "$tmp/none.bin"
R merge --out
R merge "$tmp/none.bin" --out "$out"
R merge "$tmp" --out "$out"
printf 'not a state file' > "$tmp/garbage.bin"
R merge "$tmp/garbage.bin" --out "$out"
refuse merge-noargs merge
# a real shard, then damaged copies of it
if "$bin" sweep --shard 0/2 --samples 64 --exhaustive-count 64 --grid 4x8 --methods duff --quiet --out "$tmp/shard" > /dev/null 2>&1 \
   && [ -f "$tmp/shard/sweep-state-0-of-2.bin" ]; then
	ok
	st="$tmp/shard/sweep-state-0-of-2.bin"
	size=$(wc -c < "$st")
	head -c $((size / 2)) "$st" > "$tmp/trunc.bin"
	R merge "$tmp/trunc.bin" --out "$out"
	cat "$st" "$st" > "$tmp/long.bin"
	R merge "$tmp/long.bin" --out "$out"
	R merge "$st" --out "$out"                      # shard 1 of 2 missing
	R merge "$st" "$st" --out "$out"                # shard 0 twice
	# shard_k (int at the offset of sweep_cfg.shard_k) set to 100000:
	# the offset is computed by a small C program from sweep/state.h
	cat > "$tmp/off.c" <<'C'
#include <stdio.h>
#include <stddef.h>
#include "sweep/state.h"
int main(void) { printf("%lu\n", (unsigned long)offsetof(sweep_cfg, shard_k)); return 0; }
C
	if cc -std=c99 -Iinclude -Isrc -o "$tmp/off" "$tmp/off.c" 2>/dev/null; then
		off=$("$tmp/off")
		{ head -c "$off" "$st"; printf '\240\206\001\000'; tail -c +$((off + 5)) "$st"; } > "$tmp/badk.bin"
		[ "$(wc -c < "$tmp/badk.bin")" -eq "$size" ] && ok || bad "could not build the bad-shard state file"
		refuse merge-shard-index merge "$tmp/badk.bin" --out "$out"
	else
		bad "cannot compile the offset helper"
	fi
else
	bad "the small shard sweep failed"
fi

# --- scene
printf 'vn 0 0 1\nvn 0.6 0.8 0\n' > "$tmp/ok.obj"
: > "$tmp/empty.obj"
printf 'v 0 0 0\nf 1 2 3\n' > "$tmp/badidx.obj"
printf 'ply\nformat ascii 1.0\nelement vertex 99\nproperty float nx\nend_header\n1\n' > "$tmp/short.ply"
R scene
R scene --bogus "$tmp/ok.obj"
R scene "$tmp/ok.obj" "$tmp/ok.obj"
R scene "$tmp/ok.obj" --tolerance
R scene "$tmp/ok.obj" --tolerance -1
R scene "$tmp/ok.obj" --tolerance 0
R scene "$tmp/ok.obj" --tolerance nan
R scene "$tmp/ok.obj" --tolerance inf
R scene "$tmp/ok.obj" --tolerance 1e999
R scene "$tmp/ok.obj" --tolerance 1e-6x
R scene "$tmp/ok.obj" --precision quarter
R scene "$tmp/ok.obj" --up w
R scene "$tmp/ok.obj" --up xy
R scene "$tmp/ok.obj" --repeats 0
R scene "$tmp/ok.obj" --repeats 65
R scene "$tmp/ok.obj" --repeats x
R scene "$tmp/none.obj" --out "$out"
R scene "$tmp" --out "$out"
R scene "$tmp/empty.obj" --out "$out"
R scene "$tmp/badidx.obj" --out "$out"
R scene "$tmp/short.ply" --out "$out"
R scene "$tmp/ok.obj" --repeats 1 --out "$tmp/afile/sub"
R scene "$tmp/ok.obj" --repeats 1 --out "$tmp/afile"
R scene "$tmp/ok.obj" --repeats 1 --out /proc/onbstudy-cli-test/x
if [ "$(id -u)" -ne 0 ]; then
	cp "$tmp/ok.obj" "$tmp/noread.obj"; chmod 000 "$tmp/noread.obj"
	R scene "$tmp/noread.obj" --out "$out"
fi

# --- commands that may exist by now
for c in bench threshold eval; do
	if "$bin" $c --help > /dev/null 2>&1; then
		R $c --onbstudy-no-such-option
		R $c --onbstudy-no-such-option --out "$out"
	else
		echo "skip: onbstudy $c does not exist here"
	fi
done

# --- binary16 (issue 43): bench and table take --precision half; certify
#     --precision half takes --resume but not the float run's options; a
#     table of files without half rows, asked for half, is refused
R bench --precision quarter --out "$out"
R bench --precision half --methods nope --out "$out"
R table --precision quarter --out "$out"
printf '# x\nmethod,precision,mode,threads,size_class,mbases_per_s,ns_per_call\nduff,float,batch,1,l2,100,1\n' > "$tmp/fb.csv"
printf '# x\nmethod,precision,distribution,rmse,max_defect\nduff,float,uniform,1e-8,1e-7\n' > "$tmp/fs.csv"
R table --precision half --bench "$tmp/fb.csv" --summary "$tmp/fs.csv" --out "$out"
R certify --precision half --reuse "$tmp" --out "$out"
R certify --precision half --resume "$out" --out "$tmp/other"

# --- SIGINT during a sweep: the earlier summary.csv survives, the partial
# figures go to *.partial.csv marked '# PARTIAL'
d="$tmp/int"
if "$bin" sweep --samples 256 --exhaustive-count 256 --grid 4x8 --methods duff,frisvad --quiet --out "$d" > /dev/null 2>&1; then
	ok
	sum0=$(cksum < "$d/summary.csv")
	"$bin" sweep --samples 2000000 --methods duff,frisvad --quiet --out "$d" > "$tmp/int.out" 2> "$tmp/int.err" &
	pid=$!
	sleep 2
	kill -INT $pid 2>/dev/null
	i=0
	while kill -0 $pid 2>/dev/null && [ $i -lt 60 ]; do sleep 1; i=$((i + 1)); done
	if kill -0 $pid 2>/dev/null; then
		kill -KILL $pid; bad "sweep still running 60 s after SIGINT"
	fi
	wait $pid; rc=$?
	[ $rc -eq 130 ] && ok || bad "interrupted sweep exited $rc, expected 130; stderr: $(cat "$tmp/int.err")"
	[ "$(cksum < "$d/summary.csv")" = "$sum0" ] && ok || bad "summary.csv changed after SIGINT"
	for f in summary by_nz worst; do
		if [ -f "$d/$f.partial.csv" ] && grep -q '^# PARTIAL' "$d/$f.partial.csv"; then ok
		else bad "no $f.partial.csv marked '# PARTIAL' after SIGINT"; fi
	done
	[ -z "$(find "$d" -name '.*.partial.*')" ] && ok || bad "temporary files left after SIGINT: $(ls -A "$d")"
	grep -q 'interrupted' "$tmp/int.err" && ok || bad "no 'interrupted' message on stderr"
else
	bad "the small sweep before the SIGINT test failed"
fi

echo "$pass passed, $fail failed, $known known issues (reported, in KNOWN)"
[ $fail -eq 0 ]
