# Held-out residual of the outlet force against one candidate variable in bins
# (data sets of more than 5,000 rows, src/loop/figure_data.hpp): each bin's mean,
# the bars one standard deviation of its rows, before (base model) and after
# (final model) the loop.
# Variables: outfile, datafile (tables/residual_bins.csv), cand (the candidate's
# number, column 1), xname, rows (rows in the data set).
load figdir."/common.gp"
set title "Held-out residual against ".xname.": bin means ± 1 sd (".rows." rows)"
set xlabel xname
set ylabel "residual of outlet force (N)"
set key below horizontal
plot datafile using (column(1) == int(cand) ? column(2) : NaN):4:5 with yerrorbars ls 1 pt 7 ps 0.8 title "before (base model)", \
     ''       using (column(1) == int(cand) ? column(2) : NaN):6:7 with yerrorbars ls 2 pt 5 ps 0.7 title "after (final model)"
