# map.gp - error maps over the sphere: one panel per method, in the
# equal-area (Lambert cylindrical) projection of the grid distribution:
# x = azimuth, y = n.z, so equal areas on the sphere are equal areas here.
# One sequential colour bar (viridis, style.gp) for all panels, at the
# right: the defect in units of u (uname: "u = 2^{-24}" or 2^{-53}), so
# that the accurate methods' own structure (their seams) shows; a defect of
# 64u or more saturates.  A file "-" draws its panel empty, titled, with
# the note blank (a method with no rows in this precision: "no double
# rows"), so panels sit where they sit in the other.
# Called by plots.sh with: out, ttl, files, names, cbmin, cbmax, uname,
# ncols, nrows, here, note (what the grid's resolution can and cannot show),
# blank (the note of an empty panel); optional dirnames (the methods whose
# rows are a direction error)
load here."/style.gp"
set datafile separator whitespace
set xrange [0:360]
set yrange [-1:1]
set cbrange [cbmin:cbmax]
set xtics 90
set ytics 0.5
# the colour: log2 of the defect in units of u, from 1/4 u to 64 u (the
# top saturates: every larger defect)
set cbtics ("1/4 u (or 0)" -2, "1/2 u" -1, "u" 0, "2u" 1, "4u" 2, "8u" 3, "16u" 4, "32u" 5, ">= 64u" 6)
set tics scale 0.5
unset grid
set object 20 rect from graph 0, graph 0 to graph 1, graph 1 behind fc rgb "#e8e8e8" fs solid 1.0 noborder
unset key
n = words(files)
last = 0
do for [i = 1:n] { if (word(files, i) ne "-") { last = i } }
W = W_MULTI
H = (nrows > 1) ? 150 + 250 * nrows : 480  # (one row: room for the colour-bar label)
do for [term_i = 1:NTERM] {
    eval term(term_i, W, H)
    set output out.ext(term_i)
    set multiplot layout nrows,ncols title ttl."\n{/*0.8 ".note."}" font F_TITLE margins 0.06, 0.86, 70.0/H, 1 - 100.0/H spacing 0.04, 80.0/H
    set label 901 "x: azimuth (degrees); y: n.z of the input" at screen 0.06, screen 20.0/H left font F_AXIS
    do for [i = 1:n] {
        # (a method whose rows are a direction error, not the defect the
        # colour bar names: dirnames, from plots.sh, says so in its title)
        set title word(names, i).((exists("dirnames") && strstrt(" ".dirnames." ", " ".word(names, i)." ") > 0) ? " (direction error)" : "") font F_PANEL offset 0,-0.5 noenhanced
        if (word(files, i) eq "-") {
            # a method with no rows here: its panel keeps its place, its
            # name and says so (white, not the grey of a non-finite cell)
            unset colorbox; unset object 20
            set label 902 (exists("blank") ? blank : "no rows") at graph 0.5, graph 0.5 center font F_AXIS
            plot -5 notitle
            unset label 902; unset label 901
            set object 20 rect from graph 0, graph 0 to graph 1, graph 1 behind fc rgb "#e8e8e8" fs solid 1.0 noborder
            continue
        }
        if (i == last) {
            set colorbox user origin screen 0.9, screen 0.12 size screen 0.018, screen 1 - 250.0/H
            set cblabel (nrows > 1 ? "orthonormality defect in units of ".uname." (one scale for all; light grey: non-finite)" : "defect in units of ".uname."; light grey: non-finite") font F_AXIS offset 1.5,0
        } else { unset colorbox }
        # a non-finite cell leaves the light grey background
        plot word(files, i) using 1:2:(strcol(3) eq "nan" ? NaN : $3) with image
        unset label 901
    }
    unset multiplot
}
