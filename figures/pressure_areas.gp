# Contact area per pressure range (thesis Fig. 4.11), one bar set per pin.
# Variables: outfile, datafile (range, then area columns per pin), title_text.
load figdir."/common.gp"
set title title_text
set xlabel "Contact pressure range (MPa)"
set ylabel "Contact area, half model (mm²)"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set key top right
n = system("grep -v '^#' ".datafile." | head -1 | tr ',' '\\n' | wc -l") + 0
# Column heads are area_d<D>_mm2: the key shows "<D> mm pin".
plot for [k=2:n] datafile using k:xtic(1) ls (k-1) title columnhead(k)[7:strlen(columnhead(k))-4]." mm pin"
