# gdsmc 0.3.0 verify: scene verify/cases/scenes/grw-ex6.ini, seed 20030330, n = 10000000, N = 10 ensembles, 21 outputs on [0, 2.5]
# grw-ex6: the local slope of y_k against x_k (paper A Figs. 7-9) over windows of width 1 in c: gnuplot reports/paper/grw-ex6-local-slope.gp
set terminal pngcairo size 1000,390 font ',10'
set termoption noenhanced
set output 'reports/paper/grw-ex6-local-slope.png'
set datafile separator ','
set datafile missing ''
set multiplot layout 1,1 title 'grw-ex6: the local slope of y_k against x_k (paper A Figs. 7-9) over windows of width 1 in c'
set key outside right top
set grid
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 'c = |C|/v0 (window centre)'
set ylabel 'local slope'
plot 'reports/paper/grw-ex6-local-slope-curves.csv' index 0 using 1:($2-$3):($2+$3) with filledcurves fs transparent solid 0.25 noborder lc 1 notitle, 'reports/paper/grw-ex6-local-slope-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc 1 title 'local slope (DSMC), band: 2 standard errors', 'reports/paper/grw-ex6-local-slope-curves.csv' index 1 using 1:2 with lines lw 2 dt 2 lc 2 title 'b = 1 + lambda/2 = 1', 'reports/paper/grw-ex6-local-slope-curves.csv' index 2 using 1:2 with lines lw 2 dt 2 lc 3 title 'b = 2 (Gaussian)'
unset multiplot
