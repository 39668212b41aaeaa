# Slip speed of a node under the die during the draw step with mu updated every
# cycle and every 100 cycles (thesis Figs. 3.5 and 3.7).
# Variables: outfile, datafile (time_s,speed_interval_1,speed_interval_100).
load figdir."/common.gp"
set title "Nodal sliding speed, Stribeck law, 10 MPa, 8 mm/s"
set xlabel "Time in the draw step (s)"
set ylabel "Slip speed (mm/s)"
set key below horizontal center height 1.5 samplen 2  # clear of the x label
plot datafile using 1:2 with lines ls 2 title "μ updated every cycle", \
     datafile using 1:3 with lines ls 1 title "μ from the speed averaged over 100 cycles"
