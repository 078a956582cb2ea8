# gdsmc 0.3.0 verify: scene verify/cases/scenes/as.ini, seed 20050501, n = 10000, N = 8 ensembles, 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 701 outputs on [0, 700], 321 outputs on [0, 16], 701 outputs on [0, 700] (by row)
# paper E Figs. 5-6: collisions per particle s (EHS: s'/beta) and s/s0 against t: gnuplot reports/paper/as-transient-collisions.gp
set terminal pngcairo size 1220,720 font ',10'
set termoption noenhanced
set output 'reports/paper/as-transient-collisions.png'
set datafile separator ','
set datafile missing ''
set multiplot title 'paper E Figs. 5-6: collisions per particle s (EHS: s''/beta) and s/s0 against t'
set logscale x
set key off
set grid
set yrange [-6.67466:140.168]
set lmargin at screen 0.0650
set rmargin at screen 0.3483
set tmargin at screen 0.9150
set bmargin at screen 0.5400
set title 'alpha = 0.5'
set xlabel ''
set ylabel 's, s''/beta'
plot 'reports/paper/as-transient-collisions-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 1 using 1:2 with lines lw 2 dt 2 lc rgb '#000000' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 2 using 1:2 with lines lw 1.5 dt 4 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 3 using 1:2 with lines lw 2 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 4 using 1:2 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 5 using 1:2 with lines lw 1.5 dt 4 lc rgb '#d55e00' notitle
set lmargin at screen 0.3833
set rmargin at screen 0.6667
set tmargin at screen 0.9150
set bmargin at screen 0.5400
set title 'alpha = 0.7'
set xlabel ''
set ylabel ''
plot 'reports/paper/as-transient-collisions-curves.csv' index 6 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 7 using 1:2 with lines lw 2 dt 2 lc rgb '#000000' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 8 using 1:2 with lines lw 1.5 dt 4 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 9 using 1:2 with lines lw 2 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 10 using 1:2 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 11 using 1:2 with lines lw 1.5 dt 4 lc rgb '#d55e00' notitle
set lmargin at screen 0.7017
set rmargin at screen 0.9850
set tmargin at screen 0.9150
set bmargin at screen 0.5400
set title 'alpha = 0.9'
set xlabel ''
set ylabel ''
plot 'reports/paper/as-transient-collisions-curves.csv' index 12 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 13 using 1:2 with lines lw 2 dt 2 lc rgb '#000000' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 14 using 1:2 with lines lw 1.5 dt 4 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 15 using 1:2 with lines lw 2 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 16 using 1:2 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 17 using 1:2 with lines lw 1.5 dt 4 lc rgb '#d55e00' notitle
set yrange [0.9452:1.0309]
set lmargin at screen 0.0650
set rmargin at screen 0.3483
set tmargin at screen 0.4750
set bmargin at screen 0.1000
set title ''
set xlabel 't/tau0'
set ylabel 's/s0'
plot 'reports/paper/as-transient-collisions-curves.csv' index 0 using 1:4 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 2 using 1:4 with lines lw 1.5 dt 4 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 4 using 1:4 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 5 using 1:4 with lines lw 1.5 dt 4 lc rgb '#d55e00' notitle
set lmargin at screen 0.3833
set rmargin at screen 0.6667
set tmargin at screen 0.4750
set bmargin at screen 0.1000
set title ''
set xlabel 't/tau0'
set ylabel ''
plot 'reports/paper/as-transient-collisions-curves.csv' index 6 using 1:4 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 8 using 1:4 with lines lw 1.5 dt 4 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 10 using 1:4 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 11 using 1:4 with lines lw 1.5 dt 4 lc rgb '#d55e00' notitle
set lmargin at screen 0.7017
set rmargin at screen 0.9850
set tmargin at screen 0.4750
set bmargin at screen 0.1000
set title ''
set xlabel 't/tau0'
set ylabel ''
plot 'reports/paper/as-transient-collisions-curves.csv' index 12 using 1:4 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 14 using 1:4 with lines lw 1.5 dt 4 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 16 using 1:4 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle, 'reports/paper/as-transient-collisions-curves.csv' index 17 using 1:4 with lines lw 1.5 dt 4 lc rgb '#d55e00' notitle
set lmargin at screen 0.065
set rmargin at screen 0.985
set bmargin at screen 0
set tmargin at screen 0.04
unset title
unset xlabel
unset ylabel
unset border
unset tics
unset grid
unset logscale
set xrange [0:1]
set yrange [0:1]
set key on center center horizontal samplen 4
plot NaN with lines lw 1.5 dt 1 lc rgb '#0072b2' title 'IHS a_tau0=4', NaN with lines lw 2 dt 2 lc rgb '#000000' title 'BGK a_tau0=4', NaN with lines lw 1.5 dt 4 lc rgb '#0072b2' title 'IHS a_tau0=0.1', NaN with lines lw 2 dt 3 lc rgb '#000000' title 'BGK a_tau0=0.1', NaN with lines lw 1.5 dt 1 lc rgb '#d55e00' title 'EHS a_tau0=4', NaN with lines lw 1.5 dt 4 lc rgb '#d55e00' title 'EHS a_tau0=0.1'
unset multiplot
