# half-bounds.awk - the binary16 proofs against the committed half runs:
# no method that certify --precision half proves over the whole sphere may
# have a larger defect in the halfscan or in the half sweep's distributions
# of roundings of unit vectors (uniform, north, south, exhaustive, grid;
# not threshold, whose rings reach off unit length, nor nonunit).
#   awk -F, -f scripts/half-bounds.awk results/half/certify/certify-half.csv \
#       results/half/halfscan/halfscan.csv results/half/sweep/summary.csv
# prints each violation and how many maxima it checked; exit 1 on a
# violation or when nothing was checked.
FNR == 1 { fi++ }
/^#/ { next }
fi == 1 && $1 == "method" { for (i = 1; i <= NF; i++) c[$i] = i; next }
fi == 1 { m = $1; if ($c["status"] != "proven") nob[m] = 1; else if ($c["bound"] + 0 > B[m]) B[m] = $c["bound"] + 0; next }
fi == 2 && $1 == "method" { for (i = 1; i <= NF; i++) h[$i] = i; next }
fi == 2 { m = $1; if ((m in B) && !(m in nob)) { n++; if ($h["max_defect_u"] * 2 ^ -11 > B[m]) { bad++; print "halfscan: " m " " $h["max_defect_u"] "u above its proven " B[m] * 2048 "u" } } next }
fi == 3 && $1 == "method" { for (i = 1; i <= NF; i++) s[$i] = i; next }
fi == 3 && $2 == "half" && $3 ~ /^(uniform|north|south|exhaustive|grid)$/ { m = $1
	if ((m in B) && !(m in nob)) { n++; if ($s["max_defect"] !~ /nan|inf/ && $s["max_defect"] + 0 > B[m]) { bad++; print "sweep " $3 ": " m " " $s["max_defect"] * 2048 "u above its proven " B[m] * 2048 "u" } } }
END { print n + 0 " maxima checked"; exit bad > 0 || n == 0 }
