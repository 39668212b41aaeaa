# ESAFORM 2021 cup: cup height against angle from RD, computed on 0-90 deg
# (quarter model) and mirrored about RD and TD to 0-360 deg, per material variant.
# Variables: outfile, datafile (variant,angle_from_RD_deg,value), ylab: the cup
# height after a full draw, the flange outline (rim radius) after a partial stroke;
# stage: "end of stroke" or the partial stroke's travel.
load figdir."/common.gp"
set title "ESAFORM 2021 cup (AA6016-T4): earing profile, ".stage
set xlabel "angle from RD (deg)"
set ylabel ylab
set xrange [0:360]
set xtics 45
set key outside bottom center horizontal
set key noautotitle
sel(v) = (strcol(1) eq v) ? $3 : NaN
vars = "von_mises hill48_r hill48_s"
labels = "von~Mises Hill'48~(r-values) Hill'48~(stress~ratios)"
plot for [i=1:3] datafile using 2:(sel(word(vars, i))) with linespoints ls i title word(labels, i), \
     for [i=1:3] datafile using (180 - $2):(sel(word(vars, i))) with linespoints ls i notitle, \
     for [i=1:3] datafile using (180 + $2):(sel(word(vars, i))) with linespoints ls i notitle, \
     for [i=1:3] datafile using (360 - $2):(sel(word(vars, i))) with linespoints ls i notitle
