# Slip speed of a node under the die during the draw step with Coulomb
# friction (thesis Fig. 3.6), beside the Stribeck law updated every cycle
# (Fig. 3.5) on the same case for contrast.
# Variables: outfile, datafile (time_s,speed_coulomb,speed_stribeck_interval_1),
# title_text.
load figdir."/common.gp"
set title title_text
set xlabel "Time in the draw step (s)"
set ylabel "Slip speed (mm/s)"
set key below horizontal center height 1.5 samplen 2  # clear of the x label
plot datafile using 1:3 with lines lw 1 lc rgb "#f4a0a0" title "Stribeck, μ updated every cycle (Fig. 3.5)", \
     datafile using 1:2 with lines ls 1 title "Coulomb"
