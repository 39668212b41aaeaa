# Bending force F_B per pin against R/t: measured (Table 5.3 at the Table 5.13
# back tensions), the isotropic model and the model after the loop.
# Variables: outfile, datafile (tables/fb_figure.csv: R_over_t, measured_N,
# isotropic_N, final_N, pin_mm).
load figdir."/common.gp"
set title "Bending force per pin: measured against predicted"
set xlabel "pin radius / strip thickness R/t"
set ylabel "bending force F_{B}, full strip (N)" enhanced
set key top right
set yrange [0:*]
plot datafile using 1:2 with linespoints ls 1 title "measured (Table 5.3)", \
     ''       using 1:3 with linespoints ls 2 title "isotropic (before)", \
     ''       using 1:4 with linespoints ls 3 title "after the loop"
