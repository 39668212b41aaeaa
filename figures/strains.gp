# Longitudinal strain of a strip section on its inside (contact) and outside
# surfaces as it slides round the pin (thesis Figs. 2.11-2.12, 2.17).
# Variables: outfile, datafile (slide_mm, strain_inside, strain_outside).
load figdir."/common.gp"
set title "Inside and outside strain of a section passing the pin, 12.7 mm pin, μ = 0.1"
set xlabel "Slide in the draw step (mm)"
set ylabel "Longitudinal log strain"
set key below horizontal center height 1.5 samplen 2  # clear of the x label
plot datafile using 1:2 with lines ls 1 title "inside (contact side)", \
     datafile using 1:3 with lines ls 2 title "outside (free side)"
