# gdsmc 0.2.0 verify: scene verify/scenes/as.ini, seed 20050501, n = 10000, N = 8 ensembles, 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 241 outputs on [0, 24], 351 outputs on [0, 700], 241 outputs on [0, 24], 351 outputs on [0, 700], 241 outputs on [0, 24], 351 outputs on [0, 700], 241 outputs on [0, 24], 351 outputs on [0, 700] (by row)
# as-steady: steady reduced stresses against alpha (paper E Figs. 15-16): gnuplot reports/paper/as-steady-stress.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output 'reports/paper/as-steady-stress.png'
set datafile separator ','
set title 'as-steady: steady reduced stresses against alpha (paper E Figs. 15-16)'
set xlabel 'alpha'
set ylabel 'reduced stress'
set key top right
plot 'reports/paper/as-steady-stress-theory.csv' skip 1 using 1:2 with lines lw 2 dt 1 title 'BGK -Pxy/p', 'reports/paper/as-steady-stress-theory.csv' skip 1 using 1:3 with lines lw 2 dt 2 title 'BGK (Pxx-Pyy)/p', 'reports/paper/as-steady-stress-points.csv' skip 1 using 1:2:3 with yerrorbars pt 5 title '-Pxy/nT ± c', 'reports/paper/as-steady-stress-points.csv' skip 1 using 1:4:5 with yerrorbars pt 7 title '(Pxx-Pyy)/nT ± c', 'reports/paper/as-steady-stress-points.csv' skip 1 using 1:6:7 with yerrorbars pt 9 title '(Pzz-Pyy)/nT ± c'
