# gdsmc 0.2.0 verify: scene verify/scenes/as.ini, seed 20050501, n = 10000, N = 8 ensembles, 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300], 241 outputs on [0, 24], 351 outputs on [0, 700], 241 outputs on [0, 24], 351 outputs on [0, 700], 241 outputs on [0, 24], 351 outputs on [0, 700], 241 outputs on [0, 24], 351 outputs on [0, 700] (by row)
# as-steady: steady a* against alpha, IHS and EHS, both a tau0 (paper E Fig. 14): gnuplot reports/paper/as-steady.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output 'reports/paper/as-steady.png'
set datafile separator ','
set title 'as-steady: steady a* against alpha, IHS and EHS, both a tau0 (paper E Fig. 14)'
set xlabel 'alpha'
set ylabel 'a*'
set key top right
plot 'reports/paper/as-steady-theory.csv' skip 1 using 1:2 with lines lw 2 dt 1 title 'BGK', 'reports/paper/as-steady-points.csv' skip 1 using 1:2:3 with yerrorbars pt 5 title 'DSMC ± c'
