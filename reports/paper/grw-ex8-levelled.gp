# gdsmc 0.3.0 verify: scene verify/cases/scenes/grw-ex8.ini, seed 20030332, n = 10000000, N = 10 ensembles, 21 outputs on [0, 0.5]
# grw-ex8: ln G(c) = ln f(c) + A c^1.25, A = 2.6670 from the loss-diffusion balance: gnuplot reports/paper/grw-ex8-levelled.gp
set terminal pngcairo size 1000,390 font ',10'
set termoption noenhanced
set output 'reports/paper/grw-ex8-levelled.png'
set datafile separator ','
cell(k) = strlen(strcol(k)) ? real(strcol(k)) : NaN
set datafile missing ''
set multiplot layout 1,1 title 'grw-ex8: ln G(c) = ln f(c) + A c^1.25, A = 2.6670 from the loss-diffusion balance'
set key outside right top
set grid
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 'c = |v|/v0'
set ylabel 'ln G'
plot 'reports/paper/grw-ex8-levelled-curves.csv' index 0 using 1:(cell(2)) with linespoints pt 7 ps 0.3 lw 1.5 dt 1 lc 1 title 'ln G (DSMC)'
unset multiplot
