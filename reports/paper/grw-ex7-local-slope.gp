# gdsmc 0.3.0 verify: scene verify/scenes/grw-ex7.ini, seed 20030331, n = 10000000, N = 10 ensembles, 21 outputs on [0, 0.25]
# grw-ex7: the local slope of y_k against x_k (paper A Figs. 7-9) over windows of width 1 in c: gnuplot /tmp/paper-run/out/grw-ex7-local-slope.gp
set terminal pngcairo size 1000,390 font ',10'
set termoption noenhanced
set output '/tmp/paper-run/out/grw-ex7-local-slope.png'
set datafile separator ','
set datafile missing ''
set multiplot layout 1,1 title 'grw-ex7: the local slope of y_k against x_k (paper A Figs. 7-9) over windows of width 1 in c'
set key outside right top
set grid
set xlabel 'c = |C|/v0 (window centre)'
set ylabel 'local slope'
plot '/tmp/paper-run/out/grw-ex7-local-slope-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc 1 title 'local slope (DSMC), 2 standard errors', '/tmp/paper-run/out/grw-ex7-local-slope-curves.csv' index 1 using 1:2 with lines lw 2 dt 2 lc 2 title 'b = 1 + lambda/2 = 1.5', '/tmp/paper-run/out/grw-ex7-local-slope-curves.csv' index 2 using 1:2 with lines lw 2 dt 2 lc 3 title 'b = 2 (Gaussian)'
unset multiplot
