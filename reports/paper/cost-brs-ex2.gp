# gdsmc 0.3.0 verify: scene verify/cases/scenes/brs-ex2.ini, seed 20100402, n = 16, 16, 16, 64, 64, 64, 256, 256, 256, 1024, 1024, 1024, 4096, 4096, 4096, 16384, 16384, 16384 (by row), N = 128, 512, 2048, 128, 512, 2048, 128, 512, 2048, 128, 512, 2048, 128, 512, 2048, 128, 512, 2048 ensembles (by row), 513 outputs on [0, 1]
# cost-brs-ex2: gnuplot reports/paper/cost-brs-ex2.gp
set terminal pngcairo size 1100,750 font ',10'
set termoption noenhanced
set output 'reports/paper/cost-brs-ex2.png'
set datafile separator ','
set title 'cost-brs-ex2: Err against CPU time, T'
set xlabel 'CPU seconds (all threads)'
set ylabel 'Err (relative, max norm over the output times)'
set logscale xy
set format y '%.0e'
set grid
set key below center maxcols 2 samplen 3
set offsets graph 0.04, graph 0.12, graph 0.1, graph 0.04
set label 1 'dotted: the model' at graph 0.02, graph 0.04
plot 'reports/paper/cost-brs-ex2-points.csv' index 0 using 1:2 with linespoints pt 7 ps 1.1 lw 2 lc rgb '#0072b2' title 'N = 128 (n grows)', '' index 0 using 1:3 with lines dt 3 lw 2 lc rgb '#0072b2' notitle, '' index 0 using 1:2:4 with labels offset 0.6,0.7 font ',7' left tc rgb '#0072b2' notitle, 'reports/paper/cost-brs-ex2-points.csv' index 1 using 1:2 with linespoints pt 7 ps 1.1 lw 2 lc rgb '#d55e00' title 'N = 512 (n grows)', '' index 1 using 1:3 with lines dt 3 lw 2 lc rgb '#d55e00' notitle, '' index 1 using 1:2:4 with labels offset 0.6,0.7 font ',7' left tc rgb '#d55e00' notitle, 'reports/paper/cost-brs-ex2-points.csv' index 2 using 1:2 with linespoints pt 7 ps 1.1 lw 2 lc rgb '#cc79a7' title 'N = 2048 (n grows)', '' index 2 using 1:3 with lines dt 3 lw 2 lc rgb '#cc79a7' notitle, '' index 2 using 1:2:4 with labels offset 0.6,0.7 font ',7' left tc rgb '#cc79a7' notitle, 'reports/paper/cost-brs-ex2-points.csv' index 3 every ::0::0 using 1:2 with points pt 6 ps 2.2 lw 2 lc rgb 'black' title 'predicted cheapest (model), 1e-02: n=512 N=128', 'reports/paper/cost-brs-ex2-points.csv' index 3 every ::1::1 using 1:2 with points pt 4 ps 2.2 lw 2 lc rgb 'black' title 'predicted cheapest (model), 1e-03: n=32768 N=128', 'reports/paper/cost-brs-ex2-points.csv' index 3 every ::2::2 using 1:2 with points pt 8 ps 2.2 lw 2 lc rgb 'black' title 'predicted cheapest (model), 1e-04: n=4194304 N=128', 0.01 with lines dt 2 lc rgb 'gray50' title 'targets 1e-2, 1e-3, 1e-4', 0.001 with lines dt 2 lc rgb 'gray50' notitle, 0.0001 with lines dt 2 lc rgb 'gray50' notitle
