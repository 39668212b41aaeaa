# Shared gnuplot settings for drawbend figures: SVG (or PNG/PDF), readable
# fonts, CSV input.  Variable figformat: svg (default), png or pdf.
set encoding utf8
if (!exists("figformat")) figformat = "svg"
# The terminal for a figure of w x h pixels (SVG) with font size fs; PNG is
# drawn at twice the size (print resolution), PDF at 100 px per inch.
figterm(w, h, fs) = figformat eq "png" ? \
    sprintf("set terminal pngcairo size %d,%d enhanced font 'Helvetica,%d' background rgb 'white'", 2*w, 2*h, 2*fs*3/4) : \
  figformat eq "pdf" ? \
    sprintf("set terminal pdfcairo size %.2fin,%.2fin enhanced font 'Helvetica,%d'", w/100.0, h/100.0, fs*3/4) : \
    sprintf("set terminal svg size %d,%d dynamic enhanced font 'Helvetica,%d' background rgb 'white'", w, h, fs)
eval figterm(720, 480, 14)
set output outfile
set datafile separator ","
set key autotitle columnhead
# Texts render literally: column names, file names and titles passed in from
# the programs hold underscores (F_back_N, p_y0, test_order) that enhanced text
# would turn into subscripts.  A script that means math says so on the element
# (`set xlabel "L = vη/(p R_a)" enhanced`, `title "μ_{RD}" enhanced`).
set title noenhanced
set xlabel noenhanced
set ylabel noenhanced
set zlabel noenhanced
set cblabel noenhanced
set key noenhanced
set grid lc rgb "#dddddd"
set border lw 1.2
set style line 1 lc rgb "#1f77b4" lw 2 pt 7 ps 1.2
set style line 2 lc rgb "#d62728" lw 2 pt 5 ps 1.2
set style line 3 lc rgb "#2ca02c" lw 2 pt 9 ps 1.4
set style line 4 lc rgb "#9467bd" lw 2 pt 11 ps 1.2
