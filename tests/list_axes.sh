#!/bin/sh
# onbstudy list --axes: each method's b1 and b2 at +-x, +-y and
# +-z, the migration table of docs/library.md.
#  1. six rows per registry method, in both formats;
#  2. every finite frame is orthogonal to n (each dot product exactly 0:
#     the components are 0 or +-1, or one scaled length; babylon's within
#     2^-52: the residues cos(PI/2) = 6.1e-17 and sin(PI) = 1.2e-16 of its
#     angles, which Babylon.js's own doubles have), and det(b1, b2, n)
#     has the sign of the registry's handedness;
#  3. on x86-64 the CSV equals tests/data/axes.csv, so a change to any
#     method's frame at an axis shows up here (the _rsqrt rows are the
#     x86-64 rsqrtss values, hence x86-64 only).  The rsqrtss estimate's
#     bits differ between CPU vendors (Intel and AMD tables), within its
#     documented relative error 1.5 * 2^-12: rows of a method flagged
#     ONB_HW_RSQRT (flags bit 1) match the golden row within 2^-11 of each
#     component (ulp-exact on the CPU that wrote the file); every other row
#     matches exactly.
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
	t = ($1 == "babylon") ? 2.3e-16 : 0
	if (d1 > t || d1 < -t || d2 > t || d2 < -t) print $1 " " $2 ": not orthogonal to n"
	if ($9 != 0 && ($9 > 0 ? 1 : -1) != h[$1]) print $1 " " $2 ": det " $9 ", registry handedness " h[$1]
}' "$tmp/hand" "$tmp/a.csv")
[ -z "$bads" ] && ok || bad "$bads"
./onbstudy list --axes --format nope 2>/dev/null; [ $? -eq 2 ] && ok || bad "bad --format must exit 2"
if [ "$(uname -m)" = x86_64 ]; then
	./onbstudy list --format csv | tail -n +2 | cut -d, -f1,4 > "$tmp/flags"
	changed=$(awk -F, 'FILENAME == ARGV[1] { hw[$1] = ($2 % 2 == 1); next }
		FILENAME == ARGV[2] { g[FNR] = $0; next }
		{ if ($0 == g[FNR]) next
		  split(g[FNR], w, ",")
		  if (!hw[$1] || w[1] != $1 || w[2] != $2 || NF != 9) { print "row " FNR ": " $0; next }
		  for (i = 3; i <= 9; i++) {
			d = $i - w[i]; if (d < 0) d = -d; m = (w[i] < 0) ? -w[i] : w[i]
			if (d > m / 2048 + 1e-300 && !(d == 0)) { print "row " FNR " (hardware rsqrt, beyond 2^-11): " $0; break }
		  } }
		END { if (FNR != length(g)) print "row count " FNR " against " length(g) }' \
		"$tmp/flags" tests/data/axes.csv "$tmp/a.csv")
	if [ -z "$changed" ]; then ok; else bad "frames at the axes changed:"; echo "$changed" | head; diff tests/data/axes.csv "$tmp/a.csv" | head; fi
fi
finish
