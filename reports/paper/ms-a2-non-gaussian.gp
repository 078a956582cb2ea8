# gdsmc 0.3.0 verify: scene verify/cases/scenes/ms-non-gaussian.ini, seed 20000601, n = 20000, N = 16 ensembles, 201 outputs on [0, 50]
# ms-a2-non-gaussian: a2 against alpha, non-Gaussian thermostat (paper C Figure 8): gnuplot reports/paper/ms-a2-non-gaussian.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output 'reports/paper/ms-a2-non-gaussian.png'
set datafile separator ','
set title 'ms-a2-non-gaussian: a2 against alpha, non-Gaussian thermostat (paper C Figure 8)'
set xlabel 'alpha'
set ylabel 'a2'
set key top right
set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05
plot 'reports/paper/ms-a2-non-gaussian-theory.csv' skip 1 using 1:2 with lines lw 2 dt 1 title 'a2, C Eq. (50)', 'reports/paper/ms-a2-non-gaussian-theory.csv' skip 1 using 1:3 with lines lw 2 dt 2 title 'a2, C Eq. (76) (semi-empirical)', 'reports/paper/ms-a2-non-gaussian-points.csv' skip 1 using 1:2:3 with yerrorbars pt 5 lc rgb '#0072b2' title 'a2 ± 3.2 standard errors', 'reports/paper/ms-a2-non-gaussian-points.csv' skip 1 using 1:4:5 with yerrorbars pt 7 lc rgb '#d55e00' title '(mu2-mu2_0)/mu2_1 ± 3.2 standard errors', 'reports/paper/ms-a2-non-gaussian-points.csv' skip 1 using 1:6:7 with yerrorbars pt 9 lc rgb '#cc79a7' title '(mu4-mu4_0)/mu4_1 ± 3.2 standard errors'
