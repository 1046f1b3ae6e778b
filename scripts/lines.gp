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
#   optional bands: a file (scripts/floor-bands.awk's output), one line per
#     accuracy-floor band: "data-file panel colour title...", each drawn
#     under the methods of its panel, translucent, in its colour
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
in_panel(i, p) = single ? 1 : (int(word(panels, i)) == p)
nb = exists("bands") ? int(system(sprintf("awk 'END { print NR }' '%s'", bands))) : 0
bfield(b, k) = system(sprintf("awk -v b=%d -v k=%d 'NR == b { if (k < 4) print $k; else { sub(/^[^ ]+ [^ ]+ [^ ]+ /, \"\"); print } }' '%s'", b, k, bands))
BF = ""; BP = ""; BC = ""
do for [b = 1:nb] { BF = BF." ".bfield(b, 1); BP = BP." ".bfield(b, 2); BC = BC." ".bfield(b, 3) }
in_band(b, p) = single ? 1 : (int(word(BP, b)) == p)
# the key above each panel: room for its entries, two to a row
most = 0
do for [p = 1:np] {
    e = 0
    do for [i = 1:n] { if (in_panel(i, p)) { e = e + 1 } }
    do for [b = 1:nb] { if (in_band(b, p)) { e = e + 1 } }
    if (e > most) { most = e }
}
title(i) = system(sprintf("sed -n '%dp' '%s'", i, titles))
# fixed margins, so that every panel's graph has the same size
set tmargin 2.2 + 1.25 * ceil(most / (single ? 3.0 : 2.0))
set bmargin 3.5
set lmargin 14
set rmargin 10
note = sprintf("zero error drawn at %.0e; wide lines: frisvad, frisvad\\_max, duff", floor)
if (nb > 0) note = note."}\n{/*0.8 bands: each method's own accuracy floor (its exact formula rounded once), RMS to max per bin, in its colour"
do for [term_i = 1:NTERM] {
    eval term(term_i, W, H)
    set output out.ext(term_i)
    set multiplot layout nrows,ncols title ttl."\n{/*0.8 ".note."}" font F_TITLE
    do for [p = 1:np] {
        # no panel title: the key above each panel names its series
        unset title
        # (gnuplot evaluates an empty iteration's colour once: no bands, no clause)
        if (nb > 0) {
        plot for [b = 1:nb] word(BF, b) using 1:(in_band(b, p) ? $2 : 1/0):3 with filledcurves fc rgb word(BC, b) \
                 fs transparent solid 0.22 noborder title (in_band(b, p) ? bfield(b, 4) : ""), \
             for [i = 1:n] word(files, i) using 1:(in_panel(i, p) ? column(col) : 1/0) with linespoints \
                 pt int(word(points, i)) ps 0.6 pi 4 lw real(word(widths, i)) lc rgb word(colors, i) dt int(word(dashes, i)) \
                 title (in_panel(i, p) ? title(i) : ""), \
             for [i = 1:n] word(files, i) using 1:(in_panel(i, p) && column(4) > 0 ? ceil : 1/0) with points \
                 pt int(word(points, i)) ps 1.2 lc rgb word(colors, i) notitle
        } else {
        plot for [i = 1:n] word(files, i) using 1:(in_panel(i, p) ? column(col) : 1/0) with linespoints \
                 pt int(word(points, i)) ps 0.6 pi 4 lw real(word(widths, i)) lc rgb word(colors, i) dt int(word(dashes, i)) \
                 title (in_panel(i, p) ? title(i) : ""), \
             for [i = 1:n] word(files, i) using 1:(in_panel(i, p) && column(4) > 0 ? ceil : 1/0) with points \
                 pt int(word(points, i)) ps 1.2 lc rgb word(colors, i) notitle
        }
    }
    unset multiplot
}
