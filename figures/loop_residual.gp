# Held-out residual of the outlet force against one candidate variable, before
# (base model) and after (final model) the loop.
# Variables: outfile, datafile (tables/residuals.csv), xcol (column number), xname.
load figdir."/common.gp"
set title "Held-out residual against ".xname
set xlabel xname
set ylabel "residual of outlet force (N)"
set key below horizontal
plot datafile using (column(int(xcol))):4 with points ls 1 pt 7 ps 0.6 title "before (base model)", \
     ''       using (column(int(xcol))):5 with points ls 2 pt 5 ps 0.5 title "after (final model)"
