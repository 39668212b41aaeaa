# Friction law back-predicted by the new method against the input Stribeck
# curve, with the conventional method's points (thesis Fig. 4.10).
# Variables: outfile, curvefile (p_MPa, mu_input, mu_new_order1, mu_new_order2),
# pointsfile (pin_mm, P_avg_MPa, mu_conventional).
load figdir."/common.gp"
set title "New method against the input Stribeck law (our FE maps and forces)"
set xlabel "Contact pressure (MPa)"
set ylabel "Friction coefficient μ"
set key below horizontal center height 1.5 samplen 2  # clear of the x label
plot curvefile using 1:2 with lines ls 1 lw 3 title "input Stribeck (Table 3.3, 50 mm/s)", \
     curvefile using 1:3 with lines ls 3 dt 2 title "new method, 1st order", \
     curvefile using 1:4 with lines ls 2 title "new method, 2nd order", \
     pointsfile using 2:3 with points ls 4 ps 1.6 title "conventional, Eq. (2.3)"
