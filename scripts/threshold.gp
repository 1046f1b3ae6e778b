# threshold.gp - Max's analysis: the largest normality and orthogonality
# error of Frisvad's Listing 2 against its threshold t, log-log in 1 + t,
# with the minimax points and the published thresholds.
# Called by plots.sh with: out, ttl, file (columns: 1+t normality orthogonality both),
#   marks (a gnuplot command file setting arrows and labels)
set datafile separator whitespace
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid lc rgb "#dddddd"
set key inside left bottom font ",9" box opaque
set xlabel "1 + t  (t: Frisvad's threshold on n.z)"
set ylabel "largest error over inputs near -z (unitless)"
set title ttl
load marks
# the ranges: where the data start and end (a published threshold outside
# them widens the x range so that its mark shows)
stats file using ($1 > 0 && $1 < 1e300 ? $1 : 1/0) nooutput
x0 = STATS_min; x1 = STATS_max
set xrange [x0 / 1.5 : x1 * 1.5]
stats file using ($2 > 0 && $2 < 1e300 ? $2 : 1/0) nooutput
y0 = STATS_min; y1 = STATS_max
stats file using ($3 > 0 && $3 < 1e300 ? $3 : 1/0) nooutput
if (STATS_min < y0) { y0 = STATS_min }
if (STATS_max > y1) { y1 = STATS_max }
set yrange [y0 / 3 : y1 * 3]
do for [term_i = 1:2] {
    if (term_i == 1) { set terminal pngcairo size 1100,620 font ",10"; set output out.".png" }
    if (term_i == 2) { set terminal svg size 1100,620 font "sans,10"; set output out.".svg" }
    plot file using 1:2 with lines lw 2 lc rgb "#1f77b4" title "normality  max| |b_i| - 1 |", \
         file using 1:3 with lines lw 2 lc rgb "#d62728" title "orthogonality  max(|b1.n|, |b2.n|, |b1.b2|)", \
         file using 1:4 with lines lw 1 dt 2 lc rgb "#000000" title "both"
}
