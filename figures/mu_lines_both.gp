# Friction coefficient mu(p) at three speeds: printed Table 5.16 (dashed) and
# ours from our own pressure maps (solid), thesis Figs. 5.26/5.27.
# Variables: outfile, datafile (p_MPa, T5.16_v6.35, T5.16_v25.4, T5.16_v101.6,
# ours_v6.35, ours_v25.4, ours_v101.6), title_text.
load figdir."/common.gp"
set title title_text
set xlabel "Contact pressure p (MPa)"
set ylabel "μ"
set key top left
plot datafile using 1:2 with lines ls 1 dt 2 title "6.35 mm/s, Table 5.16", \
     ''       using 1:3 with lines ls 2 dt 2 title "25.4 mm/s, Table 5.16", \
     ''       using 1:4 with lines ls 3 dt 2 title "101.6 mm/s, Table 5.16", \
     ''       using 1:5 with lines ls 1 title "6.35 mm/s, our maps", \
     ''       using 1:6 with lines ls 2 title "25.4 mm/s, our maps", \
     ''       using 1:7 with lines ls 3 title "101.6 mm/s, our maps"
