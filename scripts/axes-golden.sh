#!/bin/sh
# axes-golden.sh - add a new method's frames at the axes to the golden file
# tests/data/axes.csv (tests/list_axes.sh compares `onbstudy list --axes`
# with it).  Writes the file from ./onbstudy list --axes --format csv, in
# its order, but keeps the committed row wherever the file has one for the
# same method and axis: the _rsqrt rows are the rsqrtss values of the CPU
# that wrote them (Intel and AMD tables differ), and a new method must not
# rewrite them.  x86-64 only, as the file is.  Run from the repository
# root after `make`; then `git diff tests/data/axes.csv` shows the new rows
# alone.
set -eu
[ "$(uname -m)" = x86_64 ] || { echo "axes-golden.sh: tests/data/axes.csv is written on x86-64" >&2; exit 2; }
[ -x ./onbstudy ] || { echo "axes-golden.sh: run make first (no ./onbstudy)" >&2; exit 2; }
g=tests/data/axes.csv
trap 'rm -f "$g.new" "$g.tmp"' EXIT
./onbstudy list --axes --format csv > "$g.new"
awk -F, 'NR == FNR { old[$1 "," $2] = $0; next }
	($1 "," $2) in old { print old[$1 "," $2]; next } { print }' "$g" "$g.new" > "$g.tmp"
mv "$g.tmp" "$g"
