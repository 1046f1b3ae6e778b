#!/bin/sh
# certify-mutate.sh - the mutation check of certify: change one operation
# of certify's rounding model and show that a test catches it.
#   1. model_kit.h (mk_frisvad): frisvad's 1 + n.z done in double instead of the format
#      (a dropped rounding in the model): tests/test_certify.c must find the
#      model no longer bit-exact to the kernel.
#   2. mvf.c: round_to adds no error term (every rounding of every model
#      treated as exact): the bounds drop, and tests/certify_check.c must
#      find measured defects of the committed runs above them.
# Each mutant is built in a copy of the tree; the tree itself is untouched.
# Exit 0 when both mutants are caught.  Output: one line per mutant.
set -u
cd "$(dirname "$0")/.."
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
caught=0
copy() { rm -rf "$W/t"; mkdir -p "$W/t"; git ls-files -z | xargs -0 -I{} cp --parents {} "$W/t/" 2>/dev/null; cp -r .git "$W/t/.git" 2>/dev/null || true; }

copy
sed -i 's|a = DIV(one, sg > 0 ? ADD(one, n\[2\]) : SUB(one, n\[2\]));|a = DIV(one, sg > 0 ? cm_add(c, CM_F64, one, n[2]) : SUB(one, n[2]));|' "$W/t/src/model/model_kit.h"
grep -q 'cm_add(c, CM_F64, one, n\[2\])' "$W/t/src/model/model_kit.h" || { echo "mutant 1 not applied"; exit 2; }
(cd "$W/t" && make -s build/tests/test_certify >/dev/null 2>&1) || { echo "mutant 1 does not build"; exit 2; }
if "$W/t/build/tests/test_certify" 100000 > "$W/m1" 2>&1; then
	echo "mutant 1 (frisvad's 1 + n.z not rounded in the model): NOT caught"
else
	echo "mutant 1 (frisvad's 1 + n.z not rounded in the model): caught by test_certify: $(grep -c '^FAIL' "$W/m1") method-precision pairs not bit-exact"
	caught=$((caught + 1))
fi

copy
sed -i 's|	if (m->zero_e \|\| (h = half_ulp_of(m, x->v, f)) == 0.0)|	if (1 \|\| m->zero_e \|\| (h = half_ulp_of(m, x->v, f)) == 0.0)|' "$W/t/src/model/mvf.c"
grep -q 'if (1 || m->zero_e' "$W/t/src/model/mvf.c" || { echo "mutant 2 not applied"; exit 2; }
(cd "$W/t" && make -s onbstudy build/tests/certify_check >/dev/null 2>&1) || { echo "mutant 2 does not build"; exit 2; }
(cd "$W/t" && ./onbstudy certify --quick --quiet --methods duff_branchless,hughes_moeller,frisvad --out "$W/c2" >/dev/null 2>&1)
if "$W/t/build/tests/certify_check" "$W/c2/certify.csv" results/reference/worst.csv results/poles/worst.csv \
	results/poles/north/worst.csv results/poles/south/worst.csv > "$W/m2" 2>&1; then
	echo "mutant 2 (no rounding error term in the bounds): NOT caught"
else
	echo "mutant 2 (no rounding error term in the bounds): caught by certify_check: $(grep -c '^VIOLATION' "$W/m2") measured defects above their bound"
	caught=$((caught + 1))
fi
[ $caught -eq 2 ]
