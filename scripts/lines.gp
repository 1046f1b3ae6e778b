# lines.gp - one line per method, log y (and log x when logx=1), as small
# multiples: one panel per group of families (scripts/styles.sh, the same
# grouping in float and double), the same axes in every panel so panels
# compare at a glance; each panel's key sits above it, never beside it.
# Called by plots.sh (and poles.sh) with:
#   out (file name without extension), ttl, xl, yl: title and axis labels
#     (yl_key instead of yl: the name of one of style.gp's wordings)
#   files, colors, dashes, points, widths, panels: space-separated lists,
#     one word per method (from styles.sh), in drawing order
#   titles: a file with one key title per method, in the same order (the
#     name, "= other" when its line coincides with another's, the count of
#     non-finite outputs, "no finite point" when it has none)
#   ptitles: one word per panel (family names joined by commas)
#   col: the data column to plot (x is column 1; column 4 holds the number
#     of non-finite outputs in the bin); logx: 0 or 1
#   floor, ceil: where zero and non-finite values are drawn: non-finite
#     values sit in a shaded band at ceil, labelled "non-finite"
#   xmin, xmax, ymin, ymax: the ranges (plots.sh takes them from the data)
#   here: the scripts directory (style.gp)
#   optional zero_x: where the pole bin is drawn (an x tic "-z", or
#     zero_label: "+z" at the north pole)
#   optional ref_file, ref_title: the accuracy floor band (x lo hi), drawn
#     grey in every panel under the methods
#   optional single=1: one panel (the README's figures), W_SINGLE wide
load here."/style.gp"
if (exists("yl_key")) yl = value(yl_key)
set datafile separator whitespace
set logscale y
if (logx) set logscale x; set format x "10^{%L}"
set format y "10^{%L}"
set xrange [xmin:xmax]
if (exists("zero_x")) set xtics add ((exists("zero_label") ? zero_label : "-z") zero_x)
has_nf = exists("nf") ? nf : (ymax >= ceil)
if (has_nf) { ymax = ceil * 5; set ytics add ("non-finite" ceil) }
set yrange [ymin:ymax]
# the eps levels of float and double, on the right axis, where in range
set logscale y2
set y2range [ymin:ymax]
set y2tics nomirror font F_TICK
set format y2 ""
set ytics nomirror
if (EPS_FLOAT > ymin && EPS_FLOAT < ceil / 5) {
    set y2tics add ("float eps" EPS_FLOAT)
    set arrow 11 from graph 0, first EPS_FLOAT to graph 1, first EPS_FLOAT nohead dt 3 lw 1 lc rgb "#555555" back
}
if (EPS_DOUBLE > ymin && EPS_DOUBLE < ceil / 5) {
    set y2tics add ("double eps" EPS_DOUBLE)
    set arrow 12 from graph 0, first EPS_DOUBLE to graph 1, first EPS_DOUBLE nohead dt 3 lw 1 lc rgb "#555555" back
}
if (has_nf) set object 13 rect from graph 0, first ceil / 3 to graph 1, graph 1 fc rgb C_NONFINITE fs solid 1.0 noborder behind
set key outside top center horizontal Left reverse maxcols 3 samplen 2.5 spacing 1.1 width 1 noenhanced
set xlabel xl font F_AXIS
set ylabel yl font F_AXIS
n = words(files)
if (!exists("single")) single = 0
np = single ? 1 : words(ptitles)
ncols = (np > 1) ? 2 : 1
nrows = (np + ncols - 1) / ncols
W = single ? W_SINGLE : W_MULTI
H = single ? H_SINGLE : 90 + H_PANEL_ROW * nrows
has_ref = exists("ref_file") ? (ref_file ne "") : 0
in_panel(i, p) = single ? 1 : (int(word(panels, i)) == p)
title(i) = system(sprintf("sed -n '%dp' '%s'", i, titles))
# fixed margins, so that every panel's graph has the same size
set tmargin 5.5
set bmargin 3.5
set lmargin 14
set rmargin 10
REF = has_ref ? sprintf("'%s' using 1:2:3 with filledcurves fc rgb '%s' fs transparent solid 0.35 noborder title '%s',", ref_file, C_FLOOR, ref_title) : ""
note = sprintf("zero error drawn at %.0e; wide lines: frisvad, frisvad\\_max, duff", floor)
do for [term_i = 1:NTERM] {
    eval term(term_i, W, H)
    set output out.ext(term_i)
    set multiplot layout nrows,ncols title ttl."\n{/*0.8 ".note."}" font F_TITLE
    do for [p = 1:np] {
        # no panel title: the key above each panel names its series
        unset title
        plot @REF for [i = 1:n] word(files, i) using 1:(in_panel(i, p) ? column(col) : 1/0) with linespoints \
                 pt int(word(points, i)) ps 0.6 pi 4 lw real(word(widths, i)) lc rgb word(colors, i) dt int(word(dashes, i)) \
                 title (in_panel(i, p) ? title(i) : ""), \
             for [i = 1:n] word(files, i) using 1:(in_panel(i, p) && column(4) > 0 ? ceil : 1/0) with points \
                 pt int(word(points, i)) ps 1.2 lc rgb word(colors, i) notitle
    }
    unset multiplot
}
