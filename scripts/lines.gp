# lines.gp - one line per method, log y (and log x when logx=1).
# Called by plots.sh with:
#   out (file name without extension), ttl, xl, yl: title and axis labels
#   files, names, colors, dashes: space-separated lists, one word per method
#   col: the data column to plot (x is column 1); logx: 0 or 1
#   floor, ceil: where zero and non-finite values are drawn (noted on the chart)
#   xmin, xmax: the x range
set datafile separator whitespace
set logscale y
if (logx) set logscale x; set format x "10^{%L}"
set format y "10^{%L}"
set xrange [xmin:xmax]
set yrange [floor/3:ceil*3]
set grid lc rgb "#dddddd"
set key outside right top Left reverse font ",9" spacing 0.9
set xlabel xl
set ylabel yl
set title ttl
set label 1 sprintf("zero error drawn at %.0e, non-finite at %.0e", floor, ceil) at graph 0.01, graph 0.03 font ",8" tc rgb "#555555"
#   band, bandtitle (optional): a file of x, low, high drawn as a grey band
#     under the lines (the accuracy floor: its RMS to its max in the bin)
n = words(files)
if (!exists("band")) band = ""
if (!exists("bandtitle")) bandtitle = "floor"
do for [term_i = 1:2] {
    if (term_i == 1) { set terminal pngcairo size 1100,620 font ",10"; set output out.".png" }
    if (term_i == 2) { set terminal svg size 1100,620 font "sans,10"; set output out.".svg" }
    if (strlen(band) > 0) {
        plot band using 1:2:3 with filledcurves fc rgb "#707070" fs transparent solid 0.45 noborder title bandtitle noenhanced, \
             for [i = 1:n] word(files, i) using 1:(column(col)) with linespoints pt 7 ps 0.35 lw 1.5 \
             lc rgb word(colors, i) dt int(word(dashes, i)) title word(names, i) noenhanced
    } else {
        plot for [i = 1:n] word(files, i) using 1:(column(col)) with linespoints pt 7 ps 0.35 lw 1.5 \
             lc rgb word(colors, i) dt int(word(dashes, i)) title word(names, i) noenhanced
    }
}
