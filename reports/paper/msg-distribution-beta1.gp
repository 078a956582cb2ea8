# gdsmc 0.3.0 verify: scene verify/cases/scenes/msg.ini, seed 20070301, n = 200000, N = 16 ensembles, 201 outputs on [0, 40]
# msg-distribution: beta_1(c_x^2)/b'_1 (paper D Fig. 7): gnuplot reports/paper/msg-distribution-beta1.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output 'reports/paper/msg-distribution-beta1.png'
set datafile separator ','
set title 'msg-distribution: beta_1(c_x^2)/b''_1 (paper D Fig. 7)'
set xlabel 'c_x^2'
set ylabel 'beta_1/b''_1'
set key top right
set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05
plot 'reports/paper/msg-distribution-beta1-theory.csv' skip 1 using 1:2 with lines lw 2 dt 1 title 'first Sonine', 'reports/paper/msg-distribution-beta1-points.csv' skip 1 using 1:2:3 with yerrorbars pt 5 lc rgb '#0072b2' title 'alpha = 0.3', 'reports/paper/msg-distribution-beta1-points.csv' skip 1 using 1:4:5 with yerrorbars pt 7 lc rgb '#d55e00' title 'alpha = 1.0'
