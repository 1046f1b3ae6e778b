#!/bin/sh
# onbstudy scene on real models from Debian's assimp-testmodels (BSD):
# every OBJ and PLY there that stores normals, meshes whose normals are
# computed from the faces, and the broken ones, which must be refused with
# exit 2 and one line.  Skips (passing) when the package is absent.
. "$(dirname "$0")/lib.sh"
M=/usr/share/assimp/models
if [ ! -d "$M/OBJ" ] || [ ! -d "$M/PLY" ]; then
	echo "SKIP: assimp-testmodels is not installed ($M missing; scripts/install-deps.sh --test installs it)"
	finish
fi
export XDG_CACHE_HOME="$tmp/cache"  # speeds: the committed reference run
methods=$(./onbstudy list --format csv | tail -n +2 | cut -d, -f1)

check_model() { # file, "stored" or "computed"
	f=$M/$1
	[ -f "$f" ] || { echo "note: $f not in this version of the package"; return; }
	./onbstudy scene "$f" --repeats 1 --out "$tmp/r" > "$tmp/o" 2> "$tmp/e"
	rc=$?
	[ $rc -eq 0 ] && ok || { bad "$1: exit $rc: $(cat "$tmp/e")"; return; }
	grep -q "^normals: [0-9]* $2" "$tmp/o" && ok || bad "$1: normals not $2: $(grep '^normals' "$tmp/o")"
	counts=$(grep '^counts in' "$tmp/o")
	[ -n "$counts" ] && ok || bad "$1: no counts"
	# the renormalized row always has a method within E
	rec=$(awk -F, '$4 == "renormalized" && $17 == "recommended" && $3 == "z" { print $5 }' "$tmp/r/scene.csv")
	echo "$methods" | grep -qx "$rec" && ok || bad "$1: renormalized recommendation '$rec' is not a method"
	line=$(grep '^recommended for' "$tmp/o")
	echo "$1: $counts; $line; renormalized: $rec"
}
for f in OBJ/WusonOBJ.obj OBJ/spider.obj OBJ/empty_mat.obj OBJ/cube_usemtl.obj PLY/Wuson.ply PLY/cube_uv.ply PLY/points.ply; do
	check_model "$f" stored
done
for f in OBJ/box.obj OBJ/regr01.obj PLY/cube_binary.ply; do
	check_model "$f" computed
done

refuse() { # file, expected word
	f=$M/$1
	[ -f "$f" ] || return
	./onbstudy scene "$f" --repeats 1 --out "$tmp/bad" > /dev/null 2> "$tmp/e"
	rc=$?
	[ $rc -eq 2 ] && [ "$(wc -l < "$tmp/e")" -eq 1 ] && grep -q -- "$2" "$tmp/e" && ok || bad "$1: exit $rc, '$(cat "$tmp/e")'"
	echo "$1: refused: $(cat "$tmp/e")"
}
refuse PLY/pond.0.ply "byte"        # 69 bytes short of its header's vertex count
refuse PLY/issue623.ply "byte"      # rows shorter than the header's properties
refuse OBJ/box_UTF16BE.obj "UTF-16"
refuse invalid/malformed.obj "line 23"
refuse invalid/empty.ply "empty"

finish
