# Outside strain of the section at mid-wrap against the slide (thesis
# Sec. 2.3.2, the steady strain condition).
# Variables: outfile, datafile (slide_mm, outside_strain_at_mid_wrap).
load figdir."/common.gp"
set title "Outside strain at mid-wrap against the slide, 12.7 mm pin, μ = 0.1"
set xlabel "Slide in the draw step (mm)"
set ylabel "Outside log strain at mid-wrap"
unset key
plot datafile using 1:2 with linespoints ls 2
