# map.gp - error maps over the sphere: one panel per method, in the
# equal-area (Lambert cylindrical) projection of the grid distribution:
# x = azimuth, y = n.z, so equal areas on the sphere are equal areas here.
# One colour bar for all panels (the same scale everywhere), at the right.
# Called by plots.sh with: out, ttl, files, names, cbmin, cbmax, ncols, nrows
set datafile separator whitespace
set xrange [0:360]
set yrange [-1:1]
set cbrange [cbmin:cbmax]
set palette defined (0 "#000033", 1 "#2c7fb8", 2 "#7fcdbb", 3 "#ffffbf", 4 "#fdae61", 5 "#d7191c", 6 "#67000d")
set xtics 90 font ",9"
set ytics 0.5 font ",9"
set cbtics 1 font ",10"
set tics scale 0.5
unset key
n = words(files)
W = 1500
H = 110 + 230 * nrows
do for [term_i = 1:2] {
    if (term_i == 1) { set terminal pngcairo size W,H font ",10"; set output out.".png" }
    if (term_i == 2) { set terminal svg size W,H font "sans,10"; set output out.".svg" }
    set multiplot layout nrows,ncols title ttl font ",13" margins 0.05, 0.89, 60.0/H, 1 - 70.0/H spacing 0.035, 75.0/H
    set label 901 "x: azimuth (degrees); y: n.z" at screen 0.05, screen 18.0/H left font ",10"
    do for [i = 1:n] {
        set title word(names, i) font ",11" offset 0,-0.5 noenhanced
        if (i == n) {
            set colorbox user origin screen 0.915, screen 0.15 size screen 0.018, screen 0.7
            set cblabel "log10 of the defect (the same scale in every panel)" font ",11"
        } else { unset colorbox }
        plot word(files, i) using 1:2:3 with image
        unset label 901
    }
    unset multiplot
}
