# Block sliding along RD or TD: the input surface mu(p) at the four sliding
# speeds (lines) and the retrieved friction coefficients (points); thesis Figs. 6.8, 6.9.
# Variables: outfile, dir ("RD" or "TD"), linesfile (p_MPa,RD_v10..RD_v100,TD_v10..TD_v100),
# simfile (direction,pressure_MPa,speed_mm_s,mu_input,mu_retrieved,...).
load figdir."/common.gp"
set title "Block sliding along ".dir.": retrieved μ against the input model"
set xlabel "contact pressure p (MPa)"
set ylabel "μ"
set key top left
c0 = (dir eq "RD") ? 2 : 6
sel(v) = (strcol(1) eq dir && abs($3 - v) < 1e-6) ? $5 : NaN
plot for [k=0:3] linesfile using 1:(column(c0 + k)) with lines ls (k+1) title sprintf("input, v = %d mm/s", 10 + 30*k), \
     for [k=0:3] simfile using 2:(sel(10 + 30*k)) with points ls (k+1) ps 1.6 title sprintf("retrieved, %d mm/s", 10 + 30*k)
