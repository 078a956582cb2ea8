# gdsmc 0.3.0 verify: scene verify/cases/scenes/as.ini, seed 20050501, n = 10000, N = 8 ensembles, 241 outputs on [0, 24], 351 outputs on [0, 700], 241 outputs on [0, 24], 351 outputs on [0, 700], 161 outputs on [0, 16], 301 outputs on [0, 300], 161 outputs on [0, 16], 301 outputs on [0, 300] (by row)
# paper E Fig. 18: the steady marginals at alpha = 0.5 (C in units of sqrt(2T/m)): gnuplot reports/paper/as-distribution-0.5-log.gp
set terminal pngcairo size 1000,1050 font ',10'
set termoption noenhanced
set output 'reports/paper/as-distribution-0.5-log.png'
set datafile separator ','
set datafile missing ''
set multiplot layout 3,1 title 'paper E Fig. 18: the steady marginals at alpha = 0.5 (C in units of sqrt(2T/m))'
set logscale y
set format y '%g'
set key outside right top
set grid
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 'C_x (top), C_y (middle), C (bottom)'
set ylabel 'g_x^(+)'
plot 'reports/paper/as-distribution-0.5-log-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' title 'ihs alpha=0.5 a_tau0=4', 'reports/paper/as-distribution-0.5-log-curves.csv' index 2 using 1:2 with lines lw 1.5 dt 4 lc rgb '#56b4e9' title 'ihs alpha=0.5 a_tau0=0.1', 'reports/paper/as-distribution-0.5-log-curves.csv' index 4 using 1:2 with lines lw 1.5 dt 1 lc rgb '#d55e00' title 'ehs alpha=0.5 a_tau0=4', 'reports/paper/as-distribution-0.5-log-curves.csv' index 6 using 1:2 with lines lw 1.5 dt 4 lc rgb '#e69f00' title 'ehs alpha=0.5 a_tau0=0.1', 'reports/paper/as-distribution-0.5-log-curves.csv' index 8 using 1:2 with lines lw 2 dt 2 lc rgb '#000000' title 'BGK alpha=0.5', 'reports/paper/as-distribution-0.5-log-curves.csv' index 10 using 1:2 with lines lw 2 dt 2 lc rgb '#999999' title 'equilibrium'
set xlabel 'C_x (top), C_y (middle), C (bottom)'
set ylabel 'g_y^(+)'
plot 'reports/paper/as-distribution-0.5-log-curves.csv' index 0 using 1:4 with lines lw 1.5 dt 1 lc rgb '#0072b2' title 'ihs alpha=0.5 a_tau0=4', 'reports/paper/as-distribution-0.5-log-curves.csv' index 2 using 1:4 with lines lw 1.5 dt 4 lc rgb '#56b4e9' title 'ihs alpha=0.5 a_tau0=0.1', 'reports/paper/as-distribution-0.5-log-curves.csv' index 4 using 1:4 with lines lw 1.5 dt 1 lc rgb '#d55e00' title 'ehs alpha=0.5 a_tau0=4', 'reports/paper/as-distribution-0.5-log-curves.csv' index 6 using 1:4 with lines lw 1.5 dt 4 lc rgb '#e69f00' title 'ehs alpha=0.5 a_tau0=0.1', 'reports/paper/as-distribution-0.5-log-curves.csv' index 8 using 1:4 with lines lw 2 dt 2 lc rgb '#000000' title 'BGK alpha=0.5', 'reports/paper/as-distribution-0.5-log-curves.csv' index 10 using 1:4 with lines lw 2 dt 2 lc rgb '#999999' title 'equilibrium'
set xlabel 'C_x (top), C_y (middle), C (bottom)'
set ylabel 'F(C)'
plot 'reports/paper/as-distribution-0.5-log-curves.csv' index 1 using 1:6 with lines lw 1.5 dt 1 lc rgb '#0072b2' title 'ihs alpha=0.5 a_tau0=4', 'reports/paper/as-distribution-0.5-log-curves.csv' index 3 using 1:6 with lines lw 1.5 dt 4 lc rgb '#56b4e9' title 'ihs alpha=0.5 a_tau0=0.1', 'reports/paper/as-distribution-0.5-log-curves.csv' index 5 using 1:6 with lines lw 1.5 dt 1 lc rgb '#d55e00' title 'ehs alpha=0.5 a_tau0=4', 'reports/paper/as-distribution-0.5-log-curves.csv' index 7 using 1:6 with lines lw 1.5 dt 4 lc rgb '#e69f00' title 'ehs alpha=0.5 a_tau0=0.1', 'reports/paper/as-distribution-0.5-log-curves.csv' index 9 using 1:6 with lines lw 2 dt 2 lc rgb '#000000' title 'BGK alpha=0.5', 'reports/paper/as-distribution-0.5-log-curves.csv' index 11 using 1:6 with lines lw 2 dt 2 lc rgb '#999999' title 'equilibrium'
unset multiplot
