#!/bin/sh
# reffast-parts.sh [REPS] [float|double] - where the fast reference's time goes:
# each part of reffast_eval is run twice on the same data in a copy of
# src/reference/reffast.c (the second result is discarded, so the data and every
# decision stay the same), and the extra time per evaluation is that part's
# cost.  Parts that overlap with the rest of the work show less than their
# own cost (and a part the compiler can merge with its first run shows
# nothing: the kernel's shape dots are not listed for that reason).  Float
# (default) or double, on bench --reference's inputs (every method on 1024
# inputs of each distribution of the default sweep), one thread; each line
# is the best of REPS (default 5) alternating runs of the plain copy and
# the doubled one.  Needs `make` first (links build/libstudy.a).  Prints
# ns per evaluation; takes about two minutes.
set -eu
REPS=${1:-5}
PREC=${2:-float}
case $PREC in float) P=PREC_FLOAT ;; double) P=PREC_DOUBLE ;; *) echo "reffast-parts: precision float or double" >&2; exit 2 ;; esac
[ -f build/libstudy.a ] && [ -f libonb.a ] || { echo "reffast-parts: run make first" >&2; exit 2; }
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
CC=${CC:-cc}
F="-std=c99 -O3 -ffp-contract=off -fno-math-errno -fno-trapping-math -Iinclude -Isrc -mfma -D_POSIX_C_SOURCE=200809L"
cat > "$W/driver.c" <<'C'
#include "bench_ref.c"
int main(int argc, char **argv)
{
	static study_kernel ks[BR_MAX_KERNELS];
	static br_input in[BR_MAX_INPUTS];
	const int reps = argc > 1 ? atoi(argv[1]) : 8;
	const int nk = kernels_select(NULL, 0, ks, BR_MAX_KERNELS), m = br_inputs(PREC, 1, 1024, in);
	ref_ctx *rc = ref_new(127);
	reffast_ctx *fc = reffast_new(127);
	double check = 0.0, best = 1e30;
	unsigned long long fb = 0, ev = 0;
	int r;
	for (r = 0; r < reps; r++) {
		const double t0 = bench_now();
		double t;
		ev = br_pass(in, m, ks, nk, PREC, rc, fc, &fb, &check);
		t = bench_now() - t0;
		best = t < best ? t : best;
	}
	printf("%.1f\n", best / (double)ev * 1e9);
	return check == 0.5;
}
C
# variant NAME 'ANCHOR' 'ADDED': ADDED goes after the line ANCHOR (a whole line of reffast.c)
variant() {
	awk -v a="$2" -v b="$3" '{ print } $0 == a { print b; n++ } END { if (n != 1) exit 1 }' src/reference/reffast.c > "$W/$1.c" ||
		{ echo "reffast-parts: anchor of $1 not found in src/reference/reffast.c" >&2; exit 1; }
	printf '#define REFFAST_PAIR_DOUBLE 1\n#include "%s.c"\n' "$1" > "$W/$1_f.c"
	$CC $F -I"$W" -c "$W/$1_f.c" -o "$W/$1_f.o"
	$CC $F -I"$W" -c "$W/$1.c" -o "$W/$1_l.o"
	$CC $F -DPREC=$P -fopenmp -o "$W/$1" -Isrc "$W/driver.c" "$W/$1_f.o" "$W/$1_l.o" build/libstudy.a libonb.a \
		-Wl,-Bstatic -lmpfi -lmpfr -lgmp -Wl,-Bdynamic -lcjson -lm
}
SINK='__asm__ volatile("" ::: "memory");'
variant plain '#include "reference/reffast.h"' ''
variant formula '	xreference(k, br, loc, n, XR(e), XR(e) + 3, bad);' \
	"	{ xv q[6]; int qb = 0; xreference(k, br, loc, n, q, q + 3, &qb); __asm__ volatile(\"\" :: \"m\"(q), \"r\"(qb)); }"
variant forward '		const int f = forward_all(e, r1, r2, prec, s, undet);' \
	"		{ sample_metrics s2 = *s; double u2[2] = { 0, 0 }; int f2 = forward_all(e, r1, r2, prec, &s2, u2); __asm__ volatile(\"\" :: \"m\"(s2), \"m\"(u2), \"r\"(f2)); }"
variant floor '		const int ok = floor_fast(c, e, k, prec, s->branch, n, loc, normalize_n, inv, r1, r2, f);' \
	"		{ double f2[3]; int o2 = floor_fast(c, e, k, prec, s->branch, n, loc, normalize_n, inv, r1, r2, f2); __asm__ volatile(\"\" :: \"m\"(f2), \"r\"(o2)); }"
variant kernel '	ref_run_kernel(k, prec, n_in, loc, n, s);' \
	"	{ sample_metrics s2; double n2[3]; ref_run_kernel(k, prec, n_in, loc, n2, &s2); __asm__ volatile(\"\" :: \"m\"(s2), \"m\"(n2)); }"
variant memo_copy '		m->smp = *s;' "		$SINK m->smp = *s;"
echo "# reffast-parts: revision $(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown); load $(cut -d' ' -f1-3 /proc/loadavg); best of $REPS alternating runs, ns per $PREC evaluation"
for v in formula forward floor kernel memo_copy; do
	a=1e30; b=1e30
	i=0
	while [ $i -lt "$REPS" ]; do
		x=$("$W/plain"); y=$("$W/$v")
		a=$(echo "$a $x" | awk '{ print ($2 < $1) ? $2 : $1 }'); b=$(echo "$b $y" | awk '{ print ($2 < $1) ? $2 : $1 }')
		i=$((i + 1))
	done
	echo "$v $a $b" | awk '{ printf "%-10s plain %6.1f  doubled %6.1f  part %5.1f\n", $1, $2, $3, $3 - $2 }'
done
