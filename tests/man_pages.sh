#!/bin/sh
# man_pages.sh - the man pages: man/onbstudy.1 is what help2man
# makes of this build's --help texts (scripts/man.sh --check); man/onb.3,
# written by hand, names every method of the registry and every public
# function and type of include/libonb/onb.h; `make install` puts both where
# `man onbstudy` and `man onb` find them, and `make uninstall` removes them.
. "$(dirname "$0")/lib.sh"
sh scripts/man.sh --check > "$tmp/check" 2>&1 && ok || bad "$(cat "$tmp/check")"

# onb.3: every method, every public name of onb.h
methods=$(./onbstudy list --format csv | tail -n +2 | cut -d, -f1)
[ -n "$methods" ] || bad "onbstudy list gave no methods"
for m in $methods; do
	grep -qw -- "$m" man/onb.3 || bad "man/onb.3 does not name the method $m"
done
names=$(grep -oE '^(static inline )?(const )?[a-z_0-9]+ \*?onb_[a-z0-9_]+ *\(' include/libonb/onb.h | grep -oE 'onb_[a-z0-9_]+' | grep -v '^onb__' | sort -u)
missing=""
for n in $names; do
	s=${n#onb_}; s=${s%f}
	case " $(echo $methods) " in *" ${n#onb_} "*|*" $s "*) continue ;; esac   # a method: named above
	grep -qF -- "$n" man/onb.3 || missing="$missing $n"
done
[ -z "$missing" ] && ok || bad "man/onb.3 does not name:$missing"
[ "$(echo "$names" | wc -w)" -ge 10 ] && ok || bad "found only $(echo "$names" | wc -w) public names in include/libonb/onb.h"
# onb.3's synopsis gives each one-line declaration of onb.h as onb.h has it
# (whitespace aside): the registry, the checked and array entry points, the
# tools, and the per-method array functions with NAME for the method (an
# asm label, ONB__LABEL, is the header's business, not the synopsis')
MANWIDTH=400 man -P cat -l man/onb.3 2> /dev/null | sed 's/[[:space:]]\{1,\}/ /g' > "$tmp/onb3.txt"
{
	grep -E '^(const )?[a-z_]+ \*?onb_[a-z_]+ *\(.*\);$' include/libonb/onb.h
	grep -E '^static inline [a-z_0-9]+ \*?onb_frisvad_(threshold|rotate)f? *\(.*\)$' include/libonb/onb.h | sed 's/$/;/'
	grep -E '^[[:space:]]*void onb_##m##_arrayf? *\(.*\);' include/libonb/onb.h | sed 's/##m##/NAME/; s/; *\\$/;/'
} | sed -e 's/ ONB__LABEL("[^"]*");$/;/' -e 's/^static inline //' -e 's/^[[:space:]]*//' -e 's/[[:space:]]\{1,\}/ /g' -e 's/ *( */(/' | sort -u > "$tmp/decls"
[ "$(wc -l < "$tmp/decls")" -ge 11 ] && ok || bad "found only $(wc -l < "$tmp/decls") declarations in include/libonb/onb.h"
while IFS= read -r d; do
	grep -qF -- "$d" "$tmp/onb3.txt" || bad "man/onb.3's synopsis lacks: $d"
done < "$tmp/decls"

# installed, found by man, removed by uninstall
if make -s install PREFIX=/p DESTDIR="$tmp/root" > "$tmp/install" 2>&1; then ok; else bad "make install: $(cat "$tmp/install")"; fi
M=$tmp/root/p/share/man
for page in onbstudy onb; do
	MANPATH=$M MANWIDTH=80 man -P cat "$page" > "$tmp/$page.txt" 2> "$tmp/$page.err"
	[ $? -eq 0 ] && [ -s "$tmp/$page.txt" ] && [ ! -s "$tmp/$page.err" ] && ok || bad "man $page: $(head -3 "$tmp/$page.err")"
done
for c in $(./onbstudy --help | awk '/^commands:/ { on = 1; next } on && /^  [a-z]/ { print $1 }'); do
	grep -q "^   onbstudy $c\$" "$tmp/onbstudy.txt" || bad "man onbstudy has no section for '$c'"
done
grep -q 'onb_basis_checked' "$tmp/onb.txt" && ok || bad "man onb does not render its synopsis"
make -s uninstall PREFIX=/p DESTDIR="$tmp/root" > /dev/null 2>&1
[ -z "$(find "$tmp/root" -type f)" ] && ok || bad "uninstall left: $(find "$tmp/root" -type f)"
finish man_pages
