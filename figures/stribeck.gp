# Stribeck curves mu(L) (thesis Fig. 3.1, Eq. 3.2) with the Table 3.2
# verification cases and the draw-bend condition of Sec. 3.5.
# Variables: outfile, curvefile, casefile, pointfile.
load figdir."/common.gp"
set title "Stribeck curve, Eq. (3.2)"
set logscale x
set format x "10^{%L}"
set xlabel "Lubricant number L = vη/(p R_a)" enhanced
set ylabel "μ"
set yrange [0:0.14]
set key top right
plot curvefile using 1:2 with lines ls 1 title "Table 3.1 (strip draw)", \
     curvefile using 1:3 with lines ls 2 title "Table 3.3 (draw bend)", \
     curvefile using 1:4 with lines lc rgb "#1f77b4" dt 2 lw 1.5 title "Table 3.1, log_{10}/ln mixed" enhanced, \
     casefile using 4:5 with points ls 1 pt 7 ps 1.5 title "Table 3.2 cases", \
     pointfile using 1:2 with points ls 2 pt 13 ps 2 title "10 MPa, 50 mm/s"
