# style.gp - the one style of every chart, loaded by every
# scripts/*.gp: canvas sizes, font sizes, the sequential colour map, the
# eps levels and the wording of the axes.  Colours of the methods come from
# scripts/styles.sh (Okabe-Ito hues, one per family, shades within it).
#
# Font sizes (points): title 14, panel titles 12, axis labels 11, ticks and
# keys 10.
FS_TITLE = 14
FS_PANEL = 12
FS_AXIS = 11
FS_TICK = 10
F_TITLE = sprintf(",%d", FS_TITLE)
F_PANEL = sprintf(",%d", FS_PANEL)
F_AXIS = sprintf(",%d", FS_AXIS)
F_TICK = sprintf(",%d", FS_TICK)
# Canvas sizes (pixels): single-panel figures (the README's, one to a row)
# and multi-panel figures (linked from the README, two panels to a row).
W_SINGLE = 1000
H_SINGLE = 620
W_MULTI = 1600
H_PANEL_ROW = 400
# The unit roundoff of each format: eps = 2^-23 (float), 2^-52 (double),
# 2^-10 (binary16, half).
EPS_HALF = 2.0**-10
EPS_FLOAT = 2.0**-23
EPS_DOUBLE = 2.0**-52
# One wording per axis, with units (all errors are relative to a unit
# vector, so unitless).
# (defect: the largest of | |b_i| - 1 | and the dot products; error: the
# defect, or for frisvad_rotate its direction error)
YL_DEFECT = "largest defect per bin (unitless)"
YL_DEFECT_RMS = "RMS defect per bin (unitless)"
YL_ERROR = "largest error per bin (unitless)"
YL_ERROR_RMS = "RMS error per bin (unitless)"
# the sequential colour map of every map (viridis, sampled at 9 points)
set palette defined (0 "#440154", 1 "#472d7b", 2 "#3b528b", 3 "#2c728e", 4 "#21918c", \
    5 "#28ae80", 6 "#5ec962", 7 "#addc30", 8 "#fde725")
set tics font F_TICK
set key font F_TICK
set grid lc rgb "#e0e0e0"
# the non-finite band and the floor band
C_NONFINITE = "#fbe3d4"
C_FLOOR = "#9a9a9a"
# term(i, w, h): the command that opens output i (1: PNG, 2: SVG) of a
# chart; use: eval term(term_i, W, H); set output out.ext(term_i)
term(i, w, h) = (i == 1) ? sprintf("set terminal pngcairo size %d,%d font 'sans,%d'", w, h, FS_TICK) \
                         : sprintf("set terminal svg size %d,%d font 'sans,%d'", w, h, FS_TICK)
ext(i) = (i == 1) ? ".png" : ".svg"
# how many outputs: PNG only when nosvg=1 is passed
if (!exists("nosvg")) nosvg = 0
NTERM = nosvg ? 1 : 2
# xbreak(x, lo, hi): the commands (for eval) that mark a break in a log x
# axis from lo to hi at x: a gap in the bottom and top borders with two
# slanted strokes, between a slot (the "-z" or "t = -1" tick, a decade
# left of the first point) and the data; no line is drawn across it
xbreak(x, lo, hi) = sprintf("XBF = (%g / %g) ** 0.005; XB = %g; ", hi, lo, x) . \
    "set object 95 rect from first XB / XBF, graph -0.015 to first XB * XBF, graph 0.015 fc rgb 'white' fs solid 1.0 noborder front; " . \
    "set object 96 rect from first XB / XBF, graph 0.985 to first XB * XBF, graph 1.015 fc rgb 'white' fs solid 1.0 noborder front; " . \
    "set arrow 95 from first XB / XBF ** 2, graph -0.02 to first XB / XBF ** 0.5, graph 0.02 nohead lw 1 lc rgb '#000000' front; " . \
    "set arrow 96 from first XB * XBF ** 0.5, graph -0.02 to first XB * XBF ** 2, graph 0.02 nohead lw 1 lc rgb '#000000' front; " . \
    "set arrow 97 from first XB / XBF ** 2, graph 0.98 to first XB / XBF ** 0.5, graph 1.02 nohead lw 1 lc rgb '#000000' front; " . \
    "set arrow 98 from first XB * XBF ** 0.5, graph 0.98 to first XB * XBF ** 2, graph 1.02 nohead lw 1 lc rgb '#000000' front"
