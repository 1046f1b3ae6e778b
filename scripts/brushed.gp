# brushed.gp - one method's brushed-metal render (examples/aorender.c
# --brushed): left the image, a grey scale from 0 to 1 beside it; right
# | image - the method's own frame made exact |, on a scale from 0 to
# dmax (larger values saturate), non-finite pixels in cyan.  The title
# names the method and the largest difference; the caption says what to
# look for.
# Called by `make render` with: file (aorender's "x y image reference"),
# out, name, prec, maxd (the largest finite difference), nan (the count of
# non-finite pixels), here
load here."/style.gp"
set datafile separator whitespace
dmax = 0.05
set xrange [-0.5:159.5]
set yrange [-0.5:119.5]
set size ratio -1
unset xtics; unset ytics; unset key; unset border
# (the height the title, four caption lines and two 160x120 images at
# their own aspect need: no blank band between the caption and the images)
W = 1180; H = 458
# what to look for, by method (name comes escaped: "duff\_branchless")
is(m) = (name eq m)
look = (is("duff") || is("duff\\_branchless")) ? "duff's seam: at n.z = 0 its b1 turns by 62 deg, so the ball's lower-right highlight breaks into a V there" : \
       is("hughes\\_moeller") ? "its seam, where |n.x| = |n.z|: the ball's middle highlight kinks there; elsewhere the same as duff's" : \
       (is("frisvad") || is("frisvad\\_max")) ? "no seam on the ball: its lower-right highlight is one smooth arc (duff's breaks); frisvad: the ring on the dome near -z" : \
       (is("naive\\_nonorm") || is("hughes\\_moeller\\_nonorm")) ? "b1 or b2 not unit: the ball's highlights stretched and moved (right: where)" : \
       is("tangent\\_cross\\_z") ? "cyan: NaN on the flat ceiling, n = -z exactly; no seam on the ball: one smooth lower-right arc" : \
       "a seam of the frame (b1 jumping between neighbouring normals) is a line across a highlight"
sub = "{/*0.75 left: the highlight, Ward's lobe, grooves along b1; the camera looks 40 deg off +z}\n" . \
      "{/*0.75 ball: normals far from -z, n.z = 0 on its lower right; right of centre: the dome, within 4e-6 of -z; left edge: the flat ceiling, -z exactly}\n" . \
      "{/*0.75 right: |image - the same method's frame made exact in double|: black for a correct frame; a defect shows as structure}\n" . \
      "{/*0.75 look for: ".look."}"
ttl = sprintf("%s, %s: brushed metal, max |difference| %.3g, %d non-finite pixels", name, prec, maxd, nan)
do for [term_i = 1:NTERM] {
    eval term(term_i, W, H)
    set output out.ext(term_i)
    # (margins that leave room right of each colour bar for its label)
    set multiplot layout 1, 2 title ttl."\n".sub font F_TITLE margins 0.02, 0.86, 20.0 / H, 1 - 118.0 / H spacing 0.15, 0
    set palette grey
    set cbrange [0:1]
    set cbtics 0.25 font F_TICK
    set cblabel "radiance (1: the lobe's peak)" font F_AXIS
    set object 1 rect from graph 0, graph 0 to graph 1, graph 1 behind fc rgb "#00ffff" fs solid 1.0 noborder
    plot file using 1:2:($3 == $3 ? $3 : NaN) with image
    set palette defined (0 "#000000", 1 "#1f3fbf", 2 "#d02020", 3 "#ffe000")
    set cbrange [0:dmax]
    set cbtics ("0" 0, "0.025" 0.025, ">= 0.05" dmax) font F_TICK
    set cblabel "|image - exact frame|; cyan: not finite" font F_AXIS
    plot file using 1:2:(abs($3 - $4) == abs($3 - $4) ? (abs($3 - $4) > dmax ? dmax : abs($3 - $4)) : NaN) with image
    unset multiplot
}
