# Outside strain of the strip section at mid-wrap and at the exit tangent
# against the slide (thesis Sec. 2.3.2, the steady strain condition).
# Variables: outfile, datafile (slide_mm, strain at mid-wrap, strain at exit).
load figdir."/common.gp"
set datafile missing ""
set title "Outside strain where the strip is, against the slide, 12.7 mm pin, μ = 0.1"
set xlabel "Slide in the draw step (mm)"
set ylabel "Outside log strain"
set key below horizontal center height 1.5 samplen 2  # clear of the x label
plot datafile using 1:2 with linespoints ls 1 title "section at mid-wrap", \
     datafile using 1:3 with linespoints ls 2 title "section at the exit tangent"
