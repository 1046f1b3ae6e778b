# wild-merge.awk - one CSV from the same file of several runs (scripts/wild.sh:
# results/wild and results/wild/add/*/): the header and comment lines of the
# first file, and each method's rows from the last file that has that
# method, so that a re-run of a method replaces its rows whole.  The files
# must have the same header: a run from another revision's columns is
# refused, not mixed.
#   awk -f wild-merge.awk FILE...
function mcol(line,   n, f, i) {
	n = split(line, f, ",")
	for (i = 1; i <= n; i++) if (f[i] == "method") return i
	return 0
}
FNR == 1 { nf++; name[nf] = FILENAME; hdr = "" }
/^#/ || $0 == "" { if (nf == 1) print; next }
hdr == "" {
	hdr = $0
	if (nf == 1) { first = $0; c = mcol($0); if (!c) { print "wild-merge: " FILENAME " has no method column" > "/dev/stderr"; bad = 1; exit 1 }; print; next }
	if ($0 != first) { print "wild-merge: " FILENAME "'s header differs from " name[1] "'s: re-run it at this revision (scripts/wild-run.sh --add)" > "/dev/stderr"; bad = 1; exit 1 }
	next
}
{ split($0, f, ","); m = f[c]; last[m] = nf; nrow[nf]++; line[nf, nrow[nf]] = $0; meth[nf, nrow[nf]] = m }
END {
	if (bad) exit 1
	for (i = 1; i <= nf; i++)
		for (r = 1; r <= nrow[i]; r++)
			if (last[meth[i, r]] == i) print line[i, r]
}
