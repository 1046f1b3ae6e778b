#!/bin/sh
# babylon-node.sh - the golden bits of the `babylon` row from Node.js itself:
# scripts/babylon-node.js runs Babylon.js's getNormalToRef (completed:
# normalize(), CrossToRef(n, b1)) on N inputs (the axes and signed zeros,
# the poles, the equator, non-unit and non-finite ones, then seeded random
# unit vectors, a quarter near +-y, a quarter near y = 0) and prints every
# value as its 64-bit pattern; tests/test_babylon_node.c compares libonb's
# onb_babylon with them bit for bit.  Needs node (not a build dependency:
# the committed file is the data).
#   sh scripts/babylon-node.sh [N [SEED]] > tests/data/babylon_node.csv
set -eu
HERE=$(cd "$(dirname "$0")" && pwd)
command -v node >/dev/null 2>&1 || { echo "babylon-node: node not found" >&2; exit 1; }
N=${1:-800}
SEED=${2:-44}
case $N$SEED in *[!0-9]*) echo "usage: babylon-node.sh [N [SEED]] (positive integers)" >&2; exit 2 ;; esac
echo "# tests/data/babylon_node.csv: sh scripts/babylon-node.sh $N $SEED; node $(node --version), V8 $(node -p process.versions.v8), $(uname -m); Babylon.js 141e38dddee1ac94408a53bacf22508973697532 math.vector.ts getNormalToRef, normalize, CrossToRef"
node "$HERE/babylon-node.js" "$N" "$SEED"
