# Shared gnuplot settings for drawbend figures: SVG, readable fonts, CSV input.
set encoding utf8
set terminal svg size 720,480 dynamic enhanced font "Helvetica,14" background rgb "white"
set output outfile
set datafile separator ","
set key autotitle columnhead
set grid lc rgb "#dddddd"
set border lw 1.2
set style line 1 lc rgb "#1f77b4" lw 2 pt 7 ps 1.2
set style line 2 lc rgb "#d62728" lw 2 pt 5 ps 1.2
set style line 3 lc rgb "#2ca02c" lw 2 pt 9 ps 1.4
set style line 4 lc rgb "#9467bd" lw 2 pt 11 ps 1.2
