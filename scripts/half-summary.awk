# half-summary.awk - each method's whole-sphere row of a certify-half.csv,
# as `certify --precision half` prints it (certify_half.c ch_summary): the
# largest bound and found over its regions in u = 2^-11 (inf where a region
# has no bound), their ratio, and how many regions are proven, non-finite,
# overflow, unbounded.
#   awk -f scripts/half-summary.awk results/half/certify/certify-half.csv
BEGIN { FS = ","; u = 2 ^ -11 }
/^#/ || $1 == "method" { next }
{
	m = $1
	if (!(m in seen)) { seen[m] = 1; order[++n] = m; B[m] = 0; F[m] = 0 }
	if ($7 == "inf") Binf[m] = 1; else if ($7 + 0 > B[m]) B[m] = $7 + 0
	if ($8 == "inf") Finf[m] = 1; else if ($8 + 0 > F[m]) F[m] = $8 + 0
	c[m, $12]++
}
function g(x, inf) { return inf ? "inf" : sprintf("%.4g", x / u) }
END {
	printf "%-24s %-6s %12s %12s %7s  %s\n", "method", "prec", "bound/u", "found/u", "ratio",
	       "regions proven/non-finite/overflow/unbounded"
	for (i = 1; i <= n; i++) {
		m = order[i]
		r = (!(m in Binf) && !(m in Finf) && F[m] > 0) ? sprintf("%.3g", B[m] / F[m]) : "nan"
		printf "%-24s %-6s %12s %12s %7s  %d/%d/%d/%d\n", m, "half", g(B[m], m in Binf), g(F[m], m in Finf), r,
		       c[m, "proven"], c[m, "non-finite"], c[m, "overflow"], c[m, "unbounded"]
	}
}
