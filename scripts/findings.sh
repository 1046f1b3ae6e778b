#!/bin/sh
# findings.sh - the Findings (docs/findings.md) and the README's headline
# findings, generated from the committed reference run, so that every number
# in them comes from a CSV file.
#   sh scripts/findings.sh [--headlines]                 print the section
#   sh scripts/findings.sh [--headlines] --update FILE   replace it in FILE
#   sh scripts/findings.sh [--headlines] --check FILE    exit 1 if FILE's differs
#   sh scripts/findings.sh --certify ...                 docs/certify.md's results
# The text is scripts/findings.md.in (the full Findings, between the markers
# <!-- findings:begin ... --> and <!-- findings:end -->), or with --headlines
# scripts/headlines.md.in (the README's at most ten, between
# <!-- headlines:begin ... --> and <!-- headlines:end -->); in them,
#   {{S method precision distribution column}}  a summary.csv value (%.3g)
#   {{TH precision key field}}  from threshold.csv's '# minimax KEY' or
#                               '# published KEY' lines (key: both,
#                               orthogonality, Frisvad, Max; field: t, 1pt,
#                               max_normality, max_orthogonality, max_both)
#   {{THH precision key field}}  the same from results/half/threshold/threshold.csv
#                               (threshold --precision all: float, double, half)
#   {{HS method distribution column}}  a half row of results/half/sweep/summary.csv
#                               (sweep --precision half); HSU: it / 2^-11, in u
#   {{CH method key}}  from results/half/certify/certify-half.csv (certify
#                      --precision half, scripts/half-certify.sh): the
#                      whole-sphere bound, found (u = 2^-11), ratio,
#                      regions, proven, non-finite, overflow, unbounded,
#                      where (the n.z span of the regions with no bound)
#   {{CHLIST kind}}    its methods: proven, within2, loose (bound > 2x
#                      found), nonfinite, unbounded, overflow, all; CHN: how many
#   {{CHP dir method key}}  bound, found or ratio of a partial run in
#                      results/half/certify/DIR/certify-half.csv
#   {{TABLE half}}     every method: that bracket beside the halfscan's
#                      and the half sweep's maxima
#   {{X method precision column}}  a tradeoff.csv value
#   {{F method precision distribution column}}  a fma/summary.csv value
#   {{R method field}}  from renders/summary.txt (mean, max, pixels, nan)
#   {{RB method field}}  from renders/brushed/summary.txt (max, pixels, nan)
#   {{PARETO precision}}  the methods tradeoff.csv marks on the Pareto front
#   {{MUT key}}  a 'key: value' line of mutation.txt (scripts/mutate.sh)
#   {{TABLE accuracy precision}}    the accuracy table of one precision
#   {{TABLE tradeoff}}              the speed-accuracy table
#   With --certify: scripts/certify.md.in into docs/certify.md, from
#   results/certify/certify.csv:
#   {{TABLE certify}}               every method's whole-sphere bracket
#   {{TABLE certifybands method precision}}  the bands of n.z <= -0.9
#   {{TABLE certifyfma D}}          every method: whole-sphere bracket and
#                                   its +fma row, from results/certify/D
#   {{CW dir method precision column}}  bound or found of the first row of
#                                   results/certify/dir/certify.csv, in u
#   {{CP key}}                      a '# key: value' line of certify.csv
#   With --charts: scripts/charts.md.in into docs/charts.md; any mode:
#   {{PC method stat}}  from results/polecap/polecap.csv, the method's
#                       column: max, maxat (its 1 + n.z), bandlo, bandhi
#                       (the rows whose largest defect is above 0.01),
#                       rowratio (the largest max / min within one such row)
#   {{PCBAND method}}   where the method's rows are above 0.01, gaps said
#   {{PCH key}}         its header: evals, secs, nz, az, procs
#   {{THTR precision normality|orthogonality}}  how that error of
#                       threshold.csv changes as 1 + t grows ("falls from
#                       A to B", "rises ...", "falls ... then rises ..."),
#                       failing on any other shape
#   {{CONT precision list|max|next|cell}}  the continuous frame fields of
#                       the grid (max_b1_jump < 0.5), their largest jump,
#                       the smallest jump of the others, the cell size;
#                       failing when no such gap exists
#   {{RATE key}}        summary.csv's '# rate:' line: evals, secs,
#                       persec, perthread, threads
#   {{FASTEST precision}}  the fastest method, and what beats it by the rule
#   {{PTOL}}            the Pareto rule's speed tolerance, in % (tradeoff.csv)
#   {{INPUTS prec/dist}} summary.csv's '# inputs:' count (float/threshold);
#                       INPUTSC: with thousands separators
#   {{GRID}}            the equal-area grid of summary.csv (16x32)
#   {{BZ method precision distribution bin|max|floor}}  by_nz.csv's bin of
#                       1 + n.z (log axis) holding the method's largest
#                       error: "LO to HI", that error, or its floor there
#   {{PS pole method distribution column}}  results/poles/POLE/summary.csv
#   With --section NAME: scripts/NAME.md.in between the markers
#   <!-- NAME:begin ... --> and <!-- NAME:end --> of any doc (docs/sweep.md's
#   reference-run rate: --section sweeprate).
#   With --quotes [--check]: every line of scripts/quotes.in ("FILE<tab>
#   text") must appear, its placeholders filled, in FILE (docs/sweep.md,
#   docs/reference.md, ...: the numbers of their prose checked where it
#   stands); any mode:
#   {{V path key column}}  a value of a CSV file under results/ (path
#                       relative to it), the row whose first field is key,
#                       the column by name, as written; VC: with thousands
#                       separators (3,451,513)
#   With --onbh: scripts/onbh.in into include/libonb/onb.h's header comment:
#   {{ONBH}}                        one comment line per method
#   {{CR method precision}}  (any mode) bound / found of the whole-sphere
#                                   row, to 2 decimals
#   {{CB method precision column}}  (any mode) bound or found of the
#                                   whole-sphere row of certify.csv
#   Optional values ("n/a" when the reference run predates them,
#   instead of failing): {{SO method precision distribution column}},
#   {{XO method precision column}}, ratios {{SR method precision
#   distribution column1 column2}} (column1 / column2 of one summary.csv
#   row) and {{XR method1 method2 precision column}} (method1's tradeoff.csv
#   value / method2's); {{TABLE floor precision}} (each method against the
#   accuracy floor on uniform) and {{TABLE floordist precision}} (the floor
#   and the Duff methods per distribution).
set -eu
HERE=$(cd "$(dirname "$0")" && pwd)
. "$HERE/splice.sh"
REF=${REF:-$HERE/../results/reference}
TPL=${FINDINGS_TPL:-$HERE/findings.md.in}
BEGIN_MARK='<!-- findings:begin (generated by scripts/findings.sh from results/reference; edit scripts/findings.md.in) -->'
END_MARK='<!-- findings:end -->'
WHAT="Findings"
SRC=results/reference
if [ "${1:-}" = --headlines ]; then
	shift
	TPL=$HERE/headlines.md.in
	BEGIN_MARK='<!-- headlines:begin (generated by scripts/findings.sh --headlines from results/reference; edit scripts/headlines.md.in) -->'
	END_MARK='<!-- headlines:end -->'
	WHAT="headline findings"
elif [ "${1:-}" = --onbh ]; then
	shift
	TPL=$HERE/onbh.in
	BEGIN_MARK=' * Proven bounds (generated by scripts/findings.sh --onbh from results/certify/certify.csv; edit scripts/onbh.in):'
	END_MARK=' * (end of the proven bounds)'
	WHAT="proven bounds"
	SRC=results/certify
elif [ "${1:-}" = --charts ]; then
	shift
	TPL=$HERE/charts.md.in
	BEGIN_MARK='<!-- charts:begin (generated by scripts/findings.sh --charts from results/; edit scripts/charts.md.in) -->'
	END_MARK='<!-- charts:end -->'
	WHAT="chart captions"
	SRC=results
elif [ "${1:-}" = --section ]; then
	# a section of any doc: scripts/NAME.md.in between its markers
	NAME=${2:?usage: findings.sh --section NAME --update|--check FILE}
	shift 2
	TPL=$HERE/$NAME.md.in
	[ -f "$TPL" ] || { echo "findings: no $TPL" >&2; exit 2; }
	BEGIN_MARK="<!-- $NAME:begin (generated by scripts/findings.sh --section $NAME; edit scripts/$NAME.md.in) -->"
	END_MARK="<!-- $NAME:end -->"
	WHAT="section $NAME"
	SRC=results
elif [ "${1:-}" = --quotes ]; then
	# not a section: each line of scripts/quotes.in is "FILE<tab>text"; the
	# text, its placeholders filled, must appear in FILE as it stands
	shift
	TPL=$HERE/quotes.in
	WHAT="quoted numbers"
	SRC=results
elif [ "${1:-}" = --certify ]; then
	shift
	TPL=$HERE/certify.md.in
	BEGIN_MARK='<!-- certify:begin (generated by scripts/findings.sh --certify from results/certify; edit scripts/certify.md.in) -->'
	END_MARK='<!-- certify:end -->'
	WHAT="certify results"
	SRC=results/certify
fi

generate() {
	awk -v REF="$REF" '
	function load(file, arr, keycols,   line, n, f, k, i, hdr, nh, h, chunk, nc) {
		nh = 0; chunk = ""; nc = 0
		while ((getline line < file) > 0) {
			if (line ~ /^#/) { comments[file] = comments[file] line "\n"; continue }
			n = split(line, f, ",")
			if (!nh) { nh = n; for (i = 1; i <= n; i++) h[i] = f[i]; hdrs[file] = line; continue }
			k = ""
			for (i = 1; i <= split(keycols, kc, " "); i++) k = k (i > 1 ? SUBSEP : "") f[kc[i]]
			for (i = 1; i <= n; i++) arr[k, h[i]] = f[i]
			chunk = chunk k "\n"   # in chunks: appending each row to rows[file] copies it all each time
			if (++nc % 256 == 0) { rows[file] = rows[file] chunk; chunk = "" }
		}
		rows[file] = rows[file] chunk
		close(file)
	}
	function fmt(v) {
		if (v == "" ) return "?"
		if (v ~ /nan/) return "n/a"
		if (v ~ /inf/) return "inf"
		if (v + 0 == 0) return "0"
		if (v + 0 >= 1e6 || v + 0 <= -1e6) return sprintf("%.3g", v + 0)  # 1.58e+13, not 15772600000000
		if (v + 0 >= 100 || v + 0 <= -100) return sprintf("%.0f", v + 0)
		return sprintf("%.3g", v + 0)
	}
	function S(m, p, d, c,   k) {
		k = m SUBSEP p SUBSEP d
		if (!((k, c) in SUM)) { print "findings: no " m "," p "," d "," c " in summary.csv" > "/dev/stderr"; bad = 1; return "?" }
		return fmt(SUM[k, c])
	}
	function F(m, p, d, c,   k) {
		k = m SUBSEP p SUBSEP d
		if (!((k, c) in FMA)) { print "findings: no " m "," p "," d "," c " in fma/summary.csv" > "/dev/stderr"; bad = 1; return "?" }
		return fmt(FMA[k, c])
	}
	# the brushed renders (make render-brushed: renders/brushed/summary.txt)
	function RB(m, field,   f, line, a, n) {
		f = REF "/renders/brushed/summary.txt"
		while ((getline line < f) > 0) {
			n = split(line, a, /[ \t]+/)
			if (a[1] != m || a[3] != "brushed:") continue
			close(f)
			if (field == "max") return a[9]
			if (field == "pixels") return a[13]
			if (field == "nan") return a[16]
		}
		close(f)
		print "findings: no brushed render " m " " field > "/dev/stderr"; bad = 1; return "?"
	}
	function RN(m, field,   f, line, a, n, i) {
		f = REF "/renders/summary.txt"
		while ((getline line < f) > 0) {
			n = split(line, a, /[ \t]+/)
			if (a[1] != m) continue
			close(f)
			if (field == "mean") return a[5]
			if (field == "max") return a[7]
			if (field == "pixels") return a[11]
			if (field == "nan") return a[14]
		}
		close(f)
		print "findings: no render " m " " field > "/dev/stderr"; bad = 1; return "?"
	}
	function SO(m, p, d, c,   k) {
		k = m SUBSEP p SUBSEP d
		return ((k, c) in SUM) ? fmt(SUM[k, c]) : "n/a"
	}
	function SR(m, p, d, c1, c2,   k) {
		k = m SUBSEP p SUBSEP d
		if (!((k, c1) in SUM) || !((k, c2) in SUM) || SUM[k, c1] ~ /nan/ || SUM[k, c2] ~ /nan/ || SUM[k, c2] + 0 == 0) return "n/a"
		return sprintf("%.2f", SUM[k, c1] / SUM[k, c2])
	}
	function XO(m, p, c,   k) {
		k = m SUBSEP p
		return ((k, c) in TRD) ? fmt(TRD[k, c]) : "n/a"
	}
	function XR(m1, m2, p, c) {
		if (!((m1 SUBSEP p, c) in TRD) || !((m2 SUBSEP p, c) in TRD) || TRD[m1 SUBSEP p, c] ~ /nan/ || TRD[m2 SUBSEP p, c] + 0 == 0) return "n/a"
		return sprintf("%.2f", TRD[m1 SUBSEP p, c] / TRD[m2 SUBSEP p, c])
	}
	function table_floor(p,   out, i, m, k, n) {
		out = "| method | max defect, uniform | floor max | x floor (max / max) | per-input ratio: RMS | per-input ratio: max | inputs at the floor | input of the largest ratio |\n|---|---:|---:|---:|---:|---:|---:|---|\n"
		n = 0
		for (i = 1; i <= nmeth; i++) {
			m = meth[i]; k = m SUBSEP p SUBSEP "uniform"
			if (!((k, "max_floor") in SUM) || SUM[k, "max_floor"] ~ /nan/) continue
			out = out "| `" m "` | " fmt(SUM[k, "max_defect"]) " | " fmt(SUM[k, "max_floor"]) " | " SR(m, p, "uniform", "max_defect", "max_floor") " | " fmt(SUM[k, "rms_floor_ratio"]) " | " fmt(SUM[k, "max_floor_ratio"]) " | " sprintf("%.1f%%", 100 * SUM[k, "at_floor"]) " | (" SUM[k, "floor_ratio_nx"] ", " SUM[k, "floor_ratio_ny"] ", " SUM[k, "floor_ratio_nz"] ") |\n"
			n++
		}
		return n ? out : "(The reference run predates the floor: regenerate it with `sh scripts/reference-run.sh`.)\n"
	}
	function table_floordist(p,   out, dl, nd, i, d, n, k) {
		nd = split("uniform north south exhaustive threshold nonunit grid", dl, " ")
		out = "| distribution | floor max | floor RMS | `duff_branchless` max | `duff_wide` max | `duff_comp` max | `duff_wide` max / floor max |\n|---|---:|---:|---:|---:|---:|---:|\n"
		n = 0
		for (i = 1; i <= nd; i++) {
			d = dl[i]; k = "duff_branchless" SUBSEP p SUBSEP d
			if (!((k, "max_floor") in SUM) || SUM[k, "max_floor"] ~ /nan/) continue
			out = out "| " d " | " fmt(SUM[k, "max_floor"]) " | " fmt(SUM[k, "rms_floor"]) " | " fmt(SUM[k, "max_defect"]) " | " SO("duff_wide", p, d, "max_defect") " | " SO("duff_comp", p, d, "max_defect") " | " SR("duff_wide", p, d, "max_defect", "max_floor") " |\n"
			n++
		}
		return n ? out : "(The reference run predates the floor: regenerate it with `sh scripts/reference-run.sh`.)\n"
	}
	function PC(m, st,   v) {
		if (!((m, "max") in PCS)) { print "findings: no " m " in polecap.csv" > "/dev/stderr"; bad = 1; return "?" }
		v = PCS[m, st]
		if (st == "maxat" || st == "bandlo" || st == "bandhi") return sprintf("%.2g", v)
		if (st == "rowratio") return sprintf("%.2f", v)
		return fmt(v)
	}
	function PCH(k) { if (!(k in PCHD)) { print "findings: no " k " in polecap.csv header" > "/dev/stderr"; bad = 1; return "?" } return PCHD[k] }
	function RATE(k) { if (!(k in RATED)) { print "findings: no " k " in summary.csv # rate line" > "/dev/stderr"; bad = 1; return "?" } return RATED[k] }
	function PS(pole, m, d, c,   f, line, n, a, i, h, nh) {
		f = REF "/../poles/" pole "/summary.csv"; nh = 0
		while ((getline line < f) > 0) {
			if (line ~ /^#/) continue
			n = split(line, a, ",")
			if (!nh) { nh = n; for (i = 1; i <= n; i++) h[a[i]] = i; continue }
			if (a[1] == m && a[2] == "float" && a[3] == d && (c in h)) { close(f); return fmt(a[h[c]]) }
		}
		close(f)
		print "findings: no " m " " d " " c " in " f > "/dev/stderr"; bad = 1; return "?"
	}
	# the pole-cap run (scripts/polecap.sh): per method column, its largest
	# defect and where, the band above 0.01 and the spread within its rows
	function load_polecap(   f, line, n, a, i, hd, d, v, m) {
		f = REF "/../polecap/polecap.csv"
		while ((getline line < f) > 0) {
			if (line ~ /^# grid:/) { split(line, a, " "); PCHD["nz"] = a[3]; for (i = 1; i <= 40; i++) if (a[i] == "azimuths" && a[i - 1] ~ /^[0-9]+$/) PCHD["az"] = a[i - 1]; if (match(line, /[0-9]+ processes/)) PCHD["procs"] = substr(line, RSTART, RLENGTH - 10) + 0 }
			if (line ~ /^# time:/) { split(line, a, " "); PCHD["secs"] = a[3]; PCHD["evals"] = a[6] }
			if (line ~ /^#/) continue
			n = split(line, a, ",")
			if (a[1] == "one_plus_nz") { for (i = 3; i <= n; i++) hd[i] = a[i]; continue }
			d = a[1] + 0
			for (i = 3; i <= n; i++) {
				m = hd[i]; v = (a[i] ~ /nan|inf/) ? 1e300 : a[i] + 0
				if (!((m, "max") in PCS) || v > PCS[m, "max"]) { PCS[m, "max"] = v; PCS[m, "maxat"] = d }
				if (!((m, d) in rmx) || v > rmx[m, d]) rmx[m, d] = v
				if (!((m, d) in rmn) || v < rmn[m, d]) rmn[m, d] = v
				rows[m, d] = 1
			}
		}
		close(f)
		for (k in rows) { split(k, a, SUBSEP); m = a[1]; d = a[2]
			if (rmx[m, d] <= 0.01) continue
			if (!((m, "bandlo") in PCS) || d + 0 < PCS[m, "bandlo"]) PCS[m, "bandlo"] = d + 0
			if (!((m, "bandhi") in PCS) || d + 0 > PCS[m, "bandhi"]) PCS[m, "bandhi"] = d + 0
			if (rmn[m, d] > 0 && rmx[m, d] / rmn[m, d] > PCS[m, "rowratio"]) PCS[m, "rowratio"] = rmx[m, d] / rmn[m, d] }
	}
	# the by_nz.csv bin (log10 1 + n.z axis) holding the largest error of a method
	# lies: "LO to HI" in 1 + n.z, and the floor of that bin
	function BZ(m, p, d, what,   f, line, a, n, best, lo, hi, fl, h, i, nh) {
		f = REF "/by_nz.csv"; best = -1; nh = 0
		while ((getline line < f) > 0) {
			if (line ~ /^#/) continue
			n = split(line, a, ",")
			if (!nh) { nh = n; for (i = 1; i <= n; i++) h[a[i]] = i; continue }
			if (a[1] != m || a[2] != p || a[3] != d || a[4] != "log10_1pnz" || a[h["max"]] ~ /nan|inf/) continue
			if (a[h["max"]] + 0 > best) { best = a[h["max"]] + 0; lo = a[5]; hi = a[6]; fl = a[h["floor_max"]] }
		}
		close(f)
		if (best < 0) { print "findings: no " m " " p " " d " bins in by_nz.csv" > "/dev/stderr"; bad = 1; return "?" }
		if (what == "floor") return fmt(fl)
		if (what == "max") return fmt(best)
		return sprintf("%.2g to %.2g", 10 ^ lo, 10 ^ hi)
	}
	function commas(v,   o) { o = ""; while (length(v) > 3 && v ~ /^[0-9]+$/) { o = "," substr(v, length(v) - 2) o; v = substr(v, 1, length(v) - 3) } return v o }
	function V(path, key, col, comma,   f, line, n, a, i, h, nh, v, o) {
		f = REF "/../" path; nh = 0
		while ((getline line < f) > 0) {
			if (line ~ /^#/) continue
			n = split(line, a, ",")
			if (!nh) { nh = n; for (i = 1; i <= n; i++) h[a[i]] = i; continue }
			if (a[1] == key && (col in h)) { close(f); v = a[h[col]]
				if (!comma) return v
				o = ""; while (length(v) > 3 && v ~ /^[0-9]+$/) { o = "," substr(v, length(v) - 2) o; v = substr(v, 1, length(v) - 3) }
				return v o }
		}
		close(f)
		print "findings: no " key " " col " in " f > "/dev/stderr"; bad = 1; return "?"
	}
	# results/half/sweep/summary.csv (sweep --precision half): a value of the
	# half row of method and distribution (HS), or it in units of u = 2^-11 (HSU)
	function HS(m, d, col, inu,   f, line, n, a, i, h, nh, v) {
		f = REF "/../half/sweep/summary.csv"; nh = 0
		while ((getline line < f) > 0) {
			if (line ~ /^#/) continue
			n = split(line, a, ",")
			if (!nh) { nh = n; for (i = 1; i <= n; i++) h[a[i]] = i; continue }
			if (a[1] == m && a[2] == "half" && a[3] == d && (col in h)) { close(f); v = a[h[col]]
				return inu && v !~ /nan|inf/ ? fmt(v * 2048) : fmt(v) }
		}
		close(f)
		print "findings: no " m " half " d " " col " in " f > "/dev/stderr"; bad = 1; return "?"
	}
	# results/half/certify/certify-half.csv (certify --precision half of
	# every method, scripts/half-certify.sh): per method the whole-sphere
	# bracket, the largest bound and found over its regions (no bound where
	# a region is not proven), the regions by status and the n.z they span
	function load_ch(   f, line, a, n, m, i, st) {
		if (CHN) return
		f = REF "/../half/certify/certify-half.csv"
		while ((getline line < f) > 0) {
			if (line ~ /^#/) continue
			n = split(line, a, ",")
			if (a[1] == "method") { for (i = 1; i <= n; i++) chc[a[i]] = i; continue }
			m = a[1]; st = a[chc["status"]]
			if (!(m in CHB)) { CHM[++CHN] = m; CHB[m] = 0; CHF[m] = 0 }
			CHR[m]++; CHS[m, st]++
			if (st != "proven") { CHBAD[m] = 1
				if (!((m, "lo") in CHW) || a[chc["nz_lo"]] + 0 < CHW[m, "lo"]) CHW[m, "lo"] = a[chc["nz_lo"]] + 0
				if (!((m, "hi") in CHW) || a[chc["nz_hi"]] + 0 > CHW[m, "hi"]) CHW[m, "hi"] = a[chc["nz_hi"]] + 0 }
			else if (a[chc["bound"]] + 0 > CHB[m]) CHB[m] = a[chc["bound"]] + 0
			if (a[chc["found"]] ~ /inf|nan/) CHFI[m] = 1
			else if (a[chc["found"]] + 0 > CHF[m]) CHF[m] = a[chc["found"]] + 0
		}
		close(f)
		if (!CHN) { print "findings: no rows in " f > "/dev/stderr"; bad = 1 }
	}
	# {{CH method key}}: bound, found (in u = 2^-11, 4 digits), ratio
	# (bound / found, 2 decimals), regions, proven, non-finite, overflow,
	# unbounded (region counts), where (the n.z span of the regions with
	# no bound)
	function CH(m, k,   u) {
		load_ch(); u = 2 ^ -11
		if (!(m in CHB)) { print "findings: no " m " in results/half/certify/certify-half.csv" > "/dev/stderr"; bad = 1; return "?" }
		if (k == "bound") return (m in CHBAD) ? "none" : sprintf("%.4g", CHB[m] / u)
		if (k == "found") return (m in CHFI) ? "non-finite" : sprintf("%.4g", CHF[m] / u)
		if (k == "ratio") return ((m in CHBAD) || (m in CHFI) || CHF[m] <= 0) ? "n/a" : sprintf("%.2f", CHB[m] / CHF[m])
		if (k == "regions") return CHR[m]
		if (k == "proven" || k == "non-finite" || k == "overflow" || k == "unbounded") return CHS[m, k] + 0
		if (k == "where") return (m in CHBAD) ? sprintf("n.z in [%.6g, %.6g]", CHW[m, "lo"], CHW[m, "hi"]) : "none"
		print "findings: bad CH key " k > "/dev/stderr"; bad = 1; return "?"
	}
	# {{CHLIST kind}}: the methods, comma-separated, in the order of the registry:
	# proven (every region), within2 (proven, bound <= 2 found), loose
	# (proven, bound > 2 found), nonfinite, unbounded, overflow (some region
	# of that status); {{CHN kind}}: how many
	function chsel(m, kind) {
		if (kind == "proven") return !(m in CHBAD)
		if (kind == "within2") return !(m in CHBAD) && !(m in CHFI) && CHF[m] > 0 && CHB[m] <= 2 * CHF[m]
		if (kind == "loose") return !(m in CHBAD) && !((m in CHFI) || CHF[m] <= 0 || CHB[m] <= 2 * CHF[m])
		if (kind == "nonfinite") return CHS[m, "non-finite"] > 0
		if (kind == "unbounded") return CHS[m, "unbounded"] > 0
		if (kind == "overflow") return CHS[m, "overflow"] > 0
		if (kind == "all") return 1
		print "findings: bad CHLIST kind " kind > "/dev/stderr"; bad = 1; return 0
	}
	function CHLIST(kind, count,   i, s, n) {
		load_ch(); s = ""; n = 0
		for (i = 1; i <= CHN; i++) if (chsel(CHM[i], kind)) { n++; s = s (s == "" ? "" : ", ") "`" CHM[i] "`" }
		return count ? n : (n ? s : "none")
	}
	# {{CHP dir method key}}: bound, found (u) or ratio of the method over
	# the regions of results/half/certify/DIR/certify-half.csv (a partial run)
	function CHP(d, m, k,   f, line, a, n, i, c, bb, ff, any) {
		f = REF "/../half/certify/" d "/certify-half.csv"; bb = 0; ff = 0
		while ((getline line < f) > 0) {
			if (line ~ /^#/) continue
			n = split(line, a, ",")
			if (a[1] == "method") { for (i = 1; i <= n; i++) c[a[i]] = i; continue }
			if (a[1] != m) continue
			any = 1
			if (a[c["status"]] != "proven" || a[c["found"]] ~ /inf|nan/) { close(f); print "findings: " m " has a region without a bound in " f > "/dev/stderr"; bad = 1; return "?" }
			if (a[c["bound"]] + 0 > bb) bb = a[c["bound"]] + 0
			if (a[c["found"]] + 0 > ff) ff = a[c["found"]] + 0
		}
		close(f)
		if (!any || ff <= 0) { print "findings: no " m " rows in " f > "/dev/stderr"; bad = 1; return "?" }
		if (k == "bound") return sprintf("%.4g", bb * 2048)
		if (k == "found") return sprintf("%.4g", ff * 2048)
		if (k == "ratio") return sprintf("%.2f", bb / ff)
		print "findings: bad CHB key " k > "/dev/stderr"; bad = 1; return "?"
	}
	# {{CHLOOSE}}: nothing when every proven bracket is within 2x, else the
	# wider ones with their ratios
	function CHLOOSE(   i, s, m) {
		load_ch(); s = ""
		for (i = 1; i <= CHN; i++) { m = CHM[i]; if (chsel(m, "loose")) s = s (s == "" ? "" : ", ") "`" m "` " CH(m, "ratio") "x" }
		return s == "" ? "" : "; wider: " s " (certify.md, \"Binary16\", says which side is loose)"
	}
	# a value of results/half/halfscan/halfscan.csv or of the half sweep, "-"
	# where the method has no row there
	function hrow(path, key, col,   f, line, n, a, i, h, nh) {
		f = REF "/../" path; nh = 0
		while ((getline line < f) > 0) {
			if (line ~ /^#/) continue
			n = split(line, a, ",")
			if (!nh) { nh = n; for (i = 1; i <= n; i++) h[a[i]] = i; continue }
			if (a[1] == key && (col in h)) { close(f); return a[h[col]] }
		}
		close(f); return "-"
	}
	function hsw(m, col,   v, f, line, n, a, i, h, nh) {
		f = REF "/../half/sweep/summary.csv"; nh = 0
		while ((getline line < f) > 0) {
			if (line ~ /^#/) continue
			n = split(line, a, ",")
			if (!nh) { nh = n; for (i = 1; i <= n; i++) h[a[i]] = i; continue }
			if (a[1] == m && a[2] == "half" && a[3] == "uniform") { close(f); v = a[h[col]]; return (col == "max_defect" && v !~ /nan|inf/) ? fmt(v * 2048) : fmt(v) }
		}
		close(f); return "-"
	}
	# {{TABLE half}}: every method of the half certify run: the proven
	# bracket over the whole sphere, the regions by status and where the
	# unproven ones lie, beside the maxima of the halfscan and of the half sweep
	function table_half(   i, m, out, hs, hn) {
		load_ch()
		out = "| method | proven bound | found (certify scan) | bound / found | regions proven / non-finite / overflow / unbounded | no bound where | halfscan max | halfscan non-finite | sweep, uniform: max | sweep, uniform: non-finite |\n"
		out = out "|---|---:|---:|---:|---|---|---:|---:|---:|---:|\n"
		for (i = 1; i <= CHN; i++) {
			m = CHM[i]; hs = hrow("half/halfscan/halfscan.csv", m, "max_defect_u"); hn = hrow("half/halfscan/halfscan.csv", m, "nonfinite")
			out = out "| `" m "` | " CH(m, "bound") " | " CH(m, "found") " | " CH(m, "ratio") " | " CH(m, "proven") " / " CH(m, "non-finite") " / " CH(m, "overflow") " / " CH(m, "unbounded") " | " CH(m, "where") " | " (hs == "-" ? "-" : fmt(hs)) " | " hn " | " hsw(m, "max_defect") " | " hsw(m, "nonfinite") " |\n"
		}
		return out
	}
	# the fastest method of a precision and, when it is off the front, one
	# method that beats it by the rule of onbstudy table (speeds within PTOLV% equal)
	function werr(m, p,   k) { k = m SUBSEP p; return (TRD[k, "nonfinite"] + 0 > 0 || TRD[k, "max_defect_worst"] ~ /nan|inf/) ? 1e300 : TRD[k, "max_defect_worst"] + 0 }
	function FASTEST(p,   i, m, f, fs, t, j, s, e, ef) {
		fs = -1; t = PTOLV / 100
		for (i = 1; i <= nmeth; i++) { m = meth[i]
			if (!((m SUBSEP p, "pareto") in TRD) || TRD[m SUBSEP p, "pareto"] == "na") continue
			if (TRD[m SUBSEP p, "batch_mbases_1t"] + 0 > fs) { fs = TRD[m SUBSEP p, "batch_mbases_1t"] + 0; f = m } }
		if (fs < 0) { print "findings: no speeds for " p > "/dev/stderr"; bad = 1; return "?" }
		if (TRD[f SUBSEP p, "pareto"] == "1") return "`" f "`, the fastest at " fmt(fs) " M bases/s, is on it"
		ef = werr(f, p)
		for (i = 1; i <= nmeth; i++) { m = meth[i]
			if (m == f || !((m SUBSEP p, "pareto") in TRD) || TRD[m SUBSEP p, "pareto"] == "na") continue
			s = TRD[m SUBSEP p, "batch_mbases_1t"] + 0; e = werr(m, p)
			if (s >= (1 - t) * fs && e <= ef && (e < ef || s > (1 + t) * fs)) return "`" f "`, the fastest at " fmt(fs) " M bases/s, is beaten by `" m "` at " fmt(s)
		}
		print "findings: " f " is off the front, but no method beats it" > "/dev/stderr"; bad = 1; return "?"
	}
	function PARETO(p,   i, m, out) {
		out = ""
		for (i = 1; i <= nmeth; i++) {
			m = meth[i]
			if (TRD[m SUBSEP p, "pareto"] == "1") out = out (out == "" ? "" : ", ") "`" m "`"
		}
		if (out == "") { print "findings: empty Pareto front for " p > "/dev/stderr"; bad = 1; return "?" }
		return out
	}
	function X(m, p, c,   k) {
		k = m SUBSEP p
		if (!((k, c) in TRD)) { print "findings: no " m "," p "," c " in tradeoff.csv" > "/dev/stderr"; bad = 1; return "?" }
		return fmt(TRD[k, c])
	}
	function MUT(key,   f, line) {
		f = REF "/mutation.txt"
		while ((getline line < f) > 0)
			if (index(line, key ": ") == 1) { close(f); return substr(line, length(key) + 3) }
		close(f)
		print "findings: no " key " in mutation.txt" > "/dev/stderr"; bad = 1; return "?"
	}
	# how an error of threshold.csv changes as 1 + t grows (finite rows, by
	# 1 + t): "falls from A to B", "rises from A to B", or "falls from A to B
	# at 1 + t = X, then rises to C"; any other shape fails the generation
	function THTR(p, c,   n, i, j, k, v, x, o, lo, hi, ilo, ihi) {
		n = nth[p]
		if (n < 2 || (c != "normality" && c != "orthogonality")) { print "findings: no threshold rows " p " " c > "/dev/stderr"; bad = 1; return "?" }
		for (i = 1; i <= n; i++) { o[i] = i }
		for (i = 2; i <= n; i++) for (j = i; j > 1 && TRX[p, o[j - 1]] > TRX[p, o[j]]; j--) { k = o[j]; o[j] = o[j - 1]; o[j - 1] = k }
		for (i = 1; i <= n; i++) { v[i] = (c == "normality") ? TRN[p, o[i]] : TRO[p, o[i]]; x[i] = TRX[p, o[i]]
			if (i == 1 || v[i] < lo) { lo = v[i]; ilo = i } if (i == 1 || v[i] > hi) { hi = v[i]; ihi = i } }
		if (ihi == 1 && ilo == n) return "falls from " fmt(v[1]) " to " fmt(v[n])
		if (ilo == 1 && ihi == n) return "rises from " fmt(v[1]) " to " fmt(v[n])
		if (ilo > 1 && ilo < n && (ihi == 1 || ihi == n)) return "falls from " fmt(v[1]) " to " fmt(lo) " at 1 + t = " sprintf("%.3g", x[ilo]) ", then rises to " fmt(v[n])
		print "findings: the " p " " c " error of threshold.csv neither falls, rises nor falls then rises with 1 + t" > "/dev/stderr"; bad = 1; return "?"
	}
	# the rows of polecap.csv above 0.01 for a method: "in every row of 1 +
	# n.z from LO to HI" or "in N of the M rows of 1 + n.z from LO to HI (the
	# other K reach A to B)": the band is said as it is, gaps included
	function PCBAND(m,   lo, hi, k, d, a, nin, nabove, glo, ghi) {
		if (!((m, "bandlo") in PCS)) { print "findings: no " m " row above 0.01 in polecap.csv" > "/dev/stderr"; bad = 1; return "?" }
		lo = PCS[m, "bandlo"]; hi = PCS[m, "bandhi"]; nin = nabove = 0
		for (k in rows) { split(k, a, SUBSEP); if (a[1] != m) continue; d = a[2] + 0
			if (d < lo || d > hi) continue
			nin++; if (rmx[m, a[2]] > 0.01) nabove++
			else { if (!glo || rmx[m, a[2]] < glo) glo = rmx[m, a[2]]; if (rmx[m, a[2]] > ghi) ghi = rmx[m, a[2]] } }
		if (nabove == nin) return sprintf("in every row of 1 + n.z from %.2g to %.2g", lo, hi)
		return sprintf("in %d of the %d rows of 1 + n.z from %.2g to %.2g (the other %d reach %s to %s)", nabove, nin, lo, hi, nin - nabove, fmt(glo), fmt(ghi))
	}
	# the continuous frame fields of the grid rows of a precision: the methods
	# whose largest jump of b1 between neighbouring cells (max_b1_jump) is
	# below 0.5, far from the jump of a seam (b1 flips: up to 2); CONT p list
	# (their names, in the order of the registry), max (their largest jump), next
	# (the smallest jump of the others), cell (the cell size of the grid, the
	# dashed line of the continuity chart); fails when none is below 0.5 or the
	# next is not at least twice the largest
	function CONT(p, what,   i, m, k, v, l, n, mx, nx, c, r, a) {
		n = 0; mx = -1; nx = -1; l = ""
		for (i = 1; i <= nmeth; i++) { m = meth[i]; k = m SUBSEP p SUBSEP "grid"
			if (!((k, "max_b1_jump") in SUM) || SUM[k, "max_b1_jump"] ~ /nan/) continue
			v = SUM[k, "max_b1_jump"] + 0
			if (v < 0.5) { n++; l = l (l == "" ? "" : "|") m; if (v > mx) mx = v }
			else if (nx < 0 || v < nx) nx = v }
		if (!n || (nx >= 0 && nx < 2 * mx)) { print "findings: the " p " grid has no continuous field apart from the seams (max_b1_jump < 0.5, the next at least twice as large)" > "/dev/stderr"; bad = 1; return "?" }
		if (what == "max") return fmt(mx)
		if (what == "next") return fmt(nx)
		if (what == "cell") { if (GRIDV == "") return "?"; split(GRIDV, a, "x"); r = 2 / a[1]; c = 6.283185307 / a[2]; return fmt(r > c ? r : c) }
		k = split(l, a, "|"); r = ""
		for (i = 1; i <= k; i++) r = r (i > 1 ? (i == k ? " and " : ", ") : "") "`" a[i] "`"
		return r
	}
	function TH(p, key, field) { return THX(thc, "", p, key, field) }
	# the same from results/half/threshold/threshold.csv (onbstudy threshold --precision all)
	function THH(p, key, field) { return THX(thh, "half/", p, key, field) }
	function THX(arr, what, p, key, field,   lines, n, i, l, s, parts, v) {
		n = split(arr[p], lines, "\n")
		for (i = 1; i <= n; i++) {
			l = lines[i]
			if (l !~ ("^# (minimax|published) " key)) continue
			if (field == "t") {
				match(l, /\(([-0-9.e]+)\)/); v = substr(l, RSTART + 1, RLENGTH - 2) + 0
				return sprintf("%.9g", v)
			}
			if (field == "1pt") field = "one_plus_t"
			if (match(l, field " [-+0-9.einf]+")) { s = substr(l, RSTART, RLENGTH); split(s, parts, " "); return fmt(parts[2]) }
		}
		print "findings: no " what "threshold " p " " key " " field > "/dev/stderr"; bad = 1; return "?"
	}
	# the whole-sphere row of certify.csv (results/certify): the found
	# maximum or the proven bound ("singular" where the method has NaN/inf)
	function CF(m, p, c,   k) {
		k = m SUBSEP p SUBSEP "-1" SUBSEP "1" SUBSEP "0" SUBSEP "360"
		if (!((k, c) in CRT)) return "n/a"
		if (c == "bound" && CRT[k, "status"] == "singular") return "singular"
		return fmt(CRT[k, c])
	}
	# bound / found of the whole-sphere row, to 2 decimals ("-" when singular)
	function CR(m, p,   k) {
		k = m SUBSEP p SUBSEP "-1" SUBSEP "1" SUBSEP "0" SUBSEP "360"
		if (!((k, "bound") in CRT)) { print "findings: no whole-sphere row of " m " " p " in certify.csv" > "/dev/stderr"; bad = 1; return "?" }
		if (CRT[k, "status"] == "singular" || CRT[k, "found"] + 0 == 0) return "-"
		return sprintf("%.2f", CRT[k, "bound"] / CRT[k, "found"])
	}
	function unit(p) { return p == "float" ? 2 ^ -24 : 2 ^ -53 }
	function inu(v, p) { return v == "inf" ? "inf" : sprintf("%.4g", v / unit(p)) }
	function ratio(b, f) { return (b == "inf" || f + 0 == 0) ? "-" : sprintf("%.3g", b / f) }
	# bound / found of every region of method m in precision p (every
	# method and precision when m is ""; not the whole-sphere rows, not
	# singular ones) into v[1..]; their count, and in np how many are proven
	function brackets(m, p, v, np,   n, r, i, f, nv) {
		n = split(rows[CF_FILE], r, "\n"); nv = np[0] = 0
		for (i = 1; i <= n; i++) {
			split(r[i], f, SUBSEP)
			if (f[1] == "" || (m != "" && (f[1] != m || f[2] != p))) continue
			if (f[3] == "-1" && f[4] == "1" && f[5] == "0" && f[6] == "360") continue
			if (CRT[r[i], "status"] == "singular" || CRT[r[i], "found"] + 0 <= 0) continue
			v[++nv] = CRT[r[i], "bound"] / CRT[r[i], "found"]
			np[0] += CRT[r[i], "status"] == "proven"
		}
		return nv
	}
	# the k-th smallest of v[1..n] (Hoare selection; v is reordered)
	function kth(v, n, k,   lo, hi, i, j, x, t) {
		lo = 1; hi = n
		while (lo < hi) {
			x = v[int((lo + hi) / 2)]; i = lo; j = hi
			while (i <= j) {
				while (v[i] < x) i++
				while (v[j] > x) j--
				if (i <= j) { t = v[i]; v[i] = v[j]; v[j] = t; i++; j-- }
			}
			if (k <= j) hi = j; else if (k >= i) lo = i; else return v[k]
		}
		return v[k]
	}
	function median(v, n,   a) {
		a = kth(v, n, int((n + 1) / 2))
		return n % 2 ? a : (a + kth(v, n, n / 2 + 1)) / 2
	}
	# the median over the regions of a method of bound / found, to 2 decimals
	# ("-" when there is none)
	function CMED(m, p,   v, np, nv) {
		nv = brackets(m, p, v, np)
		return nv ? sprintf("%.2f", median(v, nv)) : "-"
	}
	# the same over every region of every method and precision: their
	# count, the median, and how many are proven
	function CMEDALL(   v, np, nv) {
		nv = brackets("", "", v, np)
		if (!nv) return "no regions"
		return sprintf("%d regions, median bound / found %.2f, %d of them proven", nv, median(v, nv), np[0])
	}
	function table_certify(   out, i, m, pp, p, k, line, any) {
		out = "| method | float: found | bound | ratio | median | status | double: found | bound | ratio | median | status |\n|---|---:|---:|---:|---:|---|---:|---:|---:|---:|---|\n"
		for (i = 1; i <= ncm; i++) {
			m = cmeth[i]; line = "| `" m "`"; any = 0
			for (pp = 1; pp <= 2; pp++) {
				p = pp == 1 ? "float" : "double"
				k = m SUBSEP p SUBSEP "-1" SUBSEP "1" SUBSEP "0" SUBSEP "360"
				if (!((k, "bound") in CRT)) { line = line " | | | | | "; continue }
				any = 1
				line = line " | " inu(CRT[k, "found"], p) " | " (CRT[k, "status"] == "singular" ? "-" : inu(CRT[k, "bound"], p)) " | " (CRT[k, "status"] == "singular" ? "-" : ratio(CRT[k, "bound"], CRT[k, "found"])) " | " CMED(m, p) " | " CRT[k, "status"]
			}
			if (any) out = out line " |\n"
		}
		return out
	}
	function onbh_cell(m, p,   k) {
		k = m SUBSEP p SUBSEP "-1" SUBSEP "1" SUBSEP "0" SUBSEP "360"
		if (!((k, "bound") in CRT)) return sprintf("%-30s", "-")
		if (CRT[k, "status"] == "singular") return sprintf("%-30s", "singular")
		return sprintf("%-30s", sprintf("<= %.3gu (found %.3gu)", CRT[k, "bound"] / unit(p), CRT[k, "found"] / unit(p)))
	}
	function table_onbh(   out, i, m, l) {
		out = sprintf(" *   %-24s %-30s %s", "method", "float", "double")
		for (i = 1; i <= ncm; i++) {
			l = sprintf(" *   %-24s %s %s", cmeth[i], onbh_cell(cmeth[i], "float"), onbh_cell(cmeth[i], "double"))
			sub(/ +$/, "", l)
			out = out "\n" l
		}
		return out
	}
	function table_bands(m, p,   out, n, r, i, f, k, lo, nb, b, bl, bh, fo, bo) {
		n = split(rows[CF_FILE], r, "\n"); nb = 0
		for (i = 1; i <= n; i++) {
			split(r[i], f, SUBSEP)
			if (f[1] != m || f[2] != p || f[4] + 0 > -0.9 || (f[3] == "-1" && f[4] == "1")) continue
			b = f[3] SUBSEP f[4]
			if (!(b in seenb)) { seenb[b] = 1; bl[++nb] = f[3]; bh[nb] = f[4]; fo[nb] = 0; bo[nb] = 0 }
			for (k = 1; k <= nb; k++) if (bl[k] == f[3] && bh[k] == f[4]) break
			if (CRT[r[i], "found"] + 0 > fo[k]) fo[k] = CRT[r[i], "found"] + 0
			if (CRT[r[i], "bound"] == "inf" || bo[k] == "inf") bo[k] = "inf"
			else if (CRT[r[i], "bound"] + 0 > bo[k]) bo[k] = CRT[r[i], "bound"] + 0
		}
		out = "| 1 + n.z from | to | found | bound | bound / found |\n|---:|---:|---:|---:|---:|\n"
		for (k = 1; k <= nb; k++)
			out = out "| " sprintf("%.3g", 1 + bl[k]) " | " sprintf("%.3g", 1 + bh[k]) " | " fmt(fo[k]) " | " (bo[k] == "inf" ? "inf" : fmt(bo[k])) " | " ratio(bo[k], fo[k]) " |\n"
		if (!nb) { print "findings: no bands of " m " " p " in certify.csv" > "/dev/stderr"; bad = 1 }
		delete seenb
		return out
	}
	function CW(d, m, p, c,   file, line, f, nh, h, i) {
		file = REF "/../certify/" d "/certify.csv"; nh = 0
		while ((getline line < file) > 0) {
			if (line ~ /^#/) continue
			split(line, f, ",")
			if (!nh) { nh = split(line, h, ","); continue }
			if (f[1] == m && f[2] == p) { close(file); for (i = 1; i <= nh; i++) if (h[i] == c) return inu(f[i], p) }
		}
		close(file)
		print "findings: no " m " " p " " c " in " file > "/dev/stderr"; bad = 1; return "?"
	}
	# every method: its whole-sphere bracket, plain and +fma, from the run in
	# results/certify/D (certify --fma): bound / found in u, the ratio
	function table_fma(d,   file, line, f, nh, nh2, h, i, c, key, bd, fo, st, nm, meth, seen, out, m, pp, p, v, k) {
		file = REF "/../certify/" d "/certify.csv"; nh = 0; nm = 0
		while ((getline line < file) > 0) {
			if (line ~ /^#/) continue
			nh2 = split(line, f, ",")
			if (!nh) { nh = nh2; for (i = 1; i <= nh; i++) c[f[i]] = i; continue }
			if (f[c["nz_lo"]] != "-1" || f[c["nz_hi"]] != "1" || f[c["phi_lo"]] != "0" || f[c["phi_hi"]] != "360") continue
			key = f[c["method"]] SUBSEP f[c["precision"]]
			bd[key] = f[c["bound"]]; fo[key] = f[c["found"]]; st[key] = f[c["status"]]
			m = f[c["method"]]; sub(/\+fma$/, "", m)
			if (!(m in seen)) { seen[m] = 1; meth[++nm] = m }
		}
		close(file)
		if (!nm) { print "findings: no whole-sphere rows in " file > "/dev/stderr"; bad = 1; return "?" }
		out = "| method | float | float+fma | double | double+fma |\n|---|---|---|---|---|\n"
		for (i = 1; i <= nm; i++) {
			out = out "| `" meth[i] "`"
			for (pp = 1; pp <= 4; pp++) {
				p = pp <= 2 ? "float" : "double"; m = meth[i] (pp % 2 ? "" : "+fma"); k = m SUBSEP p
				if (!(k in bd)) { v = "-" }
				else if (st[k] == "singular") v = "singular (found " inu(fo[k], p) ")"
				else v = inu(bd[k], p) " / " inu(fo[k], p) " (" ratio(bd[k], fo[k]) "x)"
				out = out " | " v
			}
			out = out " |\n"
		}
		return out
	}
	function CP(key,   lines, n, i, l) {
		n = split(comments[CF_FILE], lines, "\n")
		for (i = 1; i <= n; i++) if (index(lines[i], "# " key ": ") == 1) return substr(lines[i], length(key) + 5)
		print "findings: no # " key ": line in certify.csv" > "/dev/stderr"; bad = 1; return "?"
	}
	# " [lo, hi]" when summary.csv has the 95% interval columns
	function CI(m, p, d, c,   k) {
		k = m SUBSEP p SUBSEP d
		if (!((k, c "_lo") in SUM) || SUM[k, c "_lo"] == "" || SUM[k, c "_lo"] ~ /nan/) return ""
		return " [" fmt(SUM[k, c "_lo"]) ", " fmt(SUM[k, c "_hi"]) "]"
	}
	# the largest defect; for a method measured by its direction error
	# (frisvad_rotate: no defect), that error, the larger of | |w| - 1 | and
	# | w.n - z |, marked with a dagger
	function DE(m, p, d,   k, a, b) {
		k = m SUBSEP p SUBSEP d
		if (!((k, "max_defect") in SUM) || SUM[k, "max_defect"] !~ /nan/ || !((k, "max_dir_norm") in SUM) || SUM[k, "max_dir_norm"] ~ /nan/) return S(m, p, d, "max_defect")
		a = SUM[k, "max_dir_norm"] + 0; b = (SUM[k, "max_dir_cos"] ~ /nan/) ? 0 : SUM[k, "max_dir_cos"] + 0
		return fmt(a > b ? a : b) " †"
	}
	function table_accuracy(p,   out, k, m, dl, nd, i, d, nf, wr, line) {
		nd = split("uniform north south exhaustive threshold nonunit", dl, " ")
		out = "| method | RMSE, uniform | max uniform | max north | max south | max exhaustive | max threshold | max non-unit | found (certify) | proven max | max ulp, uniform | non-finite | wrong-handed |\n"
		out = out "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
		for (i = 1; i <= nmeth; i++) {
			m = meth[i]
			if (!((m SUBSEP p SUBSEP "uniform", "rmse") in SUM)) continue
			line = "| `" m "` | " S(m, p, "uniform", "rmse") CI(m, p, "uniform", "rmse")
			nf = 0; wr = 0
			for (k = 1; k <= nd; k++) {
				d = dl[k]
				line = line " | " DE(m, p, d)
				nf += SUM[m SUBSEP p SUBSEP d, "nonfinite"]; wr += SUM[m SUBSEP p SUBSEP d, "wrong_handed"]
			}
			line = line " | " CF(m, p, "found") " | " CF(m, p, "bound") " | " S(m, p, "uniform", "max_ulp") " | " nf " | " wr " |"
			out = out line "\n"
		}
		return out
	}
	function table_tradeoff(   out, i, m, cols, nc, c, p, line, pp, np) {
		if (!ntrd) { bad = 1; print "findings: tradeoff.csv missing" > "/dev/stderr"; return "?" }
		out = "| method | prec | batch M/s, 1 thread | batch M/s, all threads | ns per call | RMSE, uniform | max south | max threshold | x floor | Pareto |\n|---|---|---:|---:|---:|---:|---:|---:|---:|:-:|\n"
		np = split("float double", pp, " ")
		for (p = 1; p <= np; p++)
			for (i = 1; i <= nmeth; i++) {
				m = meth[i]
				if (!((m SUBSEP pp[p], "method") in TRD)) continue
				out = out "| `" m "` | " pp[p] " | " X(m, pp[p], TRDCOL["b1"]) " | " X(m, pp[p], TRDCOL["bn"]) " | " X(m, pp[p], TRDCOL["ns"]) " | " X(m, pp[p], TRDCOL["rmse"]) " | " X(m, pp[p], TRDCOL["south"]) " | " X(m, pp[p], TRDCOL["thr"]) " | " XO(m, pp[p], "x_floor") " | " (TRD[m SUBSEP pp[p], TRDCOL["pareto"]] == "1" ? "**yes**" : "") " |\n"
			}
		return out
	}
	BEGIN {
		load(REF "/summary.csv", SUM, "1 2 3")
		load(REF "/fma/summary.csv", FMA, "1 2 3")
		CF_FILE = REF "/../certify/certify.csv"
		load(CF_FILE, CRT, "1 2 3 4 5 6")
		n = split(rows[CF_FILE], rr, "\n")
		for (i = 1; i <= n; i++) { split(rr[i], kk, SUBSEP); if (kk[1] != "" && !(kk[1] in seencm)) { seencm[kk[1]] = 1; cmeth[++ncm] = kk[1] } }
		n = split(rows[REF "/summary.csv"], rr, "\n")
		for (i = 1; i <= n; i++) { split(rr[i], kk, SUBSEP); if (kk[1] != "" && !(kk[1] in seenm)) { seenm[kk[1]] = 1; meth[++nmeth] = kk[1] } }
		load_polecap()
		nc = split(comments[REF "/summary.csv"], cl, "\n")
		for (i = 1; i <= nc; i++) {
			if (cl[i] ~ /^# rate: /) { split(cl[i], a, " ")
				RATED["evals"] = a[3]; RATED["secs"] = a[7]; RATED["persec"] = a[10]; RATED["threads"] = a[14]; v = cl[i]; sub(/.*\(/, "", v); sub(/ per thread.*/, "", v); RATED["perthread"] = v }
			if (match(cl[i], /grid: [0-9]+x[0-9]+/)) GRIDV = substr(cl[i], RSTART + 6, RLENGTH - 6)
			if (cl[i] ~ /^# inputs: /) { n2 = split(cl[i], a, " "); for (k = 3; k <= n2; k++) { split(a[k], kv, "="); INPUTSD[kv[1]] = kv[2] } }
		}
		tf = REF "/threshold.csv"
		while ((getline line < tf) > 0) {
			if (line ~ /^(float|double),/) { split(line, f, ","); sect = f[1]
				# the finite rows, for THTR: 1 + t, normality, orthogonality
				if (f[5] !~ /nan|inf/ && f[6] !~ /nan|inf/) { nth[sect]++; TRX[sect, nth[sect]] = f[4] + 0; TRN[sect, nth[sect]] = f[5] + 0; TRO[sect, nth[sect]] = f[6] + 0 } }
			else if (line ~ /^# (minimax|published)/ && sect != "") thc[sect] = thc[sect] line "\n"
		}
		close(tf)
		tf = REF "/../half/threshold/threshold.csv"; sect = ""
		while ((getline line < tf) > 0) {
			if (line ~ /^(float|double|half),/) { split(line, f, ","); sect = f[1] }
			else if (line ~ /^# (minimax|published)/ && sect != "") thh[sect] = thh[sect] line "\n"
		}
		close(tf)
		xf = REF "/tradeoff.csv"
		if ((getline line < xf) > 0) {
			close(xf)
			load(xf, TRD, "1 2")
			ntrd = 1
			split(hdrs[xf], H, ",")
			TRDCOL["b1"] = "batch_mbases_1t"; TRDCOL["bn"] = "batch_mbases_all"; TRDCOL["ns"] = "call_ns"
			TRDCOL["rmse"] = "rmse_uniform"; TRDCOL["south"] = "max_defect_south"
			TRDCOL["thr"] = "max_defect_threshold"; TRDCOL["pareto"] = "pareto"
			if (match(comments[xf], /speeds within [0-9.]+% counted equal/)) { PTOLV = substr(comments[xf], RSTART + 14, RLENGTH - 14); sub(/%.*/, "", PTOLV) }
		}
	}
	{
		line = $0
		while (match(line, /\{\{[^}]*\}\}/)) {
			rs = RSTART; rl = RLENGTH   # the functions below call match() too
			tok = substr(line, rs + 2, rl - 4)
			nt = split(tok, a, " ")
			if (a[1] == "S" && nt == 5) rep = S(a[2], a[3], a[4], a[5])
			else if (a[1] == "SO" && nt == 5) rep = SO(a[2], a[3], a[4], a[5])
			else if (a[1] == "SR" && nt == 6) rep = SR(a[2], a[3], a[4], a[5], a[6])
			else if (a[1] == "XO" && nt == 4) rep = XO(a[2], a[3], a[4])
			else if (a[1] == "XR" && nt == 5) rep = XR(a[2], a[3], a[4], a[5])
			else if (a[1] == "TABLE" && a[2] == "floor") rep = table_floor(a[3])
			else if (a[1] == "TABLE" && a[2] == "floordist") rep = table_floordist(a[3])
			else if (a[1] == "X" && nt == 4) rep = X(a[2], a[3], a[4])
			else if (a[1] == "F" && nt == 5) rep = F(a[2], a[3], a[4], a[5])
			else if (a[1] == "PARETO" && nt == 2) rep = PARETO(a[2])
			else if (a[1] == "R" && nt == 3) rep = RN(a[2], a[3])
			else if (a[1] == "RB" && nt == 3) rep = RB(a[2], a[3])
			else if (a[1] == "TH" && nt == 4) rep = TH(a[2], a[3], a[4])
			else if (a[1] == "THH" && nt == 4) rep = THH(a[2], a[3], a[4])
			else if (a[1] == "MUT" && nt == 2) rep = MUT(a[2])
			else if (a[1] == "TABLE" && a[2] == "accuracy") rep = table_accuracy(a[3])
			else if (a[1] == "TABLE" && a[2] == "tradeoff") rep = table_tradeoff()
			else if (a[1] == "TABLE" && a[2] == "certify") rep = table_certify()
			else if (a[1] == "CMEDALL" && nt == 1) rep = CMEDALL()
			else if (a[1] == "TABLE" && a[2] == "certifybands" && nt == 4) rep = table_bands(a[3], a[4])
			else if (a[1] == "TABLE" && a[2] == "certifyfma" && nt == 3) rep = table_fma(a[3])
			else if (a[1] == "CW" && nt == 5) rep = CW(a[2], a[3], a[4], a[5])
			else if (a[1] == "CP" && nt == 2) rep = CP(a[2])
			else if (a[1] == "ONBH" && nt == 1) rep = table_onbh()
			else if (a[1] == "PC" && nt == 3) rep = PC(a[2], a[3])
			else if (a[1] == "PCBAND" && nt == 2) rep = PCBAND(a[2])
			else if (a[1] == "THTR" && nt == 3) rep = THTR(a[2], a[3])
			else if (a[1] == "CONT" && nt == 3) rep = CONT(a[2], a[3])
			else if (a[1] == "V" && nt == 4) rep = V(a[2], a[3], a[4], 0)
			else if (a[1] == "HS" && nt == 4) rep = HS(a[2], a[3], a[4], 0)
			else if (a[1] == "HSU" && nt == 4) rep = HS(a[2], a[3], a[4], 1)
			else if (a[1] == "CH" && nt == 3) rep = CH(a[2], a[3])
			else if (a[1] == "CHLIST" && nt == 2) rep = CHLIST(a[2], 0)
			else if (a[1] == "CHN" && nt == 2) rep = CHLIST(a[2], 1)
			else if (a[1] == "CHLOOSE" && nt == 1) rep = CHLOOSE()
			else if (a[1] == "CHP" && nt == 4) rep = CHP(a[2], a[3], a[4])
			else if (a[1] == "TABLE" && a[2] == "half" && nt == 2) rep = table_half()
			else if (a[1] == "VC" && nt == 4) rep = V(a[2], a[3], a[4], 1)
			else if (a[1] == "BZ" && nt == 5) rep = BZ(a[2], a[3], a[4], a[5])
			else if (a[1] == "PCH" && nt == 2) rep = PCH(a[2])
			else if (a[1] == "RATE" && nt == 2) rep = RATE(a[2])
			else if (a[1] == "FASTEST" && nt == 2) rep = FASTEST(a[2])
			else if (a[1] == "PTOL" && nt == 1) rep = (PTOLV == "" ? "?" : PTOLV)
			else if (a[1] == "INPUTS" && nt == 2) rep = ((a[2] in INPUTSD) ? INPUTSD[a[2]] : "?")
			else if (a[1] == "INPUTSC" && nt == 2) rep = ((a[2] in INPUTSD) ? commas(INPUTSD[a[2]]) : "?")
			else if (a[1] == "GRID" && nt == 1) rep = (GRIDV == "" ? "?" : GRIDV)
			else if (a[1] == "PS" && nt == 5) rep = PS(a[2], a[3], a[4], a[5])
			else if (a[1] == "CB" && nt == 4) rep = CF(a[2], a[3], a[4])
			else if (a[1] == "CR" && nt == 3) rep = CR(a[2], a[3])
			else { print "findings: bad placeholder {{" tok "}}" > "/dev/stderr"; bad = 1; rep = "?" }
			line = substr(line, 1, rs - 1) rep substr(line, rs + rl)
		}
		print line
	}
	END { if (bad) exit 1 }
	' "$TPL"
}

case "${WHAT}:${1:-}" in
"quoted numbers:--check"|"quoted numbers:")
	T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
	generate > "$T/q" || { echo "findings: generation failed" >&2; exit 1; }
	bad=0; n=0
	while IFS='	' read -r file text; do
		[ -n "$file" ] || continue
		n=$((n + 1))
		grep -qF -- "$text" "$file" || { echo "findings: $file does not say: $text" >&2; bad=1; }
	done < "$T/q"
	[ $bad -eq 0 ] && echo "findings: the $n quoted numbers of scripts/quotes.in stand in their files" && exit 0
	echo "findings: quoted numbers differ from $SRC (edit the file, or scripts/quotes.in when the sentence moved)" >&2; exit 1 ;;
*:)
	generate ;;
*:--update|*:--check)
	FILE=${2:?usage: findings.sh [--headlines] --update|--check FILE}
	T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
	{ echo "$BEGIN_MARK"; generate; echo "$END_MARK"; } > "$T/new" || { echo "findings: generation failed" >&2; exit 1; }
	opt=""; [ "$WHAT" = Findings ] || opt=" --headlines"; [ "$WHAT" = "certify results" ] && opt=" --certify"; [ "$WHAT" = "chart captions" ] && opt=" --charts"; case $WHAT in "section "*) opt=" --section ${WHAT#section }";; esac; [ "$WHAT" = "proven bounds" ] && opt=" --onbh"
	splice_marked findings "$1" "$FILE" "$T/new" "$WHAT" "$SRC" "$SRC" "sh scripts/findings.sh$opt --update $FILE" ;;
*)
	echo "usage: findings.sh [--headlines|--certify|--onbh|--charts] [--update|--check FILE] | --quotes [--check]" >&2; exit 2 ;;
esac
