#!/bin/sh
# findings.sh - the README's Findings quote the committed reference run:
# regenerate the section from results/reference/*.csv and compare.
set -u
cd "$(dirname "$0")/.."
if sh scripts/findings.sh --check README.md; then
	echo "findings: 1 passed, 0 failed"
else
	echo "findings: 0 passed, 1 failed"
	exit 1
fi
