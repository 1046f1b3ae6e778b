#!/bin/sh
# wild-run.sh - regenerate results/wild/, the committed run of the engines'
# code (docs/wild.md): every registry method that carries a provenance, the
# methods that aliases equal, and this project's NAME_fixed repairs.  The
# paper methods stay in results/reference/ and results/certify/; wild.sh
# reads both certify.csv files (this one's rows win), so a paper method can
# be an engine's drop-in fix.
#   sh scripts/wild-run.sh            (about 30 min on 2 quiet cores)
#   BUDGET=N sh scripts/wild-run.sh   certify's --budget (default 6000)
# Then the charts (PNG, scripts/plots.sh), docs/wild.md and the README's
# engines line are regenerated.
set -eu
cd "$(dirname "$0")/.."
OUT=results/wild
make
mkdir -p "$OUT"
rm -f "$OUT"/*.csv "$OUT"/*.txt "$OUT"/*.log "$OUT"/*.png
rm -rf "$OUT/figures"
eng=$(./onbstudy list --format csv | grep -E ',[0-9a-f]{40},' | cut -d, -f1)
tgt=$(./onbstudy list --aliases --format csv | awk -F, 'NR > 1 { print $2 }')
fix=$(./onbstudy list --format csv | cut -d, -f1 | grep '_fixed$' | grep -v '^stark_fixed$' || true)
M=$(printf '%s\n' $eng $tgt $fix | awk '!seen[$0]++' | paste -sd, -)
echo "wild: methods $M"
echo "wild: sweep"
./onbstudy sweep --methods "$M" --grid 16x32 --quiet --out "$OUT" > "$OUT/sweep.txt" 2> "$OUT/sweep.log"
echo "wild: bench"
./onbstudy bench --methods "$M" --out "$OUT" > "$OUT/bench.txt" 2> "$OUT/bench.log"
./onbstudy table --bench "$OUT/bench.csv" --summary "$OUT/summary.csv" --out "$OUT" > "$OUT/table.txt" 2> "$OUT/table.log"
echo "wild: certify (budget ${BUDGET:-6000})"
t0=$(date +%s)
./onbstudy certify --methods "$M" --budget "${BUDGET:-6000}" --starts "$OUT/worst.csv" --quiet --out "$OUT" \
	> "$OUT/certify.txt" 2> "$OUT/certify.log"
t1=$(date +%s)
echo "wild: plots"
make build/plot-deps.stamp
FIGS=$OUT/figures PCDIR=$OUT NOSVG=1 sh scripts/plots.sh "$OUT" > "$OUT/plots.log" 2>&1
{
	echo "# results/wild: the machine and build of the committed run of the engines' code"
	echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
	echo "revision: $(sed -n "s/^# revision: //p" "$OUT/summary.csv" | head -1) (the binary's, from summary.csv)"
	echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')"
	echo "cores: $(nproc)"
	echo "compiler: $(cc --version | head -1)"
	echo "flags: $(grep -m1 '^# flags:' "$OUT/summary.csv" | sed 's/^# flags: //')"
	echo "batch isa: $(grep -m1 '^# cpu:' "$OUT/summary.csv" | sed 's/.*batch isa: //')"
	echo "methods: $M"
	echo "certify: budget ${BUDGET:-6000}, $((t1 - t0)) s wall"
	echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
	echo "commands: scripts/wild-run.sh (sweep --grid 16x32; bench; table; certify --budget ${BUDGET:-6000} --starts worst.csv; plots.sh, PNG only)"
} > "$OUT/machine.txt"
export REF="$PWD/$OUT" CERT="$PWD/results/certify/certify.csv $PWD/$OUT/certify.csv"
sh scripts/wild.sh --update docs/wild.md
sh scripts/wild.sh --readme --update README.md
echo "wild: $(du -sh "$OUT" | cut -f1) in $OUT"
