#!/bin/sh
# onbstudy list --axes (issue 25): each method's b1 and b2 at +-x, +-y and
# +-z, the migration table of docs/library.md.
#  1. six rows per registry method, in both formats;
#  2. every finite frame is orthogonal to n (each dot product exactly 0:
#     the components are 0 or +-1, or one scaled length), and det(b1, b2, n)
#     has the sign of the registry's handedness;
#  3. on x86-64 the CSV equals tests/data/axes.csv, so a change to any
#     method's frame at an axis shows up here (the _rsqrt rows are the
#     x86-64 rsqrtss values, hence x86-64 only).
. "$(dirname "$0")/lib.sh"
nm=$(./onbstudy list --format csv | tail -n +2 | wc -l)
./onbstudy list --axes --format csv > "$tmp/a.csv" && ok || bad "list --axes --format csv"
./onbstudy list --axes > "$tmp/a.txt" && ok || bad "list --axes"
[ "$(tail -n +2 "$tmp/a.csv" | wc -l)" -eq $((6 * nm)) ] && ok || bad "csv: want $((6 * nm)) rows"
[ "$(grep -c '^ *[a-z_0-9]* *[+-][xyz] ' "$tmp/a.txt")" -eq $((6 * nm)) ] && ok || bad "table: want $((6 * nm)) rows"
./onbstudy list --format csv | tail -n +2 | cut -d, -f1,3 > "$tmp/hand"
bads=$(awk -F, 'NR == FNR { h[$1] = $2 + 0; next } FNR > 1 {
	split($2, a, ""); n[1] = n[2] = n[3] = 0; n[index("xyz", a[2])] = (a[1] == "-") ? -1 : 1
	if ($0 ~ /nan/) next
	d1 = n[1] * $3 + n[2] * $4 + n[3] * $5; d2 = n[1] * $6 + n[2] * $7 + n[3] * $8
	if (d1 != 0 || d2 != 0) print $1 " " $2 ": not orthogonal to n"
	if ($9 != 0 && ($9 > 0 ? 1 : -1) != h[$1]) print $1 " " $2 ": det " $9 ", registry handedness " h[$1]
}' "$tmp/hand" "$tmp/a.csv")
[ -z "$bads" ] && ok || bad "$bads"
./onbstudy list --axes --format nope 2>/dev/null; [ $? -eq 2 ] && ok || bad "bad --format must exit 2"
if [ "$(uname -m)" = x86_64 ]; then
	if cmp -s "$tmp/a.csv" tests/data/axes.csv; then ok; else bad "frames at the axes changed:"; diff tests/data/axes.csv "$tmp/a.csv" | head; fi
fi
finish
