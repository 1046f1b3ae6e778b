#!/bin/sh
# aliases.sh - the alias table (engines' code that is a registry method bit
# for bit): `onbstudy list` shows each as "NAME = TARGET, bit for bit", its
# CSV gives the provenance (a 40-hex commit, path:lines, license), and the
# command line runs the target where a method name is accepted.  The bit
# identity itself is tests/test_indep.c's (the aliases' transliterations,
# tests/indep_wild.h, against their targets).
. "$(dirname "$0")/lib.sh"
./onbstudy list --aliases --format csv > "$tmp/a.csv" 2> "$tmp/err" && ok || bad "list --aliases --format csv: $(cat "$tmp/err")"
n=$(tail -n +2 "$tmp/a.csv" | wc -l)
[ "$n" -ge 5 ] && ok || bad "list --aliases: want at least 5 aliases, got $n"
methods=$(./onbstudy list --format csv | tail -n +2 | cut -d, -f1)
tail -n +2 "$tmp/a.csv" | while IFS=, read -r name target rest; do
	echo "$rest" | grep -qE ',[0-9a-f]{40},"[^"]+:[0-9]+-[0-9]+",' || echo "FAIL: alias $name: no 40-hex commit and path:lines"
	case " $(echo $methods) " in *" $target "*) ;; *) echo "FAIL: alias $name: target $target is not a method" ;; esac
	case " $(echo $methods) " in *" $name "*) echo "FAIL: alias $name is also a method's name" ;; esac
	./onbstudy list | grep -q "^$name  *= $target, bit for bit" || echo "FAIL: onbstudy list does not show $name = $target"
done > "$tmp/rows"
[ -s "$tmp/rows" ] && bad "$(cat "$tmp/rows")" || ok
# an alias is accepted where a method is, and runs its target
./onbstudy eval --methods pbrt_v4 0.6 0 -0.8 > "$tmp/alias.txt" 2>&1 && ok || bad "eval --methods pbrt_v4: $(cat "$tmp/alias.txt")"
./onbstudy eval --methods duff_branchless 0.6 0 -0.8 > "$tmp/target.txt" 2>&1
cmp -s "$tmp/alias.txt" "$tmp/target.txt" && ok || bad "eval --methods pbrt_v4 differs from eval --methods duff_branchless"
./onbstudy list --axes --aliases > /dev/null 2>&1; [ $? -eq 2 ] && ok || bad "list --axes --aliases: want exit 2"
finish aliases
