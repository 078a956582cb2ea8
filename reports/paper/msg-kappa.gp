# gdsmc 0.3.0 verify: scene verify/scenes/msg.ini, seed 20070301, n = 200000, N = 16 ensembles, 201 outputs on [0, 40]
# msg-kappa: kappa'/kappa0 against alpha (paper D Fig. 3): gnuplot /tmp/paper-run/out/msg-kappa.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output '/tmp/paper-run/out/msg-kappa.png'
set datafile separator ','
set title 'msg-kappa: kappa''/kappa0 against alpha (paper D Fig. 3)'
set xlabel 'alpha'
set ylabel 'kappa''/kappa0'
set key top right
plot '/tmp/paper-run/out/msg-kappa-theory.csv' skip 1 using 1:2 with lines lw 2 dt 1 title 'first Sonine', '/tmp/paper-run/out/msg-kappa-theory.csv' skip 1 using 1:3 with lines lw 2 dt 2 title 'modified first Sonine', '/tmp/paper-run/out/msg-kappa-points.csv' skip 1 using 1:2:3 with yerrorbars pt 5 title 'DSMC ± c'
