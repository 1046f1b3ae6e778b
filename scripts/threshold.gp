# threshold.gp - Max's analysis: the largest normality and orthogonality
# error of Frisvad's Listing 2 against its threshold t, log-log in 1 + t,
# with the published thresholds and the minimax drawn as vertical lines
# whose key entries give t and the error there (marks at one t share a
# line).  Rows whose error is not finite (t = -1: no input takes the
# fallback, and n = -z divides by zero) cannot sit on a log axis at
# 1 + t = 0: they are drawn left of the data in the non-finite band, and
# the key gives their count.  The key is above the graph, off the data.
# Called by plots.sh with: out, ttl, file (columns: 1+t normality
#   orthogonality both; finite rows), mfiles (one per mark: two points
#   at its 1 + t), mtitles (a file, one key title per mark), nfrows (the
#   count of non-finite rows), nft (their t), here, optional single=1
load here."/style.gp"
set datafile separator whitespace
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set key horizontal Left reverse maxcols 1 samplen 2.5 spacing 1.1 noenhanced
set xlabel "1 + t  (t: Frisvad's threshold on n.z; unitless)" font F_AXIS
set ylabel "largest error over the inputs near -z (unitless)" font F_AXIS
# the ranges: where the data start and end
stats file using ($1 > 0 ? $1 : 1/0) nooutput
x0 = STATS_min; x1 = STATS_max
stats file using ($2 > 0 ? $2 : 1/0) nooutput
y0 = STATS_min; y1 = STATS_max
stats file using ($3 > 0 ? $3 : 1/0) nooutput
if (STATS_min < y0) { y0 = STATS_min }
if (STATS_max > y1) { y1 = STATS_max }
if (!exists("nfrows")) nfrows = 0
# the non-finite rows: at a tick "t = -1" left of the data, in a band
# above it
# (x tics by hand, one a decade; "t = -1" sits a full decade left of the
# first point, with an axis break between, and collides with none)
d0 = ceil(log10(x0)); d1 = floor(log10(x1))
xnf = x0 / 10.0
if (10.0**d0 < x0 * 1.5 && d0 < d1) { d0 = d0 + 1 }
set xtics ()
do for [d = d0:d1] { set xtics add (sprintf("10^{%d}", d) 10.0**d) }
set mxtics 10
# y tics by hand too, at most 10 of them, and "non-finite" two decades
# above the data, clear of them
e0 = floor(log10(y0 / 3)); e1 = ceil(log10(y1 * 3)) - 1
estep = ceil((e1 - e0 + 1) / 10.0)
set ytics ()
do for [e = e0:e1] { if (e % estep == 0) { set ytics add (sprintf("10^{%d}", e) 10.0**e) } }
set mytics 10
ynf = 10.0**(e1 + 1.7)
set xrange [(nfrows > 0 ? xnf / 2.5 : x0 / 1.5) : x1 * 1.5]
set yrange [y0 / 3 : (nfrows > 0 ? ynf * 6 : y1 * 3)]
if (nfrows > 0) {
    set xtics add ((nft eq "-1" ? "t = -1" : "non-finite") xnf)
    eval xbreak(sqrt(xnf * x0), xnf / 2.5, x1 * 1.5)
    set ytics add ("non-finite" ynf)
    set object 13 rect from graph 0, first ynf / 3 to graph 1, graph 1 fc rgb C_NONFINITE fs solid 1.0 noborder behind
}
# the eps levels, on the right axis, where in range
set logscale y2
set y2range [y0 / 3 : (nfrows > 0 ? ynf * 6 : y1 * 3)]
set ytics nomirror
set y2tics () font F_TICK
set my2tics 1
set format y2 ""
if (EPS_FLOAT > y0 / 3 && EPS_FLOAT < y1 * 3) {
    set y2tics add ("float eps" EPS_FLOAT)
    set arrow 91 from graph 0, first EPS_FLOAT to graph 1, first EPS_FLOAT nohead dt 3 lc rgb "#555555" back
}
if (EPS_DOUBLE > y0 / 3 && EPS_DOUBLE < y1 * 3) {
    set y2tics add ("double eps" EPS_DOUBLE)
    set arrow 92 from graph 0, first EPS_DOUBLE to graph 1, first EPS_DOUBLE nohead dt 3 lc rgb "#555555" back
}
set rmargin 11
nm = words(mfiles)
W = W_SINGLE; H = H_SINGLE + 120
# the key, one entry a row, between the title and the graph
set key at screen 0.5, screen 1 - 45.0 / H center top
set tmargin at screen 1 - (45.0 + 19 * (3 + nm + (nfrows > 0)) + 12) / H
mtitle(k) = system(sprintf("sed -n '%dp' '%s'", k, mtitles))
# the marks: the minimax green, solid; the published ones dotted and
# dashed, Frisvad 2012's grey and Max 2017's purple (no two marks in one
# colour: chart-check.awk's check 7)
mcol(k) = (strstrt(mtitle(k), "minimax") > 0) ? "#009E73" : (strstrt(mtitle(k), "Frisvad") > 0 ? "#555555" : "#8E44AD")
mdt(k) = (strstrt(mtitle(k), "minimax") > 0) ? 1 : (k % 2 ? 3 : 2)
nftitle = sprintf("t = %s (Frisvad 2012 without its fallback: n = -z divides by zero): non-finite, %d row%s", nft, nfrows, nfrows == 1 ? "" : "s")
if (!exists("single")) single = 0
do for [term_i = 1:NTERM] {
    eval term(term_i, W, H)
    set output out.ext(term_i)
    set multiplot title ttl font F_TITLE
    plot file using 1:2 with lines lw 2 lc rgb "#0072B2" title "normality  max| |b_i| - 1 |", \
         file using 1:3 with lines lw 2 dt 2 lc rgb "#D55E00" title "orthogonality  max(|b1.n|, |b2.n|, |b1.b2|)", \
         file using 1:4 with lines lw 1 lc rgb "#333333" title "both (the larger)", \
         for [k = 1:nm] word(mfiles, k) using 1:($2 < 1 ? y0 / 3 : (nfrows > 0 ? ynf * 6 : y1 * 3)) with lines lw 1.5 dt mdt(k) lc rgb mcol(k) title mtitle(k), \
         (nfrows > 0 ? "+" : "< true") using (xnf):(ynf) every ::0::0 with points pt 7 ps 1.2 lc rgb "#000000" title (nfrows > 0 ? nftitle : "")
    unset multiplot
}
