#!/bin/sh
# wild-run.sh - regenerate results/wild/, the committed run of the engines'
# code (docs/wild.md): every registry method that carries a provenance, the
# methods that aliases equal, and this project's NAME_fixed repairs.  The
# paper methods stay in results/reference/ and results/certify/; wild.sh
# reads both certify.csv files (this one's rows win), so a paper method can
# be an engine's drop-in fix.
#   sh scripts/wild-run.sh            (about 30 min on 2 quiet cores)
#   BUDGET=N sh scripts/wild-run.sh   certify's --budget (default 200, the
#                                     committed run's)
#   sh scripts/wild-run.sh --add GROUP M1,M2,...
#       the same study (sweep, bench, table, certify; no charts) for the
#       named methods alone, in results/wild/add/GROUP/: engines added after
#       the full run.  scripts/wild.sh reads results/wild and then every
#       results/wild/add/*/ (a later directory's rows of a method win), so
#       an added engine's row is complete without re-running the others.
#       A full run removes results/wild/add/ (its methods are then in it).
# Then the charts (PNG, scripts/plots.sh; full run only), docs/wild.md and
# the README's engines line are regenerated.
set -eu
cd "$(dirname "$0")/.."
usage() { echo "usage: wild-run.sh [--add GROUP METHOD[,METHOD...]]" >&2; exit 2; }
OUT=results/wild; ADD=""
case "${1:-}" in
"") ;;
--add)
	[ $# -eq 3 ] || usage
	printf '%s\n' "$2" | grep -Eq '^[a-z0-9_-]+$' || { echo "wild-run: GROUP '$2' is not [a-z0-9_-]+" >&2; exit 2; }
	printf '%s\n' "$3" | grep -Eq '^[a-z0-9_]+(,[a-z0-9_]+)*$' || { echo "wild-run: '$3' is not a comma-separated list of method names" >&2; exit 2; }
	OUT=results/wild/add/$2; ADD=$3 ;;
*) usage ;;
esac
make
if [ -n "$ADD" ]; then
	M=$ADD
	for m in $(printf '%s\n' "$M" | tr , ' '); do
		./onbstudy list --format csv | cut -d, -f1 | grep -qx "$m" ||
			{ echo "wild-run: '$m' is not a method of the registry (./onbstudy list)" >&2; exit 2; }
	done
else
	eng=$(./onbstudy list --format csv | grep -E ',[0-9a-f]{40},' | cut -d, -f1)
	tgt=$(./onbstudy list --aliases --format csv | awk -F, 'NR > 1 { print $2 }')
	fix=$(./onbstudy list --format csv | cut -d, -f1 | grep '_fixed$' | grep -v '^stark_fixed$' || true)
	M=$(printf '%s\n' $eng $tgt $fix | awk '!seen[$0]++' | paste -sd, -)
fi
# write into a fresh directory and move it in place at the end: a run
# that fails or is stopped leaves the committed one as it was
NEW=results/.wild-run.$$
rm -rf "$NEW"; mkdir -p "$NEW"
trap 'rm -rf "$NEW"' EXIT
echo "wild: methods $M"
echo "wild: sweep"
./onbstudy sweep --methods "$M" --grid 16x32 --quiet --out "$NEW" > "$NEW/sweep.txt" 2> "$NEW/sweep.log"
echo "wild: bench"
./onbstudy bench --methods "$M" --out "$NEW" > "$NEW/bench.txt" 2> "$NEW/bench.log"
./onbstudy table --bench "$NEW/bench.csv" --summary "$NEW/summary.csv" --out "$NEW" > "$NEW/table.txt" 2> "$NEW/table.log"
echo "wild: certify (budget ${BUDGET:-200})"
t0=$(date +%s)
./onbstudy certify --methods "$M" --budget "${BUDGET:-200}" --starts "$NEW/worst.csv" --quiet --out "$NEW" \
	> "$NEW/certify.txt" 2> "$NEW/certify.log"
t1=$(date +%s)
if [ -z "$ADD" ]; then
	echo "wild: plots"
	make build/plot-deps.stamp
	FIGS=$NEW/figures PCDIR=$NEW NOSVG=1 sh scripts/plots.sh "$NEW" > "$NEW/plots.log" 2>&1
fi
{
	echo "# $OUT: the machine and build of the committed run of the engines' code"
	echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
	echo "revision: $(sed -n "s/^# revision: //p" "$NEW/summary.csv" | head -1) (the binary's, from summary.csv)"
	echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')"
	echo "cores: $(nproc)"
	echo "compiler: $(cc --version | head -1)"
	echo "flags: $(grep -m1 '^# flags:' "$NEW/summary.csv" | sed 's/^# flags: //')"
	echo "batch isa: $(grep -m1 '^# cpu:' "$NEW/summary.csv" | sed 's/.*batch isa: //')"
	echo "methods: $M"
	echo "certify: budget ${BUDGET:-200}, $((t1 - t0)) s wall"
	echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
	if [ -n "$ADD" ]; then
		echo "commands: scripts/wild-run.sh --add ${OUT#results/wild/add/} $M (sweep --grid 16x32; bench; table; certify --budget ${BUDGET:-200} --starts worst.csv; no charts)"
	else
		echo "commands: scripts/wild-run.sh (sweep --grid 16x32; bench; table; certify --budget ${BUDGET:-200} --starts worst.csv; plots.sh, PNG only)"
	fi
} > "$NEW/machine.txt"
if [ -n "$ADD" ]; then
	rm -rf "$OUT"; mkdir -p "$(dirname "$OUT")"; mv "$NEW" "$OUT"
else
	# the run's own files only: results/wild/patches/ stays; add/ goes,
	# since its methods are now in this run
	rm -f "$OUT"/*.csv "$OUT"/*.txt "$OUT"/*.log "$OUT"/*.png
	rm -rf "$OUT/figures" "$OUT/add"
	mv "$NEW"/* "$OUT"/
fi
trap - EXIT
rm -rf "$NEW"
sh scripts/wild.sh --update docs/wild.md
sh scripts/wild.sh --readme --update README.md
echo "wild: $(du -sh "$OUT" | cut -f1) in $OUT"
