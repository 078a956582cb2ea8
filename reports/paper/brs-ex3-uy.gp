# gdsmc 0.3.0 verify: scene verify/cases/scenes/brs-ex3.ini, seed 20100403, n = 4, 16, 64, 256, 1024 (by row), N = 64, 256, 1024, 4096, 16384 ensembles (by row), 513 outputs on [0, 1]
# brs-ex3: paper B Maxwell kernels, relaxation (paper sizes): gnuplot reports/paper/brs-ex3-uy.gp
set terminal pngcairo size 1200,1350 font ',10'
set termoption noenhanced
set output 'reports/paper/brs-ex3-uy.png'
set datafile separator ','
set xrange [0:*]
set xlabel 't'
set ylabel 'uy'
set key below
set multiplot layout 3,2 title 'brs-ex3: paper B Maxwell kernels, relaxation (paper sizes)'
set title 'n = 4'
plot 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 lc rgb '#000000' title 'uy_exact', 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:($3-$4):($3+$4) with filledcurves fs transparent solid 0.25 lc rgb '#0072b2' title 'n = 4: mean ± 3.2 standard errors', 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:3 with lines lw 1 dt 1 lc rgb '#0072b2' notitle
set title 'n = 16'
plot 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 lc rgb '#000000' title 'uy_exact', 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:($5-$6):($5+$6) with filledcurves fs transparent solid 0.25 lc rgb '#d55e00' title 'n = 16: mean ± 3.2 standard errors', 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:5 with lines lw 1 dt 1 lc rgb '#d55e00' notitle
set title 'n = 64'
plot 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 lc rgb '#000000' title 'uy_exact', 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:($7-$8):($7+$8) with filledcurves fs transparent solid 0.25 lc rgb '#cc79a7' title 'n = 64: mean ± 3.2 standard errors', 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:7 with lines lw 1 dt 1 lc rgb '#cc79a7' notitle
set title 'n = 256'
plot 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 lc rgb '#000000' title 'uy_exact', 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:($9-$10):($9+$10) with filledcurves fs transparent solid 0.25 lc rgb '#e69f00' title 'n = 256: mean ± 3.2 standard errors', 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:9 with lines lw 1 dt 1 lc rgb '#e69f00' notitle
set title 'n = 1024'
plot 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 lc rgb '#000000' title 'uy_exact', 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:($11-$12):($11+$12) with filledcurves fs transparent solid 0.25 lc rgb '#56b4e9' title 'n = 1024: mean ± 3.2 standard errors', 'reports/paper/brs-ex3-uy-curves.csv' skip 1 using 1:11 with lines lw 1 dt 1 lc rgb '#56b4e9' notitle
unset multiplot
