# ESAFORM 2021 cup: thickness at the end of the stroke along RD, 45 deg and TD,
# against the initial radius, per material variant (blank 1.0 mm; holder gap 1.04 mm).
# Variables: outfile, datafile (variant,line_deg,initial_radius_mm,radius_mm,z_mm,thickness_mm).
load figdir."/common.gp"
set terminal svg size 1080,420 dynamic enhanced font "Helvetica,13" background rgb "white"
set output outfile
set multiplot layout 1,3 title "ESAFORM 2021 cup (AA6016-T4): thickness at the end of the stroke"
set xlabel "initial radius (mm)"
set ylabel "thickness (mm)"
set key top left noautotitle
set yrange [0.7:1.4]
vars = "von_mises hill48_r hill48_s yld2004"
labels = "\"von Mises\" \"Hill'48 (r)\" \"Hill'48 (σ)\" \"Yld2004\""
sel(v, l) = (strcol(1) eq v && $2 == l) ? $6 : NaN
do for [l in "0 45 90"] {
  set title sprintf("%s deg from RD", l)
  plot for [i=1:words(vars)] datafile using 3:(sel(word(vars, i), real(l))) with linespoints ls i title word(labels, i)
}
unset multiplot
