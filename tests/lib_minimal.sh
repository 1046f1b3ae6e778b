#!/bin/sh
# The library needs a C compiler, make and the C library's headers, nothing
# more (the README's library quick start): every header that libonb.a's
# sources and a client of <libonb/onb.h> include comes from this checkout,
# from the compiler itself, or from libc6-dev (and linux-libc-dev, which it
# depends on), by dpkg -S; `make lib` runs no tool beyond cc, ar, mkdir,
# rm (make -n).  scripts/minimal-root.sh runs the quick start itself in a
# fresh Debian 12 root (results/minimal-root.txt).
. "$(dirname "$0")/lib.sh"
command -v dpkg >/dev/null 2>&1 || skip "dpkg: not a Debian system"
printf '#include <libonb/onb.h>\nint main(void) { return 0; }\n' > "$tmp/client.c"
: > "$tmp/hdrs"
for f in src/lib/*.c "$tmp/client.c"; do
	for d in -DONB_COMMON "-DONB_ONE=duff -DONB_ONE_F" "-DONB_ONE=duff -DONB_ONE_D"; do
		cc -std=c99 -Iinclude $d -M "$f" 2>/dev/null | tr ' \\' '\n\n' | grep '^/' >> "$tmp/hdrs" ||
			bad "cc -M $d $f"
	done
done
sort -u "$tmp/hdrs" > "$tmp/h"
[ -s "$tmp/h" ] && ok || bad "no system header found (cc -M)"
others=""
while read -r h; do
	case "$h" in "$root"/*|"$tmp"/*) continue;; esac
	r=$(readlink -f "$h")
	p=$(dpkg -S "$r" 2>/dev/null | head -1 | cut -d: -f1) || p=""
	[ -n "$p" ] || p=$(dpkg -S "$h" 2>/dev/null | head -1 | cut -d: -f1) || p=""
	case "$p" in
	libc6-dev|linux-libc-dev|libgcc-*-dev|gcc-*|clang-*|libclang-*) ;;
	*) others="$others $h(${p:-no package})" ;;
	esac
done < "$tmp/h"
[ -z "$others" ] && ok || bad "headers outside the C library and the compiler:$others"
# the commands make lib runs
tools=$(env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory -n -B lib B="$tmp/b" 2>/dev/null | awk '{ print $1 }' | sort -u | tr '\n' ' ')
bads=$(for t in $tools; do case "$t" in cc|gcc|ar|mkdir|rm|"${CC:-cc}") ;; *) echo "$t";; esac; done)
[ -n "$tools" ] && [ -z "$bads" ] && ok || bad "make lib runs more than cc, ar, mkdir, rm: $tools"
finish lib_minimal
