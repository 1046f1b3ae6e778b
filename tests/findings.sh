#!/bin/sh
# findings.sh - the Findings quote the committed reference run: regenerate
# docs/findings.md's section and the README's headline findings from
# results/reference/*.csv (scripts/findings.sh) and compare; the README
# has at most ten headlines; docs/certify.md's results and include/libonb/onb.h's
# proven bounds quote results/certify/certify.csv the same way.
. "$(dirname "$0")/lib.sh"
sh scripts/findings.sh --check docs/findings.md && ok || bad "docs/findings.md differs from scripts/findings.sh's"
sh scripts/findings.sh --headlines --check README.md && ok || bad "README's headline findings differ from scripts/findings.sh --headlines"
sh scripts/findings.sh --certify --check docs/certify.md && ok || bad "docs/certify.md's results differ from results/certify (scripts/findings.sh --certify)"
sh scripts/findings.sh --onbh --check include/libonb/onb.h && ok || bad "include/libonb/onb.h's proven bounds differ from results/certify (scripts/findings.sh --onbh)"
n=$(sed -n '/^<!-- headlines:begin/,/^<!-- headlines:end/p' README.md | grep -c '^[0-9][0-9]*\. ')
[ "$n" -ge 1 ] && [ "$n" -le 10 ] && ok || bad "README: $n headline findings, want 1 to 10"
finish findings
