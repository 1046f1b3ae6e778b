# certify.gp - the bracket of each method's defect against 1 + n.z (log):
# a band from the largest defect found (solid line) to the proven bound
# (dashed), per band of n.z; singular bands draw no bound.  Four panels of
# related methods; the accuracy floor (the exact formula rounded once) in
# grey.  Called by certify-plot.sh with dir, prec, out.
set datafile separator whitespace
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
u = (prec eq "float") ? 2.0**-24 : 2.0**-53
set xrange [(prec eq "float") ? 1e-8 : 1e-17 : 2]
set yrange [u / 8 : 4]
set grid lc rgb "#dddddd"
set style fill transparent solid 0.25 noborder
set key inside left top font ",10" samplen 2 spacing 1.1 opaque box lc rgb "#bbbbbb"
set xlabel "1 + n.z" font ",11"
set ylabel "orthonormality defect (max over the band)" font ",11"
# Okabe-Ito: two methods per panel, orange and blue; a third in bluish green
hues = "#E69F00 #0072B2 #009E73"
# the panels' methods; `have` (from certify-plot.sh) lists the methods of
# this run, each between spaces
g1 = "frisvad frisvad_max"; g2 = "duff duff_branchless"
g3 = "hughes_moeller pbrt_v3 stark_fixed"; g4 = "naive rtow tangent_cross_z"
f(m) = dir."/".m.".".prec
step(file, col) = sprintf("< awk '{ print $1, $%d; print $2, $%d }' %s", col, col, file)
band(file) = sprintf("< awk '{ print $1, $3, ($4 < 1e299 ? $4 : 1/0); print $2, $3, ($4 < 1e299 ? $4 : 1/0) }' %s", file)
do for [t = 1:2] {
  if (t == 1) { set terminal pngcairo size 1400,1000 font ",10"; set output out.".png" }
  if (t == 2) { set terminal svg size 1400,1000 font "sans,10"; set output out.".svg" }
  set multiplot layout 2,2 title sprintf("Proven brackets, %s: largest defect found (solid) <= true maximum <= certified bound (dashed), per band of n.z\n{/*0.8 onbstudy certify; u = 2^{%d}; grey: the accuracy floor (exact formula rounded once, duff\\_branchless); no bound where the method is singular}", prec, (prec eq "float") ? -24 : -53) font ",13"
  do for [g = 1:4] {
    grp = (g == 1) ? g1 : (g == 2) ? g2 : (g == 3) ? g3 : g4
    ms = ""
    do for [k = 1:words(grp)] { if (strstrt(have, " ".word(grp, k)." ") > 0) { ms = ms." ".word(grp, k) } }
    n = words(ms)
    tit = word(grp, 1)
    do for [k = 2:words(grp)] { tit = tit.", ".word(grp, k) }
    set title tit noenhanced font ",12"
    if (n == 0) {
      set label 1 "none of these methods in this run" at graph 0.5, 0.5 center font ",11"
      plot dir."/floor.".prec using 1:2 with lines lw 5 lc rgb "#c8c8c8" title "floor"
      unset label 1
    } else {
      plot dir."/floor.".prec using 1:2 with lines lw 5 lc rgb "#c8c8c8" title "floor", \
           for [k = 1:n] band(f(word(ms, k))) using 1:2:3 with filledcurves fc rgb word(hues, k) notitle, \
           for [k = 1:n] step(f(word(ms, k)), 3) using 1:2 with lines lw 2 lc rgb word(hues, k) title word(ms, k) noenhanced, \
           for [k = 1:n] step(f(word(ms, k)), 4) using 1:($2 < 1e299 ? $2 : 1/0) with lines lw 2 dt 2 lc rgb word(hues, k) notitle
    }
  }
  unset multiplot
}
