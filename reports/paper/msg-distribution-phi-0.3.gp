# gdsmc 0.3.0 verify: scene verify/cases/scenes/msg.ini, seed 20070301, n = 200000, N = 16 ensembles, 201 outputs on [0, 40]
# msg-distribution: phi(c_x^2) and its truncations, alpha = 0.3 (paper D Figs. 5-6): gnuplot reports/paper/msg-distribution-phi-0.3.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output 'reports/paper/msg-distribution-phi-0.3.png'
set datafile separator ','
set title 'msg-distribution: phi(c_x^2) and its truncations, alpha = 0.3 (paper D Figs. 5-6)'
set xlabel 'c_x^2'
set ylabel 'phi'
set key top right
set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05
plot 'reports/paper/msg-distribution-phi-0.3-theory.csv' skip 1 using 1:2 with lines lw 2 dt 1 title 'phi_1', 'reports/paper/msg-distribution-phi-0.3-theory.csv' skip 1 using 1:3 with lines lw 2 dt 2 title 'phi_2', 'reports/paper/msg-distribution-phi-0.3-theory.csv' skip 1 using 1:4 with lines lw 2 dt 3 title 'phi_3', 'reports/paper/msg-distribution-phi-0.3-points.csv' skip 1 using 1:2:3 with yerrorbars pt 5 lc rgb '#0072b2' title 'phi (DSMC) ± 3.2 standard errors'
