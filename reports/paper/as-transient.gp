# gdsmc 0.3.0 verify: scene verify/cases/scenes/as.ini, seed 20050501, n = 10000, N = 8 ensembles, 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 701 outputs on [0, 700], 321 outputs on [0, 16], 701 outputs on [0, 700] (by row)
# as-transient: T/T0 against t, every row: gnuplot reports/paper/as-transient.gp
set terminal pngcairo size 1000,390 font ',10'
set termoption noenhanced
set output 'reports/paper/as-transient.png'
set datafile separator ','
set datafile missing ''
set multiplot layout 1,1 title 'as-transient: T/T0 against t, every row'
set logscale x
set logscale y
set format y '%g'
set key outside right top
set grid
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 't'
set ylabel 'T/T0'
plot 'reports/paper/as-transient-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc 1 title 'as-transient alpha=0.50 ihs a_tau0=4', 'reports/paper/as-transient-curves.csv' index 1 using 1:2 with lines lw 1.5 dt 1 lc 2 title 'as-transient alpha=0.50 ihs a_tau0=0.1', 'reports/paper/as-transient-curves.csv' index 2 using 1:2 with lines lw 1.5 dt 1 lc 3 title 'as-transient alpha=0.50 ehs a_tau0=4', 'reports/paper/as-transient-curves.csv' index 3 using 1:2 with lines lw 1.5 dt 1 lc 4 title 'as-transient alpha=0.50 ehs a_tau0=0.1', 'reports/paper/as-transient-curves.csv' index 4 using 1:2 with lines lw 1.5 dt 1 lc 5 title 'as-transient alpha=0.70 ihs a_tau0=4', 'reports/paper/as-transient-curves.csv' index 5 using 1:2 with lines lw 1.5 dt 1 lc 6 title 'as-transient alpha=0.70 ihs a_tau0=0.1', 'reports/paper/as-transient-curves.csv' index 6 using 1:2 with lines lw 1.5 dt 1 lc 7 title 'as-transient alpha=0.70 ehs a_tau0=4', 'reports/paper/as-transient-curves.csv' index 7 using 1:2 with lines lw 1.5 dt 1 lc 8 title 'as-transient alpha=0.70 ehs a_tau0=0.1', 'reports/paper/as-transient-curves.csv' index 8 using 1:2 with lines lw 1.5 dt 2 lc 1 title 'as-transient alpha=0.90 ihs a_tau0=4', 'reports/paper/as-transient-curves.csv' index 9 using 1:2 with lines lw 1.5 dt 2 lc 2 title 'as-transient alpha=0.90 ihs a_tau0=0.1', 'reports/paper/as-transient-curves.csv' index 10 using 1:2 with lines lw 1.5 dt 2 lc 3 title 'as-transient alpha=0.90 ehs a_tau0=4', 'reports/paper/as-transient-curves.csv' index 11 using 1:2 with lines lw 1.5 dt 2 lc 4 title 'as-transient alpha=0.90 ehs a_tau0=0.1'
unset multiplot
