#!/bin/sh
# gappa.sh [OUT] - the Gappa cross-check of certify: prove, with Gappa, a
# bound on the orthonormality defect of onb_duff_branchlessf over the region
# of scripts/gappa/duff_branchless_f.g (n.z in [0.5, 0.75], every azimuth,
# n the float rounding of a real unit vector).  Each '#== name' block of the
# script runs as its own Gappa script (the model, then that block); the
# defect's bound is the largest of the proven enclosures.  Prints the
# provenance, Gappa's version, each enclosure (Gappa's exact dyadic bounds,
# then decimal and in units of u = 2^-24, both rounded up) and the bound;
# with OUT, also writes all of it to OUT (atomically).  Exit 1 when Gappa
# fails on any block, prints no enclosure, or warns that a rewriting hint is
# not an identity it could check (the proof would then rest on the hint).
# About 3 minutes on one quiet core (8 at a load of 12 on 2 cores).
set -eu
cd "$(dirname "$0")/.."
G=scripts/gappa/duff_branchless_f.g
out=${1-}
command -v gappa >/dev/null 2>&1 || { echo "gappa.sh: gappa not found (scripts/install-deps.sh --test installs it)" >&2; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/onb_gappa.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
rev=$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- "$G" "$0" 2>/dev/null || rev="$rev-dirty"
{
	echo "# onbstudy gappa.sh: Gappa proof of onb_duff_branchlessf's defect, n.z in [0.5, 0.75]"
	echo "# revision: $rev"
	echo "# gappa: $(gappa --version 2>&1 | head -1)"
	echo "# script: $G (sha256 $(sha256sum "$G" | cut -c1-16))"
	echo "# date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
	echo "# command: scripts/gappa.sh${out:+ $out}"
	echo "# model: float<ieee_32,ne> on every op, no FMA; n = rnd(u), |u| = 1, u.z in [0.5, 0.75]"
} > "$tmp/report"
awk '/^#== /{exit} {print}' "$G" > "$tmp/model.g"
names=$(awk '/^#== /{print $2}' "$G")
fail=0
for q in $names; do
	{ cat "$tmp/model.g"; awk -v q="$q" '/^#== /{on = ($2 == q); next} on' "$G"; } > "$tmp/q.g"
	t0=$(date +%s)
	if ! gappa "$tmp/q.g" > "$tmp/q.out" 2>&1; then
		echo "gappa.sh: Gappa failed on $q:" >&2; cat "$tmp/q.out" >&2; fail=1; continue
	fi
	if grep -q "not trivially equal" "$tmp/q.out"; then
		echo "gappa.sh: $q: a hint is not a checked identity:" >&2; cat "$tmp/q.out" >&2; fail=1; continue
	fi
	line=$(grep ' in \[' "$tmp/q.out" | head -1)
	[ -n "$line" ] || { echo "gappa.sh: $q: no enclosure in Gappa's output" >&2; fail=1; continue; }
	echo "$q $(( $(date +%s) - t0 )) $line" >> "$tmp/results"
done
[ $fail -eq 0 ] || exit 1
# Gappa prints m b e (= m 2^e) exactly; awk's doubles carry 2^-52 relative
# error, so magnitudes are raised by 1e-12 before rounding up to 4 digits.
awk '
function dy(s,   p) { if (!index(s, "b")) return s + 0; split(s, p, "b"); return p[1] * 2 ^ p[2] }
function up(v,   e, d) { v *= 1 + 1e-12; e = int(log(v) / log(10)); if (10 ^ e > v) e--;
	d = int(v / 10 ^ (e - 3)); if (d * 10 ^ (e - 3) < v) d++; return sprintf("%.3fe%d", d / 1000, e) }
function upu(v,   d) { v *= 2 ^ 24 * (1 + 1e-12); d = int(v * 1000); if (d / 1000 < v) d++; return sprintf("%.3f", d / 1000) }
{
	# "name in [LO {dec, 2^e}, HI {dec, 2^e}]", or "[LO, HI]" when exact
	s = $0; sub(/^[^[]*\[/, "", s); sub(/\]$/, "", s)
	if (index(s, "{")) { lo = s; sub(/ .*/, "", lo); hi = s; sub(/^[^}]*\}, /, "", hi); sub(/ .*/, "", hi) }
	else { lo = s; sub(/,.*/, "", lo); hi = s; sub(/^[^,]*, */, "", hi) }
	m = dy(hi); if (-dy(lo) > m) m = -dy(lo)
	printf "%-7s in [%s, %s]  |.| <= %s = %s u  (%s s)\n", $1, lo, hi, up(m), upu(m), $2
	if (m > max) { max = m; at = $1 }
}
END { printf "bound: defect <= %s = %s u (u = 2^-24), largest term %s\n", up(max), upu(max), at }
' "$tmp/results" >> "$tmp/report"
cat "$tmp/report"
if [ -n "$out" ]; then
	mkdir -p "$(dirname "$out")"
	cp "$tmp/report" "$out.tmp" && mv -f "$out.tmp" "$out"
fi
