#!/bin/sh
# onbstudy bench --quick writes a well-formed bench.csv: provenance and
# '#' lines for timer, TSC and ISA; the header with every column; numeric
# fields numeric; exactly one row per expected combination.  Then
# `onbstudy table` joins it with a small summary.csv.  Bad options exit 2
# with one line.  No assertion on any time.
. "$(dirname "$0")/lib.sh"
# (nothing is compiled here, so $ONB_SANFLAGS needs no handling)

cols="method,precision,mode,threads,size_class,size,bytes,reps,passes,mbases_per_s,mbases_per_s_best,ns_per_call,ns_per_call_best,cycles_per_call,cycles_per_call_best,chain_ns,frac_roofline,vs_yardstick,isa,vectorized,checksum,flag"

# check_csv FILE NMETHODS NYARD NPREC [NFLOATONLY]: prints problems, returns
# non-zero on any.  NFLOATONLY of the methods (ONB_FLOAT_ONLY, flag 16) have
# no double rows.
check_csv() {
	f=$1; nm=$2; ny=$3; np=$4; nfo=${5:-0}
	[ -f "$f" ] || { echo "no $f"; return 1; }
	for k in "# onbstudy" "# revision:" "# compiler:" "# flags:" "# cpu:" "# date:" "# threads:" "# command:" "# timer:" "# isa:" "# sizes:"; do
		grep -q "^$k" "$f" || { echo "missing '$k' line"; return 1; }
	done
	hdr=$(grep -v '^#' "$f" | head -1)
	[ "$hdr" = "$cols" ] || { echo "header: $hdr"; return 1; }
	thr=$(sed -n 's/^# threads: //p' "$f")
	tc=1; [ "$thr" -gt 1 ] && tc=2
	# per precision: roofline 2*tc, batch nm*2*tc, yardstick ny*2*tc, calls 2*nm
	# (float-only methods: float rows only)
	want=$(( np * (2 * tc + nm * 2 * tc + ny * 2 * tc + 2 * nm) - (np - 1) * nfo * (2 * tc + 2) ))
	grep -v '^#' "$f" | tail -n +2 | awk -F, -v want="$want" -v tc="$tc" '
		function isnum(s) { return s ~ /^-?(nan|inf|[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?)$/ }
		{
			n++
			if (NF != 22) { print "line " n ": " NF " fields"; bad = 1; next }
			if ($22 !~ /^(ok|load|spread|load\+spread)$/) { print "line " n ": flag " $22; bad = 1 }
			if ($22 ~ /load/ && $4 + 0 <= 1) { print "line " n ": a 1-thread row flagged load"; bad = 1 }
			for (i = 4; i <= 18; i++) if (i != 5 && !isnum($i)) { print "line " n ": field " i " not numeric: " $i; bad = 1 }
			if (!isnum($21)) { print "line " n ": checksum " $21; bad = 1 }
			if ($2 != "float" && $2 != "double") { print "line " n ": precision " $2; bad = 1 }
			if ($3 !~ /^(batch|yardstick|roofline|call_throughput|call_latency)$/) { print "line " n ": mode " $3; bad = 1 }
			if ($5 != "l2" && $5 != "stream") { print "line " n ": size_class " $5; bad = 1 }
			if ($20 !~ /^(zmm|ymm|xmm|scalar|unknown)$/) { print "line " n ": vectorized " $20; bad = 1 }
			if ($10 == "nan" || $10 + 0 <= 0) { print "line " n ": mbases_per_s " $10; bad = 1 }
			if ($3 == "batch" && $17 == "nan") { print "line " n ": batch row without frac_roofline"; bad = 1 }
			if ($3 == "call_latency" && $16 == "nan") { print "line " n ": latency row without chain_ns"; bad = 1 }
			if ($21 == "nan") { print "line " n ": checksum is nan"; bad = 1 }
			key = $1 "," $2 "," $3 "," $4 "," $5
			if (key in seen) { print "duplicate row " key; bad = 1 }
			seen[key] = 1
		}
		END {
			if (n != want) { print n " rows, want " want; bad = 1 }
			exit bad
		}'
}

nm=$(./onbstudy list --format csv | tail -n +2 | wc -l)
nfo=$(./onbstudy list --format csv | tail -n +2 | awk -F, '{ if (int($4 / 16) % 2) n++ } END { print n + 0 }')
[ "$nfo" -ge 2 ] && ok || bad "onbstudy list: want at least two float-only methods (flag 16), got $nfo"
if ./onbstudy bench --quick --out "$tmp/q" >"$tmp/q.out" 2>"$tmp/q.err"; then ok; else bad "bench --quick failed: $(cat "$tmp/q.err")"; fi
if msg=$(check_csv "$tmp/q/bench.csv" "$nm" 4 2 "$nfo"); then ok; else bad "bench.csv (all methods, both precisions): $msg"; fi
grep -q 'duff_branchless' "$tmp/q.out" && ok || bad "the table on stdout lacks duff_branchless"
ls -a "$tmp/q" | grep -q partial && bad "a temporary file was left behind" || ok

# a subset, one precision, one thread, CSV on stdout
if ./onbstudy bench --quick --methods duff_branchless,stark --precision float --threads 1 --format csv --out "$tmp/s" >"$tmp/s.out" 2>/dev/null; then ok; else bad "bench subset failed"; fi
if msg=$(check_csv "$tmp/s/bench.csv" 2 1 1); then ok; else bad "bench.csv (subset): $msg"; fi
[ "$(grep -c ',float,' "$tmp/s.out")" -eq "$(grep -c ',float,' "$tmp/s/bench.csv")" ] && ok || bad "--format csv differs from bench.csv"

# the trade table on the quick run and a two-method summary
cat > "$tmp/summary.csv" <<'CSV'
# fixture
method,precision,distribution,samples,rmse,max_defect,max_ulp,mean_bits,wrong_handed,nonfinite
duff_branchless,float,uniform,1,1e-8,2e-8,1,0,0,0
duff_branchless,float,south,1,1e-8,3e-8,1,0,0,0
duff_branchless,float,threshold,1,1e-8,4e-8,1,0,0,0
stark,float,uniform,1,1e-8,1e-6,1,0,0,0
stark,float,south,1,1e-8,1e-6,1,0,0,0
stark,float,threshold,1,1e-8,1e-6,1,0,0,0
CSV
if ./onbstudy table --bench "$tmp/s/bench.csv" --summary "$tmp/summary.csv" >"$tmp/t.out" 2>/dev/null; then ok; else bad "table failed"; fi
[ "$(grep -v '^#' "$tmp/s/tradeoff.csv" | wc -l)" -eq 3 ] && ok || bad "tradeoff.csv: want header + 2 rows"
grep -q '^duff_branchless,float,' "$tmp/s/tradeoff.csv" && ok || bad "tradeoff.csv lacks duff_branchless"

# binary16 (--precision half): two methods, one thread.  Every half row
# but the copy roofline's says 'emulated' in its isa column (libonb's half kernels run in float,
# rounded per operation: no hardware half speed) and the '# half:' line
# says so; roofline, batch and the two call modes, no yardstick; live
# checksums; the trade table joins the half speeds with half accuracy.
if ./onbstudy bench --quick --methods duff_branchless,hughes_moeller --precision half --threads 1 --out "$tmp/h" >"$tmp/h.out" 2>"$tmp/h.err"; then ok; else bad "bench --precision half failed: $(cat "$tmp/h.err")"; fi
grep -q '^# half: binary16 arithmetic EMULATED' "$tmp/h/bench.csv" && ok || bad "bench.csv (half) lacks the '# half: ... EMULATED' line"
grep -q 'EMULATED' "$tmp/h.out" && ok || bad "the half table on stdout does not say EMULATED"
if msg=$(grep -v '^#' "$tmp/h/bench.csv" | tail -n +2 | awk -F, '
	{
		n++
		if (NF != 22) { print "line " n ": " NF " fields"; bad = 1; next }
		if ($2 != "half") { print "line " n ": precision " $2; bad = 1 }
		if ($3 != "roofline" && $19 !~ /^emulated-(f16c|soft|inline)$/) { print "line " n ": isa " $19 " (want emulated-*)"; bad = 1 }
		if ($3 == "yardstick") { print "line " n ": a half yardstick"; bad = 1 }
		if ($10 == "nan" || $10 + 0 <= 0) { print "line " n ": mbases_per_s " $10; bad = 1 }
		if ($21 == "nan" || $21 + 0 == 0) { print "line " n ": checksum " $21; bad = 1 }
		if ($3 == "batch" && $17 == "nan") { print "line " n ": batch row without frac_roofline"; bad = 1 }
		rows[$3]++
	}
	END {
		if (n != 2 + 2 * 2 + 2 * 2) { print n " rows, want 10"; bad = 1 }
		if (rows["roofline"] != 2 || rows["batch"] != 4 || rows["call_throughput"] != 2 || rows["call_latency"] != 2) { print "modes: roofline " rows["roofline"] " batch " rows["batch"] " calls " rows["call_throughput"] "/" rows["call_latency"]; bad = 1 }
		exit bad
	}'); then ok; else bad "bench.csv (half): $msg"; fi
# the checksums are the outputs': the same seed gives the same sums
./onbstudy bench --quick --methods duff_branchless,hughes_moeller --precision half --threads 1 --format csv --out "$tmp/h2" >/dev/null 2>&1
[ "$(grep -v '^#' "$tmp/h/bench.csv" | cut -d, -f1-3,5,21)" = "$(grep -v '^#' "$tmp/h2/bench.csv" | cut -d, -f1-3,5,21)" ] && ok || bad "half checksums differ between two runs of one seed"
cat > "$tmp/hsum.csv" <<'CSV'
# fixture
method,precision,distribution,samples,rmse,max_defect,max_ulp,mean_bits,wrong_handed,nonfinite
duff_branchless,half,uniform,1,1e-4,2e-3,1,0,0,0
duff_branchless,half,south,1,1e-4,3e-3,1,0,0,0
duff_branchless,half,threshold,1,1e-4,4e-3,1,0,0,0
hughes_moeller,half,uniform,1,1e-4,1e-2,1,0,0,0
hughes_moeller,half,south,1,1e-4,1e-2,1,0,0,0
hughes_moeller,half,threshold,1,1e-4,1e-2,1,0,0,0
CSV
if ./onbstudy table --precision half --bench "$tmp/h/bench.csv" --summary "$tmp/hsum.csv" --format csv >"$tmp/ht.out" 2>/dev/null; then ok; else bad "table --precision half failed"; fi
awk -F, '$1 == "duff_branchless" && $2 == "half" && $3 + 0 > 0 && $12 == "1"' "$tmp/ht.out" | grep -q . && ok || bad "table --precision half: duff_branchless lacks its half speed or front mark: $(cat "$tmp/ht.out")"

# bad options: exit 2, one line on stderr, no file
for args in "--precision quarter" "--methods nope" "--methods duff," "--threads -1" "--format xml" "--bogus" "--out" "--stream-mib 0"; do
	./onbstudy bench --quick $args --out "$tmp/bad" >/dev/null 2>"$tmp/err"
	rc=$?
	if [ $rc -eq 2 ] && [ "$(wc -l < "$tmp/err")" -eq 1 ] && [ ! -e "$tmp/bad/bench.csv" ]; then ok; else bad "bench $args: exit $rc, stderr: $(cat "$tmp/err")"; fi
done
./onbstudy table --bench "$tmp/none.csv" --summary "$tmp/summary.csv" >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && [ "$(wc -l < "$tmp/err")" -eq 1 ] && ok || bad "table with a missing file: $(cat "$tmp/err")"

finish
