# splice.sh - sourced by the scripts that write a generated block into a
# committed file between two marker lines (findings.sh, wild.sh): the
# --update and --check of that block, written once.
#   splice_marked TOOL MODE FILE NEW WHAT MATCHES DIFFERS RERUN
# NEW holds the block with its own begin and end lines (the first and last
# lines of NEW are the markers looked for in FILE).  MODE --check: exit 0
# when FILE already holds NEW ("TOOL: the WHAT in FILE match MATCHES"),
# else print the diff and "TOOL: the WHAT in FILE differ from DIFFERS
# (run: RERUN)" and exit 1.  MODE --update: FILE gets NEW.  Exit 1 when
# FILE lacks either marker.  Always exits.
splice_marked() {
	_t=$1 _mode=$2 _file=$3 _new=$4 _what=$5 _matches=$6 _differs=$7 _rerun=$8
	_b=$(sed -n '1p' "$_new"); _e=$(sed -n '$p' "$_new")
	if ! grep -qF "$_b" "$_file" || ! grep -qF "$_e" "$_file"; then
		echo "$_t: $_file has no markers for the $_what" >&2; exit 1
	fi
	awk -v B="$_b" -v E="$_e" -v NEW="$_new" '
		$0 == B { while ((getline l < NEW) > 0) print l; skip = 1; next }
		$0 == E { skip = 0; next }
		!skip { print }' "$_file" > "$_new.out"
	if [ "$_mode" = --check ]; then
		if cmp -s "$_file" "$_new.out"; then echo "$_t: the $_what in $_file match $_matches"; exit 0; fi
		diff "$_file" "$_new.out" | head -40 >&2
		echo "$_t: the $_what in $_file differ from $_differs (run: $_rerun)" >&2
		exit 1
	fi
	cp "$_new.out" "$_file"
	echo "$_t: updated $_file"
	exit 0
}
