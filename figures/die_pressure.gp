# Pressure under the flat die of the strip-draw test over the strip's top
# face (thesis Fig. 3.4; Fig. 3.3 is the same map before the thesis's
# contact fix), one cell per node; the colour range is the data's own, so
# that a spread of a few percent shows.
# Variables: outfile, gridfile (x_mm,y_mm,pressure_MPa blocks), title_text.
load figdir."/common.gp"
eval figterm(720, 400, 14)
set output outfile
set key noautotitle  # the grid file has no header line: keep its first row
unset key
set title title_text
set xlabel "x along the strip (mm)"
set ylabel "y from the strip's centre plane (mm)"
set cblabel "Pressure (MPa)"
set size ratio -1
set palette defined (0 "white", 0.15 "#fde0a0", 0.4 "#f08030", 0.7 "#c02020", 1 "#400010")
plot gridfile using 1:2:3 with image pixels
