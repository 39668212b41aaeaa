# Tension-force histories in the draw step (thesis Figs. 2.19-2.20, 4.6-4.8):
# outlet tension of the frictionless and friction runs and the back tension.
# Variables: outfile, datafile (time_s, F_back_N, then one column per run), title_text.
load figdir."/common.gp"
set title title_text
set xlabel "Time in the draw step (s)"
set ylabel "Force, half model (N)"
set key below horizontal center height 1.5 samplen 2  # clear of the x label
n = system("grep -v '^#' ".datafile." | head -1 | tr ',' '\\n' | wc -l") + 0
# Key entries from the column names: F_back_N -> "back tension", F_out_<run>_N
# -> "outlet force, <run>" (mu0.1 -> mu = 0.1).
titles = system("grep -v '^#' ".datafile." | head -1 | tr ',' '\\n' | sed -e 's/^F_back_N$/back tension/' -e 's/^F_out_\\(.*\\)_N$/outlet force, \\1/' -e 's/mu\\([0-9]\\)/μ = \\1/' -e 's/.*/\"&\"/' | tr '\\n' ' '")
plot for [k=2:n] datafile using 1:k with lines ls (k-1) title word(titles, k)
