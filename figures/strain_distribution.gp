# Steady distribution of the outside and inside longitudinal strain along the
# strip (thesis Fig. 2.13), 12.7 mm pin, mu = 0.1, on the chapter's mesh and
# the finer one.  The contact lies between the entry tangent (0) and the exit
# tangent (wrap length).  Variables: outfile, datafile (position_mm,
# fraction_of_wrap, outside_strain, outside_strain_fine; tracked sections),
# insidefile and insidefinefile (position_mm, inside_strain; element layer
# nearest the pin in the last snapshot), wrapfile (the wrap length in mm, as
# text).
load figdir."/common.gp"
set title "Steady strain along the strip, 12.7 mm pin, μ = 0.1 (Fig. 2.13)"
set xlabel "Position along the strip from the entry tangent (mm)"
set ylabel "Longitudinal log strain"
set key below horizontal height 1.5  # a gap between the x label and the key
Lw = wrapfile + 0.0
set arrow from 0, graph 0 to 0, graph 1 nohead dt 2 lc rgb "#777777"
set arrow from Lw, graph 0 to Lw, graph 1 nohead dt 2 lc rgb "#777777"
set xrange [-Lw : 2 * Lw]
plot datafile using 1:3 with linespoints ls 1 title "outside, chapter mesh", \
     datafile using 1:4 with linespoints ls 2 title "outside, finer mesh", \
     insidefile using 1:2 with linespoints ls 3 title "inside, chapter mesh", \
     insidefinefile using 1:2 with linespoints ls 4 title "inside, finer mesh"
