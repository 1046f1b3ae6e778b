# bars.gp - one bar per method: the largest jump of b1 between
# neighbouring grid cells (a continuous frame field jumps by about the
# cell size; a seam jumps by up to 2).
# Called by plots.sh with: out, ttl, file (lines "name value rgb-as-integer"), yl, cell, here
load here."/style.gp"
set datafile separator whitespace
set style data histograms
set style fill solid 1.0 border -1  # (opaque: each bar in its method's own colour, scripts/palette.txt)
set boxwidth 0.8
set yrange [0:2.45]
set ytics 0, 0.5, 2
last_len = 0
stats file using (last_len = strlen(strcol(1)), $2) nooutput
nb = STATS_records
# (at least 12 slots, the bars centred: a run of few methods keeps bars
# of the usual width, not one slab across the graph)
pad = (nb < 12) ? (12 - nb) / 2.0 : 0
set xrange [-0.7 - pad : nb - 0.3 + pad]
set xtics rotate by -45 nomirror noenhanced
set ylabel yl font F_AXIS
set xlabel "method" font F_AXIS
set title ttl font F_TITLE noenhanced
set key top right opaque noenhanced  # in the band above 2, which no bar reaches
# room below for the rotated names, and at the right for the last one
# (at -45 degrees a name of k characters reaches about 0.71 k to the right)
set bmargin 12
set rmargin (last_len * 0.75 + 2 > 6) ? int(last_len * 0.75 + 2) : 6
do for [term_i = 1:NTERM] {
    eval term(term_i, W_MULTI * 3 / 4, H_SINGLE)
    set output out.ext(term_i)
    plot file using 0:2:(0.8):3:xtic(1) with boxes lc rgb variable notitle, \
         cell with lines dt 2 lw 1.5 lc rgb "#555555" title "the cell size: what b1 jumps where it turns no faster than n"
}
