#!/bin/sh
# examples/aorender --obj on meshes written here: a cube with one `vn` per
# face (its bottom face has n = -z exactly) and an octahedron without `vn`
# (normals computed by the scene reader).  Each is rendered with two
# methods; the PNG must be valid (signature, IHDR 480x360: 160x120 pixels
# drawn 3x; the diff 58 rows taller for its numbered colour bar and its max line).  The cube seen
# from below must show the NaN of tangent_cross_z at n = -z (and duff none).
# --diff compares with the method's own frame made exact (the same
# orientation): duff_branchless must match it, naive_nonorm (a frame that is
# not orthonormal) must not, on the octahedron.
# Bad input (missing file, malformed OBJ, no faces, bad --up) must give
# exit 2 and one line on stderr, and write no image.
. "$(dirname "$0")/lib.sh"

if ! make -s build/aorender > "$tmp/make" 2>&1; then
	echo "FAIL: make build/aorender: $(tail -5 "$tmp/make")"
	echo "0 passed, 1 failed"
	exit 1
fi
R=build/aorender

cat > "$tmp/cube.obj" <<'OBJ'
# unit cube, one normal per face, quads
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vn 0 0 -1
vn 0 0 1
vn 0 -1 0
vn 1 0 0
vn 0 1 0
vn -1 0 0
f 1//1 4//1 3//1 2//1
f 5//2 6//2 7//2 8//2
f 1//3 2//3 6//3 5//3
f 2//4 3//4 7//4 6//4
f 3//5 4//5 8//5 7//5
f 4//6 1//6 5//6 8//6
OBJ
cat > "$tmp/octa.obj" <<'OBJ'
# octahedron, no normals: the reader computes them
v 1 0 0
v -1 0 0
v 0 1 0
v 0 -1 0
v 0 0 1
v 0 0 -1
f 1 3 5
f 3 2 5
f 2 4 5
f 4 1 5
f 3 1 6
f 2 3 6
f 4 2 6
f 1 4 6
OBJ

# png FILE [ROWS]: the signature and an IHDR of 480 x ROWS (default 360;
# the rendered 160 x 120 pixels, 3x)
png() {
	sig=$(od -An -tx1 -N8 "$1" | tr -d ' \n')
	ihdr=$(od -An -tx1 -j12 -N12 "$1" | tr -d ' \n')
	[ "$sig" = "89504e470d0a1a0a" ] && [ "$ihdr" = "$(printf '49484452%08x%08x' 480 "${2:-360}")" ]
}

for mesh in cube octa; do
	for m in duff_branchless tangent_cross_z naive_nonorm; do
		out="$tmp/$mesh-$m.png"
		$R --obj "$tmp/$mesh.obj" --method $m --spp 16 --out "$out" --diff "$tmp/$mesh-$m-diff.png" > "$tmp/sum" 2> "$tmp/err"
		rc=$?
		if [ $rc -eq 0 ] && [ ! -s "$tmp/err" ]; then ok; else bad "$mesh $m: exit $rc: $(cat "$tmp/err")"; fi
		png "$out" && ok || bad "$mesh $m: not a 480x360 PNG"
		png "$tmp/$mesh-$m-diff.png" 418 && ok || bad "$mesh $m: diff is not a 480x418 PNG"
		nan=$(sed -n 's/.*NaN pixels \([0-9]*\)$/\1/p' "$tmp/sum")
		mean=$(sed -n 's/.*mean |diff| \([0-9.]*\) .*/\1/p' "$tmp/sum")
		over=$(sed -n 's/.*pixels > [0-9.]*: *\([0-9]*\) .*/\1/p' "$tmp/sum")
		[ -n "$nan" ] && [ -n "$mean" ] && [ -n "$over" ] && ok || bad "$mesh $m: no summary line: $(cat "$tmp/sum")"
		case $m in
		duff_branchless)
			awk -v x="${mean:-1}" 'BEGIN { exit !(x < 0.001) }' && ok || bad "$mesh $m: mean |diff| ${mean:-none} against its exact frame";;
		naive_nonorm) # on the octahedron's slanted normals (the cube's are axes)
			[ $mesh = cube ] || [ "${over:-0}" -ge 20 ] && ok || bad "$mesh $m: only ${over:-none} pixels differ from its exact frame";;
		esac
		if [ "$mesh" = cube ]; then
			# the bottom face, n = -z exactly, faces the camera
			if [ $m = tangent_cross_z ]; then
				[ "${nan:-0}" -gt 100 ] && ok || bad "cube tangent_cross_z: expected NaN pixels at n = -z, got ${nan:-none}"
			else
				[ "${nan:--1}" -eq 0 ] && ok || bad "cube $m: NaN pixels ${nan:-none}"
			fi
		fi
	done
done

# the same image twice (deterministic); --up, --no-renormalize and
# --precision double must run and write a PNG
$R --obj "$tmp/octa.obj" --method frisvad --spp 8 --out "$tmp/a.png" 2> "$tmp/err" && \
$R --obj "$tmp/octa.obj" --method frisvad --spp 8 --out "$tmp/b.png" 2>> "$tmp/err" && cmp -s "$tmp/a.png" "$tmp/b.png" \
	&& ok || bad "two renders of the same mesh differ: $(cat "$tmp/err")"
for opt in "--up y" "--up x" "--no-renormalize" "--precision double"; do
	# shellcheck disable=SC2086
	$R --obj "$tmp/cube.obj" $opt --method frisvad --spp 4 --out "$tmp/o.png" 2> "$tmp/err" && png "$tmp/o.png" \
		&& ok || bad "--obj with $opt: $(cat "$tmp/err")"
	rm -f "$tmp/o.png"
done

# bad input: exit 2, one line on stderr, no image
printf 'v 0 0 0\nv 1 0 0\nf 1 2 3\n' > "$tmp/badidx.obj"
printf 'v 0 0 0\nv 1 0 zero\n' > "$tmp/badnum.obj"
printf 'v 0 0 0\nvn 0 0 1\n' > "$tmp/nofaces.obj"
printf 'v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n' > "$tmp/point.obj"
expect2() { # label args...
	label=$1; shift
	rm -f "$tmp/x.png"
	$R "$@" --out "$tmp/x.png" > /dev/null 2> "$tmp/err"
	rc=$?
	n=$(wc -l < "$tmp/err")
	if [ $rc -eq 2 ] && [ "$n" -eq 1 ] && [ ! -e "$tmp/x.png" ]; then ok
	else bad "$label: exit $rc, $n lines on stderr, image $( [ -e "$tmp/x.png" ] && echo written || echo absent ): $(cat "$tmp/err")"; fi
}
expect2 "missing file" --obj "$tmp/nosuch.obj" --method duff
expect2 "bad index" --obj "$tmp/badidx.obj" --method duff
grep -q "line 3" "$tmp/err" && ok || bad "bad index: error does not name line 3: $(cat "$tmp/err")"
expect2 "bad number" --obj "$tmp/badnum.obj" --method duff
grep -q "line 2" "$tmp/err" && ok || bad "bad number: error does not name line 2: $(cat "$tmp/err")"
expect2 "no faces" --obj "$tmp/nofaces.obj" --method duff
expect2 "faces in one point" --obj "$tmp/point.obj" --method duff
expect2 "directory" --obj "$tmp" --method duff
expect2 "bad --up" --obj "$tmp/cube.obj" --up w --method duff
expect2 "unknown method" --obj "$tmp/cube.obj" --method nosuch

# every format the scene reader reads: a PLY octahedron without
# normals (a binary-free ascii file) and the glTF test file (object space)
{
	printf 'ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n'
	printf 'element face 8\nproperty list uchar int vertex_indices\nend_header\n'
	printf '1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n'
	printf '3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n'
} > "$tmp/octa.ply"
for f in "$tmp/octa.ply" tests/data/gltf/strided.gltf; do
	rm -f "$tmp/m.png"
	$R --mesh "$f" --method duff_branchless --spp 8 --out "$tmp/m.png" 2> "$tmp/err"
	[ $? -eq 0 ] && png "$tmp/m.png" && ok || bad "--mesh $f: $(cat "$tmp/err")"
done
printf 'ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\nend_header\n0 0 0 0 0 1\n' > "$tmp/points.ply"
expect2 "PLY without faces" --mesh "$tmp/points.ply" --method duff
grep -q "no geometry" "$tmp/err" && ok || bad "PLY without faces: $(cat "$tmp/err")"

# --brushed (the brushed-metal render of make render-brushed) separates the
# methods as the metrics do: duff and duff_branchless match their own frame
# made exact to rounding; the nonorm variants and float frisvad differ by
# more than 0.05 somewhere; tangent_cross_z has NaN pixels (the ceiling at
# n = -z exactly), duff none
brushed() { $R --method "$1" --precision float --brushed "$tmp/b.dat" 2> "$tmp/err"; }
for m in duff duff_branchless; do
	l=$(brushed $m) && echo "$l" | awk '{ for (i = 1; i < NF; i++) if ($i == "frame|") mx = $(i + 1) } END { exit !(mx + 0 < 1e-5) }' &&
		echo "$l" | grep -q 'NaN pixels 0$' && ok || bad "brushed $m: not its exact frame: $l $(cat "$tmp/err")"
done
for m in naive_nonorm hughes_moeller_nonorm frisvad; do
	l=$(brushed $m) && echo "$l" | awk '{ for (i = 1; i < NF; i++) if ($i == "frame|") mx = $(i + 1) } END { exit !(mx + 0 > 0.05) }' &&
		ok || bad "brushed $m: its defect does not show: $l $(cat "$tmp/err")"
done
l=$(brushed tangent_cross_z) && echo "$l" | grep -q 'NaN pixels [1-9]' && ok || bad "brushed tangent_cross_z: no NaN pixel: $l"
[ "$(awk 'NF == 4' "$tmp/b.dat" | wc -l)" -eq 19200 ] && ok || bad "brushed: not 160x120 pixels in its data file"

finish
