# Bending force F_B per pin against R/t, as the error against the measured fit
# (Table 5.3 at the Table 5.13 back tensions), with the +-10 % goal as a band:
# the finite-element models (solid) and beam theory, step 2a (dashed).
# Variables: outfile, datafile (tables/fb_figure.csv: R_over_t, measured_N,
# isotropic_N, final_N, pin_mm, beam_isotropic_N, beam_af_N).
load figdir."/common.gp"
set title "Bending force per pin: error against the measured fit"
set xlabel "pin radius / strip thickness R/t (pins 12.7, 25.4, 42 mm)"
set ylabel "F_{B} predicted / measured - 1 (%)" enhanced
set key bottom right
set yrange [-40:70]
set xrange [4:22]
set object 1 rect from graph 0, first -10 to graph 1, first 10 fc rgb "#e8f3e8" fs solid noborder behind
set label 1 "goal: within 10 %" at graph 0.03, first 6
set xzeroaxis lt 0
plot datafile using 1:(100*($3/$2-1)) with linespoints ls 2 title "FE, isotropic (before)", \
     ''       using 1:(100*($4/$2-1)) with linespoints ls 3 title "FE, after the loop", \
     ''       using 1:(100*($6/$2-1)) with linespoints ls 2 dt 2 title "beam theory, isotropic", \
     ''       using 1:(100*($7/$2-1)) with linespoints ls 3 dt 2 title "beam theory, back stress chosen on the fit pin"
