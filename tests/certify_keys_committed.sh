#!/bin/sh
# certify_keys_committed.sh - every key of the committed certify results is
# current for this code, checked without proving anything (issue 46):
# each directory under results/certify, results/gpu and results/half that
# holds a certify-keys.csv is checked with `onbstudy certify ARGS
# --check-keys DIR`, ARGS its keys file's '# command:' line without the
# binary, --out, --resume, --checkpoint-every, --write-keys and --quiet (a
# --starts path is read from its results/... part).  results/certify's
# keys were written by --write-keys (its rows predate the keys:
# docs/certify.md says how they were shown current).  A changed kernel, model, family,
# setting or certify engine makes its keys stale and this test fail
# (src/certify/engines.txt: an engine declared byte-identical to an
# earlier one keeps that one's name).  The check itself is checked: a copy
# of each keys file with one key altered must be found stale, naming that
# method.  The wild rows' certify runs (results/wild/add) are not checked:
# each was made by the engine of its day and is kept as that day's record.
. "$(dirname "$0")/lib.sh"
T=$tmp
n=0
for keys in $(find results/certify results/gpu results/half -name certify-keys.csv 2> /dev/null | sort); do
	d=${keys%/certify-keys.csv}
	cmd=$(sed -n 's/^# command: //p' "$keys")
	[ -n "$cmd" ] || { bad "$keys: no '# command:' line"; continue; }
	args=$(printf '%s\n' "$cmd" | awk '{
		out = ""
		for (i = 1; i <= NF; i++) {
			if (i == 1 || $i == "certify" && !seen++) continue
			if ($i == "--out" || $i == "--resume" || $i == "--checkpoint-every" || $i == "--write-keys") { i++; continue }
			if ($i == "--quiet") continue
			a = $i
			if (prev == "--starts" && (k = index(a, "results/")) > 0) a = substr(a, k)
			out = out " " a; prev = $i
		}
		print out }')
	# shellcheck disable=SC2086  # ARGS are words of a command line
	./onbstudy certify $args --quiet --check-keys "$d" > "$T/ck.out" 2> "$T/ck.err"
	rc=$?
	[ $rc -eq 0 ] && grep -q ': \([0-9]*\) of \1 keys current$' "$T/ck.out" && ok ||
		bad "$d: keys not current (exit $rc): $(cat "$T/ck.out" "$T/ck.err" | head -5)"
	# the same check on a copy with the first key altered: stale, named
	# (of that method alone: a later --methods replaces the list)
	mkdir -p "$T/stale$n"
	awk -F, '!done && /^[^#]/ && $1 != "method" { print $1 "," $2 ",0123456789abcdef"; m = $1 " " $2; done = 1; next }
		{ print } END { print m > "/dev/stderr" }' "$keys" > "$T/stale$n/certify-keys.csv" 2> "$T/stale$n.name"
	./onbstudy certify $args --methods "$(cut -d' ' -f1 "$T/stale$n.name")" --quiet --check-keys "$T/stale$n" > "$T/st.out" 2>&1
	rc=$?
	[ $rc -eq 1 ] && grep -q "^stale: $(cat "$T/stale$n.name") " "$T/st.out" && ok ||
		bad "$d with one key altered ($(cat "$T/stale$n.name")): exit $rc: $(head -3 "$T/st.out")"
	n=$((n + 1))
done
[ $n -gt 0 ] && ok || bad "no committed certify-keys.csv under results/certify, results/gpu, results/half"
[ -f results/certify/certify-keys.csv ] && ok || bad "results/certify (the committed IEEE run) has no certify-keys.csv"

# --write-keys refuses a certify.csv that is not of its command line: a
# region's row missing, or a method on the command line with no rows
mkdir -p "$T/wk"
awk -F, '!/^#/ && $1 == "rtow" && $2 == "float" && ++k == 3 { next } { print }' results/certify/certify.csv > "$T/wk/certify.csv"
./onbstudy certify --methods rtow --precision float --starts results/certify/starts.csv --quiet --write-keys "$T/wk" > "$T/wk.out" 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q 'does not hold the [0-9]* regions of rtow float' "$T/wk.out" && [ ! -e "$T/wk/certify-keys.csv" ] && ok ||
	bad "--write-keys on a certify.csv with a row missing: exit $rc: $(head -2 "$T/wk.out")"
./onbstudy certify --methods rtow --precision double --starts results/certify/starts.csv --quiet --write-keys "$T/wk" > "$T/wk.out" 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q 'rows of methods, precisions or regions not on this command line' "$T/wk.out" && ok ||
	bad "--write-keys with rows of another method there: exit $rc: $(head -2 "$T/wk.out")"
# ... and writes, for a certify.csv of its command line, the key
# --check-keys finds current: rtow float's rows alone, the committed key
mkdir -p "$T/wk2"
awk -F, '/^#/ || $1 == "method" || $1 == "rtow" && $2 == "float"' results/certify/certify.csv > "$T/wk2/certify.csv"
./onbstudy certify --methods rtow --precision float --starts results/certify/starts.csv --quiet --write-keys "$T/wk2" > "$T/wk2.out" 2>&1
rc=$?
[ $rc -eq 0 ] && grep -q '^rtow,float,' "$T/wk2/certify-keys.csv" &&
	[ "$(grep '^rtow,float,' "$T/wk2/certify-keys.csv")" = "$(grep '^rtow,float,' results/certify/certify-keys.csv)" ] && ok ||
	bad "--write-keys of rtow float: exit $rc, key $(grep '^rtow,float,' "$T/wk2/certify-keys.csv" 2> /dev/null), committed $(grep '^rtow,float,' results/certify/certify-keys.csv 2> /dev/null): $(head -2 "$T/wk2.out")"
finish certify_keys_committed
