# gdsmc 0.3.0 verify: scene verify/cases/scenes/split-ex5.ini, seed 20100906, n = 64, 256, 1024, 4096, 64, 256, 1024, 256, 256, 256, 256, 1024, 1024, 1024, 1024, 1024, 1024, 1024, 1024 (by row), N = 256, 256, 256, 256, 1024, 1024, 1024, 256, 256, 256, 256, 256, 256, 256, 256, 256, 256, 256, 256 ensembles (by row), 21 outputs on [0, 32]
# cost-split-ex5: gnuplot reports/paper/cost-split-ex5.gp
set terminal pngcairo size 1100,750 font ',10'
set termoption noenhanced
set output 'reports/paper/cost-split-ex5.png'
set datafile separator ','
set title 'cost-split-ex5: Err of the time-averaged T against CPU time'
set xlabel 'CPU seconds (all threads)'
set ylabel 'Err = |T - T_inf| / T_inf (time-averaged T)'
set logscale xy
set format y '%.0e'
set grid
set key below center maxcols 2 samplen 3
set offsets graph 0.04, graph 0.12, graph 0.1, graph 0.04
set label 1 'dotted: the model' at graph 0.02, graph 0.04
plot 'reports/paper/cost-split-ex5-points.csv' index 0 using 1:2 with linespoints pt 7 ps 1.1 lw 2 lc rgb '#0072b2' title 'jump, N = 256 (n grows)', '' index 0 using 1:3 with lines dt 3 lw 2 lc rgb '#0072b2' notitle, '' index 0 using 1:2:4 with labels offset 0.6,0.7 font ',7' left tc rgb '#0072b2' notitle, 'reports/paper/cost-split-ex5-points.csv' index 1 using 1:2 with linespoints pt 7 ps 1.1 lw 2 lc rgb '#d55e00' title 'jump, N = 1024 (n grows)', '' index 1 using 1:3 with lines dt 3 lw 2 lc rgb '#d55e00' notitle, '' index 1 using 1:2:4 with labels offset 0.6,0.7 font ',7' left tc rgb '#d55e00' notitle, 'reports/paper/cost-split-ex5-points.csv' index 2 using 1:2 with linespoints pt 7 ps 1.1 lw 2 lc rgb '#cc79a7' title 'strang, n = 256, N = 256 (h shrinks)', '' index 2 using 1:3 with lines dt 3 lw 2 lc rgb '#cc79a7' notitle, '' index 2 using 1:2:4 with labels offset 0.6,0.7 font ',7' left tc rgb '#cc79a7' notitle, 'reports/paper/cost-split-ex5-points.csv' index 3 using 1:2 with linespoints pt 7 ps 1.1 lw 2 lc rgb '#e69f00' title 'strang, n = 1024, N = 256 (h shrinks)', '' index 3 using 1:3 with lines dt 3 lw 2 lc rgb '#e69f00' notitle, '' index 3 using 1:2:4 with labels offset 0.6,0.7 font ',7' left tc rgb '#e69f00' notitle, 'reports/paper/cost-split-ex5-points.csv' index 4 using 1:2 with linespoints pt 7 ps 1.1 lw 2 lc rgb '#56b4e9' title 'euler, n = 1024, N = 256 (h shrinks)', '' index 4 using 1:3 with lines dt 3 lw 2 lc rgb '#56b4e9' notitle, '' index 4 using 1:2:4 with labels offset 0.6,0.7 font ',7' left tc rgb '#56b4e9' notitle, 'reports/paper/cost-split-ex5-points.csv' index 5 every ::0::0 using 1:2 with points pt 6 ps 2.2 lw 2 lc rgb 'black' title 'predicted cheapest (model), 1e-02: strang n=128 N=256 h=0.1', 'reports/paper/cost-split-ex5-points.csv' index 5 every ::1::1 using 1:2 with points pt 4 ps 2.2 lw 2 lc rgb 'black' title 'predicted cheapest (model), 1e-03: strang n=2048 N=256 h=0.05', 'reports/paper/cost-split-ex5-points.csv' index 5 every ::2::2 using 1:2 with points pt 8 ps 2.2 lw 2 lc rgb 'black' title 'predicted cheapest (model), 1e-04: jump n=32768 N=256', 0.01 with lines dt 2 lc rgb 'gray50' title 'targets 1e-2, 1e-3, 1e-4', 0.001 with lines dt 2 lc rgb 'gray50' notitle, 0.0001 with lines dt 2 lc rgb 'gray50' notitle
