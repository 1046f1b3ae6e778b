#!/bin/sh
# onbstudy scene on glTF 2.0: every .gltf and .glb file of
# Debian's assimp-testmodels, with and without --world, in float; each must
# give a recommendation (exit 0) or one clear line on stderr (exit 2),
# never anything else (a crash, a hang, a partial result).  Files known to
# be invalid must be refused with the named reason, files known to be
# valid must be read; BoxBadNormals' zero normals and BoxWithInfinites'
# non-finite positions must be reported.  Then the small files of
# tests/data/gltf (always present).  The assimp part skips (passing) when
# the package is absent.
. "$(dirname "$0")/lib.sh"
export XDG_CACHE_HOME="$tmp/cache"  # speeds: the committed reference run
methods=$(./onbstudy list --format csv | tail -n +2 | cut -d, -f1)
M=/usr/share/assimp/models

run() { # file, extra option (or ""); sets rc, leaves $tmp/o and $tmp/e
	# shellcheck disable=SC2086
	timeout 120 ./onbstudy scene "$1" $2 --out "$tmp/r" > "$tmp/o" 2> "$tmp/e"
	rc=$?
}

nvalid=0; ninvalid=0
if [ -d "$M/glTF2" ]; then
	files=$(find "$M" \( -name '*.gltf' -o -name '*.glb' \) | sort)
	for f in $files; do
		for w in "" --world; do
			run "$f" "$w"
			short=${f#"$M"/}
			if [ $rc -eq 0 ]; then
				rec=$(sed -n 's/^recommended for .*: \([a-z_0-9]*\)$/\1/p' "$tmp/o")
				if [ "$rec" = none ] || echo "$methods" | grep -qx "$rec"; then ok; else bad "$short $w: no recommendation line"; fi
				[ -f "$tmp/r/scene.csv" ] && ok || bad "$short $w: no scene.csv"
				[ -z "$w" ] && nvalid=$((nvalid + 1))
				[ -z "$w" ] && echo "$short: $(grep '^counts' "$tmp/o" | cut -c1-60)...; recommended $rec"
			elif [ $rc -eq 2 ] && [ "$(wc -l < "$tmp/e")" -eq 1 ] && grep -q "^onbstudy: scene: $f: " "$tmp/e"; then
				ok
				[ -z "$w" ] && ninvalid=$((ninvalid + 1))
				[ -z "$w" ] && echo "$short: refused: $(sed "s|^onbstudy: scene: $f: ||" "$tmp/e")"
			else
				bad "$short $w: exit $rc: $(head -3 "$tmp/e")"
			fi
		done
	done
	echo "assimp-testmodels: $nvalid glTF files read, $ninvalid refused"
	refused() { # file, expected words
		[ -f "$M/$1" ] || return
		run "$M/$1" ""
		[ $rc -eq 2 ] && grep -q -- "$2" "$tmp/e" && ok || bad "$1 not refused with '$2': exit $rc $(cat "$tmp/e")"
	}
	refused glTF2/IndexOutOfRange/IndexOutOfRange.gltf "out of range"
	refused glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf "out of range"
	refused glTF2/RecursiveNodes/RecursiveNodes.gltf "cycle"
	refused glTF2/MissingBin/BoxTextured.gltf "cannot open"
	refused glTF2/SchemaFailures/sceneWrongType.gltf "'scene' must be an index"
	refused glTF2/draco/2CylinderEngine.gltf "KHR_draco_mesh_compression"
	refused glTF/TwoBoxes/TwoBoxes.gltf "only glTF 2.0"
	refused glTF/BoxTextured-glTF-Binary/BoxTextured.glb "container version 1"
	read_ok() { # file, expected line (grep pattern)
		[ -f "$M/$1" ] || return
		for w in "" --world; do
			run "$M/$1" "$w"
			[ $rc -eq 0 ] && grep -q -- "$2" "$tmp/o" && ok || bad "$1 $w: exit $rc, no '$2': $(head -2 "$tmp/e")"
		done
	}
	read_ok glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb "^normals: [0-9]* stored (float"
	read_ok glTF2/BoxBadNormals-glTF-Binary/BoxBadNormals.glb "degenerate 4 (zero 4"
	read_ok glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb "POSITION values are not finite"
	read_ok glTF2/ClearCoat-glTF/ClearCoatTest.gltf "^format: glTF 2.0 JSON"
	read_ok glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf "^recommended for"
	# --world reports object space too
	run "$M/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb" --world
	grep -q "^format: .*world space" "$tmp/o" && grep -q "^object space" "$tmp/o" && ok || bad "--world does not report both spaces"
else
	echo "SKIP: assimp-testmodels is not installed ($M/glTF2 missing)"
fi

# the small files of tests/data/gltf
D=tests/data/gltf
run $D/quantized.gltf ""
[ $rc -eq 0 ] && grep -q "normalized integers (KHR_mesh_quantization)" "$tmp/o" && grep -q "non-unit 4" "$tmp/o" && ok || bad "quantized.gltf: $(cat "$tmp/e")"
run $D/strided.gltf --world
[ $rc -eq 0 ] && grep -q "counts in float: total 8" "$tmp/o" && ok || bad "strided.gltf --world: $(cat "$tmp/e")"
run $D/sparse.gltf ""
[ $rc -eq 0 ] && grep -q "4 of them computed" "$tmp/o" && grep -q "degenerate 2 (zero 2" "$tmp/o" && ok || bad "sparse.gltf: $(cat "$tmp/e")"
run $D/rotated.glb "--world --precision double"
[ $rc -eq 0 ] && grep -q "binary (.glb)" "$tmp/o" && ok || bad "rotated.glb: $(cat "$tmp/e")"
cp $D/external.gltf "$tmp/moved.gltf"
run "$tmp/moved.gltf" ""
[ $rc -eq 2 ] && grep -q "external buf.bin" "$tmp/e" && ok || bad "external buffer missing: exit $rc $(cat "$tmp/e")"
# detection by content: a PLY named .obj is read as PLY; STL and ELF are named
printf 'ply\nformat ascii 1.0\nelement vertex 1\nproperty float nx\nproperty float ny\nproperty float nz\nend_header\n0 0 1\n' > "$tmp/p.obj"
run "$tmp/p.obj" ""
[ $rc -eq 0 ] && grep -q "^format: PLY" "$tmp/o" && grep -q "content is PLY" "$tmp/o" && ok || bad "PLY named .obj: $(cat "$tmp/e")"
printf 'solid x\n facet normal 0 0 1\n' > "$tmp/s.obj"
run "$tmp/s.obj" ""
[ $rc -eq 2 ] && grep -q "STL (ascii), which is not read here; supported: OBJ, PLY, glTF 2.0" "$tmp/e" && ok || bad "STL: $(cat "$tmp/e")"
run ./onbstudy ""
[ $rc -eq 2 ] && grep -q "ELF" "$tmp/e" && ok || bad "ELF: $(cat "$tmp/e")"
finish
