#!/bin/sh
# half-certify.sh - regenerate results/half/certify/, the committed
# `certify --precision half` of every registry method (issue 43, item 3).
#   sh scripts/half-certify.sh [--chunks N] [CERTIFY OPTIONS...]
#       every method of `onbstudy list`, in N runs of consecutive methods
#       (default 6: each run's rows are whole, a run that is stopped costs
#       only its own part), each
#         nice -n 10 ./onbstudy certify --precision half --methods CHUNK
#                    --sectors 4 [OPTIONS] --quiet --out PART
#       then one certify-half.csv (the first run's provenance, every run's
#       command and time as '# run:' lines, every region row) and one
#       summary.txt (scripts/half-summary.awk: each method's whole-sphere row).
#   sh scripts/half-certify.sh --redo M1,M2,... [CERTIFY OPTIONS...]
#       the named methods again with the options (a larger --depth or
#       --azimuths): their rows in the committed set are replaced, the
#       run's '# run:' line is added, summary.txt is rebuilt.
# runs.txt lists every run: command, wall and CPU seconds (user + sys of
# the children, from `times`), the load average before and after.
set -eu
cd "$(dirname "$0")/.."
usage() { echo "usage: half-certify.sh [--chunks N | --redo METHOD[,METHOD...]] [CERTIFY OPTIONS...]" >&2; exit 2; }
OUT=results/half/certify; CHUNKS=6; REDO=""
case "${1:-}" in
--chunks) [ $# -ge 2 ] || usage; CHUNKS=$2; shift 2
	printf '%s\n' "$CHUNKS" | grep -Eq '^[1-9][0-9]?$' || { echo "half-certify: --chunks '$CHUNKS' is not 1..99" >&2; exit 2; } ;;
--redo) [ $# -ge 2 ] || usage; REDO=$2; shift 2
	printf '%s\n' "$REDO" | grep -Eq '^[a-z0-9_]+(,[a-z0-9_]+)*$' || { echo "half-certify: '$REDO' is not a comma-separated list of method names" >&2; exit 2; }
	[ -f "$OUT/certify-half.csv" ] || { echo "half-certify: --redo needs a committed $OUT/certify-half.csv" >&2; exit 2; } ;;
esac
[ -x ./onbstudy ] || { echo "half-certify: build ./onbstudy first (make)" >&2; exit 2; }
NEW=results/.half-certify.$$
rm -rf "$NEW"; mkdir -p "$NEW"
trap 'rm -rf "$NEW"' EXIT

# one run: certify the methods $1 into part directory $2, with "$@" after
run() {
	m=$1; d=$2; shift 2
	set -- ./onbstudy certify --precision half --methods "$m" --sectors 4 "$@" --quiet --out "$d"
	l0=$(cut -d' ' -f1 /proc/loadavg); t0=$(date +%s)
	times > "$NEW/times"; c0=$(sed -n 2p "$NEW/times")   # (not in a subshell: its own children)
	nice -n 10 "$@" 2> "$d.log" || { cat "$d.log" >&2; echo "half-certify: run failed: $*" >&2; exit 1; }
	times > "$NEW/times"; c1=$(sed -n 2p "$NEW/times")
	t1=$(date +%s); l1=$(cut -d' ' -f1 /proc/loadavg)
	cpu=$(printf '%s\n%s\n' "$c0" "$c1" | awk '{ gsub(/s/, ""); n = split($0, a, /[ m]/); s = 60 * a[1] + a[2] + 60 * a[3] + a[4] }
		NR == 1 { s0 = s } NR == 2 { printf "%.0f", s - s0 }')
	rev=$(sed -n 's/^# revision: //p' "$d/certify-half.csv" | head -1)
	printf '%s\twall %d s\tcpu %s s\tload %s -> %s\trevision %s\n' "$*" $((t1 - t0)) "$cpu" "$l0" "$l1" "$rev" >> "$NEW/runs.new"
	echo "half-certify: $m: $((t1 - t0)) s wall, $cpu s CPU, load $l0 -> $l1" >&2
}

if [ -n "$REDO" ]; then
	for m in $(printf '%s\n' "$REDO" | tr , ' '); do
		./onbstudy list --format csv | cut -d, -f1 | grep -qx "$m" ||
			{ echo "half-certify: '$m' is not a method of the registry (./onbstudy list)" >&2; exit 2; }
	done
	mkdir -p "$NEW/p"; run "$REDO" "$NEW/p/1" "$@"
	# the old set without the methods' rows, their new rows at the end
	awk -F, -v m="$REDO" 'BEGIN { n = split(m, a, ","); for (i = 1; i <= n; i++) drop[a[i]] = 1 }
		/^#/ || $1 == "method" || !($1 in drop)' "$OUT/certify-half.csv" > "$NEW/old.csv"
	{
		awk '/^# run:/ { print } /^[^#]/ { exit } !/^# run:/ && /^#/ { print }' "$NEW/old.csv" | awk '!/^# run:/'
		grep '^# run:' "$NEW/old.csv"
		sed -n 's/^/# run: /p' "$NEW/runs.new"
		grep -v '^#' "$NEW/old.csv"
		grep -v '^#' "$NEW/p/1/certify-half.csv" | tail -n +2
	} > "$NEW/certify-half.csv"
	cat "$OUT/runs.txt" "$NEW/runs.new" > "$NEW/runs.txt"
else
	M=$(./onbstudy list --format csv | awk -F, 'NR > 1 { print $1 }')
	n=$(printf '%s\n' $M | wc -l)
	per=$(( (n + CHUNKS - 1) / CHUNKS ))
	mkdir -p "$NEW/p"
	k=0
	printf '%s\n' $M | split -l "$per" - "$NEW/p/list."
	for f in "$NEW"/p/list.*; do
		k=$((k + 1)); run "$(paste -sd, "$f")" "$NEW/p/$k" "$@"
	done
	{
		grep '^#' "$NEW/p/1/certify-half.csv" | grep -v '^# command:'
		sed -n 's/^/# run: /p' "$NEW/runs.new"
		grep -v '^#' "$NEW/p/1/certify-half.csv" | head -1
		for d in $(ls -d "$NEW"/p/[0-9]*/ | sort -t/ -k4 -n); do grep -v '^#' "$d/certify-half.csv" | tail -n +2; done
	} > "$NEW/certify-half.csv"
	cp "$NEW/runs.new" "$NEW/runs.txt"
fi
# every method of the set in the registry's order, once
./onbstudy list --format csv | awk -F, 'NR > 1 { print $1 }' > "$NEW/order"
awk -F, 'NR == FNR { o[$1] = FNR; next } !/^#/ && $1 != "method" { print o[$1] "," $0 }' "$NEW/order" "$NEW/certify-half.csv" |
	sort -t, -k1,1n -s | cut -d, -f2- > "$NEW/rows"
{ grep '^#' "$NEW/certify-half.csv"; grep -v '^#' "$NEW/certify-half.csv" | grep '^method,' ; cat "$NEW/rows"; } > "$NEW/sorted.csv"
awk -f scripts/half-summary.awk "$NEW/sorted.csv" > "$NEW/summary.txt"
# README.md: what the directory holds, and every run of runs.txt
{
	echo "# results/half/certify"
	echo
	echo "\`onbstudy certify --precision half\` (binary16; issue 43, item 3) of every"
	echo "method of the registry, made by \`sh scripts/half-certify.sh\`, which writes"
	echo "this file: certify-half.csv holds every region's row (the first run's"
	echo "provenance, every run's command and time as \`# run:\` lines), summary.txt"
	echo "each method's whole-sphere row (scripts/half-summary.awk), runs.txt the"
	echo "runs. The charts certify_half.png and certify_ratio_half.png are drawn by"
	echo "\`NOSVG=1 sh scripts/certify-plot.sh results/half/certify\`."
	echo
	echo "Each run, under \`nice -n 10\`; CPU is the user + sys time of the run's"
	echo "process (\`times\`), load the 1-minute load average before and after"
	echo "(a 2-core machine shared with other jobs):"
	echo
	echo "| run | revision | wall | CPU | load |"
	echo "|---|---|---:|---:|---|"
	awk -F'\t' '{ sub(/^wall /, "", $2); sub(/^cpu /, "", $3); sub(/^load /, "", $4); sub(/^revision /, "", $5)
		printf "| `%s` | %s | %s | %s | %s |\n", $1, ($5 == "" ? "certify-half.csv header" : $5), $2, $3, $4; w += $2; c += $3 }
		END { printf "| all %d runs | | %d s | %d s | |\n", NR, w, c }' "$NEW/runs.txt"
	echo
	echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores"
} > "$NEW/README.md"
mkdir -p "$OUT"
mv "$NEW/README.md" "$OUT/README.md"
mv "$NEW/sorted.csv" "$OUT/certify-half.csv"
mv "$NEW/summary.txt" "$OUT/summary.txt"
mv "$NEW/runs.txt" "$OUT/runs.txt"
trap - EXIT
rm -rf "$NEW"
cat "$OUT/summary.txt"
