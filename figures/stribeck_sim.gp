# Input Stribeck curve and the friction coefficients our solver reproduces in
# the strip-draw simulations (thesis Fig. 3.8).
# Variables: outfile, curvefile (L,mu_table_3_1,...), simfile (case,...,L,mu_input,mu_simulated,...).
load figdir."/common.gp"
set title "Strip-draw verification of the Stribeck law"
set logscale x
set format x "10^{%L}"
set xlabel "Lubricant number L = vη/(p R_a)" enhanced
set ylabel "μ"
set yrange [0:0.12]
set key top right
plot curvefile using 1:2 with lines ls 1 title "input curve (Table 3.1)", \
     simfile using 4:6 with points ls 2 pt 7 ps 1.6 title "simulated, Table 3.2 cases"
