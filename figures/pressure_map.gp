# Contact-pressure map round the pin (thesis Figs. 2.6, 4.2-4.5): pressure over
# angle round the pin x position across the half width, as a heat map.
# Variables: outfile, gridfile (angle_deg,y_mm,pressure_MPa blocks), title_text.
load figdir."/common.gp"
eval figterm(720, 360, 14)
set output outfile
unset key
set title title_text
set xlabel "Angle round the pin from the inlet tangent point (deg)"
set ylabel "y from strip centre (mm)"
set cblabel "Pressure (MPa)"
set view map
set pm3d map interpolate 2,2
set palette defined (0 "white", 0.15 "#fde0a0", 0.4 "#f08030", 0.7 "#c02020", 1 "#400010")
set xrange [-10:100]
set cbrange [0:*]
splot gridfile using 1:2:3 with pm3d
