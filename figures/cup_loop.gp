# The cup loop (Chapter 8): punch force at 15 mm of each model the loop tried
# (baseline, each candidate's chosen member), cases 1 and 9, against the
# measured forces (horizontal lines, Sec. 6.6.2).
# Variables: outfile, datafile (tables/cup_figure.csv: step, model, case1_kN,
# case9_kN), e1, e9 (measured, kN), v1, v9 (punch speeds, mm/s).
load figdir."/common.gp"
eval figterm(760, 520, 13)
set output outfile
set title "Cup punch force at 15 mm: each model of the loop against measured"
set ylabel "punch force at 15 mm, full blank (kN)"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.55 border -1
set boxwidth 0.9
set xtics rotate by 30 right noenhanced font ",11"
set bmargin 9
set yrange [0:*]
set key top right
set arrow 1 from graph 0, first real(e1) to graph 1, first real(e1) nohead lc rgb "#1f77b4" dt 2 lw 2
set arrow 2 from graph 0, first real(e9) to graph 1, first real(e9) nohead lc rgb "#d62728" dt 2 lw 2
plot datafile using 3:xtic(2) lc rgb "#1f77b4" title sprintf("case 1 (%s mm/s); dashed: measured", v1), \
     ''       using 4 lc rgb "#d62728" title sprintf("case 9 (%s mm/s); dashed: measured", v9)
