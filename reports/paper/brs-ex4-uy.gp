# gdsmc 0.3.0 verify: scene verify/cases/scenes/brs-ex4.ini, seed 20101435, 20102435, 20103435 (by row), n = 64, 256, 1024 (by row), N = 1024, 256, 64 ensembles (by row), 513 outputs on [0, 2]
# brs-ex4: u_y(t) beside the closures (paper sizes): gnuplot reports/paper/brs-ex4-uy.gp
set terminal pngcairo size 1200,700 font ',10'
set termoption noenhanced
set output 'reports/paper/brs-ex4-uy.png'
set datafile separator ','
set xrange [0:*]
set xlabel 't'
set ylabel 'uy'
set key below
set title 'brs-ex4: u_y(t) beside the closures (paper sizes)'
plot 'reports/paper/brs-ex4-uy-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 lc rgb '#000000' title 'uy_le', 'reports/paper/brs-ex4-uy-curves.csv' skip 1 using 1:3 with lines dt 3 lw 2 lc rgb '#000000' title 'uy_grad', 'reports/paper/brs-ex4-uy-curves.csv' skip 1 using 1:($4-$5):($4+$5) with filledcurves fs transparent solid 0.25 lc rgb '#0072b2' title 'n = 64: mean ± 3.2 standard errors', 'reports/paper/brs-ex4-uy-curves.csv' skip 1 using 1:4 with lines lw 1 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/brs-ex4-uy-curves.csv' skip 1 using 1:($6-$7):($6+$7) with filledcurves fs transparent solid 0.25 lc rgb '#d55e00' title 'n = 256: mean ± 3.2 standard errors', 'reports/paper/brs-ex4-uy-curves.csv' skip 1 using 1:6 with lines lw 1 dt 1 lc rgb '#d55e00' notitle, 'reports/paper/brs-ex4-uy-curves.csv' skip 1 using 1:($8-$9):($8+$9) with filledcurves fs transparent solid 0.25 lc rgb '#cc79a7' title 'n = 1024: mean ± 3.2 standard errors', 'reports/paper/brs-ex4-uy-curves.csv' skip 1 using 1:8 with lines lw 1 dt 1 lc rgb '#cc79a7' notitle
