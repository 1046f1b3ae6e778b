#!/bin/sh
# libonb in other people's builds (issue 15):
#  1. onb.h compiles clean under -Wall -Wextra -Wpedantic -Wshadow
#     -Wconversion -Wdouble-promotion -Wfloat-equal -Werror in C99, C11 and
#     C++17 (gcc/g++, and clang/clang++ when installed), every inline
#     function instantiated; and under -ffast-math with ONB_ALLOW_FAST_MATH;
#  2. a client built with -ffast-math, and one built with
#     -ffp-contract=fast, get the studied bits (those of the inline
#     functions built with the library's flags) from the out-of-line calls,
#     through onb_vec3[f] (onb_NAME_outline[f]) and through their own
#     float[3]/double[3] vectors (onb_NAME_array[f], onb_basis_array[f]);
#  3. the contraction pragmas: with them, GCC's inline functions keep the
#     studied bits under -ffp-contract=fast; without them
#     (ONB_INLINE_FOLLOWS_CLIENT_FP) the bits change on an FMA CPU, which
#     shows that check 2 can fail.
. "$(dirname "$0")/lib.sh"
W="-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion -Wfloat-equal -Werror"
LIBFP="-O2 -ffp-contract=off -fno-math-errno -fno-trapping-math"

# 1. every inline function, under the strict warnings
cat > "$tmp/all.c" <<'C'
#include "onb.h"
#define USE(m) \
	static void use_##m(onb_vec3 n, onb_vec3f nf, onb_vec3 *b, onb_vec3f *bf) \
	{ onb_##m(n, b, b + 1); onb_##m##f(nf, bf, bf + 1); }
ONB_METHOD_LIST(USE)
#undef USE
#define USEF(m) static void usef_##m(onb_vec3f nf, onb_vec3f *bf) { onb_##m##f(nf, bf, bf + 1); }
ONB_FLOAT_METHOD_LIST(USEF)
#undef USEF
int main(void)
{
	onb_vec3 n = { 0.0, 0.6, 0.8 }, b[2];
	onb_vec3f nf = { 0.0f, 0.6f, 0.8f }, bf[2];
#define CALL(m) use_##m(n, nf, b, bf);
	ONB_METHOD_LIST(CALL)
#undef CALL
#define CALLF(m) usef_##m(nf, bf);
	ONB_FLOAT_METHOD_LIST(CALLF)
#undef CALLF
	onb_frisvad_threshold(n, -0.5, b, b + 1);
	onb_frisvad_thresholdf(nf, -0.5f, bf, bf + 1);
	b[0] = onb_frisvad_rotate(n, 1.0, 0.0, 0.0);
	bf[0] = onb_frisvad_rotatef(nf, 1.0f, 0.0f, 0.0f);
	return b[0].x > 2.0 || bf[0].x > 2.0f;
}
C
cp "$tmp/all.c" "$tmp/all.cpp"
for c in "gcc -std=c99" "gcc -std=c11" "g++ -std=c++17" "clang -std=c99" "clang -std=c11" "clang++ -std=c++17"; do
	set -- $c
	command -v "$1" >/dev/null 2>&1 || { echo "skip: $1 not installed"; continue; }
	src="$tmp/all.c"; case "$1" in *++) src="$tmp/all.cpp";; esac
	if $c $W -O2 -Iinclude -c "$src" -o "$tmp/all.o" 2>"$tmp/w.err"; then ok; else bad "onb.h under $c $W:"; cat "$tmp/w.err"; fi
	if $c $W -O2 -ffast-math -DONB_ALLOW_FAST_MATH -Iinclude -c "$src" -o "$tmp/all.o" 2>"$tmp/w.err"; then ok; else bad "onb.h under $c -ffast-math -DONB_ALLOW_FAST_MATH:"; cat "$tmp/w.err"; fi
done

# 2. the studied bits from out-of-line calls
B=tests/client/bits.c
build() { # name, flags...
	out=$1; shift
	cc -Iinclude "$@" $SAN "$B" libonb.a -lm -o "$tmp/$out" 2>"$tmp/$out.err" || { bad "build $out: $*"; cat "$tmp/$out.err"; return 1; }
}
build gen -std=c99 $LIBFP -DMODE_GEN && "$tmp/gen" > "$tmp/in.txt"
build ref -std=c99 $LIBFP -DMODE_REF && "$tmp/ref" < "$tmp/in.txt" > "$tmp/ref.txt"
lines=$(wc -l < "$tmp/ref.txt")
[ "$lines" -gt 1000 ] && ok || bad "reference output has only $lines lines"
ARCH=""; case "$(uname -m)" in x86_64) ARCH="-march=native";; esac
for mode in OUTLINE ARRAY; do
	for fl in "-std=gnu11 -O3 -ffast-math -DONB_ALLOW_FAST_MATH" "-std=gnu11 -O3 -ffp-contract=fast"; do
		name=$(echo "$mode$fl" | tr -c 'a-zA-Z0-9\n' _)
		if build "$name" $fl $ARCH -DMODE_$mode && "$tmp/$name" < "$tmp/in.txt" > "$tmp/$name.txt" &&
		   cmp -s "$tmp/ref.txt" "$tmp/$name.txt"; then ok
		else bad "$mode client built with $fl $ARCH: not the studied bits"; diff "$tmp/ref.txt" "$tmp/$name.txt" | head -4; fi
	done
done

# 3. contraction: what the pragmas keep, and what the bits are without them
fma=0
case "$(uname -m)" in x86_64) grep -qw fma /proc/cpuinfo 2>/dev/null && fma=1;; esac
if [ "$fma" -eq 1 ]; then
	build inl_follow -std=gnu11 -O3 -ffp-contract=fast -mfma -DONB_INLINE_FOLLOWS_CLIENT_FP -DMODE_REF &&
	"$tmp/inl_follow" < "$tmp/in.txt" > "$tmp/inl_follow.txt"
	nd=$(diff "$tmp/ref.txt" "$tmp/inl_follow.txt" | grep -c '^>')
	echo "inline, -ffp-contract=fast -mfma, no pragmas: $nd of $lines results differ from the studied bits; per method:"
	paste -d '\n' "$tmp/ref.txt" "$tmp/inl_follow.txt" | awk '
		NR % 2 == 1 { a = $0; next }
		{ split(a, x, " "); k = x[1] " " x[2]; if (!(k in t)) o[++n] = k; t[k]++; if (a != $0) d[k]++ }
		END { for (i = 1; i <= n; i++) printf "  %-32s %4d of %d\n", o[i], d[o[i]], t[o[i]] }'

	[ "$nd" -gt 0 ] && ok || bad "contraction changed nothing: the bit comparison above could not fail"
	build inl_gcc -std=gnu11 -O3 -ffp-contract=fast -mfma -DMODE_REF &&
	"$tmp/inl_gcc" < "$tmp/in.txt" > "$tmp/inl_gcc.txt"
	if cc --version | grep -q 'Free Software Foundation' && ! cmp -s "$tmp/ref.txt" "$tmp/inl_gcc.txt"; then
		bad "GCC: inline functions under -ffp-contract=fast lost the studied bits despite the pragma"
	else ok; fi
else
	echo "skip: no FMA on this CPU, contraction cannot change a bit here"
fi

finish
