#!/bin/sh
# halfscan.sh - `onbstudy halfscan` (issue 43): the binary16 survey finds
# what the format does to three methods on the binary16 roundings of unit
# vectors: duff (a sign branch, no cancellation) stays within a few u =
# 2^-11 with no non-finite basis; frisvad, whose threshold rounds to -1 in
# half, returns NaN at n = -z; physx, whose 0.9999f rounds to 1, returns
# b1 = b2 = 0 at n = +-y (a defect of exactly 1 = 2048u).  A build without
# _Float16 refuses the command with exit 2 and says why.
. "$(dirname "$0")/lib.sh"

./onbstudy halfscan --methods duff,frisvad,physx --azimuths 4 --threads 2 --out "$tmp/hs" > "$tmp/o" 2> "$tmp/e"; rc=$?
if [ $rc -eq 2 ] && grep -q '_Float16' "$tmp/e"; then
	ok; finish halfscan
fi
[ $rc -eq 0 ] && ok || bad "halfscan failed (exit $rc): $(cat "$tmp/e")"
f="$tmp/hs/halfscan.csv"
row() { grep "^$1," "$f"; }
grep -q '^# revision: ' "$f" && ok || bad "halfscan.csv has no provenance"
[ "$(row duff | cut -d, -f2)" = "$((3 * 30721 * 4))" ] && ok || bad "duff: $(row duff | cut -d, -f2) inputs, not every binary16 value of [-1, 1] on 3 axes x 4 azimuths"
row duff | awk -F, '$3 == 0 && $4 > 0 && $4 <= 8 { ok = 1 } END { exit !ok }' && ok || bad "duff in half: $(row duff)"
row frisvad | awk -F, '$3 > 0 && $8 == "0x0p+0" && $9 == "0x0p+0" && $10 == "-0x1p+0" { ok = 1 } END { exit !ok }' && ok || bad "frisvad in half must be non-finite first at (0, 0, -1): $(row frisvad)"
row physx | awk -F, '$4 == 2048 && $5 == "0x0p+0" && ($6 == "0x1p+0" || $6 == "-0x1p+0") { ok = 1 } END { exit !ok }' && ok || bad "physx in half must reach D = 2048u at +-y: $(row physx)"
./onbstudy halfscan --azimuths 0 > /dev/null 2>&1; [ $? -eq 2 ] && ok || bad "halfscan --azimuths 0 must exit 2"
finish halfscan
