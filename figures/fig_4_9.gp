# Conventional friction coefficient (Eq. 2.3) from the Stribeck simulations of
# Table 4.2 against pin diameter (thesis Fig. 4.9).
# Variables: outfile, datafile (pin_mm,F_B_N,F_T_N,c,P_avg_rotating_MPa,P_avg_fixed_MPa,mu_conventional).
load figdir."/common.gp"
set title "Conventional μ from the Table 4.2 simulations"
set xlabel "Pin diameter (mm)"
set ylabel "μ by Eq. (2.3)"
set xrange [8:46]
set key below horizontal center height 1.5 samplen 2  # clear of the x label
set yrange [0:*]
plot datafile using 1:7 with linespoints ls 1 title "Stribeck input (Table 3.3)"
