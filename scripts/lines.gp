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
#     accuracy-floor band: "data-file panel colour fill title...", each
#     drawn under the methods of its panel in its colour, translucent
#     (fill 0) or hatched (fill: a pattern number)
#   optional single=1: one panel (the README's figures), W_SINGLE wide
#   optional wide: the names of the wide series, for the subtitle
load here."/style.gp"
if (exists("yl_key")) yl = value(yl_key)
set datafile separator whitespace
set logscale y
if (logx) set logscale x; set format x "10^{%L}"
set format y "10^{%L}"
set xrange [xmin:xmax]
# the pole slot: its tick, a decade left of the first bin, an axis break
# between, and no line across it (the pole's points are drawn alone)
has_zx = exists("zero_x")
zx = has_zx ? zero_x : 0
off(x) = has_zx && x < zx * 1.5
# (x tics by hand, one a decade, the first at least a decade right of the
# slot, so that its label and the slot's never crowd: "-z 10^{-16}" in double)
if (has_zx) {
    set xtics ()
    # (a labelled tick every decade up to 9 decades, every second or
    # third beyond, counted down from the last, so that the labels of a
    # half-width panel never touch: double's 17 decades near the pole)
    xd0 = ceil(log10(zx * 10)); xd1 = floor(log10(xmax)); xdn = xd1 - xd0 + 1
    xstep = (xdn > 15) ? 3 : ((xdn > 9) ? 2 : 1)
    do for [d = xd0:xd1] { if ((xd1 - d) % xstep == 0) { set xtics add (sprintf("10^{%d}", d) 10.0**d) } else { set xtics add ("" 10.0**d 1) } }
    set mxtics 10
    set xtics add ((exists("zero_label") ? zero_label : "-z") zero_x)
    eval xbreak(zx * sqrt(10.0), xmin, xmax)
}
has_nf = exists("nf") ? nf : (ymax >= ceil)
set yrange [ymin:ymax]
# the eps levels of half, float and double, on the right axis, where in range
set logscale y2
set y2range [ymin:ymax]
set y2tics nomirror font F_TICK
set format y2 ""
set ytics nomirror
# (the dotted lines per panel, within its range: below)
eps_in(e, top) = e > ymin && e < ceil / 5 && e < top
if (EPS_HALF > ymin && EPS_HALF < ceil / 5) { set y2tics add ("half eps" EPS_HALF) }
if (EPS_FLOAT > ymin && EPS_FLOAT < ceil / 5) { set y2tics add ("float eps" EPS_FLOAT) }
if (EPS_DOUBLE > ymin && EPS_DOUBLE < ceil / 5) { set y2tics add ("double eps" EPS_DOUBLE) }
set key outside top center horizontal Left reverse maxcols 3 samplen 2.5 spacing 1.1 width 1 noenhanced
set xlabel xl font F_AXIS
set ylabel yl font F_AXIS
n = words(files)
if (!exists("single")) single = 0
np = single ? 1 : words(ptitles)
ncols = (np > 1) ? 2 : 1
nrows = (np + ncols - 1) / ncols
in_panel(i, p) = single ? 1 : (int(word(panels, i)) == p)
# the non-finite band only in the panels that draw a non-finite output
# (NFP: one 0/1 per panel, a bin with a non-finite count or a value at
# ceil), the others topped where the finite data end (YFIN: 4x the largest
# finite value of any panel, so that they share one axis); the panels with
# the band reach ceil * 5
NFP = system(sprintf("awk -v ce=%g -v c=%d -v np=%d -v single=%d -v files='%s' -v panels='%s' -f '%s/nf-panels.awk'", ceil, col, np, single, files, panels, here))
YFIN = real(word(NFP, 1))
panel_nf(p) = has_nf && int(word(NFP, p + 1))
ymax_nf = ceil * 5
ymax_fin = (YFIN > ymin && YFIN < ymax) ? YFIN : ymax
nb = exists("bands") ? int(system(sprintf("awk 'END { print NR }' '%s'", bands))) : 0
bfield(b, k) = system(sprintf("awk -v b=%d -v k=%d 'NR == b { if (k < 5) print $k; else { sub(/^[^ ]+ [^ ]+ [^ ]+ [^ ]+ /, \"\"); print } }' '%s'", b, k, bands))
BF = ""; BP = ""; BC = ""; BS = ""
do for [b = 1:nb] { BF = BF." ".bfield(b, 1); BP = BP." ".bfield(b, 2); BC = BC." ".bfield(b, 3); BS = BS." ".bfield(b, 4) }
hatched(b) = int(word(BS, b)) > 0
in_band(b, p) = single ? 1 : (int(word(BP, b)) == p)
title(i) = system(sprintf("sed -n '%dp' '%s'", i, titles))
# the key above each panel, in columns (vertical, at most krows rows, so
# gnuplot adds the columns), as many as the longest title of the panel
# lets fit in its cell (at most 3), and room above every graph for the
# most rows any panel needs, so that no key reaches a frame; a canvas
# 200 px wider when that keeps every key within 5 rows
CHW = 6.4
do for [wide_try = 0:1] {
    W = single ? W_SINGLE : W_MULTI + 200 * wide_try
    KW = (single ? W : W / 2) - 60
    krows = 1
    do for [p = 1:np] {
        e = 0; L = 0
        do for [i = 1:n] { if (in_panel(i, p)) { e = e + 1; if (strlen(title(i)) > L) { L = strlen(title(i)) } } }
        do for [b = 1:nb] { if (in_band(b, p)) { e = e + 1; if (strlen(bfield(b, 5)) > L) { L = strlen(bfield(b, 5)) } } }
        c = int(KW / (L * CHW + 70)); c = (c < 1) ? 1 : ((c > 3) ? 3 : c)
        r = ceil(e * 1.0 / c)
        if (r > krows) { krows = r }
    }
    if (krows <= 5 || single) { break }
}
set key vertical maxrows krows
# fixed margins, so that every panel's graph has the same size
set tmargin 1.8 + 1.15 * krows
# (and a taller canvas for a key of more rows than the usual, so that the
# graphs keep their height)
H = single ? H_SINGLE + 24 * (krows > 3 ? krows - 3 : 0) : 90 + (H_PANEL_ROW + 24 * (krows > 4 ? krows - 4 : 0)) * nrows
set bmargin 3.5
set lmargin 14
set rmargin 10
# the wide lines named from the series drawn (wide: their names, escaped
# for enhanced text, from plots.sh or poles.sh; none when all or none are wide)
note = sprintf("zero error drawn at %.0e", floor).((exists("wide") && wide ne "") ? "; wide lines: ".wide : "")
if (nb > 0) note = note."}\n{/*0.8 bands: each method's own accuracy floor (its exact formula rounded once), RMS to max per bin, in its colour"
do for [term_i = 1:NTERM] {
    eval term(term_i, W, H)
    set output out.ext(term_i)
    set multiplot layout nrows,ncols title ttl."\n{/*0.8 ".note."}" font F_TITLE
    do for [p = 1:np] {
        # no panel title: the key above each panel names its series
        unset title
        # this panel's top: the non-finite band, its tick and room for it
        # only where a series of the panel is non-finite
        if (panel_nf(p)) {
            set yrange [ymin:ymax_nf]; set y2range [ymin:ymax_nf]
            set ytics autofreq nomirror; set ytics add ("non-finite" ceil)
            set object 13 rect from graph 0, first ceil / 3 to graph 1, graph 1 fc rgb C_NONFINITE fs solid 1.0 noborder behind
        } else {
            set yrange [ymin:ymax_fin]; set y2range [ymin:ymax_fin]
            set ytics autofreq nomirror
            unset object 13
        }
        ptop = panel_nf(p) ? ymax_nf : ymax_fin
        if (eps_in(EPS_HALF, ptop)) {
            set arrow 10 from graph 0, first EPS_HALF to graph 1, first EPS_HALF nohead dt 3 lw 1 lc rgb "#555555" back
        } else { unset arrow 10 }
        if (eps_in(EPS_FLOAT, ptop)) {
            set arrow 11 from graph 0, first EPS_FLOAT to graph 1, first EPS_FLOAT nohead dt 3 lw 1 lc rgb "#555555" back
        } else { unset arrow 11 }
        if (eps_in(EPS_DOUBLE, ptop)) {
            set arrow 12 from graph 0, first EPS_DOUBLE to graph 1, first EPS_DOUBLE nohead dt 3 lw 1 lc rgb "#555555" back
        } else { unset arrow 12 }
        # (gnuplot evaluates an empty iteration's colour once: no bands, no clause)
        if (nb > 0) {
        plot for [b = 1:nb] word(BF, b) using 1:(in_band(b, p) && !off($1) && !hatched(b) ? $2 : 1/0):3 with filledcurves fc rgb word(BC, b) \
                 fs transparent solid 0.22 noborder title (in_band(b, p) && !hatched(b) ? bfield(b, 5) : ""), \
             for [b = 1:nb] word(BF, b) using 1:(in_band(b, p) && !off($1) && hatched(b) ? $2 : 1/0):3 with filledcurves fc rgb word(BC, b) \
                 fs transparent pattern int(word(BS, b)) border lc rgb word(BC, b) title (in_band(b, p) && hatched(b) ? bfield(b, 5) : ""), \
             for [i = 1:n] word(files, i) using 1:(in_panel(i, p) && !off($1) ? column(col) : 1/0) with linespoints \
                 pt int(word(points, i)) ps 0.6 pi 4 lw real(word(widths, i)) lc rgb word(colors, i) dt int(word(dashes, i)) \
                 title (in_panel(i, p) ? title(i) : ""), \
             for [i = 1:n] word(files, i) using 1:(in_panel(i, p) && off($1) ? column(col) : 1/0) with points \
                 pt int(word(points, i)) ps 0.8 lc rgb word(colors, i) notitle, \
             for [i = 1:n] word(files, i) using 1:(in_panel(i, p) && column(4) > 0 ? ceil : 1/0) with points \
                 pt int(word(points, i)) ps 1.2 lc rgb word(colors, i) notitle
        } else {
        plot for [i = 1:n] word(files, i) using 1:(in_panel(i, p) && !off($1) ? column(col) : 1/0) with linespoints \
                 pt int(word(points, i)) ps 0.6 pi 4 lw real(word(widths, i)) lc rgb word(colors, i) dt int(word(dashes, i)) \
                 title (in_panel(i, p) ? title(i) : ""), \
             for [i = 1:n] word(files, i) using 1:(in_panel(i, p) && off($1) ? column(col) : 1/0) with points \
                 pt int(word(points, i)) ps 0.8 lc rgb word(colors, i) notitle, \
             for [i = 1:n] word(files, i) using 1:(in_panel(i, p) && column(4) > 0 ? ceil : 1/0) with points \
                 pt int(word(points, i)) ps 1.2 lc rgb word(colors, i) notitle
        }
    }
    unset multiplot
}
