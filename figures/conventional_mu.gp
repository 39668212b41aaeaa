# Conventional friction coefficient (Eq. 5.1) against pin diameter, one line per
# sliding speed (thesis Figs. 5.19, 5.20, 5.30).
# Variables: outfile, datafile (pin_mm,v6.35,v25.4,v101.6), dir.
load figdir."/common.gp"
set title "Conventional friction coefficient, ".dir." strips"
set xlabel "Pin diameter (mm)"
set ylabel "μ by Eq. (5.1)"
set xrange [8:46]
set key below horizontal center height 1.5 samplen 2  # clear of the x label
set yrange [0:*]
plot datafile using 1:2 with linespoints ls 1 title "6.35 mm/s", \
     ''       using 1:3 with linespoints ls 2 title "25.4 mm/s", \
     ''       using 1:4 with linespoints ls 3 title "101.6 mm/s"
