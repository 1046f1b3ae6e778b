# threshold.gp - Max's analysis: the largest normality and orthogonality
# error of Frisvad's Listing 2 against its threshold t, log-log in 1 + t,
# with the minimax points and the published thresholds.
# Called by plots.sh with: out, ttl, file (columns: 1+t normality orthogonality both),
#   marks (a gnuplot command file setting arrows and boxed labels), here,
#   optional single=1 (the README's figure: the same chart, W_SINGLE wide)
load here."/style.gp"
set datafile separator whitespace
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set key inside left bottom Left reverse box opaque noenhanced
set xlabel "1 + t  (t: Frisvad's threshold on n.z; unitless)" font F_AXIS
set ylabel "largest error over the inputs near -z (unitless)" font F_AXIS
set title ttl font F_TITLE noenhanced
set style textbox opaque noborder margins 1, 1
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
# the eps levels, on the right axis, where in range
set logscale y2
set y2range [y0 / 3 : y1 * 3]
set ytics nomirror
set y2tics font F_TICK
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
if (!exists("single")) single = 0
W = W_SINGLE; H = H_SINGLE
do for [term_i = 1:NTERM] {
    eval term(term_i, W, H)
    set output out.ext(term_i)
    plot file using 1:2 with lines lw 2 lc rgb "#0072B2" title "normality  max| |b_i| - 1 |", \
         file using 1:3 with lines lw 2 dt 2 lc rgb "#D55E00" title "orthogonality  max(|b1.n|, |b2.n|, |b1.b2|)", \
         file using 1:4 with lines lw 1 lc rgb "#000000" title "both (the larger)"
}
