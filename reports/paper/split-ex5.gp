# gdsmc 0.3.0 verify: scene verify/cases/scenes/split-ex5.ini, seed 20100906, n = 1024, N = 1500 ensembles, 21 outputs on [0, 32]
# split-ex5: |time-step - jump| in the time-averaged T: gnuplot reports/paper/split-ex5.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output 'reports/paper/split-ex5.png'
set datafile separator ','
set title 'split-ex5: |time-step - jump| in the time-averaged T'
set xlabel 'h'
set ylabel '|difference in T|'
set key top right
set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05
set logscale xy
set format xy '%g'
plot 'reports/paper/split-ex5-theory.csv' skip 1 using 1:2 with lines lw 2 dt 1 title 'slope 1', 'reports/paper/split-ex5-theory.csv' skip 1 using 1:3 with lines lw 2 dt 2 title 'slope 2', 'reports/paper/split-ex5-points.csv' skip 1 using 1:2:3 with yerrorbars pt 5 lc rgb '#0072b2' title 'Euler |dT| ± 3.2 standard errors', 'reports/paper/split-ex5-points.csv' skip 1 using 1:4:5 with yerrorbars pt 7 lc rgb '#d55e00' title 'Strang |dT| ± 3.2 standard errors'
