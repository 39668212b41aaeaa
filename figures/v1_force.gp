# ESAFORM 2021 cup: punch force (full blank = 4 x quarter) against punch travel.
# Variables: outfile, datafile (variant,punch_travel_mm,punch_force_kN).
load figdir."/common.gp"
set title "ESAFORM 2021 cup (AA6016-T4): punch force"
set xlabel "punch travel (mm)"
set ylabel "punch force (kN)"
set key top right noautotitle
sel(v) = (strcol(1) eq v) ? $3 : NaN
vars = "von_mises hill48_r hill48_s yld2004"
labels = "\"von Mises\" \"Hill'48 (r-values)\" \"Hill'48 (stress ratios)\" \"Yld2004-18p (fitted)\""
set xrange [0:*]
set yrange [0:*]
plot for [i=1:words(vars)] datafile using 2:(sel(word(vars, i))) with lines ls i title word(labels, i)
