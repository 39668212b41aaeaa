# Bending force of the rotating-pin tests against the back tension (thesis
# Figs. 5.12-5.14): Table 5.3's linear fit over its printed back-tension range
# (full strip, N) and our frictionless FE run at the Table 5.13 back tension.
# Variables: outfile, linefile (F_back_N, F_bend_T5.3_N), pointfile
# (F_back_N, F_B_ours_N), title_text.
load figdir."/common.gp"
set title title_text
set xlabel "Back tension F_{back} (N, full strip)" enhanced
set ylabel "Bending force F_B (N, full strip)" enhanced
set key below horizontal
set offsets graph 0.1, graph 0.1, graph 0.2, graph 0.2
plot linefile using 1:2 with lines ls 1 title "Table 5.3 fit (measured, rotating pin)", \
     pointfile using 1:2 with points ls 2 title "our FE, frictionless"
