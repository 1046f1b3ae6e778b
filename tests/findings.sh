#!/bin/sh
# findings.sh - the README's Findings quote the committed reference run:
# regenerate the section from results/reference/*.csv and compare.
. "$(dirname "$0")/lib.sh"
sh scripts/findings.sh --check README.md && ok || bad "README's findings differ from scripts/findings.sh's"
finish findings
