#!/bin/sh
# What a static link of one libonb function pulls in: the same
# one-function client (onb_duff_branchless_arrayf only) linked against
# libonb.a built at REV (default main) and at the working tree.
#   sh scripts/client-size.sh [REV] [OUT]   (default main, results/clients/size.txt)
# Prints the client's size (text, data, bss: `size`) and how many onb_
# functions it contains, for each.
set -eu
cd "$(dirname "$0")/.."
rev=${1:-main}
outf=${2:-results/clients/size.txt}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/old" "$(dirname "$outf")"
git archive "$rev" | tar -x -C "$tmp/old"
make -s -C "$tmp/old" libonb.a >/dev/null
make -s lib >/dev/null
# the header's path: include/libonb/onb.h now, include/onb.h before
one='\nint main(void) { float n[3] = { 0, 0, 1 }, t[3], b[3]; onb_duff_branchless_arrayf(n, t, b); return t[0] != 1.0f; }\n'
line() { # label include-dir libonb.a
	h=onb.h; [ -f "$2/libonb/onb.h" ] && h=libonb/onb.h
	printf "#include \"$h\"$one" > "$tmp/one.c"
	cc -std=c99 -O2 -I"$2" "$tmp/one.c" "$3" -lm -o "$tmp/one"
	"$tmp/one"
	set -- "$1" $(size "$tmp/one" | awk 'NR == 2 { print $1, $2, $3 }') $(nm "$tmp/one" | awk '$NF ~ /^onb_/' | wc -l)
	printf '%-34s text %6d  data %5d  bss %3d  onb_ symbols %3d\n' "$1" "$2" "$3" "$4" "$5"
}
{
	echo "# scripts/client-size.sh $rev at $(git rev-parse --short=12 HEAD)$(git diff --quiet HEAD -- include src/lib Makefile || echo -dirty), $(date -u +%Y-%m-%dT%H:%MZ); $(cc --version | head -1), cc -std=c99 -O2 one.c libonb.a -lm"
	line "libonb.a at $rev ($(git rev-parse --short=12 "$rev"))" "$tmp/old/include" "$tmp/old/libonb.a"
	line "libonb.a of this tree" include libonb.a
} | tee "$outf"
