#!/bin/sh
# family-list.sh - the study's formula families, as the X-macro list that
# src/families/families.c is compiled with (-DSTUDY_FAMILY_LIST(X)=...):
# X(name) for each `const study_family family_NAME = {` line of the family
# files, so a family is listed by being defined, with no hand-kept list.
# The Makefile and scripts/fuzz.sh call it; run from the repository root.
sed -n 's/^const study_family family_\([a-z0-9_]*\) = {$/X(\1)/p' src/families/*.c | tr '\n' ' ' | sed 's/ $//'
