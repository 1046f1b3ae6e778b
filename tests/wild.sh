#!/bin/sh
# wild.sh - docs/wild.md and the README's engines line against the
# committed runs and the registry (scripts/wild.sh --check), their layout
# (findings first, the engines' table sorted by the worst defect, aliases
# grouped, the README's six worst), the patches in results/wild/patches,
# and the table itself: at least 12 engine rows, each with a 40-hex commit, a path with
# its line range and a replay command that `onbstudy eval` runs and that
# gives the defect the row reports; the generator refuses an engine that
# fails in float without a maintainer paragraph.  Run from the top
# directory after `make`.
set -u
pass=0; fail=0
ok() { pass=$((pass + 1)); }
bad() { echo "FAIL: $*"; fail=$((fail + 1)); }
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT

if sh scripts/wild.sh --check docs/wild.md > "$T/out" 2>&1; then ok; else cat "$T/out"; bad "docs/wild.md is not what scripts/wild.sh generates"; fi
if sh scripts/wild.sh --readme --check README.md > "$T/out" 2>&1; then ok; else cat "$T/out"; bad "README.md's engines line is not what scripts/wild.sh --readme generates"; fi

# the engine rows: "| `name`..." lines of the tables before the binary16
# section (the findings use ### headings; that section's table, one row per
# shader engine, is checked by wild.sh --check above)
awk '/^## The shader engines in binary16/ { exit } /^\| `/' docs/wild.md > "$T/rows"
./onbstudy list --format csv | tail -n +2 | cut -d, -f1,4 > "$T/flags"
n=$(wc -l < "$T/rows")
if [ "$n" -ge 12 ]; then ok; else bad "docs/wild.md has $n engine rows, fewer than 12"; fi
m=$(./onbstudy list --format csv | grep -cE ',[0-9a-f]{40},')
a=$(./onbstudy list --aliases --format csv | awk 'NR > 1' | wc -l)
if [ "$n" -eq $((m + a)) ]; then ok; else bad "docs/wild.md has $n engine rows, the registry $m engines' methods and $a aliases"; fi
while IFS= read -r row; do
	name=$(printf '%s\n' "$row" | sed 's/^| `\([a-z0-9_]*\)`.*/\1/')
	printf '%s\n' "$row" | grep -Eq '`[0-9a-f]{40}`' || bad "$name: no 40-hex commit"
	printf '%s\n' "$row" | grep -Eq ':[0-9]+-[0-9]+' || bad "$name: no path with a line range"
	cmd=$(printf '%s\n' "$row" | sed -n 's/.*`onbstudy \(eval [^`]*\)`.*/\1/p')
	if [ -z "$cmd" ]; then
		# only a method the committed run predates may lack its input
		tgt=$(printf '%s\n' "$row" | sed -n 's/^| `[a-z0-9_]*` = `\([a-z0-9_]*\)`.*/\1/p'); [ -n "$tgt" ] || tgt=$name
		if printf '%s\n' "$row" | grep -q 'not in the committed run' && ! cat results/wild/summary.csv results/wild/add/*/summary.csv 2> /dev/null | grep -q "^$tgt,"; then
			echo "note: $name is not in the committed run yet"; ok
		else bad "$name: no replayable input"; fi
		continue
	fi
	prec=$(printf '%s\n' "$cmd" | sed 's/.*--precision \([a-z]*\).*/\1/')
	# shellcheck disable=SC2086 # the command's words
	if ! ./onbstudy $cmd > "$T/eval" 2>&1; then bad "$name: '$cmd' failed"; continue; fi
	got=$(sed -n 's/.*(max \([^)]*\)).*/\1/p' "$T/eval" | head -1)
	grep -q 'NON-FINITE output' "$T/eval" && got=nan
	# the row's figure for that precision: found column, "float / double"
	want=$(printf '%s\n' "$row" | awk -F' [|] ' -v p="$prec" '{ split($5, f, " / "); v = (p == "float") ? f[1] : f[2]; sub(/ \(.*/, "", v); print v }')
	# a method flagged ONB_HW_RSQRT (flags bit 0) runs rsqrtss, whose bits
	# differ between CPU vendors (Intel's and AMD's tables, both within
	# 1.5 * 2^-12): its replayed defect is the row's on the CPU that made the
	# run, and on another vendor's it must still lie within the row's bound
	hw=$(awk -F, -v m="$name" '$1 == m { print $2 % 2 }' "$T/flags")
	bnd=$(printf '%s\n' "$row" | awk -F' [|] ' -v p="$prec" '{ split($6, f, " / "); v = (p == "float") ? f[1] : f[2]; sub(/ \(.*/, "", v); sub(/^<= /, "", v); print v }')
	if awk -v g="$got" -v w="$want" -v p="$prec" -v hw="${hw:-0}" -v b="$bnd" 'BEGIN {
		u = (p == "float") ? 2^-24 : 2^-53
		if (w ~ /u$/) { sub(/u$/, "", w); w *= u }
		if (b ~ /u$/) { sub(/u$/, "", b); b *= u }
		if (w == "non-finite") exit !(g ~ /nan|inf/)
		if (g + 0 > 0 && (g - w) / w < 0.006 && (w - g) / w < 0.006) exit 0
		exit !(hw == 1 && b ~ /^[0-9.e+-]+$/ && g + 0 > 0 && g + 0 <= b + 0) }'; then ok
	else bad "$name: '$cmd' gives defect $got, the row says $want (bound $bnd)"; fi
done < "$T/rows"

# a paragraph's "finds D = X at" followed by an `onbstudy eval` command
# (a worst input outside the committed run, as rtao's): the replay gives X
tr '\n' ' ' < docs/wild.md | grep -o 'finds D = [0-9.e+-]* at `onbstudy eval [^`]*`' > "$T/paras"
[ -s "$T/paras" ] && ok || bad "no 'finds D = X at \`onbstudy eval ...\`' replay in docs/wild.md"
while IFS= read -r para; do
	want=$(printf '%s\n' "$para" | sed 's/^finds D = \([^ ]*\) at.*/\1/')
	cmd=$(printf '%s\n' "$para" | sed 's/.*`onbstudy \(eval [^`]*\)`/\1/')
	# shellcheck disable=SC2086 # the command's words
	got=$(./onbstudy $cmd 2>&1 | sed -n 's/.*(max \([^)]*\)).*/\1/p' | head -1)
	awk -v g="$got" -v w="$want" 'BEGIN { exit !(g != "" && sprintf("%.3g", g) == sprintf("%.3g", w)) }' && ok ||
		bad "docs/wild.md says D = $want at '$cmd', the replay gives '$got'"
done < "$T/paras"

# the layout of docs/wild.md: the findings (### headings) before the
# engines' table; that table and the findings sorted by the worst defect
# found in float (non-finite first), then in double; the aliases grouped
# by their target; the README's list at most six, the docs' first ones.
# order FILE: the rows of FILE's engines' table (not the aliases) out of
# order, "" when sorted; each row's float and double figures as numbers.
order() {
	awk -F' [|] ' '
	function v(s, p) {
		sub(/ \(.*/, "", s)
		if (s == "non-finite" || s ~ /nan|inf/) return 1e308 * 10
		if (s == "-" || s == "") return -1
		if (s ~ /u$/) { sub(/u$/, "", s); return s * (p == "float" ? 2 ^ -24 : 2 ^ -53) }
		return s + 0
	}
	/^## The engines.* own arithmetic/ { on = 1; next }
	/^## / { on = 0 }
	on && /^[|] `/ && !/^[|] `[a-z0-9_]*` = / {
		split($5, f, " / "); a = v(f[1], "float"); b = v(f[2], "double")
		name = $1; sub(/^[|] `/, "", name); sub(/`.*/, "", name)
		if (n && (a > pa || (a == pa && b > pb))) print name " above " prev
		n++; pa = a; pb = b; prev = name
	}' "$1"
}
got=$(order docs/wild.md)
if [ -z "$got" ]; then ok; else bad "docs/wild.md's engines' table is not sorted by the worst defect: $got"; fi
# the check can fail: the table with its first two rows exchanged
awk '/^## The engines.* own arithmetic/ { on = 1 } on && /^[|] `/ && !held { held = $0; next } { print } held != "" && on && /^[|] `/ && !done { print held; done = 1 }' docs/wild.md > "$T/swap.md"
if [ -n "$(order "$T/swap.md")" ]; then ok; else bad "the sort check passed a table with its first two rows exchanged"; fi
# the findings come first, in the table's order
fl=$(grep -n '^### `' docs/wild.md | tail -1 | cut -d: -f1); tl=$(grep -n "^## The engines.* own arithmetic" docs/wild.md | cut -d: -f1)
if [ -n "$tl" ] && [ "${fl:-0}" -lt "$tl" ]; then ok; else bad "docs/wild.md: the findings do not come before the engines' table"; fi
grep '^### `' docs/wild.md | sed 's/^### `\([a-z0-9_]*\)`.*/\1/' > "$T/fnames"
awk '/^## The engines.* own arithmetic/ { on = 1; next } /^## / { on = 0 } on && /^[|] `/ { n = $0; sub(/^[|] `/, "", n); sub(/`.*/, "", n); print n }' docs/wild.md > "$T/mnames"
# (the methods' findings in the table's order; an alias's sorts with its target's figures)
grep -Fxf "$T/mnames" "$T/fnames" > "$T/fm" || true
grep -Fxf "$T/fnames" "$T/mnames" > "$T/tm" || true
if [ -s "$T/fm" ] && cmp -s "$T/fm" "$T/tm"; then ok; else bad "docs/wild.md: the findings are not in the engines' table's order"; fi
# the aliases: each target's rows together
got=$(grep '^| `[a-z0-9_]*` = `' docs/wild.md | sed 's/^| `[a-z0-9_]*` = `\([a-z0-9_]*\)`.*/\1/' | uniq | sort | uniq -d)
if [ -z "$got" ]; then ok; else bad "docs/wild.md: the aliases of $got are not grouped"; fi
# the README: at most six findings, the docs' first ones in the same order
sed -n '/^<!-- wild:begin/,/^<!-- wild:end/p' README.md | grep '^| `' | sed 's/^| `\([a-z0-9_]*\)`.*/\1/' > "$T/rnames"
nr=$(wc -l < "$T/rnames")
if [ "$nr" -ge 1 ] && [ "$nr" -le 6 ] && head -n "$nr" "$T/fnames" | cmp -s - "$T/rnames"; then ok
else bad "README's engines table is not the first $nr of docs/wild.md's findings (at most six)"; fi

# results/wild/patches: each NAME.diff is the fix NAME of a registry
# method F (NAME's family, an engine's method), against F's file at F's
# commit, names F's license, is a unified diff of that file, and is listed
# in the patches' README.  A fix of an engine outside its family names
# both in its header: "Method: FIX" (else NAME) and "Engine: E" (a
# registry method or alias with a commit: q2rtx_fixed patches q2rtx and
# the alias nvpro)
./onbstudy list --format csv > "$T/list"
./onbstudy list --aliases --format csv | tail -n +2 >> "$T/list"
np=0
for d in results/wild/patches/*.diff; do
	[ -f "$d" ] || continue
	np=$((np + 1)); p=$(basename "$d" .diff)
	hm=$(sed -n 's/^Method: *\([a-z0-9_]*\).*/\1/p' "$d" | head -1); [ -n "$hm" ] && p=$hm
	fam=$(awk -F, -v m="$p" '$1 == m { print $2 }' "$T/list")
	if [ -z "$fam" ]; then bad "patches/$p.diff: $p is not a registry method"; continue; fi
	he=$(sed -n 's/^Engine: *\([a-z0-9_]*\).*/\1/p' "$d" | head -1); [ -n "$he" ] && fam=$he
	line=$(grep "^$fam," "$T/list")
	c=$(printf '%s\n' "$line" | grep -oE '[0-9a-f]{40}' | head -1)
	f=$(printf '%s\n' "$line" | sed -n 's/.*,"\([^":]*\):[0-9]*-[0-9]*",.*/\1/p')
	l=$(printf '%s\n' "$line" | sed -n 's/.*:[0-9]*-[0-9]*",\([^,]*\),.*/\1/p')
	if [ -z "$c" ] || [ -z "$f" ] || [ -z "$l" ]; then bad "patches/$p.diff: $p's family $fam is not an engine's method with a commit, path and license"; continue; fi
	if grep -q "^Of: .* at commit $c\$" "$d" && grep -q "^File: *$f\$" "$d" && grep -q "^License: $l " "$d" \
		&& grep -q "^--- a/$f\$" "$d" && grep -q "^+++ b/$f\$" "$d" && grep -qE '^@@ -[0-9]+,[0-9]+ \+[0-9]+,[0-9]+ @@' "$d"; then ok
	else bad "patches/$p.diff: not a diff of $fam's $f at $c naming its license $l"; fi
	grep -q "($(basename "$d"))" results/wild/patches/README.md && ok || bad "patches/$(basename "$d") is not in results/wild/patches/README.md"
done
[ "$np" -ge 4 ] && ok || bad "results/wild/patches has $np diffs, fewer than 4"

# a missing maintainer paragraph stops the generator
awk '/^<!-- para / { skip = 1; next } skip && /^<!-- end -->$/ { skip = 0; next } !skip' scripts/wild.md.in > "$T/nopara.md.in"
if grep -q '^### ' docs/wild.md; then
	if WILD_TPL="$T/nopara.md.in" sh scripts/wild.sh > /dev/null 2> "$T/err"; then
		bad "scripts/wild.sh accepted a template without the findings' paragraphs"
	elif grep -q 'has no <!-- para' "$T/err"; then ok
	else cat "$T/err"; bad "scripts/wild.sh failed without naming the missing paragraph"; fi
fi
# --check notices a changed figure
sed '0,/^| `/{s/^| `\([a-z0-9_]*\)` /| `\1` X/}' docs/wild.md > "$T/wild.md"
if sh scripts/wild.sh --check "$T/wild.md" > /dev/null 2>&1; then bad "--check accepted a changed row"; else ok; fi

# runs added after the full one (wild-run.sh --add): a method's rows come
# from the last directory that has it; another header is refused
printf '# a\nmethod,precision,error\nm1,float,1\nm2,float,2\nm2,double,3\n' > "$T/a.csv"
printf '# b\nmethod,precision,error\nm2,float,9\n' > "$T/b.csv"
printf 'method,precision,error2\nm3,float,1\n' > "$T/c.csv"
got=$(awk -f scripts/wild-merge.awk "$T/a.csv" "$T/b.csv" | paste -sd' ' -)
if [ "$got" = "# a method,precision,error m1,float,1 m2,float,9" ]; then ok; else bad "wild-merge.awk gave '$got'"; fi
if awk -f scripts/wild-merge.awk "$T/a.csv" "$T/c.csv" > /dev/null 2> "$T/err"; then bad "wild-merge.awk mixed two headers"
elif grep -q "header differs" "$T/err"; then ok; else bad "wild-merge.awk failed without naming the header"; fi
if sh scripts/wild-run.sh --add 'Bad/Group' x > /dev/null 2>&1; then bad "wild-run.sh --add accepted the group 'Bad/Group'"; else ok; fi

echo "wild: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
