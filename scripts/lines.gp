# lines.gp - one line per method, log y (and log x when logx=1), as small
# multiples: one panel per group of families (scripts/styles.sh), the same
# axes in every panel so panels compare at a glance.
# Called by plots.sh with:
#   out (file name without extension), ttl, xl, yl: title and axis labels
#   files, names, colors, dashes, points, widths, panels: space-separated
#     lists, one word per method (from styles.sh), in drawing order
#   ptitles: one word per panel (family names joined by commas)
#   col: the data column to plot (x is column 1); logx: 0 or 1
#   floor, ceil: where zero and non-finite values are drawn (noted in the title)
#   xmin, xmax, ymin, ymax: the ranges (plots.sh takes them from the data)
#   optional zero_x: where the n.z = -1 bin is drawn (an x tic "-z", or
#     zero_label: "+z" at the north pole)
#   optional ref_file, ref_title: a reference series (x y) drawn grey in
#     every panel, under the methods; with ref_band=1 the file holds
#     x lo hi and is drawn as a grey band (the accuracy floor, issue 16)
set datafile separator whitespace
set logscale y
if (logx) set logscale x; set format x "10^{%L}"
set format y "10^{%L}"
set xrange [xmin:xmax]
if (exists("zero_x")) set xtics add ((exists("zero_label") ? zero_label : "-z") zero_x)
set yrange [ymin:ymax]
set grid lc rgb "#dddddd"
set key outside right top Left reverse font ",9" spacing 1.0 samplen 2 width 0
set rmargin 33
set lmargin 11
set xlabel xl font ",9"
set ylabel yl font ",9"
n = words(files)
np = words(ptitles)
ncols = (np > 1) ? 2 : 1
nrows = (np + ncols - 1) / ncols
H = 90 + 330 * nrows
has_ref = exists("ref_file") ? (ref_file ne "") : 0
if (!exists("ref_band")) ref_band = 0
in_panel(i, p) = (int(word(panels, i)) == p)
do for [term_i = 1:2] {
    if (term_i == 1) { set terminal pngcairo size 1500,H font ",10"; set output out.".png" }
    if (term_i == 2) { set terminal svg size 1500,H font "sans,10"; set output out.".svg" }
    set multiplot layout nrows,ncols title ttl."\n{/*0.8 zero error drawn at ".sprintf("%.0e", floor).", non-finite output at ".sprintf("%.0e", ceil)."; wide lines: frisvad, frisvad\\_max, duff}" font ",12"
    do for [p = 1:np] {
        set title word(ptitles, p) font ",10" noenhanced
        if (has_ref && ref_band) {
            plot ref_file using 1:2:3 with filledcurves fc rgb "#8c8c8c" fs transparent solid 0.45 noborder title ref_title noenhanced, \
                 for [i = 1:n] word(files, i) using 1:(in_panel(i, p) ? column(col) : 1/0) with linespoints \
                 pt int(word(points, i)) ps 0.45 pi 4 lw real(word(widths, i)) lc rgb word(colors, i) dt int(word(dashes, i)) \
                 title (in_panel(i, p) ? word(names, i) : "") noenhanced
        } else { if (has_ref) {
            plot ref_file using 1:2 with lines lw 6 lc rgb "#cccccc" title ref_title noenhanced, \
                 for [i = 1:n] word(files, i) using 1:(in_panel(i, p) ? column(col) : 1/0) with linespoints \
                 pt int(word(points, i)) ps 0.45 pi 4 lw real(word(widths, i)) lc rgb word(colors, i) dt int(word(dashes, i)) \
                 title (in_panel(i, p) ? word(names, i) : "") noenhanced
        } else {
            plot for [i = 1:n] word(files, i) using 1:(in_panel(i, p) ? column(col) : 1/0) with linespoints \
                 pt int(word(points, i)) ps 0.45 pi 4 lw real(word(widths, i)) lc rgb word(colors, i) dt int(word(dashes, i)) \
                 title (in_panel(i, p) ? word(names, i) : "") noenhanced
        } }
    }
    unset multiplot
}
