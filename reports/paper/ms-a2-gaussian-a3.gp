# gdsmc 0.3.0 verify: scene verify/cases/scenes/ms-gaussian.ini, seed 20000601, n = 20000, N = 16 ensembles, 201 outputs on [0, 50]
# ms-a2-gaussian: a3 against alpha, Gaussian thermostat (paper C Figure 6): gnuplot reports/paper/ms-a2-gaussian-a3.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output 'reports/paper/ms-a2-gaussian-a3.png'
set datafile separator ','
set title 'ms-a2-gaussian: a3 against alpha, Gaussian thermostat (paper C Figure 6)'
set xlabel 'alpha'
set ylabel 'a3'
set key top right
set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05
plot 'reports/paper/ms-a2-gaussian-a3-points.csv' skip 1 using 1:2:3 with yerrorbars pt 5 lc rgb '#0072b2' title 'a3 ± 3.2 standard errors'
