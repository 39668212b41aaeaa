# Block sliding in directions 0-90 deg from RD: the elliptical limit of
# Eq. (6.3b) in the (mu_x, mu_y) plane and the retrieved components; thesis Fig. 6.10.
# Variables: outfile, ellipsefile (mu_x,mu_y), simfile (direction_deg,...,mu_x,mu_y,...), label.
load figdir."/common.gp"
set title "Sliding direction sweep, ".label
set xlabel "μ_x = F_x / F_N (RD)" enhanced
set ylabel "μ_y = F_y / F_N (TD)" enhanced
set size ratio -1
# Margins on every side, so that the 0 and 90 deg markers clear the axes' tick labels.
set autoscale noextend
set offsets graph 0.06, graph 0.1, graph 0.1, graph 0.06
set key bottom left
plot ellipsefile using 1:2 with lines ls 1 title "input ellipse (μ_{RD}, μ_{TD})" enhanced, \
     simfile using 4:5 with points ls 3 ps 2.0 title "input at the sliding angle", \
     simfile using 6:7 with points ls 2 ps 1.2 title "retrieved", \
     simfile using 6:7:(sprintf("%g°", $1)) with labels offset 1.6,0.6 notitle
