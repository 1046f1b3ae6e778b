#!/bin/sh
# polecap.sh [DIR] - the southern cap near n = -z on a fine grid in
# (log10(1 + n.z), azimuth), for the pole-cap map: the whole-
# sphere grid of a sweep never comes near 1 + n.z ~ 1e-7, where Frisvad's
# formula fails, and a bin of by_nz.csv keeps no azimuth.
#   DIR/polecap.csv   one_plus_nz,azimuth_deg, then one error column per
#                     method (float; the input: see below)
# (default DIR results/polecap).  NZ (default 112) values of 1 + n.z,
# log-spaced from 1e-8 to 0.1, times AZ (default 72) azimuths; each input
# is the unit vector (r cos a, r sin a, -1 + d), r = sqrt(d (2 - d)), in
# double, rounded to float by `onbstudy eval --precision float`, as a
# renderer's normalized float normal is (its n.z then sits on the float
# grid; the chart's y is d, before rounding); error: the orthonormality
# defect (max of | |b_i| - 1 | and the dots), "nan" for non-finite output.
# Deterministic (no random numbers, no seed); JOBS (default 2) evaluations
# run at once.  Methods: METHODS (default frisvad,frisvad_max,duff).
set -eu
DIR=${1:-results/polecap}
HERE=$(cd "$(dirname "$0")" && pwd)
ONBSTUDY=${ONBSTUDY:-$HERE/../onbstudy}
NZ=${NZ:-112}; AZ=${AZ:-72}; JOBS=${JOBS:-2}; METHODS=${METHODS:-frisvad,frisvad_max,duff}
[ -x "$ONBSTUDY" ] || { echo "polecap: $ONBSTUDY not found (make onbstudy)" >&2; exit 2; }
mkdir -p "$DIR" || { echo "polecap: cannot make $DIR" >&2; exit 2; }
case "$NZ$AZ$JOBS" in *[!0-9]*) echo "polecap: NZ, AZ and JOBS must be whole numbers" >&2; exit 2;; esac
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
start=$(date +%s)
# the inputs: one line "one_plus_nz azimuth x y z" each
awk -v nz="$NZ" -v az="$AZ" 'BEGIN {
	for (i = 0; i < nz; i++) {
		d = 10 ^ (-8 + 7 * i / (nz - 1)); z = -1 + d; r = sqrt(d * (2 - d))
		for (j = 0; j < az; j++) { a = (j + 0.5) * 360 / az; t = a * atan2(0, -1) / 180
			printf "%.17g %.6g %.17g %.17g %.17g\n", d, a, r * cos(t), r * sin(t), z } } }' > "$W/inputs"
# evaluate (JOBS at once), one output line per method: method,1+nz,az,error
n=$(wc -l < "$W/inputs")
xargs -P "$JOBS" -L 1 sh -c '"$0" eval --precision float --methods "$1" -- "$4" "$5" "$6" |
	awk -v d="$2" -v a="$3" -v x="$4" -v y="$5" -v z="$6" '"'"'
		/^[a-z_0-9]+ \(float\)/ { m = $1 }
		/NON-FINITE/ { print m "," d "," a ",nan" }
		/defects:/ { e = $NF; sub(/\)$/, "", e); print m "," d "," a "," e }'"'"'' \
	"$ONBSTUDY" "$METHODS" < "$W/inputs" > "$W/rows" 2> "$W/err" || { cat "$W/err" >&2; echo "polecap: onbstudy eval failed" >&2; exit 1; }
[ -s "$W/err" ] && { cat "$W/err" >&2; echo "polecap: onbstudy eval wrote errors" >&2; exit 1; }
nm=$(echo "$METHODS" | tr ',' '\n' | wc -l)
got=$(wc -l < "$W/rows")
[ "$got" -eq $((n * nm)) ] || { echo "polecap: expected $((n * nm)) rows, got $got" >&2; exit 1; }
secs=$(( $(date +%s) - start ))
{
	echo "# onbstudy polecap (scripts/polecap.sh): the southern cap, float"
	echo "# revision: $("$ONBSTUDY" --version | sed 's/.*(\(.*\)).*/\1/')"
	echo "# compiler: $(cc --version | head -1) (the cc on PATH, which make uses; flags: the Makefile's)"
	echo "# cpu: $(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo 2>/dev/null | head -1)"
	echo "# date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
	echo "# command: NZ=$NZ AZ=$AZ JOBS=$JOBS METHODS=$METHODS sh scripts/polecap.sh $DIR"
	echo "# grid: $(cut -d' ' -f1 "$W/inputs" | sort -u | wc -l) values of 1 + n.z (log-spaced from 1e-8 to 0.1, in double) x $AZ azimuths ((j + 0.5) 360/$AZ degrees); no random numbers (no seed); $JOBS processes"
	echo "# inputs: the unit vector (r cos a, r sin a, -1 + d), r = sqrt(d (2 - d)), in double (a in radians), rounded to float by onbstudy eval; one_plus_nz: d; error: the defect (max), nan: non-finite output"
	echo "# time: $secs s for $got evaluations"
	# one row per input, one column per method
	awk -F, -v ms="$METHODS" 'BEGIN { nm = split(ms, M, ","); printf "one_plus_nz,azimuth_deg"; for (i = 1; i <= nm; i++) printf ",%s", M[i]; print "" }
		{ k = $2 "," $3; if (!(k in e)) ord[++n] = k; e[k, $1] = $4; e[k] = 1 }
		END { for (j = 1; j <= n; j++) { printf "%s", ord[j]; for (i = 1; i <= nm; i++) printf ",%s", e[ord[j], M[i]]; print "" } }' "$W/rows" |
		{ IFS= read -r h; echo "$h"; sort -t, -k1,1g -k2,2g; }
} > "$DIR/polecap.csv.tmp"
mv "$DIR/polecap.csv.tmp" "$DIR/polecap.csv"
echo "polecap: $got evaluations in $secs s, $DIR/polecap.csv"
