#!/bin/sh
# libonb as a renderer sees it:
#  1. libonb.a exports only onb_* symbols (nm);
#  2. a program compiled elsewhere against only onb.h and libonb.a
#     enumerates the registry and calls every method in both precisions;
#  3. make install/uninstall with DESTDIR, and pkg-config --cflags --libs onb;
#     two prefixes in a row, each with its own onb.pc;
#  4. -ffast-math compiles, and the method names call the out-of-line copies.
. "$(dirname "$0")/lib.sh"
# Under `make test SANITIZE=...` the library carries sanitizer hooks, so
# programs linking it need the same flags.

# 1. symbol names
others=$(nm -g --defined-only libonb.a | awk 'NF == 3 {print $3}' | grep -v '^onb_' || true)
if [ -z "$others" ]; then ok; else bad "non-onb_ global symbols in libonb.a: $others"; fi
# External references: libm (fma: cycles_cross111_avx2), libc's memcpy/memset/strcmp, and libgcc's CPU
# detection for the ifunc resolvers; libgcc's binary16 conversions and
# comparisons (__extendhfsf2, __truncsfhf2, __extendhfdf2, __truncdfhf2,
# __eqhf2, __nehf2 and the other comparisons: the half entry points of src/lib/half.c without F16C; compiler-rt
# has the same names), which every gcc or clang link adds by itself.
# Nothing else (no MPFR, no OpenMP).
nm -g --defined-only libonb.a | awk 'NF == 3 {print $3}' | sort -u > "$tmp/defined"
undef=$(nm -u libonb.a | awk '{print $2}' | sort -u | comm -23 - "$tmp/defined" | grep -v -E '^(__asan_.*|__ubsan_.*|__sanitizer_.*|sqrt|sqrtf|copysign|copysignf|fmax|fmaxf|fma|fmaf|memcpy|memset|strcmp|__cpu_model|__cpu_indicator_init|__cpu_features2|__extendhfsf2|__truncsfhf2|__extendhfdf2|__truncdfhf2|__eqhf2|__nehf2|__lthf2|__lehf2|__gthf2|__gehf2|__unordhf2|_GLOBAL_OFFSET_TABLE_)$' || true)
if [ -z "$undef" ]; then ok; else bad "libonb.a needs more than libm and libc: $undef"; fi

# 2. a renderer-like program elsewhere
mkdir -p "$tmp/app/libonb"
cp include/libonb/onb.h "$tmp/app/libonb/"
cp libonb.a "$tmp/app/"
cat > "$tmp/app/app.c" <<'C'
#include <stdio.h>
#include <math.h>
#include "libonb/onb.h"
int main(void)
{
	size_t n, i, calls = 0;
	const onb_method *m = onb_methods(&n);
	onb_vec3 v = { 0.48, 0.6, 0.64 }, b1, b2;
	onb_vec3f vf = { 0.48f, 0.6f, 0.64f }, b1f, b2f;
	double nx = 0.0, ny = 0.6, nz = 0.8, o[6];
	float fx = 0.0f, fy = 0.6f, fz = 0.8f, of[6];
	for (i = 0; i < n; i++) {
		if (!m[i].basis != !!(m[i].flags & ONB_FLOAT_ONLY) || !m[i].batch != !!(m[i].flags & ONB_FLOAT_ONLY))
			return printf("%s: double entry points present iff not ONB_FLOAT_ONLY\n", m[i].name), 1;
		if (m[i].basis) {
			m[i].basis(v, &b1, &b2);
			m[i].batch(1, &nx, &ny, &nz, o, o + 1, o + 2, o + 3, o + 4, o + 5);
			calls += 2;
		} else {
			b1.x = b1.y = b1.z = 0.0;
		}
		m[i].basisf(vf, &b1f, &b2f);
		m[i].batchf(1, &fx, &fy, &fz, of, of + 1, of + 2, of + 3, of + 4, of + 5);
		if (fabs(b1.x * v.x + b1.y * v.y + b1.z * v.z) > 1e-6 || fabsf(of[0] * fx + of[1] * fy + of[2] * fz) > 1e-3f)
			return printf("%s: not orthogonal\n", m[i].name), 1;
		calls += 2;
	}
	onb_duff_branchless(v, &b1, &b2); /* the inline function */
	printf("%zu methods, %zu calls, isa %s\n", n, calls, onb_batch_isa());
	/* the registry has one row per method of the header's lists */
#define ONE(m) + 1
	return n == (size_t)(0 ONB_METHOD_LIST(ONE) ONB_FLOAT_METHOD_LIST(ONE)) ? 0 : 1;
}
C
if (cd "$tmp/app" && cc -std=c99 -Wall -Wextra -O2 -ffp-contract=off $SAN app.c libonb.a -lm -o app && ./app); then ok; else bad "standalone program against onb.h + libonb.a"; fi

# 3. install, pkg-config, uninstall
if make -s install PREFIX=/opt/onb DESTDIR="$tmp/root" >/dev/null; then ok; else bad "make install"; fi
pc="$tmp/root/opt/onb/lib/pkgconfig"
if [ -f "$pc/onb.pc" ] && [ -f "$tmp/root/opt/onb/include/libonb/onb.h" ] && [ -f "$tmp/root/opt/onb/lib/libonb.a" ]; then ok; else bad "installed files"; fi
if command -v pkg-config >/dev/null 2>&1; then
	flags=$(PKG_CONFIG_PATH="$pc" PKG_CONFIG_SYSROOT_DIR="$tmp/root" pkg-config --cflags --libs onb)
	if cc -std=c99 $SAN "$tmp/app/app.c" -o "$tmp/app2" $flags && "$tmp/app2" >/dev/null; then ok; else bad "build with pkg-config flags: $flags"; fi
fi
make -s uninstall PREFIX=/opt/onb DESTDIR="$tmp/root" >/dev/null
if [ -z "$(find "$tmp/root" -type f)" ]; then ok; else bad "uninstall left: $(find "$tmp/root" -type f)"; fi
# Two real prefixes in a row (no DESTDIR): each onb.pc names its own
# prefix, carries no floating-point flag, and builds a client; nothing is
# generated in the tree.
for p in "$tmp/pa" "$tmp/pb"; do
	if make -s install PREFIX="$p" >/dev/null; then ok; else bad "make install PREFIX=$p"; continue; fi
	grep -qx "prefix=$p" "$p/lib/pkgconfig/onb.pc" && ok || bad "$p/lib/pkgconfig/onb.pc names another prefix: $(head -1 "$p/lib/pkgconfig/onb.pc")"
	! grep -q 'fp-contract\|ffast\|fno-' "$p/lib/pkgconfig/onb.pc" && ok || bad "onb.pc carries FP flags to clients"
	if command -v pkg-config >/dev/null 2>&1; then
		flags=$(PKG_CONFIG_PATH="$p/lib/pkgconfig" pkg-config --cflags --libs onb)
		case "$flags" in *"$p"/include*) ok;; *) bad "pkg-config --cflags for $p: $flags";; esac
		if (cd "$tmp" && cc -std=c99 $SAN app/app.c -o app_p $flags && ./app_p >/dev/null); then ok; else bad "client with $p's pkg-config flags: $flags"; fi
	fi
done
[ ! -e onb.pc ] && ok || bad "make install left onb.pc in the tree"

# 4. -ffast-math compiles with no define, and the method names then call
# libonb.a's out-of-line copies (the bits: tests/lib_client.sh)
printf '#include "libonb/onb.h"\nvoid f(onb_vec3 n, onb_vec3 *a, onb_vec3 *b) { onb_duff(n, a, b); }\n' > "$tmp/fm.c"
if cc -std=c99 -ffast-math -O2 -Wall -Wextra -Werror -Iinclude -c "$tmp/fm.c" -o "$tmp/fm.o" 2>"$tmp/fm.err"; then
	nm "$tmp/fm.o" | grep -q ' U onb_duff_outline$' && ok || bad "-ffast-math: onb_duff does not call onb_duff_outline"
else bad "-ffast-math did not compile: $(head -3 "$tmp/fm.err")"; fi

# 5. onbstudy list names every method; --help works; a bad command exits 2
nmeth=$(sed -n '/define ONB_METHOD_LIST/,/^$/p' include/libonb/onb.h | grep -o 'X([a-z0-9_]*)' | wc -l)
nmeth=$((nmeth + $(grep 'define ONB_FLOAT_METHOD_LIST' include/libonb/onb.h | grep -o 'X([a-z0-9_]*)' | wc -l)))
if [ "$nmeth" -ge 18 ] && [ "$(./onbstudy list --format csv | tail -n +2 | wc -l)" -eq "$nmeth" ]; then ok; else bad "onbstudy list (want $nmeth methods)"; fi
./onbstudy --help >/dev/null && ok || bad "onbstudy --help"
./onbstudy frobnicate 2>/dev/null; [ $? -eq 2 ] && ok || bad "unknown command must exit 2"

finish
