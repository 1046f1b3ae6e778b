#!/bin/sh
# The README's library quick start on a minimal root, as written: a fresh
# Debian 12 minbase root (debootstrap) with only gcc, make and libc6-dev
# installed (--no-install-recommends), a copy of this checkout's HEAD, and
# the commands of the README's "Quick start: the library alone" code
# block run one by one (they compile and run examples/render.c, which
# includes <libonb/onb.h>).
# Before that, `make lib` without libc6-dev, to show why the README names it.
#   sh scripts/minimal-root.sh [OUT]      (default results/minimal-root.txt)
# Needs root, debootstrap and the network to deb.debian.org; about 5 min and
# 400 MB in a temporary directory.  Not part of `make test` (network, root):
# its record is committed; tests/lib_minimal.sh checks the same package list
# on every `make test` from the headers the build includes, and
# tests/lib_quickstart.sh runs the block itself.
set -eu
cd "$(dirname "$0")/.."
out=${1:-results/minimal-root.txt}
[ "$(id -u)" -eq 0 ] || { echo "minimal-root: needs root (debootstrap, chroot)" >&2; exit 1; }
command -v debootstrap >/dev/null 2>&1 || { echo "minimal-root: debootstrap not installed (apt-get install debootstrap)" >&2; exit 1; }
root=$(mktemp -d /tmp/onb-minroot.XXXXXX)
trap 'rm -rf "$root"' EXIT
log="$root.log"
debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian > "$log" 2>&1 ||
	{ tail -5 "$log" >&2; echo "minimal-root: debootstrap failed" >&2; exit 1; }
cp /etc/resolv.conf "$root/etc/resolv.conf"
inroot() { chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/bin:/bin:/usr/sbin:/sbin sh -c "$1"; }
inroot 'apt-get update -q' >> "$log" 2>&1
mkdir -p "$root/root/onb"
git archive HEAD | tar -x -C "$root/root/onb"
# the README's block, comments dropped
sed -n '/^## Quick start: the library alone/,/^## /p' README.md | sed -n '/^```sh/,/^```/p' | sed '1d;$d' | sed 's/ *#.*//' > "$root/root/onb/quickstart.sh"
{
	echo "# scripts/minimal-root.sh at $(git rev-parse --short=12 HEAD), $(date -u +%Y-%m-%dT%H:%MZ): debootstrap --variant=minbase bookworm"
	inroot 'DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends gcc make' >> "$log" 2>&1
	echo "## gcc and make only ($(inroot 'dpkg -l | grep -c ^ii') packages installed): make lib"
	if inroot 'cd /root/onb && make lib' > "$root/l1.log" 2>&1; then echo "built (libc6-dev was not needed?)"
	else echo "failed, as expected: $(grep -m1 -o '[a-z./]*: No such file or directory' "$root/l1.log")"; fi
	inroot 'cd /root/onb && make clean' > /dev/null 2>&1
	inroot 'DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends libc6-dev' >> "$log" 2>&1
	echo "## gcc, make and libc6-dev ($(inroot 'dpkg -l | grep -c ^ii') packages installed; pkg-config: $(inroot 'command -v pkg-config || echo absent'), man: $(inroot 'command -v man || echo absent'))"
	echo "## the README's quick start, from the checkout's top:"
	sed 's/^/\$ /' "$root/root/onb/quickstart.sh"
	if inroot 'cd /root/onb && set -e && . ./quickstart.sh' > "$root/q.log" 2>&1; then
		grep -v '^\(printf\|mv\|install\|cc\|ar\|rm\|mkdir\) ' "$root/q.log" | grep -v '^make' || true
		echo "## installed under \$HOME/.local ($(inroot 'find /root/.local -type f | wc -l') files):"
		inroot 'cd /root/.local && find . -type f | sort'
		echo "## result: the quick start works with gcc, make and libc6-dev alone"
	else
		tail -5 "$root/q.log"
		echo "## result: FAILED"
		exit 1
	fi
} > "$out.tmp"
mv "$out.tmp" "$out"
rm -f "$log"
cat "$out"
