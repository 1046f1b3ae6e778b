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
set key inside left top font ",10" samplen 2 spacing 1.1 opaque box lc rgb "#bbbbbb"
set xlabel "1 + n.z" font ",11"
set ylabel "orthonormality defect (max over the band)" font ",11"
# Okabe-Ito: two methods per panel, orange and blue; a third in bluish green
c1 = "#E69F00"; c2 = "#0072B2"; c3 = "#009E73"
panel(a, b, c, t) = 0
f(m) = dir."/".m.".".prec
step(file, col) = sprintf("< awk '{ print $1, $%d; print $2, $%d }' %s", col, col, file)
band(file) = sprintf("< awk '{ print $1, $3, ($4 < 1e299 ? $4 : 1/0); print $2, $3, ($4 < 1e299 ? $4 : 1/0) }' %s", file)
do for [t = 1:2] {
  if (t == 1) { set terminal pngcairo size 1400,1000 font ",10"; set output out.".png" }
  if (t == 2) { set terminal svg size 1400,1000 font "sans,10"; set output out.".svg" }
  set multiplot layout 2,2 title sprintf("Proven brackets, %s: largest defect found (solid) <= true maximum <= certified bound (dashed), per band of n.z\n{/*0.8 onbstudy certify; u = 2^{%d}; grey: the accuracy floor (exact formula rounded once, duff\\_branchless); no bound where the method is singular}", prec, (prec eq "float") ? -24 : -53) font ",13"
  groups = "frisvad,frisvad_max duff,duff_branchless hughes_moeller,pbrt_v3,stark_fixed naive,rtow,tangent_cross_z"
  do for [g = 1:4] {
    grp = word(groups, g)
    m1 = grp[1:strstrt(grp, ",") - 1]
    rest = grp[strstrt(grp, ",") + 1:]
    m2 = (strstrt(rest, ",") > 0) ? rest[1:strstrt(rest, ",") - 1] : rest
    m3 = (strstrt(rest, ",") > 0) ? rest[strstrt(rest, ",") + 1:] : ""
    set title sprintf("%s", grp) font ",12" noenhanced
    plot dir."/floor.".prec using 1:2 with lines lw 5 lc rgb "#c8c8c8" title "floor", \
         band(f(m1)) using 1:2:3 with filledcurves fc rgb c1 fs transparent solid 0.25 noborder notitle, \
         step(f(m1), 3) using 1:2 with lines lw 2 lc rgb c1 title m1 noenhanced, \
         step(f(m1), 4) using 1:($2 < 1e299 ? $2 : 1/0) with lines lw 2 dt 2 lc rgb c1 notitle, \
         band(f(m2)) using 1:2:3 with filledcurves fc rgb c2 fs transparent solid 0.25 noborder notitle, \
         step(f(m2), 3) using 1:2 with lines lw 2 lc rgb c2 title m2 noenhanced, \
         step(f(m2), 4) using 1:($2 < 1e299 ? $2 : 1/0) with lines lw 2 dt 2 lc rgb c2 notitle, \
         (m3 ne "" ? band(f(m3)) : "< true") using 1:2:3 with filledcurves fc rgb c3 fs transparent solid 0.25 noborder notitle, \
         (m3 ne "" ? step(f(m3), 3) : "< true") using 1:2 with lines lw 2 lc rgb c3 title (m3 ne "" ? m3 : "") noenhanced, \
         (m3 ne "" ? step(f(m3), 4) : "< true") using 1:($2 < 1e299 ? $2 : 1/0) with lines lw 2 dt 2 lc rgb c3 notitle
  }
  unset multiplot
}
