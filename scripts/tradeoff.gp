# tradeoff.gp - speed against accuracy, one point per method (the
# successor of Frisvad 2012, Table 1, as a chart), log-log, two panels:
# against the RMSE on uniform inputs, and against the worst max defect over
# uniform, south and threshold inputs, where `onbstudy table`'s Pareto
# front is drawn (circled and joined).
# Called by plots.sh with: dir (holding tradeoff_PREC.dat and
# front_PREC.dat from tradeoff-data.sh), prec, out, floor, here (the
# scripts directory: tradeoff-labels.awk places the labels so that none
# overprints another).
set datafile separator whitespace
set logscale xy
set format y "10^{%L}"
set grid lc rgb "#dddddd"
set key outside bottom center horizontal font ",9"
set xtics ("100" 100, "200" 200, "300" 300, "500" 500, "700" 700, "1000" 1000, "1500" 1500, "2000" 2000, "3000" 3000, "5000" 5000)
data = dir."/tradeoff_".prec.".dat"
front = dir."/front_".prec.".dat"
stats data using 1 nooutput
xmin = STATS_min / 1.5
xmax = STATS_max * 1.6
stats data using 2 nooutput
ymin2 = STATS_min / 5
stats data using 6 nooutput
ymin1 = STATS_min / 5
ymax = 30
labels(c, y0) = sprintf("< awk -v col=%d -v xmin=%g -v xmax=%g -v ymin=%g -v ymax=%g -f '%s/tradeoff-labels.awk' '%s'", c, xmin, xmax, y0, ymax, here, data)
set xrange [xmin:xmax]
set xlabel "batch throughput, 1 thread, L2-resident (million bases per second)"
do for [term_i = 1:2] {
    if (term_i == 1) { set terminal pngcairo size 1400,640 font ",10"; set output out.".png" }
    if (term_i == 2) { set terminal svg size 1400,640 font "sans,10"; set output out.".svg" }
    set multiplot layout 1,2 title prec.": speed against accuracy (onbstudy bench and sweep; right is faster, down is more accurate; zero error drawn at ".sprintf("%.0e", floor).", non-finite at 10)" font ",11"
    set yrange [ymin1:ymax]
    unset label; unset arrow
    load labels(6, ymin1)
    set ylabel "RMSE on uniform inputs (Frisvad 2012, Table 1; unitless)"
    set title "against the RMSE" font ",10"
    plot data using 1:6:3 with points pt 7 ps 1.2 lc rgb variable notitle, \
         data using 1:($5 == 1 ? $6 : 1/0) with points pt 6 ps 2.2 lc rgb "#000000" title "on the Pareto front (right panel)"
    set yrange [ymin2:ymax]
    unset label; unset arrow
    load labels(2, ymin2)
    set ylabel "worst max defect over uniform, south, threshold (unitless)"
    set title "against the worst case, with the Pareto front" font ",10"
    plot front using 1:2 with steps lw 1.2 lc rgb "#555555" dt 2 title "Pareto front", \
         front using 1:2 with points pt 6 ps 2.2 lc rgb "#000000" notitle, \
         data using 1:2:3 with points pt 7 ps 1.2 lc rgb variable notitle
    unset multiplot
}
