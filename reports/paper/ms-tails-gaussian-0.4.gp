# gdsmc 0.3.0 verify: scene verify/cases/scenes/ms-white-noise.ini, verify/cases/scenes/ms-white-noise.ini, verify/cases/scenes/ms-gaussian.ini, verify/cases/scenes/ms-gaussian.ini (by row), seed 20000601, n = 20000, N = 16 ensembles, 201 outputs on [0, 50]
# ms-tails: G(c) = exp(4.414 c^1.0) f(c), gaussian, alpha = 0.4: gnuplot reports/paper/ms-tails-gaussian-0.4.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output 'reports/paper/ms-tails-gaussian-0.4.png'
set datafile separator ','
set title 'ms-tails: G(c) = exp(4.414 c^1.0) f(c), gaussian, alpha = 0.4'
set xlabel 'c = |v - V|/v0 with v0 = sqrt(2T/m)'
set ylabel 'G(c)'
set key bottom left
set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05
set logscale y
set format y '%g'
plot 'reports/paper/ms-tails-gaussian-0.4-theory.csv' skip 1 using 1:2 with lines lw 2 dt 1 title 'G of the Maxwellian', 'reports/paper/ms-tails-gaussian-0.4-points.csv' skip 1 using 1:2:3 with yerrorbars pt 5 lc rgb '#0072b2' title 'G (DSMC) ± 3.2 standard errors'
