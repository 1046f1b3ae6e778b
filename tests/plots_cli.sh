#!/bin/sh
# plots_cli.sh - `make plots` on a small run: every chart, PNG and SVG,
# non-empty, and gnuplot without a warning (plots.sh fails on one).
. "$(dirname "$0")/lib.sh"
if ! command -v gnuplot >/dev/null 2>&1; then
	echo "plots_cli: gnuplot missing: scripts/install-deps.sh must install it"; exit 1
fi
./onbstudy sweep --samples 2000 --exhaustive-count 1024 --azimuths 2 --grid 8x16 --quiet --out "$tmp/run" >/dev/null 2>&1 || bad "small sweep failed"
./onbstudy threshold --logspaced 300 --consecutive 256 --azimuths 4 --out "$tmp/run" >/dev/null 2>&1 || bad "threshold failed"
if [ -x ./onbstudy ] && ./onbstudy bench --help >/dev/null 2>&1; then
	./onbstudy bench --quick --out "$tmp/run" >/dev/null 2>&1 && ./onbstudy table --bench "$tmp/run/bench.csv" --summary "$tmp/run/summary.csv" --out "$tmp/run" >/dev/null 2>&1 || bad "bench/table failed"
fi
make plots RUN="$tmp/run" > "$tmp/log" 2>&1 || bad "make plots failed: $(cat "$tmp/log")"
grep -qi warning "$tmp/log" && bad "gnuplot warned: $(grep -i warning "$tmp/log")" || ok
for P in float double; do
	for c in error_vs_nz error_vs_nz_rms south_pole maps continuity nonunit threshold; do
		for ext in png svg; do
			[ -s "$tmp/run/${c}_$P.$ext" ] && ok || bad "missing or empty ${c}_$P.$ext"
		done
	done
	if [ -f "$tmp/run/tradeoff.csv" ]; then
		[ -s "$tmp/run/tradeoff_$P.png" ] && ok || bad "missing tradeoff_$P.png"
	fi
done
# a PNG is a PNG
head -c 8 "$tmp/run/maps_float.png" | od -An -tx1 | grep -q "89 50 4e 47" && ok || bad "maps_float.png is not a PNG"
# bad input
sh scripts/plots.sh "$tmp/nothing" >/dev/null 2>&1; [ $? -eq 2 ] && ok || bad "plots.sh on a missing run must exit 2"
finish plots_cli
