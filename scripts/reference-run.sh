#!/bin/sh
# reference-run.sh - regenerate results/reference/, the committed reference
# run that the Findings quote, and then the Findings (docs/findings.md, and
# the README's headlines: scripts/findings.sh) and the published figures
# reproduced (docs/findings.md: scripts/reproduce-md.sh).  Takes about two minutes on 2 cores; run it on a
# quiet machine (the benchmark's figures are only as good as the machine is
# idle).  Kept under 5 MB: the SVG charts are left to `make plots`.
set -eu
cd "$(dirname "$0")/.."
OUT=results/reference
make
mkdir -p "$OUT"
rm -f "$OUT"/*.csv "$OUT"/*.png "$OUT"/*.svg "$OUT"/*.txt
rm -rf "$OUT/fma"
echo "reference: sweep"
./onbstudy sweep --grid 16x32 --quiet --out "$OUT" > "$OUT/sweep.txt" 2> "$OUT/sweep.log"
echo "reference: sweep --fma (every method, uniform and south)"
mkdir -p "$OUT/fma"
./onbstudy sweep --fma --dists uniform,south \
	--quiet --out "$OUT/fma" > "$OUT/fma/sweep.txt" 2> "$OUT/fma/sweep.log"
rm -f "$OUT/fma/by_nz.csv" "$OUT/fma/worst.csv"   # the summary is what the Findings quote
echo "reference: threshold"
./onbstudy threshold --consecutive 1024 --logspaced 1024 --azimuths 64 --out "$OUT" > "$OUT/threshold.txt" 2> "$OUT/threshold.log"
echo "reference: bench"
./onbstudy bench --out "$OUT" > "$OUT/bench.txt" 2> "$OUT/bench.log"
./onbstudy table --bench "$OUT/bench.csv" --summary "$OUT/summary.csv" --out "$OUT" > "$OUT/table.txt" 2> "$OUT/table.log"
echo "reference: plots"
# the README's figures and the pole-cap map (its data: sh scripts/polecap.sh)
# beside the run, PNG only (docs/charts.md)
FIGS=results/figures PCDIR=results/polecap NOSVG=1 sh scripts/plots.sh "$OUT"
echo "reference: renders"
make render > /dev/null
echo "reference: reproduce"
./onbstudy reproduce --out "$OUT" > "$OUT/reproduce.txt" 2> "$OUT/reproduce.log"
echo "reference: mutation testing"
sh scripts/mutate.sh --out "$OUT/mutation.txt" > "$OUT/mutate.log" 2>&1
echo "reference: sampling test"
make build/tests/test_sampling > /dev/null
build/tests/test_sampling > "$OUT/sampling.txt"
{
	echo "# results/reference: the machine and build of the committed reference run"
	echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
	echo "revision: $(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)$(git diff --quiet HEAD -- . ':(exclude)results' 2>/dev/null || echo -dirty)"
	echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')"
	echo "cores: $(nproc)"
	echo "cpu flags (vector): $(grep -m1 '^flags' /proc/cpuinfo | tr ' ' '\n' | grep -E '^(sse2|avx|avx2|fma|avx512f|avx512vl|constant_tsc|nonstop_tsc)$' | tr '\n' ' ')"
	echo "os: $(. /etc/os-release && echo "$PRETTY_NAME"), $(uname -r)"
	echo "compiler: $(cc --version | head -1)"
	echo "mpfr: $(grep -m1 '^# mpfr:' "$OUT/summary.csv" | sed 's/^# mpfr: //')"
	echo "flags: $(grep -m1 '^# flags:' "$OUT/summary.csv" | sed 's/^# flags: //')"
	echo "batch isa: $(grep -m1 '^# cpu:' "$OUT/summary.csv" | sed 's/.*batch isa: //')"
	echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
	echo "commands: scripts/reference-run.sh (sweep --grid 16x32; sweep --fma on every method; threshold --consecutive 1024 --logspaced 1024 --azimuths 64; bench; table; plots; make render; reproduce; scripts/mutate.sh)"
} > "$OUT/machine.txt"
sh scripts/findings.sh --update docs/findings.md
sh scripts/findings.sh --headlines --update README.md
sh scripts/reproduce-md.sh --update docs/findings.md
# the chart captions, the sweep's rate in docs/sweep.md and docs/scene.md's
# cube example quote this run too
sh scripts/findings.sh --charts --update docs/charts.md
sh scripts/findings.sh --section sweeprate --update docs/sweep.md
sh scripts/scene-example.sh --update
echo "reference: $(du -sh "$OUT" | cut -f1) in $OUT"
