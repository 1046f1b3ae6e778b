# ao.gp - one method's ambient-occlusion render (examples/aorender.c, the
# default scene) as a chart: left the image on a grey scale from 0 to 1,
# right | image - the double reference | (aorender --diff, duff_branchless
# in double) on a scale from 0 to 0.05 (larger values saturate), NaN
# pixels in cyan; the title names the method and the largest difference,
# the caption says what the scene is and what to look for.  Without diff
# (the reference itself) the image alone; without grey (a method whose
# image looks the same as the reference's: the Makefile's RENDER_GREY
# names the others) the difference alone.
# Called by `make render` with: grey (aorender's --out PNG, 480x360; ''
# for none), diff (its --diff PNG: the image over a 58-row legend strip,
# cropped here; '' for none), out, name (escaped: "duff\_branchless"),
# prec, and from aorender's summary line maxd, over (pixels above 0.025),
# nan; here
load here."/style.gp"
if (!exists("diff")) diff = ""
if (!exists("grey")) grey = ""
one = (diff eq "")
np = (grey ne "") + (diff ne "")
# (two images side by side: the height the title, four caption lines and
# two 480x360 images at their own aspect need, no blank band above them)
W = (np == 1) ? 960 : 1180; H = (np == 1) ? 540 : 468
is(m) = (name eq m)
look = one ? "every float render of this page is compared with this image" : \
       (nan > 0 ? sprintf("cyan: %d NaN pixels%s%s", nan, is("tangent\\_cross\\_z") ? ", the flat ceiling at n = -z exactly" : "", grey ne "" ? " (black in the image)" : "") : \
       (over > 0 ? sprintf("the %d pixels above 0.025 (red to yellow)%s", over, (is("frisvad") ? ": a ring where 1 + n.z is a few float ulps" : "")) : \
       (maxd == 0 ? "black: the same image as the reference (its own frame)" : \
       ((is("pbrt\\_v3") || is("stark") || is("stark\\_fixed")) ? "an hourglass of faint speckle: the frame field's orientation differs from the reference's, not a defect" : \
       ((is("naive\\_nonorm") || is("hughes\\_moeller\\_nonorm")) ? "little: occlusion barely sees a frame that is not unit (the brushed render shows it)" : \
       "faint speckle at most, where the frame field turns samples otherwise; a defect this small does not show")))))
scene = "ambient occlusion, looking up at a shallow dome (centre: within 1e-5 of -z) and a flat ceiling (n = -z exactly)"
dtext = "|image - duff\\_branchless in double|: a frame turned about n sends the same samples elsewhere,"
dtext2 = "so noise marks where this frame field differs from the reference's"
sub = (np == 2 ? "{/*0.75 left: ".scene."}\n{/*0.75 right: ".dtext."}\n{/*0.75 ".dtext2."}\n" : \
      (one ? "{/*0.75 ".scene."}\n" : "{/*0.75 ".scene."}\n{/*0.75 ".dtext."}\n{/*0.75 ".dtext2."}\n")) . \
      "{/*0.75 look for: ".look."}"
ttl = one ? sprintf("%s, %s: the reference of the ambient-occlusion renders", name, prec) : \
      sprintf("%s, %s: ambient occlusion, max |image - reference| %.3g, %d NaN pixels", name, prec, maxd, nan)
set datafile separator whitespace
unset xtics; unset ytics; unset key; unset border
set size ratio -1
do for [term_i = 1:NTERM] {
    eval term(term_i, W, H)
    set output out.ext(term_i)
    # (margins that leave room right of each colour bar for its label)
    if (np == 2) { set multiplot layout 1, 2 title ttl."\n".sub font F_TITLE margins 0.02, 0.86, 20.0 / H, 1 - 120.0 / H spacing 0.15, 0 } else { set multiplot layout 1, 1 title ttl."\n".sub font F_TITLE margins 0.12, 0.74, 0.04, 0.78 }
    if (grey ne "") {
    set palette grey
    set cbrange [0:1]
    set cbtics 0.25 font F_TICK
    set cblabel "ambient occlusion (1: unoccluded)" font F_AXIS
    set xrange [-0.5:479.5]; set yrange [-0.5:359.5]
    # (the image's own colours; an off-range point draws the grey scale's bar)
    plot grey binary filetype=png with rgbimage, '+' using (-100):(-100):(0) with points palette
    }
    if (!one) {
        set palette defined (0 "#000000", 1 "#0000ff", 2 "#ff0000", 3 "#ffff00")
        set cbrange [0:0.05]
        set cbtics ("0" 0, "0.025" 0.025, ">= 0.05" 0.05) font F_TICK
        set cblabel "|image - reference|; cyan: NaN" font F_AXIS
        # the diff PNG's image rows (its legend strip, rows 0 to 57 from
        # the bottom, left out)
        set yrange [57.5:417.5]
        plot diff binary filetype=png with rgbimage, '+' using (-100):(-100):(0) with points palette
    }
    unset multiplot
}
