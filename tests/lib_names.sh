#!/bin/sh
# libonb's include name cannot clash with a renderer's own onb.h:
#  1. a client whose own onb.h (guarded by ONB_H, as in "Ray Tracing: The
#     Rest of Your Life") comes first on the include path includes both
#     headers, in either order, and links libonb.a: no file renamed, no define;
#     the same in C++ when a C++ compiler is present;
#  2. the installed tree: pkg-config's -I finds <libonb/onb.h>, a bare
#     <onb.h> there is the client's own; `make install-compat` adds the old
#     <onb.h> forward, and uninstall removes every file either wrote.
. "$(dirname "$0")/lib.sh"

# 1. the book-style adapter
mkdir -p "$tmp/book"
cat > "$tmp/book/onb.h" <<'H'
#ifndef ONB_H
#define ONB_H
/* a renderer's own basis type, under libonb's old file name and guard */
typedef struct onb { double axis[3][3]; } onb;
static inline void onb_build_from_w(onb *o, const double w[3])
{
	int i;
	for (i = 0; i < 3; i++) o->axis[2][i] = w[i];
}
#endif
H
for order in "book first" "libonb first"; do
	if [ "$order" = "book first" ]; then a='#include "onb.h"'; b='#include <libonb/onb.h>'
	else a='#include <libonb/onb.h>'; b='#include "onb.h"'; fi
	cat > "$tmp/adapter.c" <<C
$a
$b
int main(void)
{
	onb o;
	const double w[3] = { 0.0, 0.0, 1.0 };
	onb_vec3 n = { 0.0, 0.0, 1.0 }, b1, b2;
	onb_build_from_w(&o, w);
	onb_duff_branchless(n, &b1, &b2);
	onb_find("pbrt_v3")->basis(n, &b1, &b2);
	return !(o.axis[2][2] == 1.0 && b1.x * b1.x + b1.y * b1.y + b1.z * b1.z > 0.99);
}
C
	for c in cc c++; do
		command -v $c >/dev/null 2>&1 || continue
		lang=; [ $c = c++ ] && lang="-x c++"
		if $c $lang -Wall -Wextra -Werror -O2 $SAN -I"$tmp/book" -Iinclude -c "$tmp/adapter.c" -o "$tmp/adapter.o" 2>"$tmp/err" &&
		   $c $SAN "$tmp/adapter.o" libonb.a -lm -o "$tmp/adapter" 2>>"$tmp/err" && "$tmp/adapter"; then ok
		else bad "$c, $order, the book's onb.h first on -I:"; cat "$tmp/err"; fi
	done
done
grep -q '^#define ONB_H$' include/libonb/onb.h && bad "libonb's header defines ONB_H" || ok

# 2. installed: pkg-config's -I, the opt-in forward, uninstall
r="$tmp/root"; p=/opt/onb
if make -s install PREFIX=$p DESTDIR="$r" >/dev/null; then ok; else bad "make install"; fi
[ -f "$r$p/include/libonb/onb.h" ] && [ ! -e "$r$p/include/onb.h" ] && ok ||
	bad "make install: want include/libonb/onb.h and no include/onb.h"
if command -v pkg-config >/dev/null 2>&1; then
	flags=$(PKG_CONFIG_PATH="$r$p/lib/pkgconfig" PKG_CONFIG_SYSROOT_DIR="$r" pkg-config --cflags --libs onb)
else # the flags onb.pc gives, without the tool
	flags="-I$r$p/include -L$r$p/lib -lonb -lm"
fi
mkdir -p "$tmp/client"
sed 's|#include "onb.h"|#include <onb.h>|' "$tmp/adapter.c" > "$tmp/client/adapter.c"
if cc -std=c99 $SAN -I"$tmp/book" "$tmp/client/adapter.c" -o "$tmp/client/a" $flags 2>"$tmp/err" && "$tmp/client/a"; then ok
else bad "installed: <libonb/onb.h> with $flags beside the book's <onb.h>:"; cat "$tmp/err"; fi
# old code: #include <onb.h> alone, after make install-compat
printf '#include <onb.h>\nint main(void) { onb_vec3f n = { 0, 0, 1 }, a, b; onb_duff_branchlessf(n, &a, &b); return a.x != 1.0f; }\n' > "$tmp/client/old.c"
if make -s install-compat PREFIX=$p DESTDIR="$r" >/dev/null && [ -f "$r$p/include/onb.h" ] &&
   cc -std=c99 $SAN "$tmp/client/old.c" -o "$tmp/client/old" $flags 2>"$tmp/err" && "$tmp/client/old"; then ok
else bad "make install-compat: old <onb.h> client:"; cat "$tmp/err"; fi
make -s uninstall PREFIX=$p DESTDIR="$r" >/dev/null
left=$(find "$r" -type f)
[ -z "$left" ] && ok || bad "uninstall left: $left"
# a foreign include/onb.h is not libonb's to remove
mkdir -p "$r$p/include" && cp "$tmp/book/onb.h" "$r$p/include/onb.h"
make -s uninstall PREFIX=$p DESTDIR="$r" >/dev/null
[ -f "$r$p/include/onb.h" ] && ok || bad "uninstall removed another package's include/onb.h"
finish
