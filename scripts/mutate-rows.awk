# mutate-rows.awk - scripts/mutate.sh's rows for a mutated function:
#   awk -F'\t' -v k=KEY -f scripts/mutate-rows.awk ROWS
# ROWS: NAME TAB ROW lines (the table of tests/indep_lib.c); KEY: the
# function's name less onb_ (duff_compf, dufff, stark_pref).  Prints the
# ROW (with a comma) of every NAME that is a prefix of KEY or has KEY as
# its prefix, KEY with or without its final f: the rule of test_indep.c's
# INDEP_FIRST.  A row too many or too few changes no verdict: mutate.sh
# runs the full test on whatever these rows do not catch.
function pre(a, b,   m) { m = length(a) < length(b) ? length(a) : length(b); return m > 0 && substr(a, 1, m) == substr(b, 1, m) }
{
	if (pre(k, $1) || (length(k) > 1 && k ~ /f$/ && pre(substr(k, 1, length(k) - 1), $1)))
		print $2 ","
}
