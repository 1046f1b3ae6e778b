# certify.gp - onbstudy certify's brackets (ratio=0) or their tightness
# (ratio=1), per band of n.z, one slot of equal width per band from -z to
# +z (the x tics give the bands' edges: 1 + n.z near -z, n.z between -0.9
# and 0.9, 1 - n.z near +z; dotted lines where the regions meet, and at the
# seam n.z = 0).  Small multiples: the panels and colours of
# scripts/styles.sh, each panel's key above it.
#   ratio=0: the largest defect found (solid line) and the proven bound
#     (dashed), shaded between: the true maximum lies in the shade; a
#     singular band has no bound: a marker in the "no bound" strip on top
#   ratio=1: bound / found per band (1: the proof is tight), the singular
#     bands in the same strip
# Called by certify-plot.sh with: prec, files (lines "k found bound ratio
# singular"), names, colors, dashes, points, panels, xt (a file setting
# the x tics, nbands, xs1, xs2, xs3), out, ratio,
# here, keys (a file, one line per method: "DUP FILL TITLE": DUP 1 for a
# bracket that repeats an earlier one of its panel, drawn once, under the
# earlier; FILL 0 a translucent shade, else a hatch pattern; the key
# title); optional single=1: one panel of all the files (the README's figure)
load here."/style.gp"
set datafile separator whitespace
load xt
set logscale y
set xrange [0:nbands]
# u of the format: 2^-24 (float), 2^-53 (double), 2^-11 (binary16, half)
uexp = (prec eq "float") ? -24 : ((prec eq "half") ? -11 : -53)
u = 2.0**uexp
n = words(files)
# the y range: from the data (found and bound), and a strip on top for "no bound"
ymin = 1e300; ymax = 0; anysing = 0
# (nvalid(f, c): how many rows of f have a number in column c: a method
# with no bound in any band, physx in half, has none in columns 3 and 4,
# and gnuplot's stats would warn and define nothing)
nvalid(f, c) = int(system(sprintf("awk '$%d != \"nan\" && $%d + 0 > 0 { n++ } END { print n + 0 }' '%s'", c, c, f)))
do for [i = 1:n] {
    stats word(files, i) using 5 nooutput
    if (STATS_max > 0) { anysing = 1 }
    if (nvalid(word(files, i), ratio ? 4 : 2) > 0) {
        stats word(files, i) using (ratio ? $4 : $2) nooutput
        if (STATS_records > 0 && STATS_min < ymin && STATS_min > 0) { ymin = STATS_min }
        if (STATS_records > 0 && STATS_max > ymax) { ymax = STATS_max }
    }
    if (!ratio && nvalid(word(files, i), 3) > 0) {
        stats word(files, i) using 3 nooutput
        if (STATS_records > 0 && STATS_max > ymax) { ymax = STATS_max }
    }
}
# (ratio: at most 100 on the axis; a larger ratio is drawn at 100, the
# tick "100 or more")
RCAP = 100.0
if (ratio) { ymin = 1; ymax = (ymax < 2) ? 2 : (ymax > RCAP ? RCAP : ymax) }
ylo = ratio ? 0.8 : ymin / 4
# y tics by hand: whole decades, at most 8 labels, and "no bound" a decade
# and a half above the data, clear of them
e0 = ceil(log10(ylo)); e1 = ceil(log10(ymax))
estep = ceil((e1 - e0 + 1) / 8.0)
set ytics ()
do for [e = e0:e1] { if (e % estep == 0) { set ytics add ((e == 0 ? "1" : (e == 1 ? "10" : (ratio && 10.0**e >= RCAP ? ">= 100" : sprintf("10^{%d}", e)))) 10.0**e) } }
set mytics 10
ystrip = 10.0**(e1 + (ratio ? 0.6 : 1.5))
yhi = anysing ? ystrip * (ratio ? 2 : 4) : 10.0**e1 * 3
ynosing = 10.0**e1 * 3
set yrange [ylo:yhi]
# (the "no bound" strip, its tick and its room only in the panels that
# have a singular band: set per panel below, SING)
# the run's target: certify's branch and bound stops at 1.25x, certify
# --precision half halves a region while its bound is above 2x
TGT = (prec eq "half") ? 2.0 : 1.25
if (ratio) { set arrow 14 from graph 0, first TGT to graph 1, first TGT nohead dt 3 lw 1 lc rgb "#555555" back }
do for [k = 1:3] {
    xs = (k == 1) ? xs1 : (k == 2) ? xs2 : xs3
    if (xs > 0) { set arrow 20 + k from first xs, graph 0 to first xs, graph 1 nohead dt 2 lw 1 lc rgb "#999999" back }
}
set xtics rotate by 0 font F_TICK
set grid ytics lc rgb "#e0e0e0"
set key outside top center horizontal Left reverse maxcols 3 samplen 2.5 spacing 1.1 width 1 noenhanced
set xlabel "band of n.z: 1 + n.z near -z | n.z from -0.9 to 0.9 (seam at 0) | 1 - n.z near +z" font F_AXIS
kfield(i, k) = system(sprintf("awk -v i=%d -v k=%d 'NR == i { if (k < 3) print $k; else { sub(/^[^ ]+ [^ ]+ /, \"\"); print } }' '%s'", i, k, keys))
DUPS = ""; FILLS = ""
do for [i = 1:words(files)] { DUPS = DUPS." ".kfield(i, 1); FILLS = FILLS." ".kfield(i, 2) }
dup(i) = int(word(DUPS, i))
hatch(i) = int(word(FILLS, i))
# frisvad_rotate's rows are its direction error: the y label of its panel says so
rot = 0
do for [i = 1:words(names)] { if (word(names, i) eq "frisvad_rotate") { rot = i } }
ylab(p) = ratio ? "proven bound / largest defect found" : \
    ((rot > 0 && in_panel(rot, p)) ? "largest defect or direction error, per band" : "orthonormality defect, largest over the band")
if (!exists("single")) single = 0
np = 0
do for [i = 1:n] { if (int(word(panels, i)) > np) { np = int(word(panels, i)) } }
if (single) { np = 1 }
ncols = (np > 1) ? 2 : 1
nrows = (np + ncols - 1) / ncols
in_panel(i, p) = single ? 1 : (int(word(panels, i)) == p)
# SING: one 0/1 per panel, 1 when a method of the panel has a singular band
SING = ""
do for [p = 1:np] {
    sg = 0
    do for [i = 1:n] { if (in_panel(i, p) && int(system(sprintf("awk '$5 > 0 { f = 1 } END { print f + 0 }' '%s'", word(files, i))))) { sg = 1 } }
    SING = SING." ".sg
}
psing(p) = int(word(SING, p))
# the key above each panel: its methods, three to a row
most = 0
do for [p = 1:np] { e = 0; do for [i = 1:n] { if (in_panel(i, p)) { e = e + 1 } }; if (e > most) { most = e } }
set tmargin 2 + 1.25 * ceil(most / (single ? 3.0 : 2.0))
set bmargin 3.5
set lmargin 12
set rmargin 3
W = single ? W_SINGLE : W_MULTI; H = single ? H_SINGLE + 60 : 100 + H_PANEL_ROW * nrows
# steps: each band a slot from k to k + 1
# (column 3 of a step: 1 where the band repeats an earlier bracket, not drawn)
st(c) = sprintf("< awk '{ print $1, $%d, $6; print $1 + 1, $%d, $6; print \"\" }' ", c, c)
# the shade of a band: found, bound, and 1 where it is not drawn (singular,
# or a repeat)
shade(i) = "< awk '{ print $1, $2, $3, $5 + $6; print $1 + 1, $2, $3, $5 + $6; print \"\" }' ".word(files, i)
sub1 = ratio ? sprintf("proven bound / largest defect found, per band (1: tight; the run's target %g, dotted; 100 or more drawn at 100)", TGT) \
             : "largest defect found (solid) <= true maximum (in the shade) <= proven bound (dashed), per band"
# (certify --precision half: a region has no bound where the scan found a
# NaN or an infinity, a value may exceed 65504, or no enclosure exists)
nobound = (prec eq "half") ? "no bound: a band with a non-finite basis, a possible overflow or no enclosure (certify --precision half's status)" \
                           : "no bound: a singular band (the method returns NaN or inf there: no finite bound exists)"
ttl = sprintf("%s: onbstudy certify%s, %s\n{/*0.8 %s; u = 2^{%d}}%s", \
              (prec eq "half") ? "binary16" : prec, (prec eq "half") ? " --precision half" : "", ratio ? "how tight each proof is" : "the proven brackets", sub1, uexp, \
              anysing ? "\n{/*0.8 ".nobound."}" : "")
do for [term_i = 1:NTERM] {
    eval term(term_i, W, H)
    set output out.ext(term_i)
    set multiplot layout nrows, ncols title ttl font F_TITLE
    do for [p = 1:np] {
        set ylabel ylab(p) font F_AXIS
        set ytics ()
        do for [e = e0:e1] { if (e % estep == 0) { set ytics add ((e == 0 ? "1" : (e == 1 ? "10" : (ratio && 10.0**e >= RCAP ? ">= 100" : sprintf("10^{%d}", e)))) 10.0**e) } }
        if (psing(p)) {
            set yrange [ylo:yhi]
            set ytics add ("no bound" ystrip)
            set object 13 rect from graph 0, first ystrip / (ratio ? 1.6 : 2) to graph 1, graph 1 fc rgb C_NONFINITE fs solid 1.0 noborder behind
        } else {
            set yrange [ylo:ynosing]
            unset object 13
        }
        if (ratio) {
        plot for [i = 1:n] st(4).word(files, i) using 1:(in_panel(i, p) && !dup(i) && $3 == 0 ? ($2 > RCAP ? RCAP : $2) : 1/0) with lines lw 2 lc rgb word(colors, i) dt int(word(dashes, i)) title (in_panel(i, p) ? kfield(i, 3) : ""), \
             for [i = 1:n] word(files, i) using ($1 + 0.5):(in_panel(i, p) && $5 > 0 ? ystrip : 1/0) with points pt int(word(points, i)) ps 1.1 lc rgb word(colors, i) notitle
        } else {
        plot for [i = 1:n] st(2).word(files, i) using 1:(in_panel(i, p) && !dup(i) && $3 == 0 ? $2 : 1/0) with lines lw 2 lc rgb word(colors, i) title (in_panel(i, p) ? kfield(i, 3) : ""), \
             for [i = 1:n] shade(i) using 1:(in_panel(i, p) && !dup(i) && !hatch(i) && $4 == 0 ? $2 : 1/0):3 with filledcurves fc rgb word(colors, i) fs transparent solid 0.18 noborder notitle, \
             for [i = 1:n] shade(i) using 1:(in_panel(i, p) && !dup(i) && hatch(i) && $4 == 0 ? $2 : 1/0):3 with filledcurves fc rgb word(colors, i) fs transparent pattern hatch(i) noborder notitle, \
             for [i = 1:n] st(3).word(files, i) using 1:(in_panel(i, p) && !dup(i) && $3 == 0 ? $2 : 1/0) with lines lw 1.5 dt 2 lc rgb word(colors, i) notitle, \
             for [i = 1:n] word(files, i) using ($1 + 0.5):(in_panel(i, p) && $5 > 0 ? ystrip : 1/0) with points pt int(word(points, i)) ps 1.1 lc rgb word(colors, i) notitle
        }
    }
    unset multiplot
}
