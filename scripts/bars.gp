# bars.gp - one bar per method: the largest jump of b1 between
# neighbouring grid cells (a continuous frame field jumps by about the
# cell size; a seam jumps by up to 2).
# Called by plots.sh with: out, ttl, file (lines "name value rgb-as-integer"), yl, cell
set datafile separator whitespace
set style data histograms
set style fill solid 0.8 border -1
set boxwidth 0.8
set yrange [0:2.45]
set ytics 0, 0.5, 2
set xtics rotate by -45 font ",8" nomirror noenhanced
set ylabel yl
set title ttl
set grid ytics lc rgb "#dddddd"
set key top right font ",9" opaque  # in the band above 2, which no bar reaches
do for [term_i = 1:2] {
    if (term_i == 1) { set terminal pngcairo size 1100,560 font ",10"; set output out.".png" }
    if (term_i == 2) { set terminal svg size 1100,560 font "sans,10"; set output out.".svg" }
    plot file using 0:2:(0.8):3:xtic(1) with boxes lc rgb variable notitle, \
         cell with lines dt 2 lc rgb "#555555" title "the cell size: what a continuous frame field jumps"
}
