# gdsmc 0.3.0 verify: scene verify/cases/scenes/msg.ini, seed 20070301, n = 200000, N = 16 ensembles, 201 outputs on [0, 40]
# msg-kappa: kappa'/kappa0 against alpha (paper D Fig. 3): gnuplot reports/paper/msg-kappa.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output 'reports/paper/msg-kappa.png'
set datafile separator ','
set title 'msg-kappa: kappa''/kappa0 against alpha (paper D Fig. 3)'
set xlabel 'alpha'
set ylabel 'kappa''/kappa0'
set key top right
set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05
plot 'reports/paper/msg-kappa-theory.csv' skip 1 using 1:2 with lines lw 2 dt 1 title 'first Sonine', 'reports/paper/msg-kappa-theory.csv' skip 1 using 1:3 with lines lw 2 dt 2 title 'modified first Sonine', 'reports/paper/msg-kappa-points.csv' skip 1 using 1:2:3 with yerrorbars pt 7 lc rgb '#0072b2' title 'DSMC (eps* 0.025) ± 3.2 standard errors', 'reports/paper/msg-kappa-points.csv' skip 1 using 1:4:5 with yerrorbars pt 6 lc rgb '#d55e00' title 'DSMC (eps* 0.05) ± 3.2 standard errors'
