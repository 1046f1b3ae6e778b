#!/bin/sh
# The scene recommendation does not change between identical runs (issue
# 12): ten runs of `onbstudy scene` on each file, with a CPU-burning
# process beside them, must name one method per file and variant.  Once
# with the committed reference run's speeds (no cache), once with a
# per-machine cache measured here (--refresh-speed, 3 quick repetitions:
# the figures are poor, which does not matter: they are measured once and
# then only read).  Files: box.obj, cube_usemtl.obj, Wuson.ply from
# assimp-testmodels and bunny.obj from glmark2-data when present, and a
# sphere written here (always).
. "$(dirname "$0")/lib.sh"
hog=""
cleanup() { [ -n "$hog" ] && kill "$hog" 2>/dev/null; rm -rf "$tmp"; }
trap cleanup EXIT INT TERM

# a UV sphere with stored normals (not unit in float), always available
awk 'BEGIN { pi = atan2(0, -1); n = 0
	for (i = 1; i < 12; i++) for (j = 0; j < 24; j++) {
		t = pi * i / 12; p = 2 * pi * j / 24
		printf "vn %.9f %.9f %.9f\n", sin(t) * cos(p), sin(t) * sin(p), cos(t) } }' > "$tmp/sphere.obj"
files="$tmp/sphere.obj"
for f in /usr/share/assimp/models/OBJ/box.obj /usr/share/assimp/models/OBJ/cube_usemtl.obj \
         /usr/share/assimp/models/PLY/Wuson.ply /usr/share/glmark2/models/bunny.obj; do
	if [ -f "$f" ]; then files="$files $f"; else echo "note: $f is not installed; skipped"; fi
done

sh -c 'while :; do :; done' &
hog=$!

tenruns() { # label
	for f in $files; do
		: > "$tmp/recs"
		i=0
		while [ $i -lt 10 ]; do
			./onbstudy scene "$f" --out "$tmp/r" > "$tmp/o" 2> "$tmp/e" || { bad "$1 $f: exit $?: $(cat "$tmp/e")"; break; }
			grep '^  recommended (' "$tmp/o" | sed 's/, max defect.*//' >> "$tmp/recs"
			i=$((i + 1))
		done
		n=$(sort -u "$tmp/recs" | wc -l)
		[ "$n" -eq 2 ] && [ "$(wc -l < "$tmp/recs")" -eq 20 ] && ok || bad "$1 $(basename "$f"): $n different answers in 10 runs: $(sort "$tmp/recs" | uniq -c | tr '\n' ';')"
		echo "$1 $(basename "$f"): $(sort -u "$tmp/recs" | sed 's/^  recommended //' | tr '\n' ' ')"
	done
}

export XDG_CACHE_HOME="$tmp/cache"
tenruns reference
grep -q "^speed (float): the committed reference run" "$tmp/o" && ok || bad "the speed source is not named: $(grep '^speed' "$tmp/o")"
./onbstudy scene --refresh-speed --repeats 3 > "$tmp/refresh" 2>&1 && ok || bad "--refresh-speed: $(cat "$tmp/refresh")"
ls "$tmp/cache/onbstudy/"speed-*.csv > /dev/null 2>&1 && ok || bad "no cache file written"
tenruns cache
grep -q "^speed (float): this machine's cache $tmp/cache/onbstudy/speed-" "$tmp/o" && ok || bad "the cache is not named: $(grep '^speed' "$tmp/o")"
grep -q "margin [-+][0-9.]*% in median speed" "$tmp/o" && ok || bad "no margin to the runner-up"
finish
