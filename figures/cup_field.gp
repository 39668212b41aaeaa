# Cup drawing, case 1 at the end of the stroke (thesis Figs. 6.17, 6.21,
# 6.26): the deformed quarter cup drawn by element centroids, coloured by the
# equivalent plastic strain (left) and the von Mises stress (right).  RD = x,
# TD = y; z is the punch direction.  The .vtu beside the tables holds the same
# fields for ParaView.
# Variables: outfile, datafile (x_mm,y_mm,z_mm,plastic_strain,von_mises_MPa).
load figdir."/common.gp"
eval figterm(1080, 520, 13)
set output outfile
unset key
unset grid
set view 50, 30, 1.3, 1
set view equal xyz
set xlabel "x = RD (mm)"
set ylabel "y = TD (mm)" offset -2, 0
set zlabel "z (mm)" rotate parallel offset 2, 0
set xtics 20
set ytics 20
set ztics 10
set xyplane at 0
set palette defined (0 "#30123b", 0.25 "#4686fb", 0.5 "#1ae4b6", 0.75 "#faba39", 1 "#7a0403")
# Each plot keeps a band below it for its colour bar, so the axis labels stay
# clear of the bars and inside the figure.
set multiplot
set origin 0.02, 0.20
set size 0.47, 0.80
set colorbox horizontal user origin 0.10, 0.15 size 0.30, 0.035
set title "Equivalent plastic strain"
set cblabel "plastic strain (-)"
splot datafile using 1:2:3:4 with points pt 5 ps 0.55 lc palette
set origin 0.51, 0.20
set size 0.47, 0.80
set colorbox horizontal user origin 0.60, 0.15 size 0.30, 0.035
set title "von Mises stress"
set cblabel "von Mises (MPa)"
splot datafile using 1:2:3:5 with points pt 5 ps 0.55 lc palette
unset multiplot
