# gdsmc 0.3.0 verify: scene verify/cases/scenes/as.ini, seed 20050501, n = 10000, N = 8 ensembles, 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 701 outputs on [0, 700], 321 outputs on [0, 16], 701 outputs on [0, 700] (by row)
# paper E Fig. 10: eta* against a* at alpha = 0.5 (2 <= s <= 50): gnuplot reports/paper/as-transient-viscosity.gp
set terminal pngcairo size 1000,390 font ',10'
set termoption noenhanced
set output 'reports/paper/as-transient-viscosity.png'
set datafile separator ','
set datafile missing ''
set multiplot layout 1,1 title 'paper E Fig. 10: eta* against a* at alpha = 0.5 (2 <= s <= 50)'
set key outside right top
set grid
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 'a*'
set ylabel 'eta*'
plot 'reports/paper/as-transient-viscosity-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' title 'ihs alpha=0.5 a_tau0=4', 'reports/paper/as-transient-viscosity-curves.csv' index 1 using 1:2 with lines lw 2 dt 2 lc rgb '#000000' title 'BGK ihs alpha=0.5 a_tau0=4', 'reports/paper/as-transient-viscosity-curves.csv' index 2 using 1:2 with lines lw 1.5 dt 4 lc rgb '#0072b2' title 'ihs alpha=0.5 a_tau0=0.1', 'reports/paper/as-transient-viscosity-curves.csv' index 3 using 1:2 with lines lw 2 dt 3 lc rgb '#000000' title 'BGK ihs alpha=0.5 a_tau0=0.1', 'reports/paper/as-transient-viscosity-curves.csv' index 4 using 1:2 with lines lw 1.5 dt 1 lc rgb '#d55e00' title 'ehs alpha=0.5 a_tau0=4', 'reports/paper/as-transient-viscosity-curves.csv' index 5 using 1:2 with lines lw 1.5 dt 4 lc rgb '#d55e00' title 'ehs alpha=0.5 a_tau0=0.1'
unset multiplot
