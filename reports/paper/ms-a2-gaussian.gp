# gdsmc 0.3.0 verify: scene verify/scenes/ms-gaussian.ini, seed 20000601, n = 20000, N = 16 ensembles, 201 outputs on [0, 50]
# ms-a2-gaussian: a2 against alpha, Gaussian thermostat (HCS in scaled variables) (paper C Figure 4): gnuplot /tmp/paper-run/out/ms-a2-gaussian.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output '/tmp/paper-run/out/ms-a2-gaussian.png'
set datafile separator ','
set title 'ms-a2-gaussian: a2 against alpha, Gaussian thermostat (HCS in scaled variables) (paper C Figure 4)'
set xlabel 'alpha'
set ylabel 'a2'
set key top right
plot '/tmp/paper-run/out/ms-a2-gaussian-theory.csv' skip 1 using 1:2 with lines lw 2 dt 1 title 'a2 (C.5)', '/tmp/paper-run/out/ms-a2-gaussian-theory.csv' skip 1 using 1:3 with lines lw 2 dt 2 title 'a2 (C.40)', '/tmp/paper-run/out/ms-a2-gaussian-points.csv' skip 1 using 1:2:3 with yerrorbars pt 5 title 'a2 ± c', '/tmp/paper-run/out/ms-a2-gaussian-points.csv' skip 1 using 1:4:5 with yerrorbars pt 7 title '(mu2-mu2_0)/mu2_1 ± c', '/tmp/paper-run/out/ms-a2-gaussian-points.csv' skip 1 using 1:6:7 with yerrorbars pt 9 title '(mu4-mu4_0)/mu4_1 ± c'
