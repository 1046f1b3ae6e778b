#!/bin/sh
# doc_links.sh - every relative link in README.md, docs/*.md and
# results/*/README.md names a file that exists, and every #anchor a heading
# of its page (GitHub's slugs: lower case, punctuation dropped, spaces to
# '-').  Links inside ``` blocks are not links.  PENDING names the pages
# that other branches being written at the same time write: a link to one of them is reported
# as pending while the page does not exist, checked once it does.
. "$(dirname "$0")/lib.sh"
PENDING="docs/library.md docs/charts.md docs/certify.md"
slugs() { # FILE: the anchors of its headings, one a line
	awk '/^```/ { code = !code; next } !code && /^#+ / { sub(/^#+ +/, ""); print }' "$1" |
		tr 'A-Z' 'a-z' | sed -e 's/[^a-z0-9 _-]//g' -e 's/ /-/g'
}
links() { # FILE: its link targets, one a line
	awk '/^```/ { code = !code; next } !code {
		while (match($0, /\]\([^) ]+\)/)) { print substr($0, RSTART + 2, RLENGTH - 3); $0 = substr($0, RSTART + RLENGTH) } }' "$1"
}
pending=""
for f in README.md docs/*.md results/*/README.md; do
	[ -f "$f" ] || continue
	dir=$(dirname "$f")
	for t in $(links "$f"); do
		case $t in http:*|https:*|mailto:*) continue ;; esac
		path=${t%%#*}; frag=""
		case $t in *#*) frag=${t#*#} ;; esac
		if [ -n "$path" ]; then target=$(realpath -m --relative-to=. "$dir/$path"); else target=$f; fi
		if [ ! -e "$target" ]; then
			case " $PENDING " in *" $target "*) pending="$pending $target"; continue ;; esac
			bad "$f: link to $t: no $target"; continue
		fi
		if [ -n "$frag" ]; then
			case $target in *.md) ;; *) continue ;; esac
			slugs "$target" | grep -qxF -- "$frag" && ok || bad "$f: link to $t: no heading '#$frag' in $target"
		else
			ok
		fi
	done
done
[ -n "$pending" ] && echo "pending (written on other branches):$(echo "$pending" | tr ' ' '\n' | sort -u | tr '\n' ' ')"
finish doc_links
