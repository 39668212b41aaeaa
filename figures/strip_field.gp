# A field of the strip's centre row of elements at the end of the draw
# (thesis Figs. 2.15, 2.16), unrolled: position along the strip from the
# entry tangent against depth through the thickness (0 = pin side, 1 = free
# side); each element is a box coloured by its value.  The dashed lines mark
# the entry and exit tangents.
# Variables: outfile, datafile (position_mm, length_mm, depth, layer, ...),
# column (the value's column number, as text), wrapfile (wrap length in mm,
# as text), title_text, cb_text.
load figdir."/common.gp"
eval figterm(720, 360, 14)
set output outfile
unset key
set title title_text
set xlabel "Position along the strip from the entry tangent (mm)"
set ylabel "Depth (0 = pin side, 1 = free side)"
set cblabel cb_text
Lw = wrapfile + 0.0
k = column + 0
# Blue for compression, red for tension, white at zero: a range symmetric
# about 0 (over the elements drawn, before the axis ranges are set).
stats datafile using (($1 >= -Lw && $1 <= 2 * Lw) ? column(k) : NaN) nooutput
m = abs(STATS_min) > abs(STATS_max) ? abs(STATS_min) : abs(STATS_max)
set xrange [-Lw : 2 * Lw]
set yrange [0 : 1]
set cbrange [-m : m]
set palette defined (0 "#2040a0", 0.5 "#f4f4f4", 1 "#b02020")
set arrow from 0, graph 0 to 0, graph 1 nohead dt 2 lw 2 lc rgb "#333333" front
set arrow from Lw, graph 0 to Lw, graph 1 nohead dt 2 lw 2 lc rgb "#333333" front
set style fill solid 1.0 noborder
plot datafile using 1:3:($2 / 2):($4 / 2):k with boxxyerror lc palette
