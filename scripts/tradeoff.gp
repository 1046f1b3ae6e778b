# tradeoff.gp - speed against accuracy, one point per method (the
# successor of Frisvad 2012, Table 1, as a chart); the Pareto front of
# `onbstudy table` circled and joined.
# Called by plots.sh with: dir (holding tradeoff_PREC.dat and
# front_PREC.dat from tradeoff-data.sh), prec, out, floor.
set datafile separator whitespace
set logscale y
set format y "10^{%L}"
set grid lc rgb "#dddddd"
set key below font ",9"
set xlabel "batch throughput, 1 thread, L2-resident (million bases per second)"
set ylabel "worst max defect over uniform, south and threshold (unitless)"
set title prec.": speed against accuracy (onbstudy bench + sweep; higher right is faster, lower is more accurate)"
set label 1 sprintf("zero error drawn at %.0e, non-finite output at 10", floor) at graph 0.99, graph 0.3 right font ",8" tc rgb "#555555"
data = dir."/tradeoff_".prec.".dat"
front = dir."/front_".prec.".dat"
stats data using 1 nooutput
set xrange [0:STATS_max * 1.2]
stats data using 2 nooutput
set yrange [STATS_min / 5:30]
do for [term_i = 1:2] {
    if (term_i == 1) { set terminal pngcairo size 1100,680 font ",10"; set output out.".png" }
    if (term_i == 2) { set terminal svg size 1100,680 font "sans,10"; set output out.".svg" }
    plot front using 1:2 with steps lw 1.2 lc rgb "#555555" dt 2 title "Pareto front", \
         front using 1:2 with points pt 6 ps 2.2 lc rgb "#000000" notitle, \
         data using 1:2:3 with points pt 7 ps 1.2 lc rgb variable notitle, \
         data using 1:2:4 with labels left offset 0.8,0.4 font ",8" noenhanced notitle
}
