# Section of the strip nearest mid-wrap at the end of the draw (thesis
# Fig. 2.8): the mesh lines of the half width, current position across the
# width against the current distance from the pin surface, on the chapter
# mesh and the finer one; the pin surface is h = 0.
# Variables: outfile, datafile (gnuplot blocks y_mm h_mm; index 0 chapter
# mesh, index 1 finer mesh), thickness (mm, as text).
load figdir."/common.gp"
eval figterm(720, 360, 14)
set output outfile
set datafile separator whitespace
set key autotitle
set title "Section of the strip at mid-wrap, 12.7 mm pin, μ = 0.1 (Fig. 2.8)"
set xlabel "y across the half width from the strip centre (mm)"
set ylabel "Distance from the pin surface (mm)"
set key below horizontal
t = thickness + 0.0
set yrange [-0.25 * t : 1.35 * t]
set arrow from graph 0, first 0 to graph 1, first 0 nohead lw 3 lc rgb "#555555"
set label "pin surface" at graph 0.02, first -0.12 * t tc rgb "#555555"
plot datafile index 0 using 1:2 with linespoints ls 1 ps 0.6 title "chapter mesh", \
     datafile index 1 using 1:2 with lines ls 2 dt 2 title "finer mesh"
