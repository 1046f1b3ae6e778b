# polecap.gp - the southern cap near n = -z, in (azimuth, log10(1 + n.z)):
# one panel per method (polecap.sh's polecap.csv), the colour the log10 of
# the orthonormality defect on one sequential scale (viridis), eps marked
# on the bar, non-finite output in its own colour, and the thresholds of
# Frisvad 2012 and Max 2017 drawn across (the failure band of Frisvad's
# formula lies just above its threshold).
# Called by plots.sh with: out, ttl, files (one per panel, lines "azimuth
# log10(1+n.z) half-width half-height log10(defect)|nan", a regular grid
# row by row), names, cbmin,
# cbmax, ymin, ymax, tfris, tmax (where the two thresholds fall on the
# axis, 1 + n.z before rounding: below it the float n.z is below t; 0: none),
# here; optional single=1 (the README's figure: W_SINGLE wide)
load here."/style.gp"
set datafile separator whitespace
set xrange [0:360]
set yrange [ymin:ymax]
set cbrange [cbmin:cbmax]
set xtics 90
set ytics 1
set format y "10^{%.0f}"
# (whole decades, none within 0.45 of an eps mark, so no two collide)
cbstep = ceil((cbmax - cbmin) / 8.0)
set cbtics ()
do for [k = int(cbmin):int(cbmax)] {
    if (k % cbstep == 0 && abs(k - log10(EPS_FLOAT)) > 0.45 && abs(k - log10(EPS_DOUBLE)) > 0.45) { set cbtics add (sprintf("%d", k) k) }
}
if (log10(EPS_FLOAT) > cbmin) set cbtics add ("float eps" log10(EPS_FLOAT))
if (log10(EPS_DOUBLE) > cbmin) set cbtics add ("double eps" log10(EPS_DOUBLE))
set tics scale 0.5
unset grid
set object 20 rect from graph 0, graph 0 to graph 1, graph 1 behind fc rgb "#e8e8e8" fs solid 1.0 noborder
unset key
if (!exists("single")) single = 0
n = words(files)
W = single ? W_SINGLE : W_MULTI
H = single ? H_SINGLE : 640
do for [term_i = 1:NTERM] {
    eval term(term_i, W, H)
    set output out.ext(term_i)
    set multiplot layout 1, n title ttl font F_TITLE margins 0.08, 0.84, 0.16, 0.84 spacing (single ? 0.1 : 0.06), 0
    do for [i = 1:n] {
        set title word(names, i) font F_PANEL noenhanced
        set xlabel "azimuth (degrees)" font F_AXIS
        set ylabel (i == 1 ? "1 + n.z of the input (before rounding to float)" : "1 + n.z") font F_AXIS
        unset arrow; unset label
        # the lines' key, under the panels, off the data
        if (i == 1 && (tfris > 0 || tmax > 0)) {
            set label 90 "white lines: ".(tfris > 0 ? "dashed, Frisvad 2012's t" : "").(tfris > 0 && tmax > 0 ? "; " : "").(tmax > 0 ? "dotted, Max 2017's t" : "")." (below a line the float n.z is below t: the fallback branch)" at screen 0.46, screen 0.03 center font F_TICK
        }
        if (tfris > 0) {
            set arrow 1 from 0, log10(tfris) to 360, log10(tfris) nohead lw 1.5 dt 2 lc rgb "#ffffff" front
        }
        if (tmax > 0) {
            set arrow 2 from 0, log10(tmax) to 360, log10(tmax) nohead lw 1.5 dt 3 lc rgb "#ffffff" front
        }
        if (i == n) {
            set colorbox user origin screen 0.87, screen 0.16 size screen 0.018, screen 0.68
            set cblabel "log10 of the orthonormality defect (float; light grey: non-finite)" font F_AXIS offset 1,0
        } else { unset colorbox }
        # a regular grid (log-spaced d, even azimuths): drawn as an image,
        # pixel-exact; a non-finite cell leaves the grey background
        plot word(files, i) using 1:2:(strcol(5) eq "nan" ? NaN : $5) with image
    }
    unset multiplot
}
