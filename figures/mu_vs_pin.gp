# Friction coefficient retrieved by the conventional method (Eq. 2.3) against
# pin diameter, Coulomb 0.1 and Stribeck inputs at 10 MPa (thesis Fig. 3.13).
# Variables: outfile, datafile (drawbend_10mpa.csv: pin_mm col 1, mu_coulomb
# col 8, mu_stribeck col 9, mu_stribeck_curve_at_P_avg col 10).
load figdir."/common.gp"
set title "Conventional μ against pin diameter, 10 MPa average pressure"
set xlabel "Pin diameter (mm)"
set ylabel "Friction coefficient μ (Eq. 2.3)"
set key below horizontal center height 1.5 samplen 2  # clear of the x label
set xrange [8:42]
plot datafile using 1:8 with linespoints ls 1 title "Coulomb input 0.1", \
     datafile using 1:9 with linespoints ls 2 title "Stribeck input (Table 3.3)", \
     datafile using 1:10 with points ls 3 title "Stribeck curve at the run's P_{avg}" enhanced, \
     0.1 with lines ls 4 dt 2 title "Coulomb input"
