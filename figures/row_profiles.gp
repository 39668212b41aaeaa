# Pressure profiles along rows of the contact map (thesis Figs. 2.8-2.10,
# 3.15-3.18): pressure against angle round the pin, centre and edge rows.
# Variables: outfile, datafile (angle_deg, p_y<row>... columns), title_text.
load figdir."/common.gp"
set title title_text
set xlabel "Angle round the pin from the inlet tangent point (deg)"
set ylabel "Contact pressure (MPa)"
set xrange [-10:100]
set key below horizontal center height 1.5 samplen 2  # clear of the peaks and the x label
n = system("head -50 ".datafile." | grep -v '^#' | head -1 | tr ',' '\\n' | wc -l") + 0
# Key entries from the column names: p_y<row> -> "y = <row> mm".
titles = system("grep -v '^#' ".datafile." | head -1 | tr ',' '\\n' | sed -e 's/^p_y\\(.*\\)$/\"y = \\1 mm\"/' -e 's/^\\([^\"].*\\)$/\"\\1\"/' | tr '\\n' ' '")
plot for [k=2:n] datafile using 1:k with linespoints ls (k-1) ps 0.5 title word(titles, k)
