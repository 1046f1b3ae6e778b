# tradeoff.gp - speed against accuracy, one point per method (the
# successor of Frisvad 2012, Table 1, as a chart), log-log, two panels:
# against the RMSE on uniform inputs, and against the worst max defect over
# uniform, south and threshold inputs, where `onbstudy table`'s Pareto
# front is drawn (circled and joined).
# Called by plots.sh with: dir (holding tradeoff_PREC.dat and
# front_PREC.dat from tradeoff-data.sh), prec, out, floor.
set datafile separator whitespace
set logscale xy
set format y "10^{%L}"
set grid lc rgb "#dddddd"
set key top left font ",9" box opaque
set xtics ("300" 300, "500" 500, "700" 700, "1000" 1000, "1500" 1500, "2000" 2000, "3000" 3000, "5000" 5000)
data = dir."/tradeoff_".prec.".dat"
front = dir."/front_".prec.".dat"
stats data using 1 nooutput
xmin = STATS_min / 1.5
xmax = STATS_max * 1.6
stats data using 2 nooutput
ymin2 = STATS_min / 5
stats data using 6 nooutput
ymin1 = STATS_min / 5
set xrange [xmin:xmax]
set xlabel "batch throughput, 1 thread, L2-resident (million bases per second)"
do for [term_i = 1:2] {
    if (term_i == 1) { set terminal pngcairo size 1400,640 font ",10"; set output out.".png" }
    if (term_i == 2) { set terminal svg size 1400,640 font "sans,10"; set output out.".svg" }
    set multiplot layout 1,2 title prec.": speed against accuracy (onbstudy bench and sweep; right is faster, down is more accurate; zero error drawn at ".sprintf("%.0e", floor).", non-finite at 10)" font ",11"
    set yrange [ymin1:30]
    set ylabel "RMSE on uniform inputs (Frisvad 2012, Table 1; unitless)"
    set title "against the RMSE" font ",10"
    plot data using 1:6:3 with points pt 7 ps 1.2 lc rgb variable notitle, \
         data using 1:6:4 with labels left offset 0.6,0.35 font ",7" noenhanced notitle, \
         data using 1:($5 == 1 ? $6 : 1/0) with points pt 6 ps 2.2 lc rgb "#000000" title "on the Pareto front (right panel)"
    set yrange [ymin2:30]
    set ylabel "worst max defect over uniform, south, threshold (unitless)"
    set title "against the worst case, with the Pareto front" font ",10"
    plot front using 1:2 with steps lw 1.2 lc rgb "#555555" dt 2 title "Pareto front", \
         front using 1:2 with points pt 6 ps 2.2 lc rgb "#000000" notitle, \
         data using 1:2:3 with points pt 7 ps 1.2 lc rgb variable notitle, \
         data using 1:2:4 with labels left offset 0.6,0.35 font ",7" noenhanced notitle
    unset multiplot
}
