#!/bin/sh
# certify.sh - `onbstudy certify` end to end, at a reduced size:
# the bracket found <= bound in every region, every measured defect of the
# committed runs below its region's bound (tests/certify_check.c), the same
# file with 1 and 2 threads, found inputs that `eval` replays to the same
# defect, and bad input (exit 2, one line, nothing written).
. "$(dirname "$0")/lib.sh"
T=$tmp
data() { grep -v '^#' "$1"; }

M=frisvad,frisvad_max,duff,duff_branchless,hughes_moeller,naive,tangent_cross_z
# under a sanitizer, the four that the checks below name (the same code runs)
[ -n "$SAN" ] && M=frisvad,duff,naive,tangent_cross_z
Q="--quick --quiet --methods $M"
OMP_NUM_THREADS=2 ./onbstudy certify $Q --out "$T/a" >"$T/a.out" 2>"$T/a.err" || bad "certify --quick failed: $(cat "$T/a.err")"
# (three of the methods are enough to show the thread count changes nothing)
M1=frisvad,duff,naive
OMP_NUM_THREADS=1 ./onbstudy certify --quick --quiet --methods $M1 --precision float --out "$T/b" >/dev/null 2>"$T/b.err" || bad "certify --threads 1 failed"
C="$T/a/certify.csv"
[ -s "$C" ] && ok || bad "no certify.csv"

# 1. the columns, and found <= bound wherever a bound is claimed
head=$(data "$C" | head -1)
[ "$head" = "method,precision,nz_lo,nz_hi,phi_lo,phi_hi,bound,found,found_nx,found_ny,found_nz,status,evaluated,found_lx,found_ly,found_lz" ] && ok || bad "header: $head"
data "$C" | awk -F, 'NR > 1 && $12 != "singular" && !($7 + 0 >= $8 + 0) { print; n++ } END { exit n > 0 }' >"$T/inv" \
	&& ok || bad "found above bound in $(wc -l <"$T/inv") rows: $(head -2 "$T/inv")"
data "$C" | awk -F, 'NR > 1 && $12 !~ /^(proven|singular|budget)$/ { n++ } END { exit n > 0 }' && ok || bad "a status outside proven/singular/budget"
# the singular sets: naive at -x, tangent_cross_z at the poles; frisvad has none
data "$C" | awk -F, '$1 == "naive" && $5 <= 180 && $6 >= 180 && $3 <= 0 && $4 >= 0 && $12 == "singular" { s++ } END { exit !(s > 0) }' && ok || bad "naive not singular at -x"
data "$C" | awk -F, '$1 == "frisvad" && $12 == "singular" { s++ } END { exit s > 0 }' && ok || bad "frisvad reported singular"

# 1b. the profile: certify-times.csv has each region of certify.csv (its
#     rows less the whole-sphere ones) with six phases' CPU seconds, their
#     sum in the '# profile' line and on stderr
P="$T/a/certify-times.csv"
data "$C" | awk -F, 'NR > 1 && !($3 == -1 && $4 == 1 && $5 == 0 && $6 == 360) { print $1 "," $2 "," $3 "," $4 "," $5 "," $6 }' > "$T/reg.c"
data "$P" | awk -F, 'NR > 1 { print $1 "," $2 "," $3 "," $4 "," $5 "," $6 }' > "$T/reg.t"
[ -s "$T/reg.t" ] && cmp -s "$T/reg.c" "$T/reg.t" && ok || bad "certify-times.csv's regions differ from certify.csv's"
data "$P" | awk -F, 'NR > 1 { for (i = 7; i <= 12; i++) { if (!($i + 0 >= 0)) b++; s += $i } } END { exit !(s > 0 && !b) }' \
	&& ok || bad "certify-times.csv: a negative or no CPU time"
grep -q '^# profile: CPU per phase: sampling .* s (.*), walks .*boxes .*refinement .* s in all' "$C" && ok || bad "no '# profile' line in certify.csv"
grep -q '^certify: CPU per phase: ' "$T/a.err" && grep -q '^certify: CPU per method' "$T/a.err" && ok || bad "no profile on stderr"

# 2. 1 and 2 threads: the same float rows
data "$T/b/certify.csv" > "$T/b1"
data "$C" | awk -F, -v m=",$M1," 'NR == 1 || ($2 == "float" && index(m, "," $1 ","))' > "$T/a1"
[ "$(wc -l < "$T/b1")" -gt 3 ] || bad "certify with 1 thread wrote $(wc -l < "$T/b1") lines"
cmp -s "$T/a1" "$T/b1" && ok || bad "certify.csv differs between 1 and 2 threads"

# 3. soundness: no measured defect of the committed runs above its region's bound
build/tests/certify_check "$C" results/reference/worst.csv results/poles/worst.csv \
	results/poles/north/worst.csv results/poles/south/worst.csv >"$T/chk" 2>&1 && ok || bad "$(cat "$T/chk")"
grep -q 'checked' "$T/chk" && echo "  $(tail -1 "$T/chk")"
# ... and the committed run's bounds (results/certify/certify.csv, the figures the docs quote)
build/tests/certify_check results/certify/certify.csv results/reference/worst.csv results/poles/worst.csv \
	results/poles/north/worst.csv results/poles/south/worst.csv >"$T/chk2" 2>&1 && ok || bad "committed run: $(cat "$T/chk2")"
grep -q 'checked' "$T/chk2" && echo "  committed run: $(tail -1 "$T/chk2")"

# 4. the found inputs replay: eval gives the same defect
data "$C" | awk -F, 'NR > 1 && $1 == "frisvad" && $2 == "float" && $3 == -1 && $4 == 1 { print $9, $10, $11, $8 }' | {
	read -r x y z f || exit 1
	e=$(./onbstudy eval --methods frisvad --precision float -- "$x" "$y" "$z" | awk '/defects:/ { print $NF }' | tr -d ')')
	awk -v a="$e" -v b="$f" 'BEGIN { exit !(a + 0 > 0 && (a - b) / b < 1e-5 && (b - a) / b < 1e-5) }'
} && ok || bad "frisvad's whole-sphere found input does not replay in eval"

# 4b. frisvad_rotate: its direction error over (n, loc), next to -z (one
#     sector: the band's regions at their quickest): found <= bound with
#     a loc on every row, the study's measured direction errors below the
#     bounds, and the whole band's found input replayed through eval --local
./onbstudy certify --quick --quiet --sectors 1 --methods frisvad_rotate --band -1,-0.9999 --out "$T/rot" >/dev/null 2>"$T/rot.err" ||
	bad "certify frisvad_rotate failed: $(cat "$T/rot.err")"
data "$T/rot/certify.csv" | awk -F, 'NR > 1 { n++; if (!($7 + 0 >= $8 + 0 && $8 + 0 > 0 && $14 != "" && $12 != "singular")) b++ } END { exit !(n > 4 && !b) }' \
	&& ok || bad "frisvad_rotate rows: $(data "$T/rot/certify.csv" | head -3)"
build/tests/certify_check "$T/rot/certify.csv" results/reference/worst.csv results/poles/worst.csv \
	results/poles/north/worst.csv results/poles/south/worst.csv >"$T/chk3" 2>&1 && ok || bad "frisvad_rotate: $(cat "$T/chk3")"
for p in float double; do
	data "$T/rot/certify.csv" | awk -F, -v p=$p 'NR > 1 && $2 == p && $3 == -1 && $4 == -0.9999 { print $9, $10, $11, $14 "," $15 "," $16, $8 }' | {
		read -r x y z l f || exit 1
		e=$(./onbstudy eval --methods frisvad_rotate --precision $p --local "$l" -- "$x" "$y" "$z" |
		    awk '/^  direction:/ { a = $(NF - 6); b = $NF; print (a + 0 > b + 0 ? a : b) }')
		awk -v a="$e" -v b="$f" 'BEGIN { exit !(a + 0 > 0 && (a - b) / b < 1e-5 && (b - a) / b < 1e-5) }'
	} && ok || bad "frisvad_rotate's $p found input does not replay in eval --local"
done

# 5. scene --certify: the spherical triangles of a scene's vertex normals.
#    A dome (n.z >= 0.2) proves frisvad within E = 1e-6; a cap around -z
#    (n.z <= -0.99999) does not.
cap() { # cap ZTOP ZBOT N: a z-band of a UV sphere, smooth normals, as OBJ
	awk -v zt="$1" -v zb="$2" -v n="$3" 'BEGIN { pi = 3.14159265358979
	  for (i = 0; i <= n; i++) for (j = 0; j < n; j++) {
	    z = zt + (zb - zt) * i / n; r = sqrt(1 - z * z); p = 2 * pi * j / n
	    printf "v %.12f %.12f %.12f\nvn %.12f %.12f %.12f\n", r * cos(p), r * sin(p), z, r * cos(p), r * sin(p), z }
	  for (i = 0; i < n; i++) for (j = 0; j < n; j++) {
	    a = i * n + j + 1; b = i * n + (j + 1) % n + 1; c = a + n; d = b + n
	    printf "f %d//%d %d//%d %d//%d\nf %d//%d %d//%d %d//%d\n", a, a, c, c, b, b, b, b, c, c, d, d } }'; }
cap 1 0.2 6 > "$T/dome.obj"
cap -0.99999 -1 6 > "$T/south.obj"
# (under a sanitizer the south cap alone: it takes both paths, proven and
# not, through the same code, and each scene proves all methods, minutes there)
if [ -z "$SAN" ]; then
./onbstudy scene "$T/dome.obj" --certify --repeats 1 --out "$T/sd" > "$T/sd.out" 2>&1 || bad "scene --certify dome failed: $(tail -2 "$T/sd.out")"
grep -q '^  frisvad  .*[0-9]  proven within E$' "$T/sd.out" && ok || bad "frisvad not proven on the dome: $(grep '^  frisvad ' "$T/sd.out")"
fi
./onbstudy scene "$T/south.obj" --certify --repeats 1 --out "$T/ss" > "$T/ss.out" 2>&1 || bad "scene --certify south cap failed: $(tail -2 "$T/ss.out")"
grep -q '^  frisvad  .* not proven within E$' "$T/ss.out" && ok || bad "frisvad proven near -z: $(grep '^  frisvad ' "$T/ss.out")"
grep -q '^  duff  .*[0-9]  proven within E$' "$T/ss.out" && ok || bad "duff not proven near -z: $(grep '^  duff ' "$T/ss.out")"
# the bounds in scene.csv's proven_max: on the renormalized z rows of object
# space only, equal to the printed ones; empty on every other row
awk -F, '!/^#/ && !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1; next }
	!/^#/ && h { k = $c["method"] "," $c["up"] "," $c["variant"]; p[k] = $c["proven_max"]; n++ }
	END { exit !(n > 0 && p["duff,z,renormalized"] != "" && p["duff,z,as_read"] == "") }' "$T/ss/scene.csv" && ok ||
	bad "scene.csv's proven_max: not on the renormalized z rows alone"
want=$(awk '$1 == "duff" && / proven within E$/ { print $2; exit }' "$T/ss.out")
got=$(awk -F, '!/^#/ && $5 == "duff" && $3 == "z" && $4 == "renormalized" { print $NF }' "$T/ss/scene.csv")
awk -v a="$want" -v b="$got" 'BEGIN { exit !(a + 0 > 0 && (a - b) / a < 1e-3 && (b - a) / a < 1e-3) }' && ok ||
	bad "scene.csv's proven_max for duff is '$got', the report says '$want'"

# 6. --band: only that band, the first row is the band itself
./onbstudy certify --quick --quiet --methods duff --precision float --band -1,-0.9999 --out "$T/band" >/dev/null 2>&1 || bad "certify --band failed"
data "$T/band/certify.csv" | awk -F, 'NR == 2 { first = ($3 == -1 && $4 == -0.9999) } NR > 1 { n++; if ($3 < -1 || $4 > -0.9999) out++ } END { exit !(first && n > 1 && !out) }' \
	&& ok || bad "--band rows: $(data "$T/band/certify.csv" | head -3)"

# 6b. --fma: the contracted kernels' rows (METHOD+fma, bounded with their
#     contracted models) beside the plain ones, as many, found <= bound
if ./onbstudy certify --quick --quiet --fma --methods duff_branchless,rtow --precision float --band 0.3,0.6 --out "$T/fma" >/dev/null 2>"$T/fma.err"; then
	data "$T/fma/certify.csv" | awk -F, '$1 ~ /\+fma$/ { n[$1]++; if (!($7 + 0 >= $8 + 0 && $8 + 0 > 0)) b++ } $1 !~ /\+fma$/ { p[$1]++ }
		END { exit !(n["duff_branchless+fma"] > 0 && n["duff_branchless+fma"] == p["duff_branchless"] && n["rtow+fma"] == p["rtow"] && p["rtow"] > 0 && !b) }' \
		&& ok || bad "--fma rows: $(data "$T/fma/certify.csv" | head -3)"
elif grep -q 'no FMA' "$T/fma.err"; then
	echo "  (no FMA on this CPU: --fma not checked)"
else
	bad "certify --fma failed: $(cat "$T/fma.err")"
fi

# 7. the charts of the quick run (scripts/certify-plot.sh), through the chart check
if command -v gnuplot >/dev/null 2>&1; then
	sh scripts/certify-plot.sh "$T/a" >/dev/null 2>"$T/plot.err" && ok || bad "certify-plot.sh failed: $(cat "$T/plot.err")"
	for p in float double; do
		out=$(awk -f scripts/chart-check.awk "$T/a/certify_$p.svg" 2>&1) && ok || bad "certify_$p chart check: $out"
	done
else
	bad "gnuplot missing: scripts/install-deps.sh --test must install it"
fi

# 8. bad input: exit 2, one line, nothing written
for args in "--budget 0" "--tolerance -1" "--tolerance 0.5" "--precision quad" "--depth 3" "--methods nosuch" "--sectors 0" "--band 0.5" "--band 0.5,2" "--band 1,0" "stray"; do
	./onbstudy certify $args --out "$T/bad" >/dev/null 2>"$T/e"; rc=$?
	[ $rc -eq 2 ] && [ "$(wc -l <"$T/e")" -eq 1 ] && [ ! -e "$T/bad/certify.csv" ] && ok || bad "certify $args: exit $rc, $(cat "$T/e")"
done

finish certify.sh
