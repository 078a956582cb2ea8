# gdsmc 0.3.0 verify: scene verify/cases/scenes/grw-ex8.ini, seed 20030332, n = 10000000, N = 10 ensembles, 21 outputs on [0, 0.5]
# paper A Fig. 6: ln f of the speed r, grw-ex8: gnuplot reports/paper/grw-ex8-histogram.gp
set terminal pngcairo size 1000,390 font ',10'
set termoption noenhanced
set output 'reports/paper/grw-ex8-histogram.png'
set datafile separator ','
cell(k) = strlen(strcol(k)) ? real(strcol(k)) : NaN
set datafile missing ''
set multiplot layout 1,1 title 'paper A Fig. 6: ln f of the speed r, grw-ex8'
set key outside right top
set grid
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 'r = |v|'
set ylabel 'ln f'
plot 'reports/paper/grw-ex8-histogram-curves.csv' index 0 using 1:(cell(2)) with linespoints pt 7 ps 0.3 lw 1.5 dt 1 lc 1 title 'steady state (DSMC)', 'reports/paper/grw-ex8-histogram-curves.csv' index 1 using 1:2 with lines lw 2 dt 2 lc 2 title 'initial Maxwellian'
unset multiplot
