# gdsmc 0.3.0 verify: scene verify/cases/scenes/as.ini, seed 20050501, n = 10000, N = 8 ensembles, 161 outputs on [0, 15.72], 301 outputs on [0, 529.1], 161 outputs on [0, 15.72], 301 outputs on [0, 529.1], 161 outputs on [0, 15.64], 301 outputs on [0, 524.3], 161 outputs on [0, 15.64], 301 outputs on [0, 524.3], 161 outputs on [0, 15.6], 301 outputs on [0, 520.5], 161 outputs on [0, 15.6], 301 outputs on [0, 520.5], 161 outputs on [0, 15.6], 301 outputs on [0, 519.2], 161 outputs on [0, 15.6], 301 outputs on [0, 519.2], 161 outputs on [0, 15.7], 301 outputs on [0, 520.8], 161 outputs on [0, 15.7], 301 outputs on [0, 520.8], 161 outputs on [0, 15.7], 161 outputs on [0, 15.94], 301 outputs on [0, 527.2], 161 outputs on [0, 15.94], 301 outputs on [0, 527.2], 161 outputs on [0, 15.94], 161 outputs on [0, 16.4], 301 outputs on [0, 541.9], 161 outputs on [0, 16.4], 301 outputs on [0, 541.9], 161 outputs on [0, 16.4], 161 outputs on [0, 17.28], 301 outputs on [0, 571.3], 161 outputs on [0, 17.28], 301 outputs on [0, 571.3], 161 outputs on [0, 17.28], 161 outputs on [0, 19.12], 301 outputs on [0, 633.1], 161 outputs on [0, 19.12], 301 outputs on [0, 633.1], 161 outputs on [0, 24.01], 301 outputs on [0, 791.6], 161 outputs on [0, 24.01], 301 outputs on [0, 791.6] (by row)
# as-steady: steady a* against alpha, IHS and EHS, both a tau0 (paper E Fig. 14): gnuplot reports/paper/as-steady.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output 'reports/paper/as-steady.png'
set datafile separator ','
set title 'as-steady: steady a* against alpha, IHS and EHS, both a tau0 (paper E Fig. 14)'
set xlabel 'alpha'
set ylabel 'a* = a tau_eta(T)'
set key top right
set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05
plot 'reports/paper/as-steady-theory.csv' skip 1 using 1:2 with lines lw 2 dt 1 title 'BGK', 'reports/paper/as-steady-points.csv' skip 1 using 1:2:3 with yerrorbars pt 7 lc rgb '#0072b2' title 'DSMC (IHS) ± 3.2 standard errors', 'reports/paper/as-steady-points.csv' skip 1 using 1:4:5 with yerrorbars pt 6 lc rgb '#d55e00' title 'DSMC (EHS) ± 3.2 standard errors', 'reports/paper/as-steady-points.csv' skip 1 using 1:6:7 with yerrorbars pt 2 lc rgb '#cc79a7' title 'DSMC (EHS jump scheme) ± 3.2 standard errors'
