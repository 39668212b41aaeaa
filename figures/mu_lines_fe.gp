# Friction coefficient mu(p) at three sliding speeds from our own pressure maps
# (thesis Fig. 5.31).  Variables: outfile, datafile (p_MPa,v6.35,v25.4,v101.6), title_text.
load figdir."/common.gp"
set title title_text
set xlabel "Contact pressure p (MPa)"
set ylabel "μ"
set key top left
plot datafile using 1:2 with lines ls 1 title "6.35 mm/s", \
     ''       using 1:3 with lines ls 2 title "25.4 mm/s", \
     ''       using 1:4 with lines ls 3 title "101.6 mm/s"
