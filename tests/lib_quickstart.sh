#!/bin/sh
# The README's library quick start, as written: the lines of its code block
# ("Quick start: the library alone") run one by one from the checkout's top
# with a temporary $HOME, so `make install PREFIX=$HOME/.local` installs
# there and the cc line compiles examples/render.c against the installed
# header and library; the last line runs the program, which checks its
# own bases (exit 1 on a direction that is not unit or leaves the
# hemisphere).  The one-line pkg-config form of the cc line that
# docs/library.md gives is run too when pkg-config is installed.  A file the block names that does
# not exist, or a command that fails, fails this test.
# (Under SANITIZE libonb.a carries the sanitizers: a cc on PATH adds $SAN.)
. "$(dirname "$0")/lib.sh"
sed -n '/^## Quick start: the library alone/,/^## /p' README.md | sed -n '/^```sh/,/^```/p' | sed '1d;$d' |
	sed 's/ *#.*//' > "$tmp/quickstart.sh"
n=$(grep -c . "$tmp/quickstart.sh")
[ "$n" -ge 3 ] && grep -q '^cc .*examples/render\.c' "$tmp/quickstart.sh" && ok ||
	bad "the README's library quick start: $n commands, no cc line compiling examples/render.c"
mkdir -p "$tmp/home" "$tmp/bin" "$tmp/w"
had_aout=0; [ -e "$root/a.out" ] && had_aout=1
real_cc=$(command -v cc)
printf '#!/bin/sh\nexec %s %s "$@"\n' "$real_cc" "$SAN" > "$tmp/bin/cc"
chmod +x "$tmp/bin/cc"
# from the top, as the README reads; a.out lands there, so it is removed after
run() { (cd "$root" && env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL HOME="$tmp/home" PATH="$tmp/bin:$PATH" sh -c "$1") > "$tmp/out" 2>&1; }
while IFS= read -r line; do
	[ -n "$line" ] || continue
	if run "$line"; then ok; else bad "README quick start: '$line' failed: $(tail -3 "$tmp/out")"; fi
	case "$line" in ./a.out*) grep -q 'every direction unit and in the hemisphere' "$tmp/out" && ok ||
		bad "examples/render.c printed: $(tail -2 "$tmp/out")";; esac
done < "$tmp/quickstart.sh"
[ "$(find "$tmp/home/.local" -type f | wc -l)" -eq 5 ] && ok ||
	bad "make install put $(find "$tmp/home/.local" -type f | wc -l) files under \$HOME/.local, the README says 5"
[ "$had_aout" -eq 1 ] || rm -f "$root/a.out"
if command -v pkg-config >/dev/null 2>&1; then
	pc=$(tr '\n' ' ' < docs/library.md | grep -o '`cc -O2 examples/render\.c \$(PKG_CONFIG_PATH=[^`]*`' | tr -d '`')
	[ -n "$pc" ] && run "$pc -o $tmp/w/render-pc && $tmp/w/render-pc" && ok ||
		bad "docs/library.md's pkg-config line '$pc' failed: $(tail -3 "$tmp/out")"
fi
finish lib_quickstart
