# ESAFORM 2021 cup: cup height against angle from RD, computed on 0-90 deg
# (quarter model) and mirrored about RD and TD to 0-360 deg, per material variant.
# Variables: outfile, datafile (variant,angle_from_RD_deg,value), ylab: the cup
# height after a full draw, the flange outline (rim radius) after a partial stroke;
# stage: "end of stroke" or the partial stroke's travel.
load figdir."/common.gp"
set xlabel "angle from RD (deg)"
set ylabel ylab
set xrange [0:360]
set xtics 45
set offsets 0, 0, graph 0.05, graph 0.05  # a flat profile stays off the frame
set key outside bottom center horizontal
set key noautotitle
sel(v) = (strcol(1) eq v) ? $3 : NaN
vars = "von_mises hill48_r hill48_s yld2004"
labels = "\"von Mises\" \"Hill'48 (r-values)\" \"Hill'48 (stress ratios)\" \"Yld2004-18p (fitted)\""
# shown: the variants drawn (indices into vars; a torn cup has no cup height);
# note: appended to the title (which variants are left out, and why).
if (!exists("shown")) shown = "1 2 3 4"
if (!exists("note")) note = ""
set title "ESAFORM 2021 cup (AA6016-T4): earing profile, ".stage.(note eq "" ? "" : "\n".note)
n = words(shown)
plot for [j=1:n] datafile using 2:(sel(word(vars, word(shown, j) + 0))) with linespoints ls (word(shown, j) + 0) \
         title word(labels, word(shown, j) + 0), \
     for [j=1:n] datafile using (180 - $2):(sel(word(vars, word(shown, j) + 0))) with linespoints ls (word(shown, j) + 0) notitle, \
     for [j=1:n] datafile using (180 + $2):(sel(word(vars, word(shown, j) + 0))) with linespoints ls (word(shown, j) + 0) notitle, \
     for [j=1:n] datafile using (360 - $2):(sel(word(vars, word(shown, j) + 0))) with linespoints ls (word(shown, j) + 0) notitle
