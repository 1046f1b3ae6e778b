# tradeoff.gp - speed against accuracy, one point per method (the
# successor of Frisvad 2012, Table 1, as a chart), log-log, two panels:
# against the RMSE on uniform inputs, and against the worst max defect over
# uniform, south and threshold inputs, where `onbstudy table`'s Pareto
# front is drawn (circled, and its staircase); the RMSE panel has its own
# front by the same rule (tradeoff-data.sh), not the worst case's.  No key: the subtitle says
# what the marks mean, with the front's rule (read from tradeoff-data.sh's
# rule file: table's own, speeds within 5% equal), and every point is
# labelled directly.
# Called by plots.sh with: dir (holding tradeoff_PREC.dat and
# front_PREC.dat from tradeoff-data.sh), prec, out, floor, ceil, here (the
# scripts directory: tradeoff-labels.awk places the labels so that none
# overprints another); optional single=1: the worst-case panel alone (the
# README's figure).
load here."/style.gp"
set datafile separator whitespace
set logscale xy
set format y "10^{%L}"
unset key
set xtics ("100" 100, "200" 200, "300" 300, "500" 500, "700" 700, "1000" 1000, "1500" 1500, "2000" 2000, "3000" 3000, "5000" 5000)
if (!exists("single")) single = 0
data = dir."/tradeoff_".prec.".dat"
front = dir."/stairs_".prec.".dat"
front_rms = dir."/stairs_rms_".prec.".dat"
stats data using 1 nooutput
npts = STATS_records
xmin = STATS_min / 1.5
xmax = STATS_max * 1.6
# y: from the data, and up to the non-finite band only when a point is in it
stats data using 2 nooutput
ymin2 = STATS_min / 5
ymax2 = (STATS_max >= ceil) ? ceil * 4 : STATS_max * 4
stats data using 6 nooutput
ymin1 = STATS_min / 5
ymax1 = (STATS_max >= ceil) ? ceil * 4 : STATS_max * 4
W = single ? W_SINGLE : W_MULTI
# taller with many methods: the labels need free rows (50 methods filled
# 790 px, and a label with no free spot would overprint another)
H = single ? H_SINGLE + 60 : (npts > 30 ? 790 + (npts - 30) * 14 : 790)
# the graph's size in pixels (for the label placer's character sizes)
gw = (single ? W : W / 2) - 150
gh = H - 170
labels(c, y0, y1) = sprintf("< awk -v col=%d -v xmin=%g -v xmax=%g -v ymin=%g -v ymax=%g -v gw=%d -v gh=%d -v stairs='%s' -f '%s/tradeoff-labels.awk' '%s'", c, xmin, xmax, y0, y1, gw, gh, (c == 2 ? front : front_rms), here, data)
set xrange [xmin:xmax]
set xlabel "batch throughput, 1 thread, L2-resident (million bases per second)" font F_AXIS
set lmargin 14
set rmargin 3
# (single: no panel title above the graph, so no room kept for one)
set tmargin (single ? 2 : 5)
set bmargin 4
# nonfinite(y1): the band and the axis label of non-finite output
nf_band(y1) = (y1 > ceil) ? 1 : 0
rule1 = system(sprintf("sed -n 1p '%s/rule_%s.txt'", dir, prec))
rule2 = system(sprintf("sed -n 2p '%s/rule_%s.txt'", dir, prec))
sub = sprintf("{/*0.8 right is faster, down is more accurate; zero error drawn at %.0e}\n{/*0.8 %s}\n{/*0.8 %s}", floor, rule1, rule2)
FRONT = "front using 1:2 with steps lw 2 lc rgb '#555555' notitle, data using 1:($5 == 1 ? $2 : 1/0) with points pt 6 ps 2.6 lw 1.5 lc rgb '#000000' notitle,"
do for [term_i = 1:NTERM] {
    eval term(term_i, W, H)
    set output out.ext(term_i)
    set multiplot layout 1, (single ? 1 : 2) title prec.": speed against accuracy (onbstudy bench and sweep)\n".sub font F_TITLE
    if (!single) {
        set yrange [ymin1:ymax1]
        unset label; unset arrow; unset object
        set ytics autofreq
        if (nf_band(ymax1)) { set ytics add ("non-finite" ceil); set object 1 rect from graph 0, first ceil / 2 to graph 1, graph 1 fc rgb C_NONFINITE fs solid 1.0 noborder behind }
        load labels(6, ymin1, ymax1)
        set ylabel "RMSE on uniform inputs (Frisvad 2012, Table 1; unitless)" font F_AXIS
        set title "against the RMSE, with its own Pareto front (grey staircase)" font F_PANEL
        plot front_rms using 1:2 with steps lw 2 lc rgb '#555555' notitle, \
             data using 1:6:3 with points pt 7 ps 1.4 lc rgb variable notitle, \
             data using 1:($7 == 1 ? $6 : 1/0) with points pt 6 ps 2.6 lw 1.5 lc rgb "#000000" notitle
    }
    set yrange [ymin2:ymax2]
    unset label; unset arrow; unset object
    set ytics autofreq
    if (nf_band(ymax2)) { set ytics add ("non-finite" ceil); set object 1 rect from graph 0, first ceil / 2 to graph 1, graph 1 fc rgb C_NONFINITE fs solid 1.0 noborder behind }
    load labels(2, ymin2, ymax2)
    set ylabel "worst max defect over uniform, south, threshold (unitless)" font F_AXIS
    set title (single ? "" : "against the worst case, with the Pareto front of onbstudy table (grey staircase)") font F_PANEL
    plot @FRONT data using 1:2:3 with points pt 7 ps 1.4 lc rgb variable notitle
    unset multiplot
}
