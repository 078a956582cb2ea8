# gdsmc 0.3.0 verify: scene verify/cases/scenes/grw-ex7.ini, seed 20030331, n = 10000000, N = 10 ensembles, 21 outputs on [0, 0.25]
# paper A Figs. 7-9: y_k = ln(ln f_1 - ln f_k) against x_k = ln(r_k - r_1), grw-ex7 (fitted b = 1.709): gnuplot reports/paper/grw-ex7-exponent.gp
set terminal pngcairo size 1000,390 font ',10'
set termoption noenhanced
set output 'reports/paper/grw-ex7-exponent.png'
set datafile separator ','
cell(k) = strlen(strcol(k)) ? real(strcol(k)) : NaN
set datafile missing ''
set multiplot layout 1,1 title 'paper A Figs. 7-9: y_k = ln(ln f_1 - ln f_k) against x_k = ln(r_k - r_1), grw-ex7 (fitted b = 1.709)'
set key outside right top
set grid
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 'x_k'
set ylabel 'y_k'
plot 'reports/paper/grw-ex7-exponent-curves.csv' index 0 using 1:(cell(2)) with linespoints pt 7 ps 0.3 lw 1.5 dt 1 lc 1 title 'y_k (DSMC)', 'reports/paper/grw-ex7-exponent-curves.csv' index 1 using 1:2 with lines lw 2 dt 2 lc 2 title 'y = 1x - 2', 'reports/paper/grw-ex7-exponent-curves.csv' index 2 using 1:2 with lines lw 2 dt 2 lc 3 title 'y = 1.25x - 2', 'reports/paper/grw-ex7-exponent-curves.csv' index 3 using 1:2 with lines lw 2 dt 2 lc 4 title 'y = 1.5x - 2'
unset multiplot
