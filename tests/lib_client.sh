#!/bin/sh
# libonb in other people's builds, whose compilers and flags are not ours:
#  1. onb.h compiles clean under -Wall -Wextra -Wpedantic -Wshadow
#     -Wconversion -Wdouble-promotion -Wfloat-equal -Werror in C99, C11 and
#     C++17 (-Wold-style-cast too), with gcc/g++ and clang/clang++, every
#     inline function instantiated; and under -ffast-math with no define;
#  2. the studied bits (the inline functions built with the library's
#     flags) from: the method names in a -ffast-math client (no define: they
#     call libonb.a), the out-of-line calls through onb_vec3[f]
#     (onb_NAME_outline[f]) and through the client's own float[3]/double[3]
#     (onb_NAME_array[f], onb_basis_array[f]) under -ffast-math and
#     -ffp-contract=fast; ONB_INLINE_FOLLOWS_CLIENT_FP under -ffast-math
#     changes bits, which shows these comparisons can fail;
#  3. contraction changes bits when the kernels follow the client
#     (ONB_INLINE_FOLLOWS_CLIENT_FP); by the object's symbols, the six
#     client builds (inline and out-of-line) and the defines inline exactly where the
#     flags cannot change the bits, call libonb.a elsewhere, and give the
#     studied bits in every case; ONB_INLINE_ACTIVE agrees with the
#     symbols, and ONB_WARN_OUTLINE gives its message exactly where the
#     names call libonb.a (none without the define);
#  4. the array API takes &v.x of a struct { float x, y, z; } without a
#     warning (gcc and clang, -O0 and -O2), where n[3] parameters warn;
#  5. a static client of one array function links only that function.
. "$(dirname "$0")/lib.sh"
W="-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion -Wfloat-equal -Werror"
LIBFP="-O2 -ffp-contract=off -fno-math-errno -fno-trapping-math"

# 1. every inline function, under the strict warnings
cat > "$tmp/all.c" <<'C'
#include "libonb/onb.h"
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
	ww="$W"; case "$1" in *++) ww="$W -Wold-style-cast";; esac
	if $c $ww -O2 -Iinclude -c "$src" -o "$tmp/all.o" 2>"$tmp/w.err"; then ok; else bad "onb.h under $c $ww:"; cat "$tmp/w.err"; fi
	if $c $ww -O2 -ffast-math -Iinclude -c "$src" -o "$tmp/all.o" 2>"$tmp/w.err"; then ok; else bad "onb.h under $c -ffast-math:"; cat "$tmp/w.err"; fi
	if $c $ww -O2 -ffast-math -DONB_INLINE_FOLLOWS_CLIENT_FP -Iinclude -c "$src" -o "$tmp/all.o" 2>"$tmp/w.err"; then ok; else bad "onb.h under $c -ffast-math -DONB_INLINE_FOLLOWS_CLIENT_FP:"; cat "$tmp/w.err"; fi
done

# 2. the studied bits from out-of-line calls
B=tests/client/bits.c
build() { # name, flags... (compiler: $BCC, default cc)
	out=$1; shift
	${BCC:-cc} -Iinclude "$@" $SAN "$B" libonb.a -lm -o "$tmp/$out" 2>"$tmp/$out.err" || { bad "build $out: ${BCC:-cc} $*"; cat "$tmp/$out.err"; return 1; }
}
build gen -std=c99 $LIBFP -DMODE_GEN && "$tmp/gen" > "$tmp/in.txt"
build ref -std=c99 $LIBFP -DMODE_REF && "$tmp/ref" < "$tmp/in.txt" > "$tmp/ref.txt"
lines=$(wc -l < "$tmp/ref.txt")
[ "$lines" -gt 1000 ] && ok || bad "reference output has only $lines lines"
ARCH=""; case "$(uname -m)" in x86_64) ARCH="-march=native";; esac
for mode in OUTLINE ARRAY; do
	for fl in "-std=gnu11 -O3 -ffast-math" "-std=gnu11 -O3 -ffp-contract=fast"; do
		name=$(echo "$mode$fl" | tr -c 'a-zA-Z0-9\n' _)
		if build "$name" $fl $ARCH -DMODE_$mode && "$tmp/$name" < "$tmp/in.txt" > "$tmp/$name.txt" &&
		   cmp -s "$tmp/ref.txt" "$tmp/$name.txt"; then ok
		else bad "$mode client built with $fl $ARCH: not the studied bits"; diff "$tmp/ref.txt" "$tmp/$name.txt" | head -4; fi
	done
done

# 3a. contraction: the bits when the kernels follow -ffp-contract=fast -mfma
# (ONB_INLINE_FOLLOWS_CLIENT_FP), and the studied bits without the define
fma=0
case "$(uname -m)" in x86_64) grep -qw fma /proc/cpuinfo 2>/dev/null && fma=1;; esac
if [ "$fma" -eq 1 ]; then
	build inl_follow -std=gnu11 -O3 -ffp-contract=fast -mfma -DONB_INLINE_FOLLOWS_CLIENT_FP -DMODE_REF &&
	"$tmp/inl_follow" < "$tmp/in.txt" > "$tmp/inl_follow.txt"
	nd=$(diff "$tmp/ref.txt" "$tmp/inl_follow.txt" | grep -c '^>')
	echo "inline, -ffp-contract=fast -mfma, ONB_INLINE_FOLLOWS_CLIENT_FP: $nd of $lines results differ from the studied bits; per method:"
	paste -d '\n' "$tmp/ref.txt" "$tmp/inl_follow.txt" | awk '
		NR % 2 == 1 { a = $0; next }
		{ split(a, x, " "); k = x[1] " " x[2]; if (!(k in t)) o[++n] = k; t[k]++; if (a != $0) d[k]++ }
		END { for (i = 1; i <= n; i++) printf "  %-32s %4d of %d\n", o[i], d[o[i]], t[o[i]] }'

	[ "$nd" -gt 0 ] && ok || bad "contraction changed nothing: the bit comparison above could not fail"
	build inl_gcc -std=gnu11 -O3 -ffp-contract=fast -mfma -DMODE_REF &&
	"$tmp/inl_gcc" < "$tmp/in.txt" > "$tmp/inl_gcc.txt"
	if cc --version | grep -q 'Free Software Foundation' && ! cmp -s "$tmp/ref.txt" "$tmp/inl_gcc.txt"; then
		bad "GCC, GNU mode, -mfma: the method names lost the studied bits (they should call libonb.a)"
	else ok; fi
else
	echo "skip: no FMA on this CPU, contraction cannot change a bit here"
fi

# 2b. the method names themselves under -ffast-math, no define: the
# studied bits (they call libonb.a); with ONB_INLINE_FOLLOWS_CLIENT_FP they
# follow -ffast-math, and some bits change
for c in gcc clang; do
	command -v $c >/dev/null 2>&1 || { echo "skip: $c not installed"; continue; }
	if BCC=$c build fm_$c -std=gnu11 -O3 -ffast-math $ARCH -DMODE_REF && "$tmp/fm_$c" < "$tmp/in.txt" > "$tmp/fm_$c.txt" &&
	   cmp -s "$tmp/ref.txt" "$tmp/fm_$c.txt"; then ok
	else bad "$c -ffast-math client, method names: not the studied bits"; fi
	if BCC=$c build ff_$c -std=gnu11 -O3 -ffast-math $ARCH -DONB_INLINE_FOLLOWS_CLIENT_FP -DMODE_REF &&
	   "$tmp/ff_$c" < "$tmp/in.txt" > "$tmp/ff_$c.txt"; then
		nd=$(diff "$tmp/ref.txt" "$tmp/ff_$c.txt" | grep -c '^>')
		echo "$c -ffast-math $ARCH -DONB_INLINE_FOLLOWS_CLIENT_FP: $nd of $lines results differ from the studied bits"
		[ "$nd" -gt 0 ] && ok || bad "$c: -ffast-math changed no bit of the inline kernels: the comparisons above could not fail"
	fi
done

# 3b. where the method names inline (object symbols), and their bits.
# Expected: "call" (a reference to onb_NAME_outline) under -ffast-math,
# under GCC with an FMA target in GNU mode, and with ONB_FORCE_OUTLINE;
# "inline" (no onb_ symbol at all) everywhere else.
cat > "$tmp/inl.c" <<'C'
#include "libonb/onb.h"
void f(const onb_vec3f *n, onb_vec3f *b1, onb_vec3f *b2) { onb_duff_branchlessf(*n, b1, b2); }
void g(const onb_vec3 *n, onb_vec3 *b1, onb_vec3 *b2) { onb_naive_rsqrt(*n, b1, b2); }
onb_vec3 h(onb_vec3 n) { return onb_frisvad_rotate(n, 1.0, 2.0, 3.0); }
C
gfma=call; gcc -O3 $ARCH -dM -E -x c /dev/null 2>/dev/null | grep -q __FP_FAST_FMA || gfma=inline
g2=call; gcc -O2 -dM -E -x c /dev/null 2>/dev/null | grep -q __FP_FAST_FMA || g2=inline
while IFS='|' read -r c flags want; do
	command -v $c >/dev/null 2>&1 || { echo "skip: $c not installed"; continue; }
	case "$want" in GFMA) want=$gfma;; G2) want=$g2;; esac
	$c $flags -Wall -Wextra -Iinclude -c "$tmp/inl.c" -o "$tmp/inl.o" || { bad "$c $flags: inl.c"; continue; }
	syms=$(nm "$tmp/inl.o" | awk '$NF ~ /^onb_/ { print $(NF - 1), $NF }' | tr '\n' ' ')
	got=inline
	case "$syms" in *"U onb_duff_branchless_outlinef"*"U onb_frisvad_rotate_outline"*"U onb_naive_rsqrt_outline"*) got=call;; ?*) got="other: $syms";; esac
	[ "$got" = "$want" ] && ok || bad "$c $flags: method names $got, expected $want"
	# "did it inline?": ONB_INLINE_ACTIVE says what the symbols say, and
	# ONB_WARN_OUTLINE speaks exactly when the names call libonb.a
	w=1; [ "$got" = call ] && w=0
	printf '#include "libonb/onb.h"\ntypedef char active_as_nm_says[(ONB_INLINE_ACTIVE == %d) ? 1 : -1];\n' $w > "$tmp/act.c"
	if $c $flags -Iinclude -DONB_WARN_OUTLINE -c "$tmp/act.c" -o "$tmp/act.o" 2> "$tmp/act.err"; then ok
	else bad "$c $flags: ONB_INLINE_ACTIVE is not $w (symbols: $got)"; fi
	said=inline; grep -q "libonb: the method names call libonb.a's out-of-line copies" "$tmp/act.err" && said=call
	[ "$said" = "$got" ] && ok || bad "$c $flags: ONB_WARN_OUTLINE says $said, the symbols $got: $(head -2 "$tmp/act.err")"
	$c $flags -Iinclude -c "$tmp/act.c" -o "$tmp/act.o" 2> "$tmp/act.err"
	[ ! -s "$tmp/act.err" ] && ok || bad "$c $flags: a message without ONB_WARN_OUTLINE: $(head -2 "$tmp/act.err")"
	case "$flags" in *FOLLOWS*|*c++*) echo "$c $flags: $got"; continue;; esac
	if BCC=$c build b_$c $flags -DMODE_REF && "$tmp/b_$c" < "$tmp/in.txt" > "$tmp/b_$c.txt" && cmp -s "$tmp/ref.txt" "$tmp/b_$c.txt"; then ok
	else bad "$c $flags: method names not the studied bits"; fi
	echo "$c $flags: $got, studied bits"
done <<L
gcc|-O2|G2
gcc|-O3 $ARCH|GFMA
gcc|-O2 -ffast-math|call
clang|-O2|inline
clang|-O3 $ARCH|inline
clang|-O2 -ffast-math|call
gcc|-std=c11 -O3 $ARCH|inline
gcc|-O3 $ARCH -ffp-contract=off -DONB_FP_CONTRACT_OFF|inline
gcc|-O3 $ARCH -DONB_FORCE_OUTLINE|call
clang|-O2 -DONB_FORCE_OUTLINE|call
g++|-x c++ -std=c++17 -O2|G2
gcc|-O2 -ffast-math -DONB_INLINE_FOLLOWS_CLIENT_FP|inline
L

# 4. &v.x of a renderer's struct, at -O0 and -O2: no warning
cat > "$tmp/st.c" <<'C'
#include "libonb/onb.h"
typedef struct { float x, y, z; } vec3;
typedef struct { double x, y, z; } dvec3;
void frame(const vec3 *n, vec3 *t, vec3 *b) { onb_duff_branchless_arrayf(&n->x, &t->x, &b->x); }
float frame2(vec3 n) { vec3 t, b; onb_pbrt_v3_arrayf(&n.x, &t.x, &b.x); return t.x + b.y; }
double frame3(dvec3 n) { dvec3 t, b; onb_basis_array(onb_find("duff"), &n.x, &t.x, &b.x); return t.x + b.y; }
C
sed 's|#include "libonb/onb.h"|void onb_duff_branchless_arrayf(const float n[3], float b1[3], float b2[3]);\nvoid onb_pbrt_v3_arrayf(const float n[3], float b1[3], float b2[3]);|; /frame3/d' "$tmp/st.c" > "$tmp/st3.c"
for c in gcc clang; do
	command -v $c >/dev/null 2>&1 || continue
	for o in -O0 -O2; do
		$c -std=c99 $o -Wall -Wextra -Iinclude -c "$tmp/st.c" -o "$tmp/st.o" 2>"$tmp/st.err"
		[ ! -s "$tmp/st.err" ] && ok || { bad "$c $o: &v.x warns"; head -5 "$tmp/st.err"; }
	done
done
# the control: GCC warns about the same calls through n[3] parameters
gcc -std=c99 -O2 -Wall -Wextra -c "$tmp/st3.c" -o "$tmp/st3.o" 2>"$tmp/st3.err"
nw=$(grep -c 'warning:' "$tmp/st3.err")
echo "control: n[3] parameters, gcc -O2: $nw warnings for the same calls"
[ "$nw" -gt 0 ] && ok || bad "control: n[3] parameters gave no warning, the check above could not fail"

# 5. a static client of one function pulls only that function
printf '#include "libonb/onb.h"\nint main(void) { float n[3] = { 0, 0, 1 }, t[3], b[3]; onb_duff_branchless_arrayf(n, t, b); return t[0] != 1.0f; }\n' > "$tmp/one.c"
if cc -std=c99 -O2 $SAN -Iinclude "$tmp/one.c" libonb.a -lm -o "$tmp/one" && "$tmp/one"; then
	pulled=$(nm "$tmp/one" | awk '$NF ~ /^onb_/ { print $NF }' | sort -u | tr '\n' ' ')
	[ "$pulled" = "onb_duff_branchless_arrayf " ] && ok || bad "one-function client pulled: $pulled"
	echo "one-function client: $pulled($(size "$tmp/one" | awk 'NR == 2 { print $1 + $2 + $3 }') bytes text+data+bss)"
else bad "one-function client"; fi

finish
