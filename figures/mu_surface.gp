# Friction-coefficient surface mu(p, v) from the nine-node interpolation, with
# the measured lines drawn on it (thesis Figs. 5.28, 5.29, 6.2).
# Variables: outfile, gridfile (x,y,z blocks separated by blank lines), linesfile (p_MPa,v6.35,v25.4,v101.6), dir.
load figdir."/common.gp"
set key noautotitle
set title "Friction surface μ(p, v), ".dir." strips"
set xlabel "p (MPa)" offset 0,-1
set ylabel "v (mm/s)" offset 1,-1
set zlabel "μ" rotate by 90
set view 60, 35
set pm3d depthorder hidden3d
set palette defined (0 "#2166ac", 1 "#f7f7f7", 2 "#b2182b")
set hidden3d
set xyplane 0
unset key
splot gridfile using 1:2:3 with pm3d, \
      linesfile every ::1 using 1:(6.35):2 with lines lc rgb "red" lw 3 dt 2, \
      linesfile every ::1 using 1:(25.4):3 with lines lc rgb "red" lw 3 dt 2, \
      linesfile every ::1 using 1:(101.6):4 with lines lc rgb "red" lw 3 dt 2
