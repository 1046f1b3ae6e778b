#!/bin/sh
# certify.sh - `onbstudy certify` (issue 22) end to end, at a reduced size:
# the bracket found <= bound in every region, every measured defect of the
# committed runs below its region's bound (tests/certify_check.c), the same
# file with 1 and 2 threads, found inputs that `eval` replays to the same
# defect, and bad input (exit 2, one line, nothing written).
set -u
cd "$(dirname "$0")/.."
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0; fail=0
ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }
data() { grep -v '^#' "$1"; }

M=frisvad,frisvad_max,duff,duff_branchless,hughes_moeller,naive,tangent_cross_z
Q="--quick --quiet --methods $M"
OMP_NUM_THREADS=2 ./onbstudy certify $Q --out "$T/a" >"$T/a.out" 2>"$T/a.err" || bad "certify --quick failed: $(cat "$T/a.err")"
OMP_NUM_THREADS=1 ./onbstudy certify $Q --precision float --out "$T/b" >/dev/null 2>"$T/b.err" || bad "certify --threads 1 failed"
C="$T/a/certify.csv"
[ -s "$C" ] && ok || bad "no certify.csv"

# 1. the columns, and found <= bound wherever a bound is claimed
head=$(data "$C" | head -1)
[ "$head" = "method,precision,nz_lo,nz_hi,phi_lo,phi_hi,bound,found,found_nx,found_ny,found_nz,status" ] && ok || bad "header: $head"
data "$C" | awk -F, 'NR > 1 && $12 != "singular" && !($7 + 0 >= $8 + 0) { print; n++ } END { exit n > 0 }' >"$T/inv" \
	&& ok || bad "found above bound in $(wc -l <"$T/inv") rows: $(head -2 "$T/inv")"
data "$C" | awk -F, 'NR > 1 && $12 !~ /^(proven|singular|budget)$/ { n++ } END { exit n > 0 }' && ok || bad "a status outside proven/singular/budget"
# the singular sets: naive at -x, tangent_cross_z at the poles; frisvad has none
data "$C" | awk -F, '$1 == "naive" && $5 <= 180 && $6 >= 180 && $3 <= 0 && $4 >= 0 && $12 == "singular" { s++ } END { exit !(s > 0) }' && ok || bad "naive not singular at -x"
data "$C" | awk -F, '$1 == "frisvad" && $12 == "singular" { s++ } END { exit s > 0 }' && ok || bad "frisvad reported singular"

# 2. 1 and 2 threads: the same float rows
data "$T/b/certify.csv" > "$T/b1"; data "$C" | awk -F, 'NR == 1 || $2 == "float"' > "$T/a1"
cmp -s "$T/a1" "$T/b1" && ok || bad "certify.csv differs between 1 and 2 threads"

# 3. soundness: no measured defect of the committed runs above its region's bound
build/tests/certify_check "$C" results/reference/worst.csv results/poles/worst.csv \
	results/poles/north/worst.csv results/poles/south/worst.csv >"$T/chk" 2>&1 && ok || bad "$(cat "$T/chk")"
grep -q 'checked' "$T/chk" && echo "  $(tail -1 "$T/chk")"

# 4. the found inputs replay: eval gives the same defect
data "$C" | awk -F, 'NR > 1 && $1 == "frisvad" && $2 == "float" && $3 == -1 && $4 == 1 { print $9, $10, $11, $8 }' | {
	read -r x y z f || exit 1
	e=$(./onbstudy eval --methods frisvad --precision float -- "$x" "$y" "$z" | awk '/defects:/ { print $NF }' | tr -d ')')
	awk -v a="$e" -v b="$f" 'BEGIN { exit !(a + 0 > 0 && (a - b) / b < 1e-5 && (b - a) / b < 1e-5) }'
} && ok || bad "frisvad's whole-sphere found input does not replay in eval"

# 5. bad input: exit 2, one line, nothing written
for args in "--budget 0" "--tolerance -1" "--tolerance 0.5" "--precision half" "--methods nosuch" "--sectors 0" "stray"; do
	./onbstudy certify $args --out "$T/bad" >/dev/null 2>"$T/e"; rc=$?
	[ $rc -eq 2 ] && [ "$(wc -l <"$T/e")" -eq 1 ] && [ ! -e "$T/bad/certify.csv" ] && ok || bad "certify $args: exit $rc, $(cat "$T/e")"
done

echo "certify.sh: $pass passed, $fail failed"
[ $fail -eq 0 ]
