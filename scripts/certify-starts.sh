#!/bin/sh
# certify-starts.sh - the inputs for `onbstudy certify --starts`: every found
# input of the given certify.csv files and every input an outside search
# (tests/found_walk's output lines "... at (x, y, z)") reached, one row per
# distinct (method, precision, input); frisvad_rotate's rows keep their
# local direction (found_lx,found_ly,found_lz) as lx,ly,lz.
#
#   sh scripts/certify-starts.sh OUT.csv FILE...
#
# FILEs are certify.csv files (found_nx,found_ny,found_nz columns), earlier
# starts files (nx,ny,nz) or found_walk outputs.  An input is a real input
# of the domain that some search evaluated on the real kernel: a run that
# starts from it can only find as much or more.  Exit 2 on bad usage or an
# unreadable file; OUT is written whole or not at all.
set -eu
[ $# -ge 2 ] || { echo "usage: certify-starts.sh OUT.csv FILE..." >&2; exit 2; }
out=$1; shift
for f in "$@"; do
	[ -r "$f" ] || { echo "certify-starts.sh: $f: cannot read" >&2; exit 2; }
done
tmp=$out.tmp.$$
trap 'rm -f "$tmp"' EXIT
{
	echo "# onbstudy certify --starts: the found inputs of $(for f in "$@"; do printf '%s ' "$f"; done)"
	echo "# (certify.csv found_n*, starts nx,ny,nz, found_walk 'at (x, y, z)'), made by scripts/certify-starts.sh"
	echo "method,precision,nx,ny,nz,lx,ly,lz"
	awk '
	FNR == 1 { hdr = 0 }
	/^#/ { next }
	/^method,/ {   # a CSV: where its columns are
		n = split($0, h, ","); cx = cy = cz = lx = ly = lz = 0
		for (i = 1; i <= n; i++) {
			if (h[i] == "found_nx" || h[i] == "nx") cx = i
			if (h[i] == "found_ny" || h[i] == "ny") cy = i
			if (h[i] == "found_nz" || h[i] == "nz") cz = i
			if (h[i] == "found_lx" || h[i] == "lx") lx = i
			if (h[i] == "found_ly" || h[i] == "ly") ly = i
			if (h[i] == "found_lz" || h[i] == "lz") lz = i
		}
		hdr = cx && cy && cz
		next
	}
	hdr {
		split($0, v, ",")
		if (v[cx] != "" && v[cy] != "" && v[cz] != "")
			put(v[1], v[2], v[cx], v[cy], v[cz], lx ? v[lx] "," v[ly] "," v[lz] : ",,")
		next
	}
	/ at \(/ {   # found_walk: "METHOD PREC n.z [...] ...: ... at (x, y, z)"
		s = $0; sub(/.* at \(/, "", s); sub(/\).*/, "", s); gsub(/ /, "", s)
		if (split(s, c, ",") == 3 && ($2 == "float" || $2 == "double"))
			put($1, $2, c[1], c[2], c[3], ",,")
	}
	function put(m, p, x, y, z, l,   k) {
		k = m "," p "," x "," y "," z "," l
		if (!(k in seen)) { seen[k] = 1; print k }
	}' "$@"
} > "$tmp"
mv "$tmp" "$out"
trap - EXIT
echo "certify-starts.sh: $(grep -vc '^#\|^method,' "$out") inputs in $out" >&2
