# empty.gp - a chart whose series are all empty in this run (no input of
# the distributions it plots): its frame, title and axis labels, and in
# its middle a note that says why it is empty, so that a small run gets a
# chart that tells the truth rather than a missing file.
# Called by plots.sh with: out, ttl, xl, yl (or yl_key), note, here;
# optional single=1 (the README figures' width).
load here."/style.gp"
if (exists("yl_key")) yl = value(yl_key)
if (!exists("single")) single = 0
W = single ? W_SINGLE : W_MULTI
H = single ? H_SINGLE : 90 + H_PANEL_ROW
set xrange [0:1]
set yrange [0:1]
unset xtics
unset ytics
unset key
set xlabel xl font F_AXIS
set ylabel yl font F_AXIS
set label 1 note at graph 0.5, 0.5 center font F_AXIS noenhanced
set lmargin 14
set rmargin 10
set bmargin 3.5
set xlabel offset 0, -1
do for [term_i = 1:NTERM] {
    eval term(term_i, W, H)
    set output out.ext(term_i)
    set title ttl font F_TITLE noenhanced
    plot NaN notitle
}
