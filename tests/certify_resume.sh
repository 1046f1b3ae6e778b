#!/bin/sh
# certify_resume.sh - `onbstudy certify --resume DIR`, `--reuse DIR` and
# `--check-keys DIR` at a reduced size (--quick, three methods, float):
#  - a run killed during the first pass, the images pass and the
#    refinement (ONB_CERT_KILL=PHASE:N: the process kills itself after its
#    N-th finished task of that phase), then the same command line: the
#    same certify.csv rows and stdout as an uninterrupted run;
#  - the same command line after completion says the work is done; before
#    any checkpoint it starts from the beginning;
#  - a checkpoint of other options, of another key (a model's revision),
#    a corrupted one are refused with the difference named, exit 2;
#  - a checkpoint that cannot be written (file size limit: disk full)
#    stops the run with a message and leaves the last checkpoint intact;
#  - --reuse: adding a method to a finished run computes that method only,
#    a changed key is recomputed, and the rows equal a from-scratch run's;
#  - --check-keys: 0 on a current run, 1 naming a stale key;
#  - --precision half: killed and resumed gives the uninterrupted rows and
#    stdout; float and half checkpoints are not resumed as each other;
#  - a kernel compiled anew (rtow's float kernel with its threshold 0.9f
#    made 0.90001f, which none of the key's 96 probe inputs tells apart:
#    only its compiled code does) changes exactly one code checksum
#    (scripts/code-keys.sh), and an onbstudy linked with it finds exactly
#    rtow float stale and, with --reuse, computes rtow alone.
. "$(dirname "$0")/lib.sh"
T=$tmp
data() { grep -v '^#' "$1"; }
Q="--quick --quiet --precision float"
M=frisvad,naive,rtow
run() { ./onbstudy certify $Q "$@"; }
same() { # DIR WHAT: DIR's rows and stdout against the uninterrupted run's
	if data "$T/ref/certify.csv" | cmp -s - "$1/certify.csv.data" 2> /dev/null ||
	   { data "$1/certify.csv" > "$1.data" 2> /dev/null && cmp -s "$T/ref.data" "$1.data"; }; then ok
	else bad "$2: certify.csv's rows differ from the uninterrupted run's"; fi
}
run --methods $M --out "$T/ref" > "$T/ref.out" 2> "$T/ref.err" || bad "the reference run failed: $(cat "$T/ref.err")"
data "$T/ref/certify.csv" > "$T/ref.data"
[ -s "$T/ref/certify-keys.csv" ] && [ ! -e "$T/ref/certify-checkpoint.bin" ] && ok || bad "a finished run: no keys, or a checkpoint left"

# 1. killed in each phase (every region checkpointed, then at 60 s: the
#    images pass redone from the first pass's checkpoint), resumed
for k in run:5 images:7 refine:1 images:20; do
	d="$T/k-$k"
	e=0; [ $k = images:20 ] && e=60
	ONB_CERT_KILL=$k run --methods $M --resume "$d" --checkpoint-every $e > /dev/null 2> "$d.err1"
	rc=$?
	[ $rc -ne 0 ] && [ -f "$d/certify-checkpoint.bin" ] && [ ! -f "$d/certify.csv" ] && ok ||
		bad "ONB_CERT_KILL=$k: exit $rc, a checkpoint $(ls "$d" 2> /dev/null | tr '\n' ' ')"
	run --methods $M --resume "$d" --checkpoint-every $e > "$d.out" 2> "$d.err"
	rc=$?
	[ $rc -eq 0 ] && grep -q 'continuing from its checkpoint' "$d.err" && ok || bad "resume after $k: exit $rc: $(head -3 "$d.err")"
	same "$d" "killed at $k, resumed"
	cmp -s "$T/ref.out" "$d.out" && ok || bad "killed at $k, resumed: stdout differs"
	[ ! -e "$d/certify-checkpoint.bin" ] && ok || bad "killed at $k: the checkpoint is left after the end"
done

# 2. the same command line after the end: done, nothing run
d="$T/k-run:5"
run --methods $M --resume "$d" > "$T/done.out" 2> "$T/done.err"
rc=$?
[ $rc -eq 0 ] && grep -q 'the work is done' "$T/done.err" && ok || bad "after the end: exit $rc: $(cat "$T/done.err")"
# ... and with other options there: refused, named
run --methods $M --seed 7 --resume "$d" > /dev/null 2> "$T/o.err"
rc=$?
[ $rc -eq 2 ] && grep -q 'seed=1 there, seed=7 here' "$T/o.err" && ok || bad "a finished run of other options: exit $rc: $(cat "$T/o.err")"

# 3. refusals of a checkpoint: other options, another key, corrupted
ONB_CERT_KILL=images:3 run --methods $M --resume "$T/c" --checkpoint-every 0 > /dev/null 2>&1
cp "$T/c/certify-checkpoint.bin" "$T/c.bin"
run --methods $M --budget 41 --resume "$T/c" > /dev/null 2> "$T/c1.err"
rc=$?
[ $rc -eq 2 ] && grep -q 'another command line: budget=40 there, budget=41 here' "$T/c1.err" && ok || bad "other options: exit $rc: $(cat "$T/c1.err")"
run --methods frisvad,naive --resume "$T/c" > /dev/null 2> "$T/c2.err"
rc=$?
[ $rc -eq 2 ] && grep -q 'methods differ' "$T/c2.err" && ok || bad "other methods: exit $rc: $(cat "$T/c2.err")"
# naive's key changed, as another revision of its model would change it
sed 's/^\(group naive float \)[0-9a-f]*$/\10123456789abcdef/' "$T/c.bin" > "$T/c/certify-checkpoint.bin"
run --methods $M --resume "$T/c" > /dev/null 2> "$T/c3.err"
rc=$?
[ $rc -eq 2 ] && grep -q "another revision of naive float's model" "$T/c3.err" && ok || bad "another key: exit $rc: $(cat "$T/c3.err")"
# a byte of the results flipped, and a truncated file
cp "$T/c.bin" "$T/c/certify-checkpoint.bin"
sz=$(wc -c < "$T/c.bin")
printf '\377' | dd of="$T/c/certify-checkpoint.bin" bs=1 seek=$((sz - 1000)) conv=notrunc 2> /dev/null
run --methods $M --resume "$T/c" > /dev/null 2> "$T/c4.err"
rc=$?
[ $rc -eq 2 ] && grep -q 'corrupted' "$T/c4.err" && ok || bad "a flipped byte: exit $rc: $(cat "$T/c4.err")"
head -c $((sz / 2)) "$T/c.bin" > "$T/c/certify-checkpoint.bin"
run --methods $M --resume "$T/c" > /dev/null 2> "$T/c5.err"
rc=$?
[ $rc -eq 2 ] && grep -q 'corrupted' "$T/c5.err" && ok || bad "a truncated checkpoint: exit $rc: $(cat "$T/c5.err")"
[ ! -f "$T/c/certify.csv" ] && ok || bad "a refused checkpoint wrote certify.csv"

# 4. no room for the checkpoint (a file size limit: writes fail as on a
#    full disk): a clear error, the last checkpoint intact, then resumed
cp "$T/c.bin" "$T/c/certify-checkpoint.bin"
lim=$(( $(wc -c < "$T/c.bin") / 1024 - 8 ))
( trap '' XFSZ; ulimit -f $lim; exec ./onbstudy certify $Q --methods $M --resume "$T/c" --checkpoint-every 0 ) > /dev/null 2> "$T/full.err"
rc=$?
[ $rc -ne 0 ] && grep -q 'could not be written' "$T/full.err" && ok || bad "no room: exit $rc: $(head -3 "$T/full.err")"
cmp -s "$T/c.bin" "$T/c/certify-checkpoint.bin" && ok || bad "no room: the last checkpoint changed"
run --methods $M --resume "$T/c" > /dev/null 2> "$T/c6.err" || bad "resume after no room: $(cat "$T/c6.err")"
same "$T/c" "no room, then resumed"

# 5. --resume DIR with no checkpoint yet: from the beginning
run --methods $M --resume "$T/new" > /dev/null 2> "$T/new.err"
grep -q 'no checkpoint there yet: starting from the beginning' "$T/new.err" && ok || bad "a new --resume DIR: $(cat "$T/new.err")"
same "$T/new" "--resume into a new DIR"

# 6. --reuse: frisvad and naive done; adding rtow computes it alone
run --methods frisvad,naive --out "$T/two" > /dev/null 2>&1
run --methods $M --reuse "$T/two" --out "$T/three" > "$T/three.out" 2> "$T/three.err"
grep -q -- '--reuse .*: 2 of 3 methods and precisions re-used' "$T/three.err" 2> /dev/null && ok || bad "adding rtow: $(cat "$T/three.err")"
data "$T/three/certify-times.csv" | awk -F, 'NR > 1 { s[$1] += $7 + $8 + $9 + $10 + $11 + $12 } END { exit !(s["frisvad"] == 0 && s["naive"] == 0 && s["rtow"] > 0) }' &&
	ok || bad "adding rtow: CPU spent on a re-used method"
same "$T/three" "--reuse, one method added"
cmp -s "$T/ref.out" "$T/three.out" && ok || bad "--reuse: stdout differs"
# naive's key changed (its model revised): naive recomputed, frisvad re-used
sed 's/^naive,float,.*/naive,float,0123456789abcdef/' "$T/two/certify-keys.csv" > "$T/k" && mv "$T/k" "$T/two/certify-keys.csv"
run --methods $M --reuse "$T/two" --out "$T/chg" > /dev/null 2> "$T/chg.err"
grep -q '1 of 3 methods and precisions re-used' "$T/chg.err" && ok || bad "a changed key: $(cat "$T/chg.err")"
data "$T/chg/certify-times.csv" | awk -F, 'NR > 1 { s[$1] += $7 + $8 + $9 + $10 + $11 + $12 } END { exit !(s["frisvad"] == 0 && s["naive"] > 0) }' &&
	ok || bad "a changed key: naive not recomputed, or frisvad not re-used"
same "$T/chg" "--reuse with a changed key"

# 7. --check-keys: current, then stale
run --methods $M --check-keys "$T/ref" > "$T/ck.out" 2>&1 && grep -q '3 of 3 keys current' "$T/ck.out" && ok || bad "--check-keys on a current run: $(cat "$T/ck.out")"
run --methods $M --check-keys "$T/two" > "$T/ck2.out" 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q '^stale: naive float' "$T/ck2.out" && grep -q '^stale: rtow float' "$T/ck2.out" && ok || bad "--check-keys on a stale run: exit $rc: $(cat "$T/ck2.out")"
# ... another arithmetic profile is another key
run --methods $M --arith vulkan --check-keys "$T/ref" > "$T/ck3.out" 2> "$T/ck3.err"
[ $? -eq 1 ] && grep -q 'arith=ieee.* there, arith=vulkan' "$T/ck3.err" && ok || bad "--check-keys with --arith vulkan: $(cat "$T/ck3.out" "$T/ck3.err")"

# 9. a kernel changed in its code: rtow's float threshold 0.9f made
#    0.90001f in a copy of onb.h, compiled as the Makefile compiles it
#    (make -n: its flags), with the code keys regenerated and keys.c and
#    onbstudy rebuilt in $T/b; the build's objects are linked, not copied
mkdir -p "$T/inc" "$T/b/lib/split" "$T/b/certify" && cp -r include/libonb "$T/inc/" &&
	sed -i 's/if (fabsf(uw.x) > 0.9f)/if (fabsf(uw.x) > 0.90001f)/' "$T/inc/libonb/onb.h" &&
	! cmp -s include/libonb/onb.h "$T/inc/libonb/onb.h" && ok || bad "rtow's float threshold not found in onb.h"
for o in build/lib/split/outline-*.o; do ln -s "$root/$o" "$T/b/lib/split/"; done
ln -s "$root/build/families" "$T/b/families"; ln -s "$root/build/methods" "$T/b/methods"
ln -s "$root/build/lib/half.o" "$root/build/lib/half_f16c.o" "$T/b/lib/"
rm "$T/b/lib/split/outline-f-rtow.o"
cc_of() { make -s -n -B "$1" 2> /dev/null | grep "^[^ ]*cc .* -o $1\$" | tail -1; }
c1=$(cc_of build/lib/split/outline-f-rtow.o | sed "s| -Iinclude | -I$T/inc -Iinclude |; s| -o build/| -o $T/b/|")
c2=$(cc_of build/certify/keys.o | sed "s| -Ibuild/certify | -I$T/b/certify |; s| -o build/| -o $T/b/|")
c3=$(make -s -n -W libonb.a onbstudy 2> /dev/null | grep '^[^ ]*cc .* -o onbstudy ' |
	sed "s| -o onbstudy | $SAN -o $T/onbstudy |; s| build/libstudy.a | $T/b/certify/keys.o $T/b/lib/split/outline-f-rtow.o build/libstudy.a |")
if eval "$c1 $SAN" && sh scripts/code-keys.sh "$T/b" > "$T/b/certify/code_keys.h" && eval "$c2 $SAN" && eval "$c3"; then ok
else bad "the changed rtow could not be built: '$c1' '$c2' '$c3'"; fi
n=$(diff build/certify/code_keys.h "$T/b/certify/code_keys.h" | grep -c '^> CODE_KEY')
diff build/certify/code_keys.h "$T/b/certify/code_keys.h" | grep -q '^> CODE_KEY("kernel", "rtow", .f.,' && [ "$n" -eq 1 ] &&
	ok || bad "the changed rtow float kernel: $n code checksums changed: $(diff build/certify/code_keys.h "$T/b/certify/code_keys.h" | head -5)"
"$T/onbstudy" certify $Q --methods $M --check-keys "$T/ref" > "$T/ck4.out" 2>&1
rc=$?
[ $rc -eq 1 ] && [ "$(grep -c '^stale: ' "$T/ck4.out")" -eq 1 ] && grep -q '^stale: rtow float' "$T/ck4.out" && ok ||
	bad "--check-keys with the changed rtow: exit $rc: $(cat "$T/ck4.out")"
"$T/onbstudy" certify $Q --methods $M --reuse "$T/ref" --out "$T/chg2" > /dev/null 2> "$T/chg2.err"
grep -q '2 of 3 methods and precisions re-used' "$T/chg2.err" && ok || bad "--reuse with the changed rtow: $(cat "$T/chg2.err")"
data "$T/chg2/certify-times.csv" | awk -F, 'NR > 1 { s[$1] += $7 + $8 + $9 + $10 + $11 + $12 } END { exit !(s["frisvad"] == 0 && s["naive"] == 0 && s["rtow"] > 0) }' &&
	ok || bad "--reuse with the changed rtow: rtow not recomputed, or frisvad or naive not re-used"

# 8. certify --precision half (issues 43 x 46): killed after its 4th region
#    and resumed, the same certify-half.csv rows and stdout as an
#    uninterrupted run (and its keys name the format); then the same line
#    says done; a float checkpoint resumed in half, and a half one in
#    float, are refused with the formats named, exit 2
H="--quick --precision half --methods duff --sectors 1 --depth 2 --azimuths 2"
./onbstudy certify $H --out "$T/href" > "$T/href.out" 2> "$T/href.err" || bad "certify $H: $(cat "$T/href.err")"
ONB_CERT_KILL=run:4 ./onbstudy certify $H --resume "$T/hk" --checkpoint-every 0 > /dev/null 2> /dev/null
rc=$?
[ $rc -ne 0 ] && [ -f "$T/hk/certify-checkpoint.bin" ] && [ ! -f "$T/hk/certify-half.csv" ] && ok ||
	bad "half, ONB_CERT_KILL=run:4: exit $rc, $(ls "$T/hk" 2> /dev/null | tr '\n' ' ')"
grep -q '^settings precision=half ' "$T/hk/certify-checkpoint.bin" && ok || bad "the half checkpoint's settings do not name precision=half"
./onbstudy certify --quick --quiet --precision float --methods duff --resume "$T/hk" > /dev/null 2> "$T/hf.err"
rc=$?
[ $rc -eq 2 ] && grep -q 'checkpoint of certify --precision half, and this run is --precision float' "$T/hf.err" && ok ||
	bad "a half checkpoint resumed in float: exit $rc: $(cat "$T/hf.err")"
./onbstudy certify $H --resume "$T/hk" > "$T/hk.out" 2> "$T/hk.err"
rc=$?
[ $rc -eq 0 ] && grep -q 'continuing from its checkpoint (4 of ' "$T/hk.err" && ok || bad "half resumed: exit $rc: $(cat "$T/hk.err")"
data "$T/href/certify-half.csv" > "$T/href.data"
data "$T/hk/certify-half.csv" 2> /dev/null | cmp -s "$T/href.data" - && ok || bad "half, killed and resumed: certify-half.csv's rows differ"
grep -v '^wrote ' "$T/href.out" > "$T/href.sum"   # the summary, without the output's path
grep -v '^wrote ' "$T/hk.out" | cmp -s "$T/href.sum" - && grep -q '^duff  *half ' "$T/hk.out" && ok || bad "half, killed and resumed: stdout differs"
[ ! -e "$T/hk/certify-checkpoint.bin" ] && grep -q '^duff,half,[0-9a-f]\{16\}$' "$T/hk/certify-keys.csv" && ok ||
	bad "half: a checkpoint left, or no duff,half key: $(cat "$T/hk/certify-keys.csv" 2> /dev/null)"
./onbstudy certify $H --resume "$T/hk" > /dev/null 2> "$T/hd.err"
[ $? -eq 0 ] && grep -q 'the work is done' "$T/hd.err" && ok || bad "half after the end: $(cat "$T/hd.err")"
ONB_CERT_KILL=run:1 run --methods frisvad --resume "$T/fk" --checkpoint-every 0 > /dev/null 2>&1
./onbstudy certify $H --resume "$T/fk" > /dev/null 2> "$T/fh.err"
rc=$?
[ $rc -eq 2 ] && grep -q 'checkpoint of certify --precision float, double or both, and this run is --precision half' "$T/fh.err" &&
	[ -f "$T/fk/certify-checkpoint.bin" ] && ok || bad "a float checkpoint resumed in half: exit $rc: $(cat "$T/fh.err")"

# 10. bad input: exit 2, one message, nothing written
for a in "--checkpoint-every -1" "--checkpoint-every x" "--resume $T/bad1 --out $T/bad2"; do
	run --methods frisvad $a > /dev/null 2> "$T/bad.err"
	rc=$?
	[ $rc -eq 2 ] && [ "$(grep -c '^onbstudy: ' "$T/bad.err")" -eq 1 ] && [ ! -e "$T/bad1" ] && [ ! -e "$T/bad2" ] && ok ||
		bad "certify $a: exit $rc: $(cat "$T/bad.err")"
done
run --methods frisvad --check-keys "$T/none" > /dev/null 2> "$T/bad.err"
[ $? -eq 2 ] && grep -q 'no certify-keys.csv' "$T/bad.err" && ok || bad "--check-keys on a DIR without keys: $(cat "$T/bad.err")"
finish certify_resume
