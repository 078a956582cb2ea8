# gdsmc 0.3.0 verify: scene verify/cases/scenes/grw-ex6.ini, seed 20030330, n = 10000000, N = 10 ensembles, 21 outputs on [0, 2.5]
# grw-ex6: ln G(c) = ln f(c) + A c^1, A = 4.0196 from the loss-diffusion balance: gnuplot reports/paper/grw-ex6-levelled.gp
set terminal pngcairo size 1000,390 font ',10'
set termoption noenhanced
set output 'reports/paper/grw-ex6-levelled.png'
set datafile separator ','
cell(k) = strlen(strcol(k)) ? real(strcol(k)) : NaN
set datafile missing ''
set multiplot layout 1,1 title 'grw-ex6: ln G(c) = ln f(c) + A c^1, A = 4.0196 from the loss-diffusion balance'
set key outside right top
set grid
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 'c = |v|/v0'
set ylabel 'ln G'
plot 'reports/paper/grw-ex6-levelled-curves.csv' index 0 using 1:(cell(2)) with linespoints pt 7 ps 0.3 lw 1.5 dt 1 lc 1 title 'ln G (DSMC)'
unset multiplot
