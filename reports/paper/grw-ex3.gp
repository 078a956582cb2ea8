# gdsmc 0.3.0 verify: scene verify/cases/scenes/grw-ex3.ini, seed 20030328, n = 64, 256, 1024, 4096, 16384 (by row), N = 10000 ensembles, 81 outputs on [0, 8]
# grw-ex3: paper A Table 1 reproduced (paper sizes): gnuplot reports/paper/grw-ex3.gp
set terminal pngcairo size 1200,1350 font ',10'
set termoption noenhanced
set output 'reports/paper/grw-ex3.png'
set datafile separator ','
set xrange [2:*]
set xlabel 't'
set ylabel 'T_raw'
set key below
set multiplot layout 3,2 title 'grw-ex3: paper A Table 1 reproduced (paper sizes)'
set title 'n = 64'
plot 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 lc rgb '#000000' title 'T_exact', 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:($3-$4):($3+$4) with filledcurves fs transparent solid 0.25 lc rgb '#0072b2' title 'n = 64: mean ± 3.2 standard errors', 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:3 with lines lw 1 dt 1 lc rgb '#0072b2' notitle
set title 'n = 256'
plot 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 lc rgb '#000000' title 'T_exact', 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:($5-$6):($5+$6) with filledcurves fs transparent solid 0.25 lc rgb '#d55e00' title 'n = 256: mean ± 3.2 standard errors', 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:5 with lines lw 1 dt 1 lc rgb '#d55e00' notitle
set title 'n = 1024'
plot 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 lc rgb '#000000' title 'T_exact', 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:($7-$8):($7+$8) with filledcurves fs transparent solid 0.25 lc rgb '#cc79a7' title 'n = 1024: mean ± 3.2 standard errors', 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:7 with lines lw 1 dt 1 lc rgb '#cc79a7' notitle
set title 'n = 4096'
plot 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 lc rgb '#000000' title 'T_exact', 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:($9-$10):($9+$10) with filledcurves fs transparent solid 0.25 lc rgb '#e69f00' title 'n = 4096: mean ± 3.2 standard errors', 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:9 with lines lw 1 dt 1 lc rgb '#e69f00' notitle
set title 'n = 16384'
plot 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 lc rgb '#000000' title 'T_exact', 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:($11-$12):($11+$12) with filledcurves fs transparent solid 0.25 lc rgb '#56b4e9' title 'n = 16384: mean ± 3.2 standard errors', 'reports/paper/grw-ex3-curves.csv' skip 1 using 1:11 with lines lw 1 dt 1 lc rgb '#56b4e9' notitle
unset multiplot
