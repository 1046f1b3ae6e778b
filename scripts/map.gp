# map.gp - error maps over the sphere: one panel per method, in the
# equal-area (Lambert cylindrical) projection of the grid distribution:
# x = azimuth, y = n.z, so equal areas on the sphere are equal areas here.
# Called by plots.sh with: out, ttl, files, names, cbmin, cbmax, ncols, nrows
set datafile separator whitespace
set xrange [0:360]
set yrange [-1:1]
set cbrange [cbmin:cbmax]
set palette defined (0 "#000033", 1 "#2c7fb8", 2 "#7fcdbb", 3 "#ffffbf", 4 "#fdae61", 5 "#d7191c", 6 "#67000d")
set xtics 90 font ",7"
set ytics 0.5 font ",7"
set tics scale 0.5
unset key
n = words(files)
do for [term_i = 1:2] {
    if (term_i == 1) { set terminal pngcairo size 1500,1000 font ",9"; set output out.".png" }
    if (term_i == 2) { set terminal svg size 1500,1000 font "sans,9"; set output out.".svg" }
    set multiplot layout nrows,ncols title ttl font ",12"
    do for [i = 1:n] {
        set title word(names, i) font ",9" offset 0,-0.6 noenhanced
        set xlabel "azimuth (degrees)" font ",7" offset 0,0.8
        set ylabel "n.z" font ",7" offset 1.5,0
        set colorbox
        set cblabel "log10 error" font ",7"
        plot word(files, i) using 1:2:3 with image
    }
    unset multiplot
}
