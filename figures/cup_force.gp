# Cup drawing: punch force against punch displacement per case (thesis
# Figs. 6.16, 6.20), with the thesis's forces at 15 mm (cases 1 and 9).
# Variables: outfile, datafile (case,punch_displacement_mm,punch_force_kN),
# cases (space-separated case ids), f1, f9 (measured), s1, s9 (thesis simulation) [kN], deval [mm].
load figdir."/common.gp"
set title "Cup drawing: punch force (full blank)"
set xlabel "punch displacement (mm)"
set ylabel "punch force (kN)"
set key bottom right
sel(c) = (strcol(1) eq c) ? $3 : NaN
d = real(deval)
set xrange [0:*]
plot for [i=1:words(cases)] datafile using 2:(sel(word(cases, i))) with lines lw 2 lt i title "ours, case ".word(cases, i), \
     '+' using (d):(real(f1)) every ::0::0 with points ls 2 pt 7 ps 1.5 title "thesis measured, cases 1 and 9", \
     '+' using (d):(real(f9)) every ::0::0 with points ls 2 pt 7 ps 1.5 notitle, \
     '+' using (d):(real(s1)) every ::0::0 with points ls 1 pt 6 ps 1.8 title "thesis simulated, cases 1 and 9", \
     '+' using (d):(real(s9)) every ::0::0 with points ls 1 pt 6 ps 1.8 notitle
